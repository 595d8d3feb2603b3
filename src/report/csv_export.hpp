#pragma once
// The comparison as files for plotting, in long ("tidy") format with units in the column names:
// summary.csv, steps.csv, camera.csv, timing.csv and config.ini (trajectories.csv is streamed by
// TrajectoryWriter). Every file but timing.csv is byte-identical for the same scene and seed.

#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// Creates `dir` if needed. An existing folder with files in it is refused unless `force`
// (std::runtime_error naming the folder).
void prepare_output_dir(const std::string& dir, bool force);

// Writes the five files into `dir`, each whole or not at all.
void write_comparison_csv(const std::string& dir, const Scene& scene,
                          const std::vector<Evaluation>& runs);

std::string summary_csv(const Scene& scene, const std::vector<Evaluation>& runs);
std::string steps_csv(const Scene& scene, const std::vector<Evaluation>& runs);
std::string camera_csv(const Scene& scene, const std::vector<Evaluation>& runs);
std::string timing_csv(const Scene& scene, const std::vector<Evaluation>& runs);

// summary.csv's column names and one run's cells (the same text summary_csv writes), for files
// that put summary rows beside their own columns (fragsim sweep).
std::vector<std::string> summary_csv_columns();
std::vector<std::string> summary_csv_cells(const Scene& scene, const RunSummary& summary);

// Reads summary.csv back (for tests and tools); throws std::runtime_error naming file:line.
std::vector<RunSummary> read_summary_csv(const std::string& path);

}  // namespace fragsim
