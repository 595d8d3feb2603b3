// One point of the physics scale curve: one scene, one fragment count, one configuration, in its
// own process so that the peak memory (ru_maxrss) belongs to that configuration alone.
// scripts/scale_curve.sh runs every point and writes the CSV.
//
//   scale_curve SCENE SPLITS CONFIG STEPS [SETTLE_STEPS] [section.key=value ...]
//   scale_curve --header
//
// CONFIG: ballistic (no ground, no fragment pairs), ground (ground, no fragment pairs) or
// collisions (ground and fragment pairs). The world is first stepped SETTLE_STEPS steps (default
// 60: 1 s at 60 Hz), then STEPS steps are timed one by one: World::set_camera and World::step,
// that is collision detection and the ODE step, not reading the state back. The time is the
// thread's CPU time (CLOCK_THREAD_CPUTIME_ID), so other processes on a shared machine do not
// count; on an idle machine it equals the wall time. Prints one CSV line:
// fragments, config, median and 95th percentile ms per step, peak RSS in MiB, then the steps
// timed, the settling steps and the fragments still awake at the end. With SETTLE_STEPS 0 and
// STEPS the scene's step count the times cover the whole run, the landing included. The
// environment variable FRAGSIM_STEP_MS, when set, names a file that gets every timed step's
// time and awake fragments (step,ms,awake), to see where the slow steps fall.

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "sim/camera_path.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"

namespace {

constexpr const char* kHeader =
    "fragments,config,ms_per_step_median,ms_per_step_p95,peak_rss_mib,steps,settle_steps,"
    "awake_at_end";

std::vector<fragsim::SceneOverride> config_overrides(const std::string& config) {
  if (config == "ballistic") {
    return {{"ground.enabled", "off"}, {"simulation.fragment_collisions", "off"}};
  }
  if (config == "ground") {
    return {{"ground.enabled", "on"}, {"simulation.fragment_collisions", "off"}};
  }
  if (config == "collisions") {
    return {{"ground.enabled", "on"}, {"simulation.fragment_collisions", "on"}};
  }
  throw std::invalid_argument("unknown config '" + config +
                              "' (expected ballistic | ground | collisions)");
}

// The value below which `share` of the sorted samples lie (nearest rank).
double quantile(std::vector<double> v, double share) {
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(share * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

int run(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--header") {
    std::printf("%s\n", kHeader);
    return 0;
  }
  if (argc < 5) {
    std::fprintf(stderr,
                 "usage: scale_curve SCENE SPLITS CONFIG STEPS [SETTLE_STEPS] "
                 "[section.key=value ...]\n       scale_curve --header\n");
    return 2;
  }
  const std::string scene_path = argv[1];
  const std::string splits = argv[2];
  const std::string config = argv[3];
  const int steps = std::stoi(argv[4]);
  const int settle = argc > 5 ? std::stoi(argv[5]) : 60;
  std::vector<fragsim::SceneOverride> overrides = config_overrides(config);
  overrides.push_back({"object.splits", splits});
  for (int i = 6; i < argc; ++i) {
    const std::string kv = argv[i];
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("expected key=value, got " + kv);
    overrides.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
  }
  const fragsim::Scene scene = fragsim::load_scene(scene_path, overrides);
  if (steps < 1 || settle < 0) throw std::invalid_argument("STEPS >= 1, SETTLE_STEPS >= 0");

  const fragsim::CameraPath path(scene.camera);
  fragsim::World world(scene, {}, fragsim::explode(scene));
  const double dt = scene.sim.dt_s;
  std::vector<double> ms;
  std::vector<int> awake;
  ms.reserve(static_cast<std::size_t>(steps));
  for (int k = 0; k < settle + steps; ++k) {
    const double t = k * dt;
    const double start = thread_cpu_ms();
    world.set_camera(path.pose_at(t), path.velocity_at(t));
    world.step(dt);
    if (k >= settle) {
      ms.push_back(thread_cpu_ms() - start);
      awake.push_back(world.awake_count());
    }
  }
  if (const char* file = std::getenv("FRAGSIM_STEP_MS")) {
    std::FILE* f = std::fopen(file, "w");
    if (f == nullptr) throw std::invalid_argument(std::string("cannot write ") + file);
    std::fprintf(f, "step,ms,awake\n");
    for (std::size_t k = 0; k < ms.size(); ++k) {
      std::fprintf(f, "%zu,%.4f,%d\n", k + static_cast<std::size_t>(settle), ms[k], awake[k]);
    }
    std::fclose(f);
  }
  std::printf("%d,%s,%.4f,%.4f,%.1f,%d,%d,%d\n", world.fragment_count(), config.c_str(),
              quantile(ms, 0.5), quantile(ms, 0.95), peak_rss_mib(), steps, settle,
              world.awake_count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "scale_curve: %s\n", e.what());
    return 2;
  }
}
