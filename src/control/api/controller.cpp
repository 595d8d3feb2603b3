#include "control/api/controller.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <span>

#include "control/api/def_mapping.hpp"
#include "control/api/fragment_io.hpp"
#include "control/api/ground_frame.hpp"
#include "control/strategies/deflect_all_strategy.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "control/strategies/edge_strategy.hpp"

namespace fragsim::control {
namespace {

Eigen::Vector3d vec(const fragsim_vec3& v) {
  return {v.x, v.y, v.z};
}

bool same_bits(const fragsim_vec3& a, const fragsim_vec3& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

Controller* Controller::create(const fragsim_controller_def& def) {
  HookResource hook(def);
  void* p = hook.allocate(sizeof(Controller), alignof(Controller));
  try {
    return new (p) Controller(def);
  } catch (...) {
    hook.deallocate(p, sizeof(Controller), alignof(Controller));
    throw;
  }
}

void Controller::destroy(Controller* c) noexcept {
  if (c == nullptr) return;
  HookResource hook = c->hook_;  // the same allocator, outliving the controller
  c->~Controller();
  hook.deallocate(c, sizeof(Controller), alignof(Controller));
}

void StrategyDelete::operator()(Strategy* s) const noexcept {
  s->~Strategy();
  mem->deallocate(s, size, align);
}

template <class S, class Params>
StrategyPtr Controller::make_strategy(const Params& params, S** made) {
  void* p = mem_->allocate(sizeof(S), alignof(S));
  S* s = nullptr;
  try {
    s = new (p) S(params, mem_);
  } catch (...) {
    mem_->deallocate(p, sizeof(S), alignof(S));
    throw;
  }
  *made = s;
  return StrategyPtr(s, {mem_, sizeof(S), alignof(S)});
}

CameraSlot Controller::make_slot() {
  CameraSlot slot(mem_);
  switch (raw(def_.strategy)) {
    case FRAGSIM_STRATEGY_EDGE_MIN:
      slot.strategy = make_strategy(edge_min_params(def_), &slot.edge_min);
      break;
    case FRAGSIM_STRATEGY_EDGE:
      slot.strategy = make_strategy(edge_params(def_), &slot.edge);
      break;
    case FRAGSIM_STRATEGY_DEFLECT_ALL: {
      DeflectAllStrategy* unused = nullptr;
      slot.strategy = make_strategy(deflect_all_params(def_), &unused);
      break;
    }
  }
  slot.strategy->set_worker_count(def_.worker_count);
  slot.strategy->reset(0);
  if (room_ > 0) {
    slot.strategy->reserve(static_cast<int>(room_));
    slot.out.reserve(room_);
  }
  return slot;
}

Controller::Controller(const fragsim_controller_def& def) : hook_(def), def_(def), tasks_(def) {
  if (def.enqueue_task != nullptr) parallel_ = &tasks_;
  // The occlusion bound allocates inside its step, after changing its state.
  undo_safe_ = !(raw(def.strategy) == FRAGSIM_STRATEGY_EDGE_MIN && def.edge_min.cover_max < 1.0);
  slots_.reserve(FRAGSIM_MAX_CAMERAS);
  slots_.push_back(make_slot());
  reset();
}

void Controller::set_cameras(const fragsim_camera_def* cameras, int count) {
  // What can fail goes first (new cameras' strategies, the probe), so failing changes nothing.
  if (count > 1 && raw(def_.strategy) == FRAGSIM_STRATEGY_EDGE_MIN) {
    joint_.make_probe(edge_min_params(def_));
  }
  if (count > 1) joint_.reserve(room_);
  while (static_cast<int>(slots_.size()) < count) slots_.push_back(make_slot());
  for (int j = 0; j < count; ++j) slots_[static_cast<std::size_t>(j)].def = cameras[j];
  camera_count_ = count;
}

void Controller::set_error(const char* why) noexcept {
  std::snprintf(error_, sizeof error_, "%s", why);
}

void Controller::reset() {
  for (CameraSlot& slot : slots_) slot.strategy->reset(0);
  last_ids_.clear();
  ids_[0].clear(0);
  ids_[1].clear(0);
  has_normal_ = false;
}

void Controller::reserve(std::size_t n) {
  reserve_work(n);
  // Both tables, as the explosion's step fills one while the other holds the last step's ids.
  ids_[0].reserve(n);
  ids_[1].reserve(n);
}

void Controller::reserve_work(std::size_t n) {
  if (n <= room_) return;
  if (states_.size() < n) states_.resize(n);
  if (caller_index_.size() < n) caller_index_.resize(n);
  if (ids_now_.size() < n) ids_now_.resize(n);
  if (previous_.size() < n) previous_.resize(n);
  last_ids_.reserve(n);
  out_.reserve(n);
  for (CameraSlot& slot : slots_) {
    slot.strategy->reserve(static_cast<int>(n));
    slot.out.reserve(n);
  }
  if (slots_.size() > 1) joint_.reserve(n);
  room_ = n;
}

fragsim_status Controller::failed(const Failure& f) {
  set_error(f.message);
  return f.status;
}

void Controller::warn_once(std::uint32_t warnings, const fragsim_camera_def& c,
                           const fragsim_camera_pose& p) {
  const std::uint32_t fresh = warnings & ~warned_;
  warned_ |= warnings;
#ifdef NDEBUG
  (void)fresh;
  (void)c;
  (void)p;
#else
  // In debug builds only, a message a developer sees at once, once per kind and controller.
  if (fresh & FRAGSIM_WARNING_CAMERA_OVER_SPEED) {
    std::fprintf(stderr,
                 "fragsim_control: warning: the camera moves faster than its max_speed_mps = %g "
                 "(velocity_mps = %g %g %g): the robust camera models promise nothing then\n",
                 c.max_speed_mps, p.velocity_mps.x, p.velocity_mps.y, p.velocity_mps.z);
  }
  if (fresh & FRAGSIM_WARNING_FOVY_IN_RADIANS) {
    std::fprintf(
        stderr, "fragsim_control: warning: camera.fovy_deg = %g: degrees are expected (radians?)\n",
        c.fovy_deg);
  }
  if (fresh & FRAGSIM_WARNING_BELOW_GROUND) {
    std::fprintf(stderr,
                 "fragsim_control: warning: fragments below the ground plane: is ground_normal "
                 "the engine's up axis (0, 0, 1 for z-up)?\n");
  }
  if (fresh & FRAGSIM_WARNING_UNPROTECTED) {
    std::fprintf(stderr,
                 "fragsim_control: warning: fragments that threaten a camera cannot be pushed "
                 "(mass 0)\n");
  }
  if (fresh & FRAGSIM_WARNING_SKIPPED) {
    std::fprintf(stderr,
                 "fragsim_control: warning: fragments skipped for numbers that break "
                 "fragsim_fragment's rules (stats.first_skipped)\n");
  }
#endif
}

StepContext Controller::context_for(const fragsim_step_input& in, const fragsim_camera_def& c,
                                    const fragsim_camera_pose& pose, const GroundFrame& frame,
                                    std::size_t m) const {
  StepContext ctx;
  ctx.step = 0;
  ctx.t_s = in.time_s;
  ctx.dt_s = in.dt_s;
  // A game has no scene end, so the look-ahead comes from the physics, capped by the def's
  // horizon_cap_s (in the strategies' parameters) and by the caller's end when one is given.
  ctx.end_time_s = in.end_time_s;
  ctx.camera.eye_m = frame.in(vec(pose.eye_m));
  ctx.camera.right = frame.in(vec(pose.right));
  ctx.camera.up = frame.in(vec(pose.up));
  ctx.camera.forward = frame.in(vec(pose.forward));
  ctx.camera.fovy_deg = c.fovy_deg;
  ctx.camera.aspect = c.aspect;
  ctx.camera.near_m = c.near_m;
  ctx.camera.far_m = c.far_m;
  ctx.camera_velocity_mps = frame.in(vec(pose.velocity_mps));
  ctx.camera_max_speed_mps = c.max_speed_mps;
  // FRAGSIM_UNDECLARED is the strategies' kUndeclaredBound, passed on as it is.
  ctx.camera_max_accel_mps2 = c.max_accel_mps2;
  ctx.camera_max_turn_degps = c.max_turn_degps;
  ctx.camera_body_half_m = vec(c.body_half_m);  // along the camera's own axes, so not rotated
  ctx.gravity_mps2 = frame.in(vec(in.gravity_mps2));
  ctx.ground_height_m = in.ground_height_m;
  ctx.fragments = std::span<const FragmentState>(states_.data(), m);
  ctx.parallel = parallel_;
  return ctx;
}

void Controller::undo_carry_over(int cameras) {
  for (int j = 0; j < cameras; ++j) {
    CameraSlot& slot = slots_[static_cast<std::size_t>(j)];
    if (slot.edge != nullptr) slot.edge->undo_carry_over();
    if (slot.edge_min != nullptr) slot.edge_min->undo_carry_over();
  }
}

// One step's numbers, passed from stage to stage (what it found of the fragments and their ids, the
// cameras' contexts, and what the strategies answered).
struct Controller::StepState {
  int cameras = 0;
  // The strategies' state is in the last step's frame, and for the last step's cameras, so another
  // normal, or another camera count, starts afresh.
  bool new_frame = false;
  std::size_t m = 0;  // the fragments usable this step
  int skipped = 0;
  int first_skipped = -1;
  int below_ground = 0;
  int first_below_ground = -1;
  // The same ids as the last step, in the same order, so no re-index.
  bool same_ids = false;
  int new_ids = 0;
  int dropped_ids = 0;
  std::array<StepContext, FRAGSIM_MAX_CAMERAS> contexts;
  std::array<const StepOutput*, FRAGSIM_MAX_CAMERAS> outs{};
  JointPush::Conflicts conflicts;
  int pushed = 0;
  int unprotected = 0;
};

fragsim_status Controller::check_input(const fragsim_step_input& in) {
  if (camera_count_ == 0) {
    return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                       "cameras: none set: call fragsim_controller_set_cameras before the first "
                       "step"));
  }
  // The count first, since a wrong count would have the poses read past the caller's array.
  if (in.camera_count != camera_count_) {
    return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                       "camera_count = %d: the controller has %d camera(s) set "
                       "(fragsim_controller_set_cameras)",
                       static_cast<int>(in.camera_count), camera_count_));
  }
  if (Failure f = validate_step_input(in)) return failed(f);
  return FRAGSIM_OK;
}

