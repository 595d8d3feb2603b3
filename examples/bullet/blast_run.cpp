#include "blast_run.hpp"

#include <fragsim/control.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "bullet_world.hpp"
#include "frame_clock.hpp"
#include "near_plane_check.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One fragment as the library reads it, in Bullet's own floats (btScalar; the arrays say
// FRAGSIM_SCALAR_FLOAT). Bullet keeps each body in its own object, not in arrays, so the example
// gathers them into this record and hands the records over as strided arrays.
struct FragmentRecord {
  btScalar position_m[3];
  btScalar velocity_mps[3];
  btScalar radius_m;
  btScalar mass_kg;
  uint64_t id;
  btScalar force_N[3];
};
static_assert(sizeof(btScalar) == sizeof(float), "Debian's Bullet is built in floats");

fragsim_vec3 to_fragsim(Vec3 v) {
  return {v.x, v.y, v.z};
}

// What Bullet's tick callbacks share, reached through the world's user info pointer.
struct Substeps {
  BulletWorld* physics = nullptr;
  const CameraPath* camera_path = nullptr;
  fragsim_controller_id controller{};  // null id: no controller
  fragsim_step_input input = fragsim_default_step_input();
  fragsim_camera_def camera_def = fragsim_default_camera_def();     // set once on the controller
  fragsim_camera_pose camera_pose = fragsim_default_camera_pose();  // what each substep passes
  fragsim_fragment_arrays arrays = fragsim_default_fragment_arrays();
  std::vector<FragmentRecord> fragments;
  std::vector<Vec3> centre_before_m;  // for the near-plane check
  std::vector<char> hit, pushed;
  NearRectangle near_rectangle;
  CameraPose camera_start, camera_end;
  double time_s = 0;  // the start of the substep being taken
  int count = 0;
  double callbacks_s = 0;
  RunResult* result = nullptr;
};

// Before each fixed substep, inside stepSimulation: the state the last substep left, the camera
// at this substep's start, one controller call, its forces applied for this substep only.
void before_substep(btDynamicsWorld* world, btScalar substep_s) {
  Substeps& s = *static_cast<Substeps*>(world->getWorldUserInfo());
  const Clock::time_point started = Clock::now();
  const double dt_s = substep_s;  // the step Bullet integrates, float included
  s.camera_start = s.camera_path->at(s.time_s);
  s.camera_end = s.camera_path->at(s.time_s + dt_s);
  const int n = s.physics->fragment_count();
  for (int i = 0; i < n; ++i) {
    const btRigidBody& body = s.physics->fragment(i);
    const btVector3& p = body.getCenterOfMassPosition();
    const btVector3& v = body.getLinearVelocity();
    FragmentRecord& f = s.fragments[i];
    f.position_m[0] = p.x(), f.position_m[1] = p.y(), f.position_m[2] = p.z();
    f.velocity_mps[0] = v.x(), f.velocity_mps[1] = v.y(), f.velocity_mps[2] = v.z();
    s.centre_before_m[i] = {f.position_m[0], f.position_m[1], f.position_m[2]};
  }
  if (!fragsim_controller_id_is_null(s.controller) && s.result->error.empty()) {
    fragsim_step_input& in = s.input;
    in.time_s = s.time_s;
    in.dt_s = dt_s;
    // Only what moves: the constants were set once (fragsim_controller_set_cameras below).
    fragsim_camera_pose& pose = s.camera_pose;
    pose.eye_m = to_fragsim(s.camera_start.eye_m);
    pose.right = to_fragsim(s.camera_start.right);
    pose.up = to_fragsim(s.camera_start.up);
    pose.forward = to_fragsim(s.camera_start.forward);
    // The eye's velocity over this substep, from the path (not the rendered frame's pose).
    pose.velocity_mps = to_fragsim((s.camera_end.eye_m - s.camera_start.eye_m) * (1 / dt_s));
    in.camera_poses = &pose;
    in.camera_count = 1;
    fragsim_step_stats stats;
    const Clock::time_point call = Clock::now();
    const fragsim_status status =
        fragsim_controller_step_arrays(s.controller, &in, &s.arrays, n, &stats);
    s.result->controller_s += seconds_since(call);
    if (status != FRAGSIM_OK) {
      s.result->error = fragsim_controller_last_error(s.controller);
    } else if (stats.skipped != 0) {
      s.result->error = "the controller skipped fragments: the conversion handed it bad numbers";
    } else {
      s.result->capped += stats.capped;
      s.result->warnings |= stats.warnings;
      for (int i = 0; i < n; ++i) {
        const btScalar* force = s.fragments[i].force_N;
        if (force[0] == 0 && force[1] == 0 && force[2] == 0) continue;
        btRigidBody& body = s.physics->fragment(i);
        // For this one substep only. stepSimulation clears forces once, after all the frame's
        // substeps: a force applied here with applyCentralForce would push again in every later
        // substep of the frame. Clearing forces in the post-tick instead would also clear the
        // gravity Bullet adds once per frame (the frame's later substeps would fall without it).
        // An impulse F dt_s changes the velocity now, before Bullet's semi-implicit Euler adds
        // g dt_s and moves the body by its new velocity: exactly the force F held for one substep.
        body.applyCentralImpulse(btVector3(force[0], force[1], force[2]) * substep_s);
        body.activate(true);  // Bullet does not integrate a sleeping body
        s.pushed[i] = 1;
      }
    }
  }
  s.callbacks_s += seconds_since(started);
}

