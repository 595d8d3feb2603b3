#include "sim/world.hpp"

#include <ode/ode.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "sim/body_snapshot.hpp"
#include "sim/face_manifold.hpp"
#include "sim/ground_sweep.hpp"
#include "sim/world_probe.hpp"

namespace fragsim {
namespace {

// ODE reports through process-wide hooks that carry no context pointer, so its warnings can only
// be counted process-wide; runs read the counter before and after (World::ode_messages).
std::atomic<long> g_ode_messages{0};
// The exact solver's LCP failures are counted apart, because World::step redoes such a step and
// counts that (World::exact_step_retries); a failure it could not redo would still be a message.
std::atomic<long> g_lcp_failures{0};
std::atomic<long> g_exact_step_retries{0};

void count_message(int, const char* msg, va_list) {
  if (std::strncmp(msg, "LCP internal error", 18) == 0) {
    ++g_lcp_failures;
  } else {
    ++g_ode_messages;
  }
}

// ODE exits (errors) or aborts (debug checks) after its hook returns, so first say what happened,
// as one line, in fragsim's voice.
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
  dMatrix3 r;  // ODE's layout, 3x4 row-major
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[i * 4 + j] = rot(i, j);
    r[i * 4 + 3] = 0.0;
  }
  dBodySetPosition(body, pos.x(), pos.y(), pos.z());
  dBodySetRotation(body, r);
}

constexpr int kMaxContactsPerPair = 4;
// A convex piece's face on the ground or on a box may have more than 4 corners; with only 4 of
// them as contacts the piece would rest on part of its face and tip. Boxes keep 4, bit for bit.
constexpr int kMaxConvexContacts = 8;
// The constraint force mixing of a convex piece's ground contacts. At double-precision ODE's world
// CFM, 1e-10, a piece's up to 4 ground contacts (vertices below the plane, often nearly in a line)
// leave the exact solver's LCP nearly singular, and the soak gets "LCP internal error, s <= 0" on
// 27 Voronoi cells landing at dt 0.1 s. 1e-5, ODE's single-precision default, makes it rarer; boxes
// keep the world's value. No value rules it out (the soak gets it at every CFM tried, on cells and
// on cubes), so World::step also redoes a step whose LCP failed.
constexpr double kConvexGroundCfm = 1e-5;
// The speculative contacts' CFM as a share, CFM = share x dt / m (ground_sweep.hpp). ODE's CFM is
// absolute (a contact keeps CFM x its force of approach speed), so a fixed value would let a heavy
// piece through; scaled by dt / m, a contact keeps at most this share of the speed it takes away,
// whatever the mass and step.
constexpr double kSweepCfmShare = 1e-3;

// The most a fragment's contact may give way to a unit impulse in ODE's units, 1/m + r^2/I (the
// entries of the matrix J M^-1 J^T that ODE's exact solver factors), bounded by 1/m plus the
// bounding radius squared over the smallest principal moment. ODE's exact solver aborts the process
// (dxLDLTRemove: "d[i] != 0", or dxNormalize4 after it) once that reaches about 5e7 per kg at any
// step from 1 ms to 1 s and any CFM; QuickStep and heavy bodies (1e30 kg) do not. On boxes dropped
// on a plane, a 1 cm cube of 3e-8 kg fails, one of 1e-7 kg runs, and a 0.1 m cube of 1 kg with its
// inertia cut 1e8 times fails too. The world therefore works in a mass unit that keeps every
// fragment 50 times under the failure. ODE's masses are kg times ode_mass_scale (1 unless a
// fragment is that light, as in every shipped scene), and forces and CFMs are scaled to match, so
// the run is the same physics in another unit. The ground, camera and wall are immovable, the
// fragments all take the same factor, and every velocity is unchanged.
constexpr double kMaxInverseMassPerKg = 1e6;

// Below these a piece's mass or smallest moment is refused, because ODE needs both positive and
// normal (dMassCheck), and so does ode_mass_scale's arithmetic, with room to spare (a 1e-60 m grain
// of anything still runs; object.size_m and object.density_kgpm3 reach below them only together).
constexpr double kLeastMassKg = 1e-250;
constexpr double kLeastMomentKgm2 = 1e-250;

