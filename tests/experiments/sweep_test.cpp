// fragsim sweep: --vary specifications, the job order, the single-key summary on hand-made rows.
// The command end to end is in tests/cli/sweep_command_test.cpp.

#include "experiments/sweep.hpp"

#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/csv_export.hpp"

namespace fragsim {
namespace {

using Values = std::vector<std::string>;

TEST(Sweep, CommaListKeepsTheTextOfEachValue) {
  EXPECT_EQ(parse_sweep_values("1,2,5"), (Values{"1", "2", "5"}));
  EXPECT_EQ(parse_sweep_values(" thesis , discrete "), (Values{"thesis", "discrete"}));
  // Vectors are values with spaces; commas separate the values.
  EXPECT_EQ(parse_sweep_values("0 1.6 -5,0 1.6 -7"), (Values{"0 1.6 -5", "0 1.6 -7"}));
  EXPECT_EQ(parse_sweep_values("0.25"), (Values{"0.25"}));
}

TEST(Sweep, IntegerRangeIncludesBothEnds) {
  const Values v = parse_sweep_values("1:20:1");
  ASSERT_EQ(v.size(), 20u);
  EXPECT_EQ(v.front(), "1");
  EXPECT_EQ(v[2], "3");
  EXPECT_EQ(v.back(), "20");
  EXPECT_EQ(parse_sweep_values("2:8:2"), (Values{"2", "4", "6", "8"}));
  EXPECT_EQ(parse_sweep_values("3:3:1"), (Values{"3"}));
}

TEST(Sweep, FloatRangeNeitherLosesTheEndNorShowsRounding) {
  // (0.5 - 0.1) / 0.1 is 3.9999999999999996 and 0.1 + 2 * 0.1 is 0.30000000000000004.
  EXPECT_EQ(parse_sweep_values("0.1:0.5:0.1"), (Values{"0.1", "0.2", "0.3", "0.4", "0.5"}));
  EXPECT_EQ(parse_sweep_values("-0.3:0.3:0.1"),
            (Values{"-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"}));
  EXPECT_EQ(parse_sweep_values("0:1:0.3"), (Values{"0", "0.3", "0.6", "0.9"}));  // hi not on grid
  EXPECT_EQ(parse_sweep_values("0:0.7:0.07").size(), 11u);
  EXPECT_EQ(parse_sweep_values("1e-3:3e-3:1e-3").size(), 3u);
  EXPECT_EQ(parse_sweep_values("1:100000:1").size(), kMaxRangeValues);
}

TEST(Sweep, BadSpecsAreRejected) {
  for (const char* bad :
       {"",        " ",       "1,,2",       "1,",         ",1",         "1,1",
        "1:2",     "1:2:3:4", "1:2:0",      "1:2:-1",     "2:1:1",      "a:2:1",
        "1:b:1",   "1:2:c",   "0:100000:1", "0:1e9:1e-3", "0:1:1e-300", "0 1.6 -5:0 1.6 -7:1",
        "1:inf:1", "a\"b",    "1\n2"}) {
    EXPECT_THROW(parse_sweep_values(bad), SweepError) << "'" << bad << "'";
  }
}

TEST(Sweep, VaryIsKeyEqualsSpec) {
  const SweepAxis a = parse_vary("object.distance_m=1:3:1");
  EXPECT_EQ(a.key, "object.distance_m");
  EXPECT_EQ(a.values, (Values{"1", "2", "3"}));
  EXPECT_EQ(parse_vary("camera.look_at_m=0 1.6 -7").values, (Values{"0 1.6 -7"}));
  EXPECT_THROW(parse_vary("object.distance_m"), SweepError);
  EXPECT_THROW(parse_vary("=1,2"), SweepError);
  EXPECT_THROW(parse_vary("edge.k="), SweepError);
}

TEST(Sweep, Seeds) {
  EXPECT_EQ(seeds_up_to(3), (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_THROW(seeds_up_to(0), SweepError);
  EXPECT_THROW(seeds_up_to(-2), SweepError);
  EXPECT_EQ(parse_seed_list("5, 7,18446744073709551615"),
            (std::vector<std::uint64_t>{5, 7, 18446744073709551615ull}));
  for (const char* bad : {"", "1,", "x", "-1", "1.5", "1,1", "18446744073709551616"}) {
    EXPECT_THROW(parse_seed_list(bad), SweepError) << "'" << bad << "'";
  }
}

TEST(Sweep, CartesianOrderFirstAxisSlowestSeedFastest) {
  const std::vector<SweepAxis> axes{{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}};
  const std::vector<SweepJob> jobs = sweep_jobs(axes, {7, 9});
  ASSERT_EQ(jobs.size(), 12u);
  std::size_t i = 0;
  for (std::size_t a = 0; a < 2; ++a) {
    for (std::size_t b = 0; b < 3; ++b) {
      for (std::uint64_t seed : {7u, 9u}) {
        EXPECT_EQ(jobs[i].value_index, (std::vector<std::size_t>{a, b})) << "job " << i;
        EXPECT_EQ(jobs[i].seed, seed) << "job " << i;
        ++i;
      }
    }
  }
  const auto combos = sweep_combinations(axes);
  ASSERT_EQ(combos.size(), 6u);
  EXPECT_EQ(combos[1], (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(combos[3], (std::vector<std::size_t>{1, 0}));
}

TEST(Sweep, TooManyJobsAreRefusedBeforeAllocating) {
  const Values thousand = parse_sweep_values("1:1000:1");
  EXPECT_EQ(sweep_jobs({{"a", thousand}, {"b", {"1", "2"}}}, {1, 2}).size(), 4000u);
  EXPECT_THROW(sweep_jobs({{"a", thousand}, {"b", thousand}}, {1, 2}), SweepError);
  EXPECT_THROW(sweep_combinations({{"a", thousand}, {"b", thousand}, {"c", {"1", "2"}}}),
               SweepError);
  EXPECT_THROW(sweep_jobs({{"a", {"1"}}}, {}), SweepError);
}

SweepOutcome row(const std::string& strategy, const std::string& value, std::uint64_t seed,
                 int intersections, double deviation) {
  return {value, seed, strategy, intersections, deviation};
}

TEST(Sweep, ThresholdIsTheStartOfTheAllZeroTail) {
  std::vector<SweepOutcome> rows;
  // Values out of order and "10" after "8": the order must be numeric, not as given or textual.
  const std::vector<std::pair<std::string, std::array<int, 2>>> edge{
      {"8", {0, 0}}, {"2", {0, 3}}, {"4", {0, 0}}, {"6", {1, 0}}, {"10", {0, 0}}};
  for (const auto& [value, hits] : edge) {
    const double v = std::stod(value);
    rows.push_back(row("edge", value, 1, hits[0], v));
    rows.push_back(row("edge", value, 2, hits[1], v + 1.0));
    rows.push_back(row("none", value, 1, 2, 0.0));  // never clear
    rows.push_back(row("none", value, 2, 0, 0.0));
    rows.push_back(row("wall", value, 1, 0, 0.5));  // always clear
    rows.push_back(row("wall", value, 2, 0, 0.5));
  }
  const std::vector<SweepStrategyStats> stats = summarise_single_key(rows);
  ASSERT_EQ(stats.size(), 3u);
  EXPECT_EQ(stats[0].strategy, "edge");
  EXPECT_EQ(stats[1].strategy, "none");
  EXPECT_EQ(stats[2].strategy, "wall");

  const SweepStrategyStats& e = stats[0];
  ASSERT_EQ(e.values.size(), 5u);
  const Values order{"2", "4", "6", "8", "10"};
  for (std::size_t i = 0; i < order.size(); ++i) {
    EXPECT_EQ(e.values[i].value, order[i]);
    EXPECT_EQ(e.values[i].seeds, 2);
  }
  EXPECT_EQ(e.values[0].zero_seeds, 1);
  EXPECT_EQ(e.values[1].zero_seeds, 2);  // clear at 4, but 6 is not: 4 is not the threshold
  EXPECT_EQ(e.values[2].zero_seeds, 1);
  EXPECT_NEAR(e.values[2].deviation_mean_m, 6.5, 1e-12);
  ASSERT_TRUE(e.threshold.has_value());
  EXPECT_EQ(e.values[*e.threshold].value, "8");
  EXPECT_NEAR(e.values[*e.threshold].deviation_mean_m, 8.5, 1e-12);

  EXPECT_FALSE(stats[1].threshold.has_value());
  EXPECT_EQ(stats[1].values[0].zero_seeds, 1);
  ASSERT_TRUE(stats[2].threshold.has_value());
  EXPECT_EQ(*stats[2].threshold, 0u);
  EXPECT_NEAR(stats[2].values[0].deviation_mean_m, 0.5, 1e-12);
}

TEST(Sweep, LastValueFailingMeansNoThreshold) {
  const std::vector<SweepOutcome> rows{row("edge", "1", 1, 0, 0.0), row("edge", "2", 1, 1, 0.0)};
  const auto stats = summarise_single_key(rows);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_FALSE(stats[0].threshold.has_value());
}

TEST(Sweep, NonNumericValuesKeepTheirOrder) {
  const std::vector<SweepOutcome> rows{row("edge", "thesis", 1, 1, 2.0),
                                       row("edge", "discrete", 1, 0, 1.0)};
  EXPECT_FALSE(sweep_values_numeric(rows));
  const auto stats = summarise_single_key(rows);
  ASSERT_EQ(stats[0].values.size(), 2u);
  EXPECT_EQ(stats[0].values[0].value, "thesis");
  ASSERT_TRUE(stats[0].threshold.has_value());
  EXPECT_EQ(stats[0].values[*stats[0].threshold].value, "discrete");
}

TEST(Sweep, ReadsOutcomesFromTheCsvByColumnName) {
  const std::string csv =
      "edge.k,seed,scene,strategy,near_fragments,camera_hit_fragments,deviation_mean_m\n"
      "0.5,3,s,edge,1,2,0.25\n"
      "1,3,s,none,0,0,0\n";
  const auto rows = read_sweep_outcomes(csv, "edge.k");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].value, "0.5");
  EXPECT_EQ(rows[0].seed, 3u);
  EXPECT_EQ(rows[0].strategy, "edge");
  EXPECT_EQ(rows[0].intersections, 3);
  EXPECT_EQ(rows[0].deviation_mean_m, 0.25);  // shortest round-trip text: exact
  EXPECT_EQ(rows[1].intersections, 0);
  EXPECT_THROW(read_sweep_outcomes(csv, "edge.a_max_mps2"), std::runtime_error);
  EXPECT_THROW(read_sweep_outcomes(csv + "1,2\n", "edge.k"), std::runtime_error);
}

}  // namespace
}  // namespace fragsim
