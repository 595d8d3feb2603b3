#include "sim/scene_file.hpp"

#include "io/number_format.hpp"
#include "sim/camera_track_file.hpp"

#include <boost/program_options/errors.hpp>
#include <boost/program_options/value_semantic.hpp>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace fragsim {
namespace po = boost::program_options;
namespace {

// A value that breaks a key's rule; the caller adds where it came from.
struct ValueError {
  std::string rule;
};

struct KeySpec {
  std::string name;
  std::string help;  // unit and meaning
  std::function<void(Scene&, const std::string&)> set;
  std::function<std::string(const Scene&)> get;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

double parse_double(const std::string& text) {
  const std::string s = trim(text);
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    throw ValueError{"not a number"};
  }
  if (!std::isfinite(v)) throw ValueError{"must be finite"};
  return v;
}

long long parse_integer(const std::string& text) {
  const std::string s = trim(text);
  long long v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    throw ValueError{"not a whole number"};
  }
  return v;
}

Eigen::Vector3d parse_vec3(const std::string& text) {
  std::string s = text;
  for (char& c : s) {
    if (c == ',') c = ' ';
  }
  std::istringstream in(s);
  Eigen::Vector3d v;
  std::string word;
  int n = 0;
  while (in >> word) {
    if (n == 3) throw ValueError{"expected three numbers x y z"};
    v[n++] = parse_double(word);
  }
  if (n != 3) throw ValueError{"expected three numbers x y z"};
  return v;
}

std::string format_vec3(const Eigen::Vector3d& v) {
  return format_double(v.x()) + " " + format_double(v.y()) + " " + format_double(v.z());
}

// An interval rule: [lo, hi] with either end open.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    if (std::isinf(hi))
      return std::string(lo_open ? "must be > " : "must be >= ") + format_double(lo);
    if (std::isinf(lo))
      return std::string(hi_open ? "must be < " : "must be <= ") + format_double(hi);
    return "must be in " + std::string(lo_open ? "(" : "[") + format_double(lo) + ", " +
           format_double(hi) + (hi_open ? ")" : "]");
  }
};

constexpr double kInf = std::numeric_limits<double>::infinity();
Range closed(double lo, double hi) {
  return {lo, hi, false, false};
}
Range open_closed(double lo, double hi) {
  return {lo, hi, true, false};
}
Range open(double lo, double hi) {
  return {lo, hi, true, true};
}

template <typename Get>
KeySpec real(std::string name, std::string help, Get field, Range range) {
  return {std::move(name), std::move(help),
          [field, range](Scene& s, const std::string& text) {
            const double v = parse_double(text);
            if (!range.contains(v)) throw ValueError{range.text()};
            field(s) = v;
          },
          [field](const Scene& s) { return format_double(field(const_cast<Scene&>(s))); }};
}

template <typename Get>
KeySpec integer(std::string name, std::string help, Get field, long long lo, long long hi) {
  return {std::move(name), std::move(help),
          [field, lo, hi](Scene& s, const std::string& text) {
            const long long v = parse_integer(text);
            if (v < lo || v > hi) {
              throw ValueError{"must be a whole number in [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "]"};
            }
            field(s) = static_cast<std::remove_reference_t<decltype(field(s))>>(v);
          },
          [field](const Scene& s) { return std::to_string(field(const_cast<Scene&>(s))); }};
}

template <typename Get>
KeySpec boolean(std::string name, std::string help, Get field) {
  return {
      std::move(name), std::move(help),
      [field](Scene& s, const std::string& text) {
        const std::string v = trim(text);
        if (v == "on" || v == "true" || v == "yes" || v == "1") {
          field(s) = true;
        } else if (v == "off" || v == "false" || v == "no" || v == "0") {
          field(s) = false;
        } else {
          throw ValueError{"expected on or off"};
        }
      },
      [field](const Scene& s) { return std::string(field(const_cast<Scene&>(s)) ? "on" : "off"); }};
}

template <typename Get>
KeySpec vec3(std::string name, std::string help, Get field, Range each) {
  return {std::move(name), std::move(help),
          [field, each](Scene& s, const std::string& text) {
            const Eigen::Vector3d v = parse_vec3(text);
            for (int i = 0; i < 3; ++i) {
              if (!each.contains(v[i])) throw ValueError{"each component " + each.text()};
            }
            field(s) = v;
          },
          [field](const Scene& s) { return format_vec3(field(const_cast<Scene&>(s))); }};
}