double smallest_moment_kgm2(const FragmentSpawn& s) {
  if (s.shape) {
    const Eigen::Matrix3d inertia_kgm2 = s.mass_kg * s.shape->inertia_per_kg_m2;
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_kgm2, Eigen::EigenvaluesOnly)
        .eigenvalues()
        .minCoeff();
  }
  const Eigen::Vector3d e2 = (2.0 * s.half_extents_m).cwiseAbs2();
  return s.mass_kg / 12.0 * std::min({e2.y() + e2.z(), e2.x() + e2.z(), e2.x() + e2.y()});
}

// Refuses, naming it, the first piece too light for ODE (kLeastMassKg, kLeastMomentKgm2).
void check_masses(const std::vector<FragmentSpawn>& spawns) {
  for (std::size_t i = 0; i < spawns.size(); ++i) {
    const double m = spawns[i].mass_kg;
    const double moment = smallest_moment_kgm2(spawns[i]);
    if (m >= kLeastMassKg && moment >= kLeastMomentKgm2) continue;
    throw InputError("object: piece " + std::to_string(i + 1) + " weighs " + format_double(m) +
                     " kg, its smallest moment of inertia " + format_double(moment) +
                     " kg m^2: below the 1e-250 that ODE can step (raise object.size_m or "
                     "object.density_kgpm3)");
  }
}

// The bound above for a fragment, 1/m + R^2 / I_min.
double inverse_mass_bound_per_kg(const FragmentSpawn& s) {
  const double radius_m = s.shape ? s.shape->radius_m : s.half_extents_m.norm();
  return 1.0 / s.mass_kg + radius_m * radius_m / smallest_moment_kgm2(s);
}

// ODE's mass per kg for these fragments, 1 or what brings the loosest below the bound.
double ode_mass_scale(const std::vector<FragmentSpawn>& spawns) {
  double loosest = 0.0;
  for (const FragmentSpawn& s : spawns) loosest = std::max(loosest, inverse_mass_bound_per_kg(s));
  return loosest > kMaxInverseMassPerKg ? loosest / kMaxInverseMassPerKg : 1.0;
}

// A fragment's convex hull in ODE's format (dCreateConvex keeps pointers to these arrays, so they
// live as long as the world): planes (n, d), points, and per face its vertex count then indices.
struct OdeHull {
  std::vector<dReal> planes;
  std::vector<dReal> points;
  std::vector<unsigned int> polygons;
};

OdeHull to_ode(const ConvexShape& shape) {
  OdeHull h;
  for (std::size_t f = 0; f < shape.faces.size(); ++f) {
    const Eigen::Vector3d& n = shape.normals[f];
    h.planes.insert(h.planes.end(), {n.x(), n.y(), n.z(), shape.offsets_m[f]});
    h.polygons.push_back(static_cast<unsigned int>(shape.faces[f].size()));
    for (int v : shape.faces[f]) h.polygons.push_back(static_cast<unsigned int>(v));
  }
  for (const Eigen::Vector3d& v : shape.vertices_m)
    h.points.insert(h.points.end(), {v.x(), v.y(), v.z()});
  return h;
}

