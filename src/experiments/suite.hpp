#pragma once
// The suite (`fragsim suite`) gives one verdict over many cameras. A fixed battery of runs (the
// shipped scenes at several explosion distances, aims and speeds, times seeds, times camera modes)
// runs every strategy on every run (`none` first, the deviation reference; `edge-min` once per
// camera model), aggregated per camera mode, with a recommendation. The battery is defined here, in
// code, so its results stay comparable between versions; it names scene keys only, so it needs no
// change when the player camera and the camera models change what those keys do.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/scene_file.hpp"

namespace fragsim {

// A bad selection (unknown scene or mode, bad seed count) or a missing scene file. One line; the
// caller prefixes the option.
class SuiteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One shipped scene (data/scenes/<scene>.ini) and the values it runs at, every distance x aim x
// speed. Values are scene-file text, written into the CSV as they are.
struct SuiteSceneSpec {
  std::string scene;
  std::vector<std::string> distances_m;        // object.distance_m
  std::vector<std::string> toward_camera_mps;  // explosion.toward_camera_mps
};

// The battery's scenes in output order, and the aims every scene runs with (explosion.aim).
const std::vector<SuiteSceneSpec>& suite_scene_specs();
const std::vector<std::string>& suite_aims();

// A camera mode of the battery, with a name for the tables and the scene keys that make it.
struct SuiteMode {
  std::string name;
  std::vector<SceneOverride> overrides;
};

// path, player (the scene's default acceleration), player-instant (player_accel_mps2 = inf),
// player-flick (turn_rate_degps = 720).
const std::vector<SuiteMode>& suite_modes();

// Whether a mode's runs count as "player runs" for the recommendation.
bool is_player_mode(const std::string& mode);

// A row of the tables, a strategy with the scene keys that select its variant (edge-min's camera
// model). `none` is always first.
struct SuiteVariant {
  std::string label;  // "edge", "edge-min/reachable"
  std::string strategy;
  std::vector<SceneOverride> overrides;
};

// Every registered strategy in registry order, edge-min once per camera model.
std::vector<SuiteVariant> suite_variants();

// Enough seeds for the full battery to hold at least 1000 runs.
inline constexpr int kSuiteDefaultSeeds = 9;
inline constexpr int kSuiteMaxSeeds = 100000;

// One battery entry (a scene at one distance, aim and speed), under one mode, with one seed.
struct SuiteRun {
  std::string scene;
  std::string distance_m;
  std::string aim;
  std::string toward_camera_mps;
  std::string mode;
  std::uint64_t seed = 0;
};

struct SuiteSelection {
  std::vector<std::string> scenes;  // empty means every battery scene
  std::vector<std::string> modes;   // empty means every mode
  int seeds = kSuiteDefaultSeeds;   // seeds 1..seeds
  std::size_t limit = 0;            // keep the first `limit` runs (0 keeps all), for a CI slice
};

// The runs in their fixed order, the order of the CSV rows: scene (table order), distance, aim,
// speed, mode, seed (fastest). Throws SuiteError naming an unknown scene or mode or bad seeds.
std::vector<SuiteRun> suite_runs(const SuiteSelection& selection);

// The scene keys that make a run from its scene file: the entry's values, the mode's keys and the
// seed. Variant keys come after these.
std::vector<SceneOverride> suite_overrides(const SuiteRun& run);

// The text of every scene file the runs need, read from `dir`, by scene name. Throws SuiteError
// naming a file it cannot read.
std::map<std::string, std::string> load_suite_scenes(const std::string& dir,
                                                     const std::vector<SuiteRun>& runs);

// Parses every (entry, mode) scene under every variant once, so a bad value or a renamed key is
// found before any worker starts. Throws SceneError or std::invalid_argument.
void validate_suite(const std::map<std::string, std::string>& scenes,
                    const std::vector<SuiteRun>& runs, const std::vector<SuiteVariant>& variants);

// What the tables and the CSV need of one variant on one run.
struct SuiteOutcome {
  std::size_t run = 0;  // index into the run list
  std::string variant;  // SuiteVariant::label
  int near_fragments = 0;
  int camera_hits = 0;
  int vanished = 0;  // faded out in view (fade), a failure as a cut is
  double deviation_mean_m = 0.0;
  int near_misses = 0;
  double strategy_ms_median = 0.0;
  bool clean() const { return near_fragments == 0 && camera_hits == 0 && vanished == 0; }
};

// One run, `none` on the run's scene (recorded as the reference), then every variant on the same
// scene with its keys added. Outcomes are in variant order.
std::vector<SuiteOutcome> run_suite_once(const std::string& scene_text, const SuiteRun& run,
                                         std::size_t run_index,
                                         const std::vector<SuiteVariant>& variants);

// Every run on `jobs` worker processes (process_runner.hpp; one task per run), outcomes in run
// order then variant order, the same for any `jobs` but for strategy_ms_median. `on_done` gets
// the number of runs finished so far. Throws TaskFailed naming the run, or Interrupted.
std::vector<SuiteOutcome> run_suite(const std::map<std::string, std::string>& scenes,
                                    const std::vector<SuiteRun>& runs,
                                    const std::vector<SuiteVariant>& variants, int jobs,
                                    const std::function<void(std::size_t done)>& on_done = nullptr);

// One variant aggregated over a set of runs.
struct SuiteRow {
  std::string variant;
  int runs = 0;
  int clean_runs = 0;             // zero near-plane fragments and zero camera hits
  double deviation_mean_m = 0.0;  // mean over runs of each run's dev_mean_m
  long long near_misses = 0;      // summed over runs
  long long none_near_misses = 0;
  double strategy_ms_median = 0.0;  // median over runs of each run's median strategy ms/step
  double clean_share() const { return runs > 0 ? static_cast<double>(clean_runs) / runs : 0.0; }
  // The variant's near misses over none's on the same runs; nullopt when none had none.
  std::optional<double> near_misses_kept() const {
    if (none_near_misses <= 0) return std::nullopt;
    return static_cast<double>(near_misses) / static_cast<double>(none_near_misses);
  }
};

// Rows for the outcomes whose run passes `keep` (all if unset), one per variant in order of first
// appearance. `none`'s near misses are taken from the same runs' `none` outcomes.
std::vector<SuiteRow> aggregate_suite(const std::vector<SuiteOutcome>& outcomes,
                                      const std::function<bool(std::size_t run)>& keep = nullptr);

struct SuiteRecommendation {
  std::string variant;
  std::optional<double> player_clean_share;  // nullopt when the selection had no player run
  double all_clean_share = 0.0;
  double deviation_mean_m = 0.0;  // over all runs
};

// The most robust variant other than `none`, by the highest clean share over the player runs, then
// over all runs, then the least mean deviation over all runs (then the earlier row). `player` and
// `all` are aggregate_suite's rows over the player runs (may be empty) and over all runs.
std::optional<SuiteRecommendation> recommend_suite(const std::vector<SuiteRow>& player,
                                                   const std::vector<SuiteRow>& all);

// The fingerprint of a plan for its slices (experiments/shard.hpp), over the scene files' text,
// every run with its scene keys, every variant with its keys, and the CSV's column header.
std::string suite_plan_fingerprint(const std::map<std::string, std::string>& scenes,
                                   const std::vector<SuiteRun>& runs,
                                   const std::vector<SuiteVariant>& variants);

// The tidy CSV, a header and one row per run and variant, with strategy_ms_median last as the only
// column whose bytes change between runs.
std::string suite_csv(const std::vector<SuiteRun>& runs, const std::vector<SuiteOutcome>& outcomes);

// A suite CSV read back (a merged one, whose tables `fragsim merge` prints), with the runs in file
// order, each starting where a row's run fields (scene, distance, aim, speed, seed, mode) change,
// and the outcomes with their run index. Throws std::runtime_error naming the line for: not the
// suite's header, a row without 12 cells, an unreadable number.
struct SuiteTable {
  std::vector<SuiteRun> runs;
  std::vector<SuiteOutcome> outcomes;
  std::size_t variants = 0;  // rows per run
};
SuiteTable read_suite_csv(const std::string& csv);

}  // namespace fragsim
