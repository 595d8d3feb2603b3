#pragma once
// Everything a run is made of, as plain settings structs with defaults and units. One Scene is
// filled from a scene file and the command line (scene_file.hpp) and never changes during a run.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "debris/debris_def.hpp"
#include "geometry/axis_convention.hpp"
#include "strategies/strategy_settings.hpp"

namespace fragsim {

// Which ODE stepper advances the world.
enum class Solver {
  kAuto,   // exact when fragments do not collide with each other (nor with a wall), else quick
  kExact,  // dWorldStep, the exact LCP solver, per island
  kQuick,  // dWorldQuickStep, iterative, with constraints shuffled by ODE's global generator
};

struct SimulationDef {
  double dt_s = 1.0 / 60.0;  // the thesis's step
  double duration_s = 3.0;
  std::uint64_t seed = 1;
  bool fragment_collisions = false;  // when off, no fragment pair is ever tested
  Eigen::Vector3d gravity_mps2{0.0, -9.81, 0.0};
  Solver solver = Solver::kAuto;
  int solver_iterations = 20;  // dWorldQuickStep iterations

  // Skipping work a scene does not need. Both are off by default, as they change results by a
  // little (docs/benchmarks.md gives the measured differences) and the pinned default results are
  // made without them.
  // With ODE's auto-disable, a fragment at rest stops being stepped (its geom still collides, so
  // the camera's sensor still sees it) until something touches it or a strategy pushes it.
  bool auto_disable = false;
  // A fragment at rest, out of view and away from the camera leaves collision detection and
  // stepping altogether, until it could matter again (a push, or the camera or its wall coming
  // near).
  bool cull_resting = false;
  // "At rest" means slower than rest_linear_mps and turning slower than rest_angular_radps for
  // rest_steps steps in a row while touching something (ODE's auto-disable rule).
  double rest_linear_mps = 0.01;
  double rest_angular_radps = 0.01;
  int rest_steps = 10;
  // Contacts kept for a convex piece on the ground plane (ODE returns every vertex below it, up to
  // 8 here). With fewer, the ones kept are spread over the piece's footprint (the deepest, then
  // each time the one farthest from those kept). A box on the ground has at most 4 either way.
  int convex_ground_contacts = 4;

