/* The controller library's differential test: replays a dump that `fragsim run --dump-control`
 * wrote (format: src/experiments/control_dump.hpp) through the library's C API, and checks that the
 * forces are bit for bit the ones fragsim applied. Plain C99: it sees the library only as a game
 * would, through fragsim/control.h. The dump carries the def the library's own mapping made of the
 * scene's settings (src/control/api/def_mapping.hpp), passed on as it is: nothing here maps a
 * setting to a field.
 *
 *   replay DUMP [--arrays]     --arrays: through fragsim_controller_step_arrays instead
 *
 * Exit status 0 when every force of every step matches, 1 on a mismatch, 2 on a bad file. */
#include <fragsim/control.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Reader {
  const unsigned char* at;
  const unsigned char* end;
  int bad;
} Reader;

static void take(Reader* r, void* out, size_t n) {
  if (r->bad || (size_t)(r->end - r->at) < n) {
    r->bad = 1;
    memset(out, 0, n);
    return;
  }
  memcpy(out, r->at, n);
  r->at += n;
}
static double take_double(Reader* r) {
  double v;
  take(r, &v, sizeof v);
  return v;
}
static int32_t take_i32(Reader* r) {
  int32_t v;
  take(r, &v, sizeof v);
  return v;
}
static uint32_t take_u32(Reader* r) {
  uint32_t v;
  take(r, &v, sizeof v);
  return v;
}
static fragsim_vec3 take_vec3(Reader* r) {
  fragsim_vec3 v;
  v.x = take_double(r);
  v.y = take_double(r);
  v.z = take_double(r);
  return v;
}

static unsigned char* read_file(const char* path, size_t* size) {
  FILE* f = fopen(path, "rb");
  unsigned char* data = NULL;
  long n;
  if (f == NULL) return NULL;
  if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
    data = (unsigned char*)malloc(n > 0 ? (size_t)n : 1);
    if (data != NULL && fread(data, 1, (size_t)n, f) != (size_t)n) {
      free(data);
      data = NULL;
    }
    *size = (size_t)n;
  }
  fclose(f);
  return data;
}

static int same_bits(double a, double b) {
  return memcmp(&a, &b, sizeof a) == 0;
}

