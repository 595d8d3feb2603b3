#include "control/strategies/collision_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "control/geometry/time_to_plane.hpp"
#include "control/geometry/vec3_sums.hpp"
#include "control/geometry/work_space.hpp"
#include "control/strategies/lanes.hpp"

namespace fragsim {

BallisticPath predicted_path(const FragmentState& f, const Eigen::Vector3d& g_mps2, Predictor p,
                             double dt_s) {
  BallisticPath path{f.position_m, f.velocity_mps, g_mps2};
  if (p == Predictor::kDiscrete) path.v0_mps += 0.5 * dt_s * g_mps2;
  return path;
}

double time_to_horizon(const BallisticPath& path, double y_ref_m, double fallback_s) {
  if (!std::isfinite(y_ref_m)) return fallback_s;  // horizon = ground without a ground
  AxisQuadratic height = path.axis(1);
  height.c0 -= y_ref_m;
  return time_to_plane_s(height).value_or(fallback_s);
}

Quartic ball_contact_quartic(const BallisticPath& path, const Eigen::Vector3d& centre_m,
                             double r0_m, double growth_mps) {
  const BallisticPath rel = path.relative_to(centre_m);
  const Eigen::Vector3d& d = rel.p0_m;
  const Eigen::Vector3d& v = rel.v0_mps;
  const Eigen::Vector3d a = rel.half_accel_mps2();
  return {dot3(d, d) - r0_m * r0_m, 2.0 * dot3(d, v) - 2.0 * r0_m * growth_mps,
          dot3(v, v) + 2.0 * dot3(d, a) - growth_mps * growth_mps, 2.0 * dot3(v, a), dot3(a, a)};
}

namespace {

// The reachable ball for a path that lands after t_horizon has radius r0 + growth tau.
struct BallSize {
  double r0_m;
  double growth_mps;
};
BallSize ball_size(const ReachModel& model, double t_horizon_s) {
  if (model.reach == Reach::kThesis) {
    return {model.radius_m + model.max_speed_mps * t_horizon_s, 0.0};  // R = V_c (t_G - t), (3.2)
  }
  return {model.radius_m, model.max_speed_mps};
}

}  // namespace

ContactPrediction predict_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                  const ReachModel& model, double t_horizon_s) {
  // Cheap rejection before any root solve (ball_clearance.hpp), as most paths that stay clear of
  // the ball are settled by Q's Bernstein coefficients, with a margin the solve agrees with.
  const BallSize ball = ball_size(model, t_horizon_s);
  if (path_clears_ball(path.relative_to(camera_m), ball.r0_m, ball.growth_mps, t_horizon_s)) {
    ContactPrediction out;
    out.t_horizon_s = t_horizon_s;
    return out;
  }
  return solve_contact(path, camera_m, model, t_horizon_s);
}

namespace {

// solve_contact up to its root search. False when the margin-free rejection settles the path clear,
// else true with the quartic whose first non-positive point in [0, t_horizon] is the entry.
bool contact_quartic(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                     const ReachModel& model, double t_horizon_s, Quartic& out) {
  const BallSize ball = ball_size(model, t_horizon_s);
  const double r0 = ball.r0_m;
  const double growth = ball.growth_mps;
  // This rejection decides without a margin. The fragment closes on the centre at most at
  // |V| + |g| tau while the ball grows at `growth`, so if even the closest it could get by the
  // horizon stays outside the ball then, no time in between is inside (a path grazing the ball
  // within rounding is "clear" here, where the solve could call it a touch).
  const double horizon_s = std::max(t_horizon_s, 0.0);
  const double closest_m = norm3(path.p0_m - camera_m) - norm3(path.v0_mps) * horizon_s -
                           0.5 * norm3(path.accel_mps2) * horizon_s * horizon_s;
  if (closest_m > r0 + growth * horizon_s) return false;
  out = ball_contact_quartic(path, camera_m, r0, growth);
  return true;
}

}  // namespace

ContactPrediction solve_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                const ReachModel& model, double t_horizon_s) {
  ContactPrediction out;
  out.t_horizon_s = t_horizon_s;
  Quartic q;
  if (!contact_quartic(path, camera_m, model, t_horizon_s, q)) return out;
  const auto t = first_nonpositive(q, 0.0, t_horizon_s);
  if (t) {
    out.candidate = true;
    out.t_contact_s = *t;
  }
  return out;
}

