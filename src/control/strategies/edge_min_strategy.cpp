#include "control/strategies/edge_min_strategy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "control/geometry/first_root.hpp"
#include "control/geometry/parabola.hpp"
#include "control/geometry/time_to_plane.hpp"
#include "control/geometry/vec3_sums.hpp"
#include "control/strategies/force_cap.hpp"
#include "control/strategies/intervals.hpp"
#include "control/strategies/parallel_ranges.hpp"
#include "control/strategies/slab_times.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The fewest exact solves a worker takes at once. A solve costs about a microsecond
// (docs/benchmarks.md), so sixteen are well worth handing to a worker.
constexpr std::int32_t kMinSolveRange = 16;

// One camera-space coordinate of the relative path, c0 + c1 t + c2 t^2.
using Coord = AxisQuadratic;

// The least acceleration along +axis (sign = +1) or -axis (sign = -1) that keeps coordinate `c`
// beyond `half` (outside [-half, half] on that side) at every time in `when`, the largest over
// those times of the gap still to cover divided by the displacement a unit acceleration gives by
// then, sampled at nine points per interval; re-solving every step corrects the rest.
double least_accel(const Coord& c, double half, int sign, const Intervals& when, double dt) {
  double need = 0.0;
  for (int i = 0; i < when.n; ++i) {
    const double a = when.span[i][0];
    const double b = when.span[i][1];
    for (int k = 0; k <= 8; ++k) {
      const double t = a + (b - a) * k / 8.0;
      const double gap = half - sign * c.at(t);  // > 0 while still inside on that side
      if (gap <= 0.0) continue;
      const double per_accel = EdgeMinStrategy::displacement_per_accel(t, dt);
      if (per_accel <= 0.0) return kInf;  // inside the box's shadow right now, where no push helps
      need = std::max(need, gap / per_accel);
    }
  }
  return need;
}

// The protected box around the eye, lo <= x <= hi, already grown by the fragment's radius.
struct Slabs {
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};
};

// rho(t) on one side of the protected box is how far that side can be, t after now, beyond where a
// constraint's centre puts it. The translation part is the constraint's own (0.5 A t^2 about the
// constant-velocity path, V_c t about the eye now); the turn part is the least of two bounds on how
// far a turn of the view moves that side:
// - By the chord, a point rot_m from the eye moves by at most rot_m min(angle, 2) when the view
//   turns by `angle` (at most turn t).
// - By the ball, every orientation of the box lies within rot_m of the eye (its farthest corner),
//   so no side reaches past rot_m, which is rot_m - half beyond a side `half` from the eye,
//   whatever the turn rate (docs/camera_models.md, section 2).
// Both are capped growths, so the turn part is rot_m min(turn t, cap / rot_m) with the side's
// cap = min(2 rot_m, rot_m - half) = rot_m - half, linear up to the side's knee, flat after it.
struct Inflation {
  double q1_mps = 0.0;
  double q2_mps2 = 0.0;
  double rot_m = 0.0;
  double turn_radps = 0.0;
  // The most the turn adds to each side: lo x, lo y, lo z, hi x, hi y, hi z (turn_side()).
  std::array<double, 6> turn_cap_m{};
  static std::size_t turn_side(int k, int sign) {
    return static_cast<std::size_t>(k + (sign > 0 ? 3 : 0));
  }
  double cap_m(int k, int sign) const { return turn_cap_m[turn_side(k, sign)]; }
  // Where a side's turn part stops growing (cap / (rot_m turn)); 0 for an instant turn or a side
  // the turn cannot move out, +inf without turning.
  static double knee_s(double cap_m, double rot_m, double turn_radps) {
    if (!(cap_m > 0.0)) return 0.0;
    if (!(turn_radps > 0.0)) return kInf;
    return cap_m / (rot_m * turn_radps);
  }
  double knee_s(double cap_m) const { return knee_s(cap_m, rot_m, turn_radps); }
  // One side's rho as a quadratic on one side of its knee.
  Coord piece(double cap_m, bool after_knee) const {
    if (after_knee) return {cap_m, q1_mps, q2_mps2};
    return {0.0, q1_mps + rot_m * turn_radps, q2_mps2};
  }
  double at(double t, double cap_m) const { return piece(cap_m, t >= knee_s(cap_m)).at(t); }
  // Each side's knee as in turn_cap_m (set by with_knees()), stored as the exact solve asks for
  // them on every axis of every candidate, and each is a division.
  std::array<double, 6> side_knee_s{};
  double knee_s(int k, int sign) const { return side_knee_s[turn_side(k, sign)]; }
  Inflation with_knees() const {
    Inflation out = *this;
    for (std::size_t i = 0; i < out.side_knee_s.size(); ++i) {
      out.side_knee_s[i] = knee_s(turn_cap_m[i]);
    }
    return out;
  }
};

// The turn caps of a box lo <= x <= hi about the eye (lo <= 0 <= hi) whose farthest corner is rot_m
// away, per side the chord's cap 2 rot_m or the ball's rot_m - |side|, the smaller.
std::array<double, 6> turn_caps_m(const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                                  double rot_m) {
  std::array<double, 6> cap{};
  for (int k = 0; k < 3; ++k) {
    for (const int sign : {-1, +1}) {
      const double side_m = sign > 0 ? hi_m[k] : -lo_m[k];
      cap[Inflation::turn_side(k, sign)] = std::max(0.0, std::min(2.0 * rot_m, rot_m - side_m));
    }
  }
  return cap;
}

// One region the camera is certain to stay in, as the fragment's camera-axis coordinates relative
// to the region's centre and how far the protected box can stray from there.
struct Constraint {
  std::array<Coord, 3> axis;
  const Inflation* rho;  // with its knees (Inflation::with_knees)
};