template <typename Enum, typename Get>
KeySpec choice(std::string name, std::string help, Get field,
               std::vector<std::pair<std::string, Enum>> names) {
  return {std::move(name), std::move(help),
          [field, names](Scene& s, const std::string& text) {
            const std::string v = trim(text);
            std::string known;
            for (const auto& [n, e] : names) {
              if (n == v) {
                field(s) = e;
                return;
              }
              known += (known.empty() ? "" : " | ") + n;
            }
            throw ValueError{"expected " + known};
          },
          [field, names](const Scene& s) {
            for (const auto& [n, e] : names) {
              if (field(const_cast<Scene&>(s)) == e) return n;
            }
            return std::string("?");
          }};
}

// A list of points 'x y z; x y z; ...' (at least one, at most 1000).
template <typename Get>
KeySpec points(std::string name, std::string help, Get field) {
  return {std::move(name), std::move(help),
          [field](Scene& s, const std::string& text) {
            std::vector<Eigen::Vector3d> pts;
            std::istringstream in(text);
            std::string item;
            while (std::getline(in, item, ';')) {
              if (trim(item).empty()) continue;
              if (pts.size() == 1000) throw ValueError{"at most 1000 points"};
              pts.push_back(parse_vec3(item));
              for (int i = 0; i < 3; ++i) {
                if (std::abs(pts.back()[i]) > 1e6)
                  throw ValueError{"each component must be in [-1e6, 1e6]"};
              }
            }
            if (pts.empty()) throw ValueError{"expected at least one point 'x y z'"};
            field(s) = pts;
          },
          [field](const Scene& s) {
            std::string out;
            for (const Eigen::Vector3d& p : field(const_cast<Scene&>(s))) {
              out += (out.empty() ? "" : "; ") + format_vec3(p);
            }
            return out;
          }};
}

// A plain text value (a file name, a strategy name): one line, no quotes or commas, so it
// survives config.ini and CSV cells.
template <typename Get>
KeySpec text(std::string name, std::string help, Get field) {
  return {std::move(name), std::move(help),
          [field](Scene& s, const std::string& v) {
            const std::string t = trim(v);
            if (t.find_first_of(",\"\n") != std::string::npos) {
              throw ValueError{"must be one line without commas or quotes"};
            }
            field(s) = t;
          },
          [field](const Scene& s) { return field(const_cast<Scene&>(s)); }};
}

// A duration or rate for which `inf` means "never" or "at once"; every other value is finite.
template <typename Get>
KeySpec real_or_inf(std::string name, std::string help, Get field, Range range) {
  return {std::move(name), std::move(help),
          [field, range](Scene& s, const std::string& text) {
            const std::string t = trim(text);
            if (t == "inf") {
              field(s) = std::numeric_limits<double>::infinity();
              return;
            }
            const double v = parse_double(t);
            if (!range.contains(v)) throw ValueError{range.text() + ", or inf"};
            field(s) = v;
          },
          [field](const Scene& s) {
            const double v = field(const_cast<Scene&>(s));
            return std::isinf(v) ? std::string("inf") : format_double(v);
          }};
}

