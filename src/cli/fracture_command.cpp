#include "cli/fracture_command.hpp"

#include <filesystem>
#include <iostream>

#include "cli/command_line.hpp"
#include "debris/mesh_file.hpp"
#include "io/input_error.hpp"
#include "sim/explosion.hpp"

namespace fragsim::cli {

int cmd_fracture(const std::vector<std::string>& args) {
  namespace po = boost::program_options;
  po::options_description own("fracture options");
  own.add_options()("out", po::value<std::string>()->value_name("FILE"),
                    "the pieces' file: .glb (binary glTF) or .obj; the object's centre at the "
                    "origin, so object.mesh_file = FILE makes the same pieces again")(
      "force", "overwrite FILE if it exists");
  ParsedCommand p = parse_command("fracture", args, own);
  if (p.help_shown) return 0;
  if (!p.options.count("out")) throw UsageError("--out: needed (FILE.glb or FILE.obj)");
  const std::string out = p.options["out"].as<std::string>();
  const std::string ext = std::filesystem::path(out).extension().string();
  if (ext != ".glb" && ext != ".obj") {
    throw UsageError("--out " + out + ": must end in .glb or .obj");
  }
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !p.options.count("force")) {
    throw UsageError("--out " + out + ": exists (use --force to overwrite)");
  }
  const std::filesystem::path dir = std::filesystem::path(out).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir, ec)) {
    throw UsageError("--out " + out + ": folder " + dir.string() + " does not exist");
  }
  std::vector<Piece> pieces;
  try {
    pieces = scene_pieces(p.scene);
  } catch (const InputError& e) {
    throw UsageError(std::string("--scene: ") + e.what());
  }
  write_pieces(pieces, out);
  double volume_m3 = 0.0;
  for (const Piece& piece : pieces) volume_m3 += piece_volume_m3(piece);
  std::cout << "wrote " << out << ": " << pieces.size() << " pieces, " << volume_m3
            << " m^3 in all\n";
  return 0;
}

}  // namespace fragsim::cli
