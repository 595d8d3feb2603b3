#include "cli/render_command.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "experiments/evaluation.hpp"
#include "experiments/median.hpp"
#include "io/output_folder.hpp"
#include "render/contact_sheet.hpp"
#include "render/image.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

constexpr int kMinSizePx = 16;
constexpr int kMaxSizePx = 8192;
constexpr std::size_t kMaxSheetColumns = 16;

// The whole of `text` as a decimal integer, or nullopt.
std::optional<int> to_int(std::string_view text) {
  int v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return v;
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string_view::npos ? at : at - start));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

std::string frame_name(int step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame_%05d.png", step);
  return buf;
}

}  // namespace

std::vector<int> parse_steps(const std::string& spec, int step_count) {
  const std::vector<std::string_view> parts = split(spec, ':');
  const auto bad = [&](const std::string& why) {
    return UsageError("--steps " + spec + ": " + why);
  };
  if (parts.size() > 3) throw bad("expected a:b:every, a:b or a");
  std::vector<int> v;
  for (const std::string_view part : parts) {
    const std::optional<int> n = to_int(part);
    if (!n) throw bad("'" + std::string(part) + "' is not a whole number (expected a:b:every)");
    v.push_back(*n);
  }
  const int a = v[0];
  const int b = v.size() > 1 ? v[1] : a;
  const int every = v.size() > 2 ? v[2] : 1;
  if (a < 0 || b > step_count || a > b) {
    throw bad("needs 0 <= a <= b <= " + std::to_string(step_count) + " (the run's last step)");
  }
  if (every < 1) throw bad("every must be >= 1");
  std::vector<int> steps;
  for (long s = a; s <= b; s += every) steps.push_back(static_cast<int>(s));
  return steps;
}

std::pair<int, int> parse_size(const std::string& spec) {
  const std::vector<std::string_view> parts = split(spec, 'x');
  const std::optional<int> w = parts.size() == 2 ? to_int(parts[0]) : std::nullopt;
  const std::optional<int> h = parts.size() == 2 ? to_int(parts[1]) : std::nullopt;
  if (!w || !h) throw UsageError("--size " + spec + ": expected WIDTHxHEIGHT, e.g. 640x360");
  if (*w < kMinSizePx || *w > kMaxSizePx || *h < kMinSizePx || *h > kMaxSizePx) {
    throw UsageError("--size " + spec + ": width and height must be in [" +
                     std::to_string(kMinSizePx) + ", " + std::to_string(kMaxSizePx) + "]");
  }
  return {*w, *h};
}

FrameOverlays parse_overlays(const std::string& spec, const std::string& option) {
  FrameOverlays o;
  if (spec == "none") return o;
  for (const std::string& name : split_list(spec)) {
    if (name == "candidates") {
      o.candidates = true;
    } else if (name == "forces") {
      o.forces = true;
    } else if (name == "central") {
      o.central = true;
    } else if (name == "cuts") {
      o.cuts = true;
    } else {
      throw UsageError(option + ": unknown overlay '" + name +
                       "' (known: candidates, forces, central, cuts)");
    }
  }
  return o;
}

