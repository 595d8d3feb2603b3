/* fragsim_fragment_arrays with scalar_type FLOAT (since 0.6), in C99 as a game sees it: floats are
 * widened to double exactly at the boundary and each force is the double force rounded to float,
 * so the float path is the double path, not a second one. Prints every failed check, exits 1 if
 * any failed. */
#include <float.h>
#include <fragsim/control.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

enum { kCount = 240 };

/* An engine's float body: position, a pad, velocity, radius, mass, id (40 bytes). */
typedef struct Body {
  float position[3];
  float pad;
  float velocity[3];
  float radius;
  float mass;
  uint64_t id;
} Body;

/* The one camera of every controller here (the default one), walking toward the blast. */
static fragsim_camera_pose g_pose;

static fragsim_controller_id make(fragsim_strategy strategy) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_controller_id id;
  def.strategy = strategy;
  CHECK(fragsim_controller_create(&def, &id, NULL, 0) == FRAGSIM_OK);
  CHECK(fragsim_controller_set_cameras(id, &camera, 1) == FRAGSIM_OK);
  return id;
}

static fragsim_step_input blast_input(void) {
  fragsim_step_input in = fragsim_default_step_input();
  in.ground_height_m = -1.5;
  g_pose = fragsim_default_camera_pose();
  g_pose.velocity_mps.z = -1.0;
  in.camera_poses = &g_pose;
  in.camera_count = 1;
  return in;
}

/* A blast 6 m ahead of the default camera: directions on a golden-angle spiral, some at the lens.
 * exact != 0 rounds every number to a multiple of 1/1024 (exact in float: below 2^14 in size,
 * 24 bits cover it); otherwise they keep the decimals a simulation gives. */
static void blast(fragsim_fragment* f, int exact) {
  int i;
  for (i = 0; i < kCount; ++i) {
    const double a = 2.399963 * i;
    const double z = 1.0 - 2.0 * (i + 0.5) / kCount;
    const double r = sqrt(1.0 - z * z);
    const double t = 0.25 + 0.0005 * i; /* time since the blast: the nearest are 2 m away */
    double v[3];
    double p[3];
    int k;
    v[0] = 7.0 * r * cos(a);
    v[1] = 7.0 * r * sin(a) + 2.0 - 9.81 * t;
    v[2] = 7.0 * z + 6.0;
    p[0] = 0.3 * cos(1.7 * i) + v[0] * t;
    p[1] = 0.3 * sin(1.3 * i) + v[1] * t;
    p[2] = -6.0 + v[2] * t;
    if (i % 4 == 0) { /* aimed at the eye, arriving after 0.15 to 0.9 s: threats to push */
      const double arrive = 0.15 + 0.003 * i;
      p[0] = 0.05 * cos(1.1 * i);
      p[1] = 0.05 * sin(1.1 * i);
      p[2] = -12.0 * arrive;
      v[0] = -p[0] / arrive;
      v[1] = -p[1] / arrive + 4.905 * arrive;
      v[2] = 12.0;
    }
    f[i] = fragsim_default_fragment();
    for (k = 0; k < 3; ++k) {
      if (exact) {
        p[k] = floor(p[k] * 1024.0 + 0.5) / 1024.0;
        v[k] = floor(v[k] * 1024.0 + 0.5) / 1024.0;
      }
    }
    f[i].position_m.x = p[0];
    f[i].position_m.y = p[1];
    f[i].position_m.z = p[2];
    f[i].velocity_mps.x = v[0];
    f[i].velocity_mps.y = v[1];
    f[i].velocity_mps.z = v[2];
    f[i].radius_m = exact ? (40 + i % 50) / 1024.0 : 0.04 + 0.000123 * i;
    f[i].mass_kg = exact ? (256 + 3 * i) / 1024.0 : 0.25 + 0.00291 * i;
    f[i].id = 1000 + 7 * (uint64_t)i;
  }
}

