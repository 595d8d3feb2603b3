#include "control/strategies/edge_strategy.hpp"

#include <algorithm>
#include <limits>

#include "control/geometry/vec3_sums.hpp"
#include "control/geometry/work_space.hpp"
#include "control/strategies/force_cap.hpp"

namespace fragsim {
namespace {

constexpr double kNoContact = std::numeric_limits<double>::quiet_NaN();

}  // namespace

void EdgeStrategy::reset(int fragment_count) {
  // At t = 0 every fragment is examined; afterwards only those still candidates.
  candidate_.assign(static_cast<std::size_t>(fragment_count), 1);
  pushed_.assign(static_cast<std::size_t>(fragment_count), 0);
  predicted_.assign(static_cast<std::size_t>(fragment_count), 0);
  last_contact_s_.assign(static_cast<std::size_t>(fragment_count), kNoContact);
  // The work space too, its pages touched, as the explosion's first step examines every fragment
  // and must not spend its time on page faults (geometry/work_space.hpp).
  reserve(fragment_count);
}

void EdgeStrategy::reserve(int fragment_count) {
  const auto n = static_cast<std::size_t>(std::max(fragment_count, 0));
  for (auto* v : {&candidate_, &pushed_, &predicted_, &candidate_before_, &pushed_before_,
                  &predicted_before_}) {
    v->reserve(n);
  }
  last_contact_s_.reserve(n);
  last_contact_before_s_.reserve(n);
  reserve_touched(screen_, n);
  reserve_touched(guess_s_, n);
  reserve_touched(examined_, n);
  predictor_.reserve(n);
}

void EdgeStrategy::carry_over(std::span<const int> previous) {
  // Each into its spare array, which then keeps the state before the call for undo_carry_over.
  auto remap = [&previous]<class T>(ResourceVector<T>& state, ResourceVector<T>& spare, T fresh) {
    spare.assign(previous.size(), fresh);
    for (std::size_t i = 0; i < previous.size(); ++i) {
      const int j = previous[i];
      if (j >= 0 && static_cast<std::size_t>(j) < state.size()) {
        spare[i] = state[static_cast<std::size_t>(j)];
      }
    }
    state.swap(spare);
  };
  remap(candidate_, candidate_before_, char{1});
  remap(pushed_, pushed_before_, char{0});
  remap(predicted_, predicted_before_, char{0});
  remap(last_contact_s_, last_contact_before_s_, kNoContact);
}

void EdgeStrategy::undo_carry_over() {
  candidate_.swap(candidate_before_);
  pushed_.swap(pushed_before_);
  predicted_.swap(predicted_before_);
  last_contact_s_.swap(last_contact_before_s_);
}

bool EdgeStrategy::should_examine(const StepContext& ctx, std::size_t i) const {
  if (candidate_[i]) return true;
  switch (params_.replan) {
    case Replan::kNever:
      return false;
    case Replan::kContact:
      return ctx.fragments[i].touched || pushed_[i];
    case Replan::kAlways:
      return true;
  }
  return false;
}

void EdgeStrategy::step(const StepContext& ctx, StepOutput& out) {
  const CameraPose& cam = ctx.camera;
  ContactQuery query;
  query.camera_m = cam.eye_m;
  query.gravity_mps2 = ctx.gravity_mps2;
  query.predictor = params_.predictor;
  query.dt_s = ctx.dt_s;
  query.y_ref_m = params_.horizon == Horizon::kCamera ? cam.eye_m.y() : ctx.ground_height_m;
  // t_G's fallback and cap is the parameter (a game has no scene end), or the shot's end if sooner.
  query.remaining_s = std::max(std::min(params_.horizon_cap_s, ctx.end_time_s - ctx.t_s), 0.0);
  query.reach = params_.reach;
  query.max_speed_mps = ctx.camera_max_speed_mps;
  query.body_radius_m = norm3(ctx.camera_body_half_m);
  const double half_w_m = cam.near_half_width_m();
  const double half_h_m = cam.near_half_height_m();

  // Every fragment to examine is predicted at once (ContactPredictor gives the same answers as one
  // at a time, with the cheap rejection batched). A fragment that was a candidate a step ago is
  // nearly always one still, so trying the rejection on it would only cost time.
  examined_.clear();
  screen_.clear();
  guess_s_.clear();
  for (std::size_t i = 0; i < ctx.fragments.size(); ++i) {
    if (!should_examine(ctx, i)) continue;
    examined_.push_back(static_cast<int>(i));
    screen_.push_back(predicted_[i] ? 0 : 1);
    // The search starts where the last step's contact is now (NaN means no guess).
    guess_s_.push_back(last_contact_s_[i] - ctx.dt_s);
  }
  // A quarter step either side of the guess, which already takes the contact's move of about -dt
  // a step; the push's own effect on it is a fraction of that.
  const auto predictions =
      predictor_.predict(query, ctx.fragments, examined_, screen_, guess_s_, 0.25 * ctx.dt_s);

  for (std::size_t k = 0; k < examined_.size(); ++k) {
    const auto i = static_cast<std::size_t>(examined_[k]);
    const ContactPrediction& pred = predictions[k];
    pushed_[i] = 0;
    candidate_[i] = pred.candidate ? 1 : 0;
    predicted_[i] = candidate_[i];
    last_contact_s_[i] = pred.candidate ? pred.t_contact_s : kNoContact;
    if (!pred.candidate) continue;
    out.activity.candidates.push_back(static_cast<int>(i));
    const FragmentState& f = ctx.fragments[i];

    // The push is toward the near rectangle's edge nearest to where the path will cross it. A path
    // that will not cross (already past, or moving away) is judged where it is now.
    const Eigen::Vector3d dir =
        crossing_edge_direction(query.path(f), cam, ctx.camera_velocity_mps, pred.t_horizon_s,
                                f.position_m, half_w_m, half_h_m);

    // Magnitude (3.4) is k |V_pc| / (|P_pc|^2 (t_C - t)). Both denominators vanish at the camera,
    // so they are kept at least one step and one contact distance, and the result capped.
    const double contact_radius_m = query.model(f).radius_m;
    const double rel_speed_mps = norm3(f.velocity_mps - ctx.camera_velocity_mps);
    double dist_m = norm3(f.position_m - cam.eye_m);
    double lead_s = pred.t_contact_s;
    if (lead_s < ctx.dt_s || dist_m < contact_radius_m) ++out.activity.guarded;
    lead_s = std::max(lead_s, ctx.dt_s);
    dist_m = std::max(dist_m, contact_radius_m);
    const double force_N = params_.k * rel_speed_mps / (dist_m * dist_m * lead_s);
    const std::size_t before = out.forces.size();
    apply_capped(out, static_cast<int>(i), force_N * dir, f.mass_kg, params_.a_max_mps2);
    pushed_[i] = out.forces.size() > before ? 1 : 0;
  }
}

}  // namespace fragsim
