#include "control/api/input_checks.hpp"

#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <span>

#include "control/api/def_mapping.hpp"
#include "control/strategies/deflect_all_params.hpp"
#include "control/strategies/edge_min_params.hpp"
#include "control/strategies/edge_params.hpp"
#include "control/strategies/param_range.hpp"

namespace fragsim::control {

Failure fail(fragsim_status status, const char* format, ...) {
  Failure f;
  f.status = status;
  va_list args;
  va_start(args, format);
  std::vsnprintf(f.message, sizeof f.message, format, args);
  va_end(args);
  return f;
}

namespace {

constexpr double kFrameTolerance = 1e-6;
// Beyond these a legal number is more likely a unit mix-up (fragsim_step_stats.warnings).
constexpr double kFovyLikelyRadians_deg = 5.0;
// Beyond these a screen's shape costs the occlusion bound's grid more than it can bound (its rows
// grow as 1 / aspect), and no display is that narrow or that wide.
constexpr double kMinAspect = 1e-3;
constexpr double kMaxAspect = 1e3;

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
// A declared camera bound is >= 0 (+inf for none), or exactly FRAGSIM_UNDECLARED.
bool bound(double v) {
  return (!std::isnan(v) && v >= 0.0) || v == FRAGSIM_UNDECLARED;
}

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

// The words of a parameter's range, as a message ends: "must be in (0, 3600]", "must be a whole
// number in [0, 100000000]", "must be in [0, 1e+06], or INFINITY".
struct RangeWords {
  char text[128];
  explicit RangeWords(const fragsim::ParamRange& r) {
    const char* number = r.whole ? "%.17g" : "%g";
    char lo[32];
    char hi[32];
    std::snprintf(lo, sizeof lo, number, r.lo);
    std::snprintf(hi, sizeof hi, number, r.hi);
    const char* inf = r.inf_ok ? ", or INFINITY" : "";
    if (std::isinf(r.hi)) {
      std::snprintf(text, sizeof text, "must be %s %s%s", r.lo_open ? ">" : ">=", lo, inf);
    } else if (std::isinf(r.lo)) {
      std::snprintf(text, sizeof text, "must be %s %s%s", r.hi_open ? "<" : "<=", hi, inf);
    } else {
      std::snprintf(text, sizeof text, "must be %sin %c%s, %s%c%s",
                    r.whole ? "a whole number " : "", r.lo_open ? '(' : '[', lo, hi,
                    r.hi_open ? ')' : ']', inf);
    }
  }
};

// The range of the parameter `name` (strategies/*_params.hpp), one the def has a field for.
const fragsim::ParamRange* def_range(std::span<const fragsim::ParamRange> ranges,
                                     const char* name) {
  const fragsim::ParamRange* r = fragsim::find_range(ranges, name);
  return r != nullptr && r->field != nullptr ? r : nullptr;
}

// A def field that is one of the strategies' parameters, checked against that parameter's range
// (the one a scene file's value must keep, as the tool's keys take theirs from the same table) and
// named by its C field (edge.k_Nms2; one horizon_cap_s for both strategies). The value is printed
// with 15 digits, which give back any number typed with 15 or fewer (1000001, not 1e+06).
Failure check_param(std::span<const fragsim::ParamRange> ranges, const char* name, double value) {
  const fragsim::ParamRange* r = def_range(ranges, name);
  if (r == nullptr) return fail(FRAGSIM_ERROR_INTERNAL, "internal: the def has no field %s", name);
  if (r->admits(value)) return {};
  return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s = %.15g: %s", r->field, value,
              RangeWords(*r).text);
}

// edge_min.edge_weights, each weight in its range and not all four zero.
Failure check_edge_weights(const std::array<double, 4>& w) {
  const fragsim::ParamRange* r = def_range(fragsim::kEdgeMinRanges, "edge_weights");
  if (r == nullptr) return fail(FRAGSIM_ERROR_INTERNAL, "internal: the def has no edge weights");
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (!r->admits(w[k])) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s[%zu] = %.15g: %s", r->field, k, w[k],
                  RangeWords(*r).text);
    }
  }
  if (!fragsim::some_edge_allowed(w)) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "%s = {%g, %g, %g, %g}: at least one weight must be > 0", r->field, w[0], w[1],
                w[2], w[3]);
  }
  return {};
}

}  // namespace

