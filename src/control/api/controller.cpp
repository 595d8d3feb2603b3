// The C API of fragsim/control.h over the strategy classes of strategies/: the same compiled code
// fragsim runs, fed a StepContext built from the caller's plain structs. Everything here is
// per controller (no globals); no exception leaves an API function.

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "api/def_mapping.hpp"
#include "api/id_table.hpp"
#include "fragsim/control.h"
#include "geometry/frustum.hpp"
#include "strategies/deflect_all_strategy.hpp"
#include "strategies/edge_min_strategy.hpp"
#include "strategies/edge_strategy.hpp"

namespace {

using fragsim::control::deflect_all_params;
using fragsim::control::edge_min_params;
using fragsim::control::edge_params;
using fragsim::control::kDefCookie;
using fragsim::control::raw;

constexpr std::int32_t kMaxFragments = std::numeric_limits<std::int32_t>::max() / 4;
constexpr double kFrameTolerance = 1e-6;

// A failed check: the status and the message that goes with it.
struct Failure {
  fragsim_status status = FRAGSIM_OK;
  std::string message;
  explicit operator bool() const { return status != FRAGSIM_OK; }
};

[[gnu::format(printf, 2, 3)]] Failure fail(fragsim_status status, const char* format, ...) {
  char buffer[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return {status, buffer};
}

// Rules for numbers, each with the words of the message.
bool finite(double v) {
  return std::isfinite(v);
}
bool nonnegative(double v) {
  return std::isfinite(v) && v >= 0.0;
}
bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
bool bound(double v) {
  return !std::isnan(v) && v >= 0.0;
}  // +inf: undeclared

Failure check(bool ok, const char* name, double value, const char* rule) {
  if (ok) return {};
  return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s = %g: %s", name, value, rule);
}

Failure check_vec(const fragsim_vec3& v, const char* name, bool (*rule)(double),
                  const char* words) {
  const double c[3] = {v.x, v.y, v.z};
  const char* axis[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (!rule(c[k])) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s.%s = %g: %s", name, axis[k], c[k], words);
    }
  }
  return {};
}

// A def field that is one of the strategies' parameters, checked by that parameter's own key (the
// range a scene file's value must keep) and named by its C field. The fields are listed here,
// not taken from the keys, because the C names differ (edge.k_Nms2, one horizon_cap_s for both
// strategies) and the C struct cannot be reflected on.
template <class Params>
Failure check_key(const fragsim::ParamSpec<Params>& spec, const char* key, const Params& p,
                  const char* field) {
  for (const fragsim::settings::Key<Params>& k : spec.keys) {
    if (k.name != key) continue;
    if (const std::optional<std::string> rule = k.broken(p)) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s = %s: %s", field, k.format(p).c_str(),
                  rule->c_str());
    }
    return {};
  }
  return fail(FRAGSIM_ERROR_INTERNAL, "internal: %s has no key %s", field, key);
}

