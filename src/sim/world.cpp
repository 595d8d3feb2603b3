#include "sim/world.hpp"

#include <ode/ode.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace fragsim {
namespace {

// ODE reports through process-wide hooks that carry no context pointer, so its warnings can only
// be counted process-wide; runs read the counter before and after (World::ode_messages).
std::atomic<long> g_ode_messages{0};

void count_message(int, const char*, va_list) {
  ++g_ode_messages;
}

// ODE exits (errors) or aborts (debug checks) after its hook returns: say what happened first, as
// one line, in fragsim's voice.
void report_fatal(int num, const char* msg, va_list ap) {
  std::fprintf(stderr, "fragsim: ODE internal error %d: ", num);
  std::vfprintf(stderr, msg, ap);
  std::fputc('\n', stderr);
}

// ODE keeps process-wide state; initialise it once and close it at exit.
struct OdeLibrary {
  OdeLibrary() {
    dInitODE2(0);
    dSetMessageHandler(&count_message);
    dSetErrorHandler(&report_fatal);
    dSetDebugHandler(&report_fatal);
  }
  ~OdeLibrary() { dCloseODE(); }
};
void ensure_ode() {
  static OdeLibrary lib;
}

enum class GeomKind : int { kFragment, kGround, kCameraSensor, kWall };

// What a geom is, reached through dGeomGetData.
struct GeomTag {
  GeomKind kind = GeomKind::kFragment;
  int fragment = -1;
};

void set_pose(dBodyID body, const Eigen::Vector3d& pos, const Eigen::Matrix3d& rot) {
  dMatrix3 r;  // ODE: 3x4 row-major
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i * 4 + j] = rot(i, j);
    r[i * 4 + 3] = 0.0;
  }
  dBodySetPosition(body, pos.x(), pos.y(), pos.z());
  dBodySetRotation(body, r);
}

constexpr int kMaxContactsPerPair = 4;

// Slack added to the distance within which the camera (or its wall) wakes a culled fragment.
constexpr double kWakeMargin_m = 0.05;

// The camera's view volume, to tell whether a sphere may be seen. The near plane is left out on
// purpose (the sphere is only tested against the eye): the near-plane strategy moves it.
class ViewVolume {
 public:
  explicit ViewVolume(const CameraPose& pose) : pose_(pose), frustum_(pose.frustum()) {}
  bool may_see(const Eigen::Vector3d& centre_m, double radius_m) const {
    return frustum_.sphere_may_show(pose_.to_camera(centre_m), radius_m, 0.0);
  }

 private:
  CameraPose pose_;
  Frustum frustum_;
};

}  // namespace

struct World::Impl {
  dWorldID world = nullptr;
  dSpaceID fragment_space = nullptr;
  dSpaceID static_space = nullptr;
  dJointGroupID contacts = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<dGeomID> geoms;
  std::vector<GeomTag> fragment_tags;  // stable addresses: sized once
  GeomTag ground_tag{GeomKind::kGround, -1};
  GeomTag sensor_tag{GeomKind::kCameraSensor, -1};
  GeomTag wall_tag{GeomKind::kWall, -1};
  dBodyID camera_body = nullptr;
  dBodyID wall_body = nullptr;
  std::optional<CameraWallSpec> wall;
  std::vector<FragmentState> constant;  // extents, mass, radius
  std::vector<char> touched;
  std::vector<char> hit_flag;
  std::vector<int> hits;
  int wall_contact_count = 0;
  bool fragment_collisions = false;
  bool exact_solver = false;
  GroundDef ground;

