#pragma once
// The comparison as one HTML page (fragsim compare --report DIR): the scene, a reading of the
// numbers in prose, the comparison table (report/results_table.hpp, the terminal's cells; also
// DIR/table.csv), the 3D view of the runs (report_viewer.hpp), the per-step metrics as inline SVG
// line charts, the contact sheet (DIR/sheet.png, beside the page) and the scene's settings. Nothing
// is fetched (no script, font or stylesheet; three.js is inside the page), so the page opens from
// disk.
//
// The page is the same bytes for the same scene and seed, as it holds no date and no wall-clock
// timing (those stay in the terminal report and timing.csv).

#include <optional>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "render/frame_recorder.hpp"
#include "report/bundled_three_js.hpp"
#include "report/report_viewer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// The contact sheet as the page shows it, an image file beside the page.
struct SheetFigure {
  std::string file;  // relative to the page ("sheet.png")
  int width_px = 0;
  int height_px = 0;
  std::vector<int> steps;  // the columns
};

// The steps the report's contact sheet shows (the --sheet default, 10%, 20%, 25% and 35% of the
// run). Record these with a FrameRecorder during the comparison.
std::vector<int> report_sheet_steps(const Scene& scene);

// What the numbers say, as plain-text paragraphs (escape them for HTML): what happened without
// control, which strategy met the thesis's goals (best_for_thesis_goals) and at what cost in
// deviation and occlusion against `none`, or that none met them.
std::vector<std::string> report_reading(const std::vector<Evaluation>& runs);

// The whole page. `sheet` is the contact sheet beside it, or nullopt for none. `viewer_section` is
// the 3D view's section (viewer_section_html), or empty for none.
std::string html_report(const Scene& scene, const std::vector<Evaluation>& runs,
                        const std::optional<SheetFigure>& sheet,
                        const std::string& viewer_section = {});

// The strategies the 3D view shows side by side at first, none (or the first run) on the left and
// the best for the thesis's goals (or the next run) on the right, empty for one run.
std::pair<std::string, std::string> report_viewer_pair(const std::vector<Evaluation>& runs);

// Draws the contact sheet from `recorder` (the runs' strategies in rows, report_sheet_steps in
// columns) into DIR/sheet.png, writes the page's table as DIR/table.csv, then
// DIR/index.html with the 3D view of `viewer`'s runs drawn by `three` (without three.js, the
// section says why instead); the three files appear together or not at all. DIR must exist
// (OutputFolder).
// Returns the paths written.
std::vector<std::string> write_html_report(const std::string& dir, const Scene& scene,
                                           const std::vector<Evaluation>& runs,
                                           const FrameRecorder& recorder,
                                           const ViewerRecorder& viewer,
                                           const BundledThreeJs& three);

}  // namespace fragsim