Failure validate(const fragsim_controller_def& def) {
  if (def.internal_value != kDefCookie) {
    return fail(FRAGSIM_ERROR_DEF_NOT_DEFAULTED,
                "def: not initialised with fragsim_default_controller_def()");
  }
  Failure f;
  // The shared fields first, whichever strategy is chosen: a def is valid as a whole.
  const auto& em_keys = fragsim::edge_min_param_spec();
  const fragsim::EdgeMinParams em = edge_min_params(def);
  if ((f = check_key(em_keys, "max_solves", em, "edge_min.max_solves")) ||
      (f = check_key(em_keys, "horizon_cap_s", em, "horizon_cap_s"))) {
    return f;
  }
  switch (raw(def.strategy)) {
    case FRAGSIM_STRATEGY_EDGE_MIN: {
      const fragsim_edge_min_def& p = def.edge_min;
      if ((f = check_key(em_keys, "margin_m", em, "edge_min.margin_m")) ||
          (f = check_key(em_keys, "a_max_mps2", em, "edge_min.a_max_mps2")) ||
          (f = check(raw(p.camera_model) >= FRAGSIM_CAMERA_CONSTANT &&
                         raw(p.camera_model) <= FRAGSIM_CAMERA_REACHABLE,
                     "edge_min.camera_model", raw(p.camera_model),
                     "must be a fragsim_camera_model")) ||
          (f = check_key(em_keys, "camera_accel_mps2", em, "edge_min.camera_accel_mps2")) ||
          (f = check_key(em_keys, "camera_turn_degps", em, "edge_min.camera_turn_degps")) ||
          (f = check_key(em_keys, "edge_weights", em, "edge_min.edge_weights")) ||
          (f = check_key(em_keys, "cover_max", em, "edge_min.cover_max")) ||
          (f = check_key(em_keys, "cover_region", em, "edge_min.cover_region"))) {
        return f;
      }
      return {};
    }
    case FRAGSIM_STRATEGY_EDGE: {
      const fragsim_edge_def& p = def.edge;
      const auto& keys = fragsim::edge_param_spec();
      const fragsim::EdgeParams e = edge_params(def);
      if ((f = check_key(keys, "k", e, "edge.k_Nms2")) ||
          (f = check_key(keys, "a_max_mps2", e, "edge.a_max_mps2")) ||
          (f = check(raw(p.predictor) == FRAGSIM_EDGE_PREDICTOR_THESIS ||
                         raw(p.predictor) == FRAGSIM_EDGE_PREDICTOR_DISCRETE,
                     "edge.predictor", raw(p.predictor), "must be a fragsim_edge_predictor")) ||
          (f = check(raw(p.reach) == FRAGSIM_EDGE_REACH_THESIS ||
                         raw(p.reach) == FRAGSIM_EDGE_REACH_GROWING,
                     "edge.reach", raw(p.reach), "must be a fragsim_edge_reach")) ||
          (f = check(raw(p.horizon) == FRAGSIM_EDGE_HORIZON_CAMERA ||
                         raw(p.horizon) == FRAGSIM_EDGE_HORIZON_GROUND,
                     "edge.horizon", raw(p.horizon), "must be a fragsim_edge_horizon")) ||
          (f = check(raw(p.replan) >= FRAGSIM_EDGE_REPLAN_NEVER &&
                         raw(p.replan) <= FRAGSIM_EDGE_REPLAN_ALWAYS,
                     "edge.replan", raw(p.replan), "must be a fragsim_edge_replan"))) {
        return f;
      }
      return {};
    }
    case FRAGSIM_STRATEGY_DEFLECT_ALL: {
      const auto& keys = fragsim::deflect_all_param_spec();
      const fragsim::DeflectAllParams d = deflect_all_params(def);
      if ((f = check_key(keys, "accel_mps2", d, "deflect_all.accel_mps2")) ||
          (f = check_key(keys, "range_m", d, "deflect_all.range_m"))) {
        return f;
      }
      return {};
    }
  }
  return check(false, "strategy", raw(def.strategy), "must be a fragsim_strategy");
}

Failure validate_frame(const fragsim_camera& c) {
  const fragsim_vec3* axes[3] = {&c.right, &c.up, &c.forward};
  const char* names[3] = {"camera.right", "camera.up", "camera.forward"};
  for (int k = 0; k < 3; ++k) {
    if (Failure f = check_vec(*axes[k], names[k], finite, "must be finite")) return f;
    const fragsim_vec3& a = *axes[k];
    const double n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    if (!(std::abs(n - 1.0) <= kFrameTolerance)) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s has length %.9g: must be 1 (within 1e-6)",
                  names[k], n);
    }
  }
  for (int k = 0; k < 3; ++k) {
    const fragsim_vec3& a = *axes[k];
    const fragsim_vec3& b = *axes[(k + 1) % 3];
    const double dot = a.x * b.x + a.y * b.y + a.z * b.z;
    if (!(std::abs(dot) <= kFrameTolerance)) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                  "%s . %s = %.9g: the camera axes must be at right angles (within 1e-6)", names[k],
                  names[(k + 1) % 3], dot);
    }
  }
  return {};
}