double ContactQuery::t_horizon_s(const BallisticPath& p) const {
  // t_G never reaches past the cap (edge's horizon_cap_s, or the shot's end).
  return std::min(time_to_horizon(p, y_ref_m, remaining_s), remaining_s);
}

ContactPrediction ContactQuery::predict(const FragmentState& f) const {
  const BallisticPath p = path(f);
  return predict_contact(p, camera_m, model(f), t_horizon_s(p));
}

namespace {

// time_to_horizon then the cap, for two paths at once (the same formula, so the same results),
// where y(tau) - y_ref = a tau^2 + b tau + c, with a the same for both.
lanes::Lanes capped_time_to_horizon(double a, lanes::Lanes b, lanes::Lanes c, double remaining_s) {
  const lanes::Lanes fallback = lanes::broadcast(remaining_s);
  return lanes::min(time_to_plane_s<lanes::LaneOps>(a, b, c, fallback), fallback);
}

}  // namespace

void ContactPredictor::reserve(std::size_t n) {
  const std::size_t padded = n + n % lanes::kWidth;
  reserve_touched(screened_, n);
  for (auto* x : {&vy_, &py_, &radius_, &t_horizon_}) reserve_touched(*x, padded);
  reserve_touched(quartics_, n);
  reserve_touched(quartic_horizons_s_, n);
  reserve_touched(quartic_of_, n);
  reserve_touched(quartic_guess_s_, n);
  reserve_touched(out_, n);
  roots_.reserve(n);
  clearance_.reserve(n);
}

std::span<const ContactPrediction> ContactPredictor::predict(
    const ContactQuery& query, std::span<const FragmentState> fragments, std::span<const int> which,
    std::span<const char> screen, std::span<const double> guess_s, double guess_half_width_s) {
  const auto fragment = [&](std::size_t k) -> const FragmentState& {
    return fragments[static_cast<std::size_t>(which[k])];
  };
  out_.assign(which.size(), ContactPrediction{});
  screened_.clear();
  quartics_.clear();
  quartic_horizons_s_.clear();
  quartic_of_.clear();
  quartic_guess_s_.clear();
  // solve_contact for out_[k], whose t_horizon_s is set, up to its root search.
  const auto defer_solve = [&](std::size_t k, const BallisticPath& p, const ReachModel& model) {
    Quartic q;
    const double th = out_[k].t_horizon_s;
    if (!contact_quartic(p, query.camera_m, model, th, q)) return;
    quartics_.push_back(q);
    quartic_horizons_s_.push_back(th);
    quartic_of_.push_back(static_cast<int>(k));
    quartic_guess_s_.push_back(guess_s.empty() ? std::numeric_limits<double>::quiet_NaN()
                                               : guess_s[k]);
  };
  for (std::size_t k = 0; k < which.size(); ++k) {
    if (screen.empty() || screen[k]) {
      screened_.push_back(static_cast<int>(k));
      continue;
    }
    const BallisticPath p = query.path(fragment(k));
    out_[k].t_horizon_s = query.t_horizon_s(p);
    defer_solve(k, p, query.model(fragment(k)));
  }
  // The screened ones go one pass at a time over arrays (their paths, t_G two at a time and the
  // balls), then the rejection runs over all of them.
  const std::size_t n = screened_.size();
  const std::size_t padded = n + n % lanes::kWidth;
  for (auto* x : {&vy_, &py_, &radius_, &t_horizon_}) x->resize(padded);
  clearance_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const FragmentState& f = fragment(static_cast<std::size_t>(screened_[j]));
    const BallisticPath p = query.path(f);
    clearance_.set_path(j, p.p0_m - query.camera_m, p.v0_mps);
    vy_[j] = p.v0_mps.y();
    py_[j] = p.p0_m.y();
    radius_[j] = query.model(f).radius_m;
  }
  if (padded > n) {
    vy_[n] = 0.0;
    py_[n] = 0.0;
  }
  const double a_y = 0.5 * query.gravity_mps2.y();
  const lanes::Lanes y_ref = lanes::broadcast(query.y_ref_m);
  for (std::size_t j = 0; j < padded; j += lanes::kWidth) {
    const lanes::Lanes th = capped_time_to_horizon(a_y, lanes::load(&vy_[j]),
                                                   lanes::load(&py_[j]) - y_ref, query.remaining_s);
    lanes::store(&t_horizon_[j], th);
  }
  // As in time_to_horizon, without a ground to fall to (y_ref = -inf) t_G is the fallback.
  if (!std::isfinite(query.y_ref_m))
    std::fill(t_horizon_.begin(), t_horizon_.end(), query.remaining_s);
  const bool thesis = query.reach == Reach::kThesis;
  for (std::size_t j = 0; j < n; ++j) {
    const double th = t_horizon_[j];
    out_[static_cast<std::size_t>(screened_[j])].t_horizon_s = th;
    clearance_.set_ball(j, thesis ? radius_[j] + query.max_speed_mps * th : radius_[j], th);
  }
  const double growth_mps = thesis ? 0.0 : query.max_speed_mps;
  const std::span<const char> clears = clearance_.run(0.5 * query.gravity_mps2, growth_mps);
  for (std::size_t j = 0; j < n; ++j) {
    if (clears[j]) continue;
    const auto k = static_cast<std::size_t>(screened_[j]);
    const FragmentState& f = fragment(k);
    defer_solve(k, query.path(f), query.model(f));
  }
  // The root searches of all of them together (the same answers as solve_contact's one by one).
  const std::span<const std::optional<double>> roots =
      guess_s.empty()
          ? roots_.run(quartics_, 0.0, quartic_horizons_s_)
          : roots_.run(quartics_, 0.0, quartic_horizons_s_, quartic_guess_s_, guess_half_width_s);
  for (std::size_t q = 0; q < roots.size(); ++q) {
    if (!roots[q]) continue;
    ContactPrediction& pred = out_[static_cast<std::size_t>(quartic_of_[q])];
    pred.candidate = true;
    pred.t_contact_s = *roots[q];
  }
  return out_;
}

