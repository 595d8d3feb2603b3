// Numerical stress (docs/method.md section 7): every strategy on seeded scenes at
// the extremes must keep every number finite, ODE quiet, forces within their caps and no fragment
// above its energy budget (health_observer.hpp); and the default scene run for a minute must come
// to rest on the ground and stay there.
//
// Run time is set by FRAGSIM_STRESS_SCALE (default 1; 0.25 in an AddressSanitizer build): it
// scales the fragment-steps each scene may take (stress_scenes.hpp) and the long run's length.
// A failing case prints its id, seed and scene as INI: save it and run
// `fragsim compare --scene case.ini` to reproduce it.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "experiments/evaluation.hpp"
#include "health_observer.hpp"
#include "io/number_format.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "stress_scenes.hpp"

namespace fragsim::stress {
namespace {

constexpr int kRandomCases = 40;

const Budget& budget() {
  static const Budget b = budget_from_environment();
  return b;
}

// The worst value each property reached over the cases this process ran, with where.
class WorstCases {
 public:
  void offer(const std::string& property, double value, const std::string& where) {
    auto it = std::find_if(entries_.begin(), entries_.end(),
                           [&](const Entry& e) { return e.property == property; });
    if (it == entries_.end()) {
      entries_.push_back({property, value, where});
    } else if (value > it->value || (std::isnan(value) && !std::isnan(it->value))) {
      it->value = value;
      it->where = where;
    }
  }
  void print(std::ostream& out) const {
    if (entries_.empty()) return;
    out << "\nstress: worst case per property (scale " << budget().scale << ")\n";
    for (const Entry& e : entries_) {
      out << "  " << e.property << ": " << e.value << "  [" << e.where << "]\n";
    }
  }

