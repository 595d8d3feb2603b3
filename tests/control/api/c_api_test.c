/* The C API's sharp edges, in C99 as a game sees them (fragsim/control.h only): what an
 * integrator gets wrong on the first day must fail loudly or work. Each check states its case; the
 * program prints every failed check and exits 1 if any failed. */
#include <fragsim/control.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

static int contains(const char* text, const char* part) {
  return strstr(text, part) != NULL;
}

/* A fragment 5 m ahead of the default camera (eye at the origin, looking down -z), flying at the
 * lens at 10 m/s, thrown up at 2.45 m/s so that gravity brings it back to the eye's height as it
 * arrives (0.5 s): without a push it hits the near plane. */
static fragsim_fragment aimed(uint64_t id, double x) {
  fragsim_fragment f = fragsim_default_fragment();
  f.position_m.x = x;
  f.position_m.y = 0.02;
  f.position_m.z = -5.0;
  f.velocity_mps.y = 2.45;
  f.velocity_mps.z = 10.0;
  f.radius_m = 0.05;
  f.mass_kg = 2.0;
  f.id = id;
  return f;
}

/* The one camera every step of this program passes: the default pose (at the origin, looking down
 * -z, still), changed in place by the tests that move it. */
static fragsim_camera_pose g_pose;

/* A controller with the default def and one camera of `camera`'s constants. */
static fragsim_controller_id make_with(const fragsim_camera_def* camera) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  CHECK(fragsim_controller_create(&def, &id, NULL, 0) == FRAGSIM_OK);
  CHECK(fragsim_controller_set_cameras(id, camera, 1) == FRAGSIM_OK);
  return id;
}

static fragsim_controller_id make(void) {
  const fragsim_camera_def camera = fragsim_default_camera_def();
  return make_with(&camera);
}

/* The default input with the one camera's pose. */
static fragsim_step_input input(void) {
  fragsim_step_input in = fragsim_default_step_input();
  g_pose = fragsim_default_camera_pose();
  in.camera_poses = &g_pose;
  in.camera_count = 1;
  return in;
}

static void default_step_input_is_usable(void) {
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_camera_def camera = fragsim_default_camera_def();
  CHECK(in.time_s == 0.0);
  CHECK(isinf(in.end_time_s) && in.end_time_s > 0);
  CHECK(fabs(in.dt_s - 1.0 / 60.0) < 1e-15);
  CHECK(in.gravity_mps2.x == 0.0 && in.gravity_mps2.y == -9.81 && in.gravity_mps2.z == 0.0);
  CHECK(isinf(in.ground_height_m) && in.ground_height_m < 0);
  CHECK(in.camera_poses == NULL && in.camera_count == 0);
  CHECK(camera.max_accel_mps2 == FRAGSIM_UNDECLARED);
  CHECK(camera.max_turn_degps == FRAGSIM_UNDECLARED);
  CHECK(camera.max_speed_mps == 3.0);
}

/* "= {0}" once said the shot had ended (end 0 at time 0): 2 of 2 aimed fragments hit, status OK.
 * Now it is refused, naming end_time_s and the way out; from the defaults the same fragments are
 * pushed. */
