// Slices of a plan and their merge (experiments/shard.hpp): --shard parsing, the slices' ranges,
// each refusal of merge_slices on hand-made slices, and end to end: `fragsim sweep --shard` and
// `fragsim suite --shard` slices merged by `fragsim merge` are the unsharded file byte for byte,
// for several N including N above the number of jobs.

#include "experiments/shard.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "experiments/suite.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShardSpec, KCountsFromZeroAndMustBeBelowN) {
  const Shard s = parse_shard("3/4");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 4u);
  EXPECT_EQ(parse_shard("0/1").count, 1u);
  for (const char* bad : {"4/4", "1/0", "0/0", "-1/4", "1", "", "a/4", "1/b", "1/4/2", " 1/4",
                          "1/4 ", "+1/4", "0/1000001", "99999999999999999999/4"}) {
    EXPECT_THROW(parse_shard(bad), ShardError) << bad;
  }
  try {
    parse_shard("4/4");
    FAIL();
  } catch (const ShardError& e) {
    EXPECT_NE(std::string(e.what()).find("0/4 .. 3/4"), std::string::npos) << e.what();
  }
}

TEST(ShardRange, SlicesAreContiguousCoverEveryJobOnceAndDifferByAtMostOne) {
  // 10 jobs in 4: floor(10 k / 4) = 0, 2, 5, 7, 10.
  const std::size_t expected[] = {0, 2, 5, 7, 10};
  for (std::size_t k = 0; k < 4; ++k) {
    const JobRange r = shard_range(10, {k, 4});
    EXPECT_EQ(r.begin, expected[k]);
    EXPECT_EQ(r.end, expected[k + 1]);
  }
  for (std::size_t m = 0; m <= 20; ++m) {
    for (std::size_t n = 1; n <= 25; ++n) {
      std::size_t next = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const JobRange r = shard_range(m, {k, n});
        ASSERT_EQ(r.begin, next) << m << " jobs, slice " << k << "/" << n;
        ASSERT_LE(r.end - r.begin, m / n + 1);
        ASSERT_GE(r.end - r.begin, m / n);
        next = r.end;
      }
      ASSERT_EQ(next, m) << m << " jobs in " << n;
    }
  }
  // More slices than jobs: 3 jobs in 5 slices, two of them empty.
  EXPECT_EQ(shard_range(3, {0, 5}).end, 0u);
  EXPECT_EQ(shard_range(3, {4, 5}).begin, 2u);
}

TEST(PlanFingerprint, IsFnv1a64AndPartsAreLengthPrefixed) {
  // FNV-1a 64 of "" is its offset basis; of "a", the published 0xaf63dc4c8601ec8c.
  EXPECT_EQ(plan_fingerprint(""), "cbf29ce484222325");
  EXPECT_EQ(plan_fingerprint("a"), "af63dc4c8601ec8c");
  EXPECT_NE(PlanText().add("ab").add("c").text(), PlanText().add("a").add("bc").text());
}

// A slice of a made-up plan of `total` jobs with one row per job: rows "j,<job>".
SliceFile slice(const std::string& name, std::size_t k, std::size_t n, std::size_t total,
                const std::string& plan = "0123456789abcdef") {
  std::string csv = "job,value\n";
  const JobRange r = shard_range(total, {k, n});
  for (std::size_t j = r.begin; j < r.end; ++j) csv += std::to_string(j) + ",x\n";
  return {name, slice_line("sweep", {k, n}, plan, total, csv) + csv};
}