// After each fixed substep: every fragment's sweep over it against the near rectangle.
void after_substep(btDynamicsWorld* world, btScalar substep_s) {
  Substeps& s = *static_cast<Substeps*>(world->getWorldUserInfo());
  const Clock::time_point started = Clock::now();
  const CameraPose& a = s.camera_start;
  const CameraPose& b = s.camera_end;
  for (int i = 0; i < s.physics->fragment_count(); ++i) {
    if (s.hit[i]) continue;  // a fragment counts once
    const btVector3& p = s.physics->fragment(i).getCenterOfMassPosition();
    const Vec3 before = to_camera_frame(s.centre_before_m[i], a.eye_m, a.right, a.up, a.forward);
    const Vec3 after = to_camera_frame({p.x(), p.y(), p.z()}, b.eye_m, b.right, b.up, b.forward);
    if (swept_sphere_meets(s.near_rectangle, before, after, s.physics->bounding_radius_m(i))) {
      s.hit[i] = 1;
      s.result->last_hit_s = s.time_s + substep_s;
    }
  }
  s.time_s += substep_s;
  ++s.count;
  s.callbacks_s += seconds_since(started);
}

// The step input's parts that stay for the run: gravity as Bullet integrates it (a float) and the
// ground; and the camera's constants: the frustum and its declared bounds.
void set_fixed_input(fragsim_step_input& in, fragsim_camera_def& camera, const btVector3& gravity) {
  in.gravity_mps2 = {gravity.x(), gravity.y(), gravity.z()};
  in.ground_height_m = 0;
  camera.fovy_deg = 60;
  camera.aspect = 16.0 / 9.0;
  camera.near_m = 0.1;
  camera.far_m = 500;
  camera.max_speed_mps = CameraBounds::max_speed_mps;
  camera.max_accel_mps2 = CameraBounds::max_accel_mps2;
  camera.max_turn_degps = CameraBounds::max_turn_degps;  // degrees, as every angle of the API
}

