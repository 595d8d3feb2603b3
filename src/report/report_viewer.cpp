#include "report/report_viewer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "io/number_format.hpp"
#include "report/html_escape.hpp"

namespace fragsim {
namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned(bytes[i]) << 16) | (unsigned(bytes[i + 1]) << 8) | bytes[i + 2];
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = (unsigned(bytes[i]) << 16) | (two ? unsigned(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += two ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string base64(std::string_view text) {
  return base64(std::vector<std::uint8_t>(text.begin(), text.end()));
}

// Little-endian whatever the host, as the page reads them with a DataView-free Int16Array and
// every browser that runs WebGL is little-endian.
void append_int16(std::vector<std::uint8_t>& out, const std::vector<std::int16_t>& values) {
  for (const std::int16_t v : values) {
    const auto u = static_cast<std::uint16_t>(v);
    out.push_back(static_cast<std::uint8_t>(u & 0xff));
    out.push_back(static_cast<std::uint8_t>(u >> 8));
  }
}

std::int16_t quantise_unit(double v) {
  return static_cast<std::int16_t>(std::lround(std::clamp(v, -1.0, 1.0) * 32767.0));
}

std::string num(double v, int decimals) {
  std::string s = fixed_text(v, decimals);
  // "-0.000" and "0.000" are one value; write it one way so equal scenes give equal pages.
  if (s.find_first_not_of("-0.") == std::string::npos) s = "0";
  return s;
}

template <typename T, typename F>
std::string json_list(const std::vector<T>& items, F write) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ",";
    out += write(items[i]);
  }
  return out + "]";
}

std::string vec3(const Eigen::Vector3d& v, int decimals) {
  return "[" + num(v.x(), decimals) + "," + num(v.y(), decimals) + "," + num(v.z(), decimals) + "]";
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '<') {
      out += "\\u003c";  // never "</script>" inside the data block
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string run_json(const ViewerRun& r, const Scene& scene) {
  std::vector<std::uint8_t> bytes;
  append_int16(bytes, r.position_q);
  append_int16(bytes, r.rotation_q);
  bytes.insert(bytes.end(), r.flags.begin(), r.flags.end());
  std::string j = "{\"strategy\":" + quoted(r.strategy);
  j += ",\"t_s\":" + json_list(r.steps, [&](int s) { return num(s * scene.sim.dt_s, 4); });
  j +=
      ",\"lo_m\":" + vec3(r.lo_m.cast<double>(), 6) + ",\"hi_m\":" + vec3(r.hi_m.cast<double>(), 6);
  j += ",\"camera\":" + json_list(r.cameras, [](const CameraPose& c) {
         const std::array<float, 4> q = camera_quaternion_xyzw(c);
         return "[" + num(c.eye_m.x(), 5) + "," + num(c.eye_m.y(), 5) + "," + num(c.eye_m.z(), 5) +
                "," + num(q[0], 6) + "," + num(q[1], 6) + "," + num(q[2], 6) + "," + num(q[3], 6) +
                "," + num(c.near_m, 5) + "]";
       });
  j += ",\"poses\":\"" + base64(bytes) + "\"}";
  return j;
}

std::string mesh_json(const BakeMesh& m) {
  std::string j = "{\"v\":[";
  for (std::size_t i = 0; i < m.vertices_m.size(); ++i) {
    if (i > 0) j += ",";
    for (int k = 0; k < 3; ++k) j += (k > 0 ? "," : "") + num(m.vertices_m[i][k], 5);
  }
  j += "],\"t\":[";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    j += (i > 0 ? "," : "") + std::to_string(m.triangles[i]);
  }
  return j + "]}";
}

}  // namespace

int viewer_sample_every(int piece_count, int step_count, int strategy_count) {
  const double per_sample =
      kViewerPieceSample_bytes * std::max(piece_count, 1) * std::max(strategy_count, 1);
  const int steps = std::max(step_count, 1);
  for (int every = 1; every < steps; ++every) {
    // Steps 0, every, 2 every, ... and the last.
    const int samples = steps / every + 1 + (steps % every != 0 ? 1 : 0);
    if (samples * per_sample <= kViewerBudget_bytes) return every;
  }
  return steps;
}

ViewerRecorder::ViewerRecorder(int every) : every_(std::max(every, 1)) {}