int main(int argc, char** argv) {
  size_t size = 0;
  unsigned char* data;
  Reader r;
  char magic[8];
  uint32_t def_size, step_count;
  int use_arrays;
  fragsim_controller_def def;
  fragsim_controller_id ctl;
  char message[256];
  uint32_t s;
  long compared = 0, pushed = 0, mismatches = 0;
  fragsim_fragment* fragments = NULL;
  fragsim_vec3* forces = NULL;
  fragsim_vec3* expected = NULL;
  int32_t capacity = 0;
  fragsim_camera_def camera_set;
  int cameras_set = 0;

  if (argc < 2 || argc > 3) {
    fprintf(stderr, "usage: replay DUMP [--arrays]\n");
    return 2;
  }
  use_arrays = argc == 3 && strcmp(argv[2], "--arrays") == 0;
  data = read_file(argv[1], &size);
  if (data == NULL) {
    fprintf(stderr, "replay: cannot read %s\n", argv[1]);
    return 2;
  }
  r.at = data;
  r.end = data + size;
  r.bad = 0;
  take(&r, magic, 8);
  if (memcmp(magic, "FSCDUMP2", 8) != 0 || take_u32(&r) != 0x01020304u) {
    fprintf(stderr, "replay: %s is not a control dump of this byte order\n", argv[1]);
    return 2;
  }
  def_size = take_u32(&r);
  step_count = take_u32(&r);
  (void)take_u32(&r);
  if (def_size != sizeof def) {
    fprintf(stderr, "replay: the dump's def has %u bytes, this library's %u\n", (unsigned)def_size,
            (unsigned)sizeof def);
    return 2;
  }
  take(&r, &def, sizeof def);
  for (s = sizeof def; s % 8 != 0; ++s) {
    unsigned char pad;
    take(&r, &pad, 1);
  }
  if (r.bad) {
    fprintf(stderr, "replay: %s is truncated in its header\n", argv[1]);
    return 2;
  }
  /* The tool's look-ahead is the strategy's horizon_cap_s (in the def) and the physics; its steps
   * carry end_time_s = INFINITY, handed over as they are. */
  if (fragsim_controller_create(&def, &ctl, message, sizeof message) != FRAGSIM_OK) {
    fprintf(stderr, "replay: create: %s\n", message);
    return 2;
  }

  for (s = 0; s < step_count; ++s) {
    fragsim_step_input in = fragsim_default_step_input();
    fragsim_camera_def camera = fragsim_default_camera_def();
    fragsim_camera_pose pose = fragsim_default_camera_pose();
    fragsim_step_stats stats;
    fragsim_status status;
    int32_t n, force_count, i;
    (void)take_i32(&r); /* step index */
    n = take_i32(&r);
    force_count = take_i32(&r);
    (void)take_i32(&r);
    if (r.bad || n < 0 || force_count < 0 || force_count > n) break;
    if (n > capacity) {
      capacity = n;
      fragments = (fragsim_fragment*)realloc(fragments, (size_t)n * sizeof *fragments);
      forces = (fragsim_vec3*)realloc(forces, (size_t)n * sizeof *forces);
      expected = (fragsim_vec3*)realloc(expected, (size_t)n * sizeof *expected);
      if (fragments == NULL || forces == NULL || expected == NULL) {
        fprintf(stderr, "replay: out of memory\n");
        return 2;
      }
    }
    in.time_s = take_double(&r);
    in.dt_s = take_double(&r);
    in.end_time_s = take_double(&r);
    pose.eye_m = take_vec3(&r);
    pose.right = take_vec3(&r);
    pose.up = take_vec3(&r);
    pose.forward = take_vec3(&r);
    camera.fovy_deg = take_double(&r);
    camera.aspect = take_double(&r);
    camera.near_m = take_double(&r);
    camera.far_m = take_double(&r);
    pose.velocity_mps = take_vec3(&r);
    camera.max_speed_mps = take_double(&r);
    camera.max_accel_mps2 = take_double(&r);
    camera.max_turn_degps = take_double(&r);
    camera.body_half_m = take_vec3(&r);
    in.gravity_mps2 = take_vec3(&r);
    in.ground_height_m = take_double(&r);
    /* The tool's world is y-up (the dump carries no normal). */
    in.ground_normal.x = 0.0;
    in.ground_normal.y = 1.0;
    in.ground_normal.z = 0.0;
    for (i = 0; i < n; ++i) {
      fragments[i].position_m = take_vec3(&r);
      fragments[i].velocity_mps = take_vec3(&r);
      fragments[i].radius_m = take_double(&r);
      fragments[i].mass_kg = take_double(&r);
      fragments[i].id = (uint64_t)i;
    }
    for (i = 0; i < n; ++i) take(&r, &fragments[i].touched, 1);
    for (i = n; i % 8 != 0; ++i) {
      unsigned char pad;
      take(&r, &pad, 1);
    }
    memset(expected, 0, (size_t)n * sizeof *expected);
    for (i = 0; i < force_count; ++i) {
      int32_t which = take_i32(&r);
      (void)take_i32(&r);
      if (which < 0 || which >= n) {
        r.bad = 1;
        break;
      }
      expected[which] = take_vec3(&r);
    }
    if (r.bad) break;
    /* The camera's constants are set once, and again only when the dump's change (they never do
     * in the tool's scenes, but a replay must not assume it). */
    if (!cameras_set || memcmp(&camera, &camera_set, sizeof camera) != 0) {
      if (fragsim_controller_set_cameras(ctl, &camera, 1) != FRAGSIM_OK) {
        fprintf(stderr, "replay: step %u: set_cameras: %s\n", (unsigned)s,
                fragsim_controller_last_error(ctl));
        return 1;
      }
      camera_set = camera;
      cameras_set = 1;
    }
    in.camera_poses = &pose;
    in.camera_count = 1;

    if (use_arrays) {
      fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
      a.position_m = &fragments[0].position_m.x;
      a.position_stride_bytes = sizeof *fragments;
      a.velocity_mps = &fragments[0].velocity_mps.x;
      a.velocity_stride_bytes = sizeof *fragments;
      a.radius_m = &fragments[0].radius_m;
      a.radius_stride_bytes = sizeof *fragments;
      a.mass_kg = &fragments[0].mass_kg;
      a.mass_stride_bytes = sizeof *fragments;
      a.id = &fragments[0].id;
      a.id_stride_bytes = sizeof *fragments;
      a.touched = &fragments[0].touched;
      a.touched_stride_bytes = sizeof *fragments;
      a.force_N = &forces[0].x;
      a.force_stride_bytes = sizeof *forces;
      status = fragsim_controller_step_arrays(ctl, &in, &a, n, &stats);
    } else {
      status = fragsim_controller_step(ctl, &in, fragments, n, forces, &stats);
    }
    if (status != FRAGSIM_OK) {
      fprintf(stderr, "replay: step %u: %s: %s\n", (unsigned)s, fragsim_status_string(status),
              fragsim_controller_last_error(ctl));
      return 1;
    }
    for (i = 0; i < n; ++i) {
      if (!same_bits(forces[i].x, expected[i].x) || !same_bits(forces[i].y, expected[i].y) ||
          !same_bits(forces[i].z, expected[i].z)) {
        if (mismatches < 5) {
          fprintf(stderr, "replay: step %u fragment %d: library %a %a %a, fragsim %a %a %a\n",
                  (unsigned)s, (int)i, forces[i].x, forces[i].y, forces[i].z, expected[i].x,
                  expected[i].y, expected[i].z);
        }
        ++mismatches;
      }
    }
    if (stats.pushed != force_count) {
      fprintf(stderr, "replay: step %u: library pushed %d fragments, fragsim %d\n", (unsigned)s,
              (int)stats.pushed, (int)force_count);
      ++mismatches;
    }
    compared += n;
    pushed += force_count;
  }
  if (r.bad || s != step_count || r.at != r.end) {
    fprintf(stderr, "replay: %s is truncated or malformed at step %u\n", argv[1], (unsigned)s);
    return 2;
  }
  fragsim_controller_destroy(ctl);
  free(fragments);
  free(forces);
  free(expected);
  free(data);
  printf("replay: %u steps, %ld fragment forces compared (%ld nonzero), %ld mismatches (%s)\n",
         (unsigned)step_count, compared, pushed, mismatches, use_arrays ? "arrays" : "structs");
  if (pushed == 0) {
    fprintf(stderr, "replay: no nonzero force in the dump: nothing was really compared\n");
    return 1;
  }
  return mismatches == 0 ? 0 : 1;
}