static void to_bodies(const fragsim_fragment* f, Body* b) {
  int i;
  memset(b, 0, kCount * sizeof *b);
  for (i = 0; i < kCount; ++i) {
    b[i].position[0] = (float)f[i].position_m.x;
    b[i].position[1] = (float)f[i].position_m.y;
    b[i].position[2] = (float)f[i].position_m.z;
    b[i].velocity[0] = (float)f[i].velocity_mps.x;
    b[i].velocity[1] = (float)f[i].velocity_mps.y;
    b[i].velocity[2] = (float)f[i].velocity_mps.z;
    b[i].radius = (float)f[i].radius_m;
    b[i].mass = (float)f[i].mass_kg;
    b[i].id = f[i].id;
  }
}

/* The arrays over Body, forces as 3 floats with a 4th float left alone (stride 16). */
static fragsim_fragment_arrays float_arrays(const Body* b, float* forces) {
  fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
  a.scalar_type = FRAGSIM_SCALAR_FLOAT;
  a.position_m = b[0].position; /* no cast: the fields are void pointers */
  a.position_stride_bytes = sizeof *b;
  a.velocity_mps = b[0].velocity;
  a.velocity_stride_bytes = sizeof *b;
  a.radius_m = &b[0].radius;
  a.radius_stride_bytes = sizeof *b;
  a.mass_kg = &b[0].mass;
  a.mass_stride_bytes = sizeof *b;
  a.id = &b[0].id;
  a.id_stride_bytes = sizeof *b;
  a.force_N = forces;
  a.force_stride_bytes = 4 * sizeof(float);
  return a;
}

static float component(const fragsim_vec3* v, int k) {
  return (float)(k == 0 ? v->x : k == 1 ? v->y : v->z);
}

/* (a) Numbers exact in float: the float path's forces are the double path's rounded to float, to
 * the bit, for every strategy, over steps whose ids stay (state kept) and change. */
static void exact_inputs_give_rounded_double_forces(void) {
  const fragsim_strategy strategies[3] = {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE,
                                          FRAGSIM_STRATEGY_DEFLECT_ALL};
  static fragsim_fragment f[kCount];
  static Body b[kCount];
  static fragsim_vec3 expected[kCount];
  static float forces[4 * kCount];
  int s, step, i, k;
  blast(f, 1);
  to_bodies(f, b);
  for (i = 0; i < kCount; ++i) { /* the float copies are exact */
    CHECK((double)b[i].position[0] == f[i].position_m.x);
    CHECK((double)b[i].velocity[2] == f[i].velocity_mps.z);
    CHECK((double)b[i].mass == f[i].mass_kg && (double)b[i].radius == f[i].radius_m);
  }
  for (s = 0; s < 3; ++s) {
    fragsim_controller_id d = make(strategies[s]);
    fragsim_controller_id fl = make(strategies[s]);
    fragsim_step_input in = blast_input();
    int pushed = 0;
    int mismatches = 0;
    for (step = 0; step < 4; ++step) {
      const int32_t count = step == 2 ? kCount - 40 : kCount; /* ids leave and come back */
      fragsim_fragment_arrays a = float_arrays(b, forces);
      fragsim_step_stats sd, sf;
      in.time_s = step / 60.0;
      for (i = 0; i < 4 * kCount; ++i) forces[i] = -7.0f;
      CHECK(fragsim_controller_step(d, &in, f, count, expected, &sd) == FRAGSIM_OK);
      CHECK(fragsim_controller_step_arrays(fl, &in, &a, count, &sf) == FRAGSIM_OK);
      CHECK(sd.pushed == sf.pushed && sd.candidates == sf.candidates);
      pushed += sd.pushed;
      for (i = 0; i < count; ++i) {
        for (k = 0; k < 3; ++k) {
          if (memcmp(&forces[4 * i + k], &(float){component(&expected[i], k)}, sizeof(float))) {
            ++mismatches;
          }
        }
        CHECK(forces[4 * i + 3] == -7.0f); /* the stride's gap untouched */
      }
    }
    CHECK(pushed > 10); /* forces to compare, not zeros */
    CHECK(mismatches == 0);
    printf("exact floats, strategy %d: %d pushes, %d components differ\n", s, pushed, mismatches);
    fragsim_controller_destroy(d);
    fragsim_controller_destroy(fl);
  }
}

