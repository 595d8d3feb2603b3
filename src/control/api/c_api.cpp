// The C API of fragsim/control.h. It resolves ids to controllers (controller_slots), checks
// arguments, and throws nothing across the C boundary. The work is Controller's (controller.hpp).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>

#include "control/api/controller.hpp"
#include "control/api/controller_slots.hpp"
#include "control/api/def_mapping.hpp"
#include "control/api/fragment_io.hpp"
#include "control/api/input_checks.hpp"
#include "control/geometry/frustum.hpp"
#include "fragsim/control.h"

namespace {

using fragsim::control::ArraySink;
using fragsim::control::ArraySource;
using fragsim::control::Controller;
using fragsim::control::Failure;
using fragsim::control::find_controller;
using fragsim::control::raw;
using fragsim::control::StructSink;
using fragsim::control::StructSource;

constexpr std::int32_t kMaxFragments = FRAGSIM_MAX_FRAGMENTS;
static_assert(kMaxFragments == std::numeric_limits<std::int32_t>::max() / 4);
constexpr const char* kStaleMessage =
    "controller: a stale id (destroyed) or the null id (never created)";

// The rule a fragment count breaks, with its value.
struct CountRule {
  char text[96];
};
CountRule count_rule(std::int32_t count) {
  CountRule r;
  std::snprintf(r.text, sizeof r.text, "fragment_count = %d: must be in [0, %d]",
                static_cast<int>(count), kMaxFragments);
  return r;
}

void copy_message(const char* text, char* message, std::size_t size) {
  if (message == nullptr || size == 0) return;
  const std::size_t n = std::min(std::strlen(text), size - 1);
  std::memcpy(message, text, n);
  message[n] = '\0';
}

// The step behind both entry points lets nothing escape the C boundary, and a failed step leaves
// zero forces. An allocation that fails comes from the step's first phase, which changed nothing.
template <typename Source, typename Sink>
fragsim_status guarded_step(Controller& controller, const fragsim_step_input& input,
                            const Source& source, std::size_t n, const Sink& sink,
                            fragsim_step_stats* stats) {
  fragsim_status s = FRAGSIM_ERROR_INTERNAL;
  try {
    s = controller.step(input, source, n, sink, stats);
  } catch (const std::bad_alloc&) {
    controller.set_error("out of memory");
    s = FRAGSIM_ERROR_OUT_OF_MEMORY;
  } catch (...) {
    controller.set_error("internal: unexpected exception");
    s = FRAGSIM_ERROR_INTERNAL;
  }
  if (s != FRAGSIM_OK) {
    sink.zero(n);
    if (stats != nullptr) *stats = {};
  }
  return s;
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
    case FRAGSIM_ERROR_STALE_ID:
      return "stale controller id";
  }
  return "unknown status";
}

FRAGSIM_API fragsim_controller_def fragsim_default_controller_def(void) {
  // The defaults are the parameter structs' (strategies/*_params.hpp), which fragsim's scenes use
  // too, so read from there they cannot drift.
  return fragsim::control::controller_def(FRAGSIM_STRATEGY_EDGE_MIN, {}, {}, {});
}

FRAGSIM_API fragsim_step_input fragsim_default_step_input(void) {
  fragsim_step_input in;
  std::memset(&in, 0, sizeof in);
  in.time_s = 0.0;
  in.end_time_s = std::numeric_limits<double>::infinity();
  in.dt_s = 1.0 / 60.0;
  in.gravity_mps2 = {0.0, -9.81, 0.0};
  // No ground until the game says where it is, so paths are examined to horizon_cap_s, which pushes
  // no less than a known ground would.
  in.ground_height_m = -std::numeric_limits<double>::infinity();
  in.ground_normal = {0.0, 1.0, 0.0};
  in.camera_poses = nullptr;
  in.camera_count = 0;
  return in;
}

FRAGSIM_API fragsim_camera_def fragsim_default_camera_def(void) {
  fragsim_camera_def c;
  std::memset(&c, 0, sizeof c);
  // The tool's default frustum, from its one home (geometry/frustum.hpp).
  c.fovy_deg = fragsim::kDefaultFrustum.fovy_deg;
  c.aspect = fragsim::kDefaultFrustum.aspect;
  c.near_m = fragsim::kDefaultFrustum.near_m;
  c.far_m = fragsim::kDefaultFrustum.far_m;
  c.body_half_m = {0.15, 0.1, 0.15};
  c.max_speed_mps = 3.0;
  c.max_accel_mps2 = FRAGSIM_UNDECLARED;
  c.max_turn_degps = FRAGSIM_UNDECLARED;
  return c;
}

FRAGSIM_API fragsim_camera_pose fragsim_default_camera_pose(void) {
  fragsim_camera_pose p;
  std::memset(&p, 0, sizeof p);
  p.right = {1.0, 0.0, 0.0};
  p.up = {0.0, 1.0, 0.0};
  p.forward = {0.0, 0.0, -1.0};
  return p;
}