// Counts stay in locals while the loop runs, since through this_step they could alias the stores of
// the ids and the compiler would keep them in memory.
template <class Source>
void Controller::read_fragments(const fragsim_step_input& in, const Source& src, std::size_t n,
                                const GroundFrame& frame, StepState& this_step) {
  std::size_t m = 0;
  int skipped = 0;
  int first_skipped = -1;
  int below_ground = 0;
  int first_below_ground = -1;
  FragmentIn f;
  for (std::size_t i = 0; i < n; ++i) {
    src.read(i, f);
    if (!fragment_usable(f.position_m, f.velocity_mps, f.radius_m, f.mass_kg)) {
      if (skipped++ == 0) first_skipped = static_cast<int>(i);
      continue;
    }
    FragmentState& s = states_[m];
    s.position_m = frame.in({f.position_m[0], f.position_m[1], f.position_m[2]});
    s.velocity_mps = frame.in({f.velocity_mps[0], f.velocity_mps[1], f.velocity_mps[2]});
    s.radius_m = f.radius_m;
    s.mass_kg = f.mass_kg;
    s.touched = src.touched(i);
    // In the strategies' frame y is the height along the ground's normal. Wholly beneath it is
    // below ground, as an engine's contacts let a landing body sink a little, never by its whole
    // size.
    if (s.position_m.y() + s.radius_m < in.ground_height_m && below_ground++ == 0) {
      first_below_ground = static_cast<int>(i);
    }
    caller_index_[m] = static_cast<std::int32_t>(i);
    ids_now_[m] = src.id(i);
    ++m;
  }
  this_step.m = m;
  this_step.skipped = skipped;
  this_step.first_skipped = first_skipped;
  this_step.below_ground = below_ground;
  this_step.first_below_ground = first_below_ground;
}

