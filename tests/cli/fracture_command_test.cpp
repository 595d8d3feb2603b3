// `fragsim fracture` end to end: the file it writes makes the same pieces again as
// object.mesh_file, and bad options are one line naming the option.

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

class FractureCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fragsim_fracture_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    scene_ = (dir_ / "cells.ini").string();
    std::ofstream(scene_) << "[object]\npattern = voronoi\npieces = 40\ncluster = 0.5\n"
                             "[explosion]\noffset_m = 0.2 0 0\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
  std::string scene_;
};

TEST_F(FractureCommand, WrittenPiecesReadBackAsTheScenesPieces) {
  for (const char* name : {"pieces.obj", "pieces.glb"}) {
    const std::string out = (dir_ / name).string();
    const test::Result r = test::run_fragsim("fracture --scene " + scene_ + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("40 pieces"), std::string::npos) << r.out;
    const auto a = scene_pieces(load_scene(scene_));
    const auto b = scene_pieces(load_scene("", {{"object.mesh_file", out}}));
    ASSERT_EQ(a.size(), b.size());
    const double tol = std::string(name) == "pieces.obj" ? 1e-12 : 1e-6;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR((a[i].centre_m - b[i].centre_m).norm(), 0.0, tol * a[i].shape->radius_m);
      EXPECT_NEAR(b[i].mass_kg / a[i].mass_kg, 1.0, tol);
    }
    // Refuses to overwrite without --force.
    EXPECT_EQ(test::run_fragsim("fracture --scene " + scene_ + " --out " + out).status, 2);
  }
}

TEST_F(FractureCommand, BadOutIsOneLineNamingTheOption) {
  for (const std::string& args : {std::string(), " --out " + (dir_ / "p.stl").string(),
                                  " --out " + (dir_ / "no" / "p.glb").string()}) {
    const test::Result r = test::run_fragsim("fracture --scene " + scene_ + args);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("--out"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << r.out;
  }
}

}  // namespace
}  // namespace fragsim