static void zero_initialised_input_is_refused(void) {
  fragsim_controller_id c = make();
  fragsim_fragment f[2];
  fragsim_vec3 forces[2];
  fragsim_step_input in;
  fragsim_step_stats stats;
  f[0] = aimed(1, 0.0);
  f[1] = aimed(2, 0.03);
  memset(&in, 0, sizeof in);
  g_pose = fragsim_default_camera_pose();
  in.camera_poses = &g_pose;
  in.camera_count = 1;
  in.dt_s = 1.0 / 60.0;
  CHECK(fragsim_controller_step(c, &in, f, 2, forces, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(c), "end_time_s = 0 is not after time_s = 0"));
  CHECK(contains(fragsim_controller_last_error(c), "fragsim_default_step_input"));
  in.time_s = 5.0; /* a cut-scene past its end: refused too */
  in.end_time_s = 5.0;
  CHECK(fragsim_controller_step(c, &in, f, 2, forces, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  in = input();
  CHECK(fragsim_controller_step(c, &in, f, 2, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.pushed == 2);
  CHECK(fragsim_controller_destroy(c) == FRAGSIM_OK);
}

/* A controller has no camera until set_cameras: a step before it is refused, saying so, and the
 * same step after it is taken. */
static void no_step_before_set_cameras(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_controller_id c;
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force = {7.0, 7.0, 7.0};
  fragsim_step_input in = input();
  fragsim_step_stats stats;
  CHECK(fragsim_controller_create(&def, &c, NULL, 0) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(c, &in, &f, 1, &force, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(c), "fragsim_controller_set_cameras"));
  CHECK(force.x == 0.0 && force.y == 0.0 && force.z == 0.0);
  CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(c, &in, &f, 1, &force, &stats) == FRAGSIM_OK);
  CHECK(stats.pushed == 1);
  fragsim_controller_destroy(c);
}

/* One meaning per special value: FRAGSIM_UNDECLARED is the def's assumption, 0 a zero bound,
 * INFINITY none; NaN and other negatives are refused. */
static void camera_bounds_have_one_meaning_each(void) {
  fragsim_controller_id c = make();
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force;
  fragsim_step_input in = input();
  fragsim_camera_def camera = fragsim_default_camera_def();
  const double ok[] = {FRAGSIM_UNDECLARED, 0.0, 2.5, INFINITY};
  const double bad[] = {-2.0, -0.5, NAN};
  size_t k;
  for (k = 0; k < sizeof ok / sizeof ok[0]; ++k) {
    camera.max_accel_mps2 = ok[k];
    camera.max_turn_degps = ok[k];
    CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_OK);
    CHECK(fragsim_controller_step(c, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
  }
  for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    camera.max_accel_mps2 = bad[k];
    camera.max_turn_degps = 1.0;
    CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(fragsim_controller_last_error(c), "cameras[0].max_accel_mps2"));
    CHECK(contains(fragsim_controller_last_error(c), "FRAGSIM_UNDECLARED"));
    camera.max_accel_mps2 = 1.0;
    camera.max_turn_degps = bad[k];
    CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(fragsim_controller_last_error(c), "cameras[0].max_turn_degps"));
  }
  fragsim_controller_destroy(c);
}

/* edge_min.camera_turn_degps: INFINITY (since 0.6 the default) means no turn bound and is
 * accepted; the aimed fragment is pushed under it as under 90 degrees a second. NaN and negatives
 * are refused, naming the field. */
static void turn_bound_may_be_infinite(void) {
  const double ok[] = {INFINITY, 90.0, 0.0};
  const double bad[] = {-1.0, NAN, -INFINITY};
  fragsim_fragment f = aimed(1, 0.0);
  fragsim_vec3 force;
  fragsim_step_input in = input();
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_controller_id c;
  char message[256];
  size_t k;
  CHECK(isinf(def.edge_min.camera_turn_degps) && def.edge_min.camera_turn_degps > 0);
  for (k = 0; k < sizeof ok / sizeof ok[0]; ++k) {
    def.edge_min.camera_turn_degps = ok[k];
    CHECK(fragsim_controller_create(&def, &c, NULL, 0) == FRAGSIM_OK);
    CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_OK);
    CHECK(fragsim_controller_step(c, &in, &f, 1, &force, NULL) == FRAGSIM_OK);
    CHECK(force.x != 0.0 || force.y != 0.0 || force.z != 0.0);
    fragsim_controller_destroy(c);
  }
  for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    def.edge_min.camera_turn_degps = bad[k];
    CHECK(fragsim_controller_create(&def, &c, message, sizeof message) ==
          FRAGSIM_ERROR_INVALID_ARGUMENT);
    CHECK(contains(message, "edge_min.camera_turn_degps"));
    CHECK(fragsim_controller_id_is_null(c));
  }
}

/* Box2D-style ids: a destroyed controller's id is refused with a status (also destroying twice),
 * and a new controller in the same slot does not answer to the old id. */
