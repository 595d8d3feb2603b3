#pragma once
// The comparison's results table, built once from the runs and rendered three ways, for the
// terminal (aligned text with its legend, notes and verdict), the HTML page and CSV. Each column
// carries its header, unit, legend and formatter, and the terminal and the page both print the
// cells built here (formatted by io/number_format.hpp), so they cannot differ on one value.
//
// The table is the reader's view (rounded, units in the headers); summary.csv
// (metrics/run_summary.hpp's field table) stays the exact, complete record of a run.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// What follows a column's legend entry. The terminal legend groups related entries with commas,
// separates groups with semicolons and breaks its lines after some groups.
enum class LegendBreak { comma, semicolon, line };

// Every member has a default, so each column names only what it has (designated initializers).
struct ResultsColumn {
  std::string header{};       // "dev_mean"
  std::string unit{};         // "m", "%", "N s"; empty for counts and names
  std::string parts{};        // for a cell of several counts, what each is ("T/B/L/R/N/S")
  std::string explanation{};  // what it counts, in a sentence (the page's tooltip)
  std::string legend_key{};   // the legend's name for it ("dev" for the three deviation columns)
  std::string legend{};       // empty if the column has no legend entry of its own
  LegendBreak legend_break = LegendBreak::semicolon;
  bool timing = false;  // wall-clock, differs between runs, so never on the page or in table.csv
  // If false, on the page and in table.csv only, a detail the terminal's width has no room for
  // (its tooltip explains it; it has no legend entry).
  bool terminal = true;
  std::function<std::string(const Evaluation&)> cell{};
};

// The one-line header the terminal and CSV print, the unit joined by '_' without its spaces
// ("dev_mean_m", "impulse_Ns"), the parts after a space ("exits T/B/L/R/N/S").
std::string column_title(const ResultsColumn& column);

// A remark below the table, about one run (strategy-specific numbers, warnings) or all of them.
struct ResultsNote {
  std::string text;  // no final full stop, as the page adds its own punctuation
  bool timing = false;
};

struct ResultsTable {
  std::string scene_name;
  std::string caption;  // "1728 fragments, 180 steps of 0.01667 s, seed 1, ODE 0.16.2"
  // About the scene, under the caption (a camera track that does not cover the run).
  std::vector<std::string> warnings;
  std::vector<ResultsColumn> columns;
  std::vector<std::vector<std::string>> rows;  // a row per run, a cell per column
  std::optional<std::size_t> best_row;         // met the thesis's goals with the least deviation
  std::vector<ResultsNote> notes;
  std::string verdict;  // the best for the thesis's goals in a line; empty if only none ran
};

// The columns in the order every rendering shows them; `near_miss_m` is the scene's near-miss
// distance, which the legend states.
std::vector<ResultsColumn> results_columns(double near_miss_m);

// Notes come from the runs' numbers, never from strategy names. A run that pulled the near plane
// in gets the depth-resolution note, a run with wall contacts gets their count, whatever its
// strategy is called.
ResultsTable results_table(const Scene& scene, const std::vector<Evaluation>& runs);

// The terminal's report has "scene NAME: caption", a "warning: " line per warning, the aligned
// table, the legend, the notes and the verdict.
std::string results_text(const ResultsTable& table);

// The legend as one text, entries in column order; lines end in '\n' (else joined by spaces)
// and the last entry in a full stop. Names in backquotes (`none`) are the page's code spans.
std::string legend_text(const ResultsTable& table, bool timings, bool line_breaks);

// The page's table (no timing columns), the best row highlighted, each header's unit on a second
// line under it and its explanation as a tooltip; and the legend as HTML.
std::string results_html(const ResultsTable& table);
std::string legend_html(const ResultsTable& table);

// The table as CSV (RFC 4180 quoting where needed), with or without the timing columns.
std::string results_csv(const ResultsTable& table, bool timings);

}  // namespace fragsim
