// The SVG line chart against hand-worked coordinates: 1-2-5 axis ticks, the data's pixels, flat
// runs and gaps in a line, escaped text, and the palette.

#include "report/svg_chart.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "support/text_count.hpp"

namespace fragsim {
namespace {

using test::occurrences;

TEST(SvgChart, NiceAxisTicksAtOneTwoFiveSteps) {
  const ChartAxis a = nice_axis(0.0, 10.0, 5);
  EXPECT_DOUBLE_EQ(a.lo, 0.0);
  EXPECT_DOUBLE_EQ(a.hi, 10.0);
  EXPECT_DOUBLE_EQ(a.step, 2.0);
  // 0.1 / 0.02 is 5.000000000000001 in doubles: no sixth tick for it.
  const ChartAxis b = nice_axis(0.0, 0.1, 5);
  EXPECT_DOUBLE_EQ(b.step, 0.02);
  EXPECT_NEAR(b.hi, 0.1, 1e-12);
  const ChartAxis c = nice_axis(0.0, 3.0, 6);
  EXPECT_DOUBLE_EQ(c.step, 0.5);
  EXPECT_DOUBLE_EQ(c.hi, 3.0);
  const ChartAxis d = nice_axis(0.0, 96.4, 5);
  EXPECT_DOUBLE_EQ(d.step, 20.0);
  EXPECT_DOUBLE_EQ(d.hi, 100.0);
  const ChartAxis flat = nice_axis(0.0, 0.0, 5);  // all zeros: still a usable range
  EXPECT_DOUBLE_EQ(flat.lo, 0.0);
  EXPECT_DOUBLE_EQ(flat.hi, 1.0);
}

// A 400x200 chart with margins 50 (left), 150 (right), 30 (top), 40 (bottom): the plot area is
// x in [50, 250], y in [30, 160]. The data x = 0, 1, 2 and y = 0, 5, 10 span the axes [0, 2]
// (ticks every 0.5) and [0, 10] (every 2), so the points land at (50, 160), (150, 95), (250, 30).
LineChart known_chart() {
  LineChart c;
  c.title = "known";
  c.x_label = "t (s)";
  c.y_label = "n";
  c.x = {0.0, 1.0, 2.0};
  c.series = {{"line", {0.0, 5.0, 10.0}}};
  return c;
}

ChartStyle known_style() {
  ChartStyle s;
  s.width_px = 400;
  s.height_px = 200;
  s.margin_left_px = 50;
  s.margin_right_px = 150;
  s.margin_top_px = 30;
  s.margin_bottom_px = 40;
  return s;
}

TEST(SvgChart, MapsAKnownSeriesToKnownCoordinates) {
  const ChartFrame f = chart_frame(known_chart(), known_style());
  EXPECT_DOUBLE_EQ(f.x_px(0.0), 50.0);
  EXPECT_DOUBLE_EQ(f.x_px(1.0), 150.0);
  EXPECT_DOUBLE_EQ(f.x_px(2.0), 250.0);
  EXPECT_DOUBLE_EQ(f.y_px(0.0), 160.0);
  EXPECT_DOUBLE_EQ(f.y_px(5.0), 95.0);
  EXPECT_DOUBLE_EQ(f.y_px(10.0), 30.0);
  const std::string svg = svg_line_chart(known_chart(), known_style());
  EXPECT_NE(svg.find("d=\"M50.00,160.00L150.00,95.00L250.00,30.00\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("viewBox=\"0 0 400 200\""), std::string::npos);
  // Tick labels: 0, 2, ..., 10 on y; 0.0, 0.5, ..., 2.0 on x.
  for (const char* label :
       {">0<", ">2<", ">4<", ">6<", ">8<", ">10<", ">0.0<", ">0.5<", ">1.5<", ">2.0<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_NE(svg.find(">t (s)<"), std::string::npos);
  EXPECT_NE(svg.find(">line<"), std::string::npos);  // the legend
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(occurrences(svg, "<svg"), 1u);
  EXPECT_EQ(occurrences(svg, "</svg>"), 1u);
}

TEST(SvgChart, FlatRunsKeepOnlyTheirEndsAndGapsBreakTheLine) {
  LineChart c = known_chart();
  c.x = {0.0, 1.0, 2.0, 3.0, 4.0};
  c.series = {{"flat", {0.0, 0.0, 0.0, 0.0, 3.0}}};
  const std::string flat = svg_line_chart(c, known_style());
  const ChartFrame f = chart_frame(c, known_style());
  // 0 at x = 0 and x = 3 (the run's ends), then 3 at x = 4: the middle points lie on the line.
  std::ostringstream want;
  want.setf(std::ios::fixed);
  want.precision(2);
  want << "d=\"M" << f.x_px(0) << "," << f.y_px(0) << "L" << f.x_px(3) << "," << f.y_px(0) << "L"
       << f.x_px(4) << "," << f.y_px(3) << "\"";
  EXPECT_NE(flat.find(want.str()), std::string::npos) << flat;

  c.series = {{"gap", {1.0, std::numeric_limits<double>::quiet_NaN(), 1.0, 2.0, 1.0}}};
  const std::string gap = svg_line_chart(c, known_style());
  const std::size_t path = gap.find("<path");
  ASSERT_NE(path, std::string::npos);
  const std::string d = gap.substr(path, gap.find("/>", path) - path);
  EXPECT_EQ(occurrences(d, "M"), 2u) << d;
  EXPECT_EQ(d.find("nan"), std::string::npos);
}

TEST(SvgChart, EscapesItsText) {
  LineChart c = known_chart();
  c.title = "a<b & \"c\"";
  c.series[0].name = "<script>";
  const std::string svg = svg_line_chart(c, known_style());
  EXPECT_NE(svg.find("a&lt;b &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_EQ(svg.find("<script>"), std::string::npos);
  EXPECT_NE(svg.find("&lt;script&gt;"), std::string::npos);
}

TEST(SvgChart, PaletteHasEightColoursThenRepeats) {
  std::set<std::string> colours;
  for (std::size_t i = 0; i < 8; ++i) colours.insert(series_colour(i));
  EXPECT_EQ(colours.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(series_colour(i + 8), series_colour(i)) << i;
  // Each line is drawn in its series' colour.
  LineChart c = known_chart();
  c.series.push_back({"second", {1.0, 1.0, 1.0}});
  const std::string svg = svg_line_chart(c, known_style());
  EXPECT_NE(svg.find("<path stroke=\"" + series_colour(0) + "\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<path stroke=\"" + series_colour(1) + "\""), std::string::npos) << svg;
}

}  // namespace
}  // namespace fragsim