const std::vector<KeySpec>& keys() {
  static const std::vector<KeySpec> table = [] {
    const std::vector<std::pair<std::string, Predictor>> predictors{
        {"thesis", Predictor::kThesis}, {"discrete", Predictor::kDiscrete}};
    const std::vector<std::pair<std::string, Reach>> reaches{{"thesis", Reach::kThesis},
                                                             {"growing", Reach::kGrowing}};
    const std::vector<std::pair<std::string, Horizon>> horizons{{"camera", Horizon::kCamera},
                                                                {"ground", Horizon::kGround}};
    const std::vector<std::pair<std::string, Replan>> replans{
        {"never", Replan::kNever}, {"contact", Replan::kContact}, {"always", Replan::kAlways}};
    std::vector<KeySpec> t;
    t.push_back({"name", "the scene's name in reports",
                 [](Scene& s, const std::string& v) {
                   const std::string n = trim(v);
                   if (n.empty() || n.find_first_of(",\"\n") != std::string::npos) {
                     throw ValueError{"must be non-empty, without commas or quotes"};
                   }
                   s.name = n;
                 },
                 [](const Scene& s) { return s.name; }});
    // [simulation]
    t.push_back(real(
        "simulation.dt_s", "s; physics step", [](Scene& s) -> double& { return s.sim.dt_s; },
        open_closed(0, 1)));
    t.push_back(real(
        "simulation.duration_s", "s; simulated time after the explosion",
        [](Scene& s) -> double& { return s.sim.duration_s; }, open_closed(0, 3600)));
    t.push_back({"simulation.seed", "random seed of the explosion and of ODE's solver",
                 [](Scene& s, const std::string& v) {
                   const std::string x = trim(v);
                   std::uint64_t seed = 0;
                   const auto res = std::from_chars(x.data(), x.data() + x.size(), seed);
                   if (x.empty() || res.ec != std::errc() || res.ptr != x.data() + x.size()) {
                     throw ValueError{"must be a whole number in [0, 2^64)"};
                   }
                   s.sim.seed = seed;
                 },
                 [](const Scene& s) { return std::to_string(s.sim.seed); }});
    t.push_back(boolean("simulation.fragment_collisions",
                        "on|off; fragments collide with each other (off: no pair is tested)",
                        [](Scene& s) -> bool& { return s.sim.fragment_collisions; }));
    t.push_back(vec3(
        "simulation.gravity_mps2", "m/s^2; gravity vector",
        [](Scene& s) -> Eigen::Vector3d& { return s.sim.gravity_mps2; }, closed(-1000, 1000)));
    t.push_back(choice<Solver>(
        "simulation.solver",
        "auto | exact | quick; ODE stepper (auto: exact unless fragments collide with each "
        "other or with the wall strategy's wall, then quick)",
        [](Scene& s) -> Solver& { return s.sim.solver; },
        {{"auto", Solver::kAuto}, {"exact", Solver::kExact}, {"quick", Solver::kQuick}}));
    t.push_back(integer(
        "simulation.solver_iterations", "dWorldQuickStep iterations",
        [](Scene& s) -> int& { return s.sim.solver_iterations; }, 1, 1000));
    t.push_back(boolean("simulation.auto_disable",
                        "on|off; ODE's auto-disable: a fragment at rest is no longer stepped "
                        "until something touches or pushes it",
                        [](Scene& s) -> bool& { return s.sim.auto_disable; }));
    t.push_back(boolean("simulation.cull_resting",
                        "on|off; a fragment at rest, out of view and away from the camera leaves "
                        "collision detection and stepping until it could matter again",
                        [](Scene& s) -> bool& { return s.sim.cull_resting; }));
    t.push_back(real(
        "simulation.rest_linear_mps",
        "m/s; at rest: slower than this (and rest_angular_radps) for rest_steps steps while "
        "touching something",
        [](Scene& s) -> double& { return s.sim.rest_linear_mps; }, closed(0, 1000)));
    t.push_back(real(
        "simulation.rest_angular_radps", "rad/s; at rest: turning slower than this",
        [](Scene& s) -> double& { return s.sim.rest_angular_radps; }, closed(0, 1000)));
    t.push_back(integer(
        "simulation.rest_steps",
        "steps in a row below both thresholds before a fragment is at rest",
        [](Scene& s) -> int& { return s.sim.rest_steps; }, 1, 1000000));
    // [object]
    t.push_back(vec3(
        "object.centre_m", "m; centre of the cube",
        [](Scene& s) -> Eigen::Vector3d& { return s.object.centre_m; }, closed(-1e6, 1e6)));
    t.push_back(real(
        "object.size_m", "m; edge of the cube", [](Scene& s) -> double& { return s.object.size_m; },
        open_closed(0, 1000)));
    t.push_back(real(
        "object.distance_m",
        "m; if > 0, the cube is moved along the line from the camera's first "
        "waypoint through centre_m to this distance from it (0: centre_m as is)",
        [](Scene& s) -> double& { return s.object.distance_m; }, closed(0, 1e6)));
    t.push_back(integer(
        "object.splits", "pieces per axis; splits^3 fragments",
        [](Scene& s) -> int& { return s.object.splits; }, 1, 64));
    t.push_back(real(
        "object.density_kgpm3", "kg/m^3",
        [](Scene& s) -> double& { return s.object.density_kgpm3; }, open_closed(0, 1e5)));
    t.push_back(real(
        "object.gap", "share by which each fragment is shrunk, so none touch at t = 0",
        [](Scene& s) -> double& { return s.object.gap; }, closed(0, 0.5)));
    // [explosion]
    t.push_back(vec3(
        "explosion.offset_m", "m; blast centre relative to the cube's centre",
        [](Scene& s) -> Eigen::Vector3d& { return s.explosion.offset_m; }, closed(-1e6, 1e6)));
    t.push_back(real(
        "explosion.speed_mps", "m/s; radial speed away from the blast centre",
        [](Scene& s) -> double& { return s.explosion.speed_mps; }, closed(0, 1000)));
    t.push_back(real(
        "explosion.jitter", "relative random variation of each fragment's velocity",
        [](Scene& s) -> double& { return s.explosion.jitter; }, closed(0, 1)));
    t.push_back(real(
        "explosion.spin_radps", "rad/s; largest random spin of a fragment",
        [](Scene& s) -> double& { return s.explosion.spin_radps; }, closed(0, 1000)));
    t.push_back(real(
        "explosion.toward_camera_mps",
        "m/s; aims the blast: added ballistic velocity carrying the cube's centre "
        "to the moving camera's eye (0 = undirected)",
        [](Scene& s) -> double& { return s.explosion.toward_camera_mps; }, closed(0, 1000)));
    t.push_back(choice<ExplosionAim>(
        "explosion.aim",
        "future | present; the aimed blast goes where the camera will be when the debris "
        "arrives (scene set-up that peeks), or where it is at t = 0 (all a game knows)",
        [](Scene& s) -> ExplosionAim& { return s.explosion.aim; },
        {{"future", ExplosionAim::kFuture}, {"present", ExplosionAim::kPresent}}));
    // [ground]
    t.push_back(boolean("ground.enabled", "on|off; an infinite ground plane",
                        [](Scene& s) -> bool& { return s.ground.enabled; }));
    t.push_back(real(
        "ground.height_m", "m; height of the ground plane",
        [](Scene& s) -> double& { return s.ground.height_m; }, closed(-1e6, 1e6)));
    t.push_back(real(
        "ground.friction", "Coulomb friction coefficient",
        [](Scene& s) -> double& { return s.ground.friction; }, closed(0, 100)));
    t.push_back(real(
        "ground.restitution", "bounce, 0 to 1",
        [](Scene& s) -> double& { return s.ground.restitution; }, closed(0, 1)));
    // [camera]
    t.push_back(choice<CameraMode>(
        "camera.mode",
        "path | track | player; where the camera's motion comes from: the waypoints, a CSV file "
        "of timed poses, or a seeded model of a player with a gamepad",
        [](Scene& s) -> CameraMode& { return s.camera.mode; },
        {{"path", CameraMode::kPath},
         {"track", CameraMode::kTrack},
         {"player", CameraMode::kPlayer}}));
    t.push_back(points(
        "camera.waypoints_m",
        "m; the camera's path, points 'x y z' separated by ';' (player: the start is the first)",
        [](Scene& s) -> std::vector<Eigen::Vector3d>& { return s.camera.waypoints_m; }));
    t.push_back(points(
        "camera.look_at_m",
        "m; the point the camera looks at, or one point per waypoint (interpolated along the "
        "path, so the view pans)",
        [](Scene& s) -> std::vector<Eigen::Vector3d>& { return s.camera.look_at_m; }));
    t.push_back(real(
        "camera.speed_mps", "m/s; speed along the waypoints",
        [](Scene& s) -> double& { return s.camera.speed_mps; }, closed(0, 1000)));
    t.push_back(real(
        "camera.max_speed_mps",
        "m/s; V_c, the fastest the player can move the camera (>= speed_mps)",
        [](Scene& s) -> double& { return s.camera.max_speed_mps; }, closed(0, 1000)));
    t.push_back(
        text("camera.track_file",
             "CSV of timed poses for mode = track: t_s, eye_x_m, eye_y_m, eye_z_m, forward_x, "
             "forward_y, forward_z, up_x, up_y, up_z (camera.csv's columns; others ignored)",
             [](Scene& s) -> std::string& { return s.camera.track_file; }));
    t.push_back(
        text("camera.track_strategy",
             "track: the rows whose `strategy` column has this value (empty: the file's first)",
             [](Scene& s) -> std::string& { return s.camera.track_strategy; }));
    t.push_back(real_or_inf(
        "camera.player_interval_s",
        "s; player: mean time between changes of the intended velocity and view target (inf: "
        "never)",
        [](Scene& s) -> double& { return s.camera.player_interval_s; }, open_closed(0, 3600)));
    t.push_back(real_or_inf(
        "camera.player_accel_mps2",
        "m/s^2; player: the most the actual velocity changes per second toward the intended one "
        "(inf: instant turns); the bound strategies are told",
        [](Scene& s) -> double& { return s.camera.player_accel_mps2; }, open_closed(0, 1e6)));
    t.push_back(real(
        "camera.turn_rate_degps",
        "degrees/s; player: the fastest the view turns; the bound strategies are told",
        [](Scene& s) -> double& { return s.camera.turn_rate_degps; }, open_closed(0, 1e6)));
    t.push_back(real(
        "camera.player_look_radius_m",
        "m; player: view targets are drawn within this distance of the object's centre",
        [](Scene& s) -> double& { return s.camera.player_look_radius_m; }, closed(0, 1e6)));
    t.push_back(real(
        "camera.fovy_deg", "degrees; vertical field of view",
        [](Scene& s) -> double& { return s.camera.fovy_deg; }, open(0, 180)));
    t.push_back(real(
        "camera.aspect", "viewport width over height",
        [](Scene& s) -> double& { return s.camera.aspect; }, open_closed(0, 100)));
    t.push_back(real(
        "camera.near_m", "m; near clip distance",
        [](Scene& s) -> double& { return s.camera.near_m; }, open_closed(0, 1000)));
    t.push_back(real(
        "camera.far_m", "m; far clip distance (> near_m)",
        [](Scene& s) -> double& { return s.camera.far_m; }, open_closed(0, 1e7)));
    t.push_back(vec3(
        "camera.body_size_m", "m; the camera body, a box centred on the eye",
        [](Scene& s) -> Eigen::Vector3d& { return s.camera.body_size_m; }, open_closed(0, 100)));
    // [wall]
    t.push_back(real(
        "wall.distance_m", "m; wall centre in front of the eye",
        [](Scene& s) -> double& { return s.wall.distance_m; }, open_closed(0, 1000)));
    t.push_back(real(
        "wall.thickness_m", "m; depth of the wall box",
        [](Scene& s) -> double& { return s.wall.thickness_m; }, open_closed(0, 100)));
    t.push_back(real(
        "wall.margin", "wall size over the frustum's cross-section",
        [](Scene& s) -> double& { return s.wall.margin; }, closed(1, 100)));
    t.push_back(real(
        "wall.restitution", "bounce off the wall, 0 to 1",
        [](Scene& s) -> double& { return s.wall.restitution; }, closed(0, 1)));
    // [deflect-all]
    t.push_back(real(
        "deflect-all.accel_mps2", "m/s^2; push away from the view axis",
        [](Scene& s) -> double& { return s.deflect_all.accel_mps2; }, closed(0, 1e6)));
    t.push_back(real(
        "deflect-all.range_m", "m; only fragments this close to the eye are pushed",
        [](Scene& s) -> double& { return s.deflect_all.range_m; }, closed(0, 1e6)));
    // [near-plane]
    t.push_back(real(
        "near-plane.min_near_m", "m; the closest the near plane may come",
        [](Scene& s) -> double& { return s.near_plane.min_near_m; }, open_closed(0, 1000)));
    t.push_back(real(
        "near-plane.margin_m", "m; kept between the near plane and a fragment",
        [](Scene& s) -> double& { return s.near_plane.margin_m; }, closed(0, 100)));
    t.push_back(integer(
        "near-plane.depth_bits", "bits of the depth buffer",
        [](Scene& s) -> int& { return s.near_plane.depth_bits; }, 8, 32));
    t.push_back(real(
        "near-plane.ref_distance_m", "m; distance at which the depth step is reported",
        [](Scene& s) -> double& { return s.near_plane.ref_distance_m; }, open_closed(0, 1e7)));
    // [edge]
    t.push_back(real(
        "edge.k", "N m s^2; gain of the thesis force (3.4)",
        [](Scene& s) -> double& { return s.edge.k; }, closed(0, 1e12)));
    t.push_back(real(
        "edge.a_max_mps2", "m/s^2; cap on the imposed acceleration",
        [](Scene& s) -> double& { return s.edge.a_max_mps2; }, closed(0, 1e9)));
    t.push_back(choice<Predictor>(
        "edge.predictor", "thesis | discrete; path used to predict",
        [](Scene& s) -> Predictor& { return s.edge.predictor; }, predictors));
    t.push_back(choice<Reach>(
        "edge.reach", "thesis | growing; the camera's reachable region",
        [](Scene& s) -> Reach& { return s.edge.reach; }, reaches));
    t.push_back(choice<Horizon>(
        "edge.horizon", "camera | ground; height that defines t_G",
        [](Scene& s) -> Horizon& { return s.edge.horizon; }, horizons));
    t.push_back(choice<Replan>(
        "edge.replan", "never | contact | always; which non-candidates are re-examined",
        [](Scene& s) -> Replan& { return s.edge.replan; }, replans));
    t.push_back(real(
        "edge.horizon_cap_s",
        "s; t_G's fallback and cap: a path that never falls through the horizon height is "
        "examined this far ahead (a game has no scene end)",
        [](Scene& s) -> double& { return s.edge.horizon_cap_s; }, open_closed(0, 3600)));
    // [edge-min]
    t.push_back(real(
        "edge-min.margin_m", "m; clearance kept beyond the protected rectangle's edge",
        [](Scene& s) -> double& { return s.edge_min.margin_m; }, closed(0, 100)));
    t.push_back(real(
        "edge-min.a_max_mps2", "m/s^2; cap on the imposed acceleration",
        [](Scene& s) -> double& { return s.edge_min.a_max_mps2; }, closed(0, 1e9)));
    t.push_back(choice<CameraModel>(
        "edge-min.camera_model",
        "constant | bounded_accel | reachable; what the camera is assumed to do before a "
        "fragment arrives: keep its velocity and view, change them within acceleration and "
        "turn-rate bounds, or go anywhere within V_c t",
        [](Scene& s) -> CameraModel& { return s.edge_min.camera_model; },
        {{"constant", CameraModel::kConstant},
         {"bounded_accel", CameraModel::kBoundedAccel},
         {"reachable", CameraModel::kReachable}}));
    t.push_back(real(
        "edge-min.camera_accel_mps2",
        "m/s^2; bounded_accel: the camera's acceleration bound assumed when the scene declares "
        "none (mode = path or track)",
        [](Scene& s) -> double& { return s.edge_min.camera_accel_mps2; }, closed(0, 1e6)));
    t.push_back(real(
        "edge-min.camera_turn_degps",
        "degrees/s; bounded_accel and reachable: the camera's turn-rate bound assumed when the "
        "scene declares none",
        [](Scene& s) -> double& { return s.edge_min.camera_turn_degps; }, closed(0, 1e6)));
    t.push_back(real(
        "edge-min.horizon_cap_s",
        "s; look-ahead cap: a path is examined until the fragment reaches the ground, at most "
        "this far ahead",
        [](Scene& s) -> double& { return s.edge_min.horizon_cap_s; }, open_closed(0, 3600)));
    t.push_back(integer(
        "edge-min.max_solves",
        "fragments solved exactly per step, the most urgent first; the rest keep their last "
        "force (0: no cap)",
        [](Scene& s) -> int& { return s.edge_min.max_solves; }, 0, 100000000));
    // [metrics]
    t.push_back(integer(
        "metrics.grid_width_px", "pixels across the occlusion raster (height from camera.aspect)",
        [](Scene& s) -> int& { return s.metrics.grid_width_px; }, 8, 4096));
    t.push_back(real(
        "metrics.central_share",
        "share of the viewport's width and height spanned by the central region",
        [](Scene& s) -> double& { return s.metrics.central_share; }, open_closed(0, 1)));
    t.push_back(real(
        "metrics.near_miss_m",
        "m; a fragment passing this close to the eye without touching is a near miss",
        [](Scene& s) -> double& { return s.metrics.near_miss_m; }, open_closed(0, 1000)));
    t.push_back(real(
        "metrics.deviation_threshold_m",
        "m; a fragment moved farther than this from its `none` path counts as deviated",
        [](Scene& s) -> double& { return s.metrics.deviation_threshold_m; }, open_closed(0, 1000)));
    return t;
  }();
  return table;
}