 private:
  struct Entry {
    std::string property;
    double value;
    std::string where;
  };
  std::vector<Entry> entries_;
};

WorstCases& worst() {
  static WorstCases w;
  return w;
}

class PrintWorst final : public ::testing::Environment {
 public:
  void TearDown() override { worst().print(std::cout); }
};
const auto* const kPrintWorst = ::testing::AddGlobalTestEnvironment(new PrintWorst);

// Every floating-point number of a run summary, by name.
std::vector<std::pair<const char*, double>> summary_numbers(const RunSummary& s) {
  return {{"dt_s", s.dt_s},
          {"deviation_mean_m", s.deviation.mean_m},
          {"deviation_max_m", s.deviation.max_m},
          {"deviated_share", s.deviation.deviated_share},
          {"occlusion_mean", s.occlusion.mean},
          {"occlusion_max", s.occlusion.max},
          {"central_occlusion_mean", s.occlusion.central_mean},
          {"central_occlusion_max", s.occlusion.central_max},
          {"single_fragment_occlusion_max", s.occlusion.single_fragment_max},
          {"impulse_Ns", s.activity.impulse_Ns},
          {"max_accel_mps2", s.activity.max_accel_mps2},
          {"min_near_m", s.activity.min_near_m},
          {"depth_step_m", s.activity.depth_step_m},
          {"physics_ms_median", s.cost.physics_ms_median},
          {"physics_ms_p95", s.cost.physics_ms_p95},
          {"strategy_ms_median", s.cost.strategy_ms_median},
          {"strategy_ms_p95", s.cost.strategy_ms_p95},
          {"wall_s", s.cost.wall_s}};
}

std::string case_name(const ::testing::TestParamInfo<StressCase>& info) {
  std::string name = info.param.id;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

class StressMatrix : public ::testing::TestWithParam<StressCase> {};

TEST_P(StressMatrix, EveryStrategyStaysFiniteQuietAndWithinItsEnergy) {
  const StressCase& c = GetParam();
  const std::string ini = scene_to_ini(c.scene);
  // The printed INI must be the case: reading it back gives the same scene.
  ASSERT_EQ(scene_to_ini(parse_scene(ini, c.id)), ini);

  HealthObserver health;
  const std::vector<Evaluation> runs = compare(c.scene, strategy_names(), true, &health);
  ASSERT_EQ(runs.size(), strategy_names().size());
  ASSERT_EQ(health.runs().size(), strategy_names().size());

  std::map<std::string, const RunHealth*> by_name;
  for (const RunHealth& h : health.runs()) by_name[h.strategy] = &h;
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    ASSERT_TRUE(by_name.count(s.strategy)) << s.strategy;
    const RunHealth& h = *by_name[s.strategy];
    const std::string where = c.id + " " + s.strategy;
    SCOPED_TRACE(where);

    EXPECT_EQ(s.health.nonfinite_fragments, 0) << "fragments frozen after a non-finite state";
    EXPECT_EQ(h.nonfinite_states, 0);
    EXPECT_EQ(h.nonfinite_forces, 0);
    EXPECT_EQ(h.nonfinite_near, 0);
    EXPECT_EQ(s.health.ode_messages, 0) << "ODE printed warnings";
    for (const auto& [name, value] : summary_numbers(s)) {
      EXPECT_TRUE(std::isfinite(value)) << "summary " << name << " = " << value;
      worst().offer(std::string("largest |summary ") + name + "|", std::abs(value), where);
    }
    EXPECT_EQ(h.unexpected_forces, 0) << "a strategy that applies no force did";
    EXPECT_EQ(h.forces_over_cap, 0) << "largest |F| / (m a_cap) = " << h.max_force_over_cap;
    if (h.energy_per_fragment) {
      EXPECT_EQ(h.energy_violations, 0)
          << "fragment " << h.energy_fragment << " at step " << h.energy_step
          << " has K = " << h.energy_K_J << " J, its budget allows " << h.energy_allowed_J
          << " J (ratio " << h.max_energy_ratio << ")";
    } else {
      EXPECT_EQ(h.energy_violations, 0)
          << "the fragments' total kinetic energy at step " << h.total_energy_step
          << " exceeds their total budget (ratio " << h.max_total_energy_ratio << ")";
    }

    worst().offer("ODE messages in a run", static_cast<double>(s.health.ode_messages), where);
    worst().offer("non-finite fragments in a run", s.health.nonfinite_fragments, where);
    worst().offer("largest |position component| (m)", h.max_abs_position_m, where);
    worst().offer("largest speed (m/s)", h.max_speed_mps, where);
    worst().offer("largest applied force (N)", h.max_force_N, where);
    worst().offer("largest applied acceleration (m/s^2)", h.max_accel_mps2, where);
    worst().offer("largest |F| / (m a_cap)", h.max_force_over_cap, where);
    const std::string fragment_where = where + " fragment " + std::to_string(h.energy_fragment) +
                                       " step " + std::to_string(h.energy_step);
    if (h.energy_per_fragment) {
      worst().offer("largest energy/budget, per fragment (collisions off)", h.max_energy_ratio,
                    fragment_where);
    } else {
      worst().offer("largest energy/budget, all fragments (collisions on)",
                    h.max_total_energy_ratio,
                    where + " step " + std::to_string(h.total_energy_step));
      worst().offer("largest energy/budget, one fragment (collisions on, not checked)",
                    h.max_energy_ratio, fragment_where);
    }
    worst().offer("largest energy/(explosion + work), no contact allowance (not checked)",
                  h.max_no_contact_ratio, where);
    worst().offer("longest run (s)", s.cost.wall_s, where);
  }
  if (HasFailure()) {
    std::cout << "stress case " << c.id << " failed (seed " << c.seed << ", scale "
              << budget().scale << "): " << c.description << "\n--- scene INI ---\n"
              << ini << "--- end of scene INI ---\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, StressMatrix,
                         ::testing::ValuesIn(all_cases(budget(), kRandomCases)), case_name);

// The long run: the default scene for a minute. Every fragment comes down, and from the time the
// debris has settled it must stay at rest on the ground and never sink through it.
constexpr double kSettledS = 20.0;          // last fragment still moving: none 6.3 s, edge 12.6 s
constexpr double kRestSpeedMps = 1e-4;      // observed: 3.4e-10 m/s (none and edge)
constexpr double kRestDriftM = 1e-3;        // largest move from 20 s to the end; observed 1.4e-8 m
constexpr double kSurfaceLayerM = 0.001;    // dWorldSetContactSurfaceLayer in world.cpp
constexpr double kPenetrationTolM = 0.001;  // beyond the layer; observed: 0 (depth = 0.001 m)

// Lowest corner of a fragment's box.
double lowest_y(const FragmentState& f) {
  const Eigen::Matrix3d& r = f.rotation;
  const Eigen::Vector3d& h = f.half_extents_m;
  return f.position_m.y() -
         (std::abs(r(1, 0)) * h.x() + std::abs(r(1, 1)) * h.y() + std::abs(r(1, 2)) * h.z());
}

class SettleObserver final : public RunObserver {
 public:
  explicit SettleObserver(double settled_s) : settled_s_(settled_s) {}

  void begin(const RunInfo& info, const StepSnapshot& initial) override {
    scene_ = info.scene;
    dt_s_ = info.dt_s;
    last_speed_.clear();
    depth_.clear();
    for (const FragmentState& f : initial.fragments) {
      last_speed_.push_back(f.velocity_mps.norm());
      depth_.push_back(scene_->ground.height_m - lowest_y(f));
    }
    accel_.assign(last_speed_.size(), 0.0);
  }

  void observe(const StepSnapshot& snap) override {
    const double ground_m = scene_->ground.height_m;
    const double g = scene_->sim.gravity_mps2.norm();
    for (const AppliedForce& af : snap.forces) {
      const auto i = static_cast<std::size_t>(af.fragment);
      accel_[i] = af.force_N.norm() / snap.fragments[i].mass_kg;
    }
    const bool settled = snap.t_s >= settled_s_ - 1e-9;
    if (settled && settled_at_.empty()) {
      for (const FragmentState& f : snap.fragments) settled_at_.push_back(f.position_m);
    }
    for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
      const FragmentState& f = snap.fragments[i];
      const double depth = ground_m - lowest_y(f);
      // Landing: in one step a fragment sinks at most as far as it travels (last speed, plus a
      // step of gravity and force) plus what turning about its lowest corner can lower that
      // corner (at most its bounding radius less its smallest half extent), past the layer.
      const double travel = (last_speed_[i] + (g + accel_[i]) * dt_s_) * dt_s_;
      const double turn = f.radius_m - f.half_extents_m.minCoeff();
      const double allowed = std::max(depth_[i], kSurfaceLayerM) + travel + turn;
      if (depth > allowed) ++sank_beyond_travel;
      max_landing_depth_m = std::max(max_landing_depth_m, depth);
      last_speed_[i] = f.velocity_mps.norm();
      depth_[i] = depth;
      if (!settled) continue;
      ++settled_fragment_steps;
      if (!f.touched || depth < -0.01) {
        ++off_ground;
        continue;
      }
      if (f.velocity_mps.norm() > max_rest_speed_mps) {
        max_rest_speed_mps = f.velocity_mps.norm();
        rest_speed_where = "fragment " + std::to_string(i) + " t " + std::to_string(snap.t_s);
      }
      max_settled_depth_m = std::max(max_settled_depth_m, depth);
      max_drift_m = std::max(max_drift_m, (f.position_m - settled_at_[i]).norm());
    }
    for (const AppliedForce& af : snap.forces) accel_[static_cast<std::size_t>(af.fragment)] = 0.0;
  }

  long sank_beyond_travel = 0;      // fragment-steps sinking deeper than their motion explains
  long settled_fragment_steps = 0;  // fragment-steps at or after the settling time
  long off_ground = 0;              // of those, fragments not resting on the ground
  double max_landing_depth_m = 0.0;
  double max_rest_speed_mps = 0.0;
  std::string rest_speed_where;
  double max_settled_depth_m = 0.0;
  double max_drift_m = 0.0;

 private:
  double settled_s_;
  const Scene* scene_ = nullptr;
  double dt_s_ = 0.0;
  std::vector<double> last_speed_;
  std::vector<double> accel_;
  std::vector<double> depth_;  // ground height minus lowest corner, at the last snapshot
  std::vector<Eigen::Vector3d> settled_at_;
};

class LongRun : public ::testing::TestWithParam<std::string> {};

TEST_P(LongRun, DefaultSceneComesToRestOnTheGroundAndStays) {
  Scene scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  // A minute at scale 1; 30 s at the sanitizer scale (still 10 s after settling).
  scene.sim.duration_s = kSettledS + 40.0 * std::min(budget().scale, 1.0);
  const std::string strategy = GetParam();
  auto s = make_strategy(strategy, scene);
  SettleObserver settle(kSettledS);
  HealthObserver health;
  const std::array<RunObserver*, 2> observers{&settle, &health};
  const RunTotals totals = simulate(scene, *s, observers);
  const std::string where =
      "long run front.ini " + format_double(scene.sim.duration_s) + " s " + strategy;
  SCOPED_TRACE(where);

  EXPECT_EQ(totals.nonfinite_fragments, 0);
  EXPECT_EQ(totals.ode_messages, 0);
  ASSERT_EQ(health.runs().size(), 1u);
  EXPECT_EQ(health.runs()[0].energy_violations, 0)
      << "energy/budget " << health.runs()[0].max_energy_ratio;
  EXPECT_GT(settle.settled_fragment_steps, 0);
  EXPECT_EQ(settle.off_ground, 0) << "fragment-steps after " << kSettledS
                                  << " s not resting on the ground";
  EXPECT_LT(settle.max_rest_speed_mps, kRestSpeedMps) << settle.rest_speed_where;
  EXPECT_LE(settle.max_settled_depth_m, kSurfaceLayerM + kPenetrationTolM);
  EXPECT_LT(settle.max_drift_m, kRestDriftM);
  EXPECT_EQ(settle.sank_beyond_travel, 0);

  worst().offer("long run: largest resting speed (m/s)", settle.max_rest_speed_mps, where);
  worst().offer("long run: deepest settled penetration (m)", settle.max_settled_depth_m, where);
  worst().offer("long run: deepest landing penetration (m, not checked)",
                settle.max_landing_depth_m, where);
  worst().offer("long run: largest drift after settling (m)", settle.max_drift_m, where);
  worst().offer("long run: energy/budget", health.runs()[0].max_energy_ratio, where);
  worst().offer("long run (s)", totals.wall_s, where);
}

INSTANTIATE_TEST_SUITE_P(FrontScene, LongRun, ::testing::Values("none", "edge"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// The largest physics step of a run, in seconds, and the most wall contact points in one step.
class SlowestStep final : public RunObserver {
 public:
  void begin(const RunInfo&, const StepSnapshot&) override {}
  void observe(const StepSnapshot& snap) override {
    slowest_s = std::max(slowest_s, snap.physics_s);
    wall_contacts = std::max(wall_contacts, snap.wall_contacts);
  }
  double slowest_s = 0.0;
  int wall_contacts = 0;
};

// Regression: the `wall` strategy's kinematic box joins every fragment touching it in a step into
// one ODE island, and the exact solver is cubic in an island's size: 2,744 fragments aimed at the
// camera put ~340 on the wall in one step, which took ~3.6 s (~600 on it: 32 s; a 12,167-fragment
// scene: 197 s for one step). World now steps with QuickStep whenever a wall exists
// (simulation.solver = auto). No timing is asserted: the case must run to its end (ctest's
// timeout catches a relapse) with the wall really loaded.
TEST(WallIsland, ManyFragmentsOnTheWallRunToTheEnd) {
  const StressCase c = wall_island_case(14);
  auto wall = make_strategy("wall", c.scene);
  SlowestStep slowest;
  const std::array<RunObserver*, 1> observers{&slowest};
  const RunTotals totals = simulate(c.scene, *wall, observers);
  EXPECT_EQ(totals.steps, c.scene.step_count());
  EXPECT_GT(slowest.wall_contacts, 300) << "the case no longer loads the wall\n--- scene INI ---\n"
                                        << scene_to_ini(c.scene);
  std::printf("[   info   ] wall island: slowest step %.3f s, up to %d wall contact points\n",
              slowest.slowest_s, slowest.wall_contacts);
}

}  // namespace
}  // namespace fragsim::stress