  // Skips (simulation.auto_disable, simulation.cull_resting).
  bool auto_disable = false;
  bool cull_resting = false;
  // A sleeping fragment's contact with the ground is only used if ODE wakes the fragment while it
  // builds islands, through a contact with an awake fragment or the wall; without either, the
  // contact can be left out (ODE would skip it).
  bool skip_sleeping_ground = false;
  double rest_linear2_mps2 = 0.0;  // squared thresholds
  double rest_angular2_radps2 = 0.0;
  int rest_steps = 0;
  std::vector<int> rest_count;  // steps in a row at rest
  std::vector<char> culled;
  int culled_total = 0;
  CameraPose camera;  // as placed for the coming step
  bool camera_placed = false;
  // A culled fragment whose bounding sphere comes this close to the eye (plus its radius) is
  // woken: the camera body's, or the wall's, farthest point from the eye.
  double wake_radius_m = 0.0;

  bool asleep(std::size_t i) const { return !culled[i] && !dBodyIsEnabled(bodies[i]); }

  void cull(std::size_t i) {
    culled[i] = 1;
    ++culled_total;
    dBodyDisable(bodies[i]);
    // As ODE's auto-disable does: a body that does not move reports no speed (a strategy would
    // otherwise see a frozen fragment creeping at up to rest_linear_mps).
    dBodySetLinearVel(bodies[i], 0.0, 0.0, 0.0);
    dBodySetAngularVel(bodies[i], 0.0, 0.0, 0.0);
    // With fragment collisions the geom must stay: another fragment must not pass through it
    // (ODE wakes the body on such a contact).
    if (!fragment_collisions) dGeomDisable(geoms[i]);
  }
  void uncull(std::size_t i) {
    culled[i] = 0;
    --culled_total;
    dGeomEnable(geoms[i]);
    dBodyEnable(bodies[i]);
    rest_count[i] = 0;
  }

  bool near_camera(std::size_t i) const {
    const dReal* p = dBodyGetPosition(bodies[i]);
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - camera.eye_m;
    const double reach = wake_radius_m + constant[i].radius_m + kWakeMargin_m;
    return d.squaredNorm() <= reach * reach;
  }

  // Before collision detection, with the camera placed for the coming step: wakes culled
  // fragments the camera or the wall could touch now, culls resting ones out of view and reach.
  void update_culling() {
    if (!camera_placed) return;
    const ViewVolume view(camera);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (culled[i]) {
        if (near_camera(i)) uncull(i);
        continue;
      }
      const bool resting = rest_count[i] >= rest_steps || !dBodyIsEnabled(bodies[i]);
      if (!resting || near_camera(i)) continue;
      const dReal* p = dBodyGetPosition(bodies[i]);
      if (view.may_see({p[0], p[1], p[2]}, constant[i].radius_m)) continue;
      cull(i);
    }
  }

  // After a step: counts the steps each awake fragment has been at rest.
  void count_rest() {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (culled[i]) {
        if (!dBodyIsEnabled(bodies[i])) continue;
        uncull(i);  // ODE woke it: a fragment hit it (fragment collisions)
      }
      if (!dBodyIsEnabled(bodies[i])) continue;  // asleep: still at rest
      const dReal* v = dBodyGetLinearVel(bodies[i]);
      const dReal* a = dBodyGetAngularVel(bodies[i]);
      const bool slow = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= rest_linear2_mps2 &&
                        a[0] * a[0] + a[1] * a[1] + a[2] * a[2] <= rest_angular2_radps2;
      rest_count[i] = touched[i] && slow ? std::min(rest_count[i] + 1, rest_steps) : 0;
    }
  }

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    static_cast<Impl*>(data)->on_pair(a, b);
  }

  void on_pair(dGeomID a, dGeomID b) {
    const auto* ta = static_cast<const GeomTag*>(dGeomGetData(a));
    const auto* tb = static_cast<const GeomTag*>(dGeomGetData(b));
    if (ta->kind != GeomKind::kFragment) {
      std::swap(a, b);
      std::swap(ta, tb);
    }
    if (ta->kind != GeomKind::kFragment) return;  // two static geoms: never
    if (tb->kind == GeomKind::kGround && skip_sleeping_ground && !dBodyIsEnabled(dGeomGetBody(a))) {
      return;
    }
    std::array<dContact, kMaxContactsPerPair> contact{};
    if (tb->kind == GeomKind::kCameraSensor) {
      // A sensor: record the touch, let the fragment pass through.
      if (dCollide(a, b, 1, &contact[0].geom, sizeof(dContact)) > 0 && !hit_flag[ta->fragment]) {
        hit_flag[ta->fragment] = 1;
        hits.push_back(ta->fragment);
      }
      return;
    }
    const int n = dCollide(a, b, kMaxContactsPerPair, &contact[0].geom, sizeof(dContact));
    if (n == 0) return;
    double bounce = ground.restitution;
    double mu = ground.friction;
    if (tb->kind == GeomKind::kWall) {
      bounce = wall->restitution;
      mu = 0.3;
      wall_contact_count += n;
    } else if (tb->kind == GeomKind::kFragment) {
      touched[tb->fragment] = 1;
    }
    touched[ta->fragment] = 1;
    for (int i = 0; i < n; ++i) {
      dSurfaceParameters& s = contact[i].surface;
      s.mode = dContactBounce | dContactApprox1;
      s.mu = mu;
      s.bounce = bounce;
      s.bounce_vel = 0.1;
      dJointID j = dJointCreateContact(world, contacts, &contact[i]);
      dJointAttach(j, dGeomGetBody(contact[i].geom.g1), dGeomGetBody(contact[i].geom.g2));
    }
  }
};