  // Without fragment-fragment contacts every island is one fragment and its few contacts, where the
  // exact solver is cheap. It also keeps islands independent. QuickStep draws its constraint
  // shuffle from one global generator, so a push on one fragment would change how every other
  // fragment's ground contacts are solved, and show up as deviation the strategy did not cause.
  bool uses_exact_solver() const {
    return solver == Solver::kExact || (solver == Solver::kAuto && !fragment_collisions);
  }
};

struct ObjectDef {
  Eigen::Vector3d centre_m{0.0, 1.6, -8.0};
  double size_m = 1.2;  // edge of the cube
  int splits = 12;      // per axis, so splits^3 fragments
  double density_kgpm3 = 600.0;
  double gap = 0.02;  // fragments are shrunk by this share so none touch at t = 0
  // When > 0, the object is moved along the line from the camera's first waypoint through
  // centre_m to this distance from the eye (for sweeps over the explosion's distance).
  double distance_m = 0.0;
  // What the cube breaks into (debris/debris_def.hpp), the grid of splits^3 cubes, or `pieces`
  // Voronoi cells with `cluster` making them smaller toward the blast, or, with mesh_file set, the
  // pieces of that file (pattern, splits, pieces, cluster and gap then do not apply). A relative
  // mesh_file in a scene file is taken from the scene file's folder and held absolute.
  DebrisPattern pattern = DebrisPattern::kGrid;
  int pieces = 1000;
  double cluster = 0.0;
  std::string mesh_file;
  // The units and axes of mesh_file's coordinates (geometry/axis_convention.hpp), in metres per
  // file unit, up axis and handedness. The defaults are fragsim's own frame and glTF's.
  double mesh_unit_m = 1.0;
  UpAxis mesh_up = UpAxis::kY;
  Handedness mesh_handedness = Handedness::kRight;
  AxisConvention mesh_frame() const { return {mesh_unit_m, mesh_up, mesh_handedness}; }
  // The pieces read from mesh_file when the scene is loaded, so a bad file fails before anything
  // runs. Not a scene key.
  std::shared_ptr<const std::vector<Piece>> mesh_pieces;
};

enum class ExplosionAim { kFuture, kPresent };

struct ExplosionDef {
  Eigen::Vector3d offset_m{0.0, 0.0, 0.0};  // blast centre relative to the object centre
  double speed_mps = 5.0;                   // radial speed away from the blast centre
  double jitter = 0.3;                      // relative random variation of each fragment's velocity
  double spin_radps = 6.0;                  // largest random angular speed
  // Aims the blast. Every fragment also gets the ballistic velocity that carries the object's
  // centre to the moving camera's eye at this mean speed; 0 means an undirected explosion.
  double toward_camera_mps = 0.0;
  // Where the aimed blast is aimed, where the camera will be when the debris arrives (a director
  // scripting the shot peeks at the camera's future) or where it is at t = 0 (all a game knows).
  ExplosionAim aim = ExplosionAim::kFuture;
};

struct GroundDef {
  bool enabled = true;
  double height_m = 0.0;
  double friction = 0.8;
  double restitution = 0.2;
};

// Where the camera's motion comes from (camera_motion.hpp).
enum class CameraMode {
  kPath,    // along the waypoints at speed_mps, looking at look_at_m
  kTrack,   // replayed from a CSV file of timed poses (an earlier run's camera.csv, an engine's)
  kPlayer,  // a seeded model of a person with a gamepad
};

// How a camera track's times are read, either as recorded (t = 0 is the blast, as in fragsim's own
// camera.csv and play recordings) or shifted so that its first sample is t = 0 (an engine's export
// stamped with the engine's clock).
enum class TrackTime { kAsRecorded, kFromFirstSample };

// The scene's camera: how it moves (mode, path, track, player model), its frustum, body and speed.
// Each step's CameraPose is made from it; CameraLimits are what it declares to strategies.
struct CameraDef {
  CameraMode mode = CameraMode::kPath;
  // A path camera moves along these points at speed_mps from t = 0 and stops at the last one. A
  // player starts at the first one.
  std::vector<Eigen::Vector3d> waypoints_m{{0.0, 1.6, 0.0}, {0.0, 1.6, -4.0}};
  // With one point the camera always looks at it. With one per waypoint the point looked at is
  // interpolated along the path, so the view pans. A player looks at the first point at t = 0.
  std::vector<Eigen::Vector3d> look_at_m{{0.0, 1.6, -8.0}};
  double speed_mps = 2.0;
  double max_speed_mps = 3.0;  // V_c, the fastest the player can move the camera
  // For a track, the file, and which rows to take when it has a `strategy` column (empty for the
  // first strategy in the file).
  std::string track_file;
  std::string track_strategy;
  // For a track, the file's clock and frame (geometry/axis_convention.hpp), turned into fragsim's
  // on load.
  TrackTime track_time = TrackTime::kAsRecorded;
  double track_unit_m = 1.0;
  UpAxis track_up = UpAxis::kY;
  Handedness track_handedness = Handedness::kRight;
  // The track's samples, read from track_file when the scene is loaded (camera_track_file.hpp),
  // so a bad file fails before anything runs. Not a scene key.
  std::vector<CameraSample> track_samples;
  // A player's intended velocity changes at random moments, this far apart on average (infinity for
  // never). The actual velocity follows at up to player_accel_mps2 (infinity for at once), and the
  // view turns at up to turn_rate_degps toward random points within player_look_radius_m of the
  // object's centre, re-drawn as often as the velocity.
  double player_interval_s = 0.5;
  double player_accel_mps2 = 20.0;
  double turn_rate_degps = 90.0;
  double player_look_radius_m = 1.0;
  double fovy_deg = kDefaultFrustum.fovy_deg;
  double aspect = kDefaultFrustum.aspect;
  double near_m = kDefaultFrustum.near_m;
  double far_m = kDefaultFrustum.far_m;
  Eigen::Vector3d body_size_m{0.3, 0.2, 0.3};  // the camera's body, a box centred on the eye

  FrustumDef frustum_def() const { return {fovy_deg, aspect, near_m, far_m}; }
  AxisConvention track_frame() const { return {track_unit_m, track_up, track_handedness}; }
};

// Settings of the metrics (they observe a run and never change it).
struct MetricsDef {
  int grid_width_px = 160;     // occlusion raster; its height follows the camera's aspect
  double central_share = 0.5;  // the central region spans this share of width and height
  double near_miss_m = 1.0;    // a pass this close to the eye, not touching, is a near miss
  double deviation_threshold_m = 0.01;  // a fragment moved more than this "deviated"
};

struct Scene {
  std::string name = "unnamed";
  SimulationDef sim;
  ObjectDef object;
  ExplosionDef explosion;
  GroundDef ground;
  CameraDef camera;
  // Every strategy's parameters (scene.strategies.edge.k), from a scene file's strategy sections.
  StrategySettings strategies;
  MetricsDef metrics;

  int fragment_count() const;
  int step_count() const;
};

}  // namespace fragsim
