// The one number formatter: fixed decimals, percentages and the shortest round-trip form, on the
// edge cases where formatters differ (negative zero, ties, non-finite values, huge values).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "io/number_format.hpp"

namespace fragsim {
namespace {

std::string printf_fixed(double v, int decimals) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

TEST(NumberFormat, NegativeZeroAndNegativesThatRoundToZeroHaveNoSign) {
  EXPECT_EQ(fixed_text(-0.0, 2), "0.00");
  EXPECT_EQ(fixed_text(-0.004, 2), "0.00");
  EXPECT_EQ(fixed_text(-1e-17, 4), "0.0000");
  EXPECT_EQ(fixed_text(-0.4, 0), "0");
  // 0.0005 is stored slightly above 5e-4: it rounds away from zero and keeps its sign.
  EXPECT_EQ(fixed_text(-0.0005, 3), "-0.001");
  EXPECT_EQ(fixed_text(-0.006, 2), "-0.01");
  EXPECT_EQ(percent_text(-1e-9, 1), "0.0");
}

TEST(NumberFormat, HalvesRoundFromTheStoredValueWithTiesToEven) {
  // Exact binary halves: ties to even.
  EXPECT_EQ(fixed_text(0.125, 2), "0.12");
  EXPECT_EQ(fixed_text(0.375, 2), "0.38");
  EXPECT_EQ(fixed_text(2.5, 0), "2");
  EXPECT_EQ(fixed_text(3.5, 0), "4");
  EXPECT_EQ(fixed_text(-2.5, 0), "-2");
  // Decimal "halves" are not halves in binary: 1.005 and 2.675 are stored below, 0.0345 above.
  EXPECT_EQ(fixed_text(1.005, 2), "1.00");
  EXPECT_EQ(fixed_text(2.675, 2), "2.67");
  EXPECT_EQ(fixed_text(0.0345, 3), "0.035");
  EXPECT_EQ(percent_text(0.00125, 2), "0.12");  // 100 * 0.00125 is exactly 0.125: to even
}

TEST(NumberFormat, FixedMatchesPrintfButForNegativeZero) {
  // The terminal's tables were printed with "%.*f": the same text for every value but -0.
  for (const double v :
       {0.0, 1.0, 0.1, 0.05, 2.675, 96.35, 1234.5678, 1e-7, 123456789.125, -3.14159, -0.51, 1e22}) {
    for (int d = 0; d <= 6; ++d) EXPECT_EQ(fixed_text(v, d), printf_fixed(v, d)) << v << " " << d;
  }
}

TEST(NumberFormat, NonFiniteValuesReadAsWords) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(fixed_text(nan, 3), "nan");
  EXPECT_EQ(fixed_text(-nan, 3), "nan");  // no "-nan": the sign of a NaN means nothing here
  EXPECT_EQ(fixed_text(inf, 1), "inf");
  EXPECT_EQ(fixed_text(-inf, 1), "-inf");
  EXPECT_EQ(percent_text(nan, 1), "nan");
  EXPECT_EQ(percent_text(inf, 1), "inf");
  EXPECT_EQ(format_double(inf), "inf");  // how scene files write an unbounded value
  EXPECT_EQ(format_double(-inf), "-inf");
}

TEST(NumberFormat, HugeValuesPrintInFull) {
  const std::string max = fixed_text(std::numeric_limits<double>::max(), 2);
  EXPECT_EQ(max.size(), 309u + 3u);
  EXPECT_EQ(max.rfind("17976931348623157", 0), 0u);
  EXPECT_EQ(max.substr(max.size() - 3), ".00");
}

TEST(NumberFormat, ShortestFormReadsBackAsTheSameDouble) {
  EXPECT_EQ(format_double(0.1), "0.1");
  EXPECT_EQ(format_double(1.0), "1");
  EXPECT_EQ(format_double(-0.0), "-0");
  EXPECT_EQ(format_double(1e-300), "1e-300");
  for (const double v : {1.0 / 3.0, 1.0 / 60.0, 2.0 / 3.0 * 1e17, 1.2345678901234567e-200}) {
    EXPECT_EQ(std::stod(format_double(v)), v) << format_double(v);
  }
  std::string s = "x=";
  append_double(s, 0.25);
  EXPECT_EQ(s, "x=0.25");
}

}  // namespace
}  // namespace fragsim