Failure validate(const fragsim_step_input& in) {
  Failure f;
  const fragsim_camera& c = in.camera;
  if ((f = check(finite(in.time_s), "time_s", in.time_s, "must be finite")) ||
      (f = check(!std::isnan(in.end_time_s), "end_time_s", in.end_time_s,
                 "must be a time or INFINITY")) ||
      (f = check(positive(in.dt_s), "dt_s", in.dt_s, "must be finite and > 0")) ||
      (f = check_vec(in.gravity_mps2, "gravity_mps2", finite, "must be finite")) ||
      (f = check(finite(in.ground_height_m) ||
                     in.ground_height_m == -std::numeric_limits<double>::infinity(),
                 "ground_height_m", in.ground_height_m, "must be finite, or -INFINITY for none")) ||
      (f = check_vec(c.eye_m, "camera.eye_m", finite, "must be finite")) ||
      (f = validate_frame(c)) ||
      (f = check_vec(c.velocity_mps, "camera.velocity_mps", finite, "must be finite")) ||
      (f = check(finite(c.fovy_deg) && c.fovy_deg > 0.0 && c.fovy_deg < 180.0, "camera.fovy_deg",
                 c.fovy_deg, "must be in (0, 180)")) ||
      (f = check(positive(c.aspect), "camera.aspect", c.aspect, "must be finite and > 0")) ||
      (f = check(positive(c.near_m), "camera.near_m", c.near_m, "must be finite and > 0")) ||
      (f = check(finite(c.far_m) && c.far_m > c.near_m, "camera.far_m", c.far_m,
                 "must be finite and > camera.near_m")) ||
      (f = check_vec(c.body_half_m, "camera.body_half_m", nonnegative, "must be finite, >= 0")) ||
      (f = check(nonnegative(c.max_speed_mps), "camera.max_speed_mps", c.max_speed_mps,
                 "must be finite and >= 0")) ||
      (f = check(bound(c.max_accel_mps2), "camera.max_accel_mps2", c.max_accel_mps2,
                 "must be >= 0 or INFINITY")) ||
      (f = check(bound(c.max_turn_radps), "camera.max_turn_radps", c.max_turn_radps,
                 "must be >= 0 or INFINITY"))) {
    return f;
  }
  return {};
}

Eigen::Vector3d vec(const fragsim_vec3& v) {
  return {v.x, v.y, v.z};
}

// The fragments as the caller gave them: an array of structs, or strided arrays.
struct StructSource {
  const fragsim_fragment* f;
  const double* position(std::size_t i) const { return &f[i].position_m.x; }
  const double* velocity(std::size_t i) const { return &f[i].velocity_mps.x; }
  double radius(std::size_t i) const { return f[i].radius_m; }
  double mass(std::size_t i) const { return f[i].mass_kg; }
  std::uint64_t id(std::size_t i) const { return f[i].id; }
  bool touched(std::size_t i) const { return f[i].touched != 0; }
};

struct ArraySource {
  const fragsim_fragment_arrays* a;
  template <class T>
  static const T* at(const T* base, std::size_t stride, std::size_t i) {
    return reinterpret_cast<const T*>(reinterpret_cast<const unsigned char*>(base) + i * stride);
  }
  const double* position(std::size_t i) const {
    return at(a->position_m, a->position_stride_bytes, i);
  }
  const double* velocity(std::size_t i) const {
    return at(a->velocity_mps, a->velocity_stride_bytes, i);
  }
  double radius(std::size_t i) const { return *at(a->radius_m, a->radius_stride_bytes, i); }
  double mass(std::size_t i) const { return *at(a->mass_kg, a->mass_stride_bytes, i); }
  std::uint64_t id(std::size_t i) const { return *at(a->id, a->id_stride_bytes, i); }
  bool touched(std::size_t i) const {
    return a->touched != nullptr && *at(a->touched, a->touched_stride_bytes, i) != 0;
  }
};

// Where the forces go.
struct StructSink {
  fragsim_vec3* f;
  void zero(std::size_t n) const {
    if (f != nullptr && n > 0) std::memset(static_cast<void*>(f), 0, n * sizeof(fragsim_vec3));
  }
  void set(std::size_t i, const Eigen::Vector3d& v) const { f[i] = {v.x(), v.y(), v.z()}; }
};