const KeySpec* find_key(const std::string& name) {
  for (const KeySpec& k : keys()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

// Where each key stands in a scene file's text: section-qualified name -> 1-based line numbers.
// Also rejects lines that are neither comments, sections nor key = value, naming the line.
std::map<std::string, std::vector<int>> index_lines(const std::string& text,
                                                    const std::string& origin) {
  std::map<std::string, std::vector<int>> where;
  std::istringstream in(text);
  std::string line;
  std::string section;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    const std::string s = trim(hash == std::string::npos ? line : line.substr(0, hash));
    if (s.empty()) continue;
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3) {
        throw SceneError(origin + ":" + std::to_string(number) + ": malformed section header '" +
                         s + "'");
      }
      section = trim(s.substr(1, s.size() - 2));
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos || trim(s.substr(0, eq)).empty()) {
      throw SceneError(origin + ":" + std::to_string(number) + ": expected 'key = value', got '" +
                       s + "'");
    }
    const std::string key = trim(s.substr(0, eq));
    where[section.empty() ? key : section + "." + key].push_back(number);
  }
  return where;
}

std::string line_of(const std::map<std::string, std::vector<int>>& where, const std::string& key,
                    std::size_t occurrence) {
  const auto it = where.find(key);
  if (it == where.end() || occurrence >= it->second.size()) return "";
  return std::to_string(it->second[occurrence]);
}

