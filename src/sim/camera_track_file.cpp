#include "sim/camera_track_file.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

#include "io/input_file.hpp"
#include "io/number_format.hpp"

namespace fragsim {
namespace {

constexpr std::array<const char*, 10> kColumns{"t_s",       "eye_x_m",   "eye_y_m",   "eye_z_m",
                                               "forward_x", "forward_y", "forward_z", "up_x",
                                               "up_y",      "up_z"};
// A basis this far from orthonormal is a broken file, not rounding (camera.csv's shortest
// round-trip numbers are exact to the last bit).
constexpr double kBasisTolerance = 1e-6;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
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

std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const std::string& strategy, double max_speed_mps) {
  std::istringstream in(text);
  std::string line;
  int number_of_line = 0;
  auto fail = [&](const std::string& why) {
    throw InputError(origin + ":" + std::to_string(number_of_line) + ": " + why);
  };

  // The header: the first non-empty line.
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++number_of_line;
    if (!trim(line).empty()) header = split(line);
  }
  if (header.empty()) throw InputError(origin + ": empty camera track (expected a header row)");
  std::array<std::size_t, kColumns.size()> column{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) {
    std::size_t found = header.size();
    for (std::size_t h = 0; h < header.size(); ++h) {
      if (header[h] == kColumns[c]) found = h;
    }
    if (found == header.size()) fail(std::string("missing column '") + kColumns[c] + "'");
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
  std::string wanted = strategy;
  while (std::getline(in, line)) {
    ++number_of_line;
    if (trim(line).empty()) continue;
    const std::vector<std::string> cells = split(line);
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
        fail(std::string(kColumns[c]) + " = '" + cells[column[c]] + "': not a finite number");
      }
      v[c] = *x;
    }
    CameraSample s;
    s.t_s = v[0];
    s.eye_m = {v[1], v[2], v[3]};
    s.forward = {v[4], v[5], v[6]};
    s.up = {v[7], v[8], v[9]};
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
        fail("speed " + format_double(speed_mps) + " m/s between t = " + format_double(prev.t_s) +
             " s and t = " + format_double(s.t_s) +
             " s is above camera.max_speed_mps = " + format_double(max_speed_mps));
      }
    }
    samples.push_back(s);
  }
  if (samples.empty()) {
    throw InputError(origin + ": no samples" +
                     (strategy_column ? " for strategy '" + wanted + "'" : std::string()));
  }
  return samples;
}

std::vector<CameraSample> load_camera_track(const std::string& path, const std::string& strategy,
                                            double max_speed_mps) {
  return parse_camera_track(read_input_file(path, "camera track"), path, strategy, max_speed_mps);
}

}  // namespace fragsim
