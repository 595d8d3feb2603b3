#include "sim/camera_track_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "io/input_file.hpp"
#include "io/number_format.hpp"
#include "io/trim.hpp"
#include "io/visible_text.hpp"

namespace fragsim {
namespace {

constexpr std::array<const char*, 10> kColumns{"t_s",       "eye_x_m",   "eye_y_m",   "eye_z_m",
                                               "forward_x", "forward_y", "forward_z", "up_x",
                                               "up_y",      "up_z"};
// A basis this far from orthonormal is a broken file, not rounding (camera.csv's shortest
// round-trip numbers are exact to the last bit).
constexpr double kBasisTolerance = 1e-6;

// One line's cells as RFC 4180 reads them. A cell in double quotes (spreadsheets and pandas quote
// every cell) may hold commas, and "" in it stands for one quote. Spaces around a cell are dropped.
// Nothing for a quote left open, or text after a closing quote.
std::optional<std::vector<std::string>> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t at = 0;
  for (;;) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    std::string cell;
    if (at < line.size() && line[at] == '"') {
      for (++at;; ++at) {
        if (at == line.size()) return std::nullopt;
        if (line[at] != '"') {
          cell += line[at];
        } else if (at + 1 < line.size() && line[at + 1] == '"') {
          cell += '"';
          ++at;
        } else {
          ++at;
          break;
        }
      }
      while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) ++at;
      if (at < line.size() && line[at] != ',') return std::nullopt;
    } else {
      const std::size_t end = std::min(line.find(',', at), line.size());
      cell = trim(line.substr(at, end - at));
      at = end;
    }
    cells.push_back(cell);
    if (at == line.size()) return cells;
    ++at;  // the comma
  }
}

// What a track in other units or axes looks like when read as fragsim's own, and the key that reads
// it right, for a speed about 10, 100 or 1000 times the bound (decimetres, centimetres as Unreal
// writes, millimetres), or up vectors along the file's z. Empty when neither fits.
std::string frame_hint(double speed_mps, double max_speed_mps, const Eigen::Vector3d& file_up,
                       const AxisConvention& frame) {
  std::string hint;
  if (frame.unit_m == 1.0 && max_speed_mps > 0.0) {
    const double ratio = speed_mps / max_speed_mps;
    for (const auto& [times, unit] :
         {std::pair{1000.0, "0.001 (millimetres)"}, std::pair{100.0, "0.01 (centimetres)"},
          std::pair{10.0, "0.1 (decimetres)"}}) {
      if (ratio > 0.3 * times && ratio < 3.0 * times) {
        hint = "; about " + format_double(times) + " times the bound: a track in other units " +
               "needs camera.track_unit_m = " + unit;
        break;
      }
    }
  }
  if (frame.up == UpAxis::kY && std::abs(file_up.z()) > 0.9) {
    hint +=
        "; its up vectors point along z: a Z-up track (Unreal, Blender) needs "
        "camera.track_up = z";
  }
  return hint;
}

std::string expected_header() {
  std::string out;
  for (const char* c : kColumns) out += (out.empty() ? "" : ",") + std::string(c);
  return out;
}

std::optional<double> number(const std::string& s) {
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

}  // namespace

CameraTrackReading track_reading(const CameraDef& camera) {
  return {camera.track_strategy, camera.max_speed_mps, camera.track_time, camera.track_frame()};
}