void apply(Scene& scene, const std::string& key, const std::string& value,
           const std::string& where) {
  const KeySpec* spec = find_key(key);
  if (!spec) throw SceneError(where + ": unknown key '" + key + "'");
  try {
    spec->set(scene, value);
  } catch (const ValueError& e) {
    throw SceneError(where + ": " + key + " = '" + trim(value) + "': " + e.rule);
  }
}

}  // namespace

const po::options_description& scene_options() {
  static const po::options_description desc = [] {
    po::options_description d(
        "Scene keys (file sections [simulation], [camera], ...; any key "
        "also on the command line)");
    const Scene defaults;
    for (const KeySpec& k : keys()) {
      d.add_options()(k.name.c_str(), po::value<std::string>()->value_name("V"),
                      (k.help + " [" + k.get(defaults) + "]").c_str());
    }
    return d;
  }();
  return desc;
}

std::vector<SceneOverride> scene_overrides(const po::parsed_options& parsed) {
  std::vector<SceneOverride> out;
  for (const po::option& o : parsed.options) {
    if (o.unregistered || !find_key(o.string_key)) continue;
    out.push_back({o.string_key, o.value.empty() ? std::string() : o.value.front()});
  }
  return out;
}

Scene parse_scene(const std::string& text, const std::string& origin,
                  const std::vector<SceneOverride>& overrides) {
  Scene scene;
  if (!origin.empty() || !text.empty()) {
    const auto where = index_lines(text, origin);
    std::istringstream in(text);
    po::parsed_options parsed(nullptr);
    try {
      parsed = po::parse_config_file(in, scene_options(), false);
    } catch (const po::unknown_option& e) {
      const std::string line = line_of(where, e.get_option_name(), 0);
      throw SceneError(origin + (line.empty() ? "" : ":" + line) + ": unknown key '" +
                       e.get_option_name() + "'");
    } catch (const po::error& e) {
      throw SceneError(origin + ": " + e.what());
    }
    std::map<std::string, std::size_t> seen;
    for (const po::option& o : parsed.options) {
      const std::size_t n = seen[o.string_key]++;
      const std::string line = line_of(where, o.string_key, n);
      const std::string at = origin + (line.empty() ? "" : ":" + line);
      if (n > 0) throw SceneError(at + ": " + o.string_key + " is set more than once");
      apply(scene, o.string_key, o.value.empty() ? std::string() : o.value.front(), at);
    }
  }
  for (const SceneOverride& o : overrides) {
    apply(scene, o.key, o.value, "--" + o.key);
  }
  validate_scene(scene);
  if (scene.camera.mode == CameraMode::kTrack) {
    try {
      scene.camera.track_samples = load_camera_track(
          scene.camera.track_file, scene.camera.track_strategy, scene.camera.max_speed_mps);
    } catch (const InputError& e) {
      throw SceneError(std::string(e.what()) + " (camera.track_file)");
    }
  }
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  if (path.empty()) return parse_scene("", "", overrides);
  std::string text;
  try {
    text = read_input_file(path, "scene file");
  } catch (const InputError& e) {
    throw SceneError(e.what());
  }
  return parse_scene(text, path, overrides);
}