std::optional<Eigen::Vector2d> near_plane_crossing(const BallisticPath& path,
                                                   const CameraPose& camera,
                                                   const Eigen::Vector3d& camera_velocity_mps,
                                                   double horizon_s) {
  const BallisticPath rel = in_camera_frame(path, camera, camera_velocity_mps);
  const AxisQuadratic depth_m = rel.axis(2);
  if (depth_m.c0 <= camera.near_m) return std::nullopt;  // already at or behind the near plane
  // depth(tau) - near <= 0 first happens at the crossing.
  const Quartic depth{depth_m.c0 - camera.near_m, depth_m.c1, depth_m.c2, 0.0, 0.0};
  const auto tau = first_nonpositive(depth, 0.0, horizon_s);
  if (!tau) return std::nullopt;
  return rel.at(*tau).head<2>();
}

Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point) {
  return nearest_edge_direction(camera, point, camera.near_half_width_m(),
                                camera.near_half_height_m());
}

Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point,
                                       double half_width_m, double half_height_m) {
  const double to_side = half_width_m - std::abs(point.x());
  const double to_top_bottom = half_height_m - std::abs(point.y());
  if (to_side < to_top_bottom)
    return point.x() < 0.0 ? Eigen::Vector3d(-camera.right) : camera.right;
  return point.y() < 0.0 ? Eigen::Vector3d(-camera.up) : camera.up;
}

