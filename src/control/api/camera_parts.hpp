#pragma once
// fragsim_camera is a camera whole: what moves (fragsim_camera_pose) and what it keeps
// (fragsim_camera_def, set once since 0.7). The controller works on whole cameras; these split
// and join them, field by field, so both forms of the API reach the same code.

#include "fragsim/control.h"

namespace fragsim::control {

inline fragsim_camera_pose pose_of(const fragsim_camera& c) {
  return {c.eye_m, c.right, c.up, c.forward, c.velocity_mps};
}

inline fragsim_camera_def def_of(const fragsim_camera& c) {
  return {c.fovy_deg,    c.aspect,        c.near_m,         c.far_m,
          c.body_half_m, c.max_speed_mps, c.max_accel_mps2, c.max_turn_radps};
}

inline fragsim_camera whole_camera(const fragsim_camera_def& d, const fragsim_camera_pose& p) {
  fragsim_camera c;
  c.eye_m = p.eye_m;
  c.right = p.right;
  c.up = p.up;
  c.forward = p.forward;
  c.velocity_mps = p.velocity_mps;
  c.fovy_deg = d.fovy_deg;
  c.aspect = d.aspect;
  c.near_m = d.near_m;
  c.far_m = d.far_m;
  c.body_half_m = d.body_half_m;
  c.max_speed_mps = d.max_speed_mps;
  c.max_accel_mps2 = d.max_accel_mps2;
  c.max_turn_radps = d.max_turn_radps;
  return c;
}

}  // namespace fragsim::control