// Constraint con's grown slab on axis k over [t0, t1], a piece wholly on one side of each of its
// sides' knees (the knees are its ends).
inline Slab grown_slab(const Constraint& con, int k, const Slabs& slabs, double t0, double t1) {
  const Inflation& rho = *con.rho;
  const double m = 0.5 * (t0 + t1);
  const Coord r_lo = rho.piece(rho.cap_m(k, -1), m >= rho.knee_s(k, -1));
  const Coord r_hi = rho.piece(rho.cap_m(k, +1), m >= rho.knee_s(k, +1));
  const double lo = slabs.lo[static_cast<std::size_t>(k)];
  const double hi = slabs.hi[static_cast<std::size_t>(k)];
  return {con.axis[static_cast<std::size_t>(k)], Coord{lo - r_lo.c0, -r_lo.c1, -r_lo.c2},
          Coord{hi + r_hi.c0, r_hi.c1, r_hi.c2}};
}

// Both knees of axis k's sides at or before the start, or both at or past the end (an instant or
// unbounded turn, a short window), so the grown slab over [0, t_end] is one piece, the common case.
inline bool one_piece(const Constraint& con, int k, double t_end) {
  const double knee_lo_s = con.rho->knee_s(k, -1);
  const double knee_hi_s = con.rho->knee_s(k, +1);
  return (knee_lo_s <= 0.0 && knee_hi_s <= 0.0) || (knee_lo_s >= t_end && knee_hi_s >= t_end);
}

// The times in [0, t_end] at which coordinate `k` is inside constraint `con`'s grown slab, found
// piece by piece between the knees, where both bounds are single quadratics.
Intervals within_grown(const Constraint& con, int k, const Slabs& slabs, double t_end) {
  const auto piece = [&](double t0, double t1) {
    const Slab s = grown_slab(con, k, slabs, t0, t1);
    return slab_times(s.c, s.lo, s.hi, t0, t1);
  };
  if (one_piece(con, k, t_end)) return piece(0.0, t_end);
  const double knee_lo_s = con.rho->knee_s(k, -1);
  const double knee_hi_s = con.rho->knee_s(k, +1);
  const std::array<double, 4> cut{0.0, std::clamp(std::min(knee_lo_s, knee_hi_s), 0.0, t_end),
                                  std::clamp(std::max(knee_lo_s, knee_hi_s), 0.0, t_end), t_end};
  Intervals out;
  bool any = false;
  for (std::size_t p = 0; p + 1 < cut.size(); ++p) {
    if (!(cut[p + 1] > cut[p])) continue;  // a knee at an end of [0, t_end] or both at one time
    out = any ? unite_in_order(out, piece(cut[p], cut[p + 1])) : piece(cut[p], cut[p + 1]);
    any = true;
  }
  return any ? out : piece(0.0, t_end);  // the one instant when t_end = 0
}

// Where the worst case's path lies inside the grown boxes, as per axis the times inside every
// constraint's grown slab, and the two pairs of axes the ways out are sampled over. Kept apart from
// the pushes (way_needs below) because most candidates need only this and one way's push.
struct GrownSets {
  std::array<Intervals, 3> in;
  Intervals in_xz;  // a push along y must clear the box while x and z are inside
  Intervals in_yz;  // a push along x, while y and z are
  bool threat = false;
};

// The times in [0, t_end] at which axis k is inside every constraint's grown slab.
Intervals axis_set(std::span<const Constraint> cons, int k, const Slabs& slabs, double t_end) {
  // Two one-piece slabs (the robust models' two regions, any turn rate) are found together.
  if (cons.size() == 2 && one_piece(cons[0], k, t_end) && one_piece(cons[1], k, t_end)) {
    Intervals both[2];
    slab_times(grown_slab(cons[0], k, slabs, 0.0, t_end), grown_slab(cons[1], k, slabs, 0.0, t_end),
               0.0, t_end, both);
    return both[0].empty() ? both[0] : intersect(both[0], both[1]);
  }
  Intervals set = within_grown(cons[0], k, slabs, t_end);
  for (std::size_t j = 1; j < cons.size() && !set.empty(); ++j) {
    set = intersect(set, within_grown(cons[j], k, slabs, t_end));
  }
  return set;
}

void join_axes(GrownSets& s) {
  s.threat = false;
  for (const Intervals& set : s.in) {
    if (set.empty()) return;
  }
  s.in_xz = intersect(s.in[0], s.in[2]);
  s.in_yz = intersect(s.in[1], s.in[2]);
  s.threat = !intersect(s.in_xz, s.in[1]).empty();
}

GrownSets grown_sets(std::span<const Constraint> cons, const Slabs& slabs, double t_end) {
  GrownSets s;
  for (int k = 0; k < 3; ++k) {
    s.in[static_cast<std::size_t>(k)] = axis_set(cons, k, slabs, t_end);
    if (s.in[static_cast<std::size_t>(k)].empty()) return s;
  }
  join_axes(s);
  return s;
}