int cmd_render(const std::vector<std::string>& args) {
  po::options_description own("render options");
  own.add_options()("strategy", po::value<std::string>()->default_value("none"),
                    "the strategy whose run is drawn")(
      "out", po::value<std::string>()->value_name("DIR"),
      "folder for the frames, DIR/frame_NNNNN.png (NNNNN: the step)")(
      "steps", po::value<std::string>()->value_name("a:b:every"),
      "steps a to b (inclusive), every every-th; default: every step of the run")(
      "size", po::value<std::string>()->default_value("640x360"), "frame size, WIDTHxHEIGHT")(
      "overlays", po::value<std::string>()->default_value("none"),
      "comma-separated: candidates (outlined), forces (arrows), central (the occlusion metric's "
      "central region), cuts (the near plane's cut through a fragment)")(
      "force", "overwrite the files of an existing, non-empty DIR");
  const ParsedCommand p = parse_command("render", args, own);
  if (p.help_shown) return 0;

  const std::string strategy = p.options["strategy"].as<std::string>();
  try {
    validate_strategy_settings(strategy, p.scene);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--strategy: ") + e.what());
  }
  if (!p.options.count("out")) throw UsageError("--out: required (the folder for the frames)");
  const std::string dir = p.options["out"].as<std::string>();
  if (dir.empty()) throw UsageError("--out: empty folder name");
  const int step_count = p.scene.step_count();
  const std::vector<int> steps = p.options.count("steps")
                                     ? parse_steps(p.options["steps"].as<std::string>(), step_count)
                                     : parse_steps("0:" + std::to_string(step_count), step_count);
  FrameStyle style;
  std::tie(style.width_px, style.height_px) = parse_size(p.options["size"].as<std::string>());
  style.overlays = parse_overlays(p.options["overlays"].as<std::string>());
  std::optional<OutputFolder> folder;
  try {
    folder.emplace(dir, p.options.count("force") > 0);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--out: ") + e.what());
  }

  FrameRecorder recorder(steps);
  EvaluationOptions opts;
  opts.occlusion = false;
  opts.extra.push_back(&recorder);
  evaluate(p.scene, strategy, opts);
  const std::vector<RecordedFrame>& frames = *recorder.frames(recorder.strategies().front());

  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::duration d) {
    return std::chrono::duration<double, std::milli>(d).count();
  };
  FrameRenderer renderer(p.scene, style);
  std::vector<double> render_ms;
  std::vector<double> write_ms;
  // Frames go one at a time (a long run has thousands, more than can wait as open temporary files),
  // so a failure part way removes the frames this run wrote, and none of a failed output remains.
  std::vector<std::string> written;
  try {
    for (const RecordedFrame& f : frames) {
      const auto t0 = Clock::now();
      const Image image = renderer.render(f.view());
      const auto t1 = Clock::now();
      written.push_back((fs::path(dir) / frame_name(f.step)).string());
      write_png(written.back(), image);
      render_ms.push_back(ms(t1 - t0));
      write_ms.push_back(ms(Clock::now() - t1));
    }
  } catch (...) {
    std::error_code ec;
    for (const std::string& path : written) fs::remove(path, ec);
    throw;
  }
  folder->keep();
  std::cout << "wrote " << frames.size() << " frames of " << strategy << " (" << style.width_px
            << "x" << style.height_px << ") to " << dir << "/";
  if (!frames.empty()) {
    std::cout << frame_name(frames.front().step) << " .. " << frame_name(frames.back().step);
  }
  char timing[128];
  std::snprintf(timing, sizeof timing,
                "\nper frame, median / max: render %.1f / %.1f ms, PNG %.1f ms\n",
                median(render_ms),
                render_ms.empty() ? 0.0 : *std::max_element(render_ms.begin(), render_ms.end()),
                median(write_ms));
  std::cout << timing;
  return 0;
}

void add_sheet_options(po::options_description& own) {
  own.add_options()("sheet", po::value<std::string>()->value_name("FILE.png"),
                    "write a contact sheet: a row per strategy, a column per chosen step (runs "
                    "the strategies in this process)")(
      "sheet-steps", po::value<std::string>()->value_name("a,b,c"),
      "the sheet's steps; default: at 10%, 20%, 25% and 35% of the run")(
      "sheet-overlays", po::value<std::string>()->default_value("cuts")->value_name("LIST"),
      "the sheet's overlays, as render's --overlays (none, or candidates, forces, central, cuts)");
}

std::optional<SheetRequest> sheet_request(const ParsedCommand& p) {
  if (!p.options.count("sheet")) {
    if (p.options.count("sheet-steps")) throw UsageError("--sheet-steps: needs --sheet FILE.png");
    if (!p.options["sheet-overlays"].defaulted()) {
      throw UsageError("--sheet-overlays: needs --sheet FILE.png");
    }
    return std::nullopt;
  }
  SheetRequest r;
  r.overlays = parse_overlays(p.options["sheet-overlays"].as<std::string>(), "--sheet-overlays");
  r.path = p.options["sheet"].as<std::string>();
  if (r.path.empty()) throw UsageError("--sheet: empty file name");
  std::error_code ec;
  const fs::path parent = fs::path(r.path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) {
    throw UsageError("--sheet " + r.path + ": folder " + parent.string() + " does not exist");
  }
  if (fs::is_directory(r.path, ec)) throw UsageError("--sheet " + r.path + ": is a folder");
  const int step_count = p.scene.step_count();
  if (!p.options.count("sheet-steps")) {
    r.steps = default_sheet_steps(step_count);
    return r;
  }
  const std::string spec = p.options["sheet-steps"].as<std::string>();
  for (const std::string& item : split_list(spec)) {
    const std::optional<int> s = to_int(item);
    if (!s || *s < 0 || *s > step_count) {
      throw UsageError("--sheet-steps " + spec + ": '" + item + "' is not a step in [0, " +
                       std::to_string(step_count) + "]");
    }
    r.steps.push_back(*s);
  }
  if (r.steps.empty() || r.steps.size() > kMaxSheetColumns) {
    throw UsageError("--sheet-steps " + spec + ": name 1 to " + std::to_string(kMaxSheetColumns) +
                     " steps");
  }
  return r;
}

void write_sheet(const SheetRequest& request, const Scene& scene, const FrameRecorder& recorder,
                 const std::vector<std::string>& strategies, std::ostream& out) {
  SheetStyle style;
  style.overlays = request.overlays;
  const Image sheet = contact_sheet(scene, recorder, strategies, request.steps, style);
  write_png(request.path, sheet);
  out << "wrote " << request.path << " (" << strategies.size() << " strategies x "
      << request.steps.size() << " steps, " << sheet.width() << "x" << sheet.height() << ")\n";
}

}  // namespace fragsim::cli
