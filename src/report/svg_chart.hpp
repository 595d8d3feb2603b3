#pragma once
// A line chart as inline SVG text for the HTML report: one line per series over a shared x, axes
// with ticks at 1-2-5 steps and labels, and a legend on the right. Numbers are written with
// std::to_chars, so the same data gives the same bytes on every platform (the report is compared
// byte for byte).

#include <string>
#include <vector>

namespace fragsim {

struct ChartSeries {
  std::string name;       // the legend's label
  std::vector<double> y;  // one value per x; a non-finite value breaks the line
};

struct LineChart {
  std::string title;
  std::string x_label;    // with its unit, "t (s)"
  std::string y_label;    // with its unit, "screen covered (%)"
  std::vector<double> x;  // shared by every series, increasing
  std::vector<ChartSeries> series;
};

// The SVG's size and the margins around the plot area (the legend sits in the right margin).
// The SVG scales to its container; these fix its proportions and its text size.
struct ChartStyle {
  int width_px = 600;
  int height_px = 300;
  int margin_left_px = 64;
  int margin_right_px = 120;
  int margin_top_px = 34;
  int margin_bottom_px = 46;
};

// An axis range with ticks at multiples of `step` (1, 2 or 5 times a power of ten), covering
// [lo, hi] with at most about `max_ticks` intervals.
struct ChartAxis {
  double lo = 0.0;
  double hi = 1.0;
  double step = 0.2;
};
ChartAxis nice_axis(double lo, double hi, int max_ticks = 6);

// The plot area in SVG pixels (y grows downward) and the map from data to it.
struct ChartFrame {
  double left_px = 0.0;
  double top_px = 0.0;
  double right_px = 0.0;
  double bottom_px = 0.0;
  ChartAxis x;
  ChartAxis y;

  double x_px(double v) const {
    return left_px + (v - x.lo) / (x.hi - x.lo) * (right_px - left_px);
  }
  double y_px(double v) const {
    return bottom_px - (v - y.lo) / (y.hi - y.lo) * (bottom_px - top_px);
  }
};
// The axes span the data and zero (counts and shares read from a zero baseline).
ChartFrame chart_frame(const LineChart& chart, const ChartStyle& style = {});

// The series' line colour by index (a colour-blind-safe palette, repeating after 8).
std::string series_colour(std::size_t index);

// The chart as one <svg> element.
std::string svg_line_chart(const LineChart& chart, const ChartStyle& style = {});

}  // namespace fragsim
