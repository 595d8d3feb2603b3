/* Every promise fragsim/types.h and fragsim/control.h make, each with the test function here that
 * checks it, in C99 as a game sees the API. A promise not tested says why.
 *
 * fragsim/types.h
 *   "Every angle is in degrees" (fovy_deg, max_turn_degps, camera_turn_degps)
 *                                                   defaults_are_documented, refusals_name_values
 *   "Special values, each with one meaning": FRAGSIM_UNDECLARED, INFINITY (bounds, end_time_s),
 *     -INFINITY (no ground), 0 (cannot move, cannot turn, mass 0 cannot be pushed)
 *                                                   special_values_have_one_meaning
 *   "a zero normal, a zero end time or a zero field of view is refused, and a def that did not
 *     come from fragsim_default_controller_def is refused"
 *                                                   zero_initialised_structs_are_refused
 *   FRAGSIM_MAX_FRAGMENTS "INT32_MAX / 4"; a count past it refused     limits_are_the_headers
 *   FRAGSIM_MAX_CAMERAS, FRAGSIM_MAX_WORKERS: the ranges of set_cameras and worker_count
 *                                                   limits_are_the_headers
 *   FRAGSIM_MAX_CONTROLLERS: not tested (65,537 live controllers cost too much for a unit test)
 *   FRAGSIM_MIN_MASS_KG..FRAGSIM_MAX_MASS_KG: "within this range [the force] is finite and not
 *     rounded to zero, as a double and as a float. A fragment outside it is skipped"
 *                                                   masses_in_range_get_finite_nonzero_forces,
 *                                                   masses_out_of_range_are_skipped
 *   controller id: "an id kept after fragsim_controller_destroy, or never created (all zero), is
 *     refused with FRAGSIM_ERROR_STALE_ID"          stale_ids_are_refused
 *   FRAGSIM_ERROR_NULL_ARGUMENT "A required pointer is NULL"            refusals_name_values
 *   FRAGSIM_ERROR_DEF_NOT_DEFAULTED                 zero_initialised_structs_are_refused
 *   FRAGSIM_ERROR_DUPLICATE_ID "Two fragments of one call share an id"  refusals_name_values
 *   FRAGSIM_ERROR_OUT_OF_MEMORY "The controller is as it was before the call, but for the one case"
 *                                                   failed_allocations_leave_the_controller
 *   FRAGSIM_ERROR_INTERNAL: never returned by any call here (every test checks each status)
 *   edge-min, edge, deflect-all defaults and ranges ("in [0, 1e9]", "[0, 1e6]", "(0, 1]", "0
 *     forbids an edge (not all four)", horizon_cap_s "(0, 3600]")
 *                                                   defaults_are_documented, def_ranges_are_kept
 *   max_solves: "stats.deferred counts them"        solve_budget_defers
 *   allocator: "Every allocation ... is alloc_fn(size, alignment, user), freed by free_fn(...)
 *     with the same size and alignment. alignment is a power of two"; "one without the other is
 *     refused"; "alloc_user ... passed to both as it is"
 *                                                   allocator_hook_is_used_exactly
 *   task system: "one without the other is refused"; "The forces and stats are the same, bit for
 *     bit, for any worker count and any split into ranges"; "user_task_context ... passed to both
 *     as it is"; worker_index below worker_count; enqueue may return NULL after running it all
 *                                                   task_system_gives_the_same_bits
 *   worker_count "In [1, FRAGSIM_MAX_WORKERS]; default 1"               limits_are_the_headers
 *   camera def: fovy (0, 180), "below 5 ... sets FRAGSIM_WARNING_FOVY_IN_RADIANS", aspect
 *     "in [1e-3, 1e3]", near > 0, far > near, body >= 0, max_speed >= 0 and the over-speed
 *     warning                                       refusals_name_values, warnings_are_raised
 *   the occlusion bound at the extreme aspects (1e-3, 1e3) steps: asserted in bounded memory
 *                                                   occlusion_bound_at_extreme_aspects
 *   camera pose: axes "each of length 1 and at right angles ... within 1e-6"
 *                                                   refusals_name_values
 *   fragment: "A fragment that breaks a rule below ... is skipped, not refused: it gets a zero
 *     force, the others are protected as usual"    masses_out_of_range_are_skipped
 *   mass 0: "examined, gets no force, and stats.unprotected counts it when it threatens"
 *                                                   massless_threat_is_unprotected
 *   "an id it did not see at its last step is a new fragment"          ids_come_and_go
 *   float arrays: "each number is converted to double exactly ... each force is the double force
 *     rounded to the nearest float"                 float_arrays_round_the_double_forces
 *   arrays: strides "at least its element's size ... with more than one fragment a smaller one,
 *     0 included, is refused"; scalar_type "another value is refused"   refusals_name_values
 *   step input: "Only differences of times are used" time_shift_changes_nothing
 *   end_time_s "must be after time_s"; dt_s > 0; ground_normal unit within 1e-6
 *                                                   refusals_name_values
 *   "a step whose normal differs from the last successful step's forgets every fragment first"
 *                                                   ids_come_and_go
 *   camera_poses: "as many as fragsim_controller_set_cameras set ... another count is refused"
 *                                                   refusals_name_values
 *   FRAGSIM_WARNING_BELOW_GROUND "Most often the ground normal was left at its y-up default in a
 *     z-up engine"; stats.below_ground, first_below_ground (-1: none)
 *                                                   forgotten_normal_is_below_ground
 *   FRAGSIM_WARNING_UNPROTECTED, FRAGSIM_WARNING_SKIPPED, CAMERA_OVER_SPEED, FOVY_IN_RADIANS
 *                                                   warnings_are_raised
 *   stats: "rejected_cheaply ... 0 for edge and deflect-all"; first_* -1 for none; pushed counts
 *     nonzero forces                                stats_mean_what_they_say
 *   the defaults functions: each documented default  defaults_are_documented
 *
 * fragsim/control.h
 *   "writes one force per fragment ... (zero for most)": only threats pushed
 *                                                   stats_mean_what_they_say
 *   "The library creates none [threads]": not tested portably (C99 has no thread count)
 *   "No function ... writes a non-finite number to the caller"
 *                                                   masses_in_range_get_finite_nonzero_forces,
 *                                                   no_non_finite_output_on_wild_input
 *   "A refused call leaves the controller as it was and says why ... naming the field and the
 *     value refused"                                refused_calls_change_nothing,
 * refusals_name_values fragsim_version, fragsim_version_string         version_is_the_headers
 *   fragsim_status_string "never NULL"              version_is_the_headers
 *   fragsim_controller_id_is_null "True for the all-zero id ... says nothing of whether a nonzero
 *     id is alive"                                  id_is_null_says_only_null
 *   create: "On failure *out_controller is the null id and ... a NUL-terminated reason ... cut to
 *     message_size"                                 create_failure_message
 *   destroy: "FRAGSIM_OK for the null id ... destroying twice is refused"
 *                                                   stale_ids_are_refused
 *   reset: "Forgets every fragment ... Keeps the room reserved and allocates nothing"
 *                                                   reserve_and_reset_allocate_as_promised
 *   reserve: "[0, FRAGSIM_MAX_FRAGMENTS] ... A step with at most that many fragments then
 *     allocates nothing"                            reserve_and_reset_allocate_as_promised
 *   set_cameras: "[1, FRAGSIM_MAX_CAMERAS] ... a refusal names cameras[i] and the field, and
 *     keeps the cameras as they were"; "The state kept per fragment survives a change of
 *     constants; a change of camera count forgets every fragment"
 *                                                   set_cameras_refusal_keeps_cameras,
 * ids_come_and_go step: "On any status other than FRAGSIM_OK, forces_N ... is filled with zeros,
 * *stats is zeroed, the controller's state is as it was before the call"; "stats may be NULL"
 *                                                   refused_calls_change_nothing
 *   step_arrays: "A refused call writes zeros to force_N only where its layout is known"
 *                                                   refused_calls_change_nothing
 *   last_error: "" after a successful call; never NULL; a static text for a stale or null id
 *                                                   stale_ids_are_refused, refusals_name_values
 */
#include <float.h>
#include <fragsim/control.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

/* ---- helpers ---------------------------------------------------------------------------- */

static int contains(const char* text, const char* part) {
  return strstr(text, part) != NULL;
}

