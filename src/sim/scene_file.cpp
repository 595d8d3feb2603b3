#include "sim/scene_file.hpp"

#include "debris/mesh_file.hpp"
#include "io/number_format.hpp"
#include "io/visible_text.hpp"
#include "settings/key.hpp"
#include "sim/camera_track_file.hpp"
#include "sim/explosion.hpp"
#include "sim/key_relevance.hpp"
#include "sim/scene_strategies.hpp"

#include <algorithm>
#include <boost/program_options/errors.hpp>
#include <boost/program_options/value_semantic.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

namespace fragsim {
namespace po = boost::program_options;
using settings::closed;
using settings::format_vec3;
using settings::open;
using settings::open_closed;
using settings::ValueError;
using KeySpec = settings::Key<Scene>;
namespace {

// `keys` of the Def that `member` is, in its section of the scene.
template <class Def>
void add_section(std::vector<KeySpec>& out, std::string_view section, Def Scene::*member,
                 const settings::Keys<Def>& keys) {
  for (KeySpec& k : settings::in_section<Scene>(
           section, keys, [member](auto& s) -> auto& { return s.*member; })) {
    out.push_back(std::move(k));
  }
}

// The scene's own keys before the strategies' sections and after them, because config.ini lists the
// strategies between [camera] and [metrics].
std::vector<KeySpec> keys_before_strategies() {
  using namespace settings;
  std::vector<KeySpec> t;
  const auto name_rule = [](const std::string& n) -> std::optional<std::string> {
    if (n.empty() || n.find_first_of(",\"\n") != std::string::npos) {
      return "must be non-empty, without commas or quotes";
    }
    return std::nullopt;
  };
  t.push_back({"name", "the scene's name in reports",
               [name_rule](Scene& s, const std::string& v) {
                 const std::string n = trim(v);
                 if (auto rule = name_rule(n)) throw ValueError{*rule};
                 s.name = n;
               },
               [](const Scene& s) { return s.name; },
               [name_rule](const Scene& s) { return name_rule(s.name); }});
  {
    using D = SimulationDef;
    const Key<D> seed{"seed", "random seed of the explosion and of ODE's solver",
                      [](D& d, const std::string& v) {
                        const std::string x = trim(v);
                        std::uint64_t seed = 0;
                        const auto res = std::from_chars(x.data(), x.data() + x.size(), seed);
                        if (x.empty() || res.ec != std::errc() || res.ptr != x.data() + x.size()) {
                          throw ValueError{"must be a whole number in [0, 2^64)"};
                        }
                        d.seed = seed;
                      },
                      [](const D& d) { return std::to_string(d.seed); },
                      [](const D&) { return std::optional<std::string>(); }};
    add_section<D>(
        t, "simulation", &Scene::sim,
        {real("dt_s", "s", "physics step", &D::dt_s, closed(1e-9, 1)),
         real("duration_s", "s", "simulated time after the explosion", &D::duration_s,
              open_closed(0, 3600)),
         seed,
         boolean("fragment_collisions",
                 "fragments collide with each other (off: no pair is tested)",
                 &D::fragment_collisions),
         vec3("gravity_mps2", "m/s^2", "gravity vector", &D::gravity_mps2, closed(-1000, 1000)),
         choice("solver",
                "ODE stepper (auto: exact unless fragments collide with each other or with the "
                "wall strategy's wall, then quick)",
                &D::solver,
                {{"auto", Solver::kAuto}, {"exact", Solver::kExact}, {"quick", Solver::kQuick}}),
         integer("solver_iterations", "", "dWorldQuickStep iterations", &D::solver_iterations, 1,
                 1000),
         boolean("auto_disable",
                 "ODE's auto-disable: a fragment at rest is no longer stepped until something "
                 "touches or pushes it",
                 &D::auto_disable),
         boolean("cull_resting",
                 "a fragment at rest, out of view and away from the camera leaves collision "
                 "detection and stepping until it could matter again",
                 &D::cull_resting),
         real("rest_linear_mps", "m/s",
              "at rest: slower than this (and rest_angular_radps) for rest_steps steps while "
              "touching something",
              &D::rest_linear_mps, closed(0, 1000)),
         real("rest_angular_radps", "rad/s", "at rest: turning slower than this",
              &D::rest_angular_radps, closed(0, 1000)),
         integer("rest_steps", "",
                 "steps in a row below both thresholds before a fragment is at rest",
                 &D::rest_steps, 1, 1000000),
         integer("convex_ground_contacts", "",
                 "contacts kept for a convex piece on the ground, spread over its footprint",
                 &D::convex_ground_contacts, 1, 8)});
  }
  {
    using D = ObjectDef;
    add_section<D>(
        t, "object", &Scene::object,
        {vec3("centre_m", "m", "centre of the cube", &D::centre_m, closed(-1e6, 1e6)),
         real("size_m", "m", "edge of the cube", &D::size_m, open_closed(0, 1000)),
         real("distance_m", "m",
              "if > 0, the cube is moved along the line from the camera's first waypoint through "
              "centre_m to this distance from it (0: centre_m as is)",
              &D::distance_m, closed(0, 1e6)),
         integer("splits", "", "grid: pieces per axis; splits^3 fragments", &D::splits, 1, 64),
         real("density_kgpm3", "kg/m^3", "", &D::density_kgpm3, open_closed(0, 1e5)),
         real("gap", "", "share by which each fragment is shrunk, so none touch at t = 0", &D::gap,
              closed(0, 0.5)),
         choice("pattern",
                "what the cube breaks into: splits^3 equal cubes, or `pieces` Voronoi cells of "
                "the cube from seeded points",
                &D::pattern,
                {{"grid", DebrisPattern::kGrid}, {"voronoi", DebrisPattern::kVoronoi}}),
         integer("pieces", "", "voronoi: the number of cells", &D::pieces, 1, kMaxPieces),
         real("cluster", "",
              "voronoi: in [0, 1); outside a small core about the blast centre, seed points' "
              "density falls off as distance^(-3 cluster), so cells are smaller near it (0: "
              "uniform)",
              &D::cluster, settings::Range{0.0, 1.0, false, true}),
         text("mesh_file",
              "pieces from a mesh file (.obj, .gltf, .glb; one mesh per piece, each taken as its "
              "convex hull, the file's origin at centre_m) instead of pattern; a relative path is "
              "taken from the scene file's folder",
              &D::mesh_file),
         real("mesh_unit_m", "m",
              "metres per unit of mesh_file's coordinates (0.01: centimetres, as Unreal and 3ds "
              "Max write)",
              &D::mesh_unit_m, open_closed(0, 1000)),
         choice("mesh_up",
                "mesh_file's up axis (Unreal: z; glTF, Unity, Blender's exporters by default: y)",
                &D::mesh_up, {{"y", UpAxis::kY}, {"z", UpAxis::kZ}}),
         choice("mesh_handedness",
                "mesh_file's handedness (Unreal, Unity: left; glTF, Blender: right)",
                &D::mesh_handedness,
                {{"right", Handedness::kRight}, {"left", Handedness::kLeft}})});
  }
  {
    using D = ExplosionDef;
    add_section<D>(
        t, "explosion", &Scene::explosion,
        {vec3("offset_m", "m", "blast centre relative to the cube's centre", &D::offset_m,
              closed(-1e6, 1e6)),
         real("speed_mps", "m/s", "radial speed away from the blast centre", &D::speed_mps,
              closed(0, 1000)),
         real("jitter", "", "relative random variation of each fragment's velocity", &D::jitter,
              closed(0, 1)),
         real("spin_radps", "rad/s", "largest random spin of a fragment", &D::spin_radps,
              closed(0, 1000)),
         real("toward_camera_mps", "m/s",
              "aims the blast: added ballistic velocity carrying the cube's centre to the moving "
              "camera's eye (0 = undirected)",
              &D::toward_camera_mps, closed(0, 1000)),
         choice("aim",
                "the aimed blast goes where the camera will be when the debris arrives (scene "
                "set-up that peeks), or where it is at t = 0 (all a game knows)",
                &D::aim,
                {{"future", ExplosionAim::kFuture}, {"present", ExplosionAim::kPresent}})});
  }
  {
    using D = GroundDef;
    add_section<D>(
        t, "ground", &Scene::ground,
        {boolean("enabled", "an infinite ground plane", &D::enabled),
         real("height_m", "m", "height of the ground plane", &D::height_m, closed(-1e6, 1e6)),
         real("friction", "", "Coulomb friction coefficient", &D::friction, closed(0, 100)),
         real("restitution", "", "bounce, 0 to 1", &D::restitution, closed(0, 1))});
  }
  {
    using D = CameraDef;
    add_section<D>(
        t, "camera", &Scene::camera,
        {choice("mode",
                "where the camera's motion comes from: the waypoints, a CSV file of timed poses, "
                "or a seeded model of a player with a gamepad",
                &D::mode,
                {{"path", CameraMode::kPath},
                 {"track", CameraMode::kTrack},
                 {"player", CameraMode::kPlayer}}),
         points("waypoints_m", "m",
                "the camera's path, points 'x y z' separated by ';' (player: the start is the "
                "first)",
                &D::waypoints_m),
         points("look_at_m", "m",
                "the point the camera looks at, or one point per waypoint (interpolated along the "
                "path, so the view pans)",
                &D::look_at_m),
         real("speed_mps", "m/s", "speed along the waypoints", &D::speed_mps, closed(0, 1000)),
         real("max_speed_mps", "m/s",
              "V_c, the fastest the player can move the camera (>= speed_mps)", &D::max_speed_mps,
              closed(0, 1000)),
         text("track_file",
              "CSV of timed poses for mode = track: t_s, eye_x_m, eye_y_m, eye_z_m, forward_x, "
              "forward_y, forward_z, up_x, up_y, up_z (camera.csv's columns; others ignored)",
              &D::track_file),
         text("track_strategy",
              "track: the rows whose `strategy` column has this value (empty: the file's first)",
              &D::track_strategy),
         choice("track_time",
                "track: the file's times as recorded (t = 0 is the blast), or shifted so its "
                "first sample is t = 0 (an engine's clock)",
                &D::track_time,
                {{"as_recorded", TrackTime::kAsRecorded},
                 {"from_first_sample", TrackTime::kFromFirstSample}}),
         real("track_unit_m", "m", "track: metres per file unit of the eye (0.01: centimetres)",
              &D::track_unit_m, open_closed(0, 1000)),
         choice("track_up", "track: the file's up axis (z: Unreal, Blender)", &D::track_up,
                {{"y", UpAxis::kY}, {"z", UpAxis::kZ}}),
         choice("track_handedness", "track: the file's handedness (left: Unity, Unreal)",
                &D::track_handedness, {{"right", Handedness::kRight}, {"left", Handedness::kLeft}}),
         real_or_inf("player_interval_s", "s",
                     "player: mean time between changes of the intended velocity and view target "
                     "(inf: never)",
                     &D::player_interval_s, open_closed(0, 3600)),
         real_or_inf("player_accel_mps2", "m/s^2",
                     "player: the most the actual velocity changes per second toward the "
                     "intended one (inf: instant turns); the bound strategies are told",
                     &D::player_accel_mps2, open_closed(0, 1e6)),
         real("turn_rate_degps", "degrees/s",
              "player: the fastest the view turns; the bound strategies are told",
              &D::turn_rate_degps, open_closed(0, 1e6)),
         real("player_look_radius_m", "m",
              "player: view targets are drawn within this distance of the object's centre",
              &D::player_look_radius_m, closed(0, 1e6)),
         real("fovy_deg", "degrees", "vertical field of view", &D::fovy_deg, open(0, 180)),
         real("aspect", "", "viewport width over height", &D::aspect, open_closed(0, 100)),
         real("near_m", "m", "near clip distance", &D::near_m, open_closed(0, 1000)),
         real("far_m", "m", "far clip distance (> near_m)", &D::far_m, open_closed(0, 1e7)),
         vec3("body_size_m", "m", "the camera body, a box centred on the eye", &D::body_size_m,
              open_closed(0, 100))});
  }
  return t;
}

std::vector<KeySpec> keys_after_strategies() {
  using namespace settings;
  using D = MetricsDef;
  std::vector<KeySpec> t;
  add_section<D>(t, "metrics", &Scene::metrics,
                 {integer("grid_width_px", "",
                          "pixels across the occlusion raster (height from camera.aspect)",
                          &D::grid_width_px, 8, 4096),
                  real("central_share", "",
                       "share of the viewport's width and height spanned by the central region",
                       &D::central_share, open_closed(0, 1)),
                  real("near_miss_m", "m",
                       "a fragment passing this close to the eye without touching is a near miss",
                       &D::near_miss_m, open_closed(0, 1000)),
                  real("deviation_threshold_m", "m",
                       "a fragment moved farther than this from its `none` path counts as deviated",
                       &D::deviation_threshold_m, open_closed(0, 1000))});
  return t;
}

// Every key of a scene whose strategies are `table`'s, in the order of --help and config.ini.
std::vector<KeySpec> make_keys(const StrategyTable& table) {
  std::vector<KeySpec> t = keys_before_strategies();
  for (const StrategyEntry& e : table) {
    for (const auto& k : e.keys) {
      // The strategies' keys are kept on the scene's strategy settings.
      t.push_back({k.name, k.help,
                   [parse = k.parse](Scene& s, const std::string& v) { parse(s.strategies, v); },
                   [format = k.format](const Scene& s) { return format(s.strategies); },
                   [broken = k.broken](const Scene& s) { return broken(s.strategies); }});
    }
  }
  for (KeySpec& k : keys_after_strategies()) t.push_back(std::move(k));
  return t;
}

const std::vector<KeySpec>& default_keys() {
  static const std::vector<KeySpec> table = make_keys(strategy_table());
  return table;
}

const KeySpec* find_key(const std::vector<KeySpec>& keys, const std::string& name) {
  for (const KeySpec& k : keys) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

// Where each key stands in a scene file's text, as section-qualified name -> 1-based line numbers.
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
                         visible_text(s) + "'");
      }
      section = trim(s.substr(1, s.size() - 2));
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos || trim(s.substr(0, eq)).empty()) {
      throw SceneError(origin + ":" + std::to_string(number) + ": expected 'key = value', got '" +
                       visible_text(s) + "'");
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

void apply(const std::vector<KeySpec>& keys, Scene& scene, const std::string& key,
           const std::string& value, const std::string& where) {
  const KeySpec* spec = find_key(keys, key);
  if (!spec) throw SceneError(where + ": unknown key '" + visible_text(key) + "'");
  try {
    spec->parse(scene, value);
  } catch (const ValueError& e) {
    // settings::apply's message with the value made visible, because a NUL would end it.
    throw SceneError(
        settings::bad_text_message(where, spec->name, visible_text(trim(value)), e.rule));
  }
}

// A key the user set, and where, as "scene.ini:3" or "--camera.near_m".
struct SetKey {
  std::string key;
  std::string where;
  std::string value;
};

// Whether `key` is named in `message` as a whole name (not inside a longer one).
bool names_key(const std::string& message, const std::string& key) {
  for (auto at = message.find(key); at != std::string::npos; at = message.find(key, at + 1)) {
    const auto end = at + key.size();
    const bool starts = at == 0 || message[at - 1] == ' ' || message[at - 1] == '(';
    const bool ends = end == message.size() || message[end] == ' ' || message[end] == ':' ||
                      message[end] == ')' || message[end] == ',';
    if (starts && ends) return true;
  }
  return false;
}

// A broken rule across keys. The message names the key it is about first
// ("a = 1: must be <= b = 2"). When the user did not set that one but set another the message
// names, the other is the one to change, so the message is put at its place (file:line or
// --option).
std::string placed(const std::string& message, const std::vector<SetKey>& set) {
  const std::string subject = message.substr(0, message.find_first_of(" :"));
  if (message.compare(subject.size(), 3, " = ") != 0) return message;  // not about a value
  for (const SetKey& k : set) {
    if (k.key == subject) return message;
  }
  for (const SetKey& k : set) {
    if (names_key(message, k.key)) {
      return k.where + ": " + k.key + " = " + visible_text(trim(k.value)) + " breaks a rule of " +
             subject + ", which is not set (its default): " + message;
    }
  }
  return message;
}

po::options_description options_of(const std::vector<KeySpec>& keys) {
  po::options_description d(
      "Scene keys (file sections [simulation], [camera], ...; any key "
      "also on the command line)");
  const Scene defaults;
  for (const KeySpec& k : keys) {
    d.add_options()(k.name.c_str(), po::value<std::string>()->value_name("V"),
                    (k.help + " [" + k.format(defaults) + "]").c_str());
  }
  return d;
}

// The files a scene names, taken from `base` when relative (the scene file's folder, or the
// current folder when empty).
void make_paths_absolute(Scene& scene, const std::filesystem::path& base) {
  for (std::string* path : {&scene.object.mesh_file, &scene.camera.track_file}) {
    if (!path->empty() && std::filesystem::path(*path).is_relative()) {
      *path = std::filesystem::absolute(base / *path).lexically_normal().string();
    }
  }
}

std::string short_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// An object that starts partly below the ground is thrown out of it by ODE's penetration correction
// (up to 7.2 m/s with no blast at all), so it is refused. Its lowest point, the cube's bottom face
// or the mesh's lowest vertex, must be at or above the ground plane.
void check_object_above_ground(const Scene& s) {
  if (!s.ground.enabled) return;
  const Eigen::Vector3d centre_m = object_centre(s);
  double lowest_m = centre_m.y() - 0.5 * s.object.size_m;
  std::string what = "the cube's bottom (object.size_m = " + format_double(s.object.size_m) + ")";
  if (s.object.mesh_pieces) {
    lowest_m = INFINITY;
    for (const Piece& p : *s.object.mesh_pieces) {
      const double y_m = centre_m.y() + p.centre_m.y();
      if (!p.shape) {  // a box
        lowest_m = std::min(lowest_m, y_m - p.rotation.row(1).cwiseAbs().dot(p.half_extents_m));
        continue;
      }
      for (const Eigen::Vector3d& v : p.shape->vertices_m) {
        lowest_m = std::min(lowest_m, y_m + p.rotation.row(1).dot(v));
      }
    }
    what = "object.mesh_file's lowest vertex";
  }
  // Rounding of the placement (a mesh vertex exactly on the ground comes out 1e-17 below) is not
  // an object below the ground.
  constexpr double kRoundingM = 1e-9;
  if (lowest_m >= s.ground.height_m - kRoundingM) return;
  const std::string placed =
      s.object.distance_m > 0.0
          ? " (placed by object.distance_m = " + format_double(s.object.distance_m) + ")"
          : "";
  throw SceneError("object.centre_m = " + format_vec3(s.object.centre_m) + placed + ": " + what +
                   " is at y = " + short_text(lowest_m) + " m, below the ground at " +
                   "ground.height_m = " + format_double(s.ground.height_m) +
                   ": the object must start wholly at or above the ground");
}
// config.ini's first line, saying fragsim wrote every key of the scene, moot ones too.
constexpr std::string_view kResolvedMark = "# fragsim scene, fully resolved";

Scene parse_with(const std::vector<KeySpec>& keys, const po::options_description& options,
                 const StrategyTable& table, const std::string& text, const std::string& origin,
                 const std::vector<SceneOverride>& overrides, std::vector<std::string>* warnings) {
  Scene scene;
  std::vector<SetKey> set;
  if (!origin.empty() || !text.empty()) {
    const auto where = index_lines(text, origin);
    std::istringstream in(text);
    po::parsed_options parsed(nullptr);
    try {
      parsed = po::parse_config_file(in, options, false);
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
      const std::string value = o.value.empty() ? std::string() : o.value.front();
      apply(keys, scene, o.string_key, value, at);
      set.push_back({o.string_key, at, value});
    }
    // A file a scene names (a mesh, a camera track) beside the scene file is held absolute, so it
    // is found from anywhere and the scene's config.ini (and a worker's copy of the scene) names
    // the same file. On the command line a relative path is the shell's, the current folder's, made
    // absolute below for the same reason.
    make_paths_absolute(scene, std::filesystem::path(origin).parent_path());
  }
  for (const SceneOverride& o : overrides) {
    apply(keys, scene, o.key, o.value, "--" + o.key);
    set.push_back({o.key, "--" + o.key, o.value});
  }
  make_paths_absolute(scene, std::filesystem::path());
  try {
    validate_scene(scene, table);
  } catch (const SceneError& e) {
    throw SceneError(placed(e.what(), set));
  }
  if (scene.camera.mode == CameraMode::kTrack) {
    try {
      scene.camera.track_samples =
          load_camera_track(scene.camera.track_file, track_reading(scene.camera));
    } catch (const InputError& e) {
      throw SceneError(std::string(e.what()) + " (camera.track_file)");
    }
  }
  if (!scene.object.mesh_file.empty()) {
    try {
      std::vector<std::string> warnings;
      scene.object.mesh_pieces = std::make_shared<const std::vector<Piece>>(
          read_pieces(scene.object.mesh_file, scene.object.density_kgpm3, scene.object.mesh_frame(),
                      &warnings));
      for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    } catch (const InputError& e) {
      throw SceneError(std::string(e.what()) + " (object.mesh_file)");
    }
  }
  check_object_above_ground(scene);
  if (warnings) {
    if (auto coverage = track_coverage_warning(scene)) warnings->push_back(*coverage);
    // config.ini holds every key, so that any of its modes can be switched on again later.
    if (text.rfind(kResolvedMark, 0) != 0) {
      for (std::size_t i = 0; i < set.size(); ++i) {
        const SetKey& k = set[i];
        // A key set in the file and again on the command line is named once, where it won.
        const auto later = std::find_if(set.begin() + static_cast<std::ptrdiff_t>(i) + 1, set.end(),
                                        [&](const SetKey& o) { return o.key == k.key; });
        if (later != set.end()) continue;
        if (auto why = why_no_effect(scene, k.key)) {
          warnings->push_back(k.where + ": " + k.key + " has no effect: " + *why);
        }
      }
    }
  }
  return scene;
}

std::string ini_of(const std::vector<KeySpec>& keys, const Scene& scene) {
  std::ostringstream out;
  std::string section;
  out << kResolvedMark << "\n";
  for (const KeySpec& k : keys) {
    const auto dot = k.name.find('.');
    const std::string sec = dot == std::string::npos ? "" : k.name.substr(0, dot);
    const std::string key = dot == std::string::npos ? k.name : k.name.substr(dot + 1);
    if (sec != section) {
      out << "\n[" << sec << "]\n";
      section = sec;
    }
    out << key << " = " << k.format(scene) << "\n";
  }
  return out.str();
}

}  // namespace

