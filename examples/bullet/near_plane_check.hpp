// The example's own judge of whether debris cut the camera's near plane, written for this
// example alone: it shares no code with libfragsim_control or with fragsim's metrics, and knows
// nothing of the controller's protected box, margins or predictions. It sees only what a
// renderer would: the frustum's numbers, and each fragment's bounding sphere where the engine
// actually put it at the start and the end of every substep.
//
// What it checks: the sphere swept along the segment from the fragment's centre before a substep
// to its centre after it, both in the camera's frame (x right, y up, z along the view axis),
// against the near rectangle: the rectangle at z = near_m, half height near_m tan(fovy / 2), half
// width that times the aspect. A sphere that touches the rectangle at any point of the sweep is
// debris the near plane would cut open on screen.
#pragma once

#include "vec3.hpp"

struct NearRectangle {
  double distance_m = 0;     // along the view axis
  double half_width_m = 0;   // along the camera's right
  double half_height_m = 0;  // along the camera's up
};

NearRectangle near_rectangle(double near_m, double fovy_deg, double aspect);

// A point in the camera's frame (x right, y up, z along the view axis) from world coordinates.
Vec3 to_camera_frame(Vec3 point_m, Vec3 eye_m, Vec3 right, Vec3 up, Vec3 forward);

// True when the sphere of radius_m whose centre moves from `from` to `to` (camera frame) comes
// within radius_m of the near rectangle: the segment's distance to the rectangle is exact (the
// crossing of the rectangle's plane, then the ends against the rectangle and the segment against
// its four edges), not sampled, so a fast fragment cannot step over the rectangle.
bool swept_sphere_meets(const NearRectangle& rect, Vec3 from, Vec3 to, double radius_m);

// Known cases with the answer worked out by hand (through the middle, beside it, past an edge
// in front, stopping short); false if the check gets any wrong.
bool near_plane_check_agrees_with_known_cases();