static fragsim_vec3 v3(double x, double y, double z) {
  fragsim_vec3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

static int is_zero(fragsim_vec3 v) {
  return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

static int is_finite3(fragsim_vec3 v) {
  return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static int stats_are_zero(const fragsim_step_stats* s) {
  static const fragsim_step_stats zero;
  return memcmp(s, &zero, sizeof zero) == 0;
}

/* The camera every scene here uses: the default one with its eye at (0, 1.6, 0), looking down
 * -z, still. */
static fragsim_camera_pose eye_pose(void) {
  fragsim_camera_pose p = fragsim_default_camera_pose();
  p.eye_m.y = 1.6;
  return p;
}

/* A fragment 6 m ahead of the eye coming at 12 m/s, thrown up at 2.45 m/s so that gravity brings
 * it back to the eye's height as it arrives (0.5 s), x to the side (0: at the lens). */
static fragsim_fragment aimed(uint64_t id, double x) {
  fragsim_fragment f = fragsim_default_fragment();
  f.position_m = v3(x, 1.6, -6.0);
  f.velocity_mps = v3(0.0, 2.45, 12.0);
  f.radius_m = 0.05;
  f.mass_kg = 0.5;
  f.id = id;
  return f;
}

/* A scene of n fragments at step k, ballistic (the engine ignores the forces): every third aimed
 * near the lens, the others passing 2 to 4 m to the side. Ids base + i. */
static void scene(int k, int n, uint64_t base, fragsim_fragment* f) {
  int i;
  const double t = k / 60.0;
  for (i = 0; i < n; ++i) {
    const double side = i % 3 == 0 ? 0.01 * (i % 7) - 0.03 : 2.0 + 0.01 * i;
    f[i] = aimed(base + (uint64_t)i, side);
    f[i].position_m.z = -6.0 - 0.02 * i + 12.0 * t;
    f[i].position_m.y = 1.6 + 2.45 * t - 4.905 * t * t;
    f[i].velocity_mps.y = 2.45 - 9.81 * t;
    f[i].radius_m = 0.03 + 0.0005 * i;
    f[i].mass_kg = 0.2 + 0.01 * i;
  }
}

/* The input of a scene step with one camera at *pose. */
static fragsim_step_input input_for(int k, const fragsim_camera_pose* pose) {
  fragsim_step_input in = fragsim_default_step_input();
  in.time_s = k / 60.0;
  in.ground_height_m = 0.0;
  in.camera_poses = pose;
  in.camera_count = 1;
  return in;
}

static fragsim_controller_id create_or_fail(const fragsim_controller_def* def) {
  fragsim_controller_id id;
  char message[256];
  const fragsim_status s = fragsim_controller_create(def, &id, message, sizeof message);
  CHECK(s == FRAGSIM_OK);
  if (s != FRAGSIM_OK) fprintf(stderr, "create: %s\n", message);
  return id;
}

/* A controller of `def` with one default camera. */
static fragsim_controller_id make_def(const fragsim_controller_def* def) {
  const fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_controller_id id = create_or_fail(def);
  CHECK(fragsim_controller_set_cameras(id, &camera, 1) == FRAGSIM_OK);
  return id;
}

static fragsim_controller_id make(void) {
  const fragsim_controller_def def = fragsim_default_controller_def();
  return make_def(&def);
}

/* ---- the game's allocator, counting ----------------------------------------------------- */

enum { kMaxLive = 1 << 14 };
typedef struct Hook {
  void* ptr[kMaxLive];
  size_t size[kMaxLive];
  size_t align[kMaxLive];
  int live;
  long calls;     /* alloc_fn calls */
  long fail_at;   /* the fail_at-th call from now returns NULL (0: none) */
  size_t bytes;   /* live bytes */
  size_t peak;    /* the most live bytes */
  int bad_free;   /* frees of an unknown pointer or another size or alignment */
  int bad_align;  /* an alignment not a power of two, or a pointer not aligned to it */
  int bad_user;   /* the user pointer not the one given */
  int overflowed; /* more live allocations than kMaxLive */
} Hook;

static Hook g_hook;

static void hook_reset(void) {
  memset(&g_hook, 0, sizeof g_hook);
}

static void* hook_alloc(size_t size, size_t alignment, void* user) {
  unsigned char* raw;
  uintptr_t at;
  if (user != &g_hook) ++g_hook.bad_user;
  ++g_hook.calls;
  if (g_hook.fail_at > 0 && --g_hook.fail_at == 0) return NULL;
  if (alignment == 0 || (alignment & (alignment - 1)) != 0) ++g_hook.bad_align;
  if (g_hook.live == kMaxLive) {
    ++g_hook.overflowed;
    return NULL;
  }
  raw = (unsigned char*)malloc(size + alignment + sizeof(void*));
  if (raw == NULL) return NULL;
  at = (uintptr_t)(raw + sizeof(void*));
  at = (at + alignment - 1) / alignment * alignment;
  memcpy((void*)(at - sizeof(void*)), &raw, sizeof raw);
  g_hook.ptr[g_hook.live] = (void*)at;
  g_hook.size[g_hook.live] = size;
  g_hook.align[g_hook.live] = alignment;
  ++g_hook.live;
  g_hook.bytes += size;
  if (g_hook.bytes > g_hook.peak) g_hook.peak = g_hook.bytes;
  return (void*)at;
}

static void hook_free(void* pointer, size_t size, size_t alignment, void* user) {
  int i;
  void* raw;
  if (user != &g_hook) ++g_hook.bad_user;
  if (pointer == NULL) return;
  for (i = g_hook.live - 1; i >= 0; --i) {
    if (g_hook.ptr[i] == pointer) break;
  }
  if (i < 0 || g_hook.size[i] != size || g_hook.align[i] != alignment) {
    ++g_hook.bad_free;
    if (i < 0) return;
  }
  g_hook.bytes -= g_hook.size[i];
  --g_hook.live;
  g_hook.ptr[i] = g_hook.ptr[g_hook.live];
  g_hook.size[i] = g_hook.size[g_hook.live];
  g_hook.align[i] = g_hook.align[g_hook.live];
  memcpy(&raw, (unsigned char*)pointer - sizeof(void*), sizeof raw);
  free(raw);
}

static fragsim_controller_def hooked_def(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.alloc_fn = hook_alloc;
  def.free_fn = hook_free;
  def.alloc_user = &g_hook;
  return def;
}

/* ---- the promises ----------------------------------------------------------------------- */

static void version_is_the_headers(void) {
  CHECK(fragsim_version() == FRAGSIM_CONTROL_VERSION);
  CHECK(FRAGSIM_CONTROL_VERSION == 10000);
  CHECK(strcmp(fragsim_version_string(), "1.0.0") == 0);
  CHECK(strcmp(fragsim_status_string(FRAGSIM_OK), "ok") == 0);
  CHECK(strcmp(fragsim_status_string(FRAGSIM_ERROR_INVALID_ARGUMENT), "invalid argument") == 0);
  CHECK(fragsim_status_string((fragsim_status)99) != NULL);
  CHECK(fragsim_status_string((fragsim_status)-1) != NULL);
}

static void defaults_are_documented(void) {
  const fragsim_controller_def d = fragsim_default_controller_def();
  const fragsim_camera_def c = fragsim_default_camera_def();
  const fragsim_camera_pose p = fragsim_default_camera_pose();
  const fragsim_fragment f = fragsim_default_fragment();
  const fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  const fragsim_step_input in = fragsim_default_step_input();
  int k;
  /* The def. */
  CHECK(d.strategy == FRAGSIM_STRATEGY_EDGE_MIN);
  CHECK(d.edge_min.margin_m == 0.05);
  CHECK(d.edge_min.a_max_mps2 == 50.0);
  CHECK(d.edge_min.camera_model == FRAGSIM_CAMERA_BOUNDED_ACCEL);
  CHECK(d.edge_min.camera_accel_mps2 == 20.0);
  CHECK(isinf(d.edge_min.camera_turn_degps) && d.edge_min.camera_turn_degps > 0.0);
  CHECK(d.edge_min.max_solves == 0);
  for (k = 0; k < 4; ++k) CHECK(d.edge_min.edge_weights[k] == 1.0);
  CHECK(d.edge_min.cover_max == 1.0);
  CHECK(d.edge_min.cover_region == 0.5);
  CHECK(d.edge.k_Nms2 == 1.0);
  CHECK(d.edge.a_max_mps2 == 50.0);
  CHECK(d.edge.predictor == FRAGSIM_EDGE_PREDICTOR_THESIS);
  CHECK(d.edge.reach == FRAGSIM_EDGE_REACH_THESIS);
  CHECK(d.edge.horizon == FRAGSIM_EDGE_HORIZON_CAMERA);
  CHECK(d.edge.replan == FRAGSIM_EDGE_REPLAN_NEVER);
  CHECK(d.deflect_all.accel_mps2 == 60.0);
  CHECK(d.deflect_all.range_m == 6.0);
  CHECK(d.horizon_cap_s == 3.0);
  CHECK(d.alloc_fn == NULL && d.free_fn == NULL && d.alloc_user == NULL);
  CHECK(d.enqueue_task == NULL && d.finish_task == NULL && d.user_task_context == NULL);
  CHECK(d.worker_count == 1);
  /* The camera def: fovy 60, 16:9, near 0.1, far 500, body 0.3 x 0.2 x 0.3, speed 3, bounds
   * undeclared. */
  CHECK(c.fovy_deg == 60.0);
  CHECK(c.aspect == 16.0 / 9.0);
  CHECK(c.near_m == 0.1);
  CHECK(c.far_m == 500.0);
  CHECK(c.body_half_m.x == 0.15 && c.body_half_m.y == 0.1 && c.body_half_m.z == 0.15);
  CHECK(c.max_speed_mps == 3.0);
  CHECK(c.max_accel_mps2 == FRAGSIM_UNDECLARED && c.max_turn_degps == FRAGSIM_UNDECLARED);
  CHECK(FRAGSIM_UNDECLARED == -1.0);
  /* The pose: at the origin, looking down -z, still. */
  CHECK(is_zero(p.eye_m) && is_zero(p.velocity_mps));
  CHECK(p.right.x == 1.0 && p.right.y == 0.0 && p.right.z == 0.0);
  CHECK(p.up.x == 0.0 && p.up.y == 1.0 && p.up.z == 0.0);
  CHECK(p.forward.x == 0.0 && p.forward.y == 0.0 && p.forward.z == -1.0);
  /* The fragment: at the origin, still, radius 0, mass 0, id 0, not touched. */
  CHECK(is_zero(f.position_m) && is_zero(f.velocity_mps));
  CHECK(f.radius_m == 0.0 && f.mass_kg == 0.0 && f.id == 0 && f.touched == 0);
  /* The arrays: every pointer NULL, doubles, packed strides. */
  CHECK(a.position_m == NULL && a.velocity_mps == NULL && a.radius_m == NULL);
  CHECK(a.mass_kg == NULL && a.id == NULL && a.touched == NULL && a.force_N == NULL);
  CHECK(a.scalar_type == FRAGSIM_SCALAR_DOUBLE);
  CHECK(a.position_stride_bytes == 24 && a.velocity_stride_bytes == 24);
  CHECK(a.force_stride_bytes == 24);
  CHECK(a.radius_stride_bytes == 8 && a.mass_stride_bytes == 8 && a.id_stride_bytes == 8);
  CHECK(a.touched_stride_bytes == 1);
  /* The step input: time 0, no end, dt 1/60, gravity -9.81 y, no ground, normal +y, no poses. */
  CHECK(in.time_s == 0.0);
  CHECK(isinf(in.end_time_s) && in.end_time_s > 0.0);
  CHECK(in.dt_s == 1.0 / 60.0);
  CHECK(in.gravity_mps2.x == 0.0 && in.gravity_mps2.y == -9.81 && in.gravity_mps2.z == 0.0);
  CHECK(isinf(in.ground_height_m) && in.ground_height_m < 0.0);
  CHECK(in.ground_normal.x == 0.0 && in.ground_normal.y == 1.0 && in.ground_normal.z == 0.0);
  CHECK(in.camera_poses == NULL && in.camera_count == 0);
}

static void limits_are_the_headers(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_camera_def cams[FRAGSIM_MAX_CAMERAS + 1];
  fragsim_camera_pose poses[FRAGSIM_MAX_CAMERAS];
  fragsim_controller_id id;
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force;
  char message[256];
  int k;
  CHECK(FRAGSIM_MAX_FRAGMENTS == INT32_MAX / 4);
  for (k = 0; k <= FRAGSIM_MAX_CAMERAS; ++k) cams[k] = fragsim_default_camera_def();
  for (k = 0; k < FRAGSIM_MAX_CAMERAS; ++k) {
    poses[k] = eye_pose();
    poses[k].eye_m.x = 0.5 * k;
  }
  def.worker_count = FRAGSIM_MAX_WORKERS;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) == FRAGSIM_OK);
  CHECK(fragsim_controller_set_cameras(id, cams, FRAGSIM_MAX_CAMERAS) == FRAGSIM_OK);
  CHECK(fragsim_controller_set_cameras(id, cams, FRAGSIM_MAX_CAMERAS + 1) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  in.camera_poses = poses;
  in.camera_count = FRAGSIM_MAX_CAMERAS;
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
  CHECK(is_finite3(force) && !is_zero(force));
  CHECK(fragsim_controller_reserve(id, 0) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, NULL, FRAGSIM_MAX_FRAGMENTS + 1, NULL, NULL) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  fragsim_controller_destroy(id);
  def.worker_count = FRAGSIM_MAX_WORKERS + 1;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  def.worker_count = 0;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
}

static void id_is_null_says_only_null(void) {
  fragsim_controller_id null_id;
  fragsim_controller_id id;
  memset(&null_id, 0, sizeof null_id);
  CHECK(fragsim_controller_id_is_null(null_id));
  id = make();
  CHECK(!fragsim_controller_id_is_null(id));
  CHECK(fragsim_controller_destroy(id) == FRAGSIM_OK);
  /* Destroyed: not alive, and still not the null id. */
  CHECK(!fragsim_controller_id_is_null(id));
  CHECK(!fragsim_controller_is_valid(id));
  CHECK(!fragsim_controller_is_valid(null_id));
}

static void stale_ids_are_refused(void) {
  fragsim_controller_id id = make();
  fragsim_controller_id null_id;
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_fragment_arrays arrays = fragsim_default_fragment_arrays();
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force = v3(7.0, 7.0, 7.0);
  fragsim_step_stats stats;
  memset(&null_id, 0, sizeof null_id);
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, &stats) == FRAGSIM_OK);
  CHECK(strcmp(fragsim_controller_last_error(id), "") == 0);
  CHECK(fragsim_controller_destroy(id) == FRAGSIM_OK);
  CHECK(fragsim_controller_destroy(id) == FRAGSIM_ERROR_STALE_ID); /* destroy twice: refused */
  CHECK(fragsim_controller_destroy(null_id) == FRAGSIM_OK);
  CHECK(fragsim_controller_reset(id) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_reserve(id, 4) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_set_cameras(id, &camera, 1) == FRAGSIM_ERROR_STALE_ID);
  force = v3(7.0, 7.0, 7.0);
  stats.pushed = 9;
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, &stats) == FRAGSIM_ERROR_STALE_ID);
  CHECK(is_zero(force) && stats_are_zero(&stats));
  CHECK(fragsim_controller_step_arrays(id, &in, &arrays, 0, NULL) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_step(null_id, &in, &f, 1, &force, NULL) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_reset(null_id) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_last_error(id) != NULL);
  CHECK(contains(fragsim_controller_last_error(id), "stale"));
  CHECK(contains(fragsim_controller_last_error(null_id), "null id"));
}

