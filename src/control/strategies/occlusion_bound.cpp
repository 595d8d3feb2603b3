#include "control/strategies/occlusion_bound.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

#include "control/geometry/frustum.hpp"
#include "control/geometry/vec3_sums.hpp"

namespace fragsim {
namespace {

// A constant unit acceleration's displacement after t_s of semi-implicit Euler steps of dt_s
// (EdgeMinStrategy::displacement_per_accel, repeated here so this file needs nothing above it).
double per_accel(double t_s, double dt_s) {
  return 0.5 * (t_s * t_s + t_s * dt_s);
}

// The radius of the disc of a box's mean projected area. The mean shadow of a convex body is a
// quarter of its surface area 8 (ab + bc + ca) for half extents a, b, c.
double disc_radius_m(const Eigen::Vector3d& half_m) {
  const double a = half_m.x();
  const double b = half_m.y();
  const double c = half_m.z();
  return std::sqrt(2.0 * (a * b + b * c + c * a) / kPi);
}

}  // namespace

void OcclusionBound::reset(int fragment_count) {
  pushed_last_.assign(static_cast<std::size_t>(std::max(fragment_count, 0)), 0);
  added_mps_.assign(static_cast<std::size_t>(std::max(fragment_count, 0)), Eigen::Vector3d::Zero());
}

int OcclusionBound::paint(int sample, const Disc& d, int delta) {
  if (!d.present) return 0;
  const double s = 1.0;  // the grid spans [-1, 1]^2 in units of the region's half size
  const double cw = 2.0 * s / cols_;
  const double rh = 2.0 * s / rows_;
  // Cells whose centre can lie in the disc's bounding box, clamped in double before the cast.
  const double c_lo = std::max(0.0, std::ceil((d.x - d.rx + s) / cw - 0.5));
  const double c_hi = std::min(cols_ - 1.0, std::floor((d.x + d.rx + s) / cw - 0.5));
  const double r_lo = std::max(0.0, std::ceil((s - (d.y + d.ry)) / rh - 0.5));
  const double r_hi = std::min(rows_ - 1.0, std::floor((s - (d.y - d.ry)) / rh - 0.5));
  if (!(c_lo <= c_hi) || !(r_lo <= r_hi)) return 0;
  const std::size_t cells = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_);
  std::uint16_t* grid = count_.data() + static_cast<std::size_t>(sample) * cells;
  int own = 0;
  for (int r = static_cast<int>(r_lo); r <= static_cast<int>(r_hi); ++r) {
    const double dy = (s - (r + 0.5) * rh - d.y) / d.ry;
    for (int c = static_cast<int>(c_lo); c <= static_cast<int>(c_hi); ++c) {
      const double dx = (-s + (c + 0.5) * cw - d.x) / d.rx;
      if (dx * dx + dy * dy > 1.0) continue;
      ++own;
      std::uint16_t& n = grid[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) +
                              static_cast<std::size_t>(c)];
      if (delta > 0) {
        if (n == 0) ++covered_[static_cast<std::size_t>(sample)];
        if (n < UINT16_MAX) ++n;
      } else if (n > 0) {
        --n;
        if (n == 0) --covered_[static_cast<std::size_t>(sample)];
      }
    }
  }
  return own;
}

// One fragment's camera-space path pieces, for x(t) = d + w t + A (t^2 + t dt) / 2.
struct OcclusionBound::Path {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  double rho = 0.0;
  double base_accel = 0.0;
  bool valid = false;
};

// Where a fragment's disc is drawn, given by the region's half sizes per metre of depth (NDC in
// units of the region's half size) and the near plane. It is small so the loops that draw keep a
// copy in registers rather than reading it through the step after each call that paints.
struct OcclusionBound::Screen {
  double sx = 0.0;
  double sy = 0.0;
  double near_m = 0.0;

  // A fragment's disc at camera-space position p, absent when wholly behind the near plane.
  Disc disc_at(const Eigen::Vector3d& p, double rho) const;
};