fragsim_fragment_arrays strided_arrays(std::vector<FragmentRecord>& fragments) {
  constexpr size_t stride = sizeof(FragmentRecord);
  FragmentRecord& f = fragments.front();
  fragsim_fragment_arrays arrays = fragsim_default_fragment_arrays();
  arrays.scalar_type = FRAGSIM_SCALAR_FLOAT;
  arrays.position_m = f.position_m, arrays.position_stride_bytes = stride;
  arrays.velocity_mps = f.velocity_mps, arrays.velocity_stride_bytes = stride;
  arrays.radius_m = &f.radius_m, arrays.radius_stride_bytes = stride;
  arrays.mass_kg = &f.mass_kg, arrays.mass_stride_bytes = stride;
  arrays.id = &f.id, arrays.id_stride_bytes = stride;
  arrays.touched = nullptr;  // edge-min never reads contacts
  arrays.force_N = f.force_N, arrays.force_stride_bytes = stride;
  return arrays;
}

}  // namespace

RunResult run_blast(const RunSettings& settings) {
  RunResult result;
  SeededDraws draws(settings.seed);
  const CameraPath camera_path = make_camera_path(settings.move, draws);
  FrameClock frame_clock(draws.next_seed());
  BulletWorld physics(make_blast(camera_path.at(0).eye_m, kGravity_mps2, draws),
                      settings.fragment_collisions);
  const int n = physics.fragment_count();
  result.fragments = n;

  Substeps s;
  s.physics = &physics;
  s.camera_path = &camera_path;
  s.result = &result;
  s.fragments.resize(n);
  s.centre_before_m.resize(n);
  s.hit.assign(n, 0);
  s.pushed.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    // Rounded up, not to nearest: a bounding radius must not shrink.
    const double radius_m = physics.bounding_radius_m(i);
    btScalar radius_float = static_cast<btScalar>(radius_m);
    if (radius_float < radius_m) radius_float = std::nextafter(radius_float, 1.0f);
    s.fragments[i].radius_m = radius_float;
    s.fragments[i].mass_kg = static_cast<btScalar>(physics.mass_kg(i));
    s.fragments[i].id = static_cast<uint64_t>(i);  // stable: Bullet's bodies never change order
  }
  s.arrays = strided_arrays(s.fragments);
  set_fixed_input(s.input, s.camera_def, physics.world().getGravity());
  s.near_rectangle =
      near_rectangle(s.camera_def.near_m, s.camera_def.fovy_deg, s.camera_def.aspect);

  if (settings.protect) {
    const fragsim_controller_def def = fragsim_default_controller_def();
    char message[256];
    if (fragsim_controller_create(&def, &s.controller, message, sizeof message) != FRAGSIM_OK) {
      result.error = message;
      return result;
    }
    // The camera's constants once, and room for the whole blast now, so its first substep (every
    // id new) grows nothing.
    if (fragsim_controller_set_cameras(s.controller, &s.camera_def, 1) != FRAGSIM_OK ||
        fragsim_controller_reserve(s.controller, n) != FRAGSIM_OK) {
      result.error = fragsim_controller_last_error(s.controller);
      fragsim_controller_destroy(s.controller);
      return result;
    }
  }

  physics.world().setInternalTickCallback(before_substep, &s, /*isPreTick=*/true);
  physics.world().setInternalTickCallback(after_substep, &s, /*isPreTick=*/false);
  const int substeps = static_cast<int>(std::lround(kDuration_s / kSubstep_s));
  double step_simulation_s = 0;
  while (s.count < substeps && result.error.empty()) {
    const double frame_s = frame_clock.next_frame_s();
    const Clock::time_point call = Clock::now();
    const int taken = physics.world().stepSimulation(static_cast<btScalar>(frame_s), kMaxSubsteps,
                                                     static_cast<btScalar>(kSubstep_s));
    step_simulation_s += seconds_since(call);
    ++result.frames;
    if (taken > kMaxSubsteps) result.error = "a frame needed more substeps than allowed";
  }
  fragsim_controller_destroy(s.controller);
  result.substeps = s.count;
  result.bullet_s = step_simulation_s - s.callbacks_s;
  for (int i = 0; i < n; ++i) {
    result.hit_fragments += s.hit[i];
    result.pushed_fragments += s.pushed[i];
  }
  return result;
}
