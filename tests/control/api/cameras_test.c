/* Cameras set once and several cameras, in C99 as a game sees the API.
 *
 * - Set once: a controller given its camera's constants once by fragsim_controller_set_cameras
 *   and only poses per step returns the very forces (bit for bit) and stats of one given the same
 *   constants again before every step (the state kept per fragment survives a set of the same
 *   count), over a blast of 400 fragments and 150 steps.
 * - Refusals name the field: cameras[1].near_m, camera_poses[1].right, camera_count; a step before
 *   any set is refused, and a refused set keeps the cameras as they were.
 * - Two eyes of a headset, 6.4 cm apart, walking into a blast aimed between them: without forces
 *   some fragments touch an eye's near rectangle or the headset (the test can fail); with the
 *   controller's forces none touches either eye, and no conflict is reported.
 * - Two split-screen cameras facing each other 0.8 m apart, offset sideways so that each one's
 *   ways out of the picture cross the other's box, with a blast between them: conflicts are
 *   reported, and every force is finite.
 *
 * The world is integrated here as ODE and Bullet do (semi-implicit Euler: v += a dt, p += v dt);
 * a fragment "touches" a camera when its bounding sphere meets the near rectangle or the body box,
 * checked at 8 points along each step's segment (a fragment covers at most 0.25 m a step here). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "fragsim/control.h"

#define N_FRAGMENTS 400
#define N_STEPS 150

typedef struct {
  uint64_t state;
} rng;

static double uniform(rng* r) { /* in [0, 1): 53 bits of a 64-bit LCG (Knuth's MMIX) */
  r->state = r->state * 6364136223846793005ull + 1442695040888963407ull;
  return (double)(r->state >> 11) / 9007199254740992.0;
}

static fragsim_vec3 v3(double x, double y, double z) {
  fragsim_vec3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}