// One step's constants, and where the pushes go, out and each fragment's place in out.forces (slot,
// -1 for none). out starts with the push already given this step (edge-min's, against the camera)
// as part of the path.
struct OcclusionBound::Step {
  Step(const StepContext& context, const EdgeMinParams& edge_min,
       const std::array<double, 4>& way_weights, StepOutput& output, int samples,
       std::size_t grid_cells, MemoryResource* mem);

  const StepContext& ctx;
  const CameraPose& cam;
  const EdgeMinParams& params;
  const std::array<double, 4>& weights;
  StepOutput& out;
  double dt = 0.0;
  std::size_t n = 0;
  int k_samples = 0;
  std::size_t cells = 0;
  Screen screen;
  // The covered cells over which a sample is over the bound.
  double bound_cells = 0.0;
  ResourceVector<int> slot;
};

OcclusionBound::Step::Step(const StepContext& context, const EdgeMinParams& edge_min,
                           const std::array<double, 4>& way_weights, StepOutput& output,
                           int samples, std::size_t grid_cells, MemoryResource* mem)
    : ctx(context),
      cam(context.camera),
      params(edge_min),
      weights(way_weights),
      out(output),
      dt(context.dt_s),
      n(context.fragments.size()),
      k_samples(samples),
      cells(grid_cells),
      screen{edge_min.cover_region * context.camera.half_width_at(1.0),
             edge_min.cover_region * context.camera.half_height_at(1.0), context.camera.near_m},
      bound_cells((edge_min.cover_max - edge_min.cover_margin) * static_cast<double>(grid_cells)),
      slot(context.fragments.size(), -1, mem) {
  for (std::size_t k = 0; k < out.forces.size(); ++k) {
    const int i = out.forces[k].fragment;
    if (i >= 0 && static_cast<std::size_t>(i) < n)
      slot[static_cast<std::size_t>(i)] = static_cast<int>(k);
  }
}

OcclusionBound::Disc OcclusionBound::Screen::disc_at(const Eigen::Vector3d& p, double rho) const {
  Disc d;
  if (!(p.z() + rho > near_m)) return d;  // wholly behind the near plane, so nothing is drawn
  const double ze = std::max(p.z(), near_m);
  d.x = p.x() / (ze * sx);
  d.y = p.y() / (ze * sy);
  d.rx = rho / (ze * sx);
  d.ry = rho / (ze * sy);
  d.present = std::abs(d.x) - d.rx < 1.0 && std::abs(d.y) - d.ry < 1.0 && d.rx > 0.0;
  return d;
}

// The sample times, as steps ahead, are every step for the first 2 B, then every 2nd step for the
// next 2 B steps, every 4th for the next 4 B, ... (B = cover_samples), each on steps of the run
// that are multiples of its stride. Then a step once sampled stays sampled as it comes nearer (a
// multiple of 2^k is one of 2^(k-1)), so the step a push was planned for is checked again on every
// later step, and the plan is kept rather than lost between samples.
int OcclusionBound::sample_times(const StepContext& ctx, const EdgeMinParams& params) {
  const double dt = ctx.dt_s;
  const long long last_step =
      std::max(1LL, static_cast<long long>(std::llround(params.cover_horizon_s / dt)));
  ResourceVector<long long> steps(mem_);
  const long long dense = 2LL * params.cover_samples;
  const long long now = std::max(0, ctx.step);
  // Band by band (stride 1 for d < dense, then stride s for dense s / 2 <= d < dense s), only the
  // sampled steps, as the samples grow with the log of the horizon in steps, and a horizon of a
  // billion steps (a long cover_horizon_s at a tiny dt) must not cost a billion iterations.
  for (long long stride = 1, lo = 1; lo <= last_step; lo = dense * stride, stride *= 2) {
    const long long hi = std::min(last_step, dense * stride - 1);
    for (long long d = lo + (stride - (now + lo) % stride) % stride; d <= hi; d += stride) {
      steps.push_back(d);
    }
  }
  const int k_samples = static_cast<int>(steps.size());
  for (long long m : steps) times_s_.push_back(static_cast<double>(m) * dt);
  return k_samples;
}