static void create_failure_message(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  char message[256];
  char small[8];
  def.horizon_cap_s = -2.5;
  id.index1 = 77;
  id.generation = 5;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(fragsim_controller_id_is_null(id) && id.generation == 0);
  CHECK(contains(message, "horizon_cap_s = -2.5"));
  memset(small, 'x', sizeof small);
  CHECK(fragsim_controller_create(&def, &id, small, sizeof small) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(small[7] == '\0' && strlen(small) == 7);
  CHECK(strncmp(small, message, 7) == 0);
  CHECK(fragsim_controller_create(&def, &id, NULL, 0) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  def = fragsim_default_controller_def();
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) == FRAGSIM_OK);
  CHECK(strcmp(message, "") == 0);
  fragsim_controller_destroy(id);
}

static void zero_initialised_structs_are_refused(void) {
  fragsim_controller_def def;
  fragsim_controller_id id = make();
  fragsim_camera_def camera;
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in;
  char message[256];
  memset(&def, 0, sizeof def);
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_DEF_NOT_DEFAULTED);
  CHECK(contains(message, "fragsim_default_controller_def"));
  /* A def copied field by field but not from the defaults function: refused too. */
  def = fragsim_default_controller_def();
  def.internal_value = 0;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_DEF_NOT_DEFAULTED);
  id = make();
  memset(&camera, 0, sizeof camera); /* zero field of view */
  CHECK(fragsim_controller_set_cameras(id, &camera, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "cameras[0].fovy_deg = 0"));
  memset(&in, 0, sizeof in); /* zero end time and zero normal */
  in.dt_s = 1.0 / 60.0;
  in.camera_poses = &pose;
  in.camera_count = 1;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, NULL) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "end_time_s = 0"));
  in.end_time_s = INFINITY;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, NULL) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "ground_normal has length 0"));
  fragsim_controller_destroy(id);
}

/* The force on a fragment aimed at the lens, with the given mass, through the struct call. */
static fragsim_vec3 force_on(fragsim_controller_id id, double mass, fragsim_step_stats* stats) {
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force = v3(7.0, 7.0, 7.0);
  f.mass_kg = mass;
  CHECK(fragsim_controller_reset(id) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, stats) == FRAGSIM_OK);
  return force;
}

/* The force on the same fragment given as floats. */
static void float_force_on(fragsim_controller_id id, float mass, float force[3],
                           fragsim_step_stats* stats) {
  const fragsim_fragment f = aimed(1, 0.0);
  const float position[3] = {(float)f.position_m.x, (float)f.position_m.y, (float)f.position_m.z};
  const float velocity[3] = {(float)f.velocity_mps.x, (float)f.velocity_mps.y,
                             (float)f.velocity_mps.z};
  const float radius = (float)f.radius_m;
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  a.scalar_type = FRAGSIM_SCALAR_FLOAT;
  a.position_m = position;
  a.velocity_mps = velocity;
  a.radius_m = &radius;
  a.mass_kg = &mass;
  a.id = &f.id;
  a.force_N = force;
  force[0] = force[1] = force[2] = 7.0f;
  CHECK(fragsim_controller_reset(id) == FRAGSIM_OK);
  CHECK(fragsim_controller_step_arrays(id, &in, &a, 1, stats) == FRAGSIM_OK);
}

/* Masses across [FRAGSIM_MIN_MASS_KG, FRAGSIM_MAX_MASS_KG], the ends included, aimed at the lens:
 * every strategy gives a finite nonzero force, as a double and as a float, and (edge-min,
 * deflect-all) one proportional to the mass: the acceleration force / mass is the same within
 * 1e-12 relative as a double. */