// least_accel against the intersection of the constraints' grown boxes. Outside any one of them at
// time t is a miss, so the gap to cover is the least over them. Stops as soon as the need passes
// stop_above (the caller then only learns that it did).
double least_accel_grown(std::span<const Constraint> cons, int k, double edge_m, int sign,
                         const Intervals& when, double dt, double delay_s,
                         double stop_above = kInf) {
  // Each constraint's side's turn cap and the knee where its growth flattens, found once.
  std::array<double, 2> cap_m{};
  std::array<double, 2> knee_s{};
  const std::size_t n_cons = std::min(cons.size(), cap_m.size());
  for (std::size_t j = 0; j < n_cons; ++j) {
    cap_m[j] = cons[j].rho->cap_m(k, sign);
    knee_s[j] = cons[j].rho->knee_s(k, sign);
  }
  double need = 0.0;
  for (int i = 0; i < when.n; ++i) {
    const double a = when.span[static_cast<std::size_t>(i)][0];
    const double b = when.span[static_cast<std::size_t>(i)][1];
    for (int s = 0; s <= 8; ++s) {
      const double t = a + (b - a) * s / 8.0;
      double gap = kInf;
      for (std::size_t j = 0; j < n_cons; ++j) {
        const Constraint& con = cons[j];
        gap = std::min(gap, edge_m + con.rho->piece(cap_m[j], t >= knee_s[j]).at(t) -
                                sign * con.axis[static_cast<std::size_t>(k)].at(t));
      }
      if (!(gap > 0.0)) continue;
      const double per_accel = EdgeMinStrategy::displacement_per_accel(t - delay_s, dt);
      if (per_accel <= 0.0) return kInf;  // no push started by then helps
      need = std::max(need, gap / per_accel);
      if (need > stop_above) return need;
    }
  }
  return need;
}

// The least push along way w (+up, -up, +right, -right, the order of Step::dir) that takes the
// worst case out of the grown boxes, for a push that starts delay_s from now.
double way_need(std::span<const Constraint> cons, const GrownSets& sets, const Slabs& slabs,
                std::size_t way, double dt, double delay_s, double stop_above = kInf) {
  const int k = way < 2 ? 1 : 0;
  const int sign = way % 2 == 0 ? +1 : -1;
  const double edge_m =
      sign > 0 ? slabs.hi[static_cast<std::size_t>(k)] : -slabs.lo[static_cast<std::size_t>(k)];
  return least_accel_grown(cons, k, edge_m, sign, k == 1 ? sets.in_xz : sets.in_yz, dt, delay_s,
                           stop_above);
}

std::array<double, 4> way_needs(std::span<const Constraint> cons, const GrownSets& sets,
                                const Slabs& slabs, double dt, double delay_s) {
  std::array<double, 4> need{};
  for (std::size_t w = 0; w < need.size(); ++w)
    need[w] = way_need(cons, sets, slabs, w, dt, delay_s);
  return need;
}

// The latest time-to-threat at which a robust model may still have to act. Beyond it, a push of
// a_max started one step later covers the half-width plus the fragment's radius plus rho(t), the
// most the nearer side of the grown box can be away from a fragment inside it. The root of
// a_max D(t - dt) = h + r + rho(t) with rho's two upper bounds on the narrower axis's sides (its
// linear chord part and its cap, `turn_cap_m`), the smaller of the two, plus a step (a threat first
// inside this window was safe to wait on a step ago); the whole horizon when a_max does not outgrow
// 2 q2 (no guarantee then).
double look_ahead_s(const Inflation& rho, double half_m, double turn_cap_m, double a_max_mps2,
                    double dt, double horizon_s) {
  const double a = 0.5 * a_max_mps2 - rho.q2_mps2;
  if (!(a > 0.0)) return horizon_s;
  const auto root = [a](double b, double c) {
    return (b + std::sqrt(b * b + 4.0 * a * c)) / (2 * a);
  };
  const double b = 0.5 * a_max_mps2 * dt + rho.q1_mps;
  double t = root(b, half_m + turn_cap_m);
  if (std::isfinite(rho.turn_radps)) t = std::min(t, root(b + rho.rot_m * rho.turn_radps, half_m));
  return std::isfinite(t) ? std::min(t + dt, horizon_s) : horizon_s;
}

// The constant model's answer for one fragment, whether its path enters the box and the least push
// (need) along each way out.
struct Nominal {
  bool threat = false;
  std::array<double, 4> need{};
};

Nominal nominal_push(const Coord& x, const Coord& y, const Coord& z, const Slabs& slabs,
                     double horizon_s, double dt) {
  Nominal out;
  const Intervals in_z = slab_times(z, slabs.lo[2], slabs.hi[2], horizon_s);
  if (in_z.empty()) return out;
  const Intervals in_x = slab_times(x, slabs.lo[0], slabs.hi[0], horizon_s);
  if (in_x.empty()) return out;
  const Intervals in_y = slab_times(y, slabs.lo[1], slabs.hi[1], horizon_s);
  if (in_y.empty()) return out;
  const Intervals in_xz = intersect(in_x, in_z);
  const Intervals in_yz = intersect(in_y, in_z);
  if (intersect(in_xz, in_y).empty()) return out;  // the path misses the box
  out.threat = true;
  // The four ways out, each the least push along one screen axis.
  out.need = {
      least_accel(y, slabs.hi[1], +1, in_xz, dt), least_accel(y, slabs.hi[1], -1, in_xz, dt),
      least_accel(x, slabs.hi[0], +1, in_yz, dt), least_accel(x, slabs.hi[0], -1, in_yz, dt)};
  return out;
}

std::size_t smallest(const std::array<double, 4>& need) {
  return static_cast<std::size_t>(std::min_element(need.begin(), need.end()) - need.begin());
}

// The way out of least need over weight, among the ways of weight > 0 (at least one is). With
// equal weights this is smallest(); the first allowed way when every allowed need is infinite.
std::size_t chosen(const std::array<double, 4>& need, const std::array<double, 4>& weight,
                   bool weighted) {
  if (!weighted) return smallest(need);
  std::size_t best = 4;
  double best_score = kInf;
  for (std::size_t k = 0; k < 4; ++k) {
    if (!(weight[k] > 0.0)) continue;
    const double score = need[k] / weight[k];
    if (best == 4 || score < best_score) {
      best = k;
      best_score = score;
    }
  }
  return best;
}

