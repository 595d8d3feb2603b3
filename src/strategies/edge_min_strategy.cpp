#include "strategies/edge_min_strategy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "strategies/first_root.hpp"
#include "strategies/force_cap.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// c0 + c1 t + c2 t^2: one camera-space coordinate of the relative path.
struct Coord {
  double c0, c1, c2;
  double at(double t) const { return c0 + t * (c1 + t * c2); }
};

// A set of at most a few disjoint time intervals, in order.
struct Intervals {
  std::array<std::array<double, 2>, 4> span{};
  int n = 0;
  bool empty() const { return n == 0; }
};

// The times in [0, horizon] where lo <= coord(t) <= hi.
Intervals within(const Coord& c, double lo, double hi, double horizon) {
  // 0, at most two roots per bound, the horizon; kept sorted by insertion.
  std::array<double, 6> pts{};
  int np = 0;
  auto add = [&pts, &np](double v) {
    int k = np++;
    for (; k > 0 && pts[static_cast<std::size_t>(k - 1)] > v; --k) {
      pts[static_cast<std::size_t>(k)] = pts[static_cast<std::size_t>(k - 1)];
    }
    pts[static_cast<std::size_t>(k)] = v;
  };
  add(0.0);
  add(horizon);
  for (double bound : {lo, hi}) {
    for (double r : list_real_roots({c.c0 - bound, c.c1, c.c2, 0.0, 0.0}, 0.0, horizon)) {
      if (np < static_cast<int>(pts.size())) add(r);
    }
  }
  Intervals out;
  for (int i = 0; i + 1 < np; ++i) {
    const double a = pts[static_cast<std::size_t>(i)];
    const double b = pts[static_cast<std::size_t>(i + 1)];
    const double mid = c.at(0.5 * (a + b));
    const bool inside = b > a ? (mid >= lo && mid <= hi) : false;
    if (!inside) continue;
    if (out.n > 0 && out.span[out.n - 1][1] >= a) {
      out.span[out.n - 1][1] = b;  // contiguous with the previous piece
    } else if (out.n < 4) {
      out.span[out.n++] = {a, b};
    }
  }
  // A path that starts inside has t = 0 in the set even when the first piece is degenerate.
  const double v0 = c.at(0.0);
  if (out.n == 0 && v0 >= lo && v0 <= hi) out.span[out.n++] = {0.0, 0.0};
  return out;
}

Intervals intersect(const Intervals& a, const Intervals& b) {
  Intervals out;
  for (int i = 0; i < a.n; ++i) {
    for (int j = 0; j < b.n; ++j) {
      const double lo = std::max(a.span[i][0], b.span[j][0]);
      const double hi = std::min(a.span[i][1], b.span[j][1]);
      if (lo <= hi && out.n < 4) out.span[out.n++] = {lo, hi};
    }
  }
  return out;
}

// The least acceleration along +axis (sign = +1) or -axis (sign = -1) that keeps coordinate
// `c` beyond `half` (outside [-half, half] on that side) at every time in `when`: the largest,
// over those times, of the gap still to cover divided by the displacement a unit acceleration
// gives by then. Sampled at nine points per interval; re-solving every step corrects the rest.
double least_accel(const Coord& c, double half, int sign, const Intervals& when, double dt) {
  double need = 0.0;
  for (int i = 0; i < when.n; ++i) {
    const double a = when.span[i][0];
    const double b = when.span[i][1];
    for (int k = 0; k <= 8; ++k) {
      const double t = a + (b - a) * k / 8.0;
      const double gap = half - sign * c.at(t);  // > 0: still inside on that side
      if (gap <= 0.0) continue;
      const double per_accel = EdgeMinStrategy::displacement_per_accel(t, dt);
      if (per_accel <= 0.0) return kInf;  // inside the box's shadow right now: no push helps
      need = std::max(need, gap / per_accel);
    }
  }
  return need;
}

}  // namespace