static void masses_in_range_get_finite_nonzero_forces(void) {
  const fragsim_strategy strategies[3] = {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE,
                                          FRAGSIM_STRATEGY_DEFLECT_ALL};
  /* The float ends: the floats nearest the limits inside the range (the nearest float to 1e-12
   * is below it, the nearest to 1e24 above: both are outside). */
  const float float_min = nextafterf((float)FRAGSIM_MIN_MASS_KG, 1.0f);
  const float float_max = nextafterf((float)FRAGSIM_MAX_MASS_KG, 0.0f);
  int s, e;
  CHECK((double)float_min >= FRAGSIM_MIN_MASS_KG && (double)float_max <= FRAGSIM_MAX_MASS_KG);
  for (s = 0; s < 3; ++s) {
    fragsim_controller_def def = fragsim_default_controller_def();
    fragsim_controller_id id;
    double unit_accel = 0.0;
    def.strategy = strategies[s];
    id = make_def(&def);
    for (e = -12; e <= 24; e += 3) {
      const double mass = e == -12  ? FRAGSIM_MIN_MASS_KG
                          : e == 24 ? FRAGSIM_MAX_MASS_KG
                                    : pow(10, e);
      fragsim_step_stats stats;
      const fragsim_vec3 force = force_on(id, mass, &stats);
      const double accel = sqrt(force.x * force.x + force.y * force.y + force.z * force.z) / mass;
      CHECK(is_finite3(force) && !is_zero(force));
      CHECK(stats.skipped == 0 && stats.pushed == 1 && stats.warnings == 0);
      if (e == -12) unit_accel = accel;
      /* edge's force is k |V| / (d^2 t), capped at mass * a_max: not proportional to the mass. */
      if (strategies[s] != FRAGSIM_STRATEGY_EDGE) {
        CHECK(fabs(accel - unit_accel) <= 1e-12 * unit_accel);
      }
    }
    {
      float force[3];
      fragsim_step_stats stats;
      float_force_on(id, float_min, force, &stats);
      CHECK(isfinite(force[0]) && isfinite(force[1]) && isfinite(force[2]));
      CHECK(force[0] != 0.0f || force[1] != 0.0f || force[2] != 0.0f);
      CHECK(stats.skipped == 0 && stats.pushed == 1);
      float_force_on(id, float_max, force, &stats);
      CHECK(isfinite(force[0]) && isfinite(force[1]) && isfinite(force[2]));
      CHECK(force[0] != 0.0f || force[1] != 0.0f || force[2] != 0.0f);
      CHECK(stats.skipped == 0 && stats.pushed == 1);
    }
    /* With every camera of FRAGSIM_MAX_CAMERAS at the same place, the forces add (edge,
     * deflect-all) or settle (edge-min): still finite at the largest mass. */
    {
      fragsim_camera_def cams[FRAGSIM_MAX_CAMERAS];
      fragsim_camera_pose poses[FRAGSIM_MAX_CAMERAS];
      fragsim_step_input in = fragsim_default_step_input();
      fragsim_fragment f = aimed(1, 0.0);
      fragsim_vec3 force;
      int k;
      for (k = 0; k < FRAGSIM_MAX_CAMERAS; ++k) {
        cams[k] = fragsim_default_camera_def();
        poses[k] = eye_pose();
        poses[k].eye_m.x = 0.01 * k;
      }
      CHECK(fragsim_controller_set_cameras(id, cams, FRAGSIM_MAX_CAMERAS) == FRAGSIM_OK);
      in.camera_poses = poses;
      in.camera_count = FRAGSIM_MAX_CAMERAS;
      f.mass_kg = FRAGSIM_MAX_MASS_KG;
      CHECK(fragsim_controller_step(id, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
      CHECK(is_finite3(force) && !is_zero(force));
    }
    fragsim_controller_destroy(id);
  }
}

/* Masses outside the range (besides 0) are skipped and counted: a zero force, never an infinite
 * one nor a silent zero. A float mass of FLT_MAX, double masses of 1e300, 1e-200, 1e25, 1e-13,
 * the denormal 5e-324, -0.5, INFINITY, NaN. The others in the call are protected as usual. */
static void masses_out_of_range_are_skipped(void) {
  const double bad[] = {1e300, 1e-200, 1e25, 1e-13, 5e-324, -0.5, INFINITY, NAN};
  const int n_bad = (int)(sizeof bad / sizeof bad[0]);
  fragsim_controller_id id = make();
  fragsim_controller_id ref = make();
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment f[2];
  fragsim_vec3 forces[2], expected;
  fragsim_step_stats stats;
  int k;
  f[1] = aimed(2, 0.02);
  CHECK(fragsim_controller_step(ref, &in, &f[1], 1, &expected, NULL) == FRAGSIM_OK);
  CHECK(!is_zero(expected));
  for (k = 0; k < n_bad; ++k) {
    f[0] = aimed(1, 0.0);
    f[0].mass_kg = bad[k];
    forces[0] = forces[1] = v3(7.0, 7.0, 7.0);
    CHECK(fragsim_controller_reset(id) == FRAGSIM_OK);
    CHECK(fragsim_controller_step(id, &in, f, 2, forces, &stats) == FRAGSIM_OK);
    CHECK(is_zero(forces[0]));
    CHECK(memcmp(&forces[1], &expected, sizeof expected) == 0);
    CHECK(stats.skipped == 1 && stats.first_skipped == 0);
    CHECK(stats.pushed == 1);
    CHECK(stats.warnings == FRAGSIM_WARNING_SKIPPED);
  }
  {
    float force[3];
    float_force_on(id, FLT_MAX, force, &stats);
    CHECK(force[0] == 0.0f && force[1] == 0.0f && force[2] == 0.0f);
    CHECK(stats.skipped == 1 && stats.first_skipped == 0 && stats.pushed == 0);
    CHECK(stats.warnings == FRAGSIM_WARNING_SKIPPED);
    float_force_on(id, FLT_MIN / 4.0f, force, &stats); /* a float denormal */
    CHECK(force[0] == 0.0f && force[1] == 0.0f && force[2] == 0.0f);
    CHECK(stats.skipped == 1 && stats.warnings == FRAGSIM_WARNING_SKIPPED);
  }
  /* The other rules: a NaN or infinite position or velocity, a negative or NaN radius. */
  for (k = 0; k < 5; ++k) {
    f[0] = aimed(1, 0.0);
    if (k == 0) f[0].position_m.z = NAN;
    if (k == 1) f[0].position_m.x = -INFINITY;
    if (k == 2) f[0].velocity_mps.y = INFINITY;
    if (k == 3) f[0].radius_m = -0.01;
    if (k == 4) f[0].radius_m = NAN;
    forces[0] = v3(7.0, 7.0, 7.0);
    CHECK(fragsim_controller_step(id, &in, f, 2, forces, &stats) == FRAGSIM_OK);
    CHECK(is_zero(forces[0]) && stats.skipped == 1 && stats.first_skipped == 0);
  }
  fragsim_controller_destroy(id);
  fragsim_controller_destroy(ref);
}

/* Wild but legal input, all in one call, for every strategy and every camera model: fragments at
 * the eye, on the near plane, 1e6 m away at 1e6 m/s, radii of 0 and 1e3, dt of 1e-9 and 10 s,
 * gravity 1e6 m/s^2, every camera bound INFINITY and 0: every force written is finite. */
static void no_non_finite_output_on_wild_input(void) {
  const fragsim_strategy strategies[3] = {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE,
                                          FRAGSIM_STRATEGY_DEFLECT_ALL};
  enum { n = 8 };
  int s, model, variant, i;
  int nonfinite = 0, calls = 0;
  for (s = 0; s < 3; ++s) {
    for (model = 0; model < 3; ++model) {
      fragsim_controller_def def = fragsim_default_controller_def();
      fragsim_controller_id id;
      def.strategy = strategies[s];
      def.edge_min.camera_model = (fragsim_camera_model)model;
      def.edge.replan = FRAGSIM_EDGE_REPLAN_ALWAYS;
      id = create_or_fail(&def);
      for (variant = 0; variant < 4; ++variant) {
        fragsim_camera_def cam = fragsim_default_camera_def();
        fragsim_camera_pose pose = eye_pose();
        fragsim_step_input in = input_for(variant, &pose);
        fragsim_fragment f[n];
        fragsim_vec3 forces[n];
        fragsim_step_stats stats;
        cam.max_accel_mps2 = variant % 2 ? INFINITY : 0.0;
        cam.max_turn_degps = variant % 2 ? 0.0 : INFINITY;
        cam.max_speed_mps = variant == 2 ? 0.0 : 1e3;
        CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_OK);
        in.dt_s = variant == 1 ? 1e-9 : variant == 3 ? 10.0 : 1.0 / 60.0;
        if (variant == 2) in.gravity_mps2 = v3(0.0, -1e6, 0.0);
        for (i = 0; i < n; ++i) f[i] = aimed((uint64_t)(i + 1), 0.0);
        f[0].position_m = pose.eye_m;         /* at the eye */
        f[1].position_m = v3(0.0, 1.6, -0.1); /* on the near plane */
        f[2].position_m = v3(0.0, 1.6, -1e6);
        f[2].velocity_mps = v3(0.0, 0.0, 1e6);
        f[3].radius_m = 0.0;
        f[4].radius_m = 1e3;
        f[5].velocity_mps = v3(0.0, 0.0, 0.0);
        f[6].position_m = v3(0.0, 1.6, 0.5); /* behind the eye, coming at it */
        f[6].velocity_mps = v3(0.0, 0.0, -12.0);
        f[7].mass_kg = FRAGSIM_MAX_MASS_KG;
        f[7].position_m.x = 1e-7;
        for (i = 0; i < n; ++i) forces[i] = v3(NAN, NAN, NAN);
        CHECK(fragsim_controller_step(id, &in, f, n, forces, &stats) == FRAGSIM_OK);
        ++calls;
        for (i = 0; i < n; ++i) nonfinite += !is_finite3(forces[i]);
      }
      fragsim_controller_destroy(id);
    }
  }
  CHECK(nonfinite == 0);
  printf("wild input: %d calls, %d non-finite forces\n", calls, nonfinite);
}

/* A mass-0 fragment aimed at the lens: examined, no force, counted unprotected, flagged. */
static void massless_threat_is_unprotected(void) {
  fragsim_controller_id id = make();
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment f[3];
  fragsim_vec3 forces[3];
  fragsim_step_stats stats;
  f[0] = aimed(1, 0.0);
  f[1] = aimed(2, 0.0);
  f[1].mass_kg = 0.0;
  f[2] = aimed(3, 3.0); /* passes 3 m to the side: no threat */
  f[2].mass_kg = 0.0;
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(!is_zero(forces[0]) && is_zero(forces[1]) && is_zero(forces[2]));
  CHECK(stats.candidates == 2);
  CHECK(stats.pushed == 1);
  CHECK(stats.unprotected == 1);
  CHECK(stats.skipped == 0);
  CHECK(stats.warnings == FRAGSIM_WARNING_UNPROTECTED);
  /* The threat gone: no flag. */
  CHECK(fragsim_controller_step(id, &in, &f[2], 1, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.unprotected == 0 && stats.warnings == 0);
  fragsim_controller_destroy(id);
}

/* A z-up world (gravity -z, ground z = 0, the camera 1.6 m up looking down -y) whose ground
 * normal was left at the y-up default: every fragment ahead of the camera is "below" the ground
 * y = 0, counted, first index given, flagged. With the normal set, none is; one sunk by less than
 * its radius is not either; a fragment truly under the ground (z = -0.5) is counted alone. */
static void forgotten_normal_is_below_ground(void) {
  fragsim_controller_id id = make();
  fragsim_camera_pose pose = fragsim_default_camera_pose();
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_fragment f[4];
  fragsim_vec3 forces[4];
  fragsim_step_stats stats;
  int i;
  pose.eye_m = v3(0.0, 0.0, 1.6);
  pose.right = v3(-1.0, 0.0, 0.0);
  pose.up = v3(0.0, 0.0, 1.0);
  pose.forward = v3(0.0, -1.0, 0.0);
  in.gravity_mps2 = v3(0.0, 0.0, -9.81);
  in.ground_height_m = 0.0;
  in.camera_poses = &pose;
  in.camera_count = 1;
  for (i = 0; i < 4; ++i) {
    f[i] = fragsim_default_fragment();
    f[i].position_m = v3(0.5 * (i - 1), -6.0, 1.6); /* the second at the lens */
    f[i].velocity_mps = v3(0.0, 12.0, 2.45);
    f[i].radius_m = 0.05;
    f[i].mass_kg = 0.5;
    f[i].id = (uint64_t)(10 + i);
  }
  f[0].position_m.y = 3.0; /* behind the camera: y > 0, above the y-up ground */
  f[0].velocity_mps.y = -1.0;
  CHECK(fragsim_controller_step(id, &in, f, 4, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.below_ground == 3);
  CHECK(stats.first_below_ground == 1);
  CHECK((stats.warnings & FRAGSIM_WARNING_BELOW_GROUND) != 0);
  in.ground_normal = v3(0.0, 0.0, 1.0);
  CHECK(fragsim_controller_step(id, &in, f, 4, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.below_ground == 0 && stats.first_below_ground == -1);
  CHECK((stats.warnings & FRAGSIM_WARNING_BELOW_GROUND) == 0);
  CHECK(!is_zero(forces[1])); /* the one at the lens is pushed in the z-up frame */
  f[3].position_m.z = -0.04;  /* sunk by less than its radius: an engine's contact, not counted */
  CHECK(fragsim_controller_step(id, &in, f, 4, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.below_ground == 0 && stats.first_below_ground == -1);
  f[3].position_m.z = -0.5;
  CHECK(fragsim_controller_step(id, &in, f, 4, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.below_ground == 1 && stats.first_below_ground == 3);
  CHECK((stats.warnings & FRAGSIM_WARNING_BELOW_GROUND) != 0);
  fragsim_controller_destroy(id);
}

static void warnings_are_raised(void) {
  fragsim_controller_id id = make();
  fragsim_camera_def cam = fragsim_default_camera_def();
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_step_stats stats;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == 0);
  pose.velocity_mps = v3(0.0, 0.0, -3.0); /* exactly max_speed_mps */
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == 0);
  pose.velocity_mps = v3(0.0, 0.0, -3.1);
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == FRAGSIM_WARNING_CAMERA_OVER_SPEED);
  pose.velocity_mps = v3(0.0, 0.0, 0.0);
  cam.fovy_deg = 4.9;
  CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == FRAGSIM_WARNING_FOVY_IN_RADIANS);
  cam.fovy_deg = 5.0;
  CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == 0);
  /* The bits are distinct. */
  CHECK((FRAGSIM_WARNING_CAMERA_OVER_SPEED & FRAGSIM_WARNING_FOVY_IN_RADIANS) == 0);
  CHECK(((FRAGSIM_WARNING_CAMERA_OVER_SPEED | FRAGSIM_WARNING_FOVY_IN_RADIANS) &
         (FRAGSIM_WARNING_BELOW_GROUND | FRAGSIM_WARNING_UNPROTECTED | FRAGSIM_WARNING_SKIPPED)) ==
        0);
  CHECK((FRAGSIM_WARNING_BELOW_GROUND & (FRAGSIM_WARNING_UNPROTECTED | FRAGSIM_WARNING_SKIPPED)) ==
        0);
  CHECK((FRAGSIM_WARNING_UNPROTECTED & FRAGSIM_WARNING_SKIPPED) == 0);
  fragsim_controller_destroy(id);
}

/* Special values: UNDECLARED, INFINITY and 0 bounds accepted; INFINITY end; -INFINITY ground. A
 * camera that cannot move (max_speed_mps 0) or turn (0) is legal; a fragment of mass 0 gets no
 * force (massless_threat_is_unprotected). */
static void special_values_have_one_meaning(void) {
  const double ok[] = {FRAGSIM_UNDECLARED, 0.0, 2.5, INFINITY};
  fragsim_controller_id id = make();
  fragsim_camera_def cam = fragsim_default_camera_def();
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force;
  size_t k;
  for (k = 0; k < sizeof ok / sizeof ok[0]; ++k) {
    cam.max_accel_mps2 = ok[k];
    cam.max_turn_degps = ok[k];
    cam.max_speed_mps = k == 1 ? 0.0 : 3.0;
    CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_OK);
    CHECK(fragsim_controller_step(id, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
    CHECK(is_finite3(force) && !is_zero(force));
  }
  cam.max_accel_mps2 = -INFINITY;
  CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  cam.max_accel_mps2 = -1.0000001;
  CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  in.ground_height_m = -INFINITY;
  in.end_time_s = INFINITY;
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
  in.ground_height_m = INFINITY;
  CHECK(fragsim_controller_step(id, &in, &f, 1, &force, NULL) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "ground_height_m = inf"));
  fragsim_controller_destroy(id);
}

/* Every kind of refusal this program can provoke names the value refused. */
static void refusals_name_values(void) {
  fragsim_controller_id id = make();
  fragsim_controller_def def;
  fragsim_controller_id other;
  fragsim_camera_def cam = fragsim_default_camera_def();
  fragsim_camera_pose three[3];
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment f[2];
  fragsim_vec3 forces[2];
  fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  char message[256];
  const char* e;
  f[0] = aimed(1, 0.0);
  f[1] = aimed(2, 0.0);
#define REFUSED(call, status, text)                                         \
  do {                                                                      \
    CHECK((call) == (status));                                              \
    e = fragsim_controller_last_error(id);                                  \
    CHECK(e != NULL && contains(e, text));                                  \
    if (e != NULL && !contains(e, text)) fprintf(stderr, "  got: %s\n", e); \
  } while (0)
  /* Counts. */
  REFUSED(fragsim_controller_step(id, &in, f, -5, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "fragment_count = -5");
  REFUSED(fragsim_controller_step_arrays(id, &in, &a, -6, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "fragment_count = -6");
  REFUSED(fragsim_controller_reserve(id, -3), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "fragment_count = -3");
  REFUSED(fragsim_controller_reserve(id, INT32_MIN), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "fragment_count = -2147483648");
  REFUSED(fragsim_controller_set_cameras(id, &cam, 9), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_count = 9");
  REFUSED(fragsim_controller_set_cameras(id, &cam, 0), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_count = 0");
  three[0] = three[1] = three[2] = eye_pose();
  in.camera_poses = three;
  in.camera_count = 3;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_count = 3: the controller has 1");
  in.camera_poses = &pose;
  in.camera_count = 0;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_count = 0");
  in.camera_count = 1;
  /* Numbers of the step input. */
  in.dt_s = -0.5;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "dt_s = -0.5");
  in.dt_s = 0.0;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "dt_s = 0");
  in.dt_s = 1.0 / 60.0;
  in.time_s = NAN;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "time_s = nan");
  in.time_s = 3.0;
  in.end_time_s = 2.5;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "end_time_s = 2.5");
  in.time_s = 0.0;
  in.end_time_s = INFINITY;
  in.gravity_mps2.z = INFINITY;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "gravity_mps2.z = inf");
  in.gravity_mps2.z = 0.0;
  in.ground_normal = v3(0.0, 1.5, 0.0);
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "ground_normal has length 1.5");
  in.ground_normal = v3(0.0, 1.0, 0.0);
  /* The pose. */
  pose.forward = v3(0.0, 0.1, -1.0);
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_poses[0].forward has length");
  pose.forward = v3(0.0, 0.0, -1.0);
  pose.velocity_mps.x = NAN;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "camera_poses[0].velocity_mps.x = nan");
  pose.velocity_mps.x = 0.0;
  /* The camera def. */
  cam.aspect = 1e-4;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].aspect = 0.0001");
  cam.aspect = 2e3;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].aspect = 2000");
  cam.aspect = 16.0 / 9.0;
  cam.fovy_deg = 180.0;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].fovy_deg = 180");
  cam.fovy_deg = 60.0;
  cam.near_m = -0.1;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].near_m = -0.1");
  cam.near_m = 0.1;
  cam.body_half_m.y = -0.2;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].body_half_m.y = -0.2");
  cam.body_half_m.y = 0.1;
  cam.max_speed_mps = -1.0;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].max_speed_mps = -1");
  cam.max_speed_mps = 3.0;
  cam.max_turn_degps = -7.0;
  REFUSED(fragsim_controller_set_cameras(id, &cam, 1), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "cameras[0].max_turn_degps = -7");
  cam.max_turn_degps = FRAGSIM_UNDECLARED;
  /* NULL pointers. */
  REFUSED(fragsim_controller_step(id, NULL, f, 2, forces, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "input: NULL");
  REFUSED(fragsim_controller_step(id, &in, NULL, 2, forces, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "fragments: NULL");
  REFUSED(fragsim_controller_step(id, &in, f, 2, NULL, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "forces_N: NULL");
  REFUSED(fragsim_controller_step_arrays(id, &in, NULL, 2, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "arrays: NULL");
  REFUSED(fragsim_controller_step_arrays(id, &in, &a, 2, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "arrays.position_m: NULL");
  REFUSED(fragsim_controller_set_cameras(id, NULL, 1), FRAGSIM_ERROR_NULL_ARGUMENT,
          "cameras: NULL");
  in.camera_poses = NULL;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_NULL_ARGUMENT,
          "camera_poses: NULL");
  in.camera_poses = &pose;
  /* The arrays. */
  a.position_m = &f[0].position_m.x;
  a.velocity_mps = &f[0].velocity_mps.x;
  a.radius_m = &f[0].radius_m;
  a.mass_kg = &f[0].mass_kg;
  a.id = &f[0].id;
  a.force_N = forces;
  a.position_stride_bytes = a.velocity_stride_bytes = a.radius_stride_bytes = sizeof f[0];
  a.mass_stride_bytes = a.id_stride_bytes = sizeof f[0];
  a.velocity_stride_bytes = 8;
  REFUSED(fragsim_controller_step_arrays(id, &in, &a, 2, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "arrays.velocity_stride_bytes = 8");
  a.velocity_stride_bytes = sizeof f[0];
  a.id_stride_bytes = 0;
  REFUSED(fragsim_controller_step_arrays(id, &in, &a, 2, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "arrays.id_stride_bytes = 0");
  a.id_stride_bytes = sizeof f[0];
  a.scalar_type = (fragsim_scalar_type)5;
  REFUSED(fragsim_controller_step_arrays(id, &in, &a, 2, NULL), FRAGSIM_ERROR_INVALID_ARGUMENT,
          "arrays.scalar_type = 5");
  a.scalar_type = FRAGSIM_SCALAR_DOUBLE;
  CHECK(fragsim_controller_step_arrays(id, &in, &a, 2, NULL) == FRAGSIM_OK);
  CHECK(strcmp(fragsim_controller_last_error(id), "") == 0);
  /* A duplicate id names it and both places. */
  f[1].id = 1;
  REFUSED(fragsim_controller_step(id, &in, f, 2, forces, NULL), FRAGSIM_ERROR_DUPLICATE_ID,
          "fragments[1].id = 1: the id of fragments[0] too");
  f[1].id = 2;
#undef REFUSED
  /* The def, through create's message. */
#define CREATE_REFUSED(field_change, status, text)                                       \
  do {                                                                                   \
    def = fragsim_default_controller_def();                                              \
    field_change;                                                                        \
    CHECK(fragsim_controller_create(&def, &other, message, sizeof message) == (status)); \
    CHECK(contains(message, text));                                                      \
    if (!contains(message, text)) fprintf(stderr, "  got: %s\n", message);               \
  } while (0)
  CREATE_REFUSED(def.worker_count = 65, FRAGSIM_ERROR_INVALID_ARGUMENT, "worker_count = 65");
  CREATE_REFUSED(def.worker_count = 0, FRAGSIM_ERROR_INVALID_ARGUMENT, "worker_count = 0");
  CREATE_REFUSED(def.horizon_cap_s = 3601.0, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "horizon_cap_s = 3601");
  CREATE_REFUSED(def.horizon_cap_s = 0.0, FRAGSIM_ERROR_INVALID_ARGUMENT, "horizon_cap_s = 0");
  CREATE_REFUSED(def.edge_min.a_max_mps2 = 2e9, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "edge_min.a_max_mps2 = 2");
  CREATE_REFUSED(def.edge_min.cover_max = 1.5, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "edge_min.cover_max = 1.5");
  CREATE_REFUSED(def.edge_min.cover_region = 0.0, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "edge_min.cover_region = 0");
  CREATE_REFUSED(def.edge_min.camera_turn_degps = 2e6, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "edge_min.camera_turn_degps = 2");
  CREATE_REFUSED(def.edge_min.max_solves = -1, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "edge_min.max_solves = -1");
  CREATE_REFUSED(def.edge_min.camera_model = (fragsim_camera_model)9,
                 FRAGSIM_ERROR_INVALID_ARGUMENT, "edge_min.camera_model = 9");
  CREATE_REFUSED(def.strategy = (fragsim_strategy)7, FRAGSIM_ERROR_INVALID_ARGUMENT,
                 "strategy = 7");
  CREATE_REFUSED((def.strategy = FRAGSIM_STRATEGY_EDGE, def.edge.k_Nms2 = -3.0),
                 FRAGSIM_ERROR_INVALID_ARGUMENT, "edge.k_Nms2 = -3");
  CREATE_REFUSED((def.strategy = FRAGSIM_STRATEGY_EDGE, def.edge.replan = (fragsim_edge_replan)4),
                 FRAGSIM_ERROR_INVALID_ARGUMENT, "edge.replan = 4");
  CREATE_REFUSED((def.strategy = FRAGSIM_STRATEGY_DEFLECT_ALL, def.deflect_all.range_m = -1.0),
                 FRAGSIM_ERROR_INVALID_ARGUMENT, "deflect_all.range_m = -1");
  CREATE_REFUSED(def.alloc_fn = hook_alloc, FRAGSIM_ERROR_INVALID_ARGUMENT, "free_fn: NULL");
  CREATE_REFUSED(def.free_fn = hook_free, FRAGSIM_ERROR_INVALID_ARGUMENT, "alloc_fn: NULL");
#undef CREATE_REFUSED
  CHECK(fragsim_controller_create(NULL, &other, message, sizeof message) ==
        FRAGSIM_ERROR_NULL_ARGUMENT);
  CHECK(contains(message, "def: NULL"));
  def = fragsim_default_controller_def();
  CHECK(fragsim_controller_create(&def, NULL, message, sizeof message) ==
        FRAGSIM_ERROR_NULL_ARGUMENT);
  CHECK(contains(message, "out_controller: NULL"));
  fragsim_controller_destroy(id);
}

/* Reference run: steps 0..n_steps-1 of the scene with `count(k)` fragments; forces per step. */
enum { kMaxN = 200, kSteps = 5 };
static int count_at(int k) {
  return k < 2 ? 20 : k == 2 ? kMaxN : 150;
}

static void run_step(fragsim_controller_id id, int k, fragsim_vec3* forces,
                     fragsim_step_stats* stats, fragsim_status expected) {
  static fragsim_fragment f[kMaxN];
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(k, &pose);
  scene(k, count_at(k), 100, f);
  CHECK(fragsim_controller_step(id, &in, f, count_at(k), forces, stats) == expected);
}

/* Forces and stats of a run, step by step. */
typedef struct Run {
  fragsim_vec3 forces[kSteps][kMaxN];
  fragsim_step_stats stats[kSteps];
} Run;

static void reference_run(const fragsim_controller_def* def, Run* r) {
  fragsim_controller_id id = make_def(def);
  int k;
  memset(r, 0, sizeof *r);
  for (k = 0; k < kSteps; ++k) run_step(id, k, r->forces[k], &r->stats[k], FRAGSIM_OK);
  fragsim_controller_destroy(id);
}

/* A refused call of each kind between steps 1 and 2 zeroes the forces and the stats and changes
 * nothing: steps 2.. give the reference's forces and stats, bit for bit. */
static void refused_calls_change_nothing(void) {
  static Run ref, got;
  const fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  fragsim_camera_pose pose = eye_pose();
  fragsim_camera_pose two[2];
  fragsim_camera_def cams[2];
  fragsim_fragment f[3];
  fragsim_vec3 forces[3];
  double array_forces[9];
  fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  fragsim_step_stats stats;
  fragsim_step_input in;
  int kind, k, pushed = 0;
  reference_run(&def, &ref);
  for (k = 0; k < kSteps; ++k) pushed += ref.stats[k].pushed;
  CHECK(pushed > 5);
  for (kind = 0; kind < 12; ++kind) {
    fragsim_status s = FRAGSIM_OK;
    id = make_def(&def);
    memset(&got, 0, sizeof got);
    run_step(id, 0, got.forces[0], &got.stats[0], FRAGSIM_OK);
    run_step(id, 1, got.forces[1], &got.stats[1], FRAGSIM_OK);
    in = input_for(2, &pose);
    scene(1, 3, 100, f); /* known ids: a refusal must not forget or replace their state */
    f[2].id = 5000;      /* and a new one: it must not be remembered */
    forces[0] = forces[1] = forces[2] = v3(7.0, 7.0, 7.0);
    memset(&stats, 0x55, sizeof stats);
    cams[0] = cams[1] = fragsim_default_camera_def();
    switch (kind) {
      case 0:
        in.dt_s = -1.0;
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        break;
      case 1:
        f[1].id = f[0].id;
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        break;
      case 2:
        two[0] = two[1] = pose;
        in.camera_poses = two;
        in.camera_count = 2;
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        break;
      case 3:
        pose.right.x = 2.0;
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        pose = eye_pose();
        break;
      case 4:
        s = fragsim_controller_step(id, &in, NULL, 3, forces, &stats);
        break;
      case 5:
        in.ground_normal = v3(0.0, 0.0, 0.0);
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        break;
      case 6:
        cams[1].near_m = 0.0; /* a refused change of count and constants */
        s = fragsim_controller_set_cameras(id, cams, 2);
        break;
      case 7:
        s = fragsim_controller_reserve(id, -1);
        break;
      case 8:
        s = fragsim_controller_step(id, &in, f, -1, forces, &stats);
        break;
      case 9: /* the arrays call: a stride too small, the force layout known */
        a.position_m = &f[0].position_m.x;
        a.velocity_mps = &f[0].velocity_mps.x;
        a.radius_m = &f[0].radius_m;
        a.mass_kg = &f[0].mass_kg;
        a.id = &f[0].id;
        a.force_N = array_forces;
        a.position_stride_bytes = a.velocity_stride_bytes = sizeof f[0];
        a.radius_stride_bytes = a.mass_stride_bytes = a.id_stride_bytes = sizeof f[0];
        a.mass_stride_bytes = 4;
        for (k = 0; k < 9; ++k) array_forces[k] = 7.0;
        s = fragsim_controller_step_arrays(id, &in, &a, 3, &stats);
        for (k = 0; k < 9; ++k) CHECK(array_forces[k] == 0.0);
        break;
      case 10: /* the arrays call with a bad scalar_type: the force layout unknown */
        a.mass_stride_bytes = sizeof f[0];
        a.scalar_type = (fragsim_scalar_type)3;
        for (k = 0; k < 9; ++k) array_forces[k] = 7.0;
        s = fragsim_controller_step_arrays(id, &in, &a, 3, &stats);
        for (k = 0; k < 9; ++k) CHECK(array_forces[k] == 7.0); /* left alone */
        a.scalar_type = FRAGSIM_SCALAR_DOUBLE;
        break;
      case 11:
        in.end_time_s = in.time_s;
        s = fragsim_controller_step(id, &in, f, 3, forces, &stats);
        break;
    }
    CHECK(s != FRAGSIM_OK && s != FRAGSIM_ERROR_INTERNAL);
    CHECK(strlen(fragsim_controller_last_error(id)) > 0);
    if (kind <= 5 || kind == 11) {
      CHECK(is_zero(forces[0]) && is_zero(forces[1]) && is_zero(forces[2]));
    }
    if (kind != 6 && kind != 7) CHECK(stats_are_zero(&stats));
    for (k = 2; k < kSteps; ++k) run_step(id, k, got.forces[k], &got.stats[k], FRAGSIM_OK);
    CHECK(memcmp(got.forces, ref.forces, sizeof ref.forces) == 0);
    CHECK(memcmp(got.stats, ref.stats, sizeof ref.stats) == 0);
    if (memcmp(got.forces, ref.forces, sizeof ref.forces) != 0) {
      fprintf(stderr, "  refused call of kind %d changed the controller\n", kind);
    }
    fragsim_controller_destroy(id);
  }
}

/* OUT_OF_MEMORY: "the controller's state is as it was before the call", except inside the
 * occlusion bound's step, which forgets every fragment and says so. Step 2 grows the controller
 * (200 new fragments after 20); its k-th allocation fails, for each k until the step needs no more
 * than k - 1: the step is refused with zeros, and retried it and the next steps give the
 * reference's forces and stats, bit for bit, or (the occlusion bound, cover_max 0.5) the message
 * says every fragment was forgotten and the retried step sees every id new. */
static void failed_allocations_leave_the_controller(void) {
  static Run ref, got;
  int config;
  for (config = 0; config < 2; ++config) {
    fragsim_controller_def def = hooked_def();
    long fail_at;
    int failures_seen = 0, changed = 0;
    char why[512];
    if (config == 1) def.edge_min.cover_max = 0.5;
    hook_reset();
    reference_run(&def, &ref);
    for (fail_at = 1; fail_at < 10000; ++fail_at) {
      fragsim_controller_id id = make_def(&def);
      fragsim_step_stats stats;
      fragsim_status s;
      int k;
      static fragsim_fragment f[kMaxN];
      fragsim_camera_pose pose = eye_pose();
      fragsim_step_input in = input_for(2, &pose);
      memset(&got, 0, sizeof got);
      run_step(id, 0, got.forces[0], &got.stats[0], FRAGSIM_OK);
      run_step(id, 1, got.forces[1], &got.stats[1], FRAGSIM_OK);
      scene(2, count_at(2), 100, f);
      for (k = 0; k < count_at(2); ++k) got.forces[2][k] = v3(7.0, 7.0, 7.0);
      g_hook.fail_at = fail_at;
      s = fragsim_controller_step(id, &in, f, count_at(2), got.forces[2], &stats);
      g_hook.fail_at = 0;
      if (s == FRAGSIM_OK) {
        fragsim_controller_destroy(id);
        break;
      }
      ++failures_seen;
      snprintf(why, sizeof why, "%s", fragsim_controller_last_error(id));
      CHECK(s == FRAGSIM_ERROR_OUT_OF_MEMORY);
      CHECK(stats_are_zero(&stats));
      for (k = 0; k < count_at(2); ++k) CHECK(is_zero(got.forces[2][k]));
      for (k = 2; k < kSteps; ++k) run_step(id, k, got.forces[k], &got.stats[k], FRAGSIM_OK);
      if (strstr(why, "every fragment was forgotten") != NULL) {
        /* The one failure the header says cannot be undone: inside the occlusion bound's step
         * (cover_max < 1), which allocates as it steps. The controller then forgot every
         * fragment, as after fragsim_controller_reset: the retried step sees every id new. */
        CHECK(config == 1);
        CHECK(got.stats[2].new_ids == count_at(2));
        ++changed;
      } else {
        CHECK(memcmp(got.forces, ref.forces, sizeof ref.forces) == 0);
        CHECK(memcmp(got.stats, ref.stats, sizeof ref.stats) == 0);
      }
      fragsim_controller_destroy(id);
    }
    printf(
        "failed allocations, config %d: %d allocations of step 2 failed in turn, %d forgot every "
        "fragment (as documented), the others left the controller as it was\n",
        config, failures_seen, changed);
    CHECK(failures_seen > 0);
    if (config == 0) CHECK(changed == 0);
    CHECK(g_hook.live == 0 && g_hook.bad_free == 0);
  }
  /* set_cameras and reserve under a failing allocator keep the controller as it was. */
  {
    fragsim_controller_def def = hooked_def();
    fragsim_controller_id id;
    fragsim_camera_def cams[3];
    static fragsim_vec3 forces[kMaxN];
    fragsim_step_stats stats;
    long fail_at;
    hook_reset();
    reference_run(&def, &ref);
    cams[0] = cams[1] = cams[2] = fragsim_default_camera_def();
    for (fail_at = 1; fail_at < 1000; ++fail_at) {
      fragsim_status s, s2;
      id = make_def(&def);
      run_step(id, 0, forces, &stats, FRAGSIM_OK);
      run_step(id, 1, forces, &stats, FRAGSIM_OK);
      g_hook.fail_at = fail_at;
      s = fragsim_controller_set_cameras(id, cams, 3);
      if (s == FRAGSIM_OK) {
        g_hook.fail_at = 0;
        fragsim_controller_destroy(id);
        break;
      }
      g_hook.fail_at = fail_at; /* reserve too: refused or done, the next step is the same */
      s2 = fragsim_controller_reserve(id, 100000);
      g_hook.fail_at = 0;
      CHECK(s2 == FRAGSIM_ERROR_OUT_OF_MEMORY || s2 == FRAGSIM_OK);
      CHECK(s == FRAGSIM_ERROR_OUT_OF_MEMORY);
      run_step(id, 2, forces, &stats, FRAGSIM_OK); /* still one camera */
      CHECK(memcmp(forces, ref.forces[2], sizeof forces) == 0);
      CHECK(memcmp(&stats, &ref.stats[2], sizeof stats) == 0);
      fragsim_controller_destroy(id);
    }
    CHECK(fail_at > 1);
    CHECK(g_hook.live == 0 && g_hook.bad_free == 0);
  }
  /* create under a failing allocator: the null id, nothing left allocated. */
  {
    fragsim_controller_def def = hooked_def();
    fragsim_controller_id id;
    char message[256];
    hook_reset();
    g_hook.fail_at = 1;
    CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
          FRAGSIM_ERROR_OUT_OF_MEMORY);
    g_hook.fail_at = 0;
    CHECK(fragsim_controller_id_is_null(id));
    CHECK(contains(message, "out of memory"));
    CHECK(g_hook.live == 0);
  }
}

/* Every allocation goes through the hook with the user pointer as given, alignments are powers
 * of two and respected, each free matches its allocation, and destroy frees everything. */
static void allocator_hook_is_used_exactly(void) {
  fragsim_controller_def def = hooked_def();
  fragsim_controller_id id;
  static fragsim_vec3 forces[kMaxN];
  fragsim_camera_def cams[2];
  fragsim_step_stats stats;
  int k;
  hook_reset();
  id = make_def(&def);
  CHECK(g_hook.calls > 0); /* the controller itself */
  for (k = 0; k < kSteps; ++k) run_step(id, k, forces, &stats, FRAGSIM_OK);
  cams[0] = cams[1] = fragsim_default_camera_def();
  CHECK(fragsim_controller_set_cameras(id, cams, 2) == FRAGSIM_OK);
  CHECK(fragsim_controller_reserve(id, 5000) == FRAGSIM_OK);
  CHECK(g_hook.live > 0);
  CHECK(fragsim_controller_destroy(id) == FRAGSIM_OK);
  CHECK(g_hook.live == 0 && g_hook.bytes == 0);
  CHECK(g_hook.bad_free == 0 && g_hook.bad_align == 0 && g_hook.bad_user == 0);
  CHECK(g_hook.overflowed == 0);
  printf("allocator hook: %ld allocations, peak %lu bytes\n", g_hook.calls,
         (unsigned long)g_hook.peak);
}

/* reserve(n), then a step of at most n fragments (every id new) allocates nothing; reset
 * allocates nothing and keeps the room: the explosion's step after it allocates nothing either,
 * and every id is new. */
static void reserve_and_reset_allocate_as_promised(void) {
  fragsim_controller_def def = hooked_def();
  fragsim_controller_id id;
  static fragsim_fragment f[kMaxN];
  static fragsim_vec3 forces[kMaxN];
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_step_stats stats;
  long before;
  int config;
  for (config = 0; config < 2; ++config) {
    hook_reset();
    if (config == 1) def.strategy = FRAGSIM_STRATEGY_EDGE;
    id = make_def(&def);
    CHECK(fragsim_controller_reserve(id, kMaxN) == FRAGSIM_OK);
    scene(0, kMaxN, 1, f);
    before = g_hook.calls;
    CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
    CHECK(g_hook.calls == before);
    CHECK(stats.new_ids == kMaxN && stats.pushed > 0);
    scene(1, kMaxN, 1, f);
    in.time_s = 1.0 / 60.0;
    CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
    CHECK(g_hook.calls == before);
    CHECK(stats.new_ids == 0);
    CHECK(fragsim_controller_reset(id) == FRAGSIM_OK);
    CHECK(g_hook.calls == before);
    scene(0, kMaxN, 50000, f); /* a new explosion: other ids */
    CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
    CHECK(g_hook.calls == before);
    CHECK(stats.new_ids == kMaxN && stats.dropped_ids == 0);
    fragsim_controller_destroy(id);
  }
}

/* The occlusion bound (cover_max < 1) at the extreme aspects 1e-3 and 1e3: a blast of 200
 * fragments steps OK for 10 steps in bounded memory, peak live bytes under 64 MB; 1e-4 and 1e4
 * are refused, naming the value. */
static void occlusion_bound_at_extreme_aspects(void) {
  const double aspects[3] = {1e-3, 1e3, 16.0 / 9.0};
  const size_t bound_bytes = (size_t)64 << 20;
  int a, k;
  for (a = 0; a < 3; ++a) {
    fragsim_controller_def def = hooked_def();
    fragsim_controller_id id;
    fragsim_camera_def cam = fragsim_default_camera_def();
    static fragsim_fragment f[kMaxN];
    static fragsim_vec3 forces[kMaxN];
    fragsim_camera_pose pose = eye_pose();
    fragsim_step_stats stats;
    int nonfinite = 0, i;
    def.edge_min.cover_max = 0.2;
    hook_reset();
    id = create_or_fail(&def);
    cam.aspect = aspects[a];
    CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_OK);
    for (k = 0; k < 10; ++k) {
      fragsim_step_input in = input_for(k, &pose);
      scene(k, kMaxN, 1, f);
      for (i = 0; i < kMaxN; ++i) f[i].radius_m = 0.3; /* large: they cover the view */
      CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
      for (i = 0; i < kMaxN; ++i) nonfinite += !is_finite3(forces[i]);
    }
    CHECK(nonfinite == 0);
    CHECK(g_hook.peak < bound_bytes);
    printf("occlusion bound, aspect %g: peak %.2f MB\n", aspects[a], g_hook.peak / 1048576.0);
    cam.aspect = a == 0 ? 1e-4 : 1e4;
    CHECK(fragsim_controller_set_cameras(id, &cam, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(fragsim_controller_last_error(id),
                   a == 0 ? "cameras[0].aspect = 0.0001" : "cameras[0].aspect = 10000"));
    fragsim_controller_destroy(id);
    CHECK(g_hook.live == 0);
  }
}

/* A refused set_cameras keeps the cameras as they were: the next step, with the old count of
 * poses, gives the forces of a controller never sent the refused set. */
static void set_cameras_refusal_keeps_cameras(void) {
  static Run ref;
  static fragsim_vec3 forces[kMaxN];
  fragsim_step_stats stats;
  const fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  fragsim_camera_def cams[2];
  fragsim_camera_pose poses[2];
  fragsim_step_input in;
  static fragsim_fragment f[kMaxN];
  reference_run(&def, &ref);
  id = make_def(&def);
  run_step(id, 0, forces, &stats, FRAGSIM_OK);
  run_step(id, 1, forces, &stats, FRAGSIM_OK);
  cams[0] = fragsim_default_camera_def();
  cams[0].fovy_deg = 90.0; /* a valid change ... */
  cams[1] = fragsim_default_camera_def();
  cams[1].far_m = 0.01; /* ... refused with the invalid second camera */
  CHECK(fragsim_controller_set_cameras(id, cams, 2) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "cameras[1].far_m = 0.01"));
  CHECK(fragsim_controller_set_cameras(id, cams, 1) == FRAGSIM_OK); /* the valid one alone */
  CHECK(fragsim_controller_set_cameras(id, &cams[1], 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  /* Now the 90-degree camera is set: a 2-pose step is refused, a 1-pose step taken. */
  poses[0] = poses[1] = eye_pose();
  in = input_for(2, &poses[0]);
  scene(2, count_at(2), 100, f);
  in.camera_count = 2;
  CHECK(fragsim_controller_step(id, &in, f, count_at(2), forces, &stats) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  in.camera_count = 1;
  CHECK(fragsim_controller_step(id, &in, f, count_at(2), forces, &stats) == FRAGSIM_OK);
  fragsim_controller_destroy(id);
  /* And with nothing valid in between, the original camera stays: the reference's bits. */
  id = make_def(&def);
  run_step(id, 0, forces, &stats, FRAGSIM_OK);
  run_step(id, 1, forces, &stats, FRAGSIM_OK);
  CHECK(fragsim_controller_set_cameras(id, cams, 2) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(fragsim_controller_set_cameras(id, &cams[1], 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  run_step(id, 2, forces, &stats, FRAGSIM_OK);
  CHECK(memcmp(forces, ref.forces[2], sizeof forces) == 0);
  CHECK(memcmp(&stats, &ref.stats[2], sizeof stats) == 0);
  fragsim_controller_destroy(id);
}

/* Ids come and go: an absent id is forgotten and new when it returns; a change of normal or of
 * camera count forgets every fragment; a change of camera constants does not. */
static void ids_come_and_go(void) {
  fragsim_controller_id id = make();
  fragsim_camera_def cams[2];
  fragsim_camera_pose poses[2];
  fragsim_step_input in;
  fragsim_fragment f[10];
  fragsim_vec3 forces[10];
  fragsim_step_stats stats;
  poses[0] = poses[1] = eye_pose();
  poses[1].eye_m.x = 0.064;
  cams[0] = cams[1] = fragsim_default_camera_def();
  in = input_for(0, poses);
  scene(0, 10, 1, f);
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 10 && stats.dropped_ids == 0);
  CHECK(fragsim_controller_step(id, &in, f, 6, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0 && stats.dropped_ids == 4);
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 4 && stats.dropped_ids == 0);
  cams[0].fovy_deg = 70.0;
  CHECK(fragsim_controller_set_cameras(id, cams, 1) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0);
  in.ground_normal = v3(0.0, 0.0, 1.0);
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 10 && stats.dropped_ids == 10);
  CHECK(fragsim_controller_set_cameras(id, cams, 2) == FRAGSIM_OK);
  in.camera_count = 2;
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 10);
  CHECK(fragsim_controller_step(id, &in, f, 10, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0);
  fragsim_controller_destroy(id);
}

/* stats.rejected_cheaply is 0 for edge and deflect-all; first_* are -1 with none; pushed counts
 * the nonzero forces and only threats get one. */
static void stats_mean_what_they_say(void) {
  const fragsim_strategy strategies[3] = {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE,
                                          FRAGSIM_STRATEGY_DEFLECT_ALL};
  int s, i;
  for (s = 0; s < 3; ++s) {
    fragsim_controller_def def = fragsim_default_controller_def();
    fragsim_controller_id id;
    fragsim_fragment f[kMaxN];
    fragsim_vec3 forces[kMaxN];
    fragsim_camera_pose pose = eye_pose();
    fragsim_step_input in = input_for(0, &pose);
    fragsim_step_stats stats;
    int nonzero = 0;
    def.strategy = strategies[s];
    id = make_def(&def);
    scene(0, kMaxN, 1, f);
    for (i = 0; i < kMaxN; i += 3) f[i].position_m.x += 30.0;   /* far to the side: no threat */
    for (i = 1; i < kMaxN; i += 3) f[i].velocity_mps.z = -12.0; /* flying away */
    CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
    for (i = 0; i < kMaxN; ++i) nonzero += !is_zero(forces[i]);
    CHECK(stats.pushed == nonzero);
    CHECK(nonzero == 0 || s == 2); /* nothing aimed at the lens now (deflect-all pushes near) */
    if (s != 0) CHECK(stats.rejected_cheaply == 0);
    CHECK(stats.first_skipped == -1 && stats.first_below_ground == -1);
    CHECK(stats.first_conflict == -1 && stats.conflicts == 0);
    scene(0, kMaxN, 1000, f); /* new ids, some near the lens (the first at it) */
    CHECK(fragsim_controller_step(id, &in, f, kMaxN, forces, &stats) == FRAGSIM_OK);
    nonzero = 0;
    for (i = 0; i < kMaxN; ++i) nonzero += !is_zero(forces[i]);
    CHECK(stats.pushed == nonzero);
    /* deflect-all pushes only within range_m (6 m): this scene starts at 6 m and beyond. */
    if (s != 2) CHECK(nonzero > 0 && !is_zero(forces[0]));
    if (s == 0) CHECK(stats.rejected_cheaply > 0 && stats.rejected_cheaply < kMaxN);
    if (s != 0) CHECK(stats.rejected_cheaply == 0);
    fragsim_controller_destroy(id);
  }
}

/* max_solves caps the exact solves per call; stats.deferred counts the others. */
static void solve_budget_defers(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  fragsim_fragment f[kMaxN];
  fragsim_vec3 forces[kMaxN];
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_step_stats stats;
  def.edge_min.max_solves = 3;
  id = make_def(&def);
  scene(0, 60, 1, f);
  CHECK(fragsim_controller_step(id, &in, f, 60, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.deferred > 0);
  CHECK(stats.pushed <= 3);
  fragsim_controller_destroy(id);
}

/* Def ranges at their ends are taken: a_max 0 and 1e9, turn 1e6, weights 0 (not all) and 1e6,
 * cover_max 0, cover_region 1, horizon_cap_s 3600. All four weights 0 is refused. */
static void def_ranges_are_kept(void) {
  fragsim_controller_def def;
  fragsim_controller_id id;
  char message[256];
  int k;
  def = fragsim_default_controller_def();
  def.edge_min.a_max_mps2 = 1e9;
  def.edge_min.camera_turn_degps = 1e6;
  def.edge_min.edge_weights[0] = 0.0;
  def.edge_min.edge_weights[3] = 1e6;
  def.edge_min.cover_max = 0.0;
  def.edge_min.cover_region = 1.0;
  def.horizon_cap_s = 3600.0;
  def.edge.a_max_mps2 = 0.0;
  def.deflect_all.accel_mps2 = 1e9;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) == FRAGSIM_OK);
  fragsim_controller_destroy(id);
  def = fragsim_default_controller_def();
  for (k = 0; k < 4; ++k) def.edge_min.edge_weights[k] = 0.0;
  CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(message, "edge_min.edge_weights"));
}

/* "Only differences of times are used": the same run 1000 s later gives the same forces. */
static void time_shift_changes_nothing(void) {
  static Run ref;
  const fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id = make_def(&def);
  static fragsim_fragment f[kMaxN];
  static fragsim_vec3 forces[kMaxN];
  fragsim_step_stats stats;
  fragsim_camera_pose pose = eye_pose();
  int k, i;
  double worst = 0.0;
  reference_run(&def, &ref);
  for (k = 0; k < kSteps; ++k) {
    fragsim_step_input in = input_for(k, &pose);
    in.time_s += 1024.0; /* a power of two: the steps' differences are unchanged, exactly */
    scene(k, count_at(k), 100, f);
    CHECK(fragsim_controller_step(id, &in, f, count_at(k), forces, &stats) == FRAGSIM_OK);
    for (i = 0; i < count_at(k); ++i) {
      const double d = fabs(forces[i].x - ref.forces[k][i].x) +
                       fabs(forces[i].y - ref.forces[k][i].y) +
                       fabs(forces[i].z - ref.forces[k][i].z);
      if (d > worst) worst = d;
    }
    CHECK(stats.pushed == ref.stats[k].pushed);
  }
  /* Tolerance: 1e-9 N on forces of at most mass * a_max = 2.2 kg * 50 m/s^2 (1e-11 relative). */
  CHECK(worst <= 1e-9);
  printf("time shift: worst force difference %.3g N\n", worst);
  fragsim_controller_destroy(id);
}

/* The float path is the double path rounded: forces are the double forces rounded to float. */
static void float_arrays_round_the_double_forces(void) {
  fragsim_controller_id d = make(), fl = make();
  fragsim_fragment f[30];
  fragsim_vec3 expected[30];
  float pos[30][3], vel[30][3], radius[30], mass[30], forces[30][3];
  uint64_t ids[30];
  fragsim_camera_pose pose = eye_pose();
  fragsim_step_input in = input_for(0, &pose);
  fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  int i, mismatches = 0;
  scene(0, 30, 1, f);
  for (i = 0; i < 30; ++i) { /* numbers exact in float: multiples of 1/1024 */
    f[i].position_m.x = floor(f[i].position_m.x * 1024.0) / 1024.0;
    f[i].position_m.y = floor(f[i].position_m.y * 1024.0) / 1024.0;
    f[i].position_m.z = floor(f[i].position_m.z * 1024.0) / 1024.0;
    f[i].velocity_mps.y = floor(f[i].velocity_mps.y * 1024.0) / 1024.0;
    f[i].radius_m = floor(f[i].radius_m * 1024.0) / 1024.0;
    f[i].mass_kg = floor(f[i].mass_kg * 1024.0) / 1024.0;
    pos[i][0] = (float)f[i].position_m.x;
    pos[i][1] = (float)f[i].position_m.y;
    pos[i][2] = (float)f[i].position_m.z;
    vel[i][0] = (float)f[i].velocity_mps.x;
    vel[i][1] = (float)f[i].velocity_mps.y;
    vel[i][2] = (float)f[i].velocity_mps.z;
    radius[i] = (float)f[i].radius_m;
    mass[i] = (float)f[i].mass_kg;
    ids[i] = f[i].id;
  }
  a.scalar_type = FRAGSIM_SCALAR_FLOAT;
  a.position_m = pos;
  a.position_stride_bytes = sizeof pos[0];
  a.velocity_mps = vel;
  a.velocity_stride_bytes = sizeof vel[0];
  a.radius_m = radius;
  a.radius_stride_bytes = sizeof(float);
  a.mass_kg = mass;
  a.mass_stride_bytes = sizeof(float);
  a.id = ids;
  a.force_N = forces;
  a.force_stride_bytes = sizeof forces[0];
  CHECK(fragsim_controller_step(d, &in, f, 30, expected, NULL) == FRAGSIM_OK);
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, 30, NULL) == FRAGSIM_OK);
  for (i = 0; i < 30; ++i) {
    mismatches += forces[i][0] != (float)expected[i].x || forces[i][1] != (float)expected[i].y ||
                  forces[i][2] != (float)expected[i].z;
  }
  CHECK(mismatches == 0);
  CHECK(!is_zero(expected[0]));
  fragsim_controller_destroy(d);
  fragsim_controller_destroy(fl);
}

/* ---- the game's task system, on the calling thread ---------------------------------------- */

typedef struct Tasks {
  int32_t split;    /* items per range (at least min_range) */
  int workers;      /* worker indices handed out in turn */
  int deferred;     /* 1: enqueue returns a handle and finish runs the ranges */
  int bad_context;  /* the user context not the one given */
  int32_t min_seen; /* the smallest min_range asked for */
  fragsim_task_fn* task;
  void* task_context;
  int32_t items;
  int32_t min_range;
} Tasks;

static void run_ranges(Tasks* t) {
  /* Ranges last to first, workers in turn: any order is legal. */
  const int32_t range = t->split > t->min_range ? t->split : t->min_range;
  int32_t start = ((t->items - 1) / range) * range;
  uint32_t worker = 0;
  for (; start >= 0; start -= range) {
    const int32_t end = start + range < t->items ? start + range : t->items;
    t->task(start, end, worker, t->task_context);
    worker = (worker + 1) % (uint32_t)t->workers;
  }
}

static void* enqueue(fragsim_task_fn* task, int32_t item_count, int32_t min_range,
                     void* task_context, void* user_context) {
  Tasks* t = (Tasks*)user_context;
  if (t == NULL) return NULL; /* cannot happen unless the context was lost: then nothing runs */
  t->task = task;
  t->task_context = task_context;
  t->items = item_count;
  t->min_range = min_range;
  if (min_range < t->min_seen) t->min_seen = min_range;
  if (t->deferred) return t;
  run_ranges(t);
  return NULL;
}

static void finish(void* user_task, void* user_context) {
  Tasks* t = (Tasks*)user_context;
  if (user_task != user_context) ++t->bad_context;
  run_ranges(t);
}

/* The forces and stats are the same, bit for bit, for any worker count and any split. */
static void task_system_gives_the_same_bits(void) {
  static Run ref, got;
  const int workers[3] = {1, 3, FRAGSIM_MAX_WORKERS};
  const int32_t splits[3] = {1, 7, 1000};
  fragsim_controller_def base = fragsim_default_controller_def();
  int config, w, sp, k;
  for (config = 0; config < 3; ++config) {
    base = fragsim_default_controller_def();
    if (config == 1) base.strategy = FRAGSIM_STRATEGY_EDGE;
    if (config == 2) base.edge_min.cover_max = 0.5;
    reference_run(&base, &ref);
    for (w = 0; w < 3; ++w) {
      for (sp = 0; sp < 3; ++sp) {
        Tasks t;
        fragsim_controller_def def = base;
        fragsim_controller_id id;
        memset(&t, 0, sizeof t);
        t.split = splits[sp];
        t.workers = workers[w];
        t.deferred = sp == 1;
        t.min_seen = INT32_MAX;
        def.enqueue_task = enqueue;
        def.finish_task = finish;
        def.user_task_context = &t;
        def.worker_count = workers[w];
        id = make_def(&def);
        memset(&got, 0, sizeof got);
        for (k = 0; k < kSteps; ++k) run_step(id, k, got.forces[k], &got.stats[k], FRAGSIM_OK);
        CHECK(memcmp(got.forces, ref.forces, sizeof ref.forces) == 0);
        CHECK(memcmp(got.stats, ref.stats, sizeof ref.stats) == 0);
        CHECK(t.bad_context == 0);
        CHECK(t.min_seen >= 1);
        fragsim_controller_destroy(id);
      }
    }
  }
  {
    fragsim_controller_def def = fragsim_default_controller_def();
    fragsim_controller_id id;
    char message[256];
    def.enqueue_task = enqueue;
    CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
          FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(message, "finish_task: NULL"));
    def.enqueue_task = NULL;
    def.finish_task = finish;
    CHECK(fragsim_controller_create(&def, &id, message, sizeof message) ==
          FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(message, "enqueue_task: NULL"));
  }
}

int main(void) {
  version_is_the_headers();
  defaults_are_documented();
  limits_are_the_headers();
  id_is_null_says_only_null();
  stale_ids_are_refused();
  create_failure_message();
  zero_initialised_structs_are_refused();
  masses_in_range_get_finite_nonzero_forces();
  masses_out_of_range_are_skipped();
  no_non_finite_output_on_wild_input();
  massless_threat_is_unprotected();
  forgotten_normal_is_below_ground();
  warnings_are_raised();
  special_values_have_one_meaning();
  refusals_name_values();
  refused_calls_change_nothing();
  failed_allocations_leave_the_controller();
  allocator_hook_is_used_exactly();
  reserve_and_reset_allocate_as_promised();
  occlusion_bound_at_extreme_aspects();
  set_cameras_refusal_keeps_cameras();
  ids_come_and_go();
  stats_mean_what_they_say();
  solve_budget_defers();
  def_ranges_are_kept();
  time_shift_changes_nothing();
  float_arrays_round_the_double_forces();
  task_system_gives_the_same_bits();
  return check_verdict("promises_test");
}