static fragsim_vec3 add(fragsim_vec3 a, fragsim_vec3 b) {
  return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static fragsim_vec3 sub(fragsim_vec3 a, fragsim_vec3 b) {
  return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static fragsim_vec3 scale(fragsim_vec3 a, double s) {
  return v3(a.x * s, a.y * s, a.z * s);
}
static double dot(fragsim_vec3 a, fragsim_vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* Distance from the point q (camera coordinates) to the box of half sizes h centred at c. */
static double box_distance(const double q[3], const double c[3], const double h[3]) {
  double d2 = 0.0;
  int k;
  for (k = 0; k < 3; ++k) {
    const double e = fabs(q[k] - c[k]) - h[k];
    if (e > 0.0) d2 += e * e;
  }
  return sqrt(d2);
}

/* A camera as this test moves it: its constants and its pose. */
typedef struct {
  fragsim_camera_def def;
  fragsim_camera_pose pose;
} camera;

/* Whether a sphere at p of radius r touches the camera's near rectangle or body. */
static int touches(const camera* c, fragsim_vec3 p, double r) {
  const fragsim_vec3 d = sub(p, c->pose.eye_m);
  /* Camera coordinates: x right, y up, z along the view. */
  const double q[3] = {dot(d, c->pose.right), dot(d, c->pose.up), dot(d, c->pose.forward)};
  const double half_h = c->def.near_m * tan(c->def.fovy_deg * 3.14159265358979323846 / 360.0);
  const double near_c[3] = {0.0, 0.0, c->def.near_m};
  const double near_h[3] = {half_h * c->def.aspect, half_h, 0.0};
  const double body_c[3] = {0.0, 0.0, 0.0};
  const double body_h[3] = {c->def.body_half_m.x, c->def.body_half_m.y, c->def.body_half_m.z};
  return box_distance(q, near_c, near_h) <= r || box_distance(q, body_c, body_h) <= r;
}

typedef struct {
  fragsim_fragment f[N_FRAGMENTS];
  fragsim_vec3 force_N[N_FRAGMENTS];
  int touched_any[N_FRAGMENTS]; /* the fragment touched some camera at some step */
} world;

/* A blast from `centre`, each fragment aimed at `target` (plus a spread of `spread_m` at the
 * target) at 7 to 12 m/s, lifted to cancel the fall over the distance. */
static void blast(world* w, fragsim_vec3 centre, fragsim_vec3 target, double spread_m,
                  uint64_t seed) {
  rng r;
  int i;
  r.state = seed;
  memset(w, 0, sizeof *w);
  for (i = 0; i < N_FRAGMENTS; ++i) {
    const fragsim_vec3 aim = add(target, v3(spread_m * (2.0 * uniform(&r) - 1.0),
                                            spread_m * (2.0 * uniform(&r) - 1.0), 0.0));
    const fragsim_vec3 d = sub(aim, centre);
    const double distance_m = sqrt(dot(d, d));
    const double speed_mps = 7.0 + 5.0 * uniform(&r);
    const double flight_s = distance_m / speed_mps;
    fragsim_vec3 v = scale(d, speed_mps / distance_m);
    v.y += 0.5 * 9.81 * flight_s;
    w->f[i].position_m = centre;
    w->f[i].velocity_mps = v;
    w->f[i].radius_m = 0.02 + 0.06 * uniform(&r);
    w->f[i].mass_kg = 0.05 + 0.45 * uniform(&r);
    w->f[i].id = (uint64_t)(1000 + i);
  }
}

/* One step of the world after the forces: semi-implicit Euler, and the touch check against each
 * camera along the step's segment. Returns the fragments touching some camera this step. */
static int advance(world* w, const camera* cams, int n_cams, double dt_s) {
  int i, s, k, hits = 0;
  for (i = 0; i < N_FRAGMENTS; ++i) {
    fragsim_fragment* f = &w->f[i];
    const fragsim_vec3 before = f->position_m;
    int hit = 0;
    const fragsim_vec3 a =
        add(v3(0.0, -9.81, 0.0),
            f->mass_kg > 0.0 ? scale(w->force_N[i], 1.0 / f->mass_kg) : v3(0.0, 0.0, 0.0));
    f->velocity_mps = add(f->velocity_mps, scale(a, dt_s));
    f->position_m = add(f->position_m, scale(f->velocity_mps, dt_s));
    for (s = 1; s <= 8 && !hit; ++s) {
      const fragsim_vec3 p = add(before, scale(sub(f->position_m, before), s / 8.0));
      for (k = 0; k < n_cams && !hit; ++k) hit = touches(&cams[k], p, f->radius_m);
    }
    if (hit) {
      ++hits;
      w->touched_any[i] = 1;
    }
  }
  return hits;
}

static int all_finite(const world* w) {
  int i;
  for (i = 0; i < N_FRAGMENTS; ++i) {
    if (!isfinite(w->force_N[i].x) || !isfinite(w->force_N[i].y) || !isfinite(w->force_N[i].z)) {
      return 0;
    }
  }
  return 1;
}

static camera camera_at(fragsim_vec3 eye, double facing_sign, fragsim_vec3 velocity) {
  camera c;
  c.def = fragsim_default_camera_def();
  c.pose = fragsim_default_camera_pose();
  c.pose.eye_m = eye;
  /* facing_sign +1: looking down -z; -1: looking down +z (turned about y). */
  c.pose.right = v3(facing_sign, 0.0, 0.0);
  c.pose.forward = v3(0.0, 0.0, -facing_sign);
  c.pose.velocity_mps = velocity;
  return c;
}

static fragsim_controller_id make_controller(void) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id id;
  CHECK(fragsim_controller_create(&def, &id, NULL, 0) == FRAGSIM_OK);
  return id;
}

/* The camera set once gives what the same constants set again before every step give, to the
 * bit: a set of the same count keeps the state kept per fragment. */
static void test_set_once_is_the_per_step_call(void) {
  static world a, b;
  const double dt_s = 1.0 / 60.0;
  fragsim_controller_id every = make_controller();
  fragsim_controller_id once = make_controller();
  fragsim_step_input in_every = fragsim_default_step_input();
  fragsim_step_input in_once = fragsim_default_step_input();
  camera cam = camera_at(v3(0.0, 1.6, 0.0), 1.0, v3(0.0, 0.0, -1.5));
  fragsim_camera_pose pose_every, pose_once;
  int step, differ = 0, pushed = 0;
  blast(&a, v3(0.0, 1.6, -8.0), v3(0.0, 1.6, 0.0), 0.4, 7);
  blast(&b, v3(0.0, 1.6, -8.0), v3(0.0, 1.6, 0.0), 0.4, 7);
  CHECK(fragsim_controller_set_cameras(once, &cam.def, 1) == FRAGSIM_OK);
  in_every.ground_height_m = in_once.ground_height_m = 0.0;
  in_every.camera_poses = &pose_every;
  in_once.camera_poses = &pose_once;
  in_every.camera_count = in_once.camera_count = 1;
  for (step = 0; step < N_STEPS; ++step) {
    fragsim_step_stats sa, sb;
    in_every.time_s = in_once.time_s = step * dt_s;
    pose_every = pose_once = cam.pose;
    CHECK(fragsim_controller_set_cameras(every, &cam.def, 1) == FRAGSIM_OK);
    CHECK(fragsim_controller_step(every, &in_every, a.f, N_FRAGMENTS, a.force_N, &sa) ==
          FRAGSIM_OK);
    CHECK(fragsim_controller_step(once, &in_once, b.f, N_FRAGMENTS, b.force_N, &sb) == FRAGSIM_OK);
    if (memcmp(a.force_N, b.force_N, sizeof a.force_N) != 0) ++differ;
    CHECK(sa.candidates == sb.candidates && sa.pushed == sb.pushed && sa.capped == sb.capped);
    CHECK(sa.new_ids == sb.new_ids && sa.dropped_ids == sb.dropped_ids);
    CHECK(sb.conflicts == 0 && sb.first_conflict == -1);
    pushed += sb.pushed;
    advance(&a, &cam, 1, dt_s);
    advance(&b, &cam, 1, dt_s);
    cam.pose.eye_m = add(cam.pose.eye_m, scale(cam.pose.velocity_mps, dt_s));
  }
  CHECK(differ == 0);
  CHECK(pushed > 0); /* the blast was a threat: the comparison compared forces */
  fragsim_controller_destroy(every);
  fragsim_controller_destroy(once);
}

static int contains(const char* text, const char* part) {
  return strstr(text, part) != NULL;
}

static void test_refusals_name_the_field(void) {
  fragsim_controller_id id = make_controller();
  fragsim_camera_def defs[2];
  fragsim_camera_pose poses[2];
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_step_stats stats;
  defs[0] = defs[1] = fragsim_default_camera_def();
  poses[0] = poses[1] = fragsim_default_camera_pose();
  CHECK(fragsim_controller_set_cameras(id, defs, 0) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(fragsim_controller_set_cameras(id, defs, FRAGSIM_MAX_CAMERAS + 1) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(fragsim_controller_set_cameras(id, NULL, 1) == FRAGSIM_ERROR_NULL_ARGUMENT);
  defs[1].near_m = 0.0;
  CHECK(fragsim_controller_set_cameras(id, defs, 2) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "cameras[1].near_m = 0"));
  defs[1].near_m = 0.1;
  defs[1].far_m = 0.05;
  CHECK(fragsim_controller_set_cameras(id, defs, 2) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id),
                 "cameras[1].far_m = 0.05: must be finite and > "
                 "cameras[1].near_m"));
  defs[1].far_m = 500.0;
  /* A refused set changed nothing: the controller still has no cameras. */
  in.camera_poses = poses;
  in.camera_count = 2;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "cameras: none set"));
  CHECK(fragsim_controller_set_cameras(id, defs, 2) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  in.camera_count = 1;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_count = 1: the controller has 2"));
  in.camera_count = -1;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_count = -1"));
  in.camera_count = 0; /* no longer a sentinel for a camera in the input: refused */
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_count = 0"));
  in.camera_count = 2;
  in.camera_poses = NULL;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_NULL_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_poses: NULL"));
  in.camera_poses = poses;
  poses[1].right = v3(1.0, 0.1, 0.0);
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_poses[1].right has length"));
  poses[1].right = v3(1.0, 0.0, 0.0);
  poses[0].eye_m.z = NAN;
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "camera_poses[0].eye_m.z = nan"));
  poses[0].eye_m.z = 0.0;
  /* A refused set keeps the two cameras: a step with two poses is still taken. */
  defs[0].aspect = 1e-4;
  CHECK(fragsim_controller_set_cameras(id, defs, 1) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(contains(fragsim_controller_last_error(id), "cameras[0].aspect = 0.0001"));
  CHECK(fragsim_controller_step(id, &in, NULL, 0, NULL, &stats) == FRAGSIM_OK);
  fragsim_controller_destroy(id);
  CHECK(fragsim_controller_set_cameras(id, defs, 1) == FRAGSIM_ERROR_STALE_ID);
}

