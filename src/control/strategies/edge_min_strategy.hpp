#pragma once
// `edge-min` applies the minimal force of docs/method.md section 4, generalised from the near plane
// to the whole camera. Every step, every fragment's ballistic path relative to the camera (moving
// at its current velocity) is tested against the protected box, the camera body and the near
// rectangle (whichever is larger on each axis) grown by the fragment's bounding radius and a
// margin. A fragment whose path enters it gets, toward one of the four screen edges (+-right,
// +-up), the least constant acceleration that makes the pushed path miss the box; of the four, the
// smallest wins. Re-solved every step, the push fades to zero once the fragment is clear, so
// distant threats get almost nothing, close ones what they need, capped by a_max (the report counts
// the capped fragments that still hit).
//
// It protects a box and not only the near plane, as a fragment steered just past the near
// rectangle's edge still hits a camera body wider than that rectangle, and debris falling onto the
// camera from above never crosses the near plane at all.
//
// What the camera does before the fragment arrives (EdgeMinParams::camera_model, see
// docs/camera_models.md):
// - Under `constant` it keeps its present velocity and orientation; the push above is all.
// - Under `bounded_accel` its velocity changes by at most A per second and its view turns at most w
//   per second (w = inf by default, any turn), and it never moves faster than V_c. The protected
//   box can then be anywhere within rho(t) of where the constant model puts it (or of where it is
//   now, for V_c), so each side of the box is grown by its own rho(t), the translation part plus
//   the turn's chord, the chord never past the ball of the box's farthest corner (any orientation
//   lies in it), a quadratic in t on each side of that side's knee.
// - Under `reachable` it is anywhere within V_c t of where it is (any acceleration), turning at w.
// Both robust models push lazily, with the constant model's push while a push of at most a_max that
// starts one step later would still clear the grown box, and the grown box's least push (at least
// the constant one's) once waiting would not be safe.
//
// The bounds are the scene's declared ones (StepContext::camera_max_accel_mps2, _turn_degps) when
// it declares them (>= 0), otherwise (kUndeclaredBound, for a path or a track, which declares none)
// the parameters' assumed camera_accel_mps2 and camera_turn_degps. A declared infinite acceleration
// (a player with instant turns) leaves bounded_accel only the ball V_c t, which is reachable's
// region, and that still holds, since reachable does not depend on A.
//
// On workers (StepContext::parallel), the cheap rejection runs in chunks and the exact solves of
// the fragments it leaves in doubt in ranges, each fragment's answer to its own place, gathered in
// fragment order afterwards, so every answer is bit for bit the calling thread's. The budget
// (max_solves) and the occlusion bound (cover_max) stay on the calling thread, as the budget ranks
// all the doubts before any solve, and the bound's prediction takes the pushes one by one.

#include <array>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "control/memory/memory_resource.hpp"
#include "control/strategies/edge_min_params.hpp"
#include "control/strategies/occlusion_bound.hpp"
#include "control/strategies/strategy.hpp"
#include "control/strategies/two_box_clearance.hpp"

namespace fragsim {

class EdgeMinStrategy final : public Strategy {
 public:
  // Its state and work space are allocated from `mem` (the controller library's allocator hook).
  explicit EdgeMinStrategy(const EdgeMinParams& params,
                           MemoryResource* mem = default_memory_resource())
      : params_(params),
        mem_(mem),
        // The ways out in the solver's order (+up, -up, +right, -right) from top bottom left right.
        way_weights_{params.edge_weights[0], params.edge_weights[1], params.edge_weights[3],
                     params.edge_weights[2]},
        weighted_(params.edge_weights != std::array<double, 4>{1.0, 1.0, 1.0, 1.0}) {}
  std::string name() const override { return "edge-min"; }
  void reset(int fragment_count) override;
  void step(const StepContext& ctx, StepOutput& out) override;
  // The library's fragments come and go by id. previous[i] is where fragment i was at the last call
  // (-1 if new), so a deferred fragment keeps its own last force (max_solves only). Within the room
  // reserve() made, it allocates nothing. undo_carry_over() puts back the state of before the last
  // carry_over (for a step that failed before it changed any state).
  void carry_over(std::span<const int> previous);
  void undo_carry_over();
  void reserve(int fragment_count) override;
  // A work space per worker for the rejection's chunks (TwoBoxClearance::set_workers).
  void set_worker_count(int workers) override;

