// The registry is one table: a strategy added as one entry (its own parameter struct and keys) is
// parsed from scene files and the command line, listed by --help, written to config.ini and
// validated, with nothing else changed. And the built-in entries' checks, one line naming the key.

#include "strategies/registry.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

// A strategy that lives only in this test: its parameters, their one key, the strategy itself.
struct ProbeParams {
  double gain_mps2 = 4.0;
};

const ParamSpec<ProbeParams>& probe_param_spec() {
  static const ParamSpec<ProbeParams> spec{
      {settings::real("gain_mps2", "m/s^2", "how hard the probe pushes", &ProbeParams::gain_mps2,
                      settings::closed(0, 10))},
      {}};
  return spec;
}

class ProbeStrategy : public SceneStrategy {
 public:
  explicit ProbeStrategy(const ProbeParams& p) : params_(p) {}
  std::string name() const override { return "probe"; }
  void reset(int) override {}
  void step(const StepContext&, SceneStepOutput&) override {}
  const ProbeParams& params() const { return params_; }

 private:
  ProbeParams params_;
};

// The tool's table plus the one line that adds the probe.
StrategyTable with_probe() {
  StrategyTable table = strategy_table();
  table.push_back(strategy_entry(
      "probe", "a test's strategy", probe_param_spec(),
      [](const ProbeParams& p, const FrustumDef&) { return std::make_unique<ProbeStrategy>(p); }));
  return table;
}

std::string parse_error(const std::string& text, const std::vector<SceneOverride>& overrides,
                        const StrategyTable& table) {
  try {
    parse_scene(text, "probe.ini", overrides, table);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Registry, OneEntryAddsAStrategyToParserHelpAndConfigIni) {
  const StrategyTable table = with_probe();

  // The parser: file and command line.
  const Scene s = parse_scene("[probe]\ngain_mps2 = 2.5\n", "probe.ini", {}, table);
  EXPECT_EQ(s.strategies.get<ProbeParams>().gain_mps2, 2.5);
  const Scene o = parse_scene("", "", {{"probe.gain_mps2", "7"}}, table);
  EXPECT_EQ(o.strategies.get<ProbeParams>().gain_mps2, 7.0);

  // --help: the key with its unit and default, and the strategy in the list.
  const auto options = scene_options(table);
  const auto* option = options.find_nothrow("probe.gain_mps2", false);
  ASSERT_NE(option, nullptr);
  EXPECT_EQ(option->description(), "m/s^2; how hard the probe pushes [4]");
  EXPECT_NE(describe_strategies(table).find("  probe "), std::string::npos);
  EXPECT_EQ(
      join_strategy_names(table, ",").substr(join_strategy_names(strategy_table(), ",").size()),
      ",probe");

  // config.ini: its section after the tool's strategies, and it reads back.
  const std::string ini = scene_to_ini(s, table);
  EXPECT_NE(ini.find("\n[edge-min]\n"), std::string::npos);
  EXPECT_LT(ini.find("\n[edge-min]\n"), ini.find("\n[probe]\ngain_mps2 = 2.5\n\n[metrics]\n"));
  EXPECT_EQ(scene_to_ini(parse_scene(ini, "config.ini", {}, table), table), ini);

  // Validation: the parser and the factory apply the key's one rule.
  EXPECT_EQ(parse_error("[probe]\ngain_mps2 = 11\n", {}, table),
            "probe.ini:2: probe.gain_mps2 = '11': must be in [0, 10]");
  EXPECT_EQ(parse_error("", {{"probe.gain_mps2", "nan"}}, table),
            "--probe.gain_mps2: probe.gain_mps2 = 'nan': must be finite");
  const auto made = make_strategy("probe", s.strategies, s.camera.frustum_def(), table);
  EXPECT_EQ(dynamic_cast<const ProbeStrategy&>(*made).params().gain_mps2, 2.5);
  Scene bad = s;
  bad.strategies.get<ProbeParams>().gain_mps2 = -1.0;
  try {
    make_strategy("probe", bad.strategies, bad.camera.frustum_def(), table);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "probe.gain_mps2 = -1: must be in [0, 10]");
  }
}

TEST(Registry, TheToolsTableDoesNotKnowTheTestStrategy) {
  EXPECT_EQ(parse_error("[probe]\ngain_mps2 = 2.5\n", {}, strategy_table()),
            "probe.ini:2: unknown key 'probe.gain_mps2'");
  EXPECT_EQ(scene_to_ini(Scene{}).find("[probe]"), std::string::npos);
  try {
    make_strategy("probe", Scene{});
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "unknown strategy 'probe' (known: none, wall, deflect-all, near-plane, edge, "
                 "edge-min, fade)");
  }
}