std::string merge_error(const std::vector<SliceFile>& files) {
  try {
    merge_slices(files);
  } catch (const ShardError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "merged";
  return "";
}

TEST(MergeSlices, JoinsInSliceOrderWhateverTheFileOrder) {
  const std::string merged =
      merge_slices({slice("c", 2, 3, 5), slice("a", 0, 3, 5), slice("b", 1, 3, 5)});
  EXPECT_EQ(merged, "job,value\n0,x\n1,x\n2,x\n3,x\n4,x\n");
  // Six slices of five jobs: slice 0 is empty and still counts.
  std::vector<SliceFile> six;
  for (std::size_t k = 0; k < 6; ++k) six.push_back(slice(std::to_string(k), k, 6, 5));
  EXPECT_EQ(merge_slices(six), merged);
  EXPECT_NE(six[0].bytes.find("jobs=0-0/5 rows=0\n"), std::string::npos) << six[0].bytes;
}

TEST(MergeSlices, EachRefusalIsOneLineNamingTheFile) {
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 1, 2, 4, "fedcba9876543210")})
                .find("b: a slice of another plan"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 1, 3, 4)}).find("b: slice 1/3"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), slice("b", 0, 2, 4)})
                .find("b: slice 0/2 is given twice (also a)"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 1, 4, 8), slice("b", 3, 4, 8)})
                .find("missing slices 0/4, 2/4 (2 of 4 given)"),
            std::string::npos);
  EXPECT_NE(merge_error({slice("a", 0, 2, 4)}).find("missing slice 1/2"), std::string::npos);

  SliceFile plain{"p.csv", "job,value\n0,x\n"};
  EXPECT_NE(merge_error({plain}).find("p.csv:1: not a slice"), std::string::npos);
  SliceFile cut = slice("cut", 0, 1, 3);
  cut.bytes.resize(cut.bytes.size() - 4);  // "2,x\n" gone: 2 rows where the line says 3
  EXPECT_NE(merge_error({cut}).find("cut: 2 rows, its slice line says 3"), std::string::npos);
  SliceFile unterminated = slice("u", 0, 1, 3);
  unterminated.bytes.pop_back();
  EXPECT_NE(merge_error({unterminated}).find("u: the last row has no line end"), std::string::npos);
  SliceFile other_columns = slice("h", 1, 2, 4);
  other_columns.bytes.replace(other_columns.bytes.find("job,value"), 9, "job,other");
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), other_columns}).find("h:2: the CSV header differs"),
            std::string::npos);
  SliceFile wrong_range = slice("r", 0, 2, 4);
  wrong_range.bytes.replace(wrong_range.bytes.find("jobs=0-2"), 8, "jobs=0-3");
  EXPECT_NE(merge_error({wrong_range}).find("r:1: jobs=0-3/4 is not slice 0/2"), std::string::npos);
  SliceFile suite = slice("s", 1, 2, 4);
  suite.bytes.replace(suite.bytes.find("command=sweep"), 13, "command=suite");
  EXPECT_NE(merge_error({slice("a", 0, 2, 4), suite}).find("s: a suite slice; a is a sweep"),
            std::string::npos);
  EXPECT_NE(merge_error({}).find("no slice files"), std::string::npos);
}

// ---- End to end. ----

using test::Result;
using test::run_fragsim;

// 3 distances x 2 seeds = 6 jobs of thesis125 cut to 8 fragments and 0.3 s, none and edge.
const std::string kSweep = "sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                           "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.3 "
                           "--vary object.distance_m=3,5,7 --seeds 2 --strategies none,edge "
                           "--jobs 1";

std::vector<std::string> shard_files(const std::string& command, const std::string& dir,
                                     std::size_t n) {
  std::vector<std::string> files;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string f = dir + "/shard_" + std::to_string(k) + "_of_" + std::to_string(n) + ".csv";
    const Result r = run_fragsim(command + " --shard " + std::to_string(k) + "/" +
                                 std::to_string(n) + " --out " + f);
    EXPECT_EQ(r.status, 0) << r.out;
    files.push_back(f);
  }
  return files;
}

std::string merge_args(const std::string& out, const std::vector<std::string>& files) {
  std::string args = "merge " + out;
  for (const std::string& f : files) args += " " + f;
  return args;
}