std::size_t OcclusionBound::make_grid(const CameraPose& cam, const EdgeMinParams& params,
                                      std::size_t n, int k_samples) {
  cols_ = params.cover_cells;
  // Square cells on screen, but at most 16 rows per column. A screen taller than 16 times its width
  // gets taller cells, so the grid's cost is bounded for any aspect (and the row count fits an int
  // before it is rounded).
  const double rows = std::min(cols_ / cam.aspect, 16.0 * cols_);
  rows_ = std::max(1, static_cast<int>(std::lround(rows)));
  const std::size_t cells = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_);
  count_.assign(cells * static_cast<std::size_t>(k_samples), 0);
  covered_.assign(static_cast<std::size_t>(k_samples), 0);
  disc_.assign(n * static_cast<std::size_t>(k_samples), Disc{});
  own_.assign(n * static_cast<std::size_t>(k_samples), 0);
  return cells;
}

void OcclusionBound::add_force(Step& s, std::size_t i, const Eigen::Vector3d& force_N) {
  const FragmentState& f = s.ctx.fragments[i];
  added_mps_[i] += force_N / f.mass_kg * s.dt;
  if (s.slot[i] >= 0) {
    s.out.forces[static_cast<std::size_t>(s.slot[i])].force_N += force_N;
  } else {
    s.slot[i] = static_cast<int>(s.out.forces.size());
    s.out.forces.push_back({static_cast<int>(i), force_N});
  }
}

// What a push added it takes back once the fragment is behind the camera and moving away, where it
// cannot be seen again (the camera keeping its velocity), as the sideways speed a push left would
// otherwise carry the fragment ever farther from its own path, which is the deviation the bound
// costs. At most a_max, above the camera body's back by the fragment's radius and a margin, so the
// braking fragment cannot touch the camera.
void OcclusionBound::brake_behind_camera(Step& s) {
  const StepContext& ctx = s.ctx;
  const CameraPose& cam = s.cam;
  const std::size_t n = s.n;
  if (added_mps_.size() != n) added_mps_.assign(n, Eigen::Vector3d::Zero());
  const double behind_m = ctx.camera_body_half_m.z() + s.params.margin_m;
  for (std::size_t i = 0; i < n; ++i) {
    if (added_mps_[i].isZero()) continue;
    const FragmentState& f = ctx.fragments[i];
    const Eigen::Vector3d d = cam.to_camera(f.position_m);
    const Eigen::Vector3d w = cam.dir_to_camera(f.velocity_mps - ctx.camera_velocity_mps);
    if (!(d.z() < -(behind_m + f.radius_m) && w.z() < 0.0 && s.slot[i] < 0 && f.mass_kg > 0.0)) {
      continue;
    }
    Eigen::Vector3d brake = -added_mps_[i] / s.dt;
    if (norm3(brake) > s.params.a_max_mps2) brake *= s.params.a_max_mps2 / norm3(brake);
    add_force(s, i, f.mass_kg * brake);
    if (norm3(added_mps_[i]) < 1e-9) added_mps_[i].setZero();
  }
}

