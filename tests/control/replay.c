/* The controller library's differential test: replays a dump that `fragsim run --dump-control`
 * wrote (format: src/experiments/control_dump.hpp) through the library's C API, and checks that the
 * forces are bit for bit the ones fragsim applied. Plain C99: it sees the library only as a game
 * would, through fragsim/control.h. The dump carries the def the library's own mapping made of the
 * scene's settings (src/control/api/def_mapping.hpp), passed on as it is: nothing here maps a
 * setting to a field.
 *
 *   replay DUMP [--arrays | --floats] [--time REPEATS]
 *     --arrays  through fragsim_controller_step_arrays instead
 *     --floats  through fragsim_controller_step_arrays over float arrays (the inputs rounded to
 *               float): the tool has no float forces to compare them with
 *     --time    replays the dump REPEATS times, each with a new controller, and prints the median
 *               of the processor time the step calls took, per fragment and step: the same
 *               states timed the same way in two builds (scripts/web_bench.sh)
 * Every mode prints a digest of every force and stat of every step, for comparing two builds of
 * the library (native and WebAssembly), whose stats the dump does not hold.
 *
 * The same program built for WebAssembly (scripts/web_build.sh) replays the native dumps: see
 * read_def for how it reads a def written by a 64-bit build.
 *
 * Exit status 0 when every force of every step matches, 1 on a mismatch, 2 on a bad file. */
#include <fragsim/control.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

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

/* 32-bit FNV-1a over bytes: the digest of every force and stat a replay printed, which two
 * builds (native, WebAssembly, the JavaScript API) must print alike. */
static uint32_t digest(uint32_t h, const void* bytes, size_t n) {
  const unsigned char* p = (const unsigned char*)bytes;
  size_t i;
  for (i = 0; i < n; ++i) h = (h ^ p[i]) * 16777619u;
  return h;
}

/* The dump's def, def_size bytes as the writing build laid it out. A build whose pointers have
 * another size (WebAssembly's 4 bytes against the tool's 8) reads the strategy's numbers only:
 * they come first in the struct, before any pointer, and each has the same offset under both
 * ABIs (doubles, and the structs holding them, are 8-aligned on both). What follows them in a
 * tool's dump is six NULL hooks, worker_count = 1 and the defaulted mark, all of which this
 * build's own default def supplies. Returns 0 when the def cannot be read so. */
static int read_def(Reader* r, uint32_t def_size, fragsim_controller_def* def) {
  const size_t numbers = offsetof(fragsim_controller_def, alloc_fn);
  const size_t hooks_end = numbers + 6 * 8; /* the writer's six 8-byte pointers */
  size_t i;
  if (def_size == sizeof *def) {
    take(r, def, sizeof *def);
    return !r->bad;
  }
  if (def_size != hooks_end + 8) return 0;
  *def = fragsim_default_controller_def();
  take(r, def, numbers);
  for (i = numbers; i < hooks_end; ++i) {
    unsigned char byte;
    take(r, &byte, 1);
    if (byte != 0) return 0; /* a hook set: not a tool's dump */
  }
  if (take_i32(r) != 1) return 0; /* worker_count */
  (void)take_i32(r);              /* the writer's defaulted mark */
  return !r->bad;
}

