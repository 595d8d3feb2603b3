#include "stress_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "io/atomic_file.hpp"
#include "io/number_format.hpp"
#include "sim/random.hpp"
#include "sim/scene_file.hpp"

namespace fragsim::stress {
namespace {

const Eigen::Vector3d kEye0{0.0, 1.6, 0.0};      // the camera's first eye position
const Eigen::Vector3d kForward{0.0, 0.0, -1.0};  // it looks down -z at t = 0

// Everything a stress scene is made of, before it becomes a Scene.
struct Spec {
  std::string name;
  int splits = 12;
  bool voronoi = false;  // object.pattern = voronoi with `pieces` cells, `cluster`
  int pieces = 1000;
  double cluster = 0.0;
  double size_m = 1.2;
  Placement placement = Placement::kAhead;
  double distance_m = 10.0;                             // ahead or behind the eye (kAhead, kBehind)
  Eigen::Vector3d lateral_m = Eigen::Vector3d::Zero();  // added to an ahead object's centre
  double dt_s = 1.0 / 60.0;
  bool collisions = false;
  Solver solver = Solver::kAuto;
  bool gravity = true;
  bool ground = true;
  double speed_mps = 5.0;  // explosion
  double jitter = 0.3;
  double spin_radps = 6.0;
  double toward_camera_mps = 0.0;
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // blast centre from the object centre
  CameraMotion motion = CameraMotion::kStill;
  double camera_speed_mps = 0.0;     // kMaxSpeed, kReversing (also max_speed_mps)
  double still_max_speed_mps = 3.0;  // V_c of a still camera
  // kPlayer: the bounds told to the strategies (the corner cases' extremes by default).
  double player_interval_s = -1.0;  // < 0: one step
  double player_accel_mps2 = std::numeric_limits<double>::infinity();
  double turn_rate_degps = 1e5;
  // kTrack: the track's sample spacing (< 0: one step) and how fast its view turns.
  double track_interval_s = -1.0;
  double track_turn_radps = 1.0;
  Eigen::Vector3d camera_dir = Eigen::Vector3d(0.0, 0.0, -1.0);  // unit
  double near_m = 0.1;
  double fovy_deg = 60.0;
  double edge_k = 1.0;
  double edge_a_max_mps2 = 50.0;
  double edge_min_a_max_mps2 = 50.0;
  double edge_min_margin_m = 0.05;
  double deflect_accel_mps2 = 60.0;
  double deflect_range_m = 6.0;
  Predictor predictor = Predictor::kThesis;
  Reach reach = Reach::kThesis;
  Horizon horizon = Horizon::kCamera;
  Replan replan = Replan::kNever;
  double wall_distance_m = 0.6;
  double wall_thickness_m = 0.05;
  double wall_restitution = 0.3;
};

const char* placement_name(Placement p) {
  switch (p) {
    case Placement::kAhead:
      return "ahead";
    case Placement::kAtEye:
      return "at-eye";
    case Placement::kBehind:
      return "behind";
    case Placement::kAtLens:
      return "0.05m-from-eye";
  }
  return "?";
}

const char* motion_name(CameraMotion m) {
  switch (m) {
    case CameraMotion::kStill:
      return "still";
    case CameraMotion::kMaxSpeed:
      return "max-speed";
    case CameraMotion::kReversing:
      return "reversing";
    case CameraMotion::kPlayer:
      return "player";
    case CameraMotion::kTrack:
      return "track";
  }
  return "?";
}

// A seeded random walk from the first eye position: speeds up to 0.999 V_c (the file's speed rule
// allows V_c exactly; the margin keeps rounding clear of it), a view turning at up to turn_radps,
// samples every interval_s from 0 past the end of the run.
std::vector<CameraSample> random_track(std::uint64_t seed, double v_c, double interval_s,
                                       double duration_s, double turn_radps) {
  Random rng(seed * 0xD1B54A32D192ED03ull + 7u);
  std::vector<CameraSample> out;
  CameraSample s;
  s.eye_m = kEye0;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  const int n = static_cast<int>(std::ceil(duration_s / interval_s)) + 2;
  for (int k = 0; k < n; ++k) {
    s.t_s = k * interval_s;
    if (k > 0) s.eye_m += velocity * interval_s;
    // The next leg: a new direction and a speed up to V_c, a tenth of them at the limit.
    Eigen::Vector3d dir(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (dir.norm() < 1e-3) dir = Eigen::Vector3d::UnitX();
    const double speed = 0.999 * v_c * (rng.uniform() < 0.1 ? 1.0 : rng.uniform());
    velocity = speed * dir.normalized();
    // The view: forward turned toward a random direction by at most turn_radps * interval_s,
    // up the world's up made orthogonal to it (x when forward is near vertical).
    Eigen::Vector3d target(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (target.norm() < 1e-3) target = kForward;
    const double step = std::min(turn_radps * interval_s, 3.0);
    s.forward = (s.forward + std::tan(std::min(step, 1.4)) * target.normalized()).normalized();
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    if (std::abs(up.dot(s.forward)) > 0.99) up = Eigen::Vector3d::UnitX();
    s.up = (up - up.dot(s.forward) * s.forward).normalized();
    out.push_back(s);
  }
  return out;
}

// Writes the samples as a camera track file and returns its path.
std::string write_track(const std::vector<CameraSample>& samples, const std::string& name) {
  std::string csv = "t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z\n";
  for (const CameraSample& c : samples) {
    const double v[10] = {c.t_s,         c.eye_m.x(),   c.eye_m.y(), c.eye_m.z(), c.forward.x(),
                          c.forward.y(), c.forward.z(), c.up.x(),    c.up.y(),    c.up.z()};
    for (int i = 0; i < 10; ++i) csv += (i ? "," : "") + format_double(v[i]);
    csv += '\n';
  }
  const std::string path = (std::filesystem::path(track_dir()) / name).string();
  write_file_atomically(path, csv);
  return path;
}

Eigen::Vector3d object_centre_for(const Spec& s) {
  switch (s.placement) {
    case Placement::kAhead:
      return kEye0 + s.distance_m * kForward + s.lateral_m;
    case Placement::kAtEye:
      return kEye0;
    case Placement::kBehind:
      return kEye0 - s.distance_m * kForward;
    case Placement::kAtLens:
      return kEye0 + 0.05 * kForward;
  }
  return kEye0;
}

// A number in three significant digits, for descriptions.
std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

StressCase build(const Spec& s, const Budget& budget, const std::string& id, std::uint64_t seed) {
  Scene sc;
  sc.name = "stress-" + s.name;
  const int fragments = s.voronoi ? s.pieces : s.splits * s.splits * s.splits;
  const int steps = budget.steps_for(fragments, s.collisions);
  sc.sim.dt_s = s.dt_s;
  sc.sim.duration_s = steps * s.dt_s;
  sc.sim.seed = seed;
  sc.sim.fragment_collisions = s.collisions;
  sc.sim.solver = s.solver;
  sc.sim.gravity_mps2 = s.gravity ? Eigen::Vector3d(0.0, -9.81, 0.0) : Eigen::Vector3d::Zero();

  const Eigen::Vector3d centre = object_centre_for(s);
  sc.object.centre_m = centre;
  // The object never starts in the ground: its bottom stays 5 cm above it.
  sc.object.size_m = std::min(s.size_m, 2.0 * (centre.y() - 0.05));
  sc.object.splits = s.splits;
  if (s.voronoi) {
    sc.object.pattern = DebrisPattern::kVoronoi;
    sc.object.pieces = s.pieces;
    sc.object.cluster = s.cluster;
  }
  sc.explosion.speed_mps = s.speed_mps;
  sc.explosion.jitter = s.jitter;
  sc.explosion.spin_radps = s.spin_radps;
  sc.explosion.toward_camera_mps = s.toward_camera_mps;
  sc.explosion.offset_m = s.offset_m;
  sc.ground.enabled = s.ground;

  CameraDef& cam = sc.camera;
  cam.near_m = s.near_m;
  cam.fovy_deg = s.fovy_deg;
  // An object ahead is looked at (as in front.ini); otherwise the camera looks 10 m ahead.
  cam.look_at_m = {s.placement == Placement::kAhead ? centre
                                                    : Eigen::Vector3d(kEye0 + 10.0 * kForward)};
  const double v = s.camera_speed_mps;
  switch (s.motion) {
    case CameraMotion::kStill:
      cam.waypoints_m = {kEye0};
      cam.speed_mps = 0.0;
      cam.max_speed_mps = s.still_max_speed_mps;
      break;
    case CameraMotion::kMaxSpeed: {
      // Long enough that the camera never reaches the end within the run.
      Eigen::Vector3d end = kEye0 + (v * sc.sim.duration_s + 1.0) * s.camera_dir;
      if ((end - cam.look_at_m.front()).norm() <= 2.0 * cam.near_m) end.y() += 1.0;
      cam.waypoints_m = {kEye0, end};
      cam.speed_mps = v;
      cam.max_speed_mps = v;
      break;
    }
    case CameraMotion::kReversing: {
      // At t = k dt the camera is exactly at waypoint k: the velocity flips every step. Two
      // spare waypoints keep it moving through the last step (steps <= 300 < 1000 waypoints).
      const Eigen::Vector3d other = kEye0 + v * s.dt_s * s.camera_dir;
      cam.waypoints_m.clear();
      for (int k = 0; k < steps + 2; ++k) cam.waypoints_m.push_back(k % 2 == 0 ? kEye0 : other);
      cam.speed_mps = v;
      cam.max_speed_mps = v;
      break;
    }
    case CameraMotion::kPlayer:
      cam.mode = CameraMode::kPlayer;
      cam.waypoints_m = {kEye0};
      cam.speed_mps = 0.0;
      cam.max_speed_mps = v;
      cam.player_interval_s = s.player_interval_s < 0.0 ? s.dt_s : s.player_interval_s;
      cam.player_accel_mps2 = s.player_accel_mps2;
      cam.turn_rate_degps = s.turn_rate_degps;
      sc.explosion.aim = ExplosionAim::kPresent;
      sc.strategies.edge_min.camera_model = CameraModel::kBoundedAccel;
      break;
    case CameraMotion::kTrack: {
      cam.mode = CameraMode::kTrack;
      cam.waypoints_m = {kEye0};
      cam.speed_mps = 0.0;
      cam.max_speed_mps = v;
      // At most ~2,000 samples a file, whatever the step.
      const double h = std::max(s.track_interval_s < 0.0 ? s.dt_s : s.track_interval_s,
                                sc.sim.duration_s / 2000.0);
      cam.track_samples = random_track(seed, v, h, sc.sim.duration_s, s.track_turn_radps);
      cam.track_file =
          write_track(cam.track_samples, "fragsim-stress-track-" + std::to_string(seed) + ".csv");
      break;
    }
  }

  sc.strategies.wall.distance_m = s.wall_distance_m;
  sc.strategies.wall.thickness_m = std::min(s.wall_thickness_m, 1.5 * s.wall_distance_m);
  sc.strategies.wall.restitution = s.wall_restitution;
  sc.strategies.deflect_all.accel_mps2 = s.deflect_accel_mps2;
  sc.strategies.deflect_all.range_m = s.deflect_range_m;
  sc.strategies.near_plane.min_near_m = std::min(sc.strategies.near_plane.min_near_m, cam.near_m);
  sc.strategies.edge.k = s.edge_k;
  sc.strategies.edge.a_max_mps2 = s.edge_a_max_mps2;
  sc.strategies.edge.predictor = s.predictor;
  sc.strategies.edge.reach = s.reach;
  sc.strategies.edge.horizon = s.horizon;
  sc.strategies.edge.replan = s.replan;
  sc.strategies.edge_min.a_max_mps2 = s.edge_min_a_max_mps2;
  sc.strategies.edge_min.margin_m = s.edge_min_margin_m;

  StressCase c;
  c.id = id;
  c.seed = seed;
  c.description =
      std::to_string(fragments) +
      (s.voronoi ? " Voronoi cells (cluster " + g3(s.cluster) + ")" : std::string(" fragments")) +
      ", " + std::to_string(steps) + " steps of " + g3(s.dt_s) + " s; blast " +
      placement_name(s.placement) + " at " + g3(s.speed_mps) + " m/s; camera " +
      motion_name(s.motion) + " " +
      (s.motion == CameraMotion::kStill ? "(V_c " + g3(cam.max_speed_mps) + ")" : g3(v)) +
      " m/s; collisions " + (s.collisions ? "on" : "off") + "; " +
      (sc.sim.uses_exact_solver() ? "exact" : "quick") + " solver; gravity " +
      (s.gravity ? "on" : "off") + "; ground " + (s.ground ? "on" : "off") + "; edge.k " +
      g3(s.edge_k) + "; a_max edge " + g3(s.edge_a_max_mps2) + ", edge-min " +
      g3(s.edge_min_a_max_mps2) + ", deflect-all " + g3(s.deflect_accel_mps2);
  c.scene = sc;
  // The scene must be valid and survive its own INI (the failure report relies on it).
  validate_scene(c.scene);
  return c;
}

// Uniform on a log scale in [lo, hi].
double log_uniform(Random& rng, double lo, double hi) {
  return std::exp(rng.uniform(std::log(lo), std::log(hi)));
}

// 0 with probability p0, `hi` with probability p_hi, else log-uniform in [lo, hi].
double extreme(Random& rng, double p0, double p_hi, double lo, double hi) {
  const double u = rng.uniform();
  if (u < p0) return 0.0;
  if (u < p0 + p_hi) return hi;
  return log_uniform(rng, lo, hi);
}

Eigen::Vector3d unit_vector(Random& rng) {
  for (;;) {
    const Eigen::Vector3d v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double n = v.norm();
    if (n > 0.1 && n <= 1.0) return v / n;
  }
}

}  // namespace

std::string track_dir() {
  if (const char* env = std::getenv("FRAGSIM_STRESS_DIR")) {
    if (*env) return env;
  }
  return std::filesystem::temp_directory_path().string();
}

int Budget::steps_for(int fragments, bool collisions) const {
  const double work =
      scale * static_cast<double>(collisions ? collision_fragment_steps : fragment_steps);
  const double steps = std::floor(work / std::max(fragments, 1));
  return static_cast<int>(
      std::clamp(steps, static_cast<double>(min_steps), static_cast<double>(max_steps)));
}

Budget budget_from_environment() {
  Budget b;
#if defined(__SANITIZE_ADDRESS__)
  b.scale = 0.25;
#endif
  if (const char* env = std::getenv("FRAGSIM_STRESS_SCALE")) {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end != env && std::isfinite(v) && v > 0.0) b.scale = v;
  }
  return b;
}

std::vector<StressCase> corner_cases(const Budget& budget) {
  std::vector<StressCase> out;
  auto add = [&](const Spec& s) { out.push_back(build(s, budget, "corner/" + s.name, 1)); };

  Spec s;
  // docs/method.md section 7: a fragment spawned inside the camera with zero velocity, zero
  // gravity, the smallest step.
  s = Spec{};
  s.name = "one-fragment-inside-camera-at-rest";
  s.splits = 1;
  s.size_m = 0.1;
  s.placement = Placement::kAtEye;
  s.speed_mps = 0.0;
  s.jitter = 0.0;
  s.spin_radps = 0.0;
  s.gravity = false;
  s.dt_s = 1e-3;
  add(s);

  // One fragment 5 cm from the lens flying at it at 200 m/s with the largest step.
  s = Spec{};
  s.name = "one-fragment-at-lens-200mps-dt0.1";
  s.splits = 1;
  s.size_m = 0.05;
  s.placement = Placement::kAtLens;
  s.offset_m = {0.0, 0.0, -1.0};
  s.speed_mps = 200.0;
  s.jitter = 0.0;
  s.dt_s = 0.1;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 1e6;
  s.edge_min_a_max_mps2 = 1e6;
  s.deflect_accel_mps2 = 1e6;
  add(s);

  // 19,683 fragments around the eye, at rest, zero gravity: every fragment starts inside the
  // reachable ball (t_C = t) and many inside the camera body (|P_pc| -> 0).
  s = Spec{};
  s.name = "20k-at-eye-at-rest-zero-g-quick";
  s.splits = 27;
  // The wall's box sits inside this cube: every fragment it overlaps joins one ODE island, which
  // the exact solver takes minutes for (stress_test.cpp, WallIsland); QuickStep is linear in it.
  s.solver = Solver::kQuick;
  s.size_m = 1.2;
  s.placement = Placement::kAtEye;
  s.speed_mps = 0.0;
  s.jitter = 0.0;
  s.spin_radps = 0.0;
  s.gravity = false;
  s.dt_s = 1e-3;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 1e6;
  s.edge_min_a_max_mps2 = 1e6;
  s.deflect_accel_mps2 = 1e6;
  add(s);

  // 19,683 fragments at 200 m/s, the largest step, the camera rushing at them.
  s = Spec{};
  s.name = "20k-200mps-dt0.1-camera-300mps";
  s.splits = 27;
  s.placement = Placement::kAhead;
  s.distance_m = 5.0;
  s.speed_mps = 200.0;
  s.jitter = 1.0;
  s.dt_s = 0.1;
  s.motion = CameraMotion::kMaxSpeed;
  s.camera_speed_mps = 300.0;
  s.camera_dir = kForward;
  add(s);

  // 19,683 fragments with the exact solver (the default without collisions) thrown at 200 m/s
  // with the largest step: a fragment falls up to 20 m through the ground in one step and the
  // contact's correction, capped at 10 m/s, lifts it back.
  s = Spec{};
  s.name = "20k-exact-200mps-dt0.1-into-ground";
  s.splits = 27;
  s.placement = Placement::kAhead;
  s.distance_m = 10.0;
  s.speed_mps = 200.0;
  s.jitter = 0.5;
  s.dt_s = 0.1;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 1e6;
  s.edge_min_a_max_mps2 = 1e6;
  s.deflect_accel_mps2 = 1e6;
  add(s);

  // The huge gain and caps with fragment collisions on and a blast aimed at the lens.
  s = Spec{};
  s.name = "k1e9-amax1e6-collisions-aimed";
  s.splits = 6;
  s.placement = Placement::kAhead;
  s.distance_m = 8.0;
  s.speed_mps = 5.0;
  s.toward_camera_mps = 50.0;
  s.collisions = true;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 1e6;
  s.edge_min_a_max_mps2 = 1e6;
  s.deflect_accel_mps2 = 1e6;
  s.deflect_range_m = 50.0;
  add(s);

  // No acceleration allowed at all, with an infinite appetite for it.
  s = Spec{};
  s.name = "amax0-k1e9-aimed";
  s.splits = 8;
  s.distance_m = 6.0;
  s.toward_camera_mps = 20.0;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 0.0;
  s.edge_min_a_max_mps2 = 0.0;
  s.deflect_accel_mps2 = 0.0;
  s.replan = Replan::kAlways;
  add(s);

  // A camera turning every step at 300 m/s with the wall carried in front of it: the wall's
  // kinematic box jumps 30 m a step into the debris.
  s = Spec{};
  s.name = "reversing-300mps-dt0.1-wall";
  s.splits = 10;
  s.placement = Placement::kAtEye;
  s.speed_mps = 2.0;
  s.dt_s = 0.1;
  s.motion = CameraMotion::kReversing;
  s.camera_speed_mps = 300.0;
  s.camera_dir = kForward;
  s.deflect_accel_mps2 = 1e6;
  add(s);

  // A reversing camera at game speed, smallest step, blast behind it and aimed at it.
  s = Spec{};
  s.name = "reversing-10mps-dt1e-3-behind-aimed";
  s.splits = 8;
  s.placement = Placement::kBehind;
  s.distance_m = 1.0;
  s.toward_camera_mps = 30.0;
  s.dt_s = 1e-3;
  s.motion = CameraMotion::kReversing;
  s.camera_speed_mps = 10.0;
  s.camera_dir = Eigen::Vector3d(1.0, 0.0, 0.0);
  add(s);

  // A player turning at once and changing its mind every step at 300 m/s, the largest step, the
  // blast at the eye: every camera bound the strategies are told is at its extreme.
  s = Spec{};
  s.name = "player-300mps-dt0.1-instant-at-eye";
  s.splits = 10;
  s.placement = Placement::kAtEye;
  s.speed_mps = 5.0;
  s.dt_s = 0.1;
  s.motion = CameraMotion::kPlayer;
  s.camera_speed_mps = 300.0;
  add(s);

  // A game-speed player with instant turns, smallest step, an aimed blast ahead.
  s = Spec{};
  s.name = "player-6mps-dt1e-3-instant-aimed";
  s.splits = 8;
  s.placement = Placement::kAhead;
  s.distance_m = 4.0;
  s.toward_camera_mps = 20.0;
  s.dt_s = 1e-3;
  s.motion = CameraMotion::kPlayer;
  s.camera_speed_mps = 6.0;
  add(s);

  // Dense debris colliding at 200 m/s with the smallest step.
  s = Spec{};
  s.name = "collisions-200mps-dt1e-3";
  s.splits = 12;
  s.speed_mps = 200.0;
  s.jitter = 0.5;
  s.collisions = true;
  s.dt_s = 1e-3;
  add(s);

  // Collisions at rest in zero gravity with the largest step: fragments 2% apart, pushed by
  // deflect-all at 1e6 m/s^2 into each other.
  s = Spec{};
  s.name = "collisions-at-rest-zero-g-dt0.1-deflect1e6";
  s.splits = 10;
  s.placement = Placement::kAtLens;
  s.speed_mps = 0.0;
  s.jitter = 0.0;
  s.spin_radps = 0.0;
  s.gravity = false;
  s.collisions = true;
  s.dt_s = 0.1;
  s.deflect_accel_mps2 = 1e6;
  s.edge_k = 1e9;
  s.edge_a_max_mps2 = 1e6;
  s.edge_min_a_max_mps2 = 1e6;
  add(s);

  // Spin at the validated limit (1000 rad/s, 100 rad per step at dt = 0.1) onto the ground.
  s = Spec{};
  s.name = "spin1000-dt0.1-ground";
  s.splits = 5;
  s.spin_radps = 1000.0;
  s.speed_mps = 20.0;
  s.dt_s = 0.1;
  add(s);
  return out;
}

StressCase random_case(std::uint64_t seed, const Budget& budget) {
  Random rng(seed * 0x9E3779B97F4A7C15ull + 12345u);
  Spec s;
  s.name = "random-" + std::to_string(seed);
  // 1 .. 27 pieces per axis, log-spread: as many small counts as large ones.
  s.splits = std::clamp(static_cast<int>(std::lround(log_uniform(rng, 1.0, 27.0))), 1, 27);
  s.collisions = rng.uniform() < 0.3;
  // Collisions between thousands of packed fragments cost ~100 ms a step: at most 14^3 there.
  if (s.collisions) s.splits = std::min(s.splits, 14);
  // Without collisions: the exact solver (the default) up to 7^3 fragments, QuickStep above.
  // The `wall` strategy's kinematic box joins every fragment touching it in a step into one ODE
  // island, and the exact solver is cubic in an island's size (615 fragments on the wall: 32 s
  // for one step; stress_test.cpp, WallIsland), so large scenes would take minutes.
  const bool exact = rng.uniform() < 0.8;
  if (!s.collisions) s.solver = s.splits <= 7 && exact ? Solver::kAuto : Solver::kQuick;
  s.size_m = log_uniform(rng, 0.1, 3.0);
  const double p = rng.uniform();
  s.placement = p < 0.4   ? Placement::kAhead
                : p < 0.6 ? Placement::kAtEye
                : p < 0.8 ? Placement::kBehind
                          : Placement::kAtLens;
  s.distance_m = s.placement == Placement::kBehind ? rng.uniform(0.3, 5.0) : rng.uniform(1.0, 30.0);
  s.lateral_m = {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), 0.0};
  const double d = rng.uniform();
  s.dt_s = d < 0.15 ? 1e-3 : d < 0.3 ? 0.1 : log_uniform(rng, 1e-3, 0.1);
  s.gravity = rng.uniform() >= 0.3;
  s.ground = rng.uniform() >= 0.1;
  s.speed_mps = extreme(rng, 0.1, 0.15, 0.1, 200.0);
  s.jitter = rng.uniform();
  s.spin_radps = rng.uniform(0.0, 50.0);
  s.toward_camera_mps = rng.uniform() < 0.5 ? 0.0 : rng.uniform(0.0, 50.0);
  s.offset_m =
      rng.uniform() < 0.5 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(s.size_m * unit_vector(rng));
  const double m = rng.uniform();
  s.motion = m < 1.0 / 3.0   ? CameraMotion::kStill
             : m < 2.0 / 3.0 ? CameraMotion::kMaxSpeed
                             : CameraMotion::kReversing;
  s.camera_speed_mps = log_uniform(rng, 0.5, 300.0);
  s.still_max_speed_mps = extreme(rng, 0.2, 0.1, 0.1, 300.0);
  s.camera_dir = unit_vector(rng);
  s.near_m = rng.uniform() < 0.7 ? 0.1 : log_uniform(rng, 0.001, 1.0);
  s.fovy_deg = rng.uniform(20.0, 120.0);
  s.edge_k = extreme(rng, 0.1, 0.15, 1e-6, 1e9);
  s.edge_a_max_mps2 = extreme(rng, 0.1, 0.15, 1e-3, 1e6);
  s.edge_min_a_max_mps2 = extreme(rng, 0.1, 0.15, 1e-3, 1e6);
  s.edge_min_margin_m = rng.uniform(0.0, 1.0);
  s.deflect_accel_mps2 = extreme(rng, 0.05, 0.3, 1.0, 1e6);
  s.deflect_range_m = rng.uniform(0.0, 50.0);
  s.predictor = rng.uniform() < 0.5 ? Predictor::kThesis : Predictor::kDiscrete;
  s.reach = rng.uniform() < 0.5 ? Reach::kThesis : Reach::kGrowing;
  s.horizon = rng.uniform() < 0.5 ? Horizon::kCamera : Horizon::kGround;
  const double r = rng.uniform();
  s.replan = r < 1.0 / 3.0 ? Replan::kNever : r < 2.0 / 3.0 ? Replan::kContact : Replan::kAlways;
  s.wall_distance_m = rng.uniform(0.2, 3.0);
  s.wall_thickness_m = rng.uniform(0.01, 0.3);
  s.wall_restitution = rng.uniform();
  // Drawn last, so the draws above keep the values they had before these existed. A fifth of
  // the cameras a player with drawn bounds, a fifth a track file; a quarter of the objects
  // Voronoi cells, as many as the grid would have had.
  const double mode = rng.uniform();
  const double player_interval =
      rng.uniform() < 0.2 ? std::numeric_limits<double>::infinity() : log_uniform(rng, 1e-3, 2.0);
  const double player_accel =
      rng.uniform() < 0.25 ? std::numeric_limits<double>::infinity() : log_uniform(rng, 0.1, 1e4);
  const double turn_rate = log_uniform(rng, 1.0, 1e5);
  const double track_interval = rng.uniform() < 0.5 ? -1.0 : log_uniform(rng, 1e-3, 0.5);
  const double track_turn = log_uniform(rng, 0.01, 30.0);
  const bool voronoi = rng.uniform() < 0.25;
  const double cluster = rng.uniform() < 0.5 ? 0.0 : rng.uniform(0.0, 0.95);
  if (mode < 0.2) {
    s.motion = CameraMotion::kPlayer;
    s.player_interval_s = player_interval;
    s.player_accel_mps2 = player_accel;
    s.turn_rate_degps = turn_rate;
  } else if (mode < 0.4) {
    s.motion = CameraMotion::kTrack;
    s.track_interval_s = track_interval;
    s.track_turn_radps = track_turn;
  }
  if (voronoi) {
    s.voronoi = true;
    s.pieces = s.splits * s.splits * s.splits;
    s.cluster = cluster;
  }
  return build(s, budget, "random/" + std::to_string(seed), seed);
}

StressCase wall_island_case(int splits) {
  Spec s;
  s.name = "wall-island-" + std::to_string(splits);
  s.splits = splits;
  s.size_m = 2.86;
  s.placement = Placement::kAhead;
  s.distance_m = 11.3;
  s.speed_mps = 0.17;
  s.jitter = 0.14;
  s.spin_radps = 47.0;
  s.toward_camera_mps = 40.0;
  s.offset_m = {0.0, 2.0, -2.0};
  s.gravity = false;
  s.dt_s = 0.0966;
  s.wall_distance_m = 2.57;
  s.wall_thickness_m = 0.2;
  s.wall_restitution = 0.55;
  Budget b;
  b.fragment_steps = 16L * splits * splits * splits;  // 16 steps: 1.5 s, the debris arrives
  return build(s, b, "wall-island/" + std::to_string(splits), 39);
}

std::vector<StressCase> all_cases(const Budget& budget, int random_count) {
  std::vector<StressCase> out = corner_cases(budget);
  for (int k = 1; k <= random_count; ++k) {
    out.push_back(random_case(static_cast<std::uint64_t>(k), budget));
  }
  return out;
}

}  // namespace fragsim::stress
