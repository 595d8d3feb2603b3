/* Controllers on several threads at once, as the header allows (one controller per thread at a
 * time; different controllers independent): each thread creates, steps and destroys its own
 * controllers while the others do the same, and must get the forces a lone thread got. Built under
 * ThreadSanitizer in CI (tests/control/api/CMakeLists.txt, FRAGSIM_API_TESTS_TSAN), where any data
 * race between them, the table of controller ids included, fails the run. */
#include <fragsim/control.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

enum { kThreads = 4, kRounds = 6, kSteps = 20, kFragments = 64 };

static fragsim_vec3 g_expected[kSteps][kFragments];

static void fragments_at(int step, fragsim_fragment* f) {
  int i;
  const double t = step / 60.0;
  for (i = 0; i < kFragments; ++i) {
    const double a = 2.399963 * i;
    const double vx = 0.4 * cos(a);
    const double vy = 0.4 * sin(a) + 2.45;
    f[i] = fragsim_default_fragment();
    f[i].velocity_mps.x = vx;
    f[i].velocity_mps.y = vy - 9.81 * t;
    f[i].velocity_mps.z = 10.0;
    f[i].position_m.x = vx * t;
    f[i].position_m.y = vy * t - 4.905 * t * t;
    f[i].position_m.z = -5.0 + 10.0 * t;
    f[i].radius_m = 0.05;
    f[i].mass_kg = 1.0;
    f[i].id = (uint64_t)i;
  }
}

/* One controller's whole run; 0 when every force equals the expected one (or, for the lone
 * reference run, when it could be recorded). */
static int run(int record) {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_camera_def camera = fragsim_default_camera_def();
  fragsim_camera_pose pose = fragsim_default_camera_pose();
  fragsim_controller_id c;
  fragsim_fragment f[kFragments];
  fragsim_vec3 forces[kFragments];
  fragsim_step_input in = fragsim_default_step_input();
  int step;
  int bad = 0;
  if (fragsim_controller_create(&def, &c, NULL, 0) != FRAGSIM_OK) return 1;
  if (fragsim_controller_set_cameras(c, &camera, 1) != FRAGSIM_OK) bad = 1;
  in.camera_poses = &pose;
  in.camera_count = 1;
  for (step = 0; step < kSteps; ++step) {
    fragments_at(step, f);
    in.time_s = step / 60.0;
    if (fragsim_controller_step(c, &in, f, kFragments, forces, NULL) != FRAGSIM_OK) bad = 1;
    if (record) {
      memcpy(g_expected[step], forces, sizeof forces);
    } else if (memcmp(g_expected[step], forces, sizeof forces) != 0) {
      bad = 1;
    }
  }
  if (fragsim_controller_destroy(c) != FRAGSIM_OK) bad = 1;
  /* Its id is stale now, whatever the other threads create meanwhile. */
  if (fragsim_controller_step(c, &in, f, kFragments, forces, NULL) != FRAGSIM_ERROR_STALE_ID) {
    bad = 1;
  }
  return bad;
}

static void* worker(void* arg) {
  int* bad = (int*)arg;
  int round;
  for (round = 0; round < kRounds; ++round) *bad |= run(0);
  return NULL;
}

int main(void) {
  pthread_t threads[kThreads];
  int bad[kThreads];
  int i;
  int failed = 0;
  double pushed = 0.0;
  if (run(1) != 0) {
    fprintf(stderr, "threads_test: the lone run failed\n");
    return 1;
  }
  for (i = 0; i < kSteps * kFragments; ++i) {
    const fragsim_vec3 v = g_expected[i / kFragments][i % kFragments];
    pushed += fabs(v.x) + fabs(v.y) + fabs(v.z);
  }
  if (!(pushed > 0.0)) {
    fprintf(stderr, "threads_test: the scenario pushes nothing, so it tests nothing\n");
    return 1;
  }
  for (i = 0; i < kThreads; ++i) {
    bad[i] = 0;
    if (pthread_create(&threads[i], NULL, worker, &bad[i]) != 0) return 1;
  }
  for (i = 0; i < kThreads; ++i) {
    pthread_join(threads[i], NULL);
    if (bad[i]) {
      fprintf(stderr, "threads_test: thread %d got other forces than the lone run\n", i);
      failed = 1;
    }
  }
  if (!failed) printf("threads_test: %d threads x %d controllers agree\n", kThreads, kRounds);
  return failed;
}
