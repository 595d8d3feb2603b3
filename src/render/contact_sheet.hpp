#pragma once
// A contact sheet has one row per strategy and one column per chosen step, each cell a small frame
// of that strategy's run at that step, with the strategy's name at the row's start and the time
// above each column.

#include <string>
#include <vector>

#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "render/image.hpp"
#include "sim/scene.hpp"

namespace fragsim {

struct SheetStyle {
  int cell_width_px = 320;
  int cell_height_px = 0;                   // 0 for the camera's aspect (180 for 320 at 16:9)
  FrameOverlays overlays = {.cuts = true};  // a small frame's hole is easy to miss
};

// The default columns are 10%, 20%, 25% and 35% of a run of `step_count` steps, rounded, repeats
// dropped, as the debris of the shipped scenes reaches the camera at 10-30% of the run (front.ini's
// is cut by the near plane from step 41 to 49 of 180, thesis125.ini 35-37 of 180, close.ini 12-17
// of 120, distance.ini 61-62 of 210).
std::vector<int> default_sheet_steps(int step_count);

// Frames the recorder lacks are left as empty cells.
Image contact_sheet(const Scene& scene, const FrameRecorder& recorder,
                    const std::vector<std::string>& strategies, const std::vector<int>& steps,
                    const SheetStyle& style = {});

}  // namespace fragsim
