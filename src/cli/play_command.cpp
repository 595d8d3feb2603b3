#include "cli/play_command.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/command_line.hpp"
#include "cli/render_command.hpp"
#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "play/play_session.hpp"
#include "play/scripted_route.hpp"
#include "sim/scene_strategies.hpp"
#include "strategies/registry.hpp"
#include "window/sdl_window.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

// The q-quantile of `v` by the nearest-rank rule (for an even count the median is the upper
// middle).
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

void print_times(const FrameTimes& t, std::ostream& out) {
  out << "frames: " << t.frame_ms.size() << ", median / p95 ms:";
  const std::pair<const char*, const std::vector<double>*> parts[] = {{"frame", &t.frame_ms},
                                                                      {"physics", &t.physics_ms},
                                                                      {"strategy", &t.strategy_ms},
                                                                      {"draw", &t.draw_ms},
                                                                      {"present", &t.present_ms}};
  const char* sep = " ";
  for (const auto& [name, v] : parts) {
    out << sep << name << " " << fixed_text(quantile(*v, 0.5), 3) << " / "
        << fixed_text(quantile(*v, 0.95), 3);
    sep = "; ";
  }
  out << "\n";
}

void print_flight(const FlightReport& f, std::ostream& out) {
  out << "flight " << f.flight << ": " << f.strategy << ", " << fixed_text(f.t_s, 3) << " s ("
      << f.steps << " steps): near " << f.near_fragments << ", cam " << f.camera_hits << "\n";
  if (f.recorded) {
    out << "recorded " << f.recorded->track_csv << " and " << f.recorded->scene_ini
        << "; every strategy on this flight:\n  fragsim compare --scene " << f.recorded->scene_ini
        << "\n";
  }
  out.flush();
}

long bench_frames(const std::string& text) {
  long n = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, n);
  if (text.empty() || ec != std::errc() || ptr != end || n < 1 || n > 10'000'000) {
    throw UsageError("--bench-frames " + text + ": expected a whole number in [1, 10000000]");
  }
  return n;
}

}  // namespace

int cmd_play(const std::vector<std::string>& args) {
  po::options_description own("play options");
  const std::string names = join_strategy_names(strategy_table(), " | ");
  own.add_options()("strategy", po::value<std::string>()->default_value("edge-min"),
                    ("the first flight's strategy (Tab and 1-9 switch): " + names).c_str())(
      "record", po::value<std::string>()->value_name("FILE.csv"),
      "each flight's camera track (camera.csv's columns) to FILE.csv and its replay scene to "
      "FILE.ini; later flights to FILE-2.csv, ... (default: play-NNN.csv in the working folder, "
      "never over an earlier one)")("size", po::value<std::string>()->default_value("640x360"),
                                    "window size, WIDTHxHEIGHT")(
      "overlays", po::value<std::string>()->default_value("candidates,forces,cuts"),
      "the overlays O shows, as render's --overlays")(
      "bench-frames", po::value<std::string>()->value_name("N"),
      "no window: fly a scripted route for N frames as fast as possible, record nothing, and "
      "print the median and 95th percentile of each part of a frame");
  const ParsedCommand p = parse_command("play", args, own);
  if (p.help_shown) return 0;

  PlayOptions options;
  options.strategy = p.options["strategy"].as<std::string>();
  std::tie(options.style.width_px, options.style.height_px) =
      parse_size(p.options["size"].as<std::string>());
  options.style.overlays = parse_overlays(p.options["overlays"].as<std::string>());
  if (p.options.count("record")) {
    options.record = p.options["record"].as<std::string>();
    const fs::path file(options.record);
    std::error_code ec;
    if (options.record.empty() || !file.has_filename()) throw UsageError("--record: no file name");
    if (file.extension() == ".ini") {
      throw UsageError("--record " + options.record +
                       ": the track is a CSV file; its scene is written beside it as .ini");
    }
    if (!file.parent_path().empty() && !fs::is_directory(file.parent_path(), ec)) {
      throw UsageError("--record " + options.record + ": folder " + file.parent_path().string() +
                       " does not exist");
    }
  }

  if (!p.options.count("bench-frames")) {
    // Found here, not when the first flight ends and its recording fails.
    if (const auto problem = record_path_problem(options.record, options.record_folder)) {
      throw UsageError((options.record.empty()
                            ? std::string("cannot record flights (--record FILE.csv): ")
                            : "--record " + options.record + ": ") +
                       *problem);
    }
  }

  try {
    // Tab and 1-9 reach every strategy, so each is validated here and a bad one fails at once.
    validate_strategy_settings(options.strategy, p.scene);
    for (const std::string& name : strategy_names()) validate_strategy_settings(name, p.scene);
  } catch (const InputError& e) {
    throw UsageError(std::string("--strategy: ") + e.what());
  }

  if (p.options.count("bench-frames")) {
    options.max_steps = bench_frames(p.options["bench-frames"].as<std::string>());
    options.record_flights = false;
    ScriptedRoute route(p.scene.sim.dt_s);
    PlaySession session(p.scene, options, route);
    session.on_flight = [](const FlightReport& f) { print_flight(f, std::cout); };
    session.run();
    print_times(session.times(), std::cout);
    return 0;
  }
  std::optional<SdlWindow> window;
  try {
    window.emplace(options.style.width_px, options.style.height_px,
                   "fragsim play - " + p.scene.name);
  } catch (const NoDisplay& e) {
    throw UsageError(e.what());
  }
  PlaySession session(p.scene, options, *window);
  session.on_flight = [](const FlightReport& f) { print_flight(f, std::cout); };
  session.on_message = [](const std::string& m) { std::cout << m << "\n" << std::flush; };
  session.run();
  print_times(session.times(), std::cout);
  return 0;
}

}  // namespace fragsim::cli