World::World(const Scene& scene, const WorldNeeds& needs, const std::vector<FragmentSpawn>& spawns)
    : impl_(std::make_unique<Impl>()) {
  ensure_ode();
  // QuickStep shuffles constraints with ODE's global generator: seed it for every world.
  dRandSetSeed(static_cast<unsigned long>(scene.sim.seed));
  Impl& w = *impl_;
  w.fragment_collisions = scene.sim.fragment_collisions;
  // A wall joins every fragment touching it into one island, and the exact solver is cubic in an
  // island's size (341 fragments on the wall: 3.6 s for one step, 0.011 s with QuickStep).
  w.exact_solver =
      scene.sim.solver == Solver::kExact || (scene.sim.uses_exact_solver() && !needs.camera_wall);
  w.ground = scene.ground;
  w.wall = needs.camera_wall;
  w.world = dWorldCreate();
  const Eigen::Vector3d& g = scene.sim.gravity_mps2;
  dWorldSetGravity(w.world, g.x(), g.y(), g.z());
  dWorldSetQuickStepNumIterations(w.world, scene.sim.solver_iterations);
  dWorldSetContactSurfaceLayer(w.world, 0.001);
  dWorldSetContactMaxCorrectingVel(w.world, 10.0);
  // Bodies copy the world's auto-disable settings when they are created: set them first.
  const SimulationDef& sim = scene.sim;
  w.auto_disable = sim.auto_disable;
  w.cull_resting = sim.cull_resting;
  w.skip_sleeping_ground = sim.auto_disable && !sim.fragment_collisions && !needs.camera_wall;
  w.rest_linear2_mps2 = sim.rest_linear_mps * sim.rest_linear_mps;
  w.rest_angular2_radps2 = sim.rest_angular_radps * sim.rest_angular_radps;
  w.rest_steps = sim.rest_steps;
  dWorldSetAutoDisableFlag(w.world, sim.auto_disable ? 1 : 0);
  dWorldSetAutoDisableLinearThreshold(w.world, sim.rest_linear_mps);
  dWorldSetAutoDisableAngularThreshold(w.world, sim.rest_angular_radps);
  dWorldSetAutoDisableSteps(w.world, sim.rest_steps);
  dWorldSetAutoDisableTime(w.world, 0.0);
  dWorldSetAutoDisableAverageSamplesCount(w.world, 1);
  // Fragments only ever collide through the fragment space; a simple space when pairs are never
  // tested (it is only walked by dSpaceCollide2), sweep-and-prune when they are.
  w.fragment_space = scene.sim.fragment_collisions
                         ? dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XZY)
                         : dSimpleSpaceCreate(nullptr);
  w.static_space = dSimpleSpaceCreate(nullptr);
  w.contacts = dJointGroupCreate(0);

  const std::size_t n = spawns.size();
  w.fragment_tags.resize(n);
  w.bodies.reserve(n);
  w.constant.resize(n);
  w.geoms.reserve(n);
  w.touched.assign(n, 0);
  w.hit_flag.assign(n, 0);
  w.rest_count.assign(n, 0);
  w.culled.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const FragmentSpawn& s = spawns[i];
    dBodyID body = dBodyCreate(w.world);
    dMass mass;
    const Eigen::Vector3d size = 2.0 * s.half_extents_m;
    dMassSetBoxTotal(&mass, s.mass_kg, size.x(), size.y(), size.z());
    dBodySetMass(body, &mass);
    dBodySetPosition(body, s.position_m.x(), s.position_m.y(), s.position_m.z());
    dBodySetLinearVel(body, s.velocity_mps.x(), s.velocity_mps.y(), s.velocity_mps.z());
    dBodySetAngularVel(body, s.angular_velocity_radps.x(), s.angular_velocity_radps.y(),
                       s.angular_velocity_radps.z());
    dGeomID geom = dCreateBox(w.fragment_space, size.x(), size.y(), size.z());
    dGeomSetBody(geom, body);
    w.fragment_tags[i] = GeomTag{GeomKind::kFragment, static_cast<int>(i)};
    dGeomSetData(geom, &w.fragment_tags[i]);
    w.bodies.push_back(body);
    w.geoms.push_back(geom);
    FragmentState& c = w.constant[i];
    c.half_extents_m = s.half_extents_m;
    c.mass_kg = s.mass_kg;
    c.radius_m = s.half_extents_m.norm();
  }

  if (scene.ground.enabled) {
    dGeomID plane = dCreatePlane(w.static_space, 0, 1, 0, scene.ground.height_m);
    dGeomSetData(plane, &w.ground_tag);
  }
  const Eigen::Vector3d& body = scene.camera.body_size_m;
  w.camera_body = dBodyCreate(w.world);
  dBodySetKinematic(w.camera_body);
  // A still camera would otherwise fall asleep; so would the wall, which must wake what it meets.
  dBodySetAutoDisableFlag(w.camera_body, 0);
  w.wake_radius_m = 0.5 * body.norm();
  dGeomID sensor = dCreateBox(w.static_space, body.x(), body.y(), body.z());
  dGeomSetBody(sensor, w.camera_body);
  dGeomSetData(sensor, &w.sensor_tag);
  if (w.wall) {
    w.wall_body = dBodyCreate(w.world);
    dBodySetKinematic(w.wall_body);
    dBodySetAutoDisableFlag(w.wall_body, 0);
    const Eigen::Vector3d half(0.5 * w.wall->width_m, 0.5 * w.wall->height_m,
                               0.5 * w.wall->thickness_m);
    w.wake_radius_m = std::max(w.wake_radius_m, w.wall->distance_m + half.norm());
    dGeomID wall =
        dCreateBox(w.static_space, w.wall->width_m, w.wall->height_m, w.wall->thickness_m);
    dGeomSetBody(wall, w.wall_body);
    dGeomSetData(wall, &w.wall_tag);
  }
}

