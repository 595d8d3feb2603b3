// The comparison's CSV files: summary.csv read back as the table it was written from, the files
// the same bytes for the same scene and seed, and hand-made runs' rows to the character.

#include "report/csv_export.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "io/output_folder.hpp"
#include "io/output_set.hpp"
#include "sim/scene_file.hpp"
#include "support/shipped_scene.hpp"

namespace fragsim {
namespace {

using test::scene_named;
using Values = std::vector<std::string>;

TEST(CsvExport, SummaryCsvReadsBackAsTheTable) {
  const Scene scene = scene_named("thesis125");
  const auto runs = compare(scene, {"none", "edge", "near-plane"});
  const std::string dir = ::testing::TempDir() + "/fragsim_csv_roundtrip";
  std::filesystem::remove_all(dir);
  {
    OutputFolder folder(dir, false);
    OutputSet files;
    add_comparison_csv(files, dir, scene, runs);
    files.commit();
    folder.keep();
  }
  const auto back = read_summary_csv(dir + "/summary.csv");
  ASSERT_EQ(back.size(), runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunSummary& a = runs[i].summary;
    const RunSummary& b = back[i];
    EXPECT_EQ(b.strategy, a.strategy);
    EXPECT_EQ(b.seed, a.seed);
    EXPECT_EQ(b.intersections.near_fragments, a.intersections.near_fragments);
    EXPECT_EQ(b.intersections.camera_hit_fragments, a.intersections.camera_hit_fragments);
    EXPECT_EQ(b.deviation.mean_m, a.deviation.mean_m);  // shortest round-trip text: exact
    EXPECT_EQ(b.occlusion.max, a.occlusion.max);
    EXPECT_EQ(b.activity.impulse_Ns, a.activity.impulse_Ns);
    EXPECT_EQ(b.activity.min_near_m, a.activity.min_near_m);
    EXPECT_EQ(b.exits.top, a.exits.top);
  }
  // config.ini is the resolved scene and loads back to the same scene.
  EXPECT_EQ(scene_to_ini(load_scene(dir + "/config.ini")), scene_to_ini(scene));
  // An existing, non-empty folder is refused without force.
  EXPECT_THROW(OutputFolder(dir, false), std::runtime_error);
  EXPECT_NO_THROW(OutputFolder(dir, true));
}

TEST(CsvExport, CsvIsByteIdenticalForTheSameSceneAndSeed) {
  const Scene scene = scene_named("thesis125");
  const auto a = compare(scene, {"none", "wall", "deflect-all", "near-plane", "edge"});
  const auto b = compare(scene, {"none", "wall", "deflect-all", "near-plane", "edge"});
  EXPECT_EQ(summary_csv(scene, a), summary_csv(scene, b));
  EXPECT_EQ(steps_csv(scene, a), steps_csv(scene, b));
  EXPECT_EQ(camera_csv(scene, a), camera_csv(scene, b));
}

TEST(CsvExport, SummaryCellsAreSummaryCsvRows) {
  Scene scene;
  Evaluation e;
  e.summary.scene = "hand";
  e.summary.strategy = "edge";
  e.summary.seed = 42;
  e.summary.intersections.near_fragments = 3;
  e.summary.deviation.mean_m = 0.1;
  auto join = [](const Values& cells) {
    std::string s;
    for (const std::string& c : cells) s += (s.empty() ? "" : ",") + c;
    return s + "\n";
  };
  EXPECT_EQ(join(summary_csv_columns()) + join(summary_csv_cells(scene, e.summary)),
            summary_csv(scene, {e}));
}

// Two steps of 0.5 s; the second run without occlusion, whose cells are left empty.
std::vector<Evaluation> hand_made_runs() {
  Evaluation edge;
  edge.summary.strategy = "edge";
  edge.near_per_step = {0, 2};
  edge.candidates_per_step = {5, 3};
  edge.occlusion_per_step = {0.25, 0.5};
  edge.central_occlusion_per_step = {0.125, 1.0};
  edge.physics_s_per_step = {0.0009765625, 0.25};  // 2^-10 s: 0.9765625 ms exactly
  edge.strategy_s_per_step = {0.5, 0.0};
  edge.camera.resize(3);
  edge.camera[2].near_m = 0.05;
  Evaluation none;
  none.summary.strategy = "none";
  none.near_per_step = {1};
  none.candidates_per_step = {0};
  none.physics_s_per_step = {0.125};
  none.strategy_s_per_step = {0.0};
  none.camera.resize(2);
  return {edge, none};
}

TEST(CsvExport, StepsAndTimingRowsOfHandMadeRuns) {
  Scene scene;
  scene.sim.dt_s = 0.5;
  const std::vector<Evaluation> runs = hand_made_runs();
  EXPECT_EQ(steps_csv(scene, runs),
            "strategy,step,t_s,candidates,near_intersections,occlusion,central_occlusion,near_m\n"
            "edge,1,0.5,5,0,0.25,0.125,0.1\n"
            "edge,2,1,3,2,0.5,1,0.05\n"
            "none,1,0.5,0,1,,,0.1\n");
  EXPECT_EQ(timing_csv(scene, runs),
            "strategy,step,t_s,physics_ms,strategy_ms\n"
            "edge,1,0.5,0.9765625,500\n"
            "edge,2,1,250,0\n"
            "none,1,0.5,125,0\n");
}

TEST(CsvExport, CameraRowIsStrategyStepTimeAndPose) {
  CameraPose pose;
  pose.eye_m = {1.0, 1.6, -2.5};
  pose.near_m = 0.1;
  pose.fovy_deg = 60.0;
  pose.aspect = 1.5;
  std::string out = camera_csv_header();
  append_camera_row(out, "none", 7, 0.125, pose);
  EXPECT_EQ(
      out,
      "strategy,step,t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z,"
      "near_m,fovy_deg,aspect\n"
      "none,7,0.125,1,1.6,-2.5,0,0,-1,0,1,0,0.1,60,1.5\n");
  // camera.csv is the header and each run's poses from step 0, at t = step dt.
  Scene scene;
  scene.sim.dt_s = 0.125;
  Evaluation e;
  e.summary.strategy = "none";
  e.camera = {CameraPose{}, pose};
  std::string want = camera_csv_header();
  append_camera_row(want, "none", 0, 0.0, CameraPose{});
  append_camera_row(want, "none", 1, 0.125, pose);
  EXPECT_EQ(camera_csv(scene, {e}), want);
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

TEST(CsvExport, UnreadableSummaryFileIsNamedWithItsLine) {
  const std::string path = ::testing::TempDir() + "/fragsim_bad_summary.csv";
  const auto error_of = [&path](const std::string& text) {
    write_text(path, text);
    try {
      read_summary_csv(path);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string header = summary_csv(Scene{}, {});  // the header line alone
  const std::size_t cells = summary_csv_columns().size();
  EXPECT_EQ(error_of(""), path + ":1: empty file");
  EXPECT_EQ(error_of("scene,strategy\n"), path + ":1: too few columns");
  EXPECT_EQ(error_of("name" + header.substr(header.find(','))),
            path + ":1: column 1 is 'name', expected 'scene'");
  EXPECT_EQ(error_of(header + "a,b\n"), path + ":2: expected " + std::to_string(cells) + " cells");
  write_text(path, header);
  EXPECT_TRUE(read_summary_csv(path).empty());
}

}  // namespace
}  // namespace fragsim
