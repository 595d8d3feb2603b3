#pragma once
// The scenes shipped in data/scenes, by name.

#include <string>

#include "sim/scene.hpp"
#include "sim/scene_file.hpp"

namespace fragsim::test {

inline Scene scene_named(const std::string& name) {
  return load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/" + name + ".ini");
}

}  // namespace fragsim::test