  // The time until the path y(t) = y0 + vy t + half_gy t^2 comes down through ground_m, the later
  // root, going down; +inf if it never does (gravity off, or no ground, ground_m = -inf), 0 if it
  // is at or below ground_m now and stays there (resting on the ground).
  static double time_to_ground_s(double y0_m, double vy_mps, double half_gy_mps2, double ground_m);

  // How far a constant acceleration of 1 m/s^2, applied from the coming step on, has moved a body
  // after tau_s under ODE's semi-implicit Euler with step dt_s, the sum over n = tau/dt steps of
  // dt * k dt = (tau^2 + tau dt) / 2.
  static double displacement_per_accel(double tau_s, double dt_s) {
    return 0.5 * (tau_s * tau_s + tau_s * dt_s);
  }

  // The acceleration and turn-rate bounds the robust models use this step (rule above).
  double assumed_accel_mps2(const StepContext& ctx) const;
  double assumed_turn_radps(const StepContext& ctx) const;

  // The occlusion bound's last prediction (cover_max < 1 only).
  const OcclusionBound& occlusion_bound() const { return cover_; }

 private:
  EdgeMinParams params_;
  MemoryResource* mem_;
  std::array<double, 4> way_weights_;
  bool weighted_;
  OcclusionBound cover_{mem_};
  // Work space kept between steps; holds no state of the run (the largest radius of the last step
  // is a hint for the rejection's window, which decides how fast a step is, not its answer).
  TwoBoxClearance clearance_{mem_};
  // What the exact solve gave one fragment, written by whichever worker solved it and gathered in
  // fragment order (the parallel step only). Whether it is a candidate, and the force asked for
  // before the cap, which the gather applies so capped and guarded come out in order too.
  struct SolveAnswer {
    bool candidate = false;
    bool pushed = false;
    Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  };
  ResourceVector<SolveAnswer> answers_{mem_};  // one per unsettled fragment, in its order
  void reserve_answers(std::size_t n);
  double r_max_hint_m_ = -1.0;  // none yet
  // The budget's state (max_solves > 0 only), each fragment's force of the last step it was solved
  // (zero when it was cleared or got none), and this step's ranking and deferrals.
  ResourceVector<Eigen::Vector3d> last_force_N_{mem_};
  ResourceVector<Eigen::Vector3d> carried_from_{mem_};  // last_force_N_ before the last carry_over
  bool carried_over_ = false;                           // ... which did swap the two
  ResourceVector<std::tuple<int, double, int>> queue_{mem_};  // (tier, arrival, fragment)
  ResourceVector<char> deferred_{mem_};

  // The stages of step(), in order, and the step's constants they share (Step, in the .cpp, with
  // the exact solve of one fragment).
  struct Step;
  // The cheap rejection of every fragment (clearance_), putting its answers and the grown box's
  // look-ahead into s.
  void reject_cheaply(Step& s);
  void run_rejection(const StepContext& ctx, const TwoBoxClearance::Boxes& boxes);
  // The budget's ranking (max_solves > 0) picks which fragments this step defers (deferred_).
  void defer_beyond_budget(const Step& s, StepOutput& out);
  // The exact solves of the fragments the rejection left in doubt, into out in the fragments'
  // order, on the calling thread, on the workers (ctx.parallel), or within the budget.
  void solve_in_order(const Step& s, StepOutput& out) const;
  void solve_on_workers(const Step& s, StepOutput& out);
  void solve_within_budget(const Step& s, StepOutput& out);
};

}  // namespace fragsim
