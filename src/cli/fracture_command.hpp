#pragma once
// `fragsim fracture` writes the pieces a scene's object breaks into as a mesh file, to look at in
// any glTF or OBJ viewer or to fracture once and load everywhere (object.mesh_file).

#include <string>
#include <vector>

namespace fragsim::cli {

// Parses, makes the pieces, writes --out atomically. Returns the exit status; throws UsageError
// naming the option for bad input.
int cmd_fracture(const std::vector<std::string>& args);

}  // namespace fragsim::cli