Eigen::Vector3d geom_position(dGeomID g) {
  const dReal* p = dGeomGetPosition(g);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

Eigen::Matrix3d geom_rotation(dGeomID g) {
  const dReal* r = dGeomGetRotation(g);
  Eigen::Matrix3d m;
  m << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
  return m;
}

// Contacts between convex a (g1) and convex-or-box b (g2). Debian's ODE 0.16 is built with libccd,
// so its dispatch sends convex-box and convex-convex to libccd's MPR, which finds overlap, normal
// and depth well but returns one point. A piece resting on a box then pivots and spins on that
// point for ever (a 0.1 m convex cube on a static box turns at 2.7 rad/s after 10 s, 12 mm sunk,
// where the same cube on the plane, whose collider returns every vertex below it, rests at once).
// So MPR's answer is the gate and the normal, and the points are the face manifold
// (face_manifold.hpp). An edge or corner contact (no face turned to the normal, or nothing left
// after clipping) keeps MPR's one point.
int convex_manifold(dGeomID a, const WorldHull& ha, dGeomID b, const WorldHull& hb, int max_count,
                    dContactGeom* out, int skip) {
  dContactGeom mpr{};
  if (dCollide(a, b, 1, &mpr, sizeof(dContactGeom)) == 0) return 0;
  auto* bytes = reinterpret_cast<char*>(out);
  auto at = [&](int i) { return reinterpret_cast<dContactGeom*>(bytes + i * skip); };
  // ODE's normal points from g2 into g1.
  const FaceManifold face =
      face_manifold(ha, hb, Eigen::Vector3d(mpr.normal[0], mpr.normal[1], mpr.normal[2]));
  if (face.points.empty()) {
    *at(0) = mpr;
    return 1;
  }
  const int count = std::min(static_cast<int>(face.points.size()), max_count);
  for (int i = 0; i < count; ++i) {
    dContactGeom& c = *at(i);
    c = mpr;
    const ManifoldPoint& p = face.points[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      c.pos[k] = p.position_m[k];
      c.normal[k] = face.normal[k];
    }
    c.depth = p.depth_m;
  }
  return count;
}

// Keeps, in place, `keep` of the n contacts at out (stride `skip`) spread over the footprint, the
// deepest, then each time the one farthest from all kept so far (first in ODE's order on a tie). A
// piece resting on a face with many corners keeps its support polygon's extremes; n <= keep leaves
// the contacts as they are.
int keep_spread(dContactGeom* out, int n, int keep, int skip) {
  if (n <= keep) return n;
  auto* bytes = reinterpret_cast<char*>(out);
  auto at = [&](int i) { return reinterpret_cast<dContactGeom*>(bytes + i * skip); };
  std::array<dContactGeom, kMaxConvexContacts> all{};
  for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = *at(i);
  std::array<double, kMaxConvexContacts> nearest2{};
  std::array<char, kMaxConvexContacts> taken{};
  int first = 0;
  for (int i = 1; i < n; ++i) {
    if (all[static_cast<std::size_t>(i)].depth > all[static_cast<std::size_t>(first)].depth) {
      first = i;
    }
  }
  nearest2.fill(INFINITY);
  int pick = first;
  for (int k = 0; k < keep; ++k) {
    const dContactGeom& chosen = all[static_cast<std::size_t>(pick)];
    taken[static_cast<std::size_t>(pick)] = 1;
    *at(k) = chosen;
    int next = -1;
    for (int i = 0; i < n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      if (taken[u]) continue;
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c)
        d2 += (all[u].pos[c] - chosen.pos[c]) * (all[u].pos[c] - chosen.pos[c]);
      nearest2[u] = std::min(nearest2[u], d2);
      if (next < 0 || nearest2[u] > nearest2[static_cast<std::size_t>(next)]) next = i;
    }
    if (next < 0) return k + 1;
    pick = next;
  }
  return keep;
}

// Slack added to the distance within which the camera (or its wall) wakes a culled fragment.
constexpr double kWakeMargin_m = 0.05;

