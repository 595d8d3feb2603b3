// fragsim sweep: --vary specifications, the job order, the single-key summary on hand-made rows,
// and the command end to end (byte-identical output whatever the number of worker processes).

#include "experiments/sweep.hpp"

#include <gtest/gtest.h>

#include "support/run_fragsim.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/csv_export.hpp"

namespace fragsim {
namespace {

using Values = std::vector<std::string>;

TEST(SweepSpec, CommaListKeepsTheTextOfEachValue) {
  EXPECT_EQ(parse_sweep_values("1,2,5"), (Values{"1", "2", "5"}));
  EXPECT_EQ(parse_sweep_values(" thesis , discrete "), (Values{"thesis", "discrete"}));
  // Vectors are values with spaces; commas separate the values.
  EXPECT_EQ(parse_sweep_values("0 1.6 -5,0 1.6 -7"), (Values{"0 1.6 -5", "0 1.6 -7"}));
  EXPECT_EQ(parse_sweep_values("0.25"), (Values{"0.25"}));
}

TEST(SweepSpec, IntegerRangeIncludesBothEnds) {
  const Values v = parse_sweep_values("1:20:1");
  ASSERT_EQ(v.size(), 20u);
  EXPECT_EQ(v.front(), "1");
  EXPECT_EQ(v[2], "3");
  EXPECT_EQ(v.back(), "20");
  EXPECT_EQ(parse_sweep_values("2:8:2"), (Values{"2", "4", "6", "8"}));
  EXPECT_EQ(parse_sweep_values("3:3:1"), (Values{"3"}));
}

TEST(SweepSpec, FloatRangeNeitherLosesTheEndNorShowsRounding) {
  // (0.5 - 0.1) / 0.1 is 3.9999999999999996 and 0.1 + 2 * 0.1 is 0.30000000000000004.
  EXPECT_EQ(parse_sweep_values("0.1:0.5:0.1"), (Values{"0.1", "0.2", "0.3", "0.4", "0.5"}));
  EXPECT_EQ(parse_sweep_values("-0.3:0.3:0.1"),
            (Values{"-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"}));
  EXPECT_EQ(parse_sweep_values("0:1:0.3"), (Values{"0", "0.3", "0.6", "0.9"}));  // hi not on grid
  EXPECT_EQ(parse_sweep_values("0:0.7:0.07").size(), 11u);
  EXPECT_EQ(parse_sweep_values("1e-3:3e-3:1e-3").size(), 3u);
  EXPECT_EQ(parse_sweep_values("1:100000:1").size(), kMaxRangeValues);
}

TEST(SweepSpec, BadSpecsAreRejected) {
  for (const char* bad :
       {"",        " ",       "1,,2",       "1,",         ",1",         "1,1",
        "1:2",     "1:2:3:4", "1:2:0",      "1:2:-1",     "2:1:1",      "a:2:1",
        "1:b:1",   "1:2:c",   "0:100000:1", "0:1e9:1e-3", "0:1:1e-300", "0 1.6 -5:0 1.6 -7:1",
        "1:inf:1", "a\"b",    "1\n2"}) {
    EXPECT_THROW(parse_sweep_values(bad), SweepError) << "'" << bad << "'";
  }
}

TEST(SweepSpec, VaryIsKeyEqualsSpec) {
  const SweepAxis a = parse_vary("object.distance_m=1:3:1");
  EXPECT_EQ(a.key, "object.distance_m");
  EXPECT_EQ(a.values, (Values{"1", "2", "3"}));
  EXPECT_EQ(parse_vary("camera.look_at_m=0 1.6 -7").values, (Values{"0 1.6 -7"}));
  EXPECT_THROW(parse_vary("object.distance_m"), SweepError);
  EXPECT_THROW(parse_vary("=1,2"), SweepError);
  EXPECT_THROW(parse_vary("edge.k="), SweepError);
}

TEST(SweepSpec, Seeds) {
  EXPECT_EQ(seeds_up_to(3), (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_THROW(seeds_up_to(0), SweepError);
  EXPECT_THROW(seeds_up_to(-2), SweepError);
  EXPECT_EQ(parse_seed_list("5, 7,18446744073709551615"),
            (std::vector<std::uint64_t>{5, 7, 18446744073709551615ull}));
  for (const char* bad : {"", "1,", "x", "-1", "1.5", "1,1", "18446744073709551616"}) {
    EXPECT_THROW(parse_seed_list(bad), SweepError) << "'" << bad << "'";
  }
}

TEST(SweepJobs, CartesianOrderFirstAxisSlowestSeedFastest) {
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

TEST(SweepJobs, TooManyJobsAreRefusedBeforeAllocating) {
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

TEST(SweepSummary, ThresholdIsTheStartOfTheAllZeroTail) {
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

TEST(SweepSummary, LastValueFailingMeansNoThreshold) {
  const std::vector<SweepOutcome> rows{row("edge", "1", 1, 0, 0.0), row("edge", "2", 1, 1, 0.0)};
  const auto stats = summarise_single_key(rows);
  ASSERT_EQ(stats.size(), 1u);
  EXPECT_FALSE(stats[0].threshold.has_value());
}

TEST(SweepSummary, NonNumericValuesKeepTheirOrder) {
  const std::vector<SweepOutcome> rows{row("edge", "thesis", 1, 1, 2.0),
                                       row("edge", "discrete", 1, 0, 1.0)};
  EXPECT_FALSE(sweep_values_numeric(rows));
  const auto stats = summarise_single_key(rows);
  ASSERT_EQ(stats[0].values.size(), 2u);
  EXPECT_EQ(stats[0].values[0].value, "thesis");
  ASSERT_TRUE(stats[0].threshold.has_value());
  EXPECT_EQ(stats[0].values[*stats[0].threshold].value, "discrete");
}

TEST(SweepSummary, ReadsOutcomesFromTheCsvByColumnName) {
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

TEST(SweepSummary, SummaryCellsAreSummaryCsvRows) {
  Scene scene;
  Evaluation e;
  e.summary.scene = "hand";
  e.summary.strategy = "edge";
  e.summary.seed = 42;
  e.summary.intersections.near_fragments = 3;
  e.summary.deviation.mean_m = 0.1;
  auto join = [](const Values& cells) {
    std::string s;
    for (const std::string& c : cells) s += (s.empty() ? "" : ",") + c;
    return s + "\n";
  };
  EXPECT_EQ(join(summary_csv_columns()) + join(summary_csv_cells(scene, e.summary)),
            summary_csv(scene, {e}));
}

// ---- The command end to end. ----

using test::Result;
Result fragsim(const std::string& args) {
  return test::run_fragsim(args);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kTiny = "sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                          "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.5 "
                          "--vary object.distance_m=3,5 --seeds 2 --strategies none,edge";

std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(SweepCommand, OutputIsTheSameWhateverTheNumberOfWorkers) {
  const std::string dir = fresh_dir("fragsim_sweep_e2e");
  const Result one = fragsim(kTiny + " --jobs 1 --out " + dir + "/one.csv");
  ASSERT_EQ(one.status, 0) << one.out;
  const Result two = fragsim(kTiny + " --jobs 2 --out " + dir + "/two.csv");
  ASSERT_EQ(two.status, 0) << two.out;
  const std::string a = read_file(dir + "/one.csv");
  const std::string b = read_file(dir + "/two.csv");
  EXPECT_EQ(a, b);
  EXPECT_EQ(lines(a), 1 + 2 * 2 * 2);  // header + 2 values x 2 seeds x 2 strategies
  EXPECT_EQ(a.rfind("object.distance_m,seed,scene,strategy,", 0), 0u) << a;
  EXPECT_NE(a.find("\n5,2,thesis125,edge,"), std::string::npos) << a;
  EXPECT_NE(one.out.find("smallest object.distance_m"), std::string::npos) << one.out;
  // Only the two outputs: every worker's temporary file is gone.
  int files = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir)) files += f.is_regular_file();
  EXPECT_EQ(files, 2);

  const Result again = fragsim(kTiny + " --jobs 2 --out " + dir + "/one.csv");
  EXPECT_EQ(again.status, 2) << again.out;
  EXPECT_NE(again.out.find("--force"), std::string::npos) << again.out;
  const Result forced = fragsim(kTiny + " --jobs 2 --force --out " + dir + "/one.csv");
  EXPECT_EQ(forced.status, 0) << forced.out;
  EXPECT_EQ(read_file(dir + "/one.csv"), b);
}

TEST(SweepCommand, BadVaryValueIsOneLineNamingOptionAndValue) {
  const std::string dir = fresh_dir("fragsim_sweep_bad");
  const Result r = fragsim(kTiny + " --vary edge.k=1,-2 --out " + dir + "/x.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--vary edge.k=-2"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv"));

  const Result range = fragsim(kTiny.substr(0, kTiny.find("--vary")) +
                               "--vary object.distance_m=1:5:0 --out " + dir + "/x.csv");
  EXPECT_EQ(range.status, 2);
  EXPECT_EQ(lines(range.out), 1) << range.out;
  EXPECT_NE(range.out.find("step must be > 0"), std::string::npos) << range.out;
}

// Test-only environment variables for one call (sim/simulation.hpp), removed again after it.
class ScopedEnv {
 public:
  explicit ScopedEnv(std::vector<std::pair<std::string, std::string>> vars)
      : vars_(std::move(vars)) {
    for (const auto& [name, value] : vars_) ::setenv(name.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() {
    for (const auto& [name, value] : vars_) ::unsetenv(name.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::vector<std::pair<std::string, std::string>> vars_;
};

TEST(SweepCommand, AWorkerThatDiesIsOneLineNamingTheJob) {
  // 3 jobs of 60 steps (none, then edge) on 2 workers: worker 0 runs jobs 1 and 3, worker 1 job 2
  // only, so step 100 of a worker is reached once, in job 3, where that worker kills itself.
  const std::string dir = fresh_dir("fragsim_sweep_crash");
  Result r;
  {
    const ScopedEnv env({{"FRAGSIM_TEST_RAISE_AT_STEP", "100"},
                         {"FRAGSIM_TEST_RAISE_SIGNAL", "KILL"},
                         {"FRAGSIM_TEST_RAISE_IN", "self"}});
    r = fragsim("sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.5 --vary "
                "object.distance_m=3,5,7 --strategies none,edge --jobs 2 --out " +
                dir + "/x.csv");
  }
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(r.out,
            "fragsim sweep: job 3 (object.distance_m=7, seed 1): the worker process was killed "
            "by signal 9 (Killed)\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fragsim