Failure validate_def(const fragsim_controller_def& def) {
  if (def.internal_value != kDefCookie) {
    return fail(FRAGSIM_ERROR_DEF_NOT_DEFAULTED,
                "def: not initialised with fragsim_default_controller_def()");
  }
  if ((def.alloc_fn == nullptr) != (def.free_fn == nullptr)) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "%s: NULL while %s is set: give both (the game's allocator) or neither (operator "
                "new and delete)",
                def.alloc_fn == nullptr ? "alloc_fn" : "free_fn",
                def.alloc_fn == nullptr ? "free_fn" : "alloc_fn");
  }
  if ((def.enqueue_task == nullptr) != (def.finish_task == nullptr)) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "%s: NULL while %s is set: give both (the game's task system) or neither (the "
                "calling thread)",
                def.enqueue_task == nullptr ? "enqueue_task" : "finish_task",
                def.enqueue_task == nullptr ? "finish_task" : "enqueue_task");
  }
  if (def.worker_count < 1 || def.worker_count > FRAGSIM_MAX_WORKERS) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "worker_count = %d: must be in [1, FRAGSIM_MAX_WORKERS = %d]",
                static_cast<int>(def.worker_count), FRAGSIM_MAX_WORKERS);
  }
  Failure f;
  // The shared fields first, whichever strategy is chosen, as a def is valid as a whole.
  const auto& em_ranges = fragsim::kEdgeMinRanges;
  const fragsim::EdgeMinParams em = edge_min_params(def);
  if ((f = check_param(em_ranges, "max_solves", em.max_solves)) ||
      (f = check_param(em_ranges, "horizon_cap_s", em.horizon_cap_s))) {
    return f;
  }
  switch (raw(def.strategy)) {
    case FRAGSIM_STRATEGY_EDGE_MIN: {
      const fragsim_edge_min_def& p = def.edge_min;
      if ((f = check_param(em_ranges, "margin_m", em.margin_m)) ||
          (f = check_param(em_ranges, "a_max_mps2", em.a_max_mps2)) ||
          (f = check(raw(p.camera_model) >= FRAGSIM_CAMERA_CONSTANT &&
                         raw(p.camera_model) <= FRAGSIM_CAMERA_REACHABLE,
                     "edge_min.camera_model", raw(p.camera_model),
                     "must be a fragsim_camera_model")) ||
          (f = check_param(em_ranges, "camera_accel_mps2", em.camera_accel_mps2)) ||
          (f = check_param(em_ranges, "camera_turn_degps", em.camera_turn_degps)) ||
          (f = check_edge_weights(em.edge_weights)) ||
          (f = check_param(em_ranges, "cover_max", em.cover_max)) ||
          (f = check_param(em_ranges, "cover_region", em.cover_region))) {
        return f;
      }
      return {};
    }
    case FRAGSIM_STRATEGY_EDGE: {
      const fragsim_edge_def& p = def.edge;
      const auto& ranges = fragsim::kEdgeRanges;
      const fragsim::EdgeParams e = edge_params(def);
      if ((f = check_param(ranges, "k", e.k)) ||
          (f = check_param(ranges, "a_max_mps2", e.a_max_mps2)) ||
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
      const auto& ranges = fragsim::kDeflectAllRanges;
      const fragsim::DeflectAllParams d = deflect_all_params(def);
      if ((f = check_param(ranges, "accel_mps2", d.accel_mps2)) ||
          (f = check_param(ranges, "range_m", d.range_m))) {
        return f;
      }
      return {};
    }
  }
  return check(false, "strategy", raw(def.strategy), "must be a fragsim_strategy");
}

namespace {

// The ground's normal must be finite and of unit length within the camera axes' tolerance. A zero
// normal is what a zero-initialised input holds; it has no direction to default from.
Failure validate_ground_normal(const fragsim_vec3& n) {
  if (Failure f = check_vec(n, "ground_normal", finite, "must be finite")) return f;
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (!(std::abs(length - 1.0) <= kFrameTolerance)) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "ground_normal has length %.9g: must be 1 (within 1e-6), e.g. (0, 1, 0) y-up or "
                "(0, 0, 1) z-up (start from fragsim_default_step_input(), not a zero-initialised "
                "input)",
                length);
  }
  return {};
}

// prefix.field, as the caller names it ("camera.near_m", "cameras[1].near_m").
struct FieldName {
  char text[64];
  FieldName(const char* prefix, const char* field) {
    std::snprintf(text, sizeof text, "%s.%s", prefix, field);
  }
};