struct ArraySink {
  double* base;
  std::size_t stride;
  double* at(std::size_t i) const {
    return reinterpret_cast<double*>(reinterpret_cast<unsigned char*>(base) + i * stride);
  }
  void zero(std::size_t n) const {
    if (base == nullptr) return;
    for (std::size_t i = 0; i < n; ++i) {
      double* p = at(i);
      p[0] = p[1] = p[2] = 0.0;
    }
  }
  void set(std::size_t i, const Eigen::Vector3d& v) const {
    double* p = at(i);
    p[0] = v.x();
    p[1] = v.y();
    p[2] = v.z();
  }
};

void copy_message(const std::string& text, char* message, std::size_t size) {
  if (message == nullptr || size == 0) return;
  const std::size_t n = std::min(text.size(), size - 1);
  std::memcpy(message, text.data(), n);
  message[n] = '\0';
}

}  // namespace

struct fragsim_controller {
  fragsim_controller_def def{};
  std::unique_ptr<fragsim::Strategy> strategy;
  fragsim::EdgeStrategy* edge = nullptr;  // the same object, when it keeps per-fragment state
  fragsim::EdgeMinStrategy* edge_min = nullptr;  // likewise (its budget's last forces)
  std::string error;

  // Work space kept between calls so a step does not allocate once it has seen its largest
  // fragment count.
  std::vector<fragsim::FragmentState> states;
  fragsim::StepOutput out;
  fragsim::control::IdTable ids[2];  // [last]: the last successful step's; the other: this one's
  int last = 0;
  std::vector<std::uint64_t> last_ids;  // in the last successful step's order
  std::vector<int> previous;            // this step's fragment i was previous[i] then, or -1

  explicit fragsim_controller(const fragsim_controller_def& d) : def(d) {
    switch (raw(d.strategy)) {
      case FRAGSIM_STRATEGY_EDGE_MIN: {
        auto e = std::make_unique<fragsim::EdgeMinStrategy>(edge_min_params(d));
        edge_min = e.get();
        strategy = std::move(e);
        break;
      }
      case FRAGSIM_STRATEGY_EDGE: {
        auto e = std::make_unique<fragsim::EdgeStrategy>(edge_params(d));
        edge = e.get();
        strategy = std::move(e);
        break;
      }
      case FRAGSIM_STRATEGY_DEFLECT_ALL:
        strategy = std::make_unique<fragsim::DeflectAllStrategy>(deflect_all_params(d));
        break;
    }
    reset();
  }

  void reset() {
    strategy->reset(0);
    last_ids.clear();
    ids[last].clear(0);
  }

  template <class Source, class Sink>
  fragsim_status step(const fragsim_step_input& in, const Source& src, std::size_t n,
                      const Sink& sink, fragsim_step_stats* stats);

  fragsim_status failed(Failure f) {
    error = std::move(f.message);
    return f.status;
  }
};