std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const CameraTrackReading& reading) {
  const std::string& strategy = reading.strategy;
  const double max_speed_mps = reading.max_speed_mps;
  std::istringstream in(text);
  std::string line;
  int number_of_line = 0;
  auto fail = [&](const std::string& why) {
    throw InputError(origin + ":" + std::to_string(number_of_line) + ": " + why);
  };

  // The header is the first non-empty line.
  std::vector<std::string> header;
  std::string header_line;
  while (header.empty() && std::getline(in, line)) {
    ++number_of_line;
    if (!trim(line).empty()) {
      header_line = trim(line);
      // A header that is not RFC 4180 (names quoted and split on ';', as some locales' spreadsheets
      // write) reads as one odd name, which the missing column's message shows.
      header = split(line).value_or(std::vector<std::string>{header_line});
    }
  }
  if (header.empty()) throw InputError(origin + ": empty camera track (expected a header row)");
  std::array<std::size_t, kColumns.size()> column{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) {
    std::size_t found = header.size();
    for (std::size_t h = 0; h < header.size(); ++h) {
      if (header[h] == kColumns[c]) found = h;
    }
    if (found == header.size()) {
      // A header split on ';' or quoted another way reads as one odd name, so show what was read.
      fail(std::string("missing column '") + kColumns[c] + "'; the header read was: " +
           visible_text(header_line) + "; expected comma-separated names: " + expected_header());
    }
    column[c] = found;
  }
  std::optional<std::size_t> strategy_column;
  for (std::size_t h = 0; h < header.size(); ++h) {
    if (header[h] == "strategy") strategy_column = h;
  }
  if (!strategy.empty() && !strategy_column) {
    fail("camera.track_strategy = '" + strategy + "' but the file has no 'strategy' column");
  }

  std::vector<CameraSample> samples;
  std::optional<double> first_t_s;
  std::string wanted = strategy;
  while (std::getline(in, line)) {
    ++number_of_line;
    if (trim(line).empty()) continue;
    const auto split_cells = split(line);
    if (!split_cells) fail("a quoted cell is not closed, or has text after its closing quote");
    const std::vector<std::string>& cells = *split_cells;
    if (cells.size() != header.size()) {
      fail(std::to_string(cells.size()) + " cells, the header has " +
           std::to_string(header.size()));
    }
    if (strategy_column) {
      const std::string& s = cells[*strategy_column];
      if (wanted.empty()) wanted = s;
      if (s != wanted) continue;
    }
    std::array<double, kColumns.size()> v{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const std::optional<double> x = number(cells[column[c]]);
      if (!x) {
        fail(std::string(kColumns[c]) + " = '" + visible_text(cells[column[c]]) +
             "': not a finite number");
      }
      v[c] = *x;
    }
    CameraSample s;
    if (!first_t_s) first_t_s = v[0];
    s.t_s = reading.time == TrackTime::kFromFirstSample ? v[0] - *first_t_s : v[0];
    s.eye_m = {v[1], v[2], v[3]};
    s.forward = {v[4], v[5], v[6]};
    s.up = {v[7], v[8], v[9]};
    // Fragsim's own files (the default) are taken bit for bit.
    if (!reading.frame.is_identity()) {
      s.eye_m = position_to_fragsim(reading.frame, s.eye_m);
      s.forward = direction_to_fragsim(reading.frame, s.forward);
      s.up = direction_to_fragsim(reading.frame, s.up);
    }
    if (std::abs(s.forward.norm() - 1.0) > kBasisTolerance ||
        std::abs(s.up.norm() - 1.0) > kBasisTolerance ||
        std::abs(s.forward.dot(s.up)) > kBasisTolerance) {
      fail("forward and up are not unit and orthogonal to 1e-6 (|forward| = " +
           format_double(s.forward.norm()) + ", |up| = " + format_double(s.up.norm()) +
           ", forward.up = " + format_double(s.forward.dot(s.up)) + ")");
    }
    if (!samples.empty()) {
      const CameraSample& prev = samples.back();
      if (!(s.t_s > prev.t_s)) {
        fail("t_s = " + format_double(s.t_s) + ": time must increase strictly (previous " +
             format_double(prev.t_s) + ")");
      }
      const double speed_mps = (s.eye_m - prev.eye_m).norm() / (s.t_s - prev.t_s);
      // A replayed path run moves at exactly its speed, up to the last bit of the samples.
      if (speed_mps > max_speed_mps * (1.0 + 1e-9) + 1e-12) {
        fail(
            "speed " + format_double(speed_mps) + " m/s between t = " + format_double(prev.t_s) +
            " s and t = " + format_double(s.t_s) +
            " s is above camera.max_speed_mps = " + format_double(max_speed_mps) +
            frame_hint(speed_mps, max_speed_mps, Eigen::Vector3d(v[7], v[8], v[9]), reading.frame));
      }
    }
    samples.push_back(s);
  }
  if (samples.empty()) {
    throw InputError(
        origin + ": no samples" +
        (strategy_column ? " for strategy '" + visible_text(wanted) + "'" : std::string()));
  }
  return samples;
}

std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const std::string& strategy, double max_speed_mps) {
  CameraTrackReading reading;
  reading.strategy = strategy;
  reading.max_speed_mps = max_speed_mps;
  return parse_camera_track(text, origin, reading);
}

std::vector<CameraSample> load_camera_track(const std::string& path,
                                            const CameraTrackReading& reading) {
  return parse_camera_track(read_text_file(path, "camera track"), path, reading);
}

std::vector<CameraSample> load_camera_track(const std::string& path, const std::string& strategy,
                                            double max_speed_mps) {
  CameraTrackReading reading;
  reading.strategy = strategy;
  reading.max_speed_mps = max_speed_mps;
  return load_camera_track(path, reading);
}

std::optional<std::string> track_coverage_warning(const std::vector<CameraSample>& samples,
                                                  double run_end_s, TrackTime time,
                                                  const std::string& name) {
  if (samples.empty()) return std::nullopt;
  const double first = samples.front().t_s;
  const double last = samples.back().t_s;
  // camera.csv's times are the run's own k dt_s; the slack only forgives the last bit of an
  // engine's rounding.
  const double slack_s = 1e-9 * std::max(1.0, run_end_s);
  const bool starts = first <= slack_s;
  const bool reaches = last >= run_end_s - slack_s;
  if (starts && reaches) return std::nullopt;

  const std::string track = name.empty() ? "the camera track" : "camera track " + name;
  std::string covers = samples.size() == 1 ? "has one sample (t = " + format_double(first) + " s)"
                                           : "covers t = " + format_double(first) + " to " +
                                                 format_double(last) + " s";
  std::string still;
  if (samples.size() == 1 || last <= 0.0 || first >= run_end_s) {
    still = "for the whole run";
  } else if (!starts && !reaches) {
    still =
        "until t = " + format_double(first) + " s and from t = " + format_double(last) + " s on";
  } else if (!starts) {
    still = "until t = " + format_double(first) + " s";
  } else {
    still = "from t = " + format_double(last) + " s on";
  }
  std::string out = track + " " + covers + ", the run needs t = 0 to " + format_double(run_end_s) +
                    " s: the camera stands still " + still;
  const auto overlap = [&](double a, double b) {
    return std::max(0.0, std::min(b, run_end_s) - std::max(a, 0.0));
  };
  if (time == TrackTime::kAsRecorded &&
      overlap(0.0, last - first) > overlap(first, last) + slack_s) {
    out +=
        " (times are read as recorded, t = 0 the blast; camera.track_time = from_first_sample "
        "starts the track at t = 0)";
  }
  return out;
}

std::optional<std::string> track_coverage_warning(const Scene& scene) {
  if (scene.camera.mode != CameraMode::kTrack) return std::nullopt;
  return track_coverage_warning(scene.camera.track_samples, scene.step_count() * scene.sim.dt_s,
                                scene.camera.track_time, scene.camera.track_file);
}

}  // namespace fragsim
