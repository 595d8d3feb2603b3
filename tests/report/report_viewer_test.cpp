// The report's 3D view (report/report_viewer.hpp): the sampling stride against the page's budget,
// the recorder's flags against the near-plane metric and the forces of a real comparison (and the
// runs unchanged by it), the quantisation's error on made-up poses, and the section with and
// without three.js. The page in a browser is tests/browser/check_report.py's.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "experiments/evaluation.hpp"
#include "report/html_escape.hpp"
#include "report/html_report.hpp"
#include "report/report_viewer.hpp"
#include "sim/scene_file.hpp"
#include "support/run_fragsim.hpp"
#include "support/text_count.hpp"

namespace fragsim {
namespace {

using test::occurrences;

const std::string kThesis125 = std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini";
const std::string kFront = std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini";

TEST(ReportViewer, SampleStrideKeepsEveryStrategyWithinTheBudget) {
  // thesis125's 125 pieces fit at every step; front.ini's 1,728 with all 7 strategies do not.
  const Scene small = load_scene(kThesis125);
  EXPECT_EQ(viewer_sample_every(small.fragment_count(), small.step_count(), 7), 1);
  const Scene front = load_scene(kFront);
  const int every = viewer_sample_every(front.fragment_count(), front.step_count(), 7);
  EXPECT_EQ(every, 2);
  const auto bytes = [&](int e) {
    const int steps = front.step_count();
    const int samples = steps / e + 1 + (steps % e != 0 ? 1 : 0);
    return samples * kViewerPieceSample_bytes * front.fragment_count() * 7;
  };
  EXPECT_LE(bytes(every), kViewerBudget_bytes);
  EXPECT_GT(bytes(every - 1), kViewerBudget_bytes);
  // One strategy fits at every step.
  EXPECT_EQ(viewer_sample_every(front.fragment_count(), front.step_count(), 1), 1);
}

struct Viewed {
  Scene scene = load_scene(kThesis125);
  std::vector<std::string> names{"none", "edge-min", "near-plane"};
  ViewerRecorder viewer{1};
  std::vector<Evaluation> runs = compare(scene, names, false, &viewer);
};

const Viewed& viewed() {
  static const Viewed v;
  return v;
}

TEST(ReportViewer, FlagsAreTheMetricsNearPlaneHitsAndTheStrategysPushes) {
  const Viewed& v = viewed();
  ASSERT_EQ(v.viewer.runs().size(), v.names.size());
  const std::size_t n = v.viewer.piece_mesh().size();
  ASSERT_EQ(static_cast<int>(n), v.scene.fragment_count());
  int pushed_runs = 0;
  for (std::size_t r = 0; r < v.runs.size(); ++r) {
    const ViewerRun& run = v.viewer.runs()[r];
    const Evaluation& e = v.runs[r];
    EXPECT_EQ(run.strategy, e.summary.strategy);
    ASSERT_EQ(run.steps.size(), static_cast<std::size_t>(v.scene.step_count()) + 1);
    ASSERT_EQ(run.flags.size(), run.steps.size() * n);
    int pushed = 0;
    for (std::size_t s = 1; s < run.steps.size(); ++s) {
      int hits = 0;
      for (std::size_t i = 0; i < n; ++i) {
        hits += (run.flags[s * n + i] & kViewerNearHit) != 0;
        pushed += (run.flags[s * n + i] & kViewerPushed) != 0;
      }
      // Every step sampled: a sample's hits are the metric's count for that step.
      EXPECT_EQ(hits, e.near_per_step[s - 1]) << run.strategy << " step " << s;
    }
    if (run.strategy == "none") {
      EXPECT_EQ(pushed, 0);
    }
    if (run.strategy == "edge-min" && pushed > 0) ++pushed_runs;
  }
  EXPECT_EQ(pushed_runs, 1);
  // none cuts pieces on thesis125 (docs/guide.md), so the hits above were not all zero.
  EXPECT_GT(v.runs.front().summary.intersections.near_fragment_steps, 0);
}

TEST(ReportViewer, RecordingDoesNotChangeTheRuns) {
  const Viewed& v = viewed();
  const std::vector<Evaluation> plain = compare(v.scene, v.names, false);
  ASSERT_EQ(plain.size(), v.runs.size());
  for (std::size_t r = 0; r < plain.size(); ++r) {
    EXPECT_EQ(plain[r].near_per_step, v.runs[r].near_per_step);
    EXPECT_EQ(plain[r].candidates_per_step, v.runs[r].candidates_per_step);
    EXPECT_EQ(plain[r].summary.deviation.mean_m, v.runs[r].summary.deviation.mean_m);
    EXPECT_EQ(plain[r].summary.deviation.max_m, v.runs[r].summary.deviation.max_m);
  }
}

// Two pieces on made-up poses: the decoded positions are within the stated error of the true ones.
TEST(ReportViewer, QuantisedPosesAreWithinTheStatedError) {
  Scene scene;
  std::vector<FragmentState> pieces(2);
  for (FragmentState& f : pieces) f.half_extents_m = {0.1, 0.1, 0.1};
  RunInfo info;
  info.scene = &scene;
  info.strategy = "made";
  info.fragment_count = 2;
  info.step_count = 3;
  info.dt_s = 0.01;
  ViewerRecorder rec(2);
  std::vector<Eigen::Vector3d> truth;
  std::vector<Eigen::Quaterniond> turns;
  const auto snap_at = [&](int step) {
    StepSnapshot s;
    s.step = step;
    s.t_s = step * 0.01;
    s.camera.eye_m = {0, 1, 5};
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      pieces[i].position_m = {0.1234567 * step - 3.0 * i, 2.0 + std::sin(step + i), -7.77 * step};
      const Eigen::Quaterniond q = Eigen::Quaterniond(
          Eigen::AngleAxisd(0.3 + step + i, Eigen::Vector3d(1, 2, 3).normalized()));
      pieces[i].rotation = q.toRotationMatrix();
      // Steps 0, 2 and the last (3) are sampled.
      if (step != 1) {
        truth.push_back(pieces[i].position_m);
        turns.push_back(q.w() < 0 ? Eigen::Quaterniond(-q.coeffs()) : q);
      }
    }
    s.fragments = pieces;
    return s;
  };
  rec.begin(info, snap_at(0));
  for (int k = 1; k <= 3; ++k) rec.observe(snap_at(k));
  rec.end();
  ASSERT_EQ(rec.runs().size(), 1u);
  const ViewerRun& run = rec.runs().front();
  EXPECT_EQ(run.steps, (std::vector<int>{0, 2, 3}));
  ASSERT_EQ(run.position_q.size(), 3 * truth.size());
  for (std::size_t j = 0; j < truth.size(); ++j) {
    for (int k = 0; k < 3; ++k) {
      const double span = double(run.hi_m[k]) - run.lo_m[k];
      const double decoded = run.lo_m[k] + (run.position_q[3 * j + k] / 32767.0 + 1) / 2 * span;
      // Half a step of 65,534 over the box, plus float rounding of the box and the poses.
      EXPECT_NEAR(decoded, truth[j][k], span / 131068.0 + 1e-5) << j << " " << k;
    }
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(run.rotation_q[4 * j + k] / 32767.0, turns[j].coeffs()[k], 1.0 / 65534 + 1e-6);
    }
  }
}

