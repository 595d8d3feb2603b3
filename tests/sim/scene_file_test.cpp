#include "sim/scene_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace fragsim {
namespace {

// The message a bad scene text raises (empty if it parses).
std::string error_of(const std::string& text, const std::vector<SceneOverride>& overrides = {}) {
  try {
    parse_scene(text, "bad.ini", overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, ReadsSectionsAndKeys) {
  const Scene s = parse_scene(
      "name = demo\n"
      "[simulation]\n"
      "dt_s = 0.01   # a comment\n"
      "fragment_collisions = on\n"
      "[camera]\n"
      "waypoints_m = 0 1 0; 0 1 -2; 1 1 -3\n"
      "fovy_deg = 75\n"
      "[edge]\n"
      "predictor = discrete\n",
      "demo.ini");
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.sim.dt_s, 0.01);
  EXPECT_TRUE(s.sim.fragment_collisions);
  ASSERT_EQ(s.camera.waypoints_m.size(), 3u);
  EXPECT_EQ(s.camera.waypoints_m[2], Eigen::Vector3d(1, 1, -3));
  EXPECT_EQ(s.camera.fovy_deg, 75.0);
  EXPECT_EQ(s.strategies.edge.predictor, Predictor::kDiscrete);
  // Untouched keys keep their defaults.
  EXPECT_EQ(s.object.splits, Scene{}.object.splits);
}

TEST(SceneFile, CommandLineOverridesTheFile) {
  const Scene s = parse_scene("[camera]\nspeed_mps = 1\n", "a.ini", {{"camera.speed_mps", "2.5"}});
  EXPECT_EQ(s.camera.speed_mps, 2.5);
}

TEST(SceneFile, RoundTripIsExact) {
  Scene s;
  s.name = "trip";
  s.sim.dt_s = 1.0 / 60.0;
  s.sim.seed = 18446744073709551615ull;
  s.object.centre_m = {0.1, 1.0 / 3.0, -7.25};
  s.object.size_m = 0.5;  // a cube of 1.2 m would reach below the ground, which is refused
  s.camera.waypoints_m = {{0, 1.6, 0}, {0.2, 1.6, -4.0 / 3.0}};
  s.strategies.edge.reach = Reach::kGrowing;
  s.strategies.edge.replan = Replan::kContact;
  const std::string ini = scene_to_ini(s);
  const Scene back = parse_scene(ini, "trip.ini");
  EXPECT_EQ(scene_to_ini(back), ini);
  EXPECT_EQ(back.sim.dt_s, s.sim.dt_s);
  EXPECT_EQ(back.sim.seed, s.sim.seed);
  EXPECT_EQ(back.object.centre_m, s.object.centre_m);
  EXPECT_EQ(back.camera.waypoints_m[1], s.camera.waypoints_m[1]);
  EXPECT_EQ(back.strategies.edge.reach, Reach::kGrowing);
}

TEST(SceneFile, OutOfRangeValueNamesFileLineKeyAndRule) {
  EXPECT_EQ(error_of("[camera]\n\nfovy_deg = 200\n"),
            "bad.ini:3: camera.fovy_deg = '200': must be in (0, 180)");
}

TEST(SceneFile, NonFiniteAndMalformedNumbersAreRejected) {
  EXPECT_EQ(error_of("[simulation]\ndt_s = nan\n"),
            "bad.ini:2: simulation.dt_s = 'nan': must be finite");
  EXPECT_EQ(error_of("[simulation]\ndt_s = inf\n"),
            "bad.ini:2: simulation.dt_s = 'inf': must be finite");
  EXPECT_EQ(error_of("[simulation]\ndt_s = 0.01x\n"),
            "bad.ini:2: simulation.dt_s = '0.01x': not a number");
  EXPECT_EQ(error_of("[object]\nsplits = -3\n"),
            "bad.ini:2: object.splits = '-3': must be a whole number in [1, 64]");
  EXPECT_EQ(error_of("[object]\ncentre_m = 1 2\n"),
            "bad.ini:2: object.centre_m = '1 2': expected three numbers x y z");
}

TEST(SceneFile, UnknownKeyAndBadLinesAreErrors) {
  EXPECT_EQ(error_of("[camera]\nspeed = 2\n"), "bad.ini:2: unknown key 'camera.speed'");
  EXPECT_EQ(error_of("[camera]\nthis is not a setting\n"),
            "bad.ini:2: expected 'key = value', got 'this is not a setting'");
  EXPECT_EQ(error_of("[camera\n"), "bad.ini:1: malformed section header '[camera'");
  EXPECT_EQ(error_of("[camera]\nnear_m = 0.1\nnear_m = 0.2\n"),
            "bad.ini:3: camera.near_m is set more than once");
}

TEST(SceneFile, ContradictionsAreErrors) {
  EXPECT_EQ(error_of("[camera]\nnear_m = 5\nfar_m = 4\n"),
            "camera.far_m = 4: must be > camera.near_m = 5");
  EXPECT_NE(error_of("[camera]\nspeed_mps = 5\nmax_speed_mps = 4\n").find("camera.max_speed_mps"),
            std::string::npos);
}

TEST(SceneFile, BadOverrideNamesTheOption) {
  EXPECT_EQ(error_of("", {{"camera.near_m", "-1"}}),
            "--camera.near_m: camera.near_m = '-1': must be in (0, 1000]");
}

TEST(SceneFile, MissingFileIsNamed) {
  try {
    load_scene("/nonexistent/scene.ini");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/scene.ini: no such scene file");
  }
}

// A directory used to read as an empty file, so the built-in defaults ran silently.
TEST(SceneFile, DirectoryIsRefused) {
  try {
    load_scene("/tmp");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/tmp: is a directory, not a scene file");
  }
}

// Some Windows editors save UTF-8 with a byte-order mark; it used to be glued to the first key.
TEST(SceneFile, ByteOrderMarkIsDropped) {
  const std::string path = ::testing::TempDir() + "/bom_scene.ini";
  {
    std::ofstream out(path, std::ios::binary);
    out << "\xEF\xBB\xBFname = bom\n[camera]\nfovy_deg = 50\n";
  }
  const Scene s = load_scene(path);
  EXPECT_EQ(s.name, "bom");
  EXPECT_EQ(s.camera.fovy_deg, 50.0);
  std::remove(path.c_str());
}

TEST(SceneFile, ShippedScenesLoad) {
  for (const char* name : {"front", "thesis125", "thesis1000", "close"}) {
    const std::string path = std::string(FRAGSIM_DATA_DIR) + "/scenes/" + name + ".ini";
    EXPECT_NO_THROW(load_scene(path)) << path;
  }
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

TEST(SceneFile, EveryKeyIsDocumented) {
  std::ifstream in(std::string(FRAGSIM_DATA_DIR) + "/../docs/guide.md");
  ASSERT_TRUE(in) << "docs/guide.md is missing";
  std::stringstream doc;
  doc << in.rdbuf();
  for (const auto& option : scene_options().options()) {
    const std::string full = option->long_name();
    const auto dot = full.find('.');
    const std::string section = dot == std::string::npos ? "" : full.substr(0, dot);
    const std::string key = dot == std::string::npos ? full : full.substr(dot + 1);
    const std::string text = doc.str();
    const auto at = text.find("### [" + section + "]");
    if (!section.empty()) {
      ASSERT_NE(at, std::string::npos) << "no section [" << section << "] in docs/guide.md";
    }
    EXPECT_NE(text.find("| `" + key + "` |", section.empty() ? 0 : at), std::string::npos)
        << full << " is not documented in docs/guide.md";
  }
}

// An object starting partly below the ground was thrown out of it by ODE at up to 7.2 m/s with no
// blast at all: refused, naming the keys and where its lowest point is.
TEST(SceneFile, ObjectBelowTheGroundIsRefused) {
  EXPECT_EQ(error_of("[object]\ncentre_m = 0 0.3 -8\n"),
            "object.centre_m = 0 0.3 -8: the cube's bottom (object.size_m = 1.2) is at y = -0.3 m, "
            "below the ground at ground.height_m = 0: the object must start wholly at or above the "
            "ground");
  // Resting on it is fine, and so is any height without a ground.
  EXPECT_EQ(error_of("[object]\ncentre_m = 0 0.6 -8\n"), "");
  EXPECT_EQ(error_of("[object]\ncentre_m = 0 0.3 -8\n[ground]\nenabled = off\n"), "");
  // A raised ground, and an object moved there by distance_m, are measured where they end up.
  EXPECT_NE(error_of("[ground]\nheight_m = 1.5\n").find("ground.height_m = 1.5"),
            std::string::npos);
  EXPECT_NE(error_of("[object]\ncentre_m = 0 -2 -8\ndistance_m = 8\n[ground]\nenabled = on\n")
                .find("(placed by object.distance_m = 8)"),
            std::string::npos);
}

// A mesh object: its lowest vertex, not object.size_m, is what must be above the ground. The
// pieces of a unit cube (vertices at y = -0.5 .. 0.5 about the file's origin).
TEST(SceneFile, MeshBelowTheGroundIsRefusedByItsLowestVertex) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fragsim_ground_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string obj = (dir / "cube.obj").string();
  {
    std::ofstream out(obj);
    out << "o cube\n";
    for (int i = 0; i < 8; ++i) {
      out << "v " << ((i & 1) ? 0.5 : -0.5) << ' ' << ((i & 2) ? 0.5 : -0.5) << ' '
          << ((i & 4) ? 0.5 : -0.5) << "\n";
    }
    out << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  }
  const std::string mesh = "[object]\nmesh_file = " + obj + "\nsize_m = 5\n";
  EXPECT_EQ(error_of(mesh + "centre_m = 0 0.5 -8\n"), "");
  EXPECT_EQ(error_of(mesh + "centre_m = 0 0.4 -8\n"),
            "object.centre_m = 0 0.4 -8: object.mesh_file's lowest vertex is at y = -0.1 m, below "
            "the ground at ground.height_m = 0: the object must start wholly at or above the "
            "ground");
  std::filesystem::remove_all(dir);
}

// Legal values the property test over the keys (tests/property/scene_keys_test.cpp) found to abort
// or hang, now refused with one line each: a step of 5e-324 s (ODE's 1 / dt overflows), a camera
// so tall and thin that the occlusion raster needs billions of rows (out of memory, or minutes),
// and a player whose track asks for 36 GB of samples or 4e7 changes of course.
TEST(SceneFile, ExtremesFoundByThePropertyTestAreRefused) {
  EXPECT_EQ(error_of("[simulation]\ndt_s = 4.9406564584124654e-324\nduration_s = 1e-322\n"),
            "bad.ini:2: simulation.dt_s = '4.9406564584124654e-324': must be in [1e-09, 1]");
  EXPECT_EQ(error_of("[camera]\naspect = 3.00042649014661e-08\n"),
            "camera.aspect = 3.00042649014661e-08: the occlusion raster would be 5332575236 rows "
            "tall (metrics.grid_width_px = 160 / camera.aspect): at most 4096");
  EXPECT_EQ(error_of("[camera]\naspect = 0.0390625\n"), "");  // 4096 rows
  EXPECT_NE(error_of("[simulation]\ndt_s = 4.4571525542105243e-09\nduration_s = 1e-7\n"
                     "[camera]\nmode = player\n")
                .find("camera.mode = player makes"),
            std::string::npos);
  EXPECT_NE(error_of("[camera]\nmode = player\nplayer_interval_s = 6.5e-9\n")
                .find("camera.player_interval_s = 6.5e-09: the player would change course about"),
            std::string::npos);
  EXPECT_EQ(error_of("[camera]\nmode = player\nplayer_interval_s = 1e-6\n"), "");
}

std::vector<std::string> warnings_of(const std::string& text,
                                     const std::vector<SceneOverride>& overrides = {}) {
  std::vector<std::string> warnings;
  parse_scene(text, "s.ini", overrides, &warnings);
  return warnings;
}

// A key the user set that the scene's modes leave without effect is named with where it was set:
// camera.track_file without camera.mode = track flew the default path without a word.
TEST(SceneFile, KeysWithoutEffectAreWarnedWhereSet) {
  EXPECT_EQ(warnings_of("[camera]\n\ntrack_file = /x/t.csv\n"),
            std::vector<std::string>{"s.ini:3: camera.track_file has no effect: only camera.mode "
                                     "= track reads a track, and camera.mode = path"});
  EXPECT_EQ(warnings_of("", {{"ground.enabled", "off"}, {"ground.friction", "0.5"}}),
            std::vector<std::string>{"--ground.friction: ground.friction has no effect: "
                                     "ground.enabled = off: there is no ground"});
  // Set in the file and again on the command line: named once, where it won.
  EXPECT_EQ(
      warnings_of("[object]\npieces = 50\n", {{"object.pieces", "60"}}),
      std::vector<std::string>{"--object.pieces: object.pieces has no effect: only "
                               "object.pattern = voronoi uses it, and object.pattern = grid"});
  // Keys that take effect, and the strategies' keys, say nothing.
  EXPECT_TRUE(warnings_of("[camera]\nnear_m = 0.2\n[object]\npattern = voronoi\npieces = 20\n"
                          "[near-plane]\nmargin_m = 0.1\n")
                  .empty());
}

// The mesh's unit and axis keys without a mesh file did nothing, silently: warned as the track's
// keys are outside track mode.
TEST(SceneFile, MeshKeysWithoutAMeshAreWarned) {
  const std::string why =
      " has no effect: only object.mesh_file is read in these units and "
      "axes, and it is not set";
  EXPECT_EQ(warnings_of("[object]\nmesh_unit_m = 0.01\nmesh_up = z\n",
                        {{"object.mesh_handedness", "left"}}),
            (std::vector<std::string>{"s.ini:2: object.mesh_unit_m" + why,
                                      "s.ini:3: object.mesh_up" + why,
                                      "--object.mesh_handedness: object.mesh_handedness" + why}));
}

// object.size_m with a mesh file is ignored: the pieces are the file's.
TEST(SceneFile, CubeKeysWithAMeshAreWarned) {
  const std::string mesh = ::testing::TempDir() + "/fragsim_tet.obj";
  std::ofstream(mesh) << "o Tet\nv 0 0 0\nv 0.2 0 0\nv 0 0.2 0\nv 0 0 0.2\n"
                         "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  EXPECT_EQ(warnings_of("[object]\nmesh_file = " + mesh + "\nsize_m = 2\n"),
            std::vector<std::string>{"s.ini:3: object.size_m has no effect: the pieces come from "
                                     "object.mesh_file, as the file makes them"});
  std::remove(mesh.c_str());
}

// config.ini holds every key (any mode can be switched on again from it): it replays without a
// warning, and as the same scene.
TEST(SceneFile, WrittenSceneReplaysWithoutWarnings) {
  const Scene s = parse_scene(
      "[camera]\ntrack_file = /x/t.csv\nplayer_interval_s = 2\n"
      "[ground]\nenabled = off\nfriction = 0.3\n",
      "s.ini");
  const std::string ini = scene_to_ini(s);
  std::vector<std::string> warnings;
  const Scene back = parse_scene(ini, "config.ini", {}, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(scene_to_ini(back), ini);
  EXPECT_EQ(back.ground.friction, 0.3);
  // The same text without its first line is a hand-written scene, and is warned about.
  const std::vector<std::string> unmarked = warnings_of(ini.substr(ini.find('\n') + 1));
  EXPECT_TRUE(std::any_of(unmarked.begin(), unmarked.end(), [](const std::string& w) {
    return w.rfind("s.ini:", 0) == 0 &&
           w.find(
               ": camera.track_file has no effect: only camera.mode = track reads a track, and "
               "camera.mode = path") != std::string::npos;
  }));
}

// camera.near_m = 1e-300 broke the near-plane strategy's rule and the message blamed
// near-plane.min_near_m, a key the user never set, without file:line.
TEST(SceneFile, RuleAcrossKeysIsPlacedAtTheKeySet) {
  EXPECT_EQ(error_of("[camera]\nnear_m = 1e-300\n"),
            "bad.ini:2: camera.near_m = 1e-300 breaks a rule of near-plane.min_near_m, which is "
            "not set (its default): near-plane.min_near_m = 0.01: must be <= camera.near_m = "
            "1e-300");
  EXPECT_EQ(error_of("", {{"camera.near_m", "1e-300"}})
                .rfind("--camera.near_m: camera.near_m = "
                       "1e-300 breaks a rule of ",
                       0),
            0u);
  // When the rule's own key was set, the message is as it was.
  EXPECT_EQ(error_of("[camera]\nnear_m = 1e-300\n[near-plane]\nmin_near_m = 0.01\n"),
            "near-plane.min_near_m = 0.01: must be <= camera.near_m = 1e-300");
}

TEST(SceneFile, WindowsLineEndsAndControlCharacters) {
  const std::string path = ::testing::TempDir() + "/fragsim_crlf.ini";
  std::ofstream(path, std::ios::binary) << "[camera]\r\nnear_m = 0.2\r\nmode = path\r\n";
  EXPECT_EQ(load_scene(path).camera.near_m, 0.2);
  std::remove(path.c_str());
  // A NUL byte in a value is shown, and the message goes on past it.
  EXPECT_EQ(error_of(std::string("[camera]\nnear_m = 0.\0"
                                 "01x\n",
                                 25)),
            "bad.ini:2: camera.near_m = '0.\\x0001x': not a number");
  EXPECT_EQ(error_of(std::string("[camera]\nnear\x01m\n", 16)),
            "bad.ini:2: expected 'key = value', got 'near\\x01m'");
}

}  // namespace
}  // namespace fragsim