static int compare_doubles(const void* a, const void* b) {
  const double x = *(const double*)a;
  const double y = *(const double*)b;
  return (x > y) - (x < y);
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
  int use_arrays, use_floats;
  uint32_t forces_digest = 2166136261u;
  float* floats = NULL; /* --floats: position, velocity, force (3 each), radius, mass */
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
  int repeats = 1, timed = 0, rep, a;
  const unsigned char* steps_at;
  double* step_seconds = NULL;
  long fragment_steps = 0;

  if (argc < 2) {
    fprintf(stderr, "usage: replay DUMP [--arrays | --floats] [--time REPEATS]\n");
    return 2;
  }
  use_floats = use_arrays = 0;
  for (a = 2; a < argc; ++a) {
    if (strcmp(argv[a], "--floats") == 0) {
      use_floats = use_arrays = 1;
    } else if (strcmp(argv[a], "--arrays") == 0) {
      use_arrays = 1;
    } else if (strcmp(argv[a], "--time") == 0 && a + 1 < argc && atoi(argv[a + 1]) > 0) {
      timed = 1;
      repeats = atoi(argv[++a]);
    } else {
      fprintf(stderr, "replay: unknown option %s\n", argv[a]);
      return 2;
    }
  }
  step_seconds = (double*)calloc((size_t)repeats, sizeof *step_seconds);
  if (step_seconds == NULL) return 2;
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
  if (!read_def(&r, def_size, &def)) {
    fprintf(stderr, "replay: the dump's def (%u bytes) cannot be read by this build (%u)\n",
            (unsigned)def_size, (unsigned)sizeof def);
    return 2;
  }
  for (s = def_size; s % 8 != 0; ++s) {
    unsigned char pad;
    take(&r, &pad, 1);
  }
  if (r.bad) {
    fprintf(stderr, "replay: %s is truncated in its header\n", argv[1]);
    return 2;
  }
  steps_at = r.at;
  for (rep = 0; rep < repeats; ++rep) {
    r.at = steps_at;
    cameras_set = 0;
    compared = pushed = mismatches = fragment_steps = 0;
    forces_digest = 2166136261u;
    /* The tool's look-ahead is the strategy's horizon_cap_s (in the def) and the physics; its steps
     * carry end_time_s = INFINITY, handed over as they are. */
    if (fragsim_controller_create(&def, &ctl, message, sizeof message) != FRAGSIM_OK) {
      fprintf(stderr, "replay: create: %s\n", message);
      return 2;
    }

    for (s = 0; s < step_count; ++s) {
      clock_t started;
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
        floats = (float*)realloc(floats, (size_t)n * 11 * sizeof *floats);
        if (fragments == NULL || forces == NULL || expected == NULL || floats == NULL) {
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

      started = clock();
      if (use_floats) {
        fragsim_fragment_arrays a = fragsim_default_fragment_arrays();
        float* position = floats;
        float* velocity = floats + 3 * n;
        float* force = floats + 6 * n;
        float* radius = floats + 9 * n;
        float* mass = floats + 10 * n;
        for (i = 0; i < n; ++i) {
          position[3 * i] = (float)fragments[i].position_m.x;
          position[3 * i + 1] = (float)fragments[i].position_m.y;
          position[3 * i + 2] = (float)fragments[i].position_m.z;
          velocity[3 * i] = (float)fragments[i].velocity_mps.x;
          velocity[3 * i + 1] = (float)fragments[i].velocity_mps.y;
          velocity[3 * i + 2] = (float)fragments[i].velocity_mps.z;
          radius[i] = (float)fragments[i].radius_m;
          mass[i] = (float)fragments[i].mass_kg;
        }
        a.position_m = position;
        a.position_stride_bytes = 3 * sizeof(float);
        a.velocity_mps = velocity;
        a.velocity_stride_bytes = 3 * sizeof(float);
        a.radius_m = radius;
        a.radius_stride_bytes = sizeof(float);
        a.mass_kg = mass;
        a.mass_stride_bytes = sizeof(float);
        a.id = &fragments[0].id;
        a.id_stride_bytes = sizeof *fragments;
        a.touched = &fragments[0].touched;
        a.touched_stride_bytes = sizeof *fragments;
        a.force_N = force;
        a.force_stride_bytes = 3 * sizeof(float);
        a.scalar_type = FRAGSIM_SCALAR_FLOAT;
        status = fragsim_controller_step_arrays(ctl, &in, &a, n, &stats);
      } else if (use_arrays) {
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
      step_seconds[rep] += (double)(clock() - started) / CLOCKS_PER_SEC;
      fragment_steps += n;
      if (status != FRAGSIM_OK) {
        fprintf(stderr, "replay: step %u: %s: %s\n", (unsigned)s, fragsim_status_string(status),
                fragsim_controller_last_error(ctl));
        return 1;
      }
      forces_digest = digest(forces_digest, &stats, sizeof stats);
      if (use_floats) {
        /* Nothing to compare them with: the digest only. */
        forces_digest = digest(forces_digest, floats + 6 * n, (size_t)n * 3 * sizeof(float));
        compared += n;
        pushed += stats.pushed;
        continue;
      }
      forces_digest = digest(forces_digest, forces, (size_t)n * sizeof *forces);
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
  }
  if (timed) {
    qsort(step_seconds, (size_t)repeats, sizeof *step_seconds, compare_doubles);
    printf(
        "replay: time: %.1f ns per fragment and step, the median of %d replays of %ld "
        "fragment-steps\n",
        1e9 * step_seconds[repeats / 2] / (double)fragment_steps, repeats, fragment_steps);
  }
  free(step_seconds);
  free(fragments);
  free(forces);
  free(expected);
  free(floats);
  free(data);
  printf(
      "replay: %u steps, %ld fragment forces compared (%ld nonzero), %ld mismatches (%s), "
      "digest %08x\n",
      (unsigned)step_count, compared, pushed, mismatches,
      use_floats   ? "floats"
      : use_arrays ? "arrays"
                   : "structs",
      (unsigned)forces_digest);
  if (pushed == 0) {
    fprintf(stderr, "replay: no nonzero force in the dump: nothing was really compared\n");
    return 1;
  }
  return mismatches == 0 ? 0 : 1;
}