// Every fragment's path, and its disc at every sample drawn into the grid.
void OcclusionBound::draw_paths(const Step& s, ResourceVector<Path>& paths) {
  const StepContext& ctx = s.ctx;
  const CameraPose& cam = s.cam;
  const int k_samples = s.k_samples;
  const double dt = s.dt;
  const Screen screen = s.screen;
  for (std::size_t i = 0; i < s.n; ++i) {
    const FragmentState& f = ctx.fragments[i];
    Path& p = paths[i];
    if (!f.position_m.allFinite() || !f.velocity_mps.allFinite() || !(f.mass_kg > 0.0)) continue;
    Eigen::Vector3d accel = ctx.gravity_mps2;
    if (s.slot[i] >= 0) {
      const Eigen::Vector3d push =
          s.out.forces[static_cast<std::size_t>(s.slot[i])].force_N / f.mass_kg;
      accel += push;
      p.base_accel = norm3(push);
    }
    p.d = cam.to_camera(f.position_m);
    p.w = cam.dir_to_camera(f.velocity_mps - ctx.camera_velocity_mps);
    p.a = cam.dir_to_camera(accel);
    // A fragment known only by its bounding sphere (the controller library's) is drawn as that
    // sphere's shadow, larger than its true mean shadow, so the bound errs toward clearing more.
    p.rho = f.half_extents_m.isZero() ? f.radius_m : disc_radius_m(f.half_extents_m);
    p.valid = p.rho > 0.0 && p.d.allFinite() && p.a.allFinite();
    if (!p.valid) continue;
    for (int j = 0; j < k_samples; ++j) {
      const double t = times_s_[static_cast<std::size_t>(j)];
      const Eigen::Vector3d pos = p.d + p.w * t + p.a * per_accel(t, dt);
      const std::size_t at = i * static_cast<std::size_t>(k_samples) + static_cast<std::size_t>(j);
      disc_[at] = screen.disc_at(pos, p.rho);
      own_[at] = paint(j, disc_[at], +1);
    }
  }
}

double OcclusionBound::share(const Step& s, int j) const {
  return covered_[static_cast<std::size_t>(j)] / static_cast<double>(s.cells);
}

bool OcclusionBound::over(const Step& s, int j) const {
  return covered_[static_cast<std::size_t>(j)] > s.bound_cells;
}

bool OcclusionBound::any_over(const Step& s) const {
  for (int j = 0; j < s.k_samples; ++j) {
    if (over(s, j)) return true;
  }
  return false;
}

// One fragment's least push out of the region, per way the least constant push that takes its disc
// out at every over-bound sample it covers that a push within a_room can still clear, and of the
// ways the least push over weight. {4, 0} means no way helps.
std::pair<std::size_t, double> OcclusionBound::plan(const Step& s, const Path& p,
                                                    std::size_t i) const {
  const int k_samples = s.k_samples;
  const double dt = s.dt;
  const Screen screen = s.screen;
  const double a_room = s.params.a_max_mps2 - p.base_accel;
  if (!(a_room > 0.0)) return {4, 0.0};
  std::array<double, 4> need{};
  std::array<bool, 4> helps{};
  for (int j = 0; j < k_samples; ++j) {
    const std::size_t at = i * static_cast<std::size_t>(k_samples) + static_cast<std::size_t>(j);
    if (!over(s, j) || own_[at] == 0) continue;
    const double t = times_s_[static_cast<std::size_t>(j)];
    const Eigen::Vector3d pos = p.d + p.w * t + p.a * per_accel(t, dt);
    const double ze = std::max(pos.z(), screen.near_m);
    const double sx = screen.sx;
    const double sy = screen.sy;
    const std::array<double, 4> gap{sy * ze + p.rho - pos.y(), sy * ze + p.rho + pos.y(),
                                    sx * ze + p.rho - pos.x(), sx * ze + p.rho + pos.x()};
    const double per = per_accel(t, dt);
    for (std::size_t k = 0; k < 4; ++k) {
      const double a = std::max(0.0, gap[k]) / per;
      if (!(a <= a_room)) continue;
      need[k] = std::max(need[k], a);
      helps[k] = true;
    }
  }
  std::size_t best = 4;
  double best_score = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    if (!helps[k] || !(s.weights[k] > 0.0) || !(need[k] > 0.0)) continue;
    const double score = need[k] / s.weights[k];
    if (best == 4 || score < best_score) {
      best = k;
      best_score = score;
    }
  }
  return {best, best == 4 ? 0.0 : need[best]};
}

