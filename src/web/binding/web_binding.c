/* What JavaScript needs besides the C API to call it. First, the structs' layouts as this build
 * lays them out, so the JavaScript wrapper (package/fragsim.mjs) writes and reads every field by
 * its offset and never by a copy of the C declarations. Second, the calls that take a controller
 * id or return a struct by value, which WebAssembly's C ABI passes through hidden pointers, as
 * calls over plain pointers and integers. Compiled into the module only; nothing here is part of
 * the library. */
#include <fragsim/control.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#define WEB_API EMSCRIPTEN_KEEPALIVE
#else
#define WEB_API
#endif

/* The layout as JSON: {"struct": {"size": n, "fields": {"a.b": [offset, "kind"], ...}}, ...}.
 * Kinds: f64, i32, u32, u8, ptr, vec3 (three f64), f64x4. */
static char layout[8192];
static size_t used;

static void put(const char* text) {
  int n = snprintf(layout + used, sizeof layout - used, "%s", text);
  if (n > 0) used += (size_t)n < sizeof layout - used ? (size_t)n : sizeof layout - used - 1;
}

static void field(const char* name, size_t offset, const char* kind, int* first) {
  char entry[160];
  snprintf(entry, sizeof entry, "%s\"%s\":[%u,\"%s\"]", *first ? "" : ",", name, (unsigned)offset,
           kind);
  put(entry);
  *first = 0;
}

static void open_struct(const char* name, size_t size, int first_struct) {
  char entry[160];
  snprintf(entry, sizeof entry, "%s\"%s\":{\"size\":%u,\"fields\":{", first_struct ? "" : ",", name,
           (unsigned)size);
  put(entry);
}

#define FIELD(type, member, kind) field(#member, offsetof(type, member), kind, &first)

WEB_API const char* fragsim_web_layout(void) {
  int first;
  if (used > 0) return layout;
  put("{");
  first = 1;
  open_struct("controller_def", sizeof(fragsim_controller_def), 1);
  FIELD(fragsim_controller_def, strategy, "i32");
  FIELD(fragsim_controller_def, edge_min.margin_m, "f64");
  FIELD(fragsim_controller_def, edge_min.a_max_mps2, "f64");
  FIELD(fragsim_controller_def, edge_min.camera_model, "i32");
  FIELD(fragsim_controller_def, edge_min.camera_accel_mps2, "f64");
  FIELD(fragsim_controller_def, edge_min.camera_turn_degps, "f64");
  FIELD(fragsim_controller_def, edge_min.max_solves, "i32");
  FIELD(fragsim_controller_def, edge_min.edge_weights, "f64x4");
  FIELD(fragsim_controller_def, edge_min.cover_max, "f64");
  FIELD(fragsim_controller_def, edge_min.cover_region, "f64");
  FIELD(fragsim_controller_def, edge.k_Nms2, "f64");
  FIELD(fragsim_controller_def, edge.a_max_mps2, "f64");
  FIELD(fragsim_controller_def, edge.predictor, "i32");
  FIELD(fragsim_controller_def, edge.reach, "i32");
  FIELD(fragsim_controller_def, edge.horizon, "i32");
  FIELD(fragsim_controller_def, edge.replan, "i32");
  FIELD(fragsim_controller_def, deflect_all.accel_mps2, "f64");
  FIELD(fragsim_controller_def, deflect_all.range_m, "f64");
  FIELD(fragsim_controller_def, horizon_cap_s, "f64");
  FIELD(fragsim_controller_def, alloc_fn, "ptr");
  put("}}");
  first = 1;
  open_struct("camera_def", sizeof(fragsim_camera_def), 0);
  FIELD(fragsim_camera_def, fovy_deg, "f64");
  FIELD(fragsim_camera_def, aspect, "f64");
  FIELD(fragsim_camera_def, near_m, "f64");
  FIELD(fragsim_camera_def, far_m, "f64");
  FIELD(fragsim_camera_def, body_half_m, "vec3");
  FIELD(fragsim_camera_def, max_speed_mps, "f64");
  FIELD(fragsim_camera_def, max_accel_mps2, "f64");
  FIELD(fragsim_camera_def, max_turn_degps, "f64");
  put("}}");
  first = 1;
  open_struct("camera_pose", sizeof(fragsim_camera_pose), 0);
  FIELD(fragsim_camera_pose, eye_m, "vec3");
  FIELD(fragsim_camera_pose, right, "vec3");
  FIELD(fragsim_camera_pose, up, "vec3");
  FIELD(fragsim_camera_pose, forward, "vec3");
  FIELD(fragsim_camera_pose, velocity_mps, "vec3");
  put("}}");
  first = 1;
  open_struct("step_input", sizeof(fragsim_step_input), 0);
  FIELD(fragsim_step_input, time_s, "f64");
  FIELD(fragsim_step_input, end_time_s, "f64");
  FIELD(fragsim_step_input, dt_s, "f64");
  FIELD(fragsim_step_input, gravity_mps2, "vec3");
  FIELD(fragsim_step_input, ground_height_m, "f64");
  FIELD(fragsim_step_input, ground_normal, "vec3");
  FIELD(fragsim_step_input, camera_poses, "ptr");
  FIELD(fragsim_step_input, camera_count, "i32");
  put("}}");
  first = 1;
  open_struct("fragment_arrays", sizeof(fragsim_fragment_arrays), 0);
  FIELD(fragsim_fragment_arrays, position_m, "ptr");
  FIELD(fragsim_fragment_arrays, position_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, velocity_mps, "ptr");
  FIELD(fragsim_fragment_arrays, velocity_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, radius_m, "ptr");
  FIELD(fragsim_fragment_arrays, radius_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, mass_kg, "ptr");
  FIELD(fragsim_fragment_arrays, mass_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, id, "ptr");
  FIELD(fragsim_fragment_arrays, id_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, touched, "ptr");
  FIELD(fragsim_fragment_arrays, touched_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, force_N, "ptr");
  FIELD(fragsim_fragment_arrays, force_stride_bytes, "ptr");
  FIELD(fragsim_fragment_arrays, scalar_type, "i32");
  put("}}");
  first = 1;
  open_struct("step_stats", sizeof(fragsim_step_stats), 0);
  FIELD(fragsim_step_stats, candidates, "i32");
  FIELD(fragsim_step_stats, pushed, "i32");
  FIELD(fragsim_step_stats, capped, "i32");
  FIELD(fragsim_step_stats, guarded, "i32");
  FIELD(fragsim_step_stats, new_ids, "i32");
  FIELD(fragsim_step_stats, dropped_ids, "i32");
  FIELD(fragsim_step_stats, deferred, "i32");
  FIELD(fragsim_step_stats, rejected_cheaply, "i32");
  FIELD(fragsim_step_stats, skipped, "i32");
  FIELD(fragsim_step_stats, first_skipped, "i32");
  FIELD(fragsim_step_stats, unprotected, "i32");
  FIELD(fragsim_step_stats, below_ground, "i32");
  FIELD(fragsim_step_stats, first_below_ground, "i32");
  FIELD(fragsim_step_stats, conflicts, "i32");
  FIELD(fragsim_step_stats, first_conflict, "i32");
  FIELD(fragsim_step_stats, warnings, "u32");
  put("}}");
  first = 1;
  open_struct("controller_id", sizeof(fragsim_controller_id), 0);
  FIELD(fragsim_controller_id, index1, "u32");
  FIELD(fragsim_controller_id, generation, "u32");
  put("}}}");
  return layout;
}

