#include "metrics/exit_metric.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fragsim {

std::string_view exit_name(Exit exit) {
  switch (exit) {
    case Exit::kNone:
      return "none";
    case Exit::kTop:
      return "top";
    case Exit::kBottom:
      return "bottom";
    case Exit::kLeft:
      return "left";
    case Exit::kRight:
      return "right";
    case Exit::kNear:
      return "near";
    case Exit::kStayed:
      return "stayed";
  }
  return "none";
}

namespace {

bool on_screen(const CameraPose& camera, const Eigen::Vector3d& c_m) {
  const double z = c_m.z();
  return z >= camera.near_m && z <= camera.far_m && std::abs(c_m.x()) <= camera.half_width_at(z) &&
         std::abs(c_m.y()) <= camera.half_height_at(z);
}

// The exit of a fragment off screen at camera-space centre c_m. Past the far plane no border is
// crossed; it goes on the border it is closest to, as the same rule gives.
Exit classify(const CameraPose& camera, const Eigen::Vector3d& c_m) {
  const double z = c_m.z();
  if (z < camera.near_m) return Exit::kNear;
  const Eigen::Vector2d n = camera.frustum().normalized(c_m);
  const double nx = n.x();
  const double ny = n.y();
  // A tie (a corner) goes to the side border; the split is arbitrary but deterministic.
  if (std::abs(ny) > std::abs(nx)) return ny > 0.0 ? Exit::kTop : Exit::kBottom;
  return nx < 0.0 ? Exit::kLeft : Exit::kRight;
}

// Squared distance from the eye (the origin) to the segment a-b.
double segment_eye_distance2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0.0 ? std::clamp(-a.dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + s * d).squaredNorm();
}

}  // namespace

void ExitMetric::begin(const RunInfo& info, const StepSnapshot& initial) {
  const auto n = static_cast<std::size_t>(info.fragment_count);
  assert(initial.fragments.size() == n);
  prev_.resize(n);
  on_screen_.assign(n, 0);
  last_exit_.assign(n, Exit::kNone);
  passed_close_.assign(n, 0);
  touched_.assign(n, 0);
  pushed_.assign(n, 0);
  prev_state_.assign(n, FragmentState{});
  prev_camera_ = initial.camera;
  const double near_miss2 = near_miss_m_ * near_miss_m_;
  for (std::size_t i = 0; i < n; ++i) {
    const FragmentState& f = initial.fragments[i];
    const SweepEnd e = sweep_end(initial.camera, f);
    prev_[i] = e;
    if (f.shape) prev_state_[i] = f;
    on_screen_[i] = on_screen(initial.camera, e.centre_m);
    passed_close_[i] = e.centre_m.squaredNorm() <= near_miss2;
    // A fragment spawned touching the camera was never a clean pass, whatever it does next.
    touched_[i] = meets_near(initial.camera, f, initial.camera, f, e, e) ||
                  sweep_meets_camera_body(e, e, initial.camera_body_half_m);
  }
}

bool ExitMetric::meets_near(const CameraPose& camera_a, const FragmentState& a,
                            const CameraPose& camera_b, const FragmentState& b, const SweepEnd& ea,
                            const SweepEnd& eb) {
  // The hull's box first, as it is cheap and clears all but the pieces at the lens.
  if (!sweep_meets_near_rectangle(ea, eb)) return false;
  return !b.shape || hull_sweep_.meets_near_rectangle(camera_a, a, camera_b, b);
}

void ExitMetric::observe(const StepSnapshot& snap) {
  assert(snap.fragments.size() == prev_.size());
  const double near_miss2 = near_miss_m_ * near_miss_m_;
  for (std::size_t i = 0; i < prev_.size(); ++i) {
    const FragmentState& f = snap.fragments[i];
    const SweepEnd now = sweep_end(snap.camera, f);
    const bool visible = on_screen(snap.camera, now.centre_m);
    if (on_screen_[i] && !visible) last_exit_[i] = classify(snap.camera, now.centre_m);
    on_screen_[i] = visible;
    // Sampled positions alone would miss a fast fragment that passes the eye between snapshots.
    if (!passed_close_[i] && segment_eye_distance2(prev_[i].centre_m, now.centre_m) <= near_miss2) {
      passed_close_[i] = 1;
    }
    if (!touched_[i] && (meets_near(prev_camera_, prev_state_[i], snap.camera, f, prev_[i], now) ||
                         sweep_meets_camera_body(prev_[i], now, snap.camera_body_half_m))) {
      touched_[i] = 1;
    }
    prev_[i] = now;
    if (f.shape) prev_state_[i] = f;
  }
  prev_camera_ = snap.camera;
  for (const AppliedForce& f : snap.forces) {
    assert(f.fragment >= 0 && static_cast<std::size_t>(f.fragment) < pushed_.size());
    pushed_[static_cast<std::size_t>(f.fragment)] = 1;  // as forced_fragments counts them
  }
  for (int f : snap.camera_hits) {
    assert(f >= 0 && static_cast<std::size_t>(f) < touched_.size());
    touched_[static_cast<std::size_t>(f)] = 1;
  }
}

void ExitMetric::fill(RunSummary& s) const {
  s.exits = {};
  s.pushed_exits = {};
  s.intersections.near_misses = 0;
  for (int f = 0; f < fragments(); ++f) {
    if (pushed(f)) {
      switch (exit(f)) {
        case Exit::kNone:
          break;
        case Exit::kTop:
          ++s.pushed_exits.top;
          break;
        case Exit::kBottom:
          ++s.pushed_exits.bottom;
          break;
        case Exit::kLeft:
          ++s.pushed_exits.left;
          break;
        case Exit::kRight:
          ++s.pushed_exits.right;
          break;
        case Exit::kNear:
          ++s.pushed_exits.near;
          break;
        case Exit::kStayed:
          ++s.pushed_exits.stayed;
          break;
      }
    }
    switch (exit(f)) {
      case Exit::kNone:
        break;
      case Exit::kTop:
        ++s.exits.top;
        break;
      case Exit::kBottom:
        ++s.exits.bottom;
        break;
      case Exit::kLeft:
        ++s.exits.left;
        break;
      case Exit::kRight:
        ++s.exits.right;
        break;
      case Exit::kNear:
        ++s.exits.near;
        break;
      case Exit::kStayed:
        ++s.exits.stayed;
        break;
    }
    if (near_miss(f)) ++s.intersections.near_misses;
  }
}

}  // namespace fragsim