World::~World() {
  Impl& w = *impl_;
  dJointGroupDestroy(w.contacts);
  dSpaceDestroy(w.fragment_space);  // destroys its geoms
  dSpaceDestroy(w.static_space);
  dWorldDestroy(w.world);  // destroys bodies and joints
}

int World::fragment_count() const {
  return static_cast<int>(impl_->bodies.size());
}

std::vector<FragmentState> World::init_states() const {
  std::vector<FragmentState> out = impl_->constant;
  read(out);
  return out;
}

void World::read(std::vector<FragmentState>& out) const {
  const Impl& w = *impl_;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    const dReal* p = dBodyGetPosition(w.bodies[i]);
    const dReal* v = dBodyGetLinearVel(w.bodies[i]);
    const dReal* r = dBodyGetRotation(w.bodies[i]);
    FragmentState& s = out[i];
    s.position_m = {p[0], p[1], p[2]};
    s.velocity_mps = {v[0], v[1], v[2]};
    s.rotation << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
    s.touched = w.touched[i] != 0;
  }
}

void World::set_camera(const CameraPose& pose, const Eigen::Vector3d& velocity_mps) {
  Impl& w = *impl_;
  w.camera = pose;
  w.camera_placed = true;
  const Eigen::Matrix3d rot = pose.rotation();
  set_pose(w.camera_body, pose.eye_m, rot);
  dBodySetLinearVel(w.camera_body, velocity_mps.x(), velocity_mps.y(), velocity_mps.z());
  if (w.wall_body) {
    set_pose(w.wall_body, pose.eye_m + w.wall->distance_m * pose.forward, rot);
    dBodySetLinearVel(w.wall_body, velocity_mps.x(), velocity_mps.y(), velocity_mps.z());
  }
}