TEST(Registry, EveryEntrysKeysAreSceneKeysInItsSection) {
  const std::string ini = scene_to_ini(Scene{});
  ASSERT_EQ(strategy_names().size(), strategy_table().size());
  for (const StrategyEntry& e : strategy_table()) {
    if (e.keys.empty()) continue;
    EXPECT_NE(ini.find("\n[" + e.name + "]\n"), std::string::npos) << e.name;
    for (const auto& k : e.keys) {
      EXPECT_EQ(k.name.rfind(e.name + ".", 0), 0u) << k.name;
      EXPECT_NE(scene_options().find_nothrow(k.name, false), nullptr) << k.name;
    }
  }
}

// One line naming the key, whether the value came from a file or was set in code.
std::string make_error(const Scene& scene, const std::string& name) {
  try {
    make_strategy(name, scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string validate_error(const Scene& scene, const std::string& name) {
  try {
    validate_strategy_settings(name, scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Validation is the factory's checks without the making: the same one-line errors, no strategy.
TEST(Registry, ValidationChecksWithoutMakingTheStrategy) {
  static int made = 0;
  StrategyTable table = strategy_table();
  table.push_back(strategy_entry("probe", "a test's strategy", probe_param_spec(),
                                 [](const ProbeParams& p, const FrustumDef&) {
                                   ++made;
                                   return std::make_unique<ProbeStrategy>(p);
                                 }));
  Scene s;
  const FrustumDef frustum = s.camera.frustum_def();
  validate_strategy_settings("probe", s.strategies, frustum, table);
  EXPECT_EQ(made, 0);
  make_strategy("probe", s.strategies, frustum, table);
  EXPECT_EQ(made, 1);
  s.strategies.get<ProbeParams>().gain_mps2 = -1.0;
  EXPECT_THROW(validate_strategy_settings("probe", s.strategies, frustum, table), InputError);
  EXPECT_EQ(made, 1);

  Scene bad;
  bad.strategies.edge_min.max_solves = -1;
  bad.strategies.wall.thickness_m = 2.0;
  bad.strategies.near_plane.min_near_m = 0.5;
  for (const char* name : {"edge-min", "wall", "near-plane", "edge", "magic"}) {
    EXPECT_EQ(validate_error(bad, name), make_error(bad, name)) << name;
  }
  EXPECT_EQ(validate_error(bad, "magic"),
            "unknown strategy 'magic' (known: none, wall, deflect-all, near-plane, edge, "
            "edge-min, fade)");
  EXPECT_EQ(validate_error(bad, "edge"), "");
}

TEST(Registry, ParametersSetInCodeAreCheckedByTheirKeys) {
  const double inf = std::numeric_limits<double>::infinity();
  Scene s;
  s.strategies.edge_min.camera_accel_mps2 = inf;
  EXPECT_EQ(make_error(s, "edge-min"), "edge-min.camera_accel_mps2 = inf: must be finite");
  s = {};
  s.strategies.edge_min.max_solves = -1;
  EXPECT_EQ(make_error(s, "edge-min"),
            "edge-min.max_solves = -1: must be a whole number in [0, 100000000]");
  s = {};
  s.strategies.edge.predictor = static_cast<Predictor>(5);
  EXPECT_EQ(make_error(s, "edge"), "edge.predictor = ?: expected thesis | discrete");
  s = {};
  s.strategies.deflect_all.range_m = -2.0;
  EXPECT_EQ(make_error(s, "deflect-all"), "deflect-all.range_m = -2: must be in [0, 1e+06]");
  // Only the named strategy's parameters are its business.
  EXPECT_EQ(make_error(s, "edge"), "");
}

TEST(Registry, RulesAcrossKeysAreTheSameFromAFileAndFromCode) {
  Scene s;
  s.strategies.wall.thickness_m = 2.0;
  const std::string rule =
      "wall.thickness_m = 2: must be < 2 wall.distance_m, so the wall stays in front of the eye";
  EXPECT_EQ(make_error(s, "wall"), rule);
  EXPECT_EQ(parse_error("[wall]\nthickness_m = 2\n", {}, strategy_table()), rule);
  s = {};
  s.strategies.near_plane.min_near_m = 0.5;
  EXPECT_EQ(make_error(s, "near-plane"),
            "near-plane.min_near_m = 0.5: must be <= camera.near_m = 0.1");
}

TEST(Registry, UnknownNameAndBadParameterAreNamed) {
  Scene scene;
  try {
    make_strategy("magic", scene);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("magic"), std::string::npos);
  }
  scene.strategies.edge.k = -1.0;
  try {
    make_strategy("edge", scene);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("edge.k = -1"), std::string::npos);
  }
}

}  // namespace
}  // namespace fragsim