/* A change of camera count forgets every fragment, as a reset does. */
static void test_camera_count_change_forgets(void) {
  fragsim_controller_id id = make_controller();
  fragsim_camera_def defs[2];
  fragsim_camera_pose poses[2];
  fragsim_fragment f[3];
  fragsim_vec3 forces[3];
  fragsim_step_input in = fragsim_default_step_input();
  fragsim_step_stats stats;
  int i;
  defs[0] = defs[1] = fragsim_default_camera_def();
  poses[0] = poses[1] = fragsim_default_camera_pose();
  poses[1].eye_m.x = 0.064;
  for (i = 0; i < 3; ++i) {
    f[i] = fragsim_default_fragment();
    f[i].position_m = v3(3.0 * i, 0.0, -20.0);
    f[i].radius_m = 0.1;
    f[i].mass_kg = 1.0;
    f[i].id = (uint64_t)(7 + i);
  }
  CHECK(fragsim_controller_set_cameras(id, defs, 1) == FRAGSIM_OK);
  in.camera_poses = poses;
  in.camera_count = 1;
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 3);
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0);
  CHECK(fragsim_controller_set_cameras(id, defs, 2) == FRAGSIM_OK);
  in.camera_count = 2;
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 3);
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0);
  /* New constants, same count: the state is kept. */
  defs[1].fovy_deg = 75.0;
  CHECK(fragsim_controller_set_cameras(id, defs, 2) == FRAGSIM_OK);
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 0);
  /* Back to one camera: every fragment forgotten again. */
  CHECK(fragsim_controller_set_cameras(id, defs, 1) == FRAGSIM_OK);
  in.camera_count = 1;
  CHECK(fragsim_controller_step(id, &in, f, 3, forces, &stats) == FRAGSIM_OK);
  CHECK(stats.new_ids == 3);
  fragsim_controller_destroy(id);
}