/* (b) A blast with arbitrary decimals, handed as floats (rounded to nearest), against the same
 * blast in double (a quarter of it aimed at the lens). A float keeps 24 bits: positions within 10 m
 * move by up to 10 * 2^-24 = 6e-7 m, speeds within 15 m/s by 9e-7 m/s. edge-min's push is a = 2 D /
 * (tau^2 + tau dt), D the displacement the path needs, tau its arrival: over tau >= 0.1 s (closer
 * ones are capped at a_max, where a does not move) D moves by at most 6e-7 + 0.3 * 9e-7 < 1e-6 m
 * and tau by 6e-7 / 10 m/s, so a moves by 2e-6 / 0.01 + 2 * 50 * 6e-8 / 0.1 < 3e-4 m/s^2; the
 * output's float rounding adds 2^-24 |F|. The bound asserted, on every component of every fragment
 * (none excluded): |F_float - F_double| <= mass * 1e-3 m/s^2 + 2^-23 |F_double|, three times the
 * estimate (this blast's worst is 3.3e-6 m/s^2: the estimate is a bound, not a forecast). A
 * fragment on a decision's edge (a tie between two screen edges, the lazy push's switch) could jump
 * further; this blast has none, and a new scene that does fails here loudly. */
static void rounded_blast_stays_within_tolerance(void) {
  static fragsim_fragment f[kCount];
  static Body b[kCount];
  static fragsim_vec3 expected[kCount];
  static float forces[4 * kCount];
  fragsim_controller_id d = make(FRAGSIM_STRATEGY_EDGE_MIN);
  fragsim_controller_id fl = make(FRAGSIM_STRATEGY_EDGE_MIN);
  fragsim_step_input in = blast_input();
  fragsim_fragment_arrays a;
  int step, i, k;
  int pushed = 0;
  int outside = 0;
  double worst = 0.0; /* the largest |difference| / mass seen, m/s^2 */
  blast(f, 0);
  to_bodies(f, b);
  CHECK((double)b[5].position[0] != f[5].position_m.x); /* the decimals were rounded */
  a = float_arrays(b, forces);
  for (step = 0; step < 3; ++step) {
    fragsim_step_stats sd, sf;
    in.time_s = step / 60.0;
    CHECK(fragsim_controller_step(d, &in, f, kCount, expected, &sd) == FRAGSIM_OK);
    CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_OK);
    CHECK(sd.pushed == sf.pushed);
    pushed += sd.pushed;
    for (i = 0; i < kCount; ++i) {
      for (k = 0; k < 3; ++k) {
        const double want = k == 0 ? expected[i].x : k == 1 ? expected[i].y : expected[i].z;
        const double diff = fabs((double)forces[4 * i + k] - want);
        const double bound = f[i].mass_kg * 1e-3 + fabs(want) * FLT_EPSILON;
        if (diff / f[i].mass_kg > worst) worst = diff / f[i].mass_kg;
        if (!(diff <= bound)) {
          if (outside < 5) {
            fprintf(stderr, "step %d fragment %d axis %d: float %.9g, double %.9g\n", step, i, k,
                    (double)forces[4 * i + k], want);
          }
          ++outside;
        }
      }
    }
  }
  CHECK(pushed > 10);
  CHECK(outside == 0);
  printf("rounded blast: %d pushes, worst difference %.3g m/s^2 times the mass, %d outside\n",
         pushed, worst, outside);
  fragsim_controller_destroy(d);
  fragsim_controller_destroy(fl);
}