const po::options_description& scene_options() {
  static const po::options_description desc = options_of(default_keys());
  return desc;
}

po::options_description scene_options(const StrategyTable& table) {
  return options_of(make_keys(table));
}

std::vector<SceneOverride> scene_overrides(const po::parsed_options& parsed) {
  std::vector<SceneOverride> out;
  for (const po::option& o : parsed.options) {
    if (o.unregistered || !find_key(default_keys(), o.string_key)) continue;
    out.push_back({o.string_key, o.value.empty() ? std::string() : o.value.front()});
  }
  return out;
}

Scene parse_scene(const std::string& text, const std::string& origin,
                  const std::vector<SceneOverride>& overrides, std::vector<std::string>* warnings) {
  return parse_with(default_keys(), scene_options(), strategy_table(), text, origin, overrides,
                    warnings);
}

Scene parse_scene(const std::string& text, const std::string& origin,
                  const std::vector<SceneOverride>& overrides, const StrategyTable& table) {
  const std::vector<KeySpec> keys = make_keys(table);
  return parse_with(keys, options_of(keys), table, text, origin, overrides, nullptr);
}

Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides,
                 std::vector<std::string>* warnings) {
  if (path.empty()) return parse_scene("", "", overrides, warnings);
  std::string text;
  try {
    text = read_text_file(path, "scene file");
  } catch (const InputError& e) {
    throw SceneError(e.what());
  }
  return parse_scene(text, path, overrides, warnings);
}