fragsim_status Controller::match_ids(StepState& this_step) {
  const std::size_t m = this_step.m;
  // The same list as the last step (the usual case, an engine passing its array every step) needs
  // neither the duplicate check nor a re-index, as that step already passed both.
  this_step.same_ids = !this_step.new_frame && last_ids_.size() == m &&
                       std::equal(last_ids_.begin(), last_ids_.end(), ids_now_.begin());
  if (this_step.same_ids) return FRAGSIM_OK;
  IdTable& now = ids_[1 - last_];
  now.clear(m);
  for (std::size_t k = 0; k < m; ++k) {
    if (!now.insert(ids_now_[k], static_cast<std::int32_t>(k))) {
      const auto first = static_cast<std::size_t>(now.find(ids_now_[k]));
      return failed(
          fail(FRAGSIM_ERROR_DUPLICATE_ID, "fragments[%d].id = %llu: the id of fragments[%d] too",
               static_cast<int>(caller_index_[k]), static_cast<unsigned long long>(ids_now_[k]),
               static_cast<int>(caller_index_[first])));
    }
  }
  int new_ids = 0;
  int kept = 0;
  for (std::size_t k = 0; k < m; ++k) {
    // In a new frame every fragment is new, as after a reset (the state kept is in the last frame).
    previous_[k] = this_step.new_frame ? -1 : ids_[last_].find(ids_now_[k]);
    if (previous_[k] < 0) {
      ++new_ids;
    } else {
      ++kept;
    }
  }
  this_step.new_ids = new_ids;
  this_step.dropped_ids = static_cast<int>(last_ids_.size()) - kept;
  return FRAGSIM_OK;
}