std::string scene_to_ini(const Scene& scene) {
  std::ostringstream out;
  std::string section;
  out << "# fragsim scene, fully resolved\n";
  for (const KeySpec& k : keys()) {
    const auto dot = k.name.find('.');
    const std::string sec = dot == std::string::npos ? "" : k.name.substr(0, dot);
    const std::string key = dot == std::string::npos ? k.name : k.name.substr(dot + 1);
    if (sec != section) {
      out << "\n[" << sec << "]\n";
      section = sec;
    }
    out << key << " = " << k.get(scene) << "\n";
  }
  return out.str();
}

void validate_scene(const Scene& s) {
  auto fail = [](const std::string& msg) { throw SceneError(msg); };
  if (s.camera.far_m <= s.camera.near_m) {
    fail("camera.far_m = " + format_double(s.camera.far_m) +
         ": must be > camera.near_m = " + format_double(s.camera.near_m));
  }
  if (s.camera.max_speed_mps < s.camera.speed_mps) {
    fail("camera.max_speed_mps = " + format_double(s.camera.max_speed_mps) +
         ": must be >= camera.speed_mps = " + format_double(s.camera.speed_mps));
  }
  const auto& look = s.camera.look_at_m;
  const auto& way = s.camera.waypoints_m;
  if (look.size() != 1 && look.size() != way.size()) {
    fail("camera.look_at_m: " + std::to_string(look.size()) + " points: must be one, or one per " +
         "waypoint (" + std::to_string(way.size()) + ")");
  }
  for (std::size_t i = 0; i < way.size(); ++i) {
    const Eigen::Vector3d& target = look.size() == 1 ? look.front() : look[i];
    if ((way[i] - target).norm() <= s.camera.near_m) {
      fail("camera.look_at_m = " + format_vec3(target) + ": must be farther than camera.near_m " +
           "from waypoint " + std::to_string(i + 1));
    }
  }
  if (s.camera.mode == CameraMode::kTrack && s.camera.track_file.empty() &&
      s.camera.track_samples.empty()) {
    fail("camera.track_file: needed with camera.mode = track");
  }
  if (s.object.distance_m > 0.0 &&
      (s.object.centre_m - s.camera.waypoints_m.front()).norm() < 1e-9) {
    fail("object.distance_m = " + format_double(s.object.distance_m) +
         ": needs object.centre_m away from the camera's first waypoint to give a direction");
  }
  if (s.near_plane.min_near_m > s.camera.near_m) {
    fail("near-plane.min_near_m = " + format_double(s.near_plane.min_near_m) +
         ": must be <= camera.near_m = " + format_double(s.camera.near_m));
  }
  if (s.sim.dt_s > s.sim.duration_s) {
    fail("simulation.dt_s = " + format_double(s.sim.dt_s) +
         ": must be <= simulation.duration_s = " + format_double(s.sim.duration_s));
  }
  const double steps = std::ceil(s.sim.duration_s / s.sim.dt_s);
  if (steps > 1e7) {
    fail("simulation.duration_s / simulation.dt_s = " + format_double(steps) +
         " steps: at most 10,000,000");
  }
  if (s.wall.thickness_m >= 2.0 * s.wall.distance_m) {
    fail("wall.thickness_m = " + format_double(s.wall.thickness_m) +
         ": must be < 2 wall.distance_m, so the wall stays in front of the eye");
  }
}

}  // namespace fragsim