std::string scene_to_ini(const Scene& scene) {
  return ini_of(default_keys(), scene);
}

std::string scene_to_ini(const Scene& scene, const StrategyTable& table) {
  return ini_of(make_keys(table), scene);
}

void validate_scene(const Scene& s, const StrategyTable& table) {
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
  if (s.sim.dt_s > s.sim.duration_s) {
    fail("simulation.dt_s = " + format_double(s.sim.dt_s) +
         ": must be <= simulation.duration_s = " + format_double(s.sim.duration_s));
  }
  // The occlusion raster is grid_width_px wide and width / aspect tall, so a tall thin camera would
  // ask for billions of rows (camera.aspect = 3e-8 would exhaust memory, 2.7e-6 take minutes).
  const double rows = std::round(s.metrics.grid_width_px / s.camera.aspect);
  if (rows > 4096) {
    fail("camera.aspect = " + format_double(s.camera.aspect) + ": the occlusion raster would be " +
         format_double(rows) + " rows tall (metrics.grid_width_px = " +
         std::to_string(s.metrics.grid_width_px) + " / camera.aspect): at most 4096");
  }
  const double steps = std::ceil(s.sim.duration_s / s.sim.dt_s);
  if (steps > 1e7) {
    fail("simulation.duration_s / simulation.dt_s = " + format_double(steps) +
         " steps: at most 10,000,000");
  }
  if (s.camera.mode == CameraMode::kPlayer) {
    // The player's track is made ahead, one sample per step for the run and 2 s beyond it, with a
    // change of course every player_interval_s on average. Both are bounded as the steps are (a
    // step of 4.5e-9 s would ask for 36 GB of samples, an interval of 6.5e-9 s would take minutes).
    const double span_s = s.sim.duration_s + 2.0;
    const double samples = std::ceil(span_s / s.sim.dt_s);
    if (samples > 1e7) {
      fail("simulation.dt_s = " + format_double(s.sim.dt_s) + ": camera.mode = player makes " +
           format_double(samples) + " samples (the run and 2 s beyond, one a step): at most " +
           "10,000,000");
    }
    const double changes = span_s / s.camera.player_interval_s;
    if (changes > 1e7) {
      fail("camera.player_interval_s = " + format_double(s.camera.player_interval_s) +
           ": the player would change course about " + format_double(std::round(changes)) +
           " times (the run and 2 s beyond): at most 10,000,000");
    }
  }
  // Each strategy's rules across its keys (or with the camera), where it declares them.
  for (const StrategyEntry& e : table) {
    try {
      e.check_across(s.strategies, s.camera.frustum_def());
    } catch (const InputError& x) {
      fail(x.what());
    }
  }
}

}  // namespace fragsim