// The camera's view volume, to tell whether a sphere may be seen. The near plane is left out on
// purpose (the sphere is only tested against the eye), because the near-plane strategy moves it.
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
  std::vector<GeomTag> fragment_tags;  // stable addresses, sized once
  GeomTag ground_tag{GeomKind::kGround, -1};
  GeomTag sensor_tag{GeomKind::kCameraSensor, -1};
  GeomTag wall_tag{GeomKind::kWall, -1};
  dGeomID ground_geom = nullptr;
  dGeomID sensor_geom = nullptr;
  dGeomID wall_geom = nullptr;
  // Every shape a fragment uses, kept alive for the snapshots' raw pointers, and its arrays for
  // ODE, one set per shape however many fragments share it.
  std::vector<std::shared_ptr<const ConvexShape>> shapes;
  std::map<const ConvexShape*, OdeHull> ode_hulls;
  dBodyID camera_body = nullptr;
  dBodyID wall_body = nullptr;
  std::optional<CameraWallSpec> wall;
  std::vector<FragmentState> constant;  // extents, shape, mass, radius
  std::vector<char> touched;
  std::vector<char> hit_flag;
  std::vector<int> hits;
  int wall_contact_count = 0;
  // Fragments that overlapped the wall in the first step, which the wall lets through until they
  // are clear of it (see on_pair), and which of them touched it in the current step.
  std::vector<int> inside_wall;
  std::vector<char> inside_wall_flag, inside_wall_touched;
  bool first_step = true;
  double mass_scale = 1.0;  // ODE's mass per kg (ode_mass_scale)
  bool fragment_collisions = false;
  bool exact_solver = false;
  int convex_ground_contacts = kMaxConvexContacts;  // simulation.convex_ground_contacts
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
  // A culled fragment whose bounding sphere comes this close to the eye (plus its radius) is woken.
  // It is the camera body's, or the wall's, farthest point from the eye.
  double wake_radius_m = 0.0;

  BodySnapshot before_step;  // every awake body before an exact step, to redo it if it fails

  bool asleep(std::size_t i) const { return !culled[i] && !dBodyIsEnabled(bodies[i]); }

  void cull(std::size_t i) {
    culled[i] = 1;
    ++culled_total;
    dBodyDisable(bodies[i]);
    // As ODE's auto-disable does, a body that does not move reports no speed; otherwise a strategy
    // would see a frozen fragment creeping at up to rest_linear_mps.
    dBodySetLinearVel(bodies[i], 0.0, 0.0, 0.0);
    dBodySetAngularVel(bodies[i], 0.0, 0.0, 0.0);
    // With fragment collisions the geom must stay, so that another fragment does not pass through
    // it (ODE wakes the body on such a contact).
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

  // Before collision detection, with the camera placed for the coming step, wakes culled fragments
  // the camera or the wall could touch then and culls resting ones out of view and reach.
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

  // After a step, counts the steps each awake fragment has been at rest.
  void count_rest() {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (culled[i]) {
        if (!dBodyIsEnabled(bodies[i])) continue;
        uncull(i);  // ODE woke it, so a fragment hit it (fragment collisions)
      }
      if (!dBodyIsEnabled(bodies[i])) continue;  // asleep, so still at rest
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

  const OdeHull& ode_hull(const std::shared_ptr<const ConvexShape>& shape) {
    auto [it, added] = ode_hulls.try_emplace(shape.get());
    if (added) {
      it->second = to_ode(*shape);
      shapes.push_back(shape);
    }
    return it->second;
  }

  const ConvexShape* shape_of(const GeomTag* t) const {
    return t->kind == GeomKind::kFragment ? constant[static_cast<std::size_t>(t->fragment)].shape
                                          : nullptr;
  }

  WorldHull hull_of(dGeomID g, const GeomTag* t) const {
    const Eigen::Vector3d position_m = geom_position(g);
    const Eigen::Matrix3d rotation = geom_rotation(g);
    if (const ConvexShape* s = shape_of(t)) {
      return place_hull(position_m, rotation, s->vertices_m, s->faces, s->normals, s->offsets_m);
    }
    if (t->kind == GeomKind::kWall) {
      return place_box(position_m, rotation,
                       0.5 * Eigen::Vector3d(wall->width_m, wall->height_m, wall->thickness_m));
    }
    return place_box(position_m, rotation,
                     constant[static_cast<std::size_t>(t->fragment)].half_extents_m);
  }

  // The contacts of fragment geom a with b, at most max_count. Boxes, the ground plane (ODE's
  // convex-plane collider returns every vertex below the plane) and the sensor (which needs only
  // whether they touch) go to dCollide as they are; a convex piece against a box or another piece
  // to convex_manifold.
  int collide(dGeomID a, const GeomTag* ta, dGeomID b, const GeomTag* tb, int max_count,
              dContactGeom* out, int skip) const {
    const bool convex = shape_of(ta) != nullptr || shape_of(tb) != nullptr;
    if (convex && tb->kind == GeomKind::kGround) {
      return keep_spread(out, dCollide(a, b, max_count, out, skip),
                         std::min(max_count, convex_ground_contacts), skip);
    }
    if (!convex || tb->kind == GeomKind::kCameraSensor) return dCollide(a, b, max_count, out, skip);
    return convex_manifold(a, hull_of(a, ta), b, hull_of(b, tb), max_count, out, skip);
  }

  // Fragments let through the wall that touched it no more this step are treated as any other
  // from the next one.
  void release_clear_of_wall() {
    std::erase_if(inside_wall, [&](int f) {
      const auto i = static_cast<std::size_t>(f);
      if (inside_wall_touched[i]) {
        inside_wall_touched[i] = 0;
        return false;
      }
      inside_wall_flag[i] = 0;
      return true;
    });
  }

  // A speculative contact for each awake convex piece that could pass through the ground this step
  // (ground_sweep.hpp); after the colliders' contacts, so a step that needs none is unchanged.
  void sweep_pieces_to_ground(double dt_s) {
    dVector3 g;
    dWorldGetGravity(world, g);
    const GroundSweepDef def{ground.height_m, g[1], ground.friction, kSweepCfmShare};
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const FragmentState& c = constant[i];
      if (c.shape == nullptr || !dBodyIsEnabled(bodies[i])) continue;
      add_ground_sweep_contacts(
          world, contacts, ground_geom,
          {bodies[i], geoms[i], c.shape->vertices_m, c.shape->radius_m, mass_scale * c.mass_kg},
          dt_s, def);
    }
  }

  void on_pair(dGeomID a, dGeomID b) {
    const auto* ta = static_cast<const GeomTag*>(dGeomGetData(a));
    const auto* tb = static_cast<const GeomTag*>(dGeomGetData(b));
    if (ta->kind != GeomKind::kFragment) {
      std::swap(a, b);
      std::swap(ta, tb);
    }
    if (ta->kind != GeomKind::kFragment) return;  // two static geoms make no contact
    if (tb->kind == GeomKind::kGround && skip_sleeping_ground && !dBodyIsEnabled(dGeomGetBody(a))) {
      return;
    }
    std::array<dContact, kMaxConvexContacts> contact{};
    if (tb->kind == GeomKind::kCameraSensor) {
      // A sensor records the touch and lets the fragment pass through.
      if (collide(a, ta, b, tb, 1, &contact[0].geom, sizeof(dContact)) > 0 &&
          !hit_flag[ta->fragment]) {
        hit_flag[ta->fragment] = 1;
        hits.push_back(ta->fragment);
      }
      return;
    }
    const bool convex = shape_of(ta) != nullptr || shape_of(tb) != nullptr;
    const int n = collide(a, ta, b, tb, convex ? kMaxConvexContacts : kMaxContactsPerPair,
                          &contact[0].geom, sizeof(dContact));
    if (tb->kind == GeomKind::kWall && n > 0) {
      // A fragment that begins the run inside the wall (a blast closer to the lens than the wall's
      // distance) is let through until it is clear of it. Pushed out from deep inside at ODE's
      // correcting speed along a contact normal that turns with the spinning box, it would leave
      // faster than anything threw it (the soak's seed 6751, 14 m/s out of a 2.7 m/s blast).
      const auto i = static_cast<std::size_t>(ta->fragment);
      if (first_step && !inside_wall_flag[i]) {
        inside_wall_flag[i] = 1;
        inside_wall.push_back(ta->fragment);
      }
      if (inside_wall_flag[i]) {
        inside_wall_touched[i] = 1;
        return;
      }
    }
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
      if (convex && tb->kind == GeomKind::kGround) {
        s.mode |= dContactSoftCFM;
        s.soft_cfm = kConvexGroundCfm / mass_scale;
      }
      dJointID j = dJointCreateContact(world, contacts, &contact[i]);
      dJointAttach(j, dGeomGetBody(contact[i].geom.g1), dGeomGetBody(contact[i].geom.g2));
    }
  }
};