/* (c) A float NaN is skipped as a double one is; a bad scalar_type and strides below the
 * element's size are refused, named, and leave a force buffer of unknown layout alone. */
static void refusals_and_skips(void) {
  static fragsim_fragment f[kCount];
  static Body b[kCount];
  static fragsim_vec3 expected[kCount];
  static float forces[4 * kCount];
  fragsim_controller_id d = make(FRAGSIM_STRATEGY_EDGE_MIN);
  fragsim_controller_id fl = make(FRAGSIM_STRATEGY_EDGE_MIN);
  fragsim_step_input in = blast_input();
  fragsim_fragment_arrays a;
  fragsim_step_stats sd, sf;
  int i;
  int mismatches = 0;
  blast(f, 1);
  f[3].position_m.y = NAN;
  to_bodies(f, b);
  CHECK(isnan(b[3].position[1]));
  a = float_arrays(b, forces);
  for (i = 0; i < 4 * kCount; ++i) forces[i] = 7.0f;
  CHECK(fragsim_controller_step(d, &in, f, kCount, expected, &sd) == FRAGSIM_OK);
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_OK);
  CHECK(sd.skipped == 1 && sd.first_skipped == 3);
  CHECK(sf.skipped == 1 && sf.first_skipped == 3);
  CHECK((sf.warnings & FRAGSIM_WARNING_SKIPPED) != 0);
  CHECK(forces[12] == 0.0f && forces[13] == 0.0f && forces[14] == 0.0f);
  for (i = 0; i < kCount; ++i) {
    mismatches +=
        forces[4 * i] != (float)expected[i].x || forces[4 * i + 1] != (float)expected[i].y;
  }
  CHECK(mismatches == 0);
  CHECK(sf.pushed > 0);

  a.scalar_type = (fragsim_scalar_type)2;
  forces[0] = 7.0f;
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(fragsim_controller_last_error(fl), "arrays.scalar_type = 2") != NULL);
  CHECK(forces[0] == 7.0f); /* its element size unknown: left alone */

  a.scalar_type = FRAGSIM_SCALAR_FLOAT;
  a.position_stride_bytes = 8; /* 3 floats need 12 */
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(fragsim_controller_last_error(fl), "arrays.position_stride_bytes = 8") != NULL);
  CHECK(forces[0] == 0.0f); /* the force layout is valid: zeros */
  a.position_stride_bytes = sizeof *b;
  a.force_stride_bytes = 8;
  forces[0] = 7.0f;
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(fragsim_controller_last_error(fl), "arrays.force_stride_bytes = 8") != NULL);
  CHECK(forces[0] == 7.0f);
  a.force_stride_bytes = 12; /* packed floats: legal */
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_OK);
  a.force_stride_bytes = 16;
  a.scalar_type = FRAGSIM_SCALAR_DOUBLE;
  a.mass_stride_bytes = 4; /* a double needs 8 */
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, kCount, &sf) == FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(fragsim_controller_last_error(fl), "arrays.mass_stride_bytes = 4") != NULL);
  CHECK(strstr(fragsim_controller_last_error(fl), "8 bytes of a double") != NULL);
  /* One fragment has no stride to speak of: zero strides pass. */
  a = float_arrays(b, forces);
  a.position_stride_bytes = a.velocity_stride_bytes = a.radius_stride_bytes = 0;
  a.mass_stride_bytes = a.id_stride_bytes = a.force_stride_bytes = 0;
  CHECK(fragsim_controller_step_arrays(fl, &in, &a, 1, &sf) == FRAGSIM_OK);
  fragsim_controller_destroy(d);
  fragsim_controller_destroy(fl);
}

int main(void) {
  exact_inputs_give_rounded_double_forces();
  rounded_blast_stays_within_tolerance();
  refusals_and_skips();
  return check_verdict("float_arrays_test");
}