void EdgeMinStrategy::step(const StepContext& ctx, StepOutput& out) {
  const CameraPose& cam = ctx.camera;
  const Eigen::Vector3d& body = ctx.camera_body_half_m;
  const double half_w_m = std::max(cam.near_half_width_m(), body.x()) + params_.margin_m;
  const double half_h_m = std::max(cam.near_half_height_m(), body.y()) + params_.margin_m;
  const double front_m = std::max(cam.near_m, body.z()) + params_.margin_m;
  const double back_m = body.z() + params_.margin_m;
  const double horizon_s = std::max(ctx.duration_s - ctx.t_s, ctx.dt_s);
  const Eigen::Vector3d half_g = 0.5 * cam.dir_to_camera(ctx.gravity_mps2);

  // Cheap rejection of every fragment at once before any root solve (cheap_rejection.hpp): a path
  // that never has all three coordinates inside the box grown by the fragment's radius, with a
  // margin the solves below agree with, is no threat. Most fragments end here.
  const BoxFrame frame{cam.eye_m, {cam.right, cam.up, cam.forward}, ctx.camera_velocity_mps};
  const std::span<const char> clears =
      clearance_.run(ctx.fragments, frame, half_g, Eigen::Vector3d(-half_w_m, -half_h_m, -back_m),
                     Eigen::Vector3d(half_w_m, half_h_m, front_m), horizon_s);

  for (std::size_t i = 0; i < ctx.fragments.size(); ++i) {
    if (clears[i]) continue;
    const FragmentState& f = ctx.fragments[i];
    const Eigen::Vector3d d = cam.to_camera(f.position_m);
    const Eigen::Vector3d w = cam.dir_to_camera(f.velocity_mps - ctx.camera_velocity_mps);
    const double r = f.radius_m;
    // Cheap rejection: in front of the box and moving away in depth, with gravity not pulling it
    // back (the camera's forward axis tilted toward the ground can).
    if (d.z() > front_m + r && w.z() >= 0.0 && half_g.z() >= 0.0) continue;
    const Coord x{d.x(), w.x(), half_g.x()};
    const Coord y{d.y(), w.y(), half_g.y()};
    const Coord z{d.z(), w.z(), half_g.z()};
    const Intervals in_z = within(z, -back_m - r, front_m + r, horizon_s);
    if (in_z.empty()) continue;
    const Intervals in_x = within(x, -half_w_m - r, half_w_m + r, horizon_s);
    if (in_x.empty()) continue;
    const Intervals in_y = within(y, -half_h_m - r, half_h_m + r, horizon_s);
    if (in_y.empty()) continue;
    const Intervals in_xz = intersect(in_x, in_z);
    const Intervals in_yz = intersect(in_y, in_z);
    if (intersect(in_xz, in_y).empty()) continue;  // the path misses the box
    out.candidates.push_back(static_cast<int>(i));

    // The four ways out, each the least push along one screen axis.
    const std::array<double, 4> need{least_accel(y, half_h_m + r, +1, in_xz, ctx.dt_s),
                                     least_accel(y, half_h_m + r, -1, in_xz, ctx.dt_s),
                                     least_accel(x, half_w_m + r, +1, in_yz, ctx.dt_s),
                                     least_accel(x, half_w_m + r, -1, in_yz, ctx.dt_s)};
    const std::array<Eigen::Vector3d, 4> dir{cam.up, -cam.up, cam.right, -cam.right};
    const auto best =
        static_cast<std::size_t>(std::min_element(need.begin(), need.end()) - need.begin());
    // Already inside the box's shadow on every side: nothing finite helps; push toward the
    // nearest way out at the cap and let the report count it if it still hits.
    const double accel = std::isfinite(need[best]) ? need[best] : 2.0 * params_.a_max_mps2 + 1.0;
    if (accel <= 0.0) continue;
    apply_capped(out, static_cast<int>(i), f.mass_kg * accel * dir[best], f.mass_kg,
                 params_.a_max_mps2);
  }
}

}  // namespace fragsim
