// The checks of what a caller hands the C API (api/input_checks.cpp), each at its boundary: a
// fragment's mass and numbers, a camera's pose and constants named with their prefix, a def's
// allocator pair, and the warnings a legal camera earns.

#include "control/api/input_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

using namespace fragsim::control;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(InputChecks, FailFormatsTheMessage) {
  const Failure f = fail(FRAGSIM_ERROR_INVALID_ARGUMENT, "%s = %g: %s", "x", 2.5, "too big");
  EXPECT_TRUE(static_cast<bool>(f));
  EXPECT_EQ(f.status, FRAGSIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(f.message), "x = 2.5: too big");
  EXPECT_FALSE(static_cast<bool>(Failure{}));
}

TEST(InputChecks, MassIsZeroOrInTheDeclaredRange) {
  EXPECT_TRUE(mass_usable(0.0));
  EXPECT_TRUE(mass_usable(FRAGSIM_MIN_MASS_KG));
  EXPECT_FALSE(mass_usable(std::nextafter(FRAGSIM_MIN_MASS_KG, 0.0)));
  EXPECT_TRUE(mass_usable(FRAGSIM_MAX_MASS_KG));
  EXPECT_FALSE(mass_usable(std::nextafter(FRAGSIM_MAX_MASS_KG, kInf)));
  EXPECT_TRUE(mass_usable(2.5));
  // A float 1e-12 is below the range: the float nearest it is 9.9999998e-13.
  EXPECT_FALSE(mass_usable(static_cast<double>(1e-12f)));
  for (double bad : {-1.0, -0.5e-12, kInf, -kInf, kNaN}) EXPECT_FALSE(mass_usable(bad)) << bad;
}

TEST(InputChecks, FragmentNeedsFiniteNumbersAndARadiusOfAtLeastZero) {
  const double p[3] = {1.0, 2.0, -3.0};
  const double v[3] = {0.0, -9.81, 4.0};
  EXPECT_TRUE(fragment_usable(p, v, 0.0, 1.0));
  EXPECT_TRUE(fragment_usable(p, v, 0.25, 0.0));
  EXPECT_FALSE(fragment_usable(p, v, -1e-300, 1.0));
  EXPECT_FALSE(fragment_usable(p, v, kInf, 1.0));
  EXPECT_FALSE(fragment_usable(p, v, 0.25, -1.0));
  for (int k = 0; k < 3; ++k) {
    double bad_p[3] = {p[0], p[1], p[2]};
    double bad_v[3] = {v[0], v[1], v[2]};
    bad_p[k] = kNaN;
    bad_v[k] = -kInf;
    EXPECT_FALSE(fragment_usable(bad_p, v, 0.25, 1.0)) << k;
    EXPECT_FALSE(fragment_usable(p, bad_v, 0.25, 1.0)) << k;
  }
}

TEST(InputChecks, PoseAxesMustBeUnitAndAtRightAnglesWithin1e6) {
  fragsim_camera_pose pose = fragsim_default_camera_pose();
  EXPECT_FALSE(static_cast<bool>(validate_camera_pose(pose, "camera")));
  pose.right = {1.0 + 5e-7, 0.0, 0.0};  // inside the tolerance
  EXPECT_FALSE(static_cast<bool>(validate_camera_pose(pose, "camera")));
  pose.right = {1.000002, 0.0, 0.0};
  Failure f = validate_camera_pose(pose, "camera");
  EXPECT_EQ(f.status, FRAGSIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(f.message), "camera.right has length 1.000002: must be 1 (within 1e-6)");
  pose = fragsim_default_camera_pose();
  pose.up = {1e-5, 1.0, 0.0};  // length 1 + 5e-11, but 1e-5 off a right angle with right
  f = validate_camera_pose(pose, "cameras[1]");
  EXPECT_EQ(std::string(f.message),
            "cameras[1].right . cameras[1].up = 1e-05: the camera axes must be at right angles "
            "(within 1e-6)");
  pose = fragsim_default_camera_pose();
  pose.velocity_mps.z = kNaN;
  f = validate_camera_pose(pose, "camera");
  EXPECT_EQ(std::string(f.message), "camera.velocity_mps.z = nan: must be finite");
}

