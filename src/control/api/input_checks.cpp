#include "api/input_checks.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "api/def_mapping.hpp"
#include "strategies/deflect_all_strategy.hpp"
#include "strategies/edge_min_strategy.hpp"
#include "strategies/edge_strategy.hpp"

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
constexpr double kTurnLikelyDegrees_radps = 60.0;

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
// A declared camera bound: >= 0 (+inf: none), or exactly FRAGSIM_UNDECLARED.
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

namespace {

// The ground's normal: finite and of unit length within the camera axes' tolerance. A zero normal
// is what a zero-initialised input holds; it has no direction to default from.
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
      (f = check(positive(c.aspect), FieldName(prefix, "aspect").text, c.aspect,
                 "must be finite and > 0")) ||
      (f = check(positive(c.near_m), near_m.text, c.near_m, "must be finite and > 0")) ||
      (f = check(finite(c.far_m) && c.far_m > c.near_m, FieldName(prefix, "far_m").text, c.far_m,
                 far_rule)) ||
      (f = check_vec(c.body_half_m, FieldName(prefix, "body_half_m").text, nonnegative,
                     "must be finite, >= 0")) ||
      (f = check(nonnegative(c.max_speed_mps), FieldName(prefix, "max_speed_mps").text,
                 c.max_speed_mps, "must be finite and >= 0")) ||
      (f = check(bound(c.max_accel_mps2), FieldName(prefix, "max_accel_mps2").text,
                 c.max_accel_mps2, "must be >= 0, INFINITY or FRAGSIM_UNDECLARED")) ||
      (f = check(bound(c.max_turn_radps), FieldName(prefix, "max_turn_radps").text,
                 c.max_turn_radps, "must be >= 0, INFINITY or FRAGSIM_UNDECLARED"))) {
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
    // The trap of a zero-initialised input: end 0 at time 0 would protect nothing, silently.
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
  if (in.camera_count == 0) {
    if ((f = validate_camera_pose(pose_of(in.camera), "camera")) ||
        (f = validate_camera_def(def_of(in.camera), "camera"))) {
      return f;
    }
    return {};
  }
  if (in.camera_count < 0 || in.camera_count > FRAGSIM_MAX_CAMERAS) {
    return fail(FRAGSIM_ERROR_INVALID_ARGUMENT,
                "camera_count = %d: must be 0 (input.camera) or the controller's cameras, at most "
                "FRAGSIM_MAX_CAMERAS = %d",
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
  // One element has no stride to speak of: a caller passing a single fragment may leave them 0.
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

bool fragment_usable(const double* p, const double* v, double r, double m) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(v[0]) &&
         std::isfinite(v[1]) && std::isfinite(v[2]) && nonnegative(r) && nonnegative(m);
}

std::uint32_t camera_warnings(const fragsim_camera& c) {
  std::uint32_t w = 0;
  const double speed_mps =
      std::sqrt(c.velocity_mps.x * c.velocity_mps.x + c.velocity_mps.y * c.velocity_mps.y +
                c.velocity_mps.z * c.velocity_mps.z);
  // A hair of slack: a camera clamped to exactly V_c must not trip it by rounding.
  if (speed_mps > c.max_speed_mps * (1.0 + 1e-9) + 1e-12) w |= FRAGSIM_WARNING_CAMERA_OVER_SPEED;
  if (c.fovy_deg < kFovyLikelyRadians_deg) w |= FRAGSIM_WARNING_FOVY_IN_RADIANS;
  if (std::isfinite(c.max_turn_radps) && c.max_turn_radps > kTurnLikelyDegrees_radps) {
    w |= FRAGSIM_WARNING_TURN_IN_DEGREES;
  }
  return w;
}

}  // namespace fragsim::control
