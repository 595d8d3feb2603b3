#include "report/svg_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/number_format.hpp"
#include "report/html_escape.hpp"

namespace fragsim {
namespace {

// Okabe and Ito's palette (distinct under the common colour-vision deficiencies), black first
// for the reference run; its yellow is left out (unreadable on white).
constexpr std::array<const char*, 8> kPalette{"#000000", "#E69F00", "#56B4E9", "#009E73",
                                              "#CC79A7", "#D55E00", "#0072B2", "#999999"};
constexpr int kXTicks = 6;
constexpr int kYTicks = 5;
constexpr double kTickPx = 5.0;
constexpr double kLegendRowPx = 18.0;
constexpr double kLegendSamplePx = 22.0;
// Series are drawn in order, each thinner than the one before, so a line that lies on top of an
// earlier one (strategies that leave a metric unchanged) still shows the earlier one's colour
// along its edges.
constexpr double kThinnestPx = 1.25;
constexpr double kWidthStepPx = 0.5;

// Two decimals for pixel coordinates are far below a pixel and keep the text short.
std::string px(double v) {
  return fixed_text(v, 2);
}

// Decimals that tell ticks `step` apart (0 for 1, 2, 5, 10; 1 for 0.5; 2 for 0.02).
int tick_decimals(double step) {
  return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

double stroke_width_px(std::size_t index, std::size_t count) {
  return kThinnestPx + kWidthStepPx * static_cast<double>(count - 1 - index);
}

// The data's range in one direction, with zero included; [0, 1] when there is no data.
std::pair<double, double> span_with_zero(const LineChart& chart, bool x_axis) {
  double lo = 0.0;
  double hi = 0.0;
  const auto take = [&](double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  if (x_axis) {
    for (const double v : chart.x) take(v);
  } else {
    for (const ChartSeries& s : chart.series) {
      for (const double v : s.y) take(v);
    }
  }
  return {lo, hi};
}

// The path of one series has M at the start and after every gap, L elsewhere. Points in the middle
// of a flat run are left out (they lie on the line between its ends), which much shortens the
// long zero runs of the count series.
std::string series_path(const ChartFrame& frame, const std::vector<double>& x,
                        const std::vector<double>& y) {
  std::string d;
  const std::size_t n = std::min(x.size(), y.size());
  bool pen_down = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i]) || !std::isfinite(x[i])) {
      pen_down = false;
      continue;
    }
    const bool flat_middle = pen_down && i + 1 < n && y[i - 1] == y[i] && y[i + 1] == y[i];
    if (flat_middle) continue;
    d += pen_down ? "L" : "M";
    d += px(frame.x_px(x[i]));
    d += ",";
    d += px(frame.y_px(y[i]));
    pen_down = true;
  }
  return d;
}

}  // namespace

ChartAxis nice_axis(double lo, double hi, int max_ticks) {
  if (!(hi > lo)) hi = lo + 1.0;
  const double raw = (hi - lo) / std::max(1, max_ticks);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / magnitude;
  const double nice = f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0;
  ChartAxis a;
  a.step = nice * magnitude;
  // The tolerance keeps 0.1 / 0.02 = 5.000000000000001 from adding a needless tick.
  a.lo = std::floor(lo / a.step + 1e-9) * a.step;
  a.hi = std::ceil(hi / a.step - 1e-9) * a.step;
  return a;
}

ChartFrame chart_frame(const LineChart& chart, const ChartStyle& style) {
  ChartFrame f;
  f.left_px = style.margin_left_px;
  f.top_px = style.margin_top_px;
  f.right_px = style.width_px - style.margin_right_px;
  f.bottom_px = style.height_px - style.margin_bottom_px;
  const auto [x_lo, x_hi] = span_with_zero(chart, true);
  const auto [y_lo, y_hi] = span_with_zero(chart, false);
  f.x = nice_axis(x_lo, x_hi, kXTicks);
  f.y = nice_axis(y_lo, y_hi, kYTicks);
  return f;
}

std::string series_colour(std::size_t index) {
  return kPalette[index % kPalette.size()];
}