Failure validate_frame(const fragsim_vec3* const (&axes)[3], const char* prefix) {
  const FieldName names[3] = {{prefix, "right"}, {prefix, "up"}, {prefix, "forward"}};
  for (int k = 0; k < 3; ++k) {
    if (Failure f = check_vec(*axes[k], names[k].text, finite, "must be finite")) return f;
    const fragsim_vec3& a = *axes[k];
    const double n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    if (!(std::abs(n - 1.0) <= kFrameTolerance)) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s has length %.9g: must be 1 (within 1e-6)",
                  names[k].text, n);
    }
  }
  for (int k = 0; k < 3; ++k) {
    const fragsim_vec3& a = *axes[k];
    const fragsim_vec3& b = *axes[(k + 1) % 3];
    const double dot = a.x * b.x + a.y * b.y + a.z * b.z;
    if (!(std::abs(dot) <= kFrameTolerance)) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                  "%s . %s = %.9g: the camera axes must be at right angles (within 1e-6)",
                  names[k].text, names[(k + 1) % 3].text, dot);
    }
  }
  return {};
}

}  // namespace

Failure validate_camera_pose(const fragsim_camera_pose& p, const char* prefix) {
  const fragsim_vec3* const axes[3] = {&p.right, &p.up, &p.forward};
  Failure f;
  if ((f = check_vec(p.eye_m, FieldName(prefix, "eye_m").text, finite, "must be finite")) ||
      (f = validate_frame(axes, prefix)) ||
      (f = check_vec(p.velocity_mps, FieldName(prefix, "velocity_mps").text, finite,
                     "must be finite"))) {
    return f;
  }
  return {};
}

Failure validate_camera_def(const fragsim_camera_def& c, const char* prefix) {
  const FieldName near_m(prefix, "near_m");
  char far_rule[96];
  std::snprintf(far_rule, sizeof far_rule, "must be finite and > %s", near_m.text);
  Failure f;
  if ((f = check(finite(c.fovy_deg) && c.fovy_deg > 0.0 && c.fovy_deg < 180.0,
                 FieldName(prefix, "fovy_deg").text, c.fovy_deg, "must be in (0, 180)")) ||
      (f = check(c.aspect >= kMinAspect && c.aspect <= kMaxAspect, FieldName(prefix, "aspect").text,
                 c.aspect, "must be in [1e-3, 1e3]")) ||
      (f = check(positive(c.near_m), near_m.text, c.near_m, "must be finite and > 0")) ||
      (f = check(finite(c.far_m) && c.far_m > c.near_m, FieldName(prefix, "far_m").text, c.far_m,
                 far_rule)) ||
      (f = check_vec(c.body_half_m, FieldName(prefix, "body_half_m").text, nonnegative,
                     "must be finite, >= 0")) ||
      (f = check(nonnegative(c.max_speed_mps), FieldName(prefix, "max_speed_mps").text,
                 c.max_speed_mps, "must be finite and >= 0")) ||
      (f = check(bound(c.max_accel_mps2), FieldName(prefix, "max_accel_mps2").text,
                 c.max_accel_mps2, "must be >= 0, INFINITY or FRAGSIM_UNDECLARED")) ||
      (f = check(bound(c.max_turn_degps), FieldName(prefix, "max_turn_degps").text,
                 c.max_turn_degps, "must be >= 0, INFINITY or FRAGSIM_UNDECLARED"))) {
    return f;
  }
  return {};
}

Failure validate_step_input(const fragsim_step_input& in) {
  Failure f;
  if ((f = check(finite(in.time_s), "time_s", in.time_s, "must be finite")) ||
      (f = check(!std::isnan(in.end_time_s), "end_time_s", in.end_time_s,
                 "must be a time or INFINITY"))) {
    return f;
  }
  if (!(in.end_time_s > in.time_s)) {
    // A zero-initialised input has end 0 at time 0, which would silently protect nothing.
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "end_time_s = %g is not after time_s = %g: a step at or past the shot's end "
                "protects nothing (INFINITY: no end; start from fragsim_default_step_input(), "
                "not a zero-initialised input)",
                in.end_time_s, in.time_s);
  }
  if ((f = check(positive(in.dt_s), "dt_s", in.dt_s, "must be finite and > 0")) ||
      (f = check_vec(in.gravity_mps2, "gravity_mps2", finite, "must be finite")) ||
      (f = check(finite(in.ground_height_m) ||
                     in.ground_height_m == -std::numeric_limits<double>::infinity(),
                 "ground_height_m", in.ground_height_m, "must be finite, or -INFINITY for none")) ||
      (f = validate_ground_normal(in.ground_normal))) {
    return f;
  }
  if (in.camera_count < 1 || in.camera_count > FRAGSIM_MAX_CAMERAS) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "camera_count = %d: must be the number of cameras set with "
                "fragsim_controller_set_cameras, in [1, FRAGSIM_MAX_CAMERAS = %d]",
                static_cast<int>(in.camera_count), FRAGSIM_MAX_CAMERAS);
  }
  if (in.camera_poses == nullptr) {
    return fail(FRAGSIM_ERROR_NULL_ARGUMENT, "camera_poses: NULL with camera_count = %d",
                static_cast<int>(in.camera_count));
  }
  for (int k = 0; k < in.camera_count; ++k) {
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "camera_poses[%d]", k);
    if ((f = validate_camera_pose(in.camera_poses[k], prefix))) return f;
  }
  return {};
}