void ViewerRecorder::begin(const RunInfo& info, const StepSnapshot& initial) {
  near_.begin(info, initial);
  step_count_ = info.step_count;
  const std::size_t n = initial.fragments.size();
  if (runs_.empty()) {
    // The pieces are the same in every run (same scene, same seed), so each shape's mesh is shared.
    std::map<std::tuple<const ConvexShape*, double, double, double>, int> seen;
    for (const FragmentState& f : initial.fragments) {
      const auto key = std::make_tuple(f.shape, f.shape ? 0.0 : f.half_extents_m.x(),
                                       f.shape ? 0.0 : f.half_extents_m.y(),
                                       f.shape ? 0.0 : f.half_extents_m.z());
      auto [it, added] = seen.try_emplace(key, static_cast<int>(meshes_.size()));
      if (added) meshes_.push_back(bake_mesh(f.shape, f.half_extents_m));
      piece_mesh_.push_back(it->second);
    }
  } else if (piece_mesh_.size() != n) {
    throw std::runtime_error("report viewer: runs of different piece counts");
  }
  run_ = ViewerRun{};
  run_.strategy = info.strategy;
  pending_.assign(n, 0);
  positions_m_.clear();
  rotations_.clear();
  sample(initial);
}

void ViewerRecorder::observe(const StepSnapshot& snap) {
  near_.observe(snap);
  for (const AppliedForce& f : snap.forces) {
    if (f.force_N.squaredNorm() > 0)
      pending_[static_cast<std::size_t>(f.fragment)] |= kViewerPushed;
  }
  for (const int f : near_.last_step_fragments()) {
    pending_[static_cast<std::size_t>(f)] |= kViewerNearHit;
  }
  if (snap.step % every_ == 0 || snap.step == step_count_) sample(snap);
}

void ViewerRecorder::sample(const StepSnapshot& snap) {
  run_.steps.push_back(snap.step);
  run_.cameras.push_back(snap.camera);
  for (const FragmentState& f : snap.fragments) {
    for (int k = 0; k < 3; ++k) positions_m_.push_back(static_cast<float>(f.position_m[k]));
    const std::array<float, 4> q = quaternion_xyzw(f.rotation);
    rotations_.insert(rotations_.end(), q.begin(), q.end());
  }
  run_.flags.insert(run_.flags.end(), pending_.begin(), pending_.end());
  std::fill(pending_.begin(), pending_.end(), std::uint8_t{0});
}

void ViewerRecorder::end() {
  if (!positions_m_.empty()) {
    run_.lo_m = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
    run_.hi_m = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < positions_m_.size(); ++i) {
      const int k = static_cast<int>(i % 3);
      run_.lo_m[k] = std::min(run_.lo_m[k], positions_m_[i]);
      run_.hi_m[k] = std::max(run_.hi_m[k], positions_m_[i]);
    }
  }
  run_.position_q.reserve(positions_m_.size());
  for (std::size_t i = 0; i < positions_m_.size(); ++i) {
    const int k = static_cast<int>(i % 3);
    const double span = std::max(double(run_.hi_m[k]) - run_.lo_m[k], 1e-9);
    const double u = (double(positions_m_[i]) - run_.lo_m[k]) / span;  // 0..1
    run_.position_q.push_back(quantise_unit(2.0 * u - 1.0));
  }
  run_.rotation_q.reserve(rotations_.size());
  for (const float c : rotations_) run_.rotation_q.push_back(quantise_unit(c));
  positions_m_ = {};
  rotations_ = {};
  runs_.push_back(std::move(run_));
  run_ = ViewerRun{};
}

std::string viewer_missing_text(const BundledThreeJs& three) {
  return "No 3D view in this report: this fragsim was built without three.js (" +
         std::string(three.missing) +
         "). To get it: run scripts/install_three.sh (it installs node's npm package three at "
         "the pinned version into build/npm; scripts/setup.sh runs it), keep FRAGSIM_THREE_JS on "
         "(the default), then reconfigure and rebuild.";
}