void Controller::make_contexts(const fragsim_step_input& in, const GroundFrame& frame,
                               StepState& this_step) const {
  for (int j = 0; j < this_step.cameras; ++j) {
    const auto k = static_cast<std::size_t>(j);
    this_step.contexts[k] = context_for(in, slots_[k].def, in.camera_poses[j], frame, this_step.m);
    this_step.outs[k] = &slots_[k].out;
  }
}

void Controller::carry_over_ids(const StepState& this_step) {
  const std::span<const int> previous(previous_.data(), this_step.m);
  for (int j = 0; j < this_step.cameras; ++j) {
    CameraSlot& slot = slots_[static_cast<std::size_t>(j)];
    // The occlusion bound's state is kept by place, not id, and cannot be undone anyway, so a new
    // frame resets it as reset() would (its failure below forgets everything too).
    if (this_step.new_frame && !undo_safe_) slot.strategy->reset(0);
    if (!this_step.same_ids && slot.edge != nullptr) slot.edge->carry_over(previous);
    if (!this_step.same_ids && slot.edge_min != nullptr) slot.edge_min->carry_over(previous);
  }
}

void Controller::ask_cameras(StepState& this_step) {
  const int cameras = this_step.cameras;
  for (int j = 0; j < cameras; ++j) {
    CameraSlot& slot = slots_[static_cast<std::size_t>(j)];
    // One camera answers the step itself; several answer to the join below.
    StepOutput& answer = cameras == 1 ? out_ : slot.out;
    answer.clear();
    slot.strategy->step(this_step.contexts[static_cast<std::size_t>(j)], answer);
  }
  if (cameras > 1) {
    out_.clear();
    this_step.conflicts = joint_.join(
        std::span<const StepContext>(this_step.contexts.data(), this_step.contexts.size())
            .first(static_cast<std::size_t>(cameras)),
        std::span<const StepOutput* const>(this_step.outs.data(), this_step.outs.size())
            .first(static_cast<std::size_t>(cameras)),
        std::span<const FragmentState>(states_.data(), this_step.m), out_);
  }
}

fragsim_status Controller::run_strategies(StepState& this_step) {
  tasks_.begin_step();
  try {
    carry_over_ids(this_step);
    ask_cameras(this_step);
  } catch (const std::bad_alloc&) {
    if (undo_safe_) {
      if (!this_step.same_ids) undo_carry_over(this_step.cameras);
      set_error("out of memory");
    } else {
      reset();
      set_error(
          "out of memory inside the occlusion bound's step (edge_min.cover_max < 1): every "
          "fragment was forgotten, as after fragsim_controller_reset");
    }
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }
  return FRAGSIM_OK;
}

fragsim_status Controller::check_answer(const StepState& this_step) {
  if (parallel_ != nullptr && tasks_.broken()) {
    // The strategies' answer is incomplete and their state may hold parts of it.
    reset();
    set_error(
        "enqueue_task ran a range on a worker_index not below worker_count, or did not run every "
        "item exactly once: every fragment was forgotten, as after fragsim_controller_reset");
    return FRAGSIM_ERROR_INVALID_ARGUMENT;
  }
  // Never a non-finite force out, whatever happened inside (the strategies already drop them).
  for (const AppliedForce& a : out_.forces) {
    if (!a.force_N.allFinite() || a.fragment < 0 ||
        static_cast<std::size_t>(a.fragment) >= this_step.m) {
      // A bug leaves the strategy's state untrustworthy, so nothing is kept.
      reset();
      set_error("internal: a strategy produced a non-finite force or a bad index");
      return FRAGSIM_ERROR_INTERNAL;
    }
  }
  return FRAGSIM_OK;
}

template <class Sink>
void Controller::write_forces(const GroundFrame& frame, std::size_t n, const Sink& sink,
                              StepState& this_step) const {
  sink.zero(n);
  int pushed = 0;
  for (const AppliedForce& a : out_.forces) {
    const auto k = static_cast<std::size_t>(a.fragment);
    sink.set(static_cast<std::size_t>(caller_index_[k]), frame.out(a.force_N));
    if (!a.force_N.isZero(0.0)) ++pushed;
  }
  this_step.pushed = pushed;
}