TEST(ReportViewer, SectionCarriesThreeJsItsLicenceAndTheData) {
  const Viewed& v = viewed();
  BundledThreeJs three;
  three.version = "0.0.1";
  three.module_js = "export const REVISION = '1';";
  three.licence = "The MIT License <copyright>";
  const std::string section = viewer_section_html(v.scene, v.viewer, "none", "edge-min", three);
  EXPECT_NE(section.find("<canvas id=\"viewer-canvas\""), std::string::npos);
  EXPECT_NE(section.find("<input type=\"range\" id=\"viewer-time\" min=\"0\" max=\"" +
                         std::to_string(v.scene.step_count()) + "\""),
            std::string::npos);
  // The module as base64 ("export const REVISION = '1';"), the licence escaped.
  EXPECT_NE(section.find(">ZXhwb3J0IGNvbnN0IFJFVklTSU9OID0gJzEnOw==</script>"), std::string::npos);
  EXPECT_NE(section.find("The MIT License &lt;copyright&gt;"), std::string::npos);
  EXPECT_NE(section.find("<option value=\"edge-min\" selected>"), std::string::npos);
  EXPECT_NE(section.find("<script type=\"module\">"), std::string::npos);
  EXPECT_EQ(occurrences(section, "\"strategy\":"), v.names.size());
  // The scripts end where they should: nothing inside them closes a script early.
  EXPECT_EQ(occurrences(section, "</script>"), 3u);
  EXPECT_EQ(section, viewer_section_html(v.scene, v.viewer, "none", "edge-min", three));
}

TEST(ReportViewer, WithoutThreeJsTheSectionSaysWhyAndRunsNoScript) {
  const Viewed& v = viewed();
  BundledThreeJs three;
  three.missing = "npm was not found at configure time";
  EXPECT_FALSE(three.available());
  const std::string section = viewer_section_html(v.scene, v.viewer, "none", "", three);
  EXPECT_EQ(section.find("<script"), std::string::npos);
  EXPECT_NE(section.find("id=\"viewer-missing\""), std::string::npos);
  EXPECT_NE(section.find(html_escape(viewer_missing_text(three))), std::string::npos);
  EXPECT_NE(viewer_missing_text(three).find("npm was not found at configure time"),
            std::string::npos);
  // The page is still whole.
  const std::string page = html_report(v.scene, v.runs, std::nullopt, section);
  EXPECT_NE(page.find("<h2>3D view</h2>"), std::string::npos);
  EXPECT_NE(page.find("</html>"), std::string::npos);
}

TEST(ReportViewer, PairIsNoneAndTheBestOrTheNextRun) {
  const Viewed& v = viewed();
  const auto [left, right] = report_viewer_pair(v.runs);
  EXPECT_EQ(left, "none");
  const std::optional<std::size_t> best = best_for_thesis_goals(v.runs);
  ASSERT_TRUE(best);
  EXPECT_EQ(right, v.runs[*best].summary.strategy);
  const std::vector<Evaluation> one(v.runs.begin(), v.runs.begin() + 1);
  EXPECT_EQ(report_viewer_pair(one), (std::pair<std::string, std::string>{"none", ""}));
}

// The bound: front.ini (1,728 pieces) with every strategy stays under 30 MB, 3D view
// included (5 s: occlusion off, it does not change the view). The page says it skips steps.
TEST(ReportViewer, FrontWithEveryStrategyStaysUnder30MB) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "fragsim_report_front";
  fs::remove_all(dir);
  const test::Result r =
      test::run_fragsim("compare --scene " + kFront + " --no-occlusion --report " + dir.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto bytes = fs::file_size(dir / "index.html");
  EXPECT_LT(bytes, 30'000'000u);
  if (bundled_three_js().available()) {
    EXPECT_GT(bytes, 10'000'000u);  // the view's data is there
    std::ifstream in(dir / "index.html", std::ios::binary);
    const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(page.find("One step in 2 is shown (and the last)"), std::string::npos);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fragsim
