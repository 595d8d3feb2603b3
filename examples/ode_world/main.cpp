// An engine integration in miniature: an ODE world of boxes thrown at a camera that walks toward
// them, stepped with fragsim_control once per step (see README.md for the lines that matter).
// Runs the same throw twice, without and with the controller, and prints how many boxes came
// within the camera's protected region (near plane or body) each time.
#include <fragsim/control.h>
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr int kBoxes = 27;
constexpr double kDt = 1.0 / 60.0;
constexpr double kBoxSize = 0.12;

struct Scene {
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contacts = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<fragsim_fragment> fragments;  // the controller's view, refreshed every step
  std::vector<fragsim_vec3> forces;
};

// ODE's collision callback gets the scene through its data pointer: no globals.
void near_callback(void* data, dGeomID a, dGeomID b) {
  Scene& s = *static_cast<Scene*>(data);
  dContact contact[4];
  const int n = dCollide(a, b, 4, &contact[0].geom, sizeof(dContact));
  for (int i = 0; i < n; ++i) {
    contact[i].surface.mode = dContactBounce;
    contact[i].surface.mu = 0.6;
    contact[i].surface.bounce = 0.2;
    dJointAttach(dJointCreateContact(s.world, s.contacts, &contact[i]), dGeomGetBody(a),
                 dGeomGetBody(b));
    for (dGeomID g : {a, b}) {  // mark the touched boxes (the body's data is its index)
      if (dBodyID body = dGeomGetBody(g)) {
        s.fragments[reinterpret_cast<std::size_t>(dBodyGetData(body))].touched = 1;
      }
    }
  }
}

// Boxes in a 3 x 3 x 3 block 8 m ahead, thrown back toward the camera with some spread.
void build(Scene& s) {
  s.world = dWorldCreate();
  dWorldSetGravity(s.world, 0, -9.81, 0);
  s.space = dHashSpaceCreate(nullptr);
  s.contacts = dJointGroupCreate(0);
  dCreatePlane(s.space, 0, 1, 0, 0);  // the ground, y = 0
  for (int i = 0; i < kBoxes; ++i) {
    const double gx = i % 3 - 1.0, gy = (i / 3) % 3 - 1.0, gz = i / 9 - 1.0;
    dBodyID b = dBodyCreate(s.world);
    dMass m;
    dMassSetBox(&m, 600.0, kBoxSize, kBoxSize, kBoxSize);
    dBodySetMass(b, &m);
    dBodySetPosition(b, 0.15 * gx, 1.6 + 0.15 * gy, -8.0 + 0.15 * gz);
    dBodySetLinearVel(b, 0.4 * gx, 2.6 + 0.4 * gy, 14.0);
    dBodySetData(b, reinterpret_cast<void*>(static_cast<std::size_t>(i)));
    dGeomSetBody(dCreateBox(s.space, kBoxSize, kBoxSize, kBoxSize), b);
    s.bodies.push_back(b);
  }
  s.fragments.assign(kBoxes, fragsim_default_fragment());
  s.forces.assign(kBoxes, fragsim_vec3{0, 0, 0});
}

void destroy(Scene& s) {
  dJointGroupDestroy(s.contacts);
  dSpaceDestroy(s.space);
  dWorldDestroy(s.world);
}

// Runs 1.5 s; returns how many boxes entered the camera's protected box (near plane, body).
int run(fragsim_controller_id ctl) {
  Scene s;
  build(s);
  // The camera's pose each step (its constants were set once on the controller, in main).
  fragsim_camera_pose camera = fragsim_default_camera_pose();  // looks down -z
  camera.eye_m = {0, 1.6, 0};
  camera.velocity_mps = {0, 0, -1.5};                    // walking toward the blast
  fragsim_step_input in = fragsim_default_step_input();  // no end
  in.dt_s = kDt;
  in.gravity_mps2 = {0, -9.81, 0};
  in.ground_height_m = 0.0;
  in.camera_poses = &camera;
  in.camera_count = 1;
  std::vector<char> hit(kBoxes, 0);
  for (int step = 0; step < 90; ++step) {
    in.time_s = step * kDt;
    // 1. The engine's bodies into the controller's fragments (touched was set by the last step).
    for (int i = 0; i < kBoxes; ++i) {
      const dReal* p = dBodyGetPosition(s.bodies[i]);
      const dReal* v = dBodyGetLinearVel(s.bodies[i]);
      fragsim_fragment& f = s.fragments[i];
      f.position_m = {p[0], p[1], p[2]};
      f.velocity_mps = {v[0], v[1], v[2]};
      f.radius_m = 0.5 * std::sqrt(3.0) * kBoxSize;  // the box's bounding sphere
      dMass m;
      dBodyGetMass(s.bodies[i], &m);
      f.mass_kg = m.mass;
      f.id = static_cast<uint64_t>(i);
    }
    // 2. One controller call, 3. its forces into the bodies, for this step only.
    if (!fragsim_controller_id_is_null(ctl)) {
      if (fragsim_controller_step(ctl, &in, s.fragments.data(), kBoxes, s.forces.data(), nullptr) !=
          FRAGSIM_OK) {
        std::fprintf(stderr, "fragsim: %s\n", fragsim_controller_last_error(ctl));
        destroy(s);
        return -1;
      }
      for (int i = 0; i < kBoxes; ++i) {
        dBodyAddForce(s.bodies[i], s.forces[i].x, s.forces[i].y, s.forces[i].z);
      }
    }
    // 4. The engine's own step.
    for (fragsim_fragment& f : s.fragments) f.touched = 0;
    dSpaceCollide(s.space, &s, near_callback);
    dWorldQuickStep(s.world, kDt);
    dJointGroupEmpty(s.contacts);
    camera.eye_m.z += camera.velocity_mps.z * kDt;
    // What the camera suffered: a box within 0.1 m of the protected box around the eye.
    for (int i = 0; i < kBoxes; ++i) {
      const dReal* p = dBodyGetPosition(s.bodies[i]);
      const double dx = std::abs(p[0] - camera.eye_m.x);
      const double dy = std::abs(p[1] - camera.eye_m.y);
      const double dz = p[2] - camera.eye_m.z;  // the camera looks down -z
      if (dx < 0.2 && dy < 0.15 && dz > -0.2 && dz < 0.15) hit[i] = 1;
    }
  }
  destroy(s);
  int hits = 0;
  for (char h : hit) hits += h;
  return hits;
}

}  // namespace

int main() {
  dInitODE2(0);
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id ctl{};
  char message[256];
  if (fragsim_controller_create(&def, &ctl, message, sizeof message) != FRAGSIM_OK) {
    std::fprintf(stderr, "fragsim: %s\n", message);
    return 1;
  }
  // The camera's constants, once: fragsim's default frustum and body, 3 m/s at most.
  const fragsim_camera_def camera = fragsim_default_camera_def();
  if (fragsim_controller_set_cameras(ctl, &camera, 1) != FRAGSIM_OK) {
    std::fprintf(stderr, "fragsim: %s\n", fragsim_controller_last_error(ctl));
    fragsim_controller_destroy(ctl);
    return 1;
  }
  const int without = run(fragsim_controller_id{});
  const int with = run(ctl);
  fragsim_controller_destroy(ctl);
  dCloseODE();
  std::printf("boxes reaching the camera: %d without the controller, %d with it\n", without, with);
  return (without > 0 && with == 0) ? 0 : 1;
}