// One fragment's path as the exact solve sees it, in the camera's axes, relative to the camera (d
// and w; x, y and z, each coordinate with half the gravity), the protected box grown by its radius,
// its own look-ahead, and the constant model's way out and least push.
struct PathInBox {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  double own_horizon_s = 0.0;
  Slabs slabs;
  Coord x;
  Coord y;
  Coord z;
  Nominal nominal;
  std::size_t best = 0;
  double a_nominal = 0.0;
};

}  // namespace

double EdgeMinStrategy::time_to_ground_s(double y0_m, double vy_mps, double half_gy_mps2,
                                         double ground_m) {
  if (!(ground_m > -kInf)) return kInf;  // no ground
  // y(t) - ground = a t^2 + b t + c.
  const double a = half_gy_mps2;
  const double b = vy_mps;
  const double c = y0_m - ground_m;
  if (const std::optional<double> t = time_to_plane_s(AxisQuadratic{c, b, a})) return *t;
  // No downward crossing is ahead. A path above the ground never comes down. One at or below it
  // (resting, or sunk into it by the contact's softness) rises for good (gravity off or up) or
  // stays underground, where nothing it predicts is real.
  if (c > 0.0) return kInf;
  return (a > 0.0 || (a == 0.0 && b > 0.0)) ? kInf : 0.0;
}

void EdgeMinStrategy::reset(int fragment_count) {
  last_force_N_.assign(static_cast<std::size_t>(std::max(fragment_count, 0)),
                       Eigen::Vector3d::Zero());
  r_max_hint_m_ = -1.0;
  cover_.reset(fragment_count);
  // The rejection's work space, its pages touched, so that no step allocates or faults.
  clearance_.reserve(static_cast<std::size_t>(std::max(fragment_count, 0)));
  reserve_answers(static_cast<std::size_t>(std::max(fragment_count, 0)));
}

void EdgeMinStrategy::reserve(int fragment_count) {
  const auto n = static_cast<std::size_t>(std::max(fragment_count, 0));
  clearance_.reserve(n);
  reserve_answers(n);
  if (params_.max_solves > 0) {  // the budget's state and work space
    last_force_N_.reserve(n);
    carried_from_.reserve(n);
    queue_.reserve(n);
    deferred_.reserve(n);
  }
}

void EdgeMinStrategy::set_worker_count(int workers) {
  clearance_.set_workers(workers);
}

// Kept at its largest size, its pages written once, as reserve() runs before every step of the
// controller library, where a fresh reserve_touched of the whole array would cost a pass over it.
void EdgeMinStrategy::reserve_answers(std::size_t n) {
  if (answers_.size() < n) answers_.resize(n);
}

void EdgeMinStrategy::carry_over(std::span<const int> previous) {
  // The last forces are read only by the budget, so without one there is nothing to carry.
  if (params_.max_solves <= 0) {
    carried_over_ = false;
    return;
  }
  carried_over_ = true;
  // Into the spare array, which keeps the state before the call for undo_carry_over.
  carried_from_.assign(previous.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < previous.size(); ++i) {
    const int j = previous[i];
    if (j >= 0 && static_cast<std::size_t>(j) < last_force_N_.size()) {
      carried_from_[i] = last_force_N_[static_cast<std::size_t>(j)];
    }
  }
  last_force_N_.swap(carried_from_);
}

void EdgeMinStrategy::undo_carry_over() {
  if (carried_over_) last_force_N_.swap(carried_from_);
  carried_over_ = false;
}

double EdgeMinStrategy::assumed_accel_mps2(const StepContext& ctx) const {
  const double declared = ctx.camera_max_accel_mps2;
  return declared >= 0.0 ? declared : params_.camera_accel_mps2;  // NaN if not declared either
}

double EdgeMinStrategy::assumed_turn_radps(const StepContext& ctx) const {
  const double declared = ctx.camera_max_turn_degps;
  return (declared >= 0.0 ? declared : params_.camera_turn_degps) * kPi / 180.0;
}

// One step's constants (the protected box about the eye, the look-ahead's bounds, the robust
// models' regions, and after the rejection its answers), with the stages that read only these (the
// exact solve of one fragment).
struct EdgeMinStrategy::Step {
  Step(const StepContext& context, const EdgeMinParams& edge_min, double assumed_accel_mps2,
       double assumed_turn_radps, const std::array<double, 4>& weights, bool weights_differ);
  Step(const Step&) = delete;
  Step& operator=(const Step&) = delete;

  const StepContext& ctx;
  const CameraPose& cam;
  const EdgeMinParams& params;
  const std::array<double, 4>& way_weights;
  bool weighted;
  // The protected box, before the fragment's radius, lo_m <= x <= hi_m in the camera's axes.
  double half_w_m = 0.0;
  double half_h_m = 0.0;
  double front_m = 0.0;
  double back_m = 0.0;
  Eigen::Vector3d lo_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi_m = Eigen::Vector3d::Zero();
  // Each fragment's own look-ahead lasts until it reaches the ground, within the cap and the shot's
  // end when known. The robust models' window is cut to it; the rejection bounds it.
  double cap_s = 0.0;
  double horizon_s = 0.0;
  Eigen::Vector3d half_g = Eigen::Vector3d::Zero();  // half the gravity, in the camera's axes
  // The robust models' regions (see the header).
  bool robust = false;
  bool ball_known = false;
  bool use_accel = false;
  Inflation accel_rho;
  Inflation ball_rho;
  // The narrower screen axis's half size and its sides' turn cap (both sides of x or y have the
  // same one).
  double half_min_m = 0.0;
  double narrow_cap_m = 0.0;
  // The ways out, +up, -up, +right, -right.
  std::array<Eigen::Vector3d, 4> dir;
  // The rejection's answers, and the grown box's look-ahead (robust models only).
  std::span<const char> clears;
  std::span<const char> grown_clears;
  std::span<const std::int32_t> unsettled;
  double look_s = 0.0;