/* Runs a blast at n_cams cameras moving at `velocity`; returns the fragments that touched some
 * camera, and the conflicts reported over the run (*conflicts), the forces' finiteness (*finite)
 * and the fragments pushed at least once (*pushed). with_forces 0: the engine ignores the forces.
 */
static int run_blast(const camera* start, int n_cams, fragsim_vec3 centre, fragsim_vec3 target,
                     double spread_m, uint64_t seed, int with_forces, int* conflicts, int* finite,
                     int* pushed) {
  static world w;
  camera cams[2];
  fragsim_camera_def defs[2];
  fragsim_camera_pose poses[2];
  const double dt_s = 1.0 / 60.0;
  fragsim_controller_id id = make_controller();
  fragsim_step_input in = fragsim_default_step_input();
  int step, k, touched = 0, i;
  blast(&w, centre, target, spread_m, seed);
  for (k = 0; k < n_cams; ++k) {
    cams[k] = start[k];
    defs[k] = cams[k].def;
  }
  CHECK(fragsim_controller_set_cameras(id, defs, n_cams) == FRAGSIM_OK);
  in.ground_height_m = 0.0;
  in.camera_poses = poses;
  in.camera_count = n_cams;
  *conflicts = 0;
  *finite = 1;
  *pushed = 0;
  for (step = 0; step < N_STEPS; ++step) {
    fragsim_step_stats stats;
    in.time_s = step * (1.0 / 60.0);
    for (k = 0; k < n_cams; ++k) poses[k] = cams[k].pose;
    CHECK(fragsim_controller_step(id, &in, w.f, N_FRAGMENTS, w.force_N, &stats) == FRAGSIM_OK);
    *conflicts += stats.conflicts;
    *pushed += stats.pushed > 0;
    if (stats.conflicts > 0) CHECK(stats.first_conflict >= 0 && stats.first_conflict < N_FRAGMENTS);
    if (!all_finite(&w)) *finite = 0;
    if (!with_forces) memset(w.force_N, 0, sizeof w.force_N);
    advance(&w, cams, n_cams, dt_s);
    for (k = 0; k < n_cams; ++k) {
      cams[k].pose.eye_m = add(cams[k].pose.eye_m, scale(cams[k].pose.velocity_mps, dt_s));
    }
  }
  for (i = 0; i < N_FRAGMENTS; ++i) touched += w.touched_any[i];
  fragsim_controller_destroy(id);
  return touched;
}

