// The one mapping between the C def and the strategies' parameters (api/def_mapping.hpp): the
// controller reads defs with it, the defaults function and fragsim's control dump write them.

#include "control/api/def_mapping.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "control/strategies/deflect_all_strategy.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "control/strategies/edge_strategy.hpp"

namespace {

using fragsim::control::controller_def;
using fragsim::control::deflect_all_params;
using fragsim::control::edge_min_params;
using fragsim::control::edge_params;
using fragsim::control::strategy_named;

// A def from the defaults with every field the mapping carries set to something else, so a field
// dropped or crossed in either direction shows.
fragsim_controller_def changed_def(fragsim_strategy strategy) {
  fragsim_controller_def d = fragsim_default_controller_def();
  d.strategy = strategy;
  d.edge_min.margin_m = 0.07;
  d.edge_min.a_max_mps2 = 41.0;
  d.edge_min.camera_model = FRAGSIM_CAMERA_REACHABLE;
  d.edge_min.camera_accel_mps2 = 17.0;
  d.edge_min.camera_turn_degps = 120.0;
  d.edge_min.max_solves = 9;
  d.edge_min.edge_weights[0] = 0.5;
  d.edge_min.edge_weights[1] = 2.0;
  d.edge_min.edge_weights[2] = 0.0;
  d.edge_min.edge_weights[3] = 3.0;
  d.edge_min.cover_max = 0.4;
  d.edge_min.cover_region = 0.3;
  d.edge.k_Nms2 = 1.5;
  d.edge.a_max_mps2 = 33.0;
  d.edge.predictor = FRAGSIM_EDGE_PREDICTOR_DISCRETE;
  d.edge.reach = FRAGSIM_EDGE_REACH_GROWING;
  d.edge.horizon = FRAGSIM_EDGE_HORIZON_GROUND;
  d.edge.replan = FRAGSIM_EDGE_REPLAN_ALWAYS;
  d.deflect_all.accel_mps2 = 70.0;
  d.deflect_all.range_m = 4.0;
  d.horizon_cap_s = 2.5;
  return d;
}

TEST(DefMapping, DefaultsFunctionIsTheDefaultParameters) {
  const fragsim_controller_def d = fragsim_default_controller_def();
  const fragsim_controller_def m = controller_def(FRAGSIM_STRATEGY_EDGE_MIN, {}, {}, {});
  EXPECT_EQ(std::memcmp(&d, &m, sizeof d), 0);
}

TEST(DefMapping, ParametersReadFromADefGiveTheSameDefBack) {
  for (fragsim_strategy s :
       {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE, FRAGSIM_STRATEGY_DEFLECT_ALL}) {
    const fragsim_controller_def d = changed_def(s);
    const fragsim_controller_def back =
        controller_def(s, edge_min_params(d), edge_params(d), deflect_all_params(d));
    EXPECT_EQ(std::memcmp(&d, &back, sizeof d), 0) << "strategy " << s;
  }
}

TEST(DefMapping, FieldsReachTheParametersOfTheSameMeaning) {
  const fragsim_controller_def d = changed_def(FRAGSIM_STRATEGY_EDGE);
  const fragsim::EdgeMinParams em = edge_min_params(d);
  EXPECT_EQ(em.margin_m, 0.07);
  EXPECT_EQ(em.a_max_mps2, 41.0);
  EXPECT_EQ(em.camera_model, fragsim::CameraModel::kReachable);
  EXPECT_EQ(em.camera_accel_mps2, 17.0);
  EXPECT_EQ(em.camera_turn_degps, 120.0);
  EXPECT_EQ(em.max_solves, 9);
  EXPECT_EQ(em.edge_weights, (std::array<double, 4>{0.5, 2.0, 0.0, 3.0}));
  EXPECT_EQ(em.cover_max, 0.4);
  EXPECT_EQ(em.cover_region, 0.3);
  EXPECT_EQ(em.horizon_cap_s, 2.5);
  const fragsim::EdgeParams e = edge_params(d);
  EXPECT_EQ(e.k, 1.5);
  EXPECT_EQ(e.a_max_mps2, 33.0);
  EXPECT_EQ(e.predictor, fragsim::Predictor::kDiscrete);
  EXPECT_EQ(e.reach, fragsim::Reach::kGrowing);
  EXPECT_EQ(e.horizon, fragsim::Horizon::kGround);
  EXPECT_EQ(e.replan, fragsim::Replan::kAlways);
  EXPECT_EQ(e.horizon_cap_s, 2.5);
  const fragsim::DeflectAllParams da = deflect_all_params(d);
  EXPECT_EQ(da.accel_mps2, 70.0);
  EXPECT_EQ(da.range_m, 4.0);
}

TEST(DefMapping, TheDefsHorizonCapIsTheChosenStrategys) {
  fragsim::EdgeMinParams em;
  em.horizon_cap_s = 2.0;
  fragsim::EdgeParams e;
  e.horizon_cap_s = 5.0;
  EXPECT_EQ(controller_def(FRAGSIM_STRATEGY_EDGE_MIN, em, e, {}).horizon_cap_s, 2.0);
  EXPECT_EQ(controller_def(FRAGSIM_STRATEGY_EDGE, em, e, {}).horizon_cap_s, 5.0);
  EXPECT_EQ(controller_def(FRAGSIM_STRATEGY_DEFLECT_ALL, em, e, {}).horizon_cap_s, 2.0);
}

TEST(DefMapping, StrategiesAreNamedAsTheyNameThemselves) {
  EXPECT_EQ(strategy_named(fragsim::EdgeMinStrategy({}).name()), FRAGSIM_STRATEGY_EDGE_MIN);
  EXPECT_EQ(strategy_named(fragsim::EdgeStrategy({}).name()), FRAGSIM_STRATEGY_EDGE);
  EXPECT_EQ(strategy_named(fragsim::DeflectAllStrategy({}).name()), FRAGSIM_STRATEGY_DEFLECT_ALL);
  EXPECT_FALSE(strategy_named("wall").has_value());
  EXPECT_FALSE(strategy_named("Edge").has_value());
}

}  // namespace