  // The grown box is rejected against in the tighter-growing frame, the constant-velocity one for
  // bounded_accel (the intersection with the ball only shrinks it), the eye's for reachable.
  const Inflation& reject_rho() const { return use_accel ? accel_rho : ball_rho; }
  // The robust models' window for fragments of radius up to r_max_m (look_ahead_s).
  double window_s(double r_max_m) const;
  // The rejection's boxes, all but the grown box's window and growth (set_window).
  TwoBoxClearance::Boxes rejection_boxes() const;
  void set_window(TwoBoxClearance::Boxes& boxes, double r_max_m) const;
  // In front of the box and moving away in depth, with gravity not pulling it back (the camera's
  // forward axis tilted toward the ground can) is no threat, without a solve.
  bool receding(const Eigen::Vector3d& d, const Eigen::Vector3d& w, double r) const {
    return d.z() > front_m + r && w.z() >= 0.0 && half_g.z() >= 0.0;
  }
  // Whether fragment i, left unsettled by the rejection, needs the exact solve.
  bool needs_solve(std::size_t i) const;
  // The exact solve of one fragment the rejections left in doubt, whether it is a candidate and
  // the force it asks for, if any. It reads only the step's constants and the fragment, so
  // fragments may be solved on any workers at once.
  SolveAnswer solve(std::size_t i, bool grown_clear) const;
  // The robust models' part of it, the worst case over the look-ahead window and whether the
  // constant model's push may wait a step.
  SolveAnswer solve_worst_case(const FragmentState& f, const PathInBox& path,
                               bool grown_clear) const;
  // `answer` with a push of force_N.
  static SolveAnswer pushed(SolveAnswer answer, const Eigen::Vector3d& force_N);
  // A solve's answer into out, the candidate, then its force through the cap.
  void emit(std::size_t i, const SolveAnswer& answer, StepOutput& out) const;
};

EdgeMinStrategy::Step::Step(const StepContext& context, const EdgeMinParams& edge_min,
                            double assumed_accel_mps2, double assumed_turn_radps,
                            const std::array<double, 4>& weights, bool weights_differ)
    : ctx(context),
      cam(context.camera),
      params(edge_min),
      way_weights(weights),
      weighted(weights_differ),
      dir{context.camera.up, -context.camera.up, context.camera.right, -context.camera.right} {
  const Eigen::Vector3d& body = ctx.camera_body_half_m;
  half_w_m = std::max(cam.near_half_width_m(), body.x()) + params.margin_m;
  half_h_m = std::max(cam.near_half_height_m(), body.y()) + params.margin_m;
  front_m = std::max(cam.near_m, body.z()) + params.margin_m;
  back_m = body.z() + params.margin_m;
  cap_s = std::min(params.horizon_cap_s, ctx.end_time_s - ctx.t_s);
  horizon_s = std::max(cap_s, ctx.dt_s);
  half_g = 0.5 * cam.dir_to_camera(ctx.gravity_mps2);
  lo_m = Eigen::Vector3d(-half_w_m, -half_h_m, -back_m);
  hi_m = Eigen::Vector3d(half_w_m, half_h_m, front_m);

  // The robust models' regions (see the header), about the constant-velocity path (bounded_accel)
  // and about the eye now (V_c; both models). Each side grows by the chord of the view's turn, at
  // most to the ball every orientation of the box lies in (Inflation), so any turn rate is safe.
  robust = params.camera_model != CameraModel::kConstant;
  const double rot_m = norm3(Eigen::Vector3d(half_w_m, half_h_m, std::max(front_m, back_m)));
  const std::array<double, 6> turn_cap_m = turn_caps_m(lo_m, hi_m, rot_m);
  ball_known = std::isfinite(ctx.camera_max_speed_mps) && ctx.camera_max_speed_mps >= 0;
  // With neither bound known (a library caller may pass V_c = inf), the parameters' is assumed.
  const double accel_mps2 = std::isfinite(assumed_accel_mps2) || ball_known
                                ? assumed_accel_mps2
                                : params.camera_accel_mps2;
  // An unbounded acceleration leaves only the ball (0.5 A t^2 would be inf * 0 at t = 0).
  use_accel = (params.camera_model == CameraModel::kBoundedAccel && std::isfinite(accel_mps2)) ||
              !ball_known;
  accel_rho = Inflation{0.0, std::isfinite(accel_mps2) ? 0.5 * accel_mps2 : 0.0, rot_m,
                        assumed_turn_radps, turn_cap_m}
                  .with_knees();
  ball_rho = Inflation{ball_known ? ctx.camera_max_speed_mps : 0.0, 0.0, rot_m, assumed_turn_radps,
                       turn_cap_m}
                 .with_knees();
  const int narrow_axis = half_w_m <= half_h_m ? 0 : 1;
  half_min_m = std::min(half_w_m, half_h_m);
  narrow_cap_m = turn_cap_m[Inflation::turn_side(narrow_axis, +1)];
}