World::World(const Scene& scene, const WorldNeeds& needs, const std::vector<FragmentSpawn>& spawns)
    : impl_(std::make_unique<Impl>()) {
  ensure_ode();
  // QuickStep shuffles constraints with ODE's global generator, so every world seeds it.
  dRandSetSeed(static_cast<unsigned long>(scene.sim.seed));
  Impl& w = *impl_;
  check_masses(spawns);  // before ODE holds anything, so a throw here leaks nothing
  w.fragment_collisions = scene.sim.fragment_collisions;
  w.convex_ground_contacts = std::clamp(scene.sim.convex_ground_contacts, 1, kMaxConvexContacts);
  // A wall joins every fragment touching it into one island, and the exact solver is cubic in an
  // island's size (341 fragments on the wall take 3.6 s for one step, 0.011 s with QuickStep).
  w.exact_solver =
      scene.sim.solver == Solver::kExact || (scene.sim.uses_exact_solver() && !needs.camera_wall);
  w.ground = scene.ground;
  w.wall = needs.camera_wall;
  w.world = dWorldCreate();
  w.mass_scale = ode_mass_scale(spawns);
  if (w.mass_scale != 1.0) dWorldSetCFM(w.world, dWorldGetCFM(w.world) / w.mass_scale);
  const Eigen::Vector3d& g = scene.sim.gravity_mps2;
  dWorldSetGravity(w.world, g.x(), g.y(), g.z());
  dWorldSetQuickStepNumIterations(w.world, scene.sim.solver_iterations);
  dWorldSetContactSurfaceLayer(w.world, 0.001);
  dWorldSetContactMaxCorrectingVel(w.world, 10.0);
  // Bodies copy the world's auto-disable settings when they are created, so those are set first.
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
  w.inside_wall_flag.assign(n, 0);
  w.inside_wall_touched.assign(n, 0);
  w.rest_count.assign(n, 0);
  w.culled.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const FragmentSpawn& s = spawns[i];
    dBodyID body = dBodyCreate(w.world);
    dMass mass;
    const Eigen::Vector3d size = 2.0 * s.half_extents_m;
    if (s.shape) {
      // The body frame is the shape's, with the centre of mass at the origin.
      const double m = w.mass_scale * s.mass_kg;
      const Eigen::Matrix3d inertia_kgm2 = m * s.shape->inertia_per_kg_m2;
      dMassSetParameters(&mass, m, 0.0, 0.0, 0.0, inertia_kgm2(0, 0), inertia_kgm2(1, 1),
                         inertia_kgm2(2, 2), inertia_kgm2(0, 1), inertia_kgm2(0, 2),
                         inertia_kgm2(1, 2));
    } else {
      dMassSetBoxTotal(&mass, w.mass_scale * s.mass_kg, size.x(), size.y(), size.z());
    }
    dBodySetMass(body, &mass);
    if (s.shape || s.rotation != Eigen::Matrix3d::Identity()) {
      set_pose(body, s.position_m, s.rotation);
    } else {
      dBodySetPosition(body, s.position_m.x(), s.position_m.y(), s.position_m.z());
    }
    dBodySetLinearVel(body, s.velocity_mps.x(), s.velocity_mps.y(), s.velocity_mps.z());
    dBodySetAngularVel(body, s.angular_velocity_radps.x(), s.angular_velocity_radps.y(),
                       s.angular_velocity_radps.z());
    dGeomID geom = nullptr;
    if (s.shape) {
      const OdeHull& hull = w.ode_hull(s.shape);
      geom = dCreateConvex(w.fragment_space, hull.planes.data(),
                           static_cast<unsigned int>(s.shape->faces.size()), hull.points.data(),
                           static_cast<unsigned int>(s.shape->vertices_m.size()),
                           hull.polygons.data());
    } else {
      geom = dCreateBox(w.fragment_space, size.x(), size.y(), size.z());
    }
    dGeomSetBody(geom, body);
    w.fragment_tags[i] = GeomTag{GeomKind::kFragment, static_cast<int>(i)};
    dGeomSetData(geom, &w.fragment_tags[i]);
    w.bodies.push_back(body);
    w.geoms.push_back(geom);
    FragmentState& c = w.constant[i];
    c.mass_kg = s.mass_kg;
    if (s.shape) {
      // Every per-fragment test below and downstream that reads half extents or the radius (the
      // view-volume cull and the camera's wake distance here, the metrics' boxes) reads a bound
      // that holds the piece, so it is conservative and never misses.
      c.shape = s.shape.get();
      c.half_extents_m = s.shape->half_extents_m;
      c.radius_m = s.shape->radius_m;
    } else {
      c.half_extents_m = s.half_extents_m;
      c.radius_m = s.half_extents_m.norm();
    }
  }

  if (scene.ground.enabled) {
    dGeomID plane = dCreatePlane(w.static_space, 0, 1, 0, scene.ground.height_m);
    dGeomSetData(plane, &w.ground_tag);
    w.ground_geom = plane;
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
  w.sensor_geom = sensor;
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
    w.wall_geom = wall;
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
    // A disabled body ignores forces, so it is woken first.
    if (w.culled[i]) {
      w.uncull(i);
    } else if (!dBodyIsEnabled(w.bodies[i])) {
      dBodyEnable(w.bodies[i]);
    }
    const Eigen::Vector3d force = w.mass_scale * f.force_N;  // in ODE's mass unit
    dBodyAddForce(w.bodies[i], force.x(), force.y(), force.z());
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
  if (!w.inside_wall.empty()) w.release_clear_of_wall();
  w.first_step = false;
  if (w.ground_geom != nullptr) w.sweep_pieces_to_ground(dt_s);
  if (w.exact_solver) {
    // ODE's Dantzig solver can fail on an island ("LCP internal error, s <= 0", nearly dependent
    // contact and friction rows) and then leaves that island's remaining forces at zero. No CFM
    // rules it out, so a failed step is redone from the state before it with the iterative
    // solver, which cannot fail that way; the contacts are still in their group.
    const std::array<dBodyID, 2> carried{w.camera_body, w.wall_body};
    w.before_step.save(w.bodies, carried);
    const long failures = g_lcp_failures.load();
    dWorldStep(w.world, dt_s);
    if (g_lcp_failures.load() != failures) {
      w.before_step.restore();
      dWorldQuickStep(w.world, dt_s);
      ++g_exact_step_retries;
    }
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

long World::exact_step_retries() {
  return g_exact_step_retries.load();
}

std::vector<ProbeContact> WorldProbe::contacts(const World& world, int fragment, ProbeTarget target,
                                               int other) {
  const World::Impl& w = *world.impl_;
  const auto i = static_cast<std::size_t>(fragment);
  dGeomID b = nullptr;
  const GeomTag* tb = nullptr;
  switch (target) {
    case ProbeTarget::kGround:
      b = w.ground_geom;
      tb = &w.ground_tag;
      break;
    case ProbeTarget::kCameraSensor:
      b = w.sensor_geom;
      tb = &w.sensor_tag;
      break;
    case ProbeTarget::kWall:
      b = w.wall_geom;
      tb = &w.wall_tag;
      break;
    case ProbeTarget::kFragment:
      b = w.geoms[static_cast<std::size_t>(other)];
      tb = &w.fragment_tags[static_cast<std::size_t>(other)];
      break;
  }
  if (b == nullptr) return {};
  std::array<dContactGeom, kMaxConvexContacts> raw{};
  const int max_count = target == ProbeTarget::kCameraSensor ? 1
                        : w.constant[i].shape != nullptr || w.shape_of(tb) != nullptr
                            ? kMaxConvexContacts
                            : kMaxContactsPerPair;
  const int n = w.collide(w.geoms[i], &w.fragment_tags[i], b, tb, max_count, raw.data(),
                          sizeof(dContactGeom));
  std::vector<ProbeContact> out;
  for (int k = 0; k < n; ++k) {
    const dContactGeom& c = raw[static_cast<std::size_t>(k)];
    // ODE's normal points from g2 into g1; the fragment may have been either.
    const double sign = c.g1 == w.geoms[i] ? 1.0 : -1.0;
    out.push_back({{c.pos[0], c.pos[1], c.pos[2]},
                   sign * Eigen::Vector3d(c.normal[0], c.normal[1], c.normal[2]),
                   c.depth});
  }
  return out;
}

ProbeMass WorldProbe::mass(const World& world, int fragment) {
  dMass m;
  dBodyGetMass(world.impl_->bodies[static_cast<std::size_t>(fragment)], &m);
  ProbeMass out;
  const double scale = world.impl_->mass_scale;
  out.mass_kg = m.mass / scale;
  out.centre_m = {m.c[0], m.c[1], m.c[2]};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.inertia_kgm2(r, c) = m.I[r * 4 + c] / scale;
  }
  return out;
}

bool WorldProbe::is_convex(const World& world, int fragment) {
  return dGeomGetClass(world.impl_->geoms[static_cast<std::size_t>(fragment)]) == dConvexClass;
}

std::string World::ode_version() {
#ifdef FRAGSIM_ODE_VERSION
  return FRAGSIM_ODE_VERSION;
#else
  return "unknown";
#endif
}

}  // namespace fragsim