static void test_two_eyes_stay_clean(void) {
  /* A headset walking into the blast at 1.5 m/s: eyes 6.4 cm apart, each with its own near
   * rectangle, one body each (the headset's half sizes), looking down -z. */
  camera eyes[2];
  int conflicts, finite, pushed, seed;
  const fragsim_vec3 walk = v3(0.0, 0.0, -1.5);
  eyes[0] = camera_at(v3(-0.032, 1.6, 0.0), 1.0, walk);
  eyes[1] = camera_at(v3(0.032, 1.6, 0.0), 1.0, walk);
  for (seed = 1; seed <= 3; ++seed) {
    const fragsim_vec3 centre = v3(0.0, 1.6, -8.0);
    const fragsim_vec3 target = v3(0.0, 1.6, -0.5);
    const int free_hits =
        run_blast(eyes, 2, centre, target, 0.5, (uint64_t)seed, 0, &conflicts, &finite, &pushed);
    const int hits =
        run_blast(eyes, 2, centre, target, 0.5, (uint64_t)seed, 1, &conflicts, &finite, &pushed);
    printf(
        "two eyes, seed %d: %d of %d fragments touch an eye without forces, %d with; %d "
        "conflicts\n",
        seed, free_hits, N_FRAGMENTS, hits, conflicts);
    CHECK(free_hits >= 10); /* the blast is a threat: the test can fail */
    CHECK(hits == 0);
    CHECK(conflicts == 0);
    CHECK(finite);
    CHECK(pushed > 0);
  }
}

static void test_facing_cameras_report_conflicts(void) {
  /* Two players' cameras face each other 0.4 m apart, B's eye 0.3 m higher (a taller player); a
   * blast from the side sends fragments between them, where their bodies leave a gap of 0.1 m
   * (depth) by 0.1 m (height), at the height where A's top edge meets B's bottom edge: A's least
   * push is up, into B's box, and B's is down, into A's. Only a push past B's top or A's bottom
   * clears both. */
  camera cams[2];
  int conflicts, finite, pushed, hits_free, hits;
  const fragsim_vec3 centre = v3(-6.0, 1.75, -0.2);
  const fragsim_vec3 target = v3(0.0, 1.75, -0.2);
  cams[0] = camera_at(v3(0.0, 1.6, 0.0), 1.0, v3(0.0, 0.0, 0.0));
  cams[1] = camera_at(v3(0.0, 1.9, -0.4), -1.0, v3(0.0, 0.0, 0.0));
  hits_free = run_blast(cams, 2, centre, target, 0.1, 11, 0, &conflicts, &finite, &pushed);
  hits = run_blast(cams, 2, centre, target, 0.1, 11, 1, &conflicts, &finite, &pushed);
  printf(
      "facing cameras: %d of %d fragments touch a camera without forces, %d with; %d "
      "conflicts reported\n",
      hits_free, N_FRAGMENTS, hits, conflicts);
  CHECK(conflicts > 0);
  CHECK(finite);
  CHECK(hits_free > 0);
}

int main(void) {
  test_set_once_is_the_per_step_call();
  test_refusals_name_the_field();
  test_camera_count_change_forgets();
  test_two_eyes_stay_clean();
  test_facing_cameras_report_conflicts();
  return check_verdict("cameras_test");
}