double EdgeMinStrategy::Step::window_s(double r_max_m) const {
  return look_ahead_s(reject_rho(), half_min_m + r_max_m, narrow_cap_m, params.a_max_mps2, ctx.dt_s,
                      horizon_s);
}

TwoBoxClearance::Boxes EdgeMinStrategy::Step::rejection_boxes() const {
  TwoBoxClearance::Boxes boxes;
  boxes.frame = BoxFrame{cam.eye_m, {cam.right, cam.up, cam.forward}, ctx.camera_velocity_mps};
  boxes.a_mps2 = half_g;
  boxes.lo_m = lo_m;
  boxes.hi_m = hi_m;
  boxes.cap_s = cap_s;
  boxes.floor_s = ctx.dt_s;
  boxes.ground_m = ctx.ground_height_m;
  boxes.half_gy_mps2 = 0.5 * ctx.gravity_mps2.y();
  boxes.grown = robust && !ctx.fragments.empty();
  boxes.grown_velocity_mps = use_accel ? ctx.camera_velocity_mps : Eigen::Vector3d::Zero();
  return boxes;
}

void EdgeMinStrategy::Step::set_window(TwoBoxClearance::Boxes& boxes, double r_max_m) const {
  const Inflation& rho = reject_rho();
  boxes.window_s = window_s(r_max_m);
  // Each side's growth only increases with time, so its value at the window's end bounds it.
  for (int k = 0; k < 3; ++k) {
    boxes.grow_lo_m[k] = rho.at(boxes.window_s, rho.cap_m(k, -1));
    boxes.grow_hi_m[k] = rho.at(boxes.window_s, rho.cap_m(k, +1));
  }
  // And piece by piece (its growth at its end, times as TwoBoxClearance computes them), as the
  // growth at the window's end is several times that of a path passing early in it, and the paths
  // the whole window leaves in doubt are mostly such.
  boxes.pieces = TwoBoxClearance::Boxes::kMaxPieces;
  for (int j = 0; j < boxes.pieces; ++j) {
    const double end_s = boxes.window_s * (j + 1) / boxes.pieces;
    for (int k = 0; k < 3; ++k) {
      boxes.piece_grow_lo_m[static_cast<std::size_t>(j)][k] = rho.at(end_s, rho.cap_m(k, -1));
      boxes.piece_grow_hi_m[static_cast<std::size_t>(j)][k] = rho.at(end_s, rho.cap_m(k, +1));
    }
  }
}

bool EdgeMinStrategy::Step::needs_solve(std::size_t i) const {
  if (robust && !grown_clears[i]) return true;
  if (clears[i]) return false;
  const FragmentState& f = ctx.fragments[i];
  return !receding(cam.to_camera(f.position_m),
                   cam.dir_to_camera(f.velocity_mps - ctx.camera_velocity_mps), f.radius_m);
}

EdgeMinStrategy::SolveAnswer EdgeMinStrategy::Step::pushed(SolveAnswer answer,
                                                           const Eigen::Vector3d& force_N) {
  answer.pushed = true;
  answer.force_N = force_N;
  return answer;
}

EdgeMinStrategy::SolveAnswer EdgeMinStrategy::Step::solve(std::size_t i, bool grown_clear) const {
  SolveAnswer answer;
  const FragmentState& f = ctx.fragments[i];
  PathInBox path;
  path.d = cam.to_camera(f.position_m);
  path.w = cam.dir_to_camera(f.velocity_mps - ctx.camera_velocity_mps);
  const double r = f.radius_m;
  // This fragment's look-ahead lasts until its path reaches the ground.
  const double ground_s = time_to_ground_s(f.position_m.y(), f.velocity_mps.y(),
                                           0.5 * ctx.gravity_mps2.y(), ctx.ground_height_m + r);
  path.own_horizon_s = std::max(std::min(ground_s, cap_s), ctx.dt_s);
  path.slabs =
      Slabs{{-half_w_m - r, -half_h_m - r, -back_m - r}, {half_w_m + r, half_h_m + r, front_m + r}};
  path.x = Coord{path.d.x(), path.w.x(), half_g.x()};
  path.y = Coord{path.d.y(), path.w.y(), half_g.y()};
  path.z = Coord{path.d.z(), path.w.z(), half_g.z()};
  if (!clears[i] && !receding(path.d, path.w, r)) {
    path.nominal = nominal_push(path.x, path.y, path.z, path.slabs, path.own_horizon_s, ctx.dt_s);
  }
  path.best = chosen(path.nominal.need, way_weights, weighted);
  // Already inside the box's shadow on every side, nothing finite helps, so the push goes toward
  // the nearest way out at the cap and the report counts it if it still hits.
  path.a_nominal = !path.nominal.threat                          ? 0.0
                   : std::isfinite(path.nominal.need[path.best]) ? path.nominal.need[path.best]
                                                                 : 2.0 * params.a_max_mps2 + 1.0;
  if (robust) return solve_worst_case(f, path, grown_clear);
  if (!path.nominal.threat) return answer;
  answer.candidate = true;
  if (path.a_nominal <= 0.0) return answer;
  return pushed(answer, f.mass_kg * path.a_nominal * dir[path.best]);
}