void Controller::remember_step(const fragsim_step_input& in, const StepState& this_step) {
  if (!this_step.same_ids) {
    last_ = 1 - last_;
    last_ids_.assign(ids_now_.begin(), ids_now_.begin() + static_cast<std::ptrdiff_t>(this_step.m));
  }
  last_normal_ = in.ground_normal;
  has_normal_ = true;
  last_cameras_ = this_step.cameras;
}

int Controller::count_unprotected() const {
  int unprotected = 0;
  for (const int k : out_.activity.candidates) {
    if (states_[static_cast<std::size_t>(k)].mass_kg == 0.0) ++unprotected;
  }
  return unprotected;
}

std::uint32_t Controller::warn(const fragsim_step_input& in, const StepState& this_step) {
  std::uint32_t warnings = 0;
  if (this_step.below_ground > 0) warnings |= FRAGSIM_WARNING_BELOW_GROUND;
  if (this_step.unprotected > 0) warnings |= FRAGSIM_WARNING_UNPROTECTED;
  if (this_step.skipped > 0) warnings |= FRAGSIM_WARNING_SKIPPED;
  for (int j = 0; j < this_step.cameras; ++j) {
    const fragsim_camera_def& c = slots_[static_cast<std::size_t>(j)].def;
    const std::uint32_t w = camera_warnings(c, in.camera_poses[j]) | warnings;
    if (w != 0) warn_once(w, c, in.camera_poses[j]);
    warnings |= w;
  }
  return warnings;
}

void Controller::write_stats(const StepState& this_step, std::uint32_t warnings,
                             fragsim_step_stats& stats) const {
  stats.candidates = static_cast<std::int32_t>(out_.activity.candidates.size());
  stats.pushed = this_step.pushed;
  stats.capped = static_cast<std::int32_t>(out_.activity.capped.size());
  stats.guarded = out_.activity.guarded;
  stats.new_ids = this_step.new_ids;
  stats.dropped_ids = this_step.dropped_ids;
  stats.deferred = out_.activity.deferred;
  stats.rejected_cheaply = out_.activity.rejected_cheaply;
  stats.skipped = this_step.skipped;
  stats.first_skipped = this_step.first_skipped;
  stats.unprotected = this_step.unprotected;
  stats.below_ground = this_step.below_ground;
  stats.first_below_ground = this_step.first_below_ground;
  stats.warnings = warnings;
  stats.conflicts = this_step.conflicts.count;
  stats.first_conflict = this_step.conflicts.first < 0
                             ? -1
                             : caller_index_[static_cast<std::size_t>(this_step.conflicts.first)];
}

template <class Source, class Sink>
fragsim_status Controller::step(const fragsim_step_input& in, const Source& src, std::size_t n,
                                const Sink& sink, fragsim_step_stats* stats) {
  // Phase 1 checks and makes room; nothing here changes the controller's state.
  if (const fragsim_status status = check_input(in); status != FRAGSIM_OK) return status;
  // The id table this step fills grows below, only if it must (a table grown here for nothing
  // would cost the first call its page faults).
  reserve_work(n);
  const GroundFrame frame(in.ground_normal);
  StepState this_step;
  this_step.cameras = in.camera_count;
  this_step.new_frame = has_normal_ && (!same_bits(in.ground_normal, last_normal_) ||
                                        this_step.cameras != last_cameras_);
  read_fragments(in, src, n, frame, this_step);
  if (const fragsim_status status = match_ids(this_step); status != FRAGSIM_OK) return status;
  make_contexts(in, frame, this_step);

  // Phase 2 runs the strategies in the room made above.
  if (const fragsim_status status = run_strategies(this_step); status != FRAGSIM_OK) return status;
  if (const fragsim_status status = check_answer(this_step); status != FRAGSIM_OK) return status;
  write_forces(frame, n, sink, this_step);
  remember_step(in, this_step);
  this_step.unprotected = count_unprotected();
  const std::uint32_t warnings = warn(in, this_step);
  if (stats != nullptr) write_stats(this_step, warnings, *stats);
  clear_error();
  return FRAGSIM_OK;
}

template fragsim_status Controller::step(const fragsim_step_input&, const StructSource&,
                                         std::size_t, const StructSink&, fragsim_step_stats*);
template fragsim_status Controller::step(const fragsim_step_input&, const ArraySource&, std::size_t,
                                         const ArraySink&, fragsim_step_stats*);

}  // namespace fragsim::control