namespace {

struct StrideRule {
  const char* name;
  std::size_t stride_bytes;
  std::size_t element_bytes;
  const char* element;
};

}  // namespace

bool force_layout_known(const fragsim_fragment_arrays& a, std::size_t count) {
  const int type = raw(a.scalar_type);
  if (type != FRAGSIM_SCALAR_DOUBLE && type != FRAGSIM_SCALAR_FLOAT) return false;
  const std::size_t scalar = type == FRAGSIM_SCALAR_FLOAT ? sizeof(float) : sizeof(double);
  return count <= 1 || a.force_stride_bytes >= 3 * scalar;
}

Failure validate_arrays(const fragsim_fragment_arrays& a, std::size_t count) {
  const int type = raw(a.scalar_type);
  if (type != FRAGSIM_SCALAR_DOUBLE && type != FRAGSIM_SCALAR_FLOAT) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "arrays.scalar_type = %d: must be a fragsim_scalar_type (FRAGSIM_SCALAR_DOUBLE or "
                "FRAGSIM_SCALAR_FLOAT)",
                type);
  }
  // One element has no stride to speak of, so a caller passing a single fragment may leave them 0.
  if (count <= 1) return {};
  const bool floats = type == FRAGSIM_SCALAR_FLOAT;
  const std::size_t scalar = floats ? sizeof(float) : sizeof(double);
  const char* three = floats ? "3 floats" : "3 doubles";
  const char* one = floats ? "a float" : "a double";
  const StrideRule rules[] = {
      {"arrays.position_stride_bytes", a.position_stride_bytes, 3 * scalar, three},
      {"arrays.velocity_stride_bytes", a.velocity_stride_bytes, 3 * scalar, three},
      {"arrays.radius_stride_bytes", a.radius_stride_bytes, scalar, one},
      {"arrays.mass_stride_bytes", a.mass_stride_bytes, scalar, one},
      {"arrays.id_stride_bytes", a.id_stride_bytes, sizeof(std::uint64_t), "a uint64_t"},
      {"arrays.touched_stride_bytes", a.touched == nullptr ? 1 : a.touched_stride_bytes, 1,
       "a uint8_t"},
      {"arrays.force_stride_bytes", a.force_stride_bytes, 3 * scalar, three}};
  for (const StrideRule& r : rules) {
    if (r.stride_bytes < r.element_bytes) {
      return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                  "%s = %zu: must be at least the %zu bytes of %s, or the elements overlap", r.name,
                  r.stride_bytes, r.element_bytes, r.element);
    }
  }
  return {};
}

bool mass_usable(double m) {
  return m == 0.0 || (m >= FRAGSIM_MIN_MASS_KG && m <= FRAGSIM_MAX_MASS_KG);
}

bool fragment_usable(const double* p, const double* v, double r, double m) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(v[0]) &&
         std::isfinite(v[1]) && std::isfinite(v[2]) && nonnegative(r) && mass_usable(m);
}

std::uint32_t camera_warnings(const fragsim_camera_def& c, const fragsim_camera_pose& p) {
  std::uint32_t w = 0;
  const double speed_mps =
      std::sqrt(p.velocity_mps.x * p.velocity_mps.x + p.velocity_mps.y * p.velocity_mps.y +
                p.velocity_mps.z * p.velocity_mps.z);
  // A hair of slack, so a camera clamped to exactly V_c does not trip it by rounding.
  if (speed_mps > c.max_speed_mps * (1.0 + 1e-9) + 1e-12) w |= FRAGSIM_WARNING_CAMERA_OVER_SPEED;
  if (c.fovy_deg < kFovyLikelyRadians_deg) w |= FRAGSIM_WARNING_FOVY_IN_RADIANS;
  return w;
}

}  // namespace fragsim::control