EdgeMinStrategy::SolveAnswer EdgeMinStrategy::Step::solve_worst_case(const FragmentState& f,
                                                                     const PathInBox& path,
                                                                     bool grown_clear) const {
  SolveAnswer answer;
  const Eigen::Vector3d& d = path.d;
  const Slabs& slabs = path.slabs;
  const std::size_t best = path.best;
  const double a_nominal = path.a_nominal;
  // The worst case over the look-ahead window.
  std::array<Constraint, 2> cons_store;
  std::size_t n_cons = 0;
  if (use_accel) cons_store[n_cons++] = {{path.x, path.y, path.z}, &accel_rho};
  if (ball_known) {
    // About the eye now, with the fragment's own velocity, not the relative one.
    const Eigen::Vector3d v = cam.dir_to_camera(f.velocity_mps);
    cons_store[n_cons++] = {{Coord{d.x(), v.x(), half_g.x()}, Coord{d.y(), v.y(), half_g.y()},
                             Coord{d.z(), v.z(), half_g.z()}},
                            &ball_rho};
  }
  const std::span<const Constraint> cons(cons_store.data(), n_cons);
  const double own_look_s = std::min(look_s, path.own_horizon_s);
  const GrownSets now = grown_clear ? GrownSets{} : grown_sets(cons, slabs, own_look_s);
  if (!path.nominal.threat && !now.threat) return answer;
  answer.candidate = true;
  if (now.threat) {
    // Would waiting a step still be safe? During it the constant model's push (as capped) acts,
    // moving the fragment by a dt t along its axis; from the next step on, a push of at most a_max
    // moves it D(t - dt) per unit. Only that axis's times inside the boxes change. Without a push
    // the next step's worst case is this one's, so nothing is copied.
    std::span<const Constraint> wait_cons = cons;
    const GrownSets* wait_sets = &now;
    std::array<Constraint, 2> pushed_cons;
    GrownSets pushed_sets;
    if (a_nominal > 0.0) {
      const std::size_t k = best < 2 ? 1 : 0;
      const double sign = best % 2 == 0 ? 1.0 : -1.0;
      const double dv = sign * std::min(a_nominal, params.a_max_mps2) * ctx.dt_s;
      pushed_cons = cons_store;
      for (std::size_t j = 0; j < n_cons; ++j) pushed_cons[j].axis[k].c1 += dv;
      wait_cons = std::span<const Constraint>(pushed_cons.data(), n_cons);
      pushed_sets = now;
      pushed_sets.in[k] = axis_set(wait_cons, static_cast<int>(k), slabs, own_look_s);
      join_axes(pushed_sets);
      wait_sets = &pushed_sets;
    }
    const GrownSets& wait = *wait_sets;
    // Waiting is safe when some allowed way's push from the next step on stays within a_max;
    // the nominal way is tried first, and each way's sampling stops once it is out of reach.
    bool wait_safe = !wait.threat;
    for (std::size_t n_tried = 0; n_tried < 4 && !wait_safe; ++n_tried) {
      const std::size_t w = (best + n_tried) % 4;
      if (weighted && !(way_weights[w] > 0.0)) continue;
      wait_safe = way_need(wait_cons, wait, slabs, w, ctx.dt_s, ctx.dt_s, params.a_max_mps2) <=
                  params.a_max_mps2;
    }
    if (!wait_safe) {
      const std::array<double, 4> wc_need = way_needs(cons, now, slabs, ctx.dt_s, 0.0);
      const std::size_t wc_best = chosen(wc_need, way_weights, weighted);
      const double a_wc =
          std::isfinite(wc_need[wc_best]) ? wc_need[wc_best] : 2.0 * params.a_max_mps2 + 1.0;
      // When no push within a_max beats the worst case, nothing is promised for this fragment, so
      // the capped push goes the constant model's way out, which saves it from the likeliest camera
      // (one that keeps its velocity and view) instead of losing to both.
      const bool beaten = !(a_wc <= params.a_max_mps2);
      const std::size_t way = beaten && path.nominal.threat ? best : wc_best;
      return pushed(answer, f.mass_kg * std::max(a_nominal, a_wc) * dir[way]);
    }
  }
  if (a_nominal <= 0.0) return answer;
  return pushed(answer, f.mass_kg * a_nominal * dir[best]);
}

void EdgeMinStrategy::Step::emit(std::size_t i, const SolveAnswer& answer, StepOutput& out) const {
  if (answer.candidate) out.activity.candidates.push_back(static_cast<int>(i));
  if (answer.pushed) {
    apply_capped(out, static_cast<int>(i), answer.force_N, ctx.fragments[i].mass_kg,
                 params.a_max_mps2);
  }
}

// Cheap rejection of every fragment at once before any root solve (two_box_clearance.hpp). A path
// that never has all three coordinates inside the box grown by the fragment's radius, with a margin
// the solves below agree with, over the fragment's own look-ahead, is no threat; for the robust
// models likewise the grown box over the window (section 4 of docs/camera_models.md). Most
// fragments end here.
void EdgeMinStrategy::reject_cheaply(Step& s) {
  TwoBoxClearance::Boxes boxes = s.rejection_boxes();
  // The window and the growth depend on the largest radius, known only after the pass, so the last
  // step's is used (a window and growth at least the solves' keep the rejection conservative, as
  // both grow with the radius), and the pass repeated in the rare step whose fragments are larger.
  // The hint changes how fast a step is, never what it answers.
  double r_hint_m = r_max_hint_m_;
  if (boxes.grown) {
    if (!(r_hint_m >= 0.0)) {
      r_hint_m = 0.0;
      for (const FragmentState& f : s.ctx.fragments) r_hint_m = std::max(r_hint_m, f.radius_m);
    }
    s.set_window(boxes, r_hint_m);
  }
  run_rejection(s.ctx, boxes);
  if (boxes.grown) {
    const double r_max_m = clearance_.max_radius_m();
    if (r_max_m > r_hint_m) {
      s.set_window(boxes, r_max_m);
      run_rejection(s.ctx, boxes);
    }
    r_max_hint_m_ = r_max_m;
    s.look_s = s.window_s(r_max_m);
  }
  s.clears = clearance_.clears();
  s.grown_clears = clearance_.grown_clears();
  s.unsettled = clearance_.unsettled();
}