template <class Source, class Sink>
fragsim_status fragsim_controller::step(const fragsim_step_input& in, const Source& src,
                                        std::size_t n, const Sink& sink,
                                        fragsim_step_stats* stats) {
  // Every check comes before any state changes, so a refused call leaves the controller as it
  // was; the strategy runs only on inputs it was written for.
  if (Failure f = validate(in)) return failed(std::move(f));
  if (states.size() < n) states.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = src.position(i);
    const double* v = src.velocity(i);
    const double r = src.radius(i);
    const double m = src.mass(i);
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
          std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && nonnegative(r) &&
          nonnegative(m))) {
      const char* axis[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(p[k])) {
          return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                             "fragments[%zu].position_m.%s = %g: must be finite", i, axis[k],
                             p[k]));
        }
        if (!std::isfinite(v[k])) {
          return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                             "fragments[%zu].velocity_mps.%s = %g: must be finite", i, axis[k],
                             v[k]));
        }
      }
      if (!nonnegative(r)) {
        return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                           "fragments[%zu].radius_m = %g: must be finite and >= 0", i, r));
      }
      return failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                         "fragments[%zu].mass_kg = %g: must be finite and >= 0", i, m));
    }
    fragsim::FragmentState& s = states[i];
    s.position_m = {p[0], p[1], p[2]};
    s.velocity_mps = {v[0], v[1], v[2]};
    s.radius_m = r;
    s.mass_kg = m;
    s.touched = src.touched(i);
  }

  // Ids: the same list as the last step (the usual case, an engine passing its array every step)
  // needs neither the duplicate check nor a re-index: that step already passed both.
  bool same_ids = last_ids.size() == n;
  for (std::size_t i = 0; same_ids && i < n; ++i) same_ids = last_ids[i] == src.id(i);
  int new_ids = 0;
  int dropped_ids = 0;
  fragsim::control::IdTable& now = ids[1 - last];
  if (!same_ids) {
    now.clear(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!now.insert(src.id(i), static_cast<std::int32_t>(i))) {
        const unsigned long long id = src.id(i);
        return failed(fail(FRAGSIM_ERROR_DUPLICATE_ID,
                           "fragments[%zu].id = %llu: the id of fragments[%d] too", i, id,
                           static_cast<int>(now.find(src.id(i)))));
      }
    }
    previous.resize(n);
    int kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      previous[i] = ids[last].find(src.id(i));
      if (previous[i] < 0) {
        ++new_ids;
      } else {
        ++kept;
      }
    }
    dropped_ids = static_cast<int>(last_ids.size()) - kept;
  }

  fragsim::StepContext ctx;
  ctx.step = 0;
  ctx.t_s = in.time_s;
  ctx.dt_s = in.dt_s;
  // A game has no scene end: the look-ahead comes from the physics, capped by the def's
  // horizon_cap_s (in the strategies' parameters) and by the caller's end when one is given.
  ctx.end_time_s = in.end_time_s;
  const fragsim_camera& c = in.camera;
  ctx.camera.eye_m = vec(c.eye_m);
  ctx.camera.right = vec(c.right);
  ctx.camera.up = vec(c.up);
  ctx.camera.forward = vec(c.forward);
  ctx.camera.fovy_deg = c.fovy_deg;
  ctx.camera.aspect = c.aspect;
  ctx.camera.near_m = c.near_m;
  ctx.camera.far_m = c.far_m;
  ctx.camera_velocity_mps = vec(c.velocity_mps);
  ctx.camera_max_speed_mps = c.max_speed_mps;
  ctx.camera_max_accel_mps2 = c.max_accel_mps2;
  ctx.camera_max_turn_radps = c.max_turn_radps;
  ctx.camera_body_half_m = vec(c.body_half_m);
  ctx.gravity_mps2 = vec(in.gravity_mps2);
  ctx.ground_height_m = in.ground_height_m;
  ctx.fragments = std::span<const fragsim::FragmentState>(states.data(), n);

  if (!same_ids && edge != nullptr) edge->carry_over(previous);
  if (!same_ids && edge_min != nullptr) edge_min->carry_over(previous);
  out.clear();
  strategy->step(ctx, out);

  // Never a non-finite force out, whatever happened inside (the strategies already drop them).
  for (const fragsim::AppliedForce& a : out.forces) {
    if (!a.force_N.allFinite() || a.fragment < 0 || static_cast<std::size_t>(a.fragment) >= n) {
      error = "internal: a strategy produced a non-finite force or a bad index";
      sink.zero(n);
      if (stats != nullptr) *stats = {};
      return FRAGSIM_ERROR_INTERNAL;
    }
  }
  sink.zero(n);
  for (const fragsim::AppliedForce& a : out.forces) {
    sink.set(static_cast<std::size_t>(a.fragment), a.force_N);
  }
  if (!same_ids) {
    last = 1 - last;
    last_ids.resize(n);
    for (std::size_t i = 0; i < n; ++i) last_ids[i] = src.id(i);
  }
  if (stats != nullptr) {
    stats->candidates = static_cast<std::int32_t>(out.activity.candidates.size());
    stats->pushed = static_cast<std::int32_t>(out.forces.size());
    stats->capped = static_cast<std::int32_t>(out.activity.capped.size());
    stats->guarded = out.activity.guarded;
    stats->new_ids = new_ids;
    stats->dropped_ids = dropped_ids;
    stats->deferred = out.activity.deferred;
    stats->rejected_cheaply = out.activity.rejected_cheaply;
  }
  error.clear();
  return FRAGSIM_OK;
}

