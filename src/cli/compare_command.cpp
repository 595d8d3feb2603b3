#include "cli/compare_command.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/render_command.hpp"
#include "cli/report_table.hpp"
#include "cli/table.hpp"
#include "experiments/evaluation.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"
#include "io/output_set.hpp"
#include "metrics/trajectory_writer.hpp"
#include "report/csv_export.hpp"
#include "report/gltf_bake.hpp"
#include "report/html_report.hpp"
#include "sim/scene_strategies.hpp"
#include "strategies/registry.hpp"

namespace fragsim::cli {

namespace po = boost::program_options;

namespace {

// For --bake FILE.glb, the recorder and one file per strategy, opened before the run so that a path
// that cannot be written fails at once. Nothing appears unless every bake fits the limit.
struct BakeRequest {
  std::vector<std::string> paths;  // in `names` order
  OutputSet files;                 // the same order
  std::size_t limit_bytes = 0;
  GltfBakeRecorder recorder;
};

std::unique_ptr<BakeRequest> bake_request(const cli::ParsedCommand& p,
                                          const std::vector<std::string>& names) {
  if (!p.options.count("bake")) {
    if (p.options.count("bake-max-mb")) throw UsageError("--bake-max-mb: needs --bake FILE.glb");
    return nullptr;
  }
  auto bake = std::make_unique<BakeRequest>();
  double limit_mb = kDefaultBakeLimit_MB;
  if (p.options.count("bake-max-mb")) {
    const std::string text = p.options["bake-max-mb"].as<std::string>();
    std::size_t used = 0;
    try {
      limit_mb = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(limit_mb) || limit_mb <= 0) {
      throw UsageError("--bake-max-mb: expected a positive number of megabytes, got '" + text +
                       "'");
    }
  }
  bake->limit_bytes = static_cast<std::size_t>(std::min(limit_mb, 4000.0) * 1e6);
  const std::string path = p.options["bake"].as<std::string>();
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".glb") throw UsageError("--bake " + path + ": expected a file name ending in .glb");
  const std::size_t least = bake_animation_bytes(p.scene.fragment_count(), p.scene.step_count(), 1);
  if (least > bake->limit_bytes) {
    throw UsageError("--bake: " + std::to_string(p.scene.fragment_count()) + " fragments over " +
                     std::to_string(p.scene.step_count() + 1) + " samples take at least " +
                     cli::fixed(static_cast<double>(least) / 1e6, 3) + " MB, over the limit of " +
                     cli::fixed(limit_mb, 3) + " MB (--bake-max-mb)");
  }
  for (const std::string& name : names) {
    const std::string file = bake_file_path(path, name, names.size() > 1);
    if (std::find(bake->paths.begin(), bake->paths.end(), file) != bake->paths.end()) {
      throw UsageError("--bake: strategy '" + name + "' named twice");
    }
    std::error_code ec;
    if (std::filesystem::exists(file, ec) && !p.options.count("force")) {
      throw UsageError("--bake " + file + ": exists (use --force to overwrite)");
    }
    try {
      bake->files.add(file);
    } catch (const std::runtime_error& e) {
      throw UsageError(std::string("--bake ") + e.what());
    }
    bake->paths.push_back(file);
  }
  return bake;
}

// Writes every strategy's bake, or none if one is over the limit or one cannot be written whole (a
// full disk).
void write_bakes(BakeRequest& bake, const std::vector<std::string>& names) {
  std::vector<const std::string*> bytes;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto& baked = bake.recorder.baked();
    const auto it = std::find_if(baked.begin(), baked.end(),
                                 [&](const auto& b) { return b.strategy == names[i]; });
    if (it == baked.end()) throw std::runtime_error("--bake: no run of " + names[i] + " recorded");
    if (it->bytes.size() > bake.limit_bytes) {
      throw UsageError("--bake " + bake.paths[i] + ": " +
                       cli::fixed(static_cast<double>(it->bytes.size()) / 1e6, 3) +
                       " MB, over the limit of " +
                       cli::fixed(static_cast<double>(bake.limit_bytes) / 1e6, 3) +
                       " MB (--bake-max-mb); nothing written");
    }
    bytes.push_back(&it->bytes);
  }
  for (std::size_t i = 0; i < names.size(); ++i) bake.files.out(i) << *bytes[i];
  bake.files.commit();
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::cout << "wrote " << bake.paths[i] << " ("
              << cli::fixed(static_cast<double>(bytes[i]->size()) / 1e6, 1) << " MB)\n";
  }
}

// The folder of output option `option` (--csv, --report), or nullopt when not given.
std::optional<OutputFolder> output_folder(const cli::ParsedCommand& p, const std::string& option) {
  if (!p.options.count(option)) return std::nullopt;
  const std::string dir = p.options[option].as<std::string>();
  if (dir.empty()) throw UsageError("--" + option + ": empty folder name");
  try {
    return std::optional<OutputFolder>(std::in_place, dir, p.options.count("force") > 0);
  } catch (const std::runtime_error& e) {
    throw UsageError("--" + option + ": " + e.what());
  }
}

}  // namespace

