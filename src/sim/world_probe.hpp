#pragma once
// For tests only, what World handed ODE and what ODE's collision detection makes of a pair at this
// moment, without stepping, so that tests need not include ODE.

#include <Eigen/Core>
#include <vector>

#include "sim/world.hpp"

namespace fragsim {

struct ProbeContact {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // from the other geom into the fragment
  double depth_m = 0.0;
};

enum class ProbeTarget { kGround, kCameraSensor, kWall, kFragment };

struct ProbeMass {
  double mass_kg = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  // in the body frame
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Zero();
};

struct WorldProbe {
  // The contacts World::step would generate at this moment between `fragment` and `target`
  // (fragment `other` for kFragment; for the sensor, whether they touch, at most one). Empty if the
  // world has no such geom.
  static std::vector<ProbeContact> contacts(const World& world, int fragment, ProbeTarget target,
                                            int other = -1);
  // The mass ODE's body holds (dBodyGetMass).
  static ProbeMass mass(const World& world, int fragment);
  // Whether ODE collides the fragment as a convex geom (rather than a box).
  static bool is_convex(const World& world, int fragment);
};

}  // namespace fragsim