namespace {

// The step behind both entry points: nothing escapes the C boundary, and a failed step leaves
// zero forces.
template <typename Source, typename Sink>
fragsim_status guarded_step(fragsim_controller& controller, const fragsim_step_input& input,
                            const Source& source, std::size_t n, const Sink& sink,
                            fragsim_step_stats* stats) {
  try {
    const fragsim_status s = controller.step(input, source, n, sink, stats);
    if (s != FRAGSIM_OK) sink.zero(n);
    return s;
  } catch (const std::bad_alloc&) {
    sink.zero(n);
    controller.error = "out of memory";
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  } catch (...) {
    sink.zero(n);
    controller.error = "internal: unexpected exception";
    return FRAGSIM_ERROR_INTERNAL;
  }
}

}  // namespace

extern "C" {

FRAGSIM_API int32_t fragsim_version(void) {
  return FRAGSIM_CONTROL_VERSION;
}

FRAGSIM_API const char* fragsim_version_string(void) {
#define FRAGSIM_STR2(x) #x
#define FRAGSIM_STR(x) FRAGSIM_STR2(x)
  return FRAGSIM_STR(FRAGSIM_CONTROL_VERSION_MAJOR) "." FRAGSIM_STR(
      FRAGSIM_CONTROL_VERSION_MINOR) "." FRAGSIM_STR(FRAGSIM_CONTROL_VERSION_PATCH);
#undef FRAGSIM_STR
#undef FRAGSIM_STR2
}

FRAGSIM_API const char* fragsim_status_string(fragsim_status status) {
  switch (status) {
    case FRAGSIM_OK:
      return "ok";
    case FRAGSIM_ERROR_NULL_ARGUMENT:
      return "null argument";
    case FRAGSIM_ERROR_DEF_NOT_DEFAULTED:
      return "def not from fragsim_default_controller_def";
    case FRAGSIM_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case FRAGSIM_ERROR_DUPLICATE_ID:
      return "duplicate fragment id";
    case FRAGSIM_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case FRAGSIM_ERROR_INTERNAL:
      return "internal error";
  }
  return "unknown status";
}

FRAGSIM_API fragsim_controller_def fragsim_default_controller_def(void) {
  // The defaults are the parameter structs' (strategies/*_params.hpp), which fragsim's scenes
  // use too: read from them, they cannot drift.
  return fragsim::control::controller_def(FRAGSIM_STRATEGY_EDGE_MIN, {}, {}, {});
}

FRAGSIM_API fragsim_camera fragsim_default_camera(void) {
  fragsim_camera c;
  std::memset(&c, 0, sizeof c);
  c.right = {1.0, 0.0, 0.0};
  c.up = {0.0, 1.0, 0.0};
  c.forward = {0.0, 0.0, -1.0};
  // The tool's default frustum, from its one home (geometry/frustum.hpp).
  c.fovy_deg = fragsim::kDefaultFrustum.fovy_deg;
  c.aspect = fragsim::kDefaultFrustum.aspect;
  c.near_m = fragsim::kDefaultFrustum.near_m;
  c.far_m = fragsim::kDefaultFrustum.far_m;
  c.body_half_m = {0.15, 0.1, 0.15};
  c.max_speed_mps = 3.0;
  c.max_accel_mps2 = 0.0;  // not declared
  c.max_turn_radps = 0.0;
  return c;
}

FRAGSIM_API fragsim_status fragsim_controller_create(const fragsim_controller_def* def,
                                                     fragsim_controller** out_controller,
                                                     char* message, size_t message_size) {
  if (out_controller != nullptr) *out_controller = nullptr;
  if (def == nullptr || out_controller == nullptr) {
    copy_message(def == nullptr ? "def: NULL" : "out_controller: NULL", message, message_size);
    return FRAGSIM_ERROR_NULL_ARGUMENT;
  }
  if (Failure f = validate(*def)) {
    copy_message(f.message, message, message_size);
    return f.status;
  }
  try {
    *out_controller = new fragsim_controller(*def);
  } catch (...) {
    copy_message("out of memory", message, message_size);
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }
  copy_message("", message, message_size);
  return FRAGSIM_OK;
}

FRAGSIM_API void fragsim_controller_destroy(fragsim_controller* controller) {
  delete controller;
}

FRAGSIM_API void fragsim_controller_reset(fragsim_controller* controller) {
  if (controller == nullptr) return;
  controller->reset();
  controller->error.clear();
}

FRAGSIM_API fragsim_status fragsim_controller_step(fragsim_controller* controller,
                                                   const fragsim_step_input* input,
                                                   fragsim_vec3* forces_N,
                                                   fragsim_step_stats* stats) {
  if (stats != nullptr) *stats = {};
  const bool count_ok =
      input != nullptr && input->fragment_count >= 0 && input->fragment_count <= kMaxFragments;
  const StructSink sink{forces_N};
  if (controller == nullptr) {
    if (count_ok) sink.zero(static_cast<std::size_t>(input->fragment_count));
    return FRAGSIM_ERROR_NULL_ARGUMENT;
  }
  auto refuse = [&](fragsim_status s, const char* why) {
    if (count_ok) sink.zero(static_cast<std::size_t>(input->fragment_count));
    controller->error = why;
    return s;
  };
  if (input == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "input: NULL");
  if (!count_ok) {
    return controller->failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                                   "fragment_count = %d: must be in [0, %d]",
                                   static_cast<int>(input->fragment_count), kMaxFragments));
  }
  const auto n = static_cast<std::size_t>(input->fragment_count);
  if (n > 0 && input->fragments == nullptr) {
    return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "fragments: NULL with fragment_count > 0");
  }
  if (n > 0 && forces_N == nullptr) {
    return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "forces_N: NULL with fragment_count > 0");
  }
  return guarded_step(*controller, *input, StructSource{input->fragments}, n, sink, stats);
}