/* The defaults, written where JavaScript says. */
WEB_API void fragsim_web_default_controller_def(fragsim_controller_def* out) {
  *out = fragsim_default_controller_def();
}
WEB_API void fragsim_web_default_camera_def(fragsim_camera_def* out) {
  *out = fragsim_default_camera_def();
}
WEB_API void fragsim_web_default_camera_pose(fragsim_camera_pose* out) {
  *out = fragsim_default_camera_pose();
}
WEB_API void fragsim_web_default_step_input(fragsim_step_input* out) {
  *out = fragsim_default_step_input();
}
WEB_API void fragsim_web_default_fragment_arrays(fragsim_fragment_arrays* out) {
  *out = fragsim_default_fragment_arrays();
}

/* The calls that take an id, with the id as its two numbers. */
static fragsim_controller_id id_of(uint32_t index1, uint32_t generation) {
  fragsim_controller_id id;
  id.index1 = index1;
  id.generation = generation;
  return id;
}
WEB_API int32_t fragsim_web_destroy(uint32_t index1, uint32_t generation) {
  return (int32_t)fragsim_controller_destroy(id_of(index1, generation));
}
WEB_API int32_t fragsim_web_reset(uint32_t index1, uint32_t generation) {
  return (int32_t)fragsim_controller_reset(id_of(index1, generation));
}
WEB_API int32_t fragsim_web_reserve(uint32_t index1, uint32_t generation, int32_t count) {
  return (int32_t)fragsim_controller_reserve(id_of(index1, generation), count);
}
WEB_API int32_t fragsim_web_set_cameras(uint32_t index1, uint32_t generation,
                                        const fragsim_camera_def* cameras, int32_t count) {
  return (int32_t)fragsim_controller_set_cameras(id_of(index1, generation), cameras, count);
}
WEB_API int32_t fragsim_web_step_arrays(uint32_t index1, uint32_t generation,
                                        const fragsim_step_input* input,
                                        const fragsim_fragment_arrays* arrays, int32_t count,
                                        fragsim_step_stats* stats) {
  return (int32_t)fragsim_controller_step_arrays(id_of(index1, generation), input, arrays, count,
                                                 stats);
}
WEB_API const char* fragsim_web_last_error(uint32_t index1, uint32_t generation) {
  return fragsim_controller_last_error(id_of(index1, generation));
}

/* JavaScript ids as 32-bit numbers (a Uint32Array, Rapier's handles), widened in one call. */
WEB_API void fragsim_web_widen_ids(const uint32_t* in, uint64_t* out, int32_t count) {
  int32_t i;
  for (i = 0; i < count; ++i) out[i] = in[i];
}