namespace {

// Guards of crossing_edge_direction, relative to the sizes involved. Both the root solver and the
// closed form are good to ~1e-15 of them (first_root.hpp); anything within a million times that
// of a decision is decided by near_plane_crossing itself.
constexpr double kGuard = 1e-9;
// A double root (a depth that only grazes the near plane) is left to the solver below this ratio of
// the discriminant's root to its terms, as the closed form loses digits there.
constexpr double kDoubleRoot = 1e-4;

// The first tau in [0, horizon] where c0 + c1 tau + c2 tau^2 <= 0, given c0 > 0. It is the
// crossing, kNone, or kDoubt when the answer is within the guards of changing.
enum class Crossing { kAt, kNone, kDoubt };
struct DepthRoot {
  Crossing kind;
  double tau_s = 0.0;
  double error_s = 0.0;  // a generous bound on |tau - the solver's tau|
};

DepthRoot depth_root(double c0, double c1, double c2, double horizon_s) {
  const double size =
      std::abs(c0) + std::abs(c1) * horizon_s + std::abs(c2) * horizon_s * horizon_s;
  if (!std::isfinite(size) || !(horizon_s >= 0.0) || !(c0 > 1e3 * kGuard * size)) {
    return {Crossing::kDoubt};
  }
  // No crossing when the depth's minimum over [0, horizon], at the ends or at a convex depth's
  // vertex inside, stays clear of the plane.
  double lowest = std::min(c0, c0 + horizon_s * (c1 + horizon_s * c2));
  if (c2 > 0.0 && -c1 > 0.0 && -c1 < 2.0 * c2 * horizon_s) lowest = c0 - c1 * c1 / (4.0 * c2);
  if (lowest > 1e3 * kGuard * size) return {Crossing::kNone};
  // The root is linear, or from the stable quadratic formula. With c0 > 0 the first entry is the
  // smaller root of a convex depth (both roots then have one sign) and the larger of a concave one.
  double tau = 0.0;
  double slope = 0.0;  // |depth'(tau)|
  if (c2 == 0.0) {
    if (!(c1 < 0.0)) return {Crossing::kDoubt};
    tau = -c0 / c1;
    slope = -c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    const double root = std::sqrt(std::max(disc, 0.0));
    if (!(root > kDoubleRoot * (std::abs(c1) + 2.0 * std::sqrt(std::abs(c2 * c0))))) {
      return {Crossing::kDoubt};
    }
    const double q = -0.5 * (c1 + std::copysign(root, c1));
    const double r1 = q / c2;
    const double r2 = c0 / q;  // q != 0, as |q| >= root / 2 > 0
    tau = c2 > 0.0 ? std::min(r1, r2) : std::max(r1, r2);
    slope = root;
  }
  const double error_s = kGuard * (size / slope + tau);
  if (!(tau > error_s && tau + error_s < horizon_s)) return {Crossing::kDoubt};
  return {Crossing::kAt, tau, error_s};
}

}  // namespace

Eigen::Vector3d crossing_edge_direction(const BallisticPath& path, const CameraPose& camera,
                                        const Eigen::Vector3d& camera_velocity_mps,
                                        double horizon_s, const Eigen::Vector3d& now_m,
                                        double half_width_m, double half_height_m) {
  // The same quantities near_plane_crossing computes.
  const BallisticPath rel = in_camera_frame(path, camera, camera_velocity_mps);
  const Eigen::Vector3d& d = rel.p0_m;
  const Eigen::Vector3d& w = rel.v0_mps;
  const Eigen::Vector3d a = rel.half_accel_mps2();
  const auto exact = [&]() {
    Eigen::Vector2d screen;
    if (auto crossing = near_plane_crossing(path, camera, camera_velocity_mps, horizon_s)) {
      screen = *crossing;
    } else {
      screen = camera.to_camera(now_m).head<2>();
    }
    return nearest_edge_direction(camera, screen, half_width_m, half_height_m);
  };
  const auto at_now = [&]() {
    return nearest_edge_direction(camera, camera.to_camera(now_m).head<2>(), half_width_m,
                                  half_height_m);
  };
  if (d.z() <= camera.near_m) return at_now();
  const DepthRoot root = depth_root(d.z() - camera.near_m, w.z(), a.z(), horizon_s);
  if (root.kind == Crossing::kNone) return at_now();
  if (root.kind == Crossing::kDoubt) return exact();
  // The crossing point, and how far the solver's could lie from it.
  const double s = root.tau_s;
  const Eigen::Vector3d at_s = rel.at(s);
  const double x = at_s.x();
  const double y = at_s.y();
  const double reach_s = s + root.error_s;
  const double error_x = (std::abs(w.x()) + 2.0 * std::abs(a.x()) * reach_s) * root.error_s +
                         kGuard * (std::abs(d.x()) + std::abs(w.x()) * s + std::abs(a.x()) * s * s);
  const double error_y = (std::abs(w.y()) + 2.0 * std::abs(a.y()) * reach_s) * root.error_s +
                         kGuard * (std::abs(d.y()) + std::abs(w.y()) * s + std::abs(a.y()) * s * s);
  const double to_side = half_width_m - std::abs(x);
  const double to_top_bottom = half_height_m - std::abs(y);
  const double error_edge = error_x + error_y + kGuard * (half_width_m + half_height_m);
  if (!(std::abs(to_side - to_top_bottom) > error_edge)) return exact();
  if (to_side < to_top_bottom) {
    if (!(std::abs(x) > error_x)) return exact();
    return x < 0.0 ? Eigen::Vector3d(-camera.right) : camera.right;
  }
  if (!(std::abs(y) > error_y)) return exact();
  return y < 0.0 ? Eigen::Vector3d(-camera.up) : camera.up;
}

}  // namespace fragsim