FRAGSIM_API fragsim_fragment fragsim_default_fragment(void) {
  fragsim_fragment f;
  std::memset(&f, 0, sizeof f);
  return f;
}

FRAGSIM_API fragsim_fragment_arrays fragsim_default_fragment_arrays(void) {
  fragsim_fragment_arrays a;
  std::memset(&a, 0, sizeof a);
  a.position_stride_bytes = 3 * sizeof(double);
  a.velocity_stride_bytes = 3 * sizeof(double);
  a.radius_stride_bytes = sizeof(double);
  a.mass_stride_bytes = sizeof(double);
  a.id_stride_bytes = sizeof(std::uint64_t);
  a.touched_stride_bytes = sizeof(std::uint8_t);
  a.force_stride_bytes = 3 * sizeof(double);
  a.scalar_type = FRAGSIM_SCALAR_DOUBLE;
  return a;
}

FRAGSIM_API fragsim_status fragsim_controller_create(const fragsim_controller_def* def,
                                                     fragsim_controller_id* out_controller,
                                                     char* message, size_t message_size) {
  if (out_controller != nullptr) *out_controller = {0, 0};
  if (def == nullptr || out_controller == nullptr) {
    copy_message(def == nullptr ? "def: NULL" : "out_controller: NULL", message, message_size);
    return FRAGSIM_ERROR_NULL_ARGUMENT;
  }
  if (Failure f = fragsim::control::validate_def(*def)) {
    copy_message(f.message, message, message_size);
    return f.status;
  }
  Controller* c = nullptr;
  try {
    c = Controller::create(*def);
    const fragsim_controller_id id = fragsim::control::add_controller(c);
    if (id.index1 == 0) {
      Controller::destroy(c);
      copy_message("too many controllers: FRAGSIM_MAX_CONTROLLERS are alive", message,
                   message_size);
      return FRAGSIM_ERROR_OUT_OF_MEMORY;
    }
    *out_controller = id;
  } catch (...) {
    Controller::destroy(c);
    copy_message("out of memory", message, message_size);
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }
  copy_message("", message, message_size);
  return FRAGSIM_OK;
}

FRAGSIM_API fragsim_status fragsim_controller_destroy(fragsim_controller_id controller) {
  if (controller.index1 == 0) return FRAGSIM_OK;
  Controller* c = fragsim::control::remove_controller(controller);
  if (c == nullptr) return FRAGSIM_ERROR_STALE_ID;
  Controller::destroy(c);
  return FRAGSIM_OK;
}

FRAGSIM_API int fragsim_controller_is_valid(fragsim_controller_id controller) {
  return find_controller(controller) != nullptr ? 1 : 0;
}

FRAGSIM_API fragsim_status fragsim_controller_reset(fragsim_controller_id controller) {
  Controller* c = find_controller(controller);
  if (c == nullptr) return FRAGSIM_ERROR_STALE_ID;
  c->reset();
  c->clear_error();
  return FRAGSIM_OK;
}

FRAGSIM_API fragsim_status fragsim_controller_reserve(fragsim_controller_id controller,
                                                      int32_t fragment_count) {
  Controller* c = find_controller(controller);
  if (c == nullptr) return FRAGSIM_ERROR_STALE_ID;
  if (fragment_count < 0 || fragment_count > kMaxFragments) {
    char why[96];
    std::snprintf(why, sizeof why,
                  "fragment_count = %d: must be in [0, FRAGSIM_MAX_FRAGMENTS = %d]",
                  static_cast<int>(fragment_count), kMaxFragments);
    c->set_error(why);
    return FRAGSIM_ERROR_INVALID_ARGUMENT;
  }
  try {
    c->reserve(static_cast<std::size_t>(fragment_count));
  } catch (...) {
    c->set_error("out of memory");
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }
  c->clear_error();
  return FRAGSIM_OK;
}

FRAGSIM_API fragsim_status fragsim_controller_set_cameras(fragsim_controller_id controller,
                                                          const fragsim_camera_def* cameras,
                                                          int32_t camera_count) {
  Controller* c = find_controller(controller);
  if (c == nullptr) return FRAGSIM_ERROR_STALE_ID;
  if (camera_count < 1 || camera_count > FRAGSIM_MAX_CAMERAS) {
    char why[96];
    std::snprintf(why, sizeof why, "camera_count = %d: must be in [1, FRAGSIM_MAX_CAMERAS = %d]",
                  static_cast<int>(camera_count), FRAGSIM_MAX_CAMERAS);
    c->set_error(why);
    return FRAGSIM_ERROR_INVALID_ARGUMENT;
  }
  if (cameras == nullptr) {
    c->set_error("cameras: NULL");
    return FRAGSIM_ERROR_NULL_ARGUMENT;
  }
  for (int32_t j = 0; j < camera_count; ++j) {
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "cameras[%d]", static_cast<int>(j));
    if (Failure f = fragsim::control::validate_camera_def(cameras[j], prefix)) {
      c->set_error(f.message);
      return f.status;
    }
  }
  try {
    c->set_cameras(cameras, camera_count);
  } catch (...) {
    c->set_error("out of memory");
    return FRAGSIM_ERROR_OUT_OF_MEMORY;
  }
  c->clear_error();
  return FRAGSIM_OK;
}