std::string svg_line_chart(const LineChart& chart, const ChartStyle& style) {
  const ChartFrame f = chart_frame(chart, style);
  const std::string title = html_escape(chart.title);
  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" viewBox=\"0 0 " +
       std::to_string(style.width_px) + " " + std::to_string(style.height_px) +
       "\" role=\"img\" aria-label=\"" + title +
       "\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#222\">\n";
  s += "<title>" + title + "</title>\n";
  s += "<text x=\"" + px(0.5 * (f.left_px + f.right_px)) +
       "\" y=\"20\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" + title +
       "</text>\n";

  // Grid lines and tick labels; the tick count comes from the axis, not from adding steps, so
  // rounding cannot drop the last tick.
  const auto ticks = [](const ChartAxis& a) {
    return static_cast<int>(std::lround((a.hi - a.lo) / a.step));
  };
  s += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
  for (int i = 0; i <= ticks(f.y); ++i) {
    const std::string y = px(f.y_px(f.y.lo + i * f.y.step));
    s += "<line x1=\"" + px(f.left_px) + "\" y1=\"" + y + "\" x2=\"" + px(f.right_px) + "\" y2=\"" +
         y + "\"/>\n";
  }
  s += "</g>\n";
  s += "<g stroke=\"#444\" stroke-width=\"1\">\n";
  for (int i = 0; i <= ticks(f.x); ++i) {
    const std::string x = px(f.x_px(f.x.lo + i * f.x.step));
    s += "<line x1=\"" + x + "\" y1=\"" + px(f.bottom_px) + "\" x2=\"" + x + "\" y2=\"" +
         px(f.bottom_px + kTickPx) + "\"/>\n";
  }
  for (int i = 0; i <= ticks(f.y); ++i) {
    const std::string y = px(f.y_px(f.y.lo + i * f.y.step));
    s += "<line x1=\"" + px(f.left_px - kTickPx) + "\" y1=\"" + y + "\" x2=\"" + px(f.left_px) +
         "\" y2=\"" + y + "\"/>\n";
  }
  s += "<polyline fill=\"none\" points=\"" + px(f.left_px) + "," + px(f.top_px) + " " +
       px(f.left_px) + "," + px(f.bottom_px) + " " + px(f.right_px) + "," + px(f.bottom_px) +
       "\"/>\n";
  s += "</g>\n";
  s += "<g text-anchor=\"middle\">\n";
  for (int i = 0; i <= ticks(f.x); ++i) {
    const double v = f.x.lo + i * f.x.step;
    s += "<text x=\"" + px(f.x_px(v)) + "\" y=\"" + px(f.bottom_px + kTickPx + 13.0) + "\">" +
         fixed_text(v, tick_decimals(f.x.step)) + "</text>\n";
  }
  s += "</g>\n<g text-anchor=\"end\">\n";
  for (int i = 0; i <= ticks(f.y); ++i) {
    const double v = f.y.lo + i * f.y.step;
    s += "<text x=\"" + px(f.left_px - kTickPx - 3.0) + "\" y=\"" + px(f.y_px(v)) +
         "\" dy=\"0.32em\">" + fixed_text(v, tick_decimals(f.y.step)) + "</text>\n";
  }
  s += "</g>\n";
  const double x_label_y = style.height_px - 8.0;
  s += "<text x=\"" + px(0.5 * (f.left_px + f.right_px)) + "\" y=\"" + px(x_label_y) +
       "\" text-anchor=\"middle\">" + html_escape(chart.x_label) + "</text>\n";
  const double y_label_x = 14.0;
  const double y_label_y = 0.5 * (f.top_px + f.bottom_px);
  s += "<text x=\"" + px(y_label_x) + "\" y=\"" + px(y_label_y) + "\" transform=\"rotate(-90 " +
       px(y_label_x) + " " + px(y_label_y) + ")\" text-anchor=\"middle\">" +
       html_escape(chart.y_label) + "</text>\n";

  // The lines, then the legend in the right margin.
  const std::size_t n = chart.series.size();
  s += "<g fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    s += "<path stroke=\"" + series_colour(i) + "\" stroke-width=\"" +
         fixed_text(stroke_width_px(i, n), 2) + "\" d=\"" +
         series_path(f, chart.x, chart.series[i].y) + "\"/>\n";
  }
  s += "</g>\n<g>\n";
  const double legend_x = f.right_px + 14.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = f.top_px + 6.0 + kLegendRowPx * static_cast<double>(i);
    s += "<line x1=\"" + px(legend_x) + "\" y1=\"" + px(y) + "\" x2=\"" +
         px(legend_x + kLegendSamplePx) + "\" y2=\"" + px(y) + "\" stroke=\"" + series_colour(i) +
         "\" stroke-width=\"" + fixed_text(stroke_width_px(i, n), 2) + "\"/>\n";
    s += "<text x=\"" + px(legend_x + kLegendSamplePx + 6.0) + "\" y=\"" + px(y) +
         "\" dy=\"0.32em\">" + html_escape(chart.series[i].name) + "</text>\n";
  }
  s += "</g>\n</svg>\n";
  return s;
}

}  // namespace fragsim