TEST(InputChecks, CameraConstantsAreNamedWithTheirPrefix) {
  fragsim_camera_def c = fragsim_default_camera_def();
  EXPECT_FALSE(static_cast<bool>(validate_camera_def(c, "camera")));
  c.near_m = 0.0;
  EXPECT_EQ(std::string(validate_camera_def(c, "cameras[1]").message),
            "cameras[1].near_m = 0: must be finite and > 0");
  c = fragsim_default_camera_def();
  c.far_m = 0.05;  // nearer than near_m = 0.1
  EXPECT_EQ(std::string(validate_camera_def(c, "camera").message),
            "camera.far_m = 0.05: must be finite and > camera.near_m");
  c = fragsim_default_camera_def();
  c.max_turn_degps = FRAGSIM_UNDECLARED;
  c.max_accel_mps2 = kInf;
  EXPECT_FALSE(static_cast<bool>(validate_camera_def(c, "camera")));
  c.max_turn_degps = -0.5;
  EXPECT_EQ(std::string(validate_camera_def(c, "camera").message),
            "camera.max_turn_degps = -0.5: must be >= 0, INFINITY or FRAGSIM_UNDECLARED");
}

TEST(InputChecks, CameraWarningsFlagOverSpeedAndAFovyInRadians) {
  const fragsim_camera_def c = fragsim_default_camera_def();  // V_c = 3 m/s, fovy 60
  fragsim_camera_pose pose = fragsim_default_camera_pose();
  EXPECT_EQ(camera_warnings(c, pose), 0u);
  pose.velocity_mps = {3.0, 0.0, 0.0};  // exactly V_c
  EXPECT_EQ(camera_warnings(c, pose), 0u);
  pose.velocity_mps = {0.0, 1.8, -2.4};  // |v| = 3 to rounding
  EXPECT_EQ(camera_warnings(c, pose), 0u);
  pose.velocity_mps = {3.001, 0.0, 0.0};
  EXPECT_EQ(camera_warnings(c, pose), FRAGSIM_WARNING_CAMERA_OVER_SPEED);
  fragsim_camera_def radians = c;
  radians.fovy_deg = 1.05;  // 60 degrees in radians
  EXPECT_EQ(camera_warnings(radians, pose),
            FRAGSIM_WARNING_CAMERA_OVER_SPEED | FRAGSIM_WARNING_FOVY_IN_RADIANS);
  radians.fovy_deg = 5.0;  // the threshold itself is degrees
  EXPECT_EQ(camera_warnings(radians, fragsim_default_camera_pose()), 0u);
}

TEST(InputChecks, DefNeedsItsDefaultsAndBothHooksOfAPairOrNeither) {
  fragsim_controller_def def = fragsim_default_controller_def();
  EXPECT_FALSE(static_cast<bool>(validate_def(def)));
  def.alloc_fn = [](size_t, size_t, void*) -> void* { return nullptr; };
  Failure f = validate_def(def);
  EXPECT_EQ(f.status, FRAGSIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(f.message),
            "free_fn: NULL while alloc_fn is set: give both (the game's allocator) or neither "
            "(operator new and delete)");
  def = fragsim_default_controller_def();
  def.finish_task = [](void*, void*) {};
  EXPECT_EQ(std::string(validate_def(def).message),
            "enqueue_task: NULL while finish_task is set: give both (the game's task system) or "
            "neither (the calling thread)");
  def = fragsim_default_controller_def();
  def.worker_count = 0;
  EXPECT_EQ(std::string(validate_def(def).message).rfind("worker_count = 0: must be in [1, ", 0),
            0u);
  def = fragsim_default_controller_def();
  def.internal_value = 0;
  EXPECT_EQ(validate_def(def).status, FRAGSIM_ERROR_DEF_NOT_DEFAULTED);
}

}  // namespace