FRAGSIM_API fragsim_status fragsim_controller_step(fragsim_controller_id controller,
                                                   const fragsim_step_input* input,
                                                   const fragsim_fragment* fragments,
                                                   int32_t fragment_count, fragsim_vec3* forces_N,
                                                   fragsim_step_stats* stats) {
  if (stats != nullptr) *stats = {};
  const bool count_ok = fragment_count >= 0 && fragment_count <= kMaxFragments;
  const StructSink sink{forces_N};
  Controller* c = find_controller(controller);
  auto refuse = [&](fragsim_status s, const char* why) {
    if (count_ok) sink.zero(static_cast<std::size_t>(fragment_count));
    if (c != nullptr) c->set_error(why);
    return s;
  };
  if (c == nullptr) return refuse(FRAGSIM_ERROR_STALE_ID, kStaleMessage);
  if (!count_ok) return refuse(FRAGSIM_ERROR_INVALID_ARGUMENT, count_rule(fragment_count).text);
  if (input == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "input: NULL");
  const auto n = static_cast<std::size_t>(fragment_count);
  if (n > 0 && fragments == nullptr) {
    return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "fragments: NULL with fragment_count > 0");
  }
  if (n > 0 && forces_N == nullptr) {
    return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "forces_N: NULL with fragment_count > 0");
  }
  return guarded_step(*c, *input, StructSource{fragments}, n, sink, stats);
}

FRAGSIM_API fragsim_status fragsim_controller_step_arrays(fragsim_controller_id controller,
                                                          const fragsim_step_input* input,
                                                          const fragsim_fragment_arrays* arrays,
                                                          int32_t fragment_count,
                                                          fragsim_step_stats* stats) {
  if (stats != nullptr) *stats = {};
  // Zeros go to the force buffer only where its size is known (a valid count, scalar_type and, if
  // count > 1, force stride).
  const bool count_ok =
      fragment_count >= 0 && fragment_count <= kMaxFragments &&
      (arrays == nullptr ||
       fragsim::control::force_layout_known(*arrays, static_cast<std::size_t>(fragment_count)));
  const ArraySink sink{arrays != nullptr ? arrays->force_N : nullptr,
                       arrays != nullptr ? arrays->force_stride_bytes : 0,
                       arrays != nullptr && raw(arrays->scalar_type) == FRAGSIM_SCALAR_FLOAT};
  Controller* c = find_controller(controller);
  auto refuse = [&](fragsim_status s, const char* why) {
    if (count_ok) sink.zero(static_cast<std::size_t>(fragment_count));
    if (c != nullptr) c->set_error(why);
    return s;
  };
  if (c == nullptr) return refuse(FRAGSIM_ERROR_STALE_ID, kStaleMessage);
  if (fragment_count < 0 || fragment_count > kMaxFragments) {
    return refuse(FRAGSIM_ERROR_INVALID_ARGUMENT, count_rule(fragment_count).text);
  }
  if (input == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "input: NULL");
  if (arrays == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, "arrays: NULL");
  const auto n = static_cast<std::size_t>(fragment_count);
  if (Failure f = fragsim::control::validate_arrays(*arrays, n)) {
    return refuse(f.status, f.message);
  }
  if (n > 0) {
    const void* required[6] = {arrays->position_m, arrays->velocity_mps, arrays->radius_m,
                               arrays->mass_kg,    arrays->id,           arrays->force_N};
    const char* names[6] = {"arrays.position_m: NULL with fragment_count > 0",
                            "arrays.velocity_mps: NULL with fragment_count > 0",
                            "arrays.radius_m: NULL with fragment_count > 0",
                            "arrays.mass_kg: NULL with fragment_count > 0",
                            "arrays.id: NULL with fragment_count > 0",
                            "arrays.force_N: NULL with fragment_count > 0"};
    for (int k = 0; k < 6; ++k) {
      if (required[k] == nullptr) return refuse(FRAGSIM_ERROR_NULL_ARGUMENT, names[k]);
    }
  }
  return guarded_step(*c, *input,
                      ArraySource{arrays, raw(arrays->scalar_type) == FRAGSIM_SCALAR_FLOAT}, n,
                      sink, stats);
}

FRAGSIM_API const char* fragsim_controller_last_error(fragsim_controller_id controller) {
  const Controller* c = find_controller(controller);
  if (c == nullptr) return kStaleMessage;
  return c->error();
}

}  // extern "C"
