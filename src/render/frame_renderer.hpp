#pragma once
// What the camera sees at one step, a snapshot (live or recorded) drawn by the software rasteriser:
// the sky, the ground plane (a checker of 1 m squares out to the far plane, fading with the
// distance), and every fragment as a box or its convex hull (FragmentState::shape), each face with
// flat Lambert shading and the fragment's own colour, clipped at that step's near plane with back
// faces culled (a fragment crossing it shows its cut as a hole). Optional overlays go on top: the
// edge candidates' outlines, the applied forces as arrows, the near plane's cut through each
// fragment it crosses and the occlusion metric's central region. A snapshot with opacities (the
// `fade` strategy) has each fragment drawn dithered by its opacity (Rasterizer::set_opacity); an
// invisible one is not drawn and shows no cut.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "render/image.hpp"
#include "render/rasterizer.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

struct FrameOverlays {
  bool candidates = false;  // outline (visible edges) of the fragments the strategy flagged
  bool forces = false;      // arrow from each pushed fragment's centre, length ~ force / mass
  bool central = false;     // the central region of the occlusion metric (MetricsDef)
  bool cuts = false;        // where the near plane cuts a fragment, outlined
};

struct FrameStyle {
  int width_px = 640;
  int height_px = 360;  // the frustum fills the image whatever its shape (as a GPU viewport)
  FrameOverlays overlays;
  double arrow_m_per_mps2 = 0.05;  // arrow length per unit of acceleration (10 m/s^2 -> 0.5 m)
};

// The base colour of fragment `index`, a hash of it, so the same in every run and strategy.
Rgb fragment_colour(int index);
// A face's colour is flat Lambert shading of `base` for the face's outward normal (world, unit),
// lit from a fixed direction above, left of and behind a camera looking down -z, plus ambient.
Rgb shaded_colour(Rgb base, const Eigen::Vector3d& world_normal);

// The overlays' colours.
inline constexpr Rgb kCandidateColour{0, 255, 255};
inline constexpr Rgb kForceColour{255, 0, 255};
inline constexpr Rgb kCutColour{255, 32, 32};
inline constexpr Rgb kCentralColour{255, 255, 255};

class FrameRenderer {
 public:
  // Keeps the ground height and the central region's share from the scene; the style is fixed.
  FrameRenderer(const Scene& scene, const FrameStyle& style);

  // Draws the snapshot with its own camera pose (and near distance). Deterministic, so the same
  // snapshot gives the same pixels.
  Image render(const StepSnapshot& snap);

  const FrameStyle& style() const { return style_; }

 private:
  void draw_background(Image& image, const CameraPose& camera);
  void draw_faces(int index, const FragmentState& f);
  void draw_outline(const FragmentState& f);
  void draw_cut(Image& image, const FragmentState& f);
  void draw_force(Image& image, const FragmentState& f, const Eigen::Vector3d& force_N);
  // The same for a convex piece (FragmentState::shape), its faces, outline and cut.
  void draw_hull_faces(int index, const FragmentState& f);
  void draw_hull_outline(const FragmentState& f);
  void draw_hull_cut(Image& image, const FragmentState& f);

  FrameStyle style_;
  bool ground_ = true;
  double ground_height_m_ = 0.0;
  double central_share_ = 0.5;
  int line_px_ = 1;
  Rasterizer raster_;
  std::vector<Eigen::Vector3d> hull_vertices_;  // scratch, reused from piece to piece
  std::vector<ScreenPoint> hull_cut_points_;
};

}  // namespace fragsim
