#include "report/csv_export.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/input_file.hpp"
#include "io/number_format.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// Appends each part in turn (also sidesteps GCC 12's false -Wrestrict on string operator+).
template <typename... Parts>
void append(std::string& out, const Parts&... parts) {
  (out.append(parts), ...);
}

void append_vec(std::string& out, const Eigen::Vector3d& v) {
  for (int k = 0; k < 3; ++k) {
    out += ',';
    append_double(out, v[k]);
  }
}

}  // namespace

std::string summary_csv(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::string out;
  for (const SummaryField& c : summary_field_table()) append(out, c.name, ",");
  out += "z_fighting,ode_version\n";
  for (const Evaluation& e : runs) {
    for (const std::string& f : summary_fields(e.summary)) append(out, f, ",");
    out += z_fighting(e.summary, scene.strategies.near_plane.ref_distance_m) ? "1" : "0";
    append(out, ",", World::ode_version(), "\n");
  }
  return out;
}

std::vector<std::string> summary_csv_columns() {
  std::vector<std::string> out;
  for (const SummaryField& c : summary_field_table()) out.emplace_back(c.name);
  out.emplace_back("z_fighting");
  out.emplace_back("ode_version");
  return out;
}

std::vector<std::string> summary_csv_cells(const Scene& scene, const RunSummary& summary) {
  std::vector<std::string> out = summary_fields(summary);
  out.emplace_back(z_fighting(summary, scene.strategies.near_plane.ref_distance_m) ? "1" : "0");
  out.push_back(World::ode_version());
  return out;
}

std::string steps_csv(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::string out =
      "strategy,step,t_s,candidates,near_intersections,occlusion,central_occlusion,near_m\n";
  for (const Evaluation& e : runs) {
    for (std::size_t k = 0; k < e.near_per_step.size(); ++k) {
      const int step = static_cast<int>(k) + 1;
      append(out, e.summary.strategy, ",", std::to_string(step), ",");
      append_double(out, step * scene.sim.dt_s);
      append(out, ",", std::to_string(e.candidates_per_step[k]), ",",
             std::to_string(e.near_per_step[k]), ",");
      if (k < e.occlusion_per_step.size()) append_double(out, e.occlusion_per_step[k]);
      out += ",";
      if (k < e.central_occlusion_per_step.size())
        append_double(out, e.central_occlusion_per_step[k]);
      out += ",";
      append_double(out, e.camera[k + 1].near_m);
      out += "\n";
    }
  }
  return out;
}

const std::string& camera_csv_header() {
  static const std::string header =
      "strategy,step,t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z,"
      "near_m,fovy_deg,aspect\n";
  return header;
}

void append_camera_row(std::string& out, const std::string& strategy, std::size_t step, double t_s,
                       const CameraPose& pose) {
  append(out, strategy, ",", std::to_string(step), ",");
  append_double(out, t_s);
  append_vec(out, pose.eye_m);
  append_vec(out, pose.forward);
  append_vec(out, pose.up);
  for (double v : {pose.near_m, pose.fovy_deg, pose.aspect}) {
    out += ',';
    append_double(out, v);
  }
  out += "\n";
}

std::string camera_csv(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::string out = camera_csv_header();
  for (const Evaluation& e : runs) {
    for (std::size_t k = 0; k < e.camera.size(); ++k) {
      append_camera_row(out, e.summary.strategy, k, static_cast<double>(k) * scene.sim.dt_s,
                        e.camera[k]);
    }
  }
  return out;
}

std::string timing_csv(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::string out = "strategy,step,t_s,physics_ms,strategy_ms\n";
  for (const Evaluation& e : runs) {
    for (std::size_t k = 0; k < e.physics_s_per_step.size(); ++k) {
      append(out, e.summary.strategy, ",", std::to_string(k + 1), ",");
      append_double(out, static_cast<double>(k + 1) * scene.sim.dt_s);
      out += ",";
      append_double(out, 1e3 * e.physics_s_per_step[k]);
      out += ",";
      append_double(out, 1e3 * e.strategy_s_per_step[k]);
      out += "\n";
    }
  }
  return out;
}

void add_comparison_csv(OutputSet& files, const std::string& dir, const Scene& scene,
                        const std::vector<Evaluation>& runs) {
  const fs::path d(dir);
  files.add((d / "summary.csv").string(), summary_csv(scene, runs));
  files.add((d / "steps.csv").string(), steps_csv(scene, runs));
  files.add((d / "camera.csv").string(), camera_csv(scene, runs));
  files.add((d / "timing.csv").string(), timing_csv(scene, runs));
  files.add((d / "config.ini").string(), scene_to_ini(scene));
}

std::vector<RunSummary> read_summary_csv(const std::string& path) {
  std::istringstream in(read_text_file(path, "summary file"));
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ":1: empty file");
  const std::vector<std::string> header = split(line);
  const auto& cols = summary_field_table();
  if (header.size() < cols.size()) throw std::runtime_error(path + ":1: too few columns");
  for (std::size_t i = 0; i < cols.size(); ++i) {
    if (header[i] != cols[i].name) {
      throw std::runtime_error(path + ":1: column " + std::to_string(i + 1) + " is '" + header[i] +
                               "', expected '" + cols[i].name + "'");
    }
  }
  std::vector<RunSummary> out;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != header.size()) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected " +
                               std::to_string(header.size()) + " cells");
    }
    RunSummary s;
    try {
      set_summary_fields(s,
                         {cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(cols.size())});
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": unreadable number");
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace fragsim