static void stale_ids_are_refused(void) {
  fragsim_controller_id a = make();
  fragsim_controller_id b;
  fragsim_controller_id null_id;
  fragsim_step_input in = input();
  fragsim_step_stats stats;
  const fragsim_camera_def camera = fragsim_default_camera_def();
  memset(&null_id, 0, sizeof null_id);
  CHECK(fragsim_controller_is_valid(a));
  CHECK(!fragsim_controller_id_is_null(a));
  CHECK(fragsim_controller_destroy(a) == FRAGSIM_OK);
  CHECK(!fragsim_controller_is_valid(a));
  CHECK(fragsim_controller_destroy(a) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_step(a, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_reset(a) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_reserve(a, 10) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_set_cameras(a, &camera, 1) == FRAGSIM_ERROR_STALE_ID);
  CHECK(contains(fragsim_controller_last_error(a), "stale"));
  b = make(); /* most likely a's slot again: a must still be stale */
  CHECK(fragsim_controller_is_valid(b));
  CHECK(!fragsim_controller_is_valid(a));
  CHECK(fragsim_controller_step(a, &in, NULL, 0, NULL, NULL) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_step(b, &in, NULL, 0, NULL, NULL) == FRAGSIM_OK);
  CHECK(fragsim_controller_destroy(null_id) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(null_id, &in, NULL, 0, NULL, NULL) == FRAGSIM_ERROR_STALE_ID);
  CHECK(fragsim_controller_destroy(b) == FRAGSIM_OK);
  CHECK(strcmp(fragsim_status_string(FRAGSIM_ERROR_STALE_ID), "stale controller id") == 0);
}

/* One bad fragment no longer zeroes the whole step: it is skipped and counted, and the others
 * get the forces they get without it. Since 1.0 a mass outside [FRAGSIM_MIN_MASS_KG,
 * FRAGSIM_MAX_MASS_KG] (besides 0) is skipped too, and the step says so in its warnings. */
static void bad_fragments_are_skipped_and_counted(void) {
  fragsim_controller_id clean = make();
  fragsim_controller_id dirty = make();
  fragsim_fragment good[2];
  fragsim_fragment mixed[6];
  fragsim_vec3 expected[2];
  fragsim_vec3 forces[6];
  fragsim_step_input in = input();
  fragsim_step_stats stats;
  int i;
  good[0] = aimed(10, 0.0);
  good[1] = aimed(11, 0.04);
  CHECK(fragsim_controller_step(clean, &in, good, 2, expected, NULL) == FRAGSIM_OK);
  CHECK(expected[0].y != 0.0 && expected[1].y != 0.0);
  mixed[0] = aimed(20, 0.0);
  mixed[0].position_m.y = NAN;
  mixed[1] = good[0];
  mixed[2] = aimed(21, 0.0);
  mixed[2].mass_kg = INFINITY; /* a static body as some engines hand it over */
  mixed[3] = good[1];
  mixed[4] = aimed(22, 0.0);
  mixed[4].mass_kg = -1.0;
  mixed[5] = aimed(23, 0.0);
  mixed[5].mass_kg = 1e30; /* finite, past FRAGSIM_MAX_MASS_KG */
  for (i = 0; i < 6; ++i) forces[i].x = forces[i].y = forces[i].z = 7.0;
  CHECK(fragsim_controller_step(dirty, &in, mixed, 6, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.skipped == 4);
  CHECK(stats.first_skipped == 0);
  CHECK(stats.pushed == 2);
  CHECK((stats.warnings & FRAGSIM_WARNING_SKIPPED) != 0);
  CHECK(memcmp(&forces[1], &expected[0], sizeof expected[0]) == 0);
  CHECK(memcmp(&forces[3], &expected[1], sizeof expected[1]) == 0);
  CHECK(forces[0].x == 0.0 && forces[0].y == 0.0 && forces[0].z == 0.0);
  CHECK(forces[2].x == 0.0 && forces[2].y == 0.0 && forces[2].z == 0.0);
  CHECK(forces[4].x == 0.0 && forces[4].y == 0.0 && forces[4].z == 0.0);
  CHECK(forces[5].x == 0.0 && forces[5].y == 0.0 && forces[5].z == 0.0);
  /* No bad fragment: first_skipped is -1, and no warning. */
  CHECK(fragsim_controller_step(dirty, &in, good, 2, expected, &stats) == FRAGSIM_OK);
  CHECK(stats.skipped == 0 && stats.first_skipped == -1);
  CHECK((stats.warnings & FRAGSIM_WARNING_SKIPPED) == 0);
  fragsim_controller_destroy(clean);
  fragsim_controller_destroy(dirty);
}

/* A mass-0 fragment aimed at the lens threatens and cannot be pushed: no force, not counted as
 * pushed (a zero force is not a push), counted as unprotected, and flagged. */
static void massless_threats_are_counted_unprotected(void) {
  fragsim_controller_id c = make();
  fragsim_fragment f[2];
  fragsim_vec3 forces[2];
  fragsim_step_input in = input();
  fragsim_step_stats stats;
  f[0] = aimed(1, 0.0);
  f[0].mass_kg = 0.0;
  f[1] = aimed(2, 0.03);
  CHECK(fragsim_controller_step(c, &in, f, 2, forces, &stats) == FRAGSIM_OK);
  CHECK(forces[0].x == 0.0 && forces[0].y == 0.0 && forces[0].z == 0.0);
  CHECK(forces[1].y != 0.0);
  CHECK(stats.candidates == 2);
  CHECK(stats.pushed == 1);
  CHECK(stats.unprotected == 1);
  CHECK(stats.warnings == FRAGSIM_WARNING_UNPROTECTED);
  fragsim_controller_destroy(c);
}

/* Unit mix-ups that can be seen are flagged: a camera at 50 m/s declaring 3 m/s, fovy in radians.
 * Each is still a valid step. */
static void likely_unit_mistakes_are_flagged(void) {
  fragsim_controller_id c = make();
  fragsim_step_input in = input();
  fragsim_step_stats stats;
  fragsim_camera_def camera = fragsim_default_camera_def();
  CHECK(fragsim_controller_step(c, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == 0);
  g_pose.velocity_mps.z = -3.0; /* exactly max_speed_mps: fine */
  CHECK(fragsim_controller_step(c, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == 0);
  g_pose.velocity_mps.z = -50.0;
  CHECK(fragsim_controller_step(c, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == FRAGSIM_WARNING_CAMERA_OVER_SPEED);
  camera.fovy_deg = 1.047; /* 60 degrees in radians */
  CHECK(fragsim_controller_set_cameras(c, &camera, 1) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(c, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  CHECK(stats.warnings == (FRAGSIM_WARNING_CAMERA_OVER_SPEED | FRAGSIM_WARNING_FOVY_IN_RADIANS));
  fragsim_controller_destroy(c);
}

/* Counts and limits: the largest count is in the header; a count past it is refused and, its
 * buffer's size unknown, the buffer is left alone; reserve takes the same range and names the
 * value it refuses. */
static void counts_and_reserve(void) {
  fragsim_controller_id c = make();
  fragsim_step_input in = input();
  fragsim_vec3 force;
  force.x = 7.0;
  CHECK(fragsim_controller_step(c, &in, NULL, FRAGSIM_MAX_FRAGMENTS + 1, &force, NULL) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(c), "fragment_count = 536870912"));
  CHECK(contains(fragsim_controller_last_error(c), "536870911"));
  CHECK(force.x == 7.0);
  CHECK(fragsim_controller_reserve(c, -1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(c), "fragment_count = -1"));
  CHECK(fragsim_controller_reserve(c, FRAGSIM_MAX_FRAGMENTS + 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(c), "fragment_count = 536870912"));
  CHECK(fragsim_controller_reserve(c, 20000) == FRAGSIM_OK);
  CHECK(strcmp(fragsim_controller_last_error(c), "") == 0);
  CHECK(fragsim_controller_reset(c) == FRAGSIM_OK);
  fragsim_controller_destroy(c);
}

/* The default edge-min never reads touched: the arrays call takes touched = NULL, and the
 * forces are those of the struct call. */
static void touched_may_be_null(void) {
  fragsim_controller_id a = make();
  fragsim_controller_id b = make();
  fragsim_fragment f = aimed(5, 0.0);
  fragsim_vec3 expected;
  double force[3] = {7, 7, 7};
  fragsim_fragment_arrays arrays = fragsim_default_fragment_arrays();
  fragsim_step_input in = input();
  CHECK(fragsim_controller_step(a, &in, &f, 1, &expected, NULL) == FRAGSIM_OK);
  arrays.position_m = &f.position_m.x;
  arrays.velocity_mps = &f.velocity_mps.x;
  arrays.radius_m = &f.radius_m;
  arrays.mass_kg = &f.mass_kg;
  arrays.id = &f.id;
  arrays.touched = NULL;
  arrays.force_N = force;
  CHECK(fragsim_controller_step_arrays(b, &in, &arrays, 1, NULL) == FRAGSIM_OK);
  CHECK(force[0] == expected.x && force[1] == expected.y && force[2] == expected.z);
  CHECK(expected.x != 0.0 || expected.y != 0.0 || expected.z != 0.0);
  fragsim_controller_destroy(a);
  fragsim_controller_destroy(b);
}

int main(void) {
  default_step_input_is_usable();
  zero_initialised_input_is_refused();
  no_step_before_set_cameras();
  camera_bounds_have_one_meaning_each();
  turn_bound_may_be_infinite();
  stale_ids_are_refused();
  bad_fragments_are_skipped_and_counted();
  massless_threats_are_counted_unprotected();
  likely_unit_mistakes_are_flagged();
  counts_and_reserve();
  touched_may_be_null();
  return check_verdict("c_api_test");
}
