#pragma once
// A parameter sweep (`fragsim sweep`) varies scene keys over lists or ranges of values and runs
// every combination for several seeds. This file holds the pure parts, apart from processes and
// files so they can be tested: parsing --vary specifications, the job list in its fixed order,
// reading the sweep CSV back and the single-key summary (zero intersections per value, and the
// smallest value from which a strategy keeps zero intersections). run_sweep, at the end, runs the
// jobs on the worker processes (process_runner.hpp).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {

// A malformed --vary specification or seed list. The message is one line naming the bad part;
// the caller prefixes the option.
class SweepError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The most values one range may give, and the most jobs (combinations x seeds) in one sweep.
inline constexpr std::size_t kMaxRangeValues = 100000;
inline constexpr std::size_t kMaxSweepJobs = 1000000;

// One --vary, a scene key and its values as scene-file text, in the order given.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// The values of a SPEC, a comma list `1,2,5` (any text a scene key takes, e.g. vectors `0 1.6 -5`
// separated by commas) or an inclusive numeric range `lo:hi:step`. Range values are computed as
// lo + i step (no accumulated rounding), hi is included within 1e-9 relative, and each value is
// written with the decimals of lo and step (0.1:0.5:0.1 gives 0.1 0.2 0.3 0.4 0.5, not
// 0.30000000000000004). Throws SweepError for step <= 0, hi < lo, more than kMaxRangeValues values,
// non-numbers in a range, empty items, quotes or line breaks (they would break the CSV row).
std::vector<std::string> parse_sweep_values(const std::string& spec);

// `KEY=SPEC` into an axis. Throws SweepError (no '=', empty key, or a bad SPEC).
SweepAxis parse_vary(const std::string& text);

// Seeds for --seeds N (1..N) and --seed-list a,b,c (whole numbers, no repeats). Throw SweepError.
std::vector<std::uint64_t> seeds_up_to(long long n);
std::vector<std::uint64_t> parse_seed_list(const std::string& text);

// One job, a value per axis (index into that axis's values) and a seed.
struct SweepJob {
  std::vector<std::size_t> value_index;  // one per axis
  std::uint64_t seed = 0;
};

// The cartesian product of the axes' values and the seeds, in a fixed order that is the order of
// the output rows, with the first axis varying slowest and the seed fastest. Throws SweepError when
// the product exceeds kMaxSweepJobs (before allocating it).
std::vector<SweepJob> sweep_jobs(const std::vector<SweepAxis>& axes,
                                 const std::vector<std::uint64_t>& seeds);

// The value combinations alone (the jobs of one seed), same order, as validating each combination's
// scene once covers every seed.
std::vector<std::vector<std::size_t>> sweep_combinations(const std::vector<SweepAxis>& axes);

// What the single-key summary needs from one row of a sweep CSV.
struct SweepOutcome {
  std::string value;  // of the one varied key
  std::uint64_t seed = 0;
  std::string strategy;
  int intersections = 0;  // near_fragments + camera_hit_fragments
  double deviation_mean_m = 0.0;
};

// Reads the rows of a sweep CSV (header included) for the varied key `key`. Throws
// std::runtime_error naming the missing column or the bad line.
std::vector<SweepOutcome> read_sweep_outcomes(const std::string& csv, const std::string& key);

// One value of the varied key, for one strategy.
struct SweepValueStats {
  std::string value;
  int seeds = 0;                  // rows (seeds) for this value
  int zero_seeds = 0;             // of them, with no near-plane intersection and no camera hit
  double deviation_mean_m = 0.0;  // mean over the seeds of each run's deviation_mean_m
  bool all_zero() const { return seeds > 0 && zero_seeds == seeds; }
};

struct SweepStrategyStats {
  std::string strategy;
  std::vector<SweepValueStats> values;  // ascending if every value is a number, else as given
  // The smallest value from which every seed has zero intersections, for it and every larger
  // value in the sweep (an index into values); nullopt if the largest value already fails.
  std::optional<std::size_t> threshold;
};

// Groups rows by strategy (in order of first appearance) and value. Values are ordered
// numerically when all of them are numbers, so "larger" means larger; otherwise in order of
// first appearance, and "larger" means later.
std::vector<SweepStrategyStats> summarise_single_key(const std::vector<SweepOutcome>& rows);

// Whether summarise_single_key ordered the values of `rows` numerically.
bool sweep_values_numeric(const std::vector<SweepOutcome>& rows);

// ---- Running a sweep. ----

// Everything the workers need, fixed before the first fork (cli/sweep_command.cpp checks it all).
struct SweepPlan {
  std::string scene_text;               // the --scene file's text, read once
  std::string origin;                   // its path, for messages
  std::vector<SceneOverride> base;      // the --section.key options
  std::vector<SweepAxis> axes;          // the --vary options
  std::vector<SweepJob> jobs;           // in output order
  std::vector<std::string> strategies;  // in --strategies order
  bool occlusion = true;
  // A slice's first job in the whole plan (--shard), so messages number jobs as the whole does.
  std::size_t first_job = 0;
};

// A job's scene keys: the base options, one value per axis and the seed.
std::vector<SceneOverride> sweep_overrides(const SweepPlan& plan,
                                           const std::vector<std::size_t>& value_index,
                                           std::uint64_t seed);

// The plan's fingerprint for its slices (experiments/shard.hpp), over everything that decides the
// rows (scene text, keys, values, jobs, strategies, occlusion) and the CSV's column header
// `columns`.
std::string sweep_plan_fingerprint(const SweepPlan& plan, const std::string& columns);

// One combination of the varied values as "a=1, b=2", or with the seed "a=1, b=2, seed 3".
std::string describe_combination(const SweepPlan& plan,
                                 const std::vector<std::size_t>& value_index);
std::string describe_sweep_job(const SweepPlan& plan, const SweepJob& job);

// Every job compared (compare(), `none` first) on `jobs` worker processes, one task per job. Per
// job, in plan order whatever the order of completion, it returns the strategies' evaluations in
// --strategies order, summaries only (no per-step series), bit for bit as the worker computed them
// (evaluation_codec.hpp). `on_done` gets the number of jobs finished so far. Throws TaskFailed
// naming the job ("job 3 (a=1, seed 2): ..."), or Interrupted.
std::vector<std::vector<Evaluation>> run_sweep(
    const SweepPlan& plan, int jobs,
    const std::function<void(std::size_t done)>& on_done = nullptr);

}  // namespace fragsim
