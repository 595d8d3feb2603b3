#include "control/strategies/collision_prediction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

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

// The push direction as `edge` had it: nearest_edge_direction at near_plane_crossing, or at the
// fragment's position when the path does not cross.
Eigen::Vector3d exact_direction(const BallisticPath& path, const CameraPose& cam,
                                const Eigen::Vector3d& cam_v, double horizon,
                                const Eigen::Vector3d& now) {
  const auto crossing = near_plane_crossing(path, cam, cam_v, horizon);
  return nearest_edge_direction(cam, crossing ? *crossing : cam.to_camera(now).head<2>());
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

TEST(CollisionPrediction, CrossingDirectionIsTheSolversOnEveryKindOfPath) {
  // Random cameras and paths, many built to sit on a decision: crossing the near plane on the
  // rectangle's diagonal or on an axis, at the horizon, grazing the plane (a double root), or
  // starting on it, each within +-1e-14..1e-1 of it. The closed form must hand all of those to
  // the solver or agree with it.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
  };
  int crossing = 0;
  for (int n = 0; n < 200000; ++n) {
    CameraPose cam;
    cam.eye_m = 5.0 * random_unit(rng);
    cam.forward = random_unit(rng);
    cam.right = cam.forward.cross(Eigen::Vector3d::UnitY()).normalized();
    cam.up = cam.right.cross(cam.forward);
    cam.near_m = log_uniform(-2, 0);
    cam.fovy_deg = 20.0 + 100.0 * u(rng);
    cam.aspect = 0.5 + 2.0 * u(rng);
    const double hw = cam.near_half_width_m();
    const double hh = cam.near_half_height_m();
    const Eigen::Vector3d cam_v = u(rng) < 0.5 ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                               : Eigen::Vector3d(3.0 * random_unit(rng));
    const Eigen::Vector3d g = u(rng) < 0.6 ? Eigen::Vector3d(0.0, -9.81, 0.0)
                                           : Eigen::Vector3d(20.0 * u(rng) * random_unit(rng));
    const double horizon = log_uniform(-2, 1);
    // Where (in camera coordinates) and when the path is to cross the near plane.
    const double tc = horizon * u(rng);
    const int family = n % 6;
    const double delta = (u(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-14, -1);
    double x = (2.0 * u(rng) - 1.0) * 1.5 * hw;
    double y = (2.0 * u(rng) - 1.0) * 1.5 * hh;
    if (family == 1) {  // on a diagonal: equally far from a side and from the top or bottom
      const double to_edge = (u(rng) - 0.2) * hh;
      x = (u(rng) < 0.5 ? -1.0 : 1.0) * (hw - to_edge + delta);
      y = (u(rng) < 0.5 ? -1.0 : 1.0) * (hh - to_edge);
    } else if (family == 2) {  // on an axis
      (u(rng) < 0.5 ? x : y) = delta;
    }
    const Eigen::Vector3d local(x, y, cam.near_m);
    Eigen::Vector3d at_cross = cam.eye_m + x * cam.right + y * cam.up + cam.near_m * cam.forward;
    Eigen::Vector3d rel_v = log_uniform(-1, 1.5) * random_unit(rng);
    double t_cross = tc;
    if (family == 3) t_cross = horizon + delta;  // at the horizon
    if (family == 4) {
      // Grazing: the depth's velocity relative to the camera is zero at the crossing.
      rel_v -= rel_v.dot(cam.forward) * cam.forward;
      at_cross += delta * cam.forward;
    }
    // The path relative to the camera reaches `at_cross` at t_cross: p(t) - eye(t) with the
    // camera moving at cam_v; in the world, p0 = at_cross - v t - g t^2 / 2 (+ the camera's move).
    const Eigen::Vector3d v_world = rel_v + cam_v;
    Eigen::Vector3d p0 = at_cross - rel_v * t_cross - 0.5 * g * t_cross * t_cross;
    if (family == 5) p0 = cam.eye_m + (cam.near_m + delta) * cam.forward + x * cam.right;
    const BallisticPath path{p0, v_world, g};
    const Eigen::Vector3d now = p0 + 0.01 * random_unit(rng);
    const Eigen::Vector3d fast = crossing_edge_direction(path, cam, cam_v, horizon, now, hw, hh);
    const Eigen::Vector3d slow = exact_direction(path, cam, cam_v, horizon, now);
    ASSERT_EQ(fast, slow) << "case " << n << " family " << family;
    crossing += near_plane_crossing(path, cam, cam_v, horizon) ? 1 : 0;
    (void)local;
  }
  EXPECT_GT(crossing, 50000);
}

// Fragments around a camera: some flying at it, some away, some falling past.
std::vector<FragmentState> random_fragments(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<FragmentState> out(n);
  for (FragmentState& f : out) {
    f.position_m = Eigen::Vector3d(0.0, 1.6, 0.0) + (1.0 + 9.0 * u(rng)) * random_unit(rng);
    const Eigen::Vector3d at_camera = (Eigen::Vector3d(0.0, 1.6, 0.0) - f.position_m).normalized();
    f.velocity_mps = u(rng) < 0.5 ? Eigen::Vector3d(10.0 * u(rng) * at_camera + random_unit(rng))
                                  : Eigen::Vector3d(8.0 * u(rng) * random_unit(rng));
    f.radius_m = 0.01 + 0.1 * u(rng);
  }
  return out;
}

TEST(CollisionPrediction, BatchedPredictionAnswersAsOneAtATime) {
  // ContactPredictor against ContactQuery::predict (the cheap rejection then the solve, fragment
  // by fragment): the same flag and the same doubles, for every predictor, reach and horizon
  // option, with and without gravity, screened or not.
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ContactPredictor predictor;  // reused across calls, as `edge` does
  int candidates = 0;
  for (int round = 0; round < 40; ++round) {
    ContactQuery q;
    q.camera_m = {0.0, 1.6, 0.0};
    q.gravity_mps2 = round % 5 == 4 ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                    : Eigen::Vector3d(0.0, -9.81, 0.0);
    q.predictor = round % 2 == 0 ? Predictor::kThesis : Predictor::kDiscrete;
    q.dt_s = 1.0 / 60.0;
    q.y_ref_m = round % 3 == 0 ? 0.0 : 1.6;
    q.remaining_s = 3.0 * u(rng);
    q.reach = round % 4 < 2 ? Reach::kThesis : Reach::kGrowing;
    q.max_speed_mps = 4.0 * u(rng);
    q.body_radius_m = 0.2345;
    const std::size_t n = 1 + static_cast<std::size_t>(u(rng) * 1500.0);
    const std::vector<FragmentState> fragments = random_fragments(rng, n);
    std::vector<int> which;
    std::vector<char> screen;
    for (std::size_t i = 0; i < n; ++i) {
      if (u(rng) < 0.2) continue;
      which.push_back(static_cast<int>(i));
      screen.push_back(u(rng) < 0.7 ? 1 : 0);
    }
    const auto batch =
        predictor.predict(q, fragments, which, round % 2 == 0 ? screen : std::vector<char>{});
    ASSERT_EQ(batch.size(), which.size());
    for (std::size_t k = 0; k < which.size(); ++k) {
      const ContactPrediction one = q.predict(fragments[static_cast<std::size_t>(which[k])]);
      ASSERT_EQ(batch[k].candidate, one.candidate) << "round " << round << " fragment " << k;
      ASSERT_EQ(batch[k].t_contact_s, one.t_contact_s) << "round " << round << " fragment " << k;
      ASSERT_EQ(batch[k].t_horizon_s, one.t_horizon_s) << "round " << round << " fragment " << k;
      candidates += one.candidate ? 1 : 0;
    }
  }
  EXPECT_GT(candidates, 1000);
}

}  // namespace
}  // namespace fragsim