FRAGSIM_API fragsim_status fragsim_controller_step_arrays(fragsim_controller* controller,
                                                          const fragsim_step_input* input,
                                                          const fragsim_fragment_arrays* arrays,
                                                          int32_t count,
                                                          fragsim_step_stats* stats) {
  if (stats != nullptr) *stats = {};
  if (controller == nullptr) return FRAGSIM_ERROR_NULL_ARGUMENT;
  const bool count_ok = count >= 0 && count <= kMaxFragments;
  const ArraySink sink{arrays != nullptr ? arrays->force_N : nullptr,
                       arrays != nullptr ? arrays->force_stride_bytes : 0};
  auto refuse = [&](fragsim_status s, const std::string& why) {
    if (count_ok) sink.zero(static_cast<std::size_t>(count));
    controller->error = why;
    return s;
  };
  if (input == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "input: NULL");
  if (arrays == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "arrays: NULL");
  if (!count_ok) {
    return controller->failed(fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "count = %d: must be in [0, %d]",
                                   static_cast<int>(count), kMaxFragments));
  }
  const auto n = static_cast<std::size_t>(count);
  if (n > 0) {
    const void* required[5] = {arrays->position_m, arrays->velocity_mps, arrays->radius_m,
                               arrays->mass_kg, arrays->id};
    const char* names[5] = {"arrays.position_m", "arrays.velocity_mps", "arrays.radius_m",
                            "arrays.mass_kg", "arrays.id"};
    for (int k = 0; k < 5; ++k) {
      if (required[k] == nullptr) {
        return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, std::string(names[k]) + ": NULL with count > 0");
      }
    }
    if (arrays->force_N == nullptr) {
      return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "arrays.force_N: NULL with count > 0");
    }
  }
  return guarded_step(*controller, *input, ArraySource{arrays}, n, sink, stats);
}

FRAGSIM_API const char* fragsim_controller_last_error(const fragsim_controller* controller) {
  if (controller == nullptr) return "controller: NULL";
  return controller->error.c_str();
}

}  // extern "C"