void World::add_forces(std::span<const AppliedForce> forces) {
  Impl& w = *impl_;
  for (const AppliedForce& f : forces) {
    const auto i = static_cast<std::size_t>(f.fragment);
    // A disabled body ignores forces: wake it first.
    if (w.culled[i]) {
      w.uncull(i);
    } else if (!dBodyIsEnabled(w.bodies[i])) {
      dBodyEnable(w.bodies[i]);
    }
    dBodyAddForce(w.bodies[i], f.force_N.x(), f.force_N.y(), f.force_N.z());
  }
}

void World::step(double dt_s) {
  Impl& w = *impl_;
  if (w.cull_resting) w.update_culling();
  if (w.auto_disable || w.cull_resting) {
    // A sleeping or culled fragment keeps the contact flag it had when it came to rest.
    for (std::size_t i = 0; i < w.bodies.size(); ++i) {
      if (dBodyIsEnabled(w.bodies[i])) w.touched[i] = 0;
    }
  } else {
    std::fill(w.touched.begin(), w.touched.end(), 0);
  }
  for (int i : w.hits) w.hit_flag[static_cast<std::size_t>(i)] = 0;
  w.hits.clear();
  w.wall_contact_count = 0;
  dSpaceCollide2(reinterpret_cast<dGeomID>(w.fragment_space),
                 reinterpret_cast<dGeomID>(w.static_space), &w, &Impl::near_callback);
  if (w.fragment_collisions) dSpaceCollide(w.fragment_space, &w, &Impl::near_callback);
  if (w.exact_solver) {
    dWorldStep(w.world, dt_s);
  } else {
    dWorldQuickStep(w.world, dt_s);
  }
  dJointGroupEmpty(w.contacts);
  std::sort(w.hits.begin(), w.hits.end());
  if (w.cull_resting) w.count_rest();
}

FragmentActivity World::activity(int fragment) const {
  const auto i = static_cast<std::size_t>(fragment);
  if (impl_->culled[i]) return FragmentActivity::kCulled;
  return impl_->asleep(i) ? FragmentActivity::kAsleep : FragmentActivity::kAwake;
}

int World::awake_count() const {
  int n = 0;
  for (dBodyID b : impl_->bodies) n += dBodyIsEnabled(b) ? 1 : 0;
  return n;
}

int World::culled_count() const {
  return impl_->culled_total;
}

const std::vector<int>& World::camera_hits() const {
  return impl_->hits;
}
int World::wall_contacts() const {
  return impl_->wall_contact_count;
}

long World::ode_messages() {
  return g_ode_messages.load();
}

std::string World::ode_version() {
#ifdef FRAGSIM_ODE_VERSION
  return FRAGSIM_ODE_VERSION;
#else
  return "unknown";
#endif
}

}  // namespace fragsim
