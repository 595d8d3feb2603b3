// A scene's object.mesh_file (sim/scene_file.cpp): a relative path is taken from the scene file's
// folder and reads back from anywhere; a file that cannot be read names the key.

#include "sim/scene_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "debris/mesh_file.hpp"
#include "sim/explosion.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

class SceneFileMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fragsim_mesh_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "scenes");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SceneFileMesh, RelativeMeshFileIsTakenFromTheSceneFilesFolder) {
  Scene cells = parse_scene("[object]\npattern = voronoi\npieces = 20\n", "cells.ini");
  write_pieces(scene_pieces(cells), (dir_ / "scenes" / "cells.obj").string());
  const std::string scene_path = (dir_ / "scenes" / "mesh.ini").string();
  std::ofstream(scene_path) << "[object]\nmesh_file = cells.obj\n";
  const Scene s = load_scene(scene_path);
  EXPECT_EQ(s.object.mesh_file, (dir_ / "scenes" / "cells.obj").string());
  ASSERT_NE(s.object.mesh_pieces, nullptr);
  EXPECT_EQ(s.fragment_count(), 20);
  const auto a = scene_pieces(cells);
  const auto b = scene_pieces(s);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a[i].centre_m - b[i].centre_m).norm(), 0.0, 1e-12);
  }
  // The resolved scene reads back to the same file from anywhere.
  const Scene again = parse_scene(scene_to_ini(s), "elsewhere/config.ini");
  EXPECT_EQ(again.object.mesh_file, s.object.mesh_file);
}

TEST_F(SceneFileMesh, BadMeshFileNamesTheKey) {
  const std::string scene_path = (dir_ / "scenes" / "bad.ini").string();
  std::ofstream(scene_path) << "[object]\nmesh_file = nowhere.glb\n";
  try {
    load_scene(scene_path);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("nowhere.glb"), std::string::npos) << m;
    EXPECT_NE(m.find("(object.mesh_file)"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace fragsim
