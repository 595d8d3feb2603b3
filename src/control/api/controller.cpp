#include "api/controller.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <span>

#include "api/def_mapping.hpp"
#include "api/fragment_io.hpp"
#include "api/ground_frame.hpp"
#include "strategies/deflect_all_strategy.hpp"
#include "strategies/edge_min_strategy.hpp"
#include "strategies/edge_strategy.hpp"

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
S* Controller::make_strategy(const Params& params) {
  void* p = mem_->allocate(sizeof(S), alignof(S));
  S* s = nullptr;
  try {
    s = new (p) S(params, mem_);
  } catch (...) {
    mem_->deallocate(p, sizeof(S), alignof(S));
    throw;
  }
  strategy_ = std::unique_ptr<Strategy, StrategyDelete>(s, {mem_, sizeof(S), alignof(S)});
  return s;
}

Controller::Controller(const fragsim_controller_def& def) : hook_(def) {
  switch (raw(def.strategy)) {
    case FRAGSIM_STRATEGY_EDGE_MIN:
      edge_min_ = make_strategy<EdgeMinStrategy>(edge_min_params(def));
      // The occlusion bound allocates inside its step, after changing its state.
      undo_safe_ = !(def.edge_min.cover_max < 1.0);
      break;
    case FRAGSIM_STRATEGY_EDGE:
      edge_ = make_strategy<EdgeStrategy>(edge_params(def));
      break;
    case FRAGSIM_STRATEGY_DEFLECT_ALL:
      make_strategy<DeflectAllStrategy>(deflect_all_params(def));
      break;
  }
  reset();
}

void Controller::set_error(const char* why) noexcept {
  std::snprintf(error_, sizeof error_, "%s", why);
}

void Controller::reset() {
  strategy_->reset(0);
  last_ids_.clear();
  ids_[0].clear(0);
  ids_[1].clear(0);
  has_normal_ = false;
}

void Controller::reserve(std::size_t n) {
  reserve_work(n);
  // Both tables: the explosion's step fills one while the other holds the last step's ids.
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
  strategy_->reserve(static_cast<int>(n));
  room_ = n;
}

fragsim_status Controller::failed(const Failure& f) {
  set_error(f.message);
  return f.status;
}

void Controller::warn_once(std::uint32_t warnings, const fragsim_camera& c) {
  const std::uint32_t fresh = warnings & ~warned_;
  warned_ |= warnings;
#ifdef NDEBUG
  (void)fresh;
  (void)c;
#else
  // Debug builds only: a message a developer sees at once, once per kind and controller.
  if (fresh & FRAGSIM_WARNING_CAMERA_OVER_SPEED) {
    std::fprintf(stderr,
                 "fragsim_control: warning: the camera moves faster than its max_speed_mps = %g "
                 "(velocity_mps = %g %g %g): the robust camera models promise nothing then\n",
                 c.max_speed_mps, c.velocity_mps.x, c.velocity_mps.y, c.velocity_mps.z);
  }
  if (fresh & FRAGSIM_WARNING_FOVY_IN_RADIANS) {
    std::fprintf(
        stderr, "fragsim_control: warning: camera.fovy_deg = %g: degrees are expected (radians?)\n",
        c.fovy_deg);
  }
  if (fresh & FRAGSIM_WARNING_TURN_IN_DEGREES) {
    std::fprintf(stderr,
                 "fragsim_control: warning: camera.max_turn_radps = %g: radians per second are "
                 "expected (degrees?)\n",
                 c.max_turn_radps);
  }
#endif
}

