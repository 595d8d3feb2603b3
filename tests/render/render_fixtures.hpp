#pragma once
// The render tests' view: a 90-degree, square camera at the origin looking down -z
// (test::square_camera), so a point at depth z and lateral offset x lands on column
// 100 + 100 x / z of a 200-pixel image, and row 100 - 100 y / z; a scene without ground; snapshots
// and frames of it.

#include <vector>

#include "render/frame_renderer.hpp"
#include "render/image.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"
#include "support/test_scenes.hpp"

namespace fragsim::test {

inline constexpr int kSize = 200;  // pixels; 100 pixels per unit of x / z

// A scene without ground, so the background is only sky.
inline Scene sky_scene() {
  Scene s;
  s.ground.enabled = false;
  return s;
}

inline FrameStyle square_style() {
  FrameStyle style;
  style.width_px = kSize;
  style.height_px = kSize;
  return style;
}

inline StepSnapshot snapshot(const CameraPose& cam, const std::vector<FragmentState>& frags) {
  StepSnapshot s;
  s.camera = cam;
  s.fragments = frags;
  return s;
}

inline Image render(const std::vector<FragmentState>& frags,
                    const CameraPose& cam = square_camera(), const Scene& scene = sky_scene(),
                    const FrameStyle& style = square_style()) {
  FrameRenderer r(scene, style);
  return r.render(snapshot(cam, frags));
}

}  // namespace fragsim::test