// In chunks on the workers when there are some, with the same answers (TwoBoxClearance::run).
void EdgeMinStrategy::run_rejection(const StepContext& ctx, const TwoBoxClearance::Boxes& boxes) {
  if (ctx.parallel != nullptr) {
    clearance_.run(ctx.fragments, boxes, ctx.parallel);
  } else {
    clearance_.run(ctx.fragments, boxes);
  }
}

// The per-step budget. Over max_solves fragments left to solve, the most urgent are solved and the
// rest deferred to a later step, keeping the force they were last given (a constant push is a plan
// until arrival, so dropping it half way loses what it already did; and the urgent ones, which a
// stale push could fail, are the ones solved).
void EdgeMinStrategy::defer_beyond_budget(const Step& s, StepOutput& out) {
  const StepContext& ctx = s.ctx;
  const std::size_t n = ctx.fragments.size();
  if (last_force_N_.size() != n) last_force_N_.assign(n, Eigen::Vector3d::Zero());
  deferred_.assign(n, 0);
  queue_.clear();
  for (const std::int32_t u : s.unsettled) {
    const auto i = static_cast<std::size_t>(u);
    if (!s.needs_solve(i)) continue;
    // Time to arrival is distance to the eye over the closing speed -d.w / |d|, so |d|^2 / -d.w,
    // and a fragment not closing in is last (+inf).
    const FragmentState& f = ctx.fragments[i];
    const Eigen::Vector3d d = f.position_m - s.cam.eye_m;
    const double closing = -dot3(d, f.velocity_mps - ctx.camera_velocity_mps);
    const double arrival_s = closing > 0.0 ? squared_norm3(d) / closing : kInf;
    // Threats to the protected box on the current path (not cleared of it) before those only the
    // grown box keeps in doubt, as the camera keeping its velocity is the likelier future.
    queue_.push_back({s.clears[i] ? 1 : 0, arrival_s, static_cast<int>(i)});
  }
  const auto cap = static_cast<std::size_t>(params_.max_solves);
  if (queue_.size() > cap) {
    // (tier, arrival, index) is a total order, so the same set is solved whatever the sort does.
    std::nth_element(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(cap),
                     queue_.end());
    for (std::size_t k = cap; k < queue_.size(); ++k) {
      deferred_[static_cast<std::size_t>(std::get<2>(queue_[k]))] = 1;
    }
    out.activity.deferred = static_cast<int>(queue_.size() - cap);
  }
}

void EdgeMinStrategy::solve_in_order(const Step& s, StepOutput& out) const {
  for (std::size_t k = 0; k < s.unsettled.size(); ++k) {
    const auto i = static_cast<std::size_t>(s.unsettled[k]);
    s.emit(i, s.solve(i, s.grown_clears[i] != 0), out);
  }
}

// Each answer to its own slot on the workers, then into out in the fragments' order, for the same
// candidates, forces, capped and guarded as one after the other.
void EdgeMinStrategy::solve_on_workers(const Step& s, StepOutput& out) {
  const std::span<const std::int32_t> unsettled = s.unsettled;
  if (answers_.size() < unsettled.size()) answers_.resize(unsettled.size());
  const auto solve_range = [&](std::int32_t begin, std::int32_t end, std::uint32_t) {
    for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k) {
      const auto i = static_cast<std::size_t>(unsettled[k]);
      answers_[k] = s.solve(i, s.grown_clears[i] != 0);
    }
  };
  for_ranges(s.ctx.parallel, static_cast<std::int32_t>(unsettled.size()), kMinSolveRange,
             solve_range);
  for (std::size_t k = 0; k < unsettled.size(); ++k) {
    s.emit(static_cast<std::size_t>(unsettled[k]), answers_[k], out);
  }
}

// Every fragment in order. A deferred one keeps its last force, the others are solved where the
// rejection left them in doubt, and what each was given is kept for a later step that defers it.
void EdgeMinStrategy::solve_within_budget(const Step& s, StepOutput& out) {
  const std::size_t n = s.ctx.fragments.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (deferred_[i]) {
      if (!last_force_N_[i].isZero()) out.forces.push_back({static_cast<int>(i), last_force_N_[i]});
      continue;
    }
    const bool grown_clear = !s.robust || s.grown_clears[i];
    const bool cleared = s.clears[i] && grown_clear;
    const std::size_t forces_before = out.forces.size();
    if (!cleared) s.emit(i, s.solve(i, grown_clear), out);
    last_force_N_[i] =
        out.forces.size() > forces_before ? out.forces.back().force_N : Eigen::Vector3d::Zero();
  }
}

void EdgeMinStrategy::step(const StepContext& ctx, StepOutput& out) {
  Step s(ctx, params_, assumed_accel_mps2(ctx), assumed_turn_radps(ctx), way_weights_, weighted_);
  reject_cheaply(s);
  out.activity.rejected_cheaply = static_cast<int>(ctx.fragments.size() - s.unsettled.size());
  // Without a budget (max_solves) every fragment left in doubt is solved.
  if (params_.max_solves > 0) {
    defer_beyond_budget(s, out);
    solve_within_budget(s, out);
  } else if (ctx.parallel == nullptr) {
    solve_in_order(s, out);
  } else {
    solve_on_workers(s, out);
  }
  // The occlusion bound goes on top; its prediction includes the pushes above.
  if (params_.cover_max < 1.0) cover_.step(ctx, params_, way_weights_, out);
}

}  // namespace fragsim