std::string viewer_section_html(const Scene& scene, const ViewerRecorder& recorder,
                                const std::string& left, const std::string& right,
                                const BundledThreeJs& three) {
  std::string h = "<section id=\"viewer-section\">\n<h2>3D view</h2>\n";
  if (!three.available() || recorder.runs().empty()) {
    const std::string why = three.available() ? "No 3D view in this report: no run was recorded."
                                              : viewer_missing_text(three);
    return h + "<p class=\"notes\" id=\"viewer-missing\">" + html_escape(why) +
           "</p>\n</section>\n";
  }
  const auto select = [&](const std::string& id, const std::string& chosen, bool optional) {
    std::string s = "<select id=\"" + id + "\">";
    if (optional)
      s += std::string("<option value=\"\"") + (chosen.empty() ? " selected" : "") +
           ">(one view)</option>";
    for (const ViewerRun& r : recorder.runs()) {
      s += "<option value=\"" + html_escape(r.strategy) + "\"" +
           (r.strategy == chosen ? " selected" : "") + ">" + html_escape(r.strategy) + "</option>";
    }
    return s + "</select>";
  };
  const int every = recorder.every();
  h += "<p class=\"notes\">Each strategy's run in three dimensions, at the same time side by side. "
       "Grey: a piece; orange: pushed by the strategy since the previous frame; red: cut by the "
       "near plane since the previous frame (the table's near-plane intersections). Camera view "
       "looks through the run's camera (its field of view, aspect and near distance at that "
       "time); orbit view shows the camera's frustum as lines, the near rectangle in red: drag to "
       "turn, wheel to zoom. ";
  h += every == 1 ? std::string("Every step is shown.")
                  : "One step in " + std::to_string(every) +
                        " is shown (and the last), to keep the page small.";
  h += "</p>\n<div class=\"viewer-controls\">\n";
  h += "<button type=\"button\" id=\"viewer-play\">Play</button>\n";
  h += "<input type=\"range\" id=\"viewer-time\" min=\"0\" max=\"" +
       std::to_string(recorder.runs().front().steps.size() - 1) +
       "\" value=\"0\" aria-label=\"time\">\n<span id=\"viewer-clock\">t = 0.00 s</span>\n";
  h += "<label>left " + select("viewer-left", left, false) + "</label>\n";
  h += "<label>right " + select("viewer-right", right, true) + "</label>\n";
  h += "<label>view <select id=\"viewer-mode\"><option value=\"orbit\" selected>orbit</option>"
       "<option value=\"camera\">camera</option></select></label>\n</div>\n";
  h += "<div id=\"viewer\" data-state=\"loading\"><canvas id=\"viewer-canvas\" width=\"1200\" "
       "height=\"520\"></canvas></div>\n";
  h += "<p class=\"notes\" id=\"viewer-status\">Loading the 3D view&hellip;</p>\n";

  // The data the script reads is JSON (numbers written fixed, so the page is the same bytes for the
  // same runs) with each run's quantised poses as base64.
  std::string data = "{\"scene\":" + quoted(scene.name);
  data += ",\"every\":" + std::to_string(every);
  data += ",\"ground\":" + std::string(scene.ground.enabled ? "true" : "false");
  data += ",\"ground_height_m\":" + num(scene.ground.height_m, 5);
  const CameraPose& c0 = recorder.runs().front().cameras.front();
  data += ",\"fovy_deg\":" + num(c0.fovy_deg, 5) + ",\"aspect\":" + num(c0.aspect, 6) +
          ",\"far_m\":" + num(c0.far_m, 5);
  data += ",\"meshes\":" + json_list(recorder.meshes(), mesh_json);
  data += ",\"piece_mesh\":" +
          json_list(recorder.piece_mesh(), [](int m) { return std::to_string(m); });
  data += ",\"runs\":" +
          json_list(recorder.runs(), [&](const ViewerRun& r) { return run_json(r, scene); });
  data += "}";
  h += "<script type=\"application/json\" id=\"viewer-data\">" + data + "</script>\n";
  // Chromium refuses module scripts from file:// URLs (the page opens from disk), but imports a
  // `data:` URL, so three.js travels in the page as base64 and is imported from there.
  h += "<script type=\"text/plain\" id=\"three-module\">" + base64(three.module_js) + "</script>\n";
  h += "<script type=\"module\">\n" + std::string(report_viewer_js()) + "</script>\n";
  h += "<details class=\"notes\"><summary>three.js " + html_escape(std::string(three.version)) +
       " (draws the 3D view), MIT licence</summary><pre>" +
       html_escape(std::string(three.licence)) + "</pre></details>\n";
  return h + "</section>\n";
}

}  // namespace fragsim
