#pragma once
// The comparison as files for plotting, in long ("tidy") format with units in the column names:
// summary.csv, steps.csv, camera.csv, timing.csv and config.ini (trajectories.csv is streamed by
// TrajectoryWriter). Every file but timing.csv is byte-identical for the same scene and seed.

#include <cstddef>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "experiments/evaluation.hpp"
#include "io/output_set.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// Adds the five files in `dir` to `files`, which the caller commits (all of them or none).
void add_comparison_csv(OutputSet& files, const std::string& dir, const Scene& scene,
                        const std::vector<Evaluation>& runs);

std::string summary_csv(const Scene& scene, const std::vector<Evaluation>& runs);
std::string steps_csv(const Scene& scene, const std::vector<Evaluation>& runs);
std::string camera_csv(const Scene& scene, const std::vector<Evaluation>& runs);
// camera.csv's header line, and one of its rows (`pose` at step `step`, time t_s) appended, the one
// format a recorded flight (fragsim play) and a run's camera.csv share, so either replays.
const std::string& camera_csv_header();
void append_camera_row(std::string& out, const std::string& strategy, std::size_t step, double t_s,
                       const CameraPose& pose);
std::string timing_csv(const Scene& scene, const std::vector<Evaluation>& runs);

// summary.csv's column names and one run's cells (the same text summary_csv writes), for files
// that put summary rows beside their own columns (fragsim sweep).
std::vector<std::string> summary_csv_columns();
std::vector<std::string> summary_csv_cells(const Scene& scene, const RunSummary& summary);

// Reads summary.csv back (for tests and tools); throws std::runtime_error naming file:line.
std::vector<RunSummary> read_summary_csv(const std::string& path);

}  // namespace fragsim