void add_output_options(po::options_description& own) {
  own.add_options()("csv", po::value<std::string>()->value_name("DIR"),
                    "write summary.csv, steps.csv, camera.csv, timing.csv and config.ini to DIR")(
      "trajectories", "also write DIR/trajectories.csv (one row per fragment per step: large)")(
      "report", po::value<std::string>()->value_name("DIR"),
      "write an HTML report to DIR/index.html: table, reading, charts over time, contact sheet "
      "(DIR/sheet.png), scene settings (runs the strategies in this process)")(
      "force", "overwrite the files of an existing, non-empty DIR")(
      "no-occlusion", "skip the screen-occlusion raster (faster; occlusion columns read 0)")(
      "jobs", po::value<std::string>()->value_name("J"),
      "worker processes for the strategies (default: one per core; --trajectories, --sheet, "
      "--report or --bake run in one)")(
      "bake", po::value<std::string>()->value_name("FILE.glb"),
      "write the run as an animated glTF 2.0 binary: a node per piece with its mesh, the camera, "
      "the ground, poses at every step (several strategies: FILE.<strategy>.glb each)")(
      "bake-max-mb", po::value<std::string>()->value_name("MB"),
      "refuse a bake file larger than MB megabytes (default 256)");
  cli::add_sheet_options(own);
}

// Runs `names` and prints the report; writes the CSV files when asked.
int run_and_report(const cli::ParsedCommand& p, const std::vector<std::string>& names) {
  for (const std::string& n : names) {
    try {
      validate_strategy_settings(n, p.scene);
    } catch (const InputError& e) {
      throw UsageError(std::string("--strategies: ") + e.what());
    }
  }
  const std::optional<cli::SheetRequest> sheet = cli::sheet_request(p);
  if (p.options.count("trajectories") && !p.options.count("csv")) {
    throw UsageError("--trajectories: needs --csv DIR");
  }
  // Declared before every file written into them, so a failure removes the files first, then the
  // folders this run created.
  std::optional<OutputFolder> csv_folder = output_folder(p, "csv");
  std::optional<OutputFolder> report_folder = output_folder(p, "report");
  const bool occlusion = p.options.count("no-occlusion") == 0;

  OutputSet csv_files;
  std::optional<TrajectoryWriter> traj;
  if (csv_folder && p.options.count("trajectories")) {
    traj.emplace(
        csv_files.add((std::filesystem::path(csv_folder->path()) / "trajectories.csv").string()));
  }
  const int jobs = cli::jobs_option(p.options);
  // The report's contact sheet draws from the same recorder as --sheet (steps may repeat).
  std::vector<int> recorded_steps = sheet ? sheet->steps : std::vector<int>{};
  if (report_folder) {
    const std::vector<int> report_steps = report_sheet_steps(p.scene);
    recorded_steps.insert(recorded_steps.end(), report_steps.begin(), report_steps.end());
  }
  std::optional<FrameRecorder> recorder;
  if (sheet || report_folder) recorder.emplace(recorded_steps);
  // The report's 3D view is recorded only when this build can draw it.
  const BundledThreeJs three = bundled_three_js();
  std::optional<ViewerRecorder> viewer;
  if (report_folder) {
    viewer.emplace(viewer_sample_every(p.scene.fragment_count(), p.scene.step_count(),
                                       static_cast<int>(names.size())));
  }
  const std::unique_ptr<BakeRequest> bake = bake_request(p, names);
  cli::ObserverFanOut extra;
  extra.add(traj ? &*traj : nullptr);
  extra.add(recorder ? &*recorder : nullptr);
  extra.add(bake ? &bake->recorder : nullptr);
  extra.add(viewer && three.available() ? &*viewer : nullptr);
  const std::vector<Evaluation> runs = compare(p.scene, names, occlusion, extra.or_null(), jobs);
  cli::print_report(p.scene, runs, std::cout);
  if (bake) write_bakes(*bake, names);
  if (sheet) cli::write_sheet(*sheet, p.scene, *recorder, names, std::cout);
  if (report_folder) {
    const std::vector<std::string> written =
        write_html_report(report_folder->path(), p.scene, runs, *recorder, *viewer, three);
    report_folder->keep();
    if (!three.available())
      std::cerr << "fragsim: --report: " << viewer_missing_text(three) << "\n";
    std::cout << "wrote";
    for (const std::string& f : written) std::cout << " " << f;
    std::cout << "\n";
  }
  if (csv_folder) {
    add_comparison_csv(csv_files, csv_folder->path(), p.scene, runs);
    csv_files.commit();
    csv_folder->keep();
    std::cout << "wrote " << csv_folder->path() << "/{summary,steps,camera,timing}.csv, config.ini"
              << (traj ? ", trajectories.csv" : "") << "\n";
  }
  return 0;
}

int cmd_compare(const std::vector<std::string>& args) {
  po::options_description own("compare options");
  const std::string all_names = join_strategy_names(strategy_table(), ",");
  own.add_options()("strategies", po::value<std::string>()->default_value(all_names),
                    "comma-separated strategies to compare");
  add_output_options(own);
  const cli::ParsedCommand p = cli::parse_command("compare", args, own);
  if (p.help_shown) return 0;
  const std::vector<std::string> names = cli::split_list(p.options["strategies"].as<std::string>());
  if (names.empty()) throw UsageError("--strategies: no strategy named");
  return run_and_report(p, names);
}

}  // namespace fragsim::cli
