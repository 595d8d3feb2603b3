#include "strategies/collision_prediction.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fragsim {
namespace {

const ReachModel kUnitBall{Reach::kGrowing, 0.0, 1.0};  // a fixed ball of radius 1 m

TEST(CollisionPrediction, TangentPathTouchesTheBall) {
  // Along x at height 1: the distance to the origin is 1 exactly once, at tau = 5 s.
  const BallisticPath path{{-5.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, Eigen::Vector3d::Zero()};
  const auto p = predict_contact(path, Eigen::Vector3d::Zero(), kUnitBall, 10.0);
  ASSERT_TRUE(p.candidate);
  EXPECT_NEAR(p.t_contact_s, 5.0, 1e-9);
}

TEST(CollisionPrediction, PathThatMissesByAKnownDistance) {
  // Passes 2 m from the centre: never within 1 m.
  const BallisticPath path{{-5.0, 2.0, 0.0}, {1.0, 0.0, 0.0}, Eigen::Vector3d::Zero()};
  EXPECT_FALSE(predict_contact(path, Eigen::Vector3d::Zero(), kUnitBall, 10.0).candidate);
}

TEST(CollisionPrediction, StartsInsideTheBall) {
  const BallisticPath path{{0.5, 0.0, 0.0}, {3.0, 0.0, 0.0}, Eigen::Vector3d::Zero()};
  const auto p = predict_contact(path, Eigen::Vector3d::Zero(), kUnitBall, 10.0);
  ASSERT_TRUE(p.candidate);
  EXPECT_EQ(p.t_contact_s, 0.0);
}

TEST(CollisionPrediction, FallingOntoTheBall) {
  // Dropped from 10 m under g = 10: height 10 - 5 tau^2 reaches 1 at tau = sqrt(1.8).
  const BallisticPath path{{0.0, 10.0, 0.0}, Eigen::Vector3d::Zero(), {0.0, -10.0, 0.0}};
  const auto p = predict_contact(path, Eigen::Vector3d::Zero(), kUnitBall, 10.0);
  ASSERT_TRUE(p.candidate);
  EXPECT_NEAR(p.t_contact_s, std::sqrt(1.8), 1e-9);
  // Not if it lands (t_G) first.
  EXPECT_FALSE(predict_contact(path, Eigen::Vector3d::Zero(), kUnitBall, 1.3).candidate);
}

TEST(CollisionPrediction, ThesisBallGrowsWithTimeToLand) {
  // R = V_c t_G + radius = 1 * 4 + 1 = 5 m: the path, 2 m from the centre at its closest (tau =
  // 5 s, after t_G), comes within 5 m at tau = 5 - sqrt(21) = 0.417 s. With V_c = 0, R = 1 m.
  const BallisticPath path{{-5.0, 2.0, 0.0}, {1.0, 0.0, 0.0}, Eigen::Vector3d::Zero()};
  const auto p = predict_contact(path, Eigen::Vector3d::Zero(), {Reach::kThesis, 1.0, 1.0}, 4.0);
  ASSERT_TRUE(p.candidate);
  EXPECT_NEAR(p.t_contact_s, 5.0 - std::sqrt(21.0), 1e-12);
  EXPECT_FALSE(
      predict_contact(path, Eigen::Vector3d::Zero(), {Reach::kThesis, 0.0, 1.0}, 4.0).candidate);
}

TEST(CollisionPrediction, TimeToHorizon) {
  // Thrown up at 10 m/s from 0 under g = 10: back through 0 at 2 s.
  const BallisticPath up{{0.0, 0.0, 0.0}, {0.0, 10.0, 0.0}, {0.0, -10.0, 0.0}};
  EXPECT_NEAR(time_to_horizon(up, 0.0, 99.0), 2.0, 1e-12);
  // Through 3.2 m on the way down: 10 t - 5 t^2 = 3.2 at t = 1.6.
  EXPECT_NEAR(time_to_horizon(up, 3.2, 99.0), 1.6, 1e-12);
  // Never as high as 6 m: the fallback.
  EXPECT_EQ(time_to_horizon(up, 6.0, 99.0), 99.0);
  // No gravity: never comes down.
  const BallisticPath flat{{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, Eigen::Vector3d::Zero()};
  EXPECT_EQ(time_to_horizon(flat, 0.0, 7.0), 7.0);
}

TEST(CollisionPrediction, DiscretePredictorShiftsVelocityByHalfAStep) {
  FragmentState f;
  f.velocity_mps = {1.0, 2.0, 3.0};
  const Eigen::Vector3d g(0.0, -9.81, 0.0);
  const auto p = predicted_path(f, g, Predictor::kDiscrete, 0.1);
  EXPECT_NEAR(p.v0_mps.y(), 2.0 - 0.4905, 1e-15);
  EXPECT_EQ(predicted_path(f, g, Predictor::kThesis, 0.1).v0_mps, f.velocity_mps);
}

TEST(CollisionPrediction, NearPlaneCrossingAndNearestEdge) {
  CameraPose cam;  // eye at origin, looking down -z, near 0.1, fovy 60, aspect 16:9
  // Straight at the camera at (0.03, 0.02): crosses the near plane there.
  const BallisticPath path{{0.03, 0.02, -5.0}, {0.0, 0.0, 10.0}, Eigen::Vector3d::Zero()};
  const auto hit = near_plane_crossing(path, cam, Eigen::Vector3d::Zero(), 10.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->x(), 0.03, 1e-12);
  EXPECT_NEAR(hit->y(), 0.02, 1e-12);
  // Half height 0.0577, half width 0.1026: the top edge is 0.0377 away, the right one 0.0726.
  EXPECT_EQ(nearest_edge_direction(cam, *hit), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(nearest_edge_direction(cam, {0.09, 0.001}), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(nearest_edge_direction(cam, {-0.09, 0.001}), Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(nearest_edge_direction(cam, {0.0, -0.05}), Eigen::Vector3d(0, -1, 0));
  // Moving away: no crossing.
  const BallisticPath away{{0.0, 0.0, -5.0}, {0.0, 0.0, -1.0}, Eigen::Vector3d::Zero()};
  EXPECT_FALSE(near_plane_crossing(away, cam, Eigen::Vector3d::Zero(), 10.0).has_value());
}

}  // namespace
}  // namespace fragsim