template <class Source, class Sink>
fragsim_status Controller::step(const fragsim_step_input& in, const Source& src, std::size_t n,
                                const Sink& sink, fragsim_step_stats* stats) {
  // Phase 1: checks and room. Nothing here changes the controller's state.
  if (Failure f = validate_step_input(in)) return failed(f);
  // The id table this step fills grows below, only if it must (a table grown here for nothing
  // would cost the first call its page faults).
  reserve_work(n);
  const GroundFrame frame(in.ground_normal);
  // The strategies' state is in the last step's frame: another normal starts afresh (below).
  const bool new_frame = has_normal_ && !same_bits(in.ground_normal, last_normal_);
  std::size_t m = 0;
  int skipped = 0;
  int first_skipped = -1;
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
    caller_index_[m] = static_cast<std::int32_t>(i);
    ids_now_[m] = src.id(i);
    ++m;
  }

  // Ids: the same list as the last step (the usual case, an engine passing its array every step)
  // needs neither the duplicate check nor a re-index: that step already passed both.
  const bool same_ids = !new_frame && last_ids_.size() == m &&
                        std::equal(last_ids_.begin(), last_ids_.end(), ids_now_.begin());
  int new_ids = 0;
  int dropped_ids = 0;
  IdTable& now = ids_[1 - last_];
  if (!same_ids) {
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
    int kept = 0;
    for (std::size_t k = 0; k < m; ++k) {
      // A new frame: every fragment new, as after a reset (the state kept is in the old frame).
      previous_[k] = new_frame ? -1 : ids_[last_].find(ids_now_[k]);
      if (previous_[k] < 0) {
        ++new_ids;
      } else {
        ++kept;
      }
    }
    dropped_ids = static_cast<int>(last_ids_.size()) - kept;
  }

  StepContext ctx;
  ctx.step = 0;
  ctx.t_s = in.time_s;
  ctx.dt_s = in.dt_s;
  // A game has no scene end: the look-ahead comes from the physics, capped by the def's
  // horizon_cap_s (in the strategies' parameters) and by the caller's end when one is given.
  ctx.end_time_s = in.end_time_s;
  const fragsim_camera& c = in.camera;
  ctx.camera.eye_m = frame.in(vec(c.eye_m));
  ctx.camera.right = frame.in(vec(c.right));
  ctx.camera.up = frame.in(vec(c.up));
  ctx.camera.forward = frame.in(vec(c.forward));
  ctx.camera.fovy_deg = c.fovy_deg;
  ctx.camera.aspect = c.aspect;
  ctx.camera.near_m = c.near_m;
  ctx.camera.far_m = c.far_m;
  ctx.camera_velocity_mps = frame.in(vec(c.velocity_mps));
  ctx.camera_max_speed_mps = c.max_speed_mps;
  // FRAGSIM_UNDECLARED is the strategies' kUndeclaredBound: passed on as it is.
  ctx.camera_max_accel_mps2 = c.max_accel_mps2;
  ctx.camera_max_turn_radps = c.max_turn_radps;
  ctx.camera_body_half_m = vec(c.body_half_m);  // along the camera's own axes: not rotated
  ctx.gravity_mps2 = frame.in(vec(in.gravity_mps2));
  ctx.ground_height_m = in.ground_height_m;
  ctx.fragments = std::span<const FragmentState>(states_.data(), m);

  // Phase 2: the strategy, in the room made above.
  const std::span<const int> previous(previous_.data(), m);
  try {
    // The occlusion bound's state is kept by place, not id, and cannot be undone anyway: a new
    // frame resets it as reset() would (its failure below forgets everything too).
    if (new_frame && !undo_safe_) strategy_->reset(0);
    if (!same_ids && edge_ != nullptr) edge_->carry_over(previous);
    if (!same_ids && edge_min_ != nullptr) edge_min_->carry_over(previous);
    out_.clear();
    strategy_->step(ctx, out_);
  } catch (const std::bad_alloc&) {
    if (undo_safe_) {
      if (!same_ids && edge_ != nullptr) edge_->undo_carry_over();
      if (!same_ids && edge_min_ != nullptr) edge_min_->undo_carry_over();
      set_error("out of memory");
    } else {
      reset();
      set_error(
          "out of memory inside the occlusion bound's step (edge_min.cover_max < 1): every "
          "fragment was forgotten, as after fragsim_controller_reset");
    }
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }

  // Never a non-finite force out, whatever happened inside (the strategies already drop them).
  for (const AppliedForce& a : out_.forces) {
    if (!a.force_N.allFinite() || a.fragment < 0 || static_cast<std::size_t>(a.fragment) >= m) {
      // A bug: the strategy's state is not to be trusted after it, so nothing is kept.
      reset();
      set_error("internal: a strategy produced a non-finite force or a bad index");
      return FRAGSIM_ERROR_INTERNAL;
    }
  }
  sink.zero(n);
  int pushed = 0;
  for (const AppliedForce& a : out_.forces) {
    const auto k = static_cast<std::size_t>(a.fragment);
    sink.set(static_cast<std::size_t>(caller_index_[k]), frame.out(a.force_N));
    if (!a.force_N.isZero(0.0)) ++pushed;
  }
  int unprotected = 0;
  for (const int k : out_.activity.candidates) {
    if (states_[static_cast<std::size_t>(k)].mass_kg == 0.0) ++unprotected;
  }
  if (!same_ids) {
    last_ = 1 - last_;
    last_ids_.assign(ids_now_.begin(), ids_now_.begin() + static_cast<std::ptrdiff_t>(m));
  }
  last_normal_ = in.ground_normal;
  has_normal_ = true;
  const std::uint32_t warnings = camera_warnings(c);
  if (warnings != 0) warn_once(warnings, c);
  if (stats != nullptr) {
    stats->candidates = static_cast<std::int32_t>(out_.activity.candidates.size());
    stats->pushed = pushed;
    stats->capped = static_cast<std::int32_t>(out_.activity.capped.size());
    stats->guarded = out_.activity.guarded;
    stats->new_ids = new_ids;
    stats->dropped_ids = dropped_ids;
    stats->deferred = out_.activity.deferred;
    stats->rejected_cheaply = out_.activity.rejected_cheaply;
    stats->skipped = skipped;
    stats->first_skipped = first_skipped;
    stats->unprotected = unprotected;
    stats->warnings = warnings;
  }
  clear_error();
  return FRAGSIM_OK;
}

template fragsim_status Controller::step(const fragsim_step_input&, const StructSource&,
                                         std::size_t, const StructSink&, fragsim_step_stats*);
template fragsim_status Controller::step(const fragsim_step_input&, const ArraySource&, std::size_t,
                                         const ArraySink&, fragsim_step_stats*);

}  // namespace fragsim::control
