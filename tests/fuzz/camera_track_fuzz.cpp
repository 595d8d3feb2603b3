// libFuzzer target: the bytes are a camera track file's text for parse_camera_track.
//
// Invariants, each a __builtin_trap() when broken:
//  - bad input throws InputError and nothing else;
//  - an accepted track is what the parser promises: at least one sample, every number finite,
//    time strictly increasing, forward and up unit and orthogonal to 1e-6, no speed between two
//    samples above camera.max_speed_mps (with the parser's own rounding allowance);
//  - written back as camera.csv's columns in shortest round-trip numbers, it reads back to the
//    same samples bit for bit.
// The first byte picks the strategy filter and V_c, so both the filtered and unfiltered paths and
// tight and loose speed limits are reached; the rest is the file.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "sim/camera_track_file.hpp"

namespace {

constexpr double kMaxSpeedsMps[4] = {0.0, 1.0, 300.0, 1e300};

bool finite(const Eigen::Vector3d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

std::vector<fragsim::CameraSample> parse_or_trap(const std::string& text,
                                                 const std::string& strategy, double vc, bool* ok) {
  *ok = false;
  try {
    std::vector<fragsim::CameraSample> s =
        fragsim::parse_camera_track(text, "fuzz.csv", strategy, vc);
    *ok = true;
    return s;
  } catch (const fragsim::InputError&) {
    return {};
  } catch (...) {
    __builtin_trap();  // only InputError may leave the parser on bad input
  }
}

std::string csv_of(const std::vector<fragsim::CameraSample>& samples) {
  std::string out = "t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z\n";
  for (const fragsim::CameraSample& s : samples) {
    const double v[10] = {s.t_s,         s.eye_m.x(),   s.eye_m.y(), s.eye_m.z(), s.forward.x(),
                          s.forward.y(), s.forward.z(), s.up.x(),    s.up.y(),    s.up.z()};
    for (int i = 0; i < 10; ++i) out += (i ? "," : "") + fragsim::format_double(v[i]);
    out += '\n';
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t mode = data[0];
  const double vc = kMaxSpeedsMps[mode & 3];
  const std::string strategy = (mode & 4) ? "edge" : "";
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  bool ok = false;
  const std::vector<fragsim::CameraSample> track = parse_or_trap(text, strategy, vc, &ok);
  if (!ok) return 0;
  if (track.empty()) __builtin_trap();
  for (std::size_t i = 0; i < track.size(); ++i) {
    const fragsim::CameraSample& s = track[i];
    if (!std::isfinite(s.t_s) || !finite(s.eye_m) || !finite(s.forward) || !finite(s.up)) {
      __builtin_trap();
    }
    if (std::abs(s.forward.norm() - 1.0) > 1e-6 || std::abs(s.up.norm() - 1.0) > 1e-6 ||
        std::abs(s.forward.dot(s.up)) > 1e-6) {
      __builtin_trap();
    }
    if (i > 0) {
      const fragsim::CameraSample& p = track[i - 1];
      if (!(s.t_s > p.t_s)) __builtin_trap();
      const double speed = (s.eye_m - p.eye_m).norm() / (s.t_s - p.t_s);
      if (!(speed <= vc * (1.0 + 1e-9) + 1e-12)) __builtin_trap();
    }
  }
  // Unfiltered on the way back: the written file has no strategy column.
  const std::vector<fragsim::CameraSample> back = parse_or_trap(csv_of(track), "", vc, &ok);
  if (!ok || back.size() != track.size()) __builtin_trap();
  for (std::size_t i = 0; i < track.size(); ++i) {
    const fragsim::CameraSample &a = track[i], &b = back[i];
    if (a.t_s != b.t_s || a.eye_m != b.eye_m || a.forward != b.forward || a.up != b.up) {
      __builtin_trap();
    }
  }
  return 0;
}