// Fragments pushed last step are taken first, then by cells covered per push, as a push is a plan
// until the fragment is out, and a plan handed from fragment to fragment every step moves many a
// little and clears none.
void OcclusionBound::rank_fragments(const Step& s, const ResourceVector<Path>& paths,
                                    ResourceVector<std::tuple<int, double, int>>& order) {
  const std::size_t n = s.n;
  const int k_samples = s.k_samples;
  if (pushed_last_.size() != n) pushed_last_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    int most = 0;
    for (int j = 0; j < k_samples; ++j) {
      const std::size_t at = i * static_cast<std::size_t>(k_samples) + static_cast<std::size_t>(j);
      if (over(s, j)) most = std::max(most, own_[at]);
    }
    if (most == 0) continue;
    const auto [way, need] = plan(s, paths[i], i);
    if (way == 4) continue;
    const double score = most / need;
    order.push_back({pushed_last_[i] ? 0 : 1, -score, static_cast<int>(i)});
  }
  std::sort(order.begin(), order.end());
  std::fill(pushed_last_.begin(), pushed_last_.end(), 0);
}

// The fragments in that order, each pushed out and redrawn on its pushed path, until no sample is
// over the bound.
void OcclusionBound::push_in_order(Step& s, const ResourceVector<Path>& paths,
                                   const ResourceVector<std::tuple<int, double, int>>& order) {
  const int k_samples = s.k_samples;
  const double dt = s.dt;
  const Screen screen = s.screen;
  const std::array<Eigen::Vector3d, 4> way_cam{Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, -1, 0),
                                               Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0)};
  const std::array<Eigen::Vector3d, 4> way_world{s.cam.up, -s.cam.up, s.cam.right, -s.cam.right};
  for (const auto& [later, neg_score, fi] : order) {
    if (!any_over(s)) break;
    const auto i = static_cast<std::size_t>(fi);
    const Path& p = paths[i];
    const auto [best, a_push] = plan(s, p, i);
    if (best == 4) continue;
    // Redraw it on its pushed path.
    const Eigen::Vector3d push_cam = a_push * way_cam[best];
    for (int j = 0; j < k_samples; ++j) {
      const std::size_t at = i * static_cast<std::size_t>(k_samples) + static_cast<std::size_t>(j);
      paint(j, disc_[at], -1);
      const double t = times_s_[static_cast<std::size_t>(j)];
      const Eigen::Vector3d pos = p.d + p.w * t + (p.a + push_cam) * per_accel(t, dt);
      disc_[at] = screen.disc_at(pos, p.rho);
      own_[at] = paint(j, disc_[at], +1);
    }
    ++pushed_;
    pushed_last_[i] = 1;
    add_force(s, i, s.ctx.fragments[i].mass_kg * a_push * way_world[best]);
  }
}

void OcclusionBound::step(const StepContext& ctx, const EdgeMinParams& params,
                          const std::array<double, 4>& weights, StepOutput& out) {
  times_s_.clear();
  before_.clear();
  after_.clear();
  pushed_ = 0;
  if (!(params.cover_max < 1.0)) return;
  const int k_samples = sample_times(ctx, params);
  const std::size_t cells = make_grid(ctx.camera, params, ctx.fragments.size(), k_samples);
  Step s(ctx, params, weights, out, k_samples, cells, mem_);
  brake_behind_camera(s);
  ResourceVector<Path> paths(s.n, mem_);
  draw_paths(s, paths);
  for (int j = 0; j < k_samples; ++j) before_.push_back(share(s, j));
  if (!any_over(s)) {
    after_ = before_;
    std::fill(pushed_last_.begin(), pushed_last_.end(), 0);
    return;
  }
  ResourceVector<std::tuple<int, double, int>> order(mem_);  // (not pushed last, -score, fragment)
  rank_fragments(s, paths, order);
  push_in_order(s, paths, order);
  for (int j = 0; j < k_samples; ++j) after_.push_back(share(s, j));
}

}  // namespace fragsim