TEST(ShardCommand, MergedSweepSlicesAreTheUnshardedFileByteForByte) {
  const test::UniqueDir dir("fragsim_shard_sweep");
  const Result whole = run_fragsim(kSweep + " --out " + dir.str() + "/whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.out;
  const std::string expected = read_file(dir.str() + "/whole.csv");
  ASSERT_EQ(lines(expected), 1 + 6 * 2);
  for (std::size_t n : {1u, 2u, 4u, 6u, 9u}) {  // 9 > 6 jobs: three empty slices
    SCOPED_TRACE("N = " + std::to_string(n));
    const std::vector<std::string> files = shard_files(kSweep, dir.str(), n);
    const std::string out = dir.str() + "/merged_" + std::to_string(n) + ".csv";
    const Result m = run_fragsim(merge_args(out, files));
    ASSERT_EQ(m.status, 0) << m.out;
    EXPECT_EQ(read_file(out), expected);
    EXPECT_NE(m.out.find("12 rows from " + std::to_string(n) + " slices"), std::string::npos)
        << m.out;
    // The per-value tables of a one-key sweep, as the unsharded command printed them.
    const std::string tables = whole.out.substr(whole.out.find("\nnone: seeds"));
    EXPECT_NE(m.out.find(tables), std::string::npos) << m.out << "\n---\n" << whole.out;
  }
  // A slice is its jobs' rows of the whole file after the slice line: 6 jobs in 4 are 1,2,1,2.
  const std::string s1 = read_file(dir.str() + "/shard_1_of_4.csv");
  EXPECT_EQ(s1.rfind("# fragsim slice: command=sweep shard=1/4 plan=", 0), 0u) << s1;
  EXPECT_NE(s1.find(" jobs=1-3/6 rows=4\n"), std::string::npos) << s1;
  EXPECT_EQ(lines(s1), 2 + 4);
}

TEST(ShardCommand, MergeRefusesOtherPlansRepeatsAndGapsAndWritesNothing) {
  const test::UniqueDir dir("fragsim_shard_refuse");
  const std::vector<std::string> files = shard_files(kSweep, dir.str(), 3);
  // The same sweep with other seeds is another plan.
  const std::string other = dir.str() + "/other.csv";
  std::string other_plan = kSweep;
  other_plan.replace(other_plan.find("--seeds 2"), 9, "--seed-list 5,6");
  ASSERT_EQ(run_fragsim(other_plan + " --shard 1/3 --out " + other).status, 0);
  const std::string out = dir.str() + "/merged.csv";
  struct Case {
    std::vector<std::string> slices;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{files[0], other, files[2]}, other + ": a slice of another plan"},
      {{files[0], files[1], files[1], files[2]}, "slice 1/3 is given twice"},
      {{files[0], files[2]}, "missing slice 1/3 (2 of 3 given)"},
      {{files[0], files[1], files[2], dir.str() + "/absent.csv"}, "absent.csv"},
  };
  for (const Case& c : cases) {
    const Result r = run_fragsim(merge_args(out, c.slices));
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(lines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(c.expected), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  const Result plain = run_fragsim(merge_args(out, {files[0], dir.str() + "/../nothing"}));
  EXPECT_EQ(plain.status, 2) << plain.out;
  // OUT exists: only with --force; OUT given as a slice: refused.
  ASSERT_EQ(run_fragsim(merge_args(out, files)).status, 0);
  const Result again = run_fragsim(merge_args(out, files));
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.out.find("--force"), std::string::npos) << again.out;
  EXPECT_EQ(
      run_fragsim("merge --force " + out + " " + files[0] + " " + files[1] + " " + files[2]).status,
      0);
  const Result self = run_fragsim(merge_args(files[0], files));
  EXPECT_EQ(self.status, 2);
  EXPECT_NE(self.out.find("is also given as a slice"), std::string::npos) << self.out;
  EXPECT_EQ(run_fragsim("merge " + out).status, 2);
}

TEST(ShardCommand, BadShardIsOneLineNamingTheOption) {
  const test::UniqueDir dir("fragsim_shard_bad");
  for (const char* bad : {"4/4", "x", "1/0", "-1/2"}) {
    const Result r =
        run_fragsim(kSweep + " --shard " + std::string(bad) + " --out " + dir.str() + "/x.csv");
    EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
    EXPECT_EQ(lines(r.out), 1) << r.out;
    EXPECT_EQ(r.out.rfind("fragsim sweep: --shard ", 0), 0u) << r.out;
    const Result s =
        run_fragsim("suite --shard " + std::string(bad) + " --out " + dir.str() + "/y.csv");
    EXPECT_EQ(s.status, 2) << bad << ": " << s.out;
    EXPECT_EQ(lines(s.out), 1) << s.out;
    EXPECT_EQ(s.out.rfind("fragsim suite: --shard ", 0), 0u) << s.out;
  }
  const Result no_out = run_fragsim("suite --shard 0/2");
  EXPECT_EQ(no_out.status, 2);
  EXPECT_NE(no_out.out.find("--shard: needs --out"), std::string::npos) << no_out.out;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(ShardCommand, AFailingJobIsNamedByItsNumberInTheWholePlan) {
  // 5 jobs of 60 steps; slice 1/2 holds jobs 3, 4 and 5. On 2 workers, worker 0 runs jobs 3 and
  // 5, so its step 100 (support/signal_at_step.cpp) falls in job 5, where it kills itself.
  const test::UniqueDir dir("fragsim_shard_crash");
  for (const auto& [name, value] :
       {std::pair<const char*, const char*>{"FRAGSIM_TEST_RAISE_AT_STEP", "100"},
        {"FRAGSIM_TEST_RAISE_SIGNAL", "KILL"},
        {"FRAGSIM_TEST_RAISE_IN", "self"}}) {
    ::setenv(name, value, 1);
  }
  const Result r = run_fragsim("sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                               "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s "
                               "0.5 --vary object.distance_m=3,5,7,9,11 --strategies none,edge "
                               "--jobs 2 --shard 1/2 --out " +
                               dir.str() + "/x.csv");
  for (const char* name :
       {"FRAGSIM_TEST_RAISE_AT_STEP", "FRAGSIM_TEST_RAISE_SIGNAL", "FRAGSIM_TEST_RAISE_IN"}) {
    ::unsetenv(name);
  }
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(r.out,
            "fragsim sweep: job 5 (object.distance_m=11, seed 1): the worker process was killed "
            "by signal 9 (Killed)\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// The suite's CSV without strategy_ms_median, its one timing column (suite_test.cpp).
std::string without_timing(const std::string& csv) {
  std::istringstream in(csv);
  std::string out, line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// Printed tables without each line's last word (strat_ms in a table row).
std::string without_timing_words(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("wrote ", 0) == 0) continue;
    out += line.substr(0, line.rfind(' ')) + "\n";
  }
  return out;
}

TEST(SuiteCsvRead, ReadsBackTheRunsAndOutcomesSuiteCsvWrote) {
  const std::vector<SuiteRun> runs = {{"front", "6", "future", "10", "path", 1},
                                      {"front", "6", "future", "10", "path", 2},
                                      {"close", "1.5", "present", "9", "player", 2}};
  std::vector<SuiteOutcome> outcomes;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    for (const char* v : {"none", "edge"}) {
      SuiteOutcome o;
      o.run = r;
      o.variant = v;
      o.near_fragments = static_cast<int>(r);
      o.camera_hits = 1;
      o.deviation_mean_m = 0.1 * static_cast<double>(r) + 1e-17;
      o.near_misses = 7;
      o.strategy_ms_median = 0.003;
      outcomes.push_back(o);
    }
  }
  const std::string csv = suite_csv(runs, outcomes);
  const SuiteTable t = read_suite_csv(csv);
  ASSERT_EQ(t.runs.size(), 3u);
  EXPECT_EQ(t.variants, 2u);
  EXPECT_EQ(t.runs[2].scene, "close");
  EXPECT_EQ(t.runs[1].seed, 2u);
  ASSERT_EQ(t.outcomes.size(), 6u);
  EXPECT_EQ(t.outcomes[5].run, 2u);
  EXPECT_EQ(suite_csv(t.runs, t.outcomes), csv);  // every number back to its last bit
  EXPECT_THROW(read_suite_csv("a,b\n"), std::runtime_error);
  EXPECT_THROW(read_suite_csv(csv + "front,6\n"), std::runtime_error);
}

TEST(ShardCommand, MergedSuiteSlicesAreTheUnshardedFileButForTheTimingColumn) {
  const test::UniqueDir dir("fragsim_shard_suite");
  // 3 runs: thesis125 at 4 m, aim future, three speeds, path camera, seed 1.
  const std::string suite = "suite --scene-dir " + std::string(FRAGSIM_DATA_DIR) +
                            "/scenes --scenes thesis125 --modes path --seeds 1 --limit 3 --jobs 1";
  const Result whole = run_fragsim(suite + " --out " + dir.str() + "/whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.out;
  const std::string expected = read_file(dir.str() + "/whole.csv");
  ASSERT_EQ(lines(expected), 1 + 3 * static_cast<int>(suite_variants().size()));
  for (std::size_t n : {2u, 4u}) {  // 4 > 3 runs: one empty slice
    SCOPED_TRACE("N = " + std::to_string(n));
    const std::vector<std::string> files = shard_files(suite, dir.str(), n);
    const std::string out = dir.str() + "/merged_" + std::to_string(n) + ".csv";
    const Result m = run_fragsim(merge_args(out, files));
    ASSERT_EQ(m.status, 0) << m.out;
    const std::string merged = read_file(out);
    EXPECT_EQ(lines(merged), lines(expected));
    EXPECT_EQ(without_timing(merged), without_timing(expected));
    // The tables and the recommendation, as the unsharded command printed them but for the
    // timing column (each table line's last number).
    const auto tables = [](const std::string& out) {
      return without_timing_words(out.substr(out.find("suite: ")));
    };
    EXPECT_EQ(tables(m.out), tables(whole.out)) << m.out;
    EXPECT_NE(m.out.find("most robust"), std::string::npos) << m.out;
  }
  // A suite slice does not merge with a sweep slice.
  std::filesystem::create_directory(dir.path() / "sweep");
  const std::vector<std::string> sweep = shard_files(kSweep, dir.str() + "/sweep", 2);
  const Result mixed = run_fragsim(
      merge_args(dir.str() + "/mixed.csv", {dir.str() + "/shard_0_of_4.csv", sweep[1]}));
  EXPECT_EQ(mixed.status, 2) << mixed.out;
  EXPECT_NE(mixed.out.find("a sweep slice;"), std::string::npos) << mixed.out;
}

// A slice saved with Windows line ends said "rows='4\r' is not a whole number": it is the same
// slice. A NUL in its slice line is shown, not an end to the message.
TEST(MergeSlices, WindowsLineEndsAreTheSameSliceAndControlCharactersAreShown) {
  const auto crlf = [](SliceFile f) {
    std::string out;
    for (char c : f.bytes) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
    f.bytes = out;
    return f;
  };
  const std::string merged = merge_slices({slice("a", 0, 2, 4), slice("b", 1, 2, 4)});
  EXPECT_EQ(merge_slices({crlf(slice("a", 0, 2, 4)), crlf(slice("b", 1, 2, 4))}), merged);
  SliceFile bad = slice("a", 0, 1, 2);
  bad.bytes.replace(bad.bytes.find("rows=2"), 6, std::string("rows=2\0", 7));
  EXPECT_EQ(merge_error({bad}), "a:1: rows='2\\x00' is not a whole number");
}

}  // namespace
}  // namespace fragsim
