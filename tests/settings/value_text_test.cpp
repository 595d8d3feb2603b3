// Scene-file values as text: read strictly (the whole text, finite numbers, three components, the
// points' limits), written so they read back as the same bits, each refusal naming its rule.

#include "settings/value_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace fragsim::settings {
namespace {

// The rule a refused text breaks, or "accepted".
template <typename Parse>
std::string rule_of(Parse parse) {
  try {
    parse();
  } catch (const ValueError& e) {
    return e.rule;
  }
  return "accepted";
}

TEST(ValueText, TrimDropsBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim(" \t a b \r\n"), "a b");
  EXPECT_EQ(trim("a"), "a");
  EXPECT_EQ(trim(" \t\r\n"), "");
}

TEST(ValueText, NumbersAreTheWholeTextAndFinite) {
  EXPECT_EQ(parse_double(" 1.5\t"), 1.5);
  EXPECT_EQ(parse_double("-2e-3"), -2e-3);
  EXPECT_EQ(parse_integer(" -7 "), -7);
  EXPECT_EQ(parse_integer("1000000"), 1000000);
  for (const char* text : {"", "two", "1.5 m", "1,5", "1e400"}) {
    EXPECT_EQ(rule_of([&] { parse_double(text); }), "not a number") << text;
  }
  for (const char* text : {"inf", "-inf", "nan"}) {
    EXPECT_EQ(rule_of([&] { parse_double(text); }), "must be finite") << text;
  }
  for (const char* text : {"", "1.5", "3 4", "9223372036854775808"}) {
    EXPECT_EQ(rule_of([&] { parse_integer(text); }), "not a whole number") << text;
  }
}

TEST(ValueText, VectorsAreThreeNumbersBySpacesOrCommas) {
  EXPECT_EQ(parse_vec3("1 2 3"), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(parse_vec3(" 0.5, -1,2 "), Eigen::Vector3d(0.5, -1, 2));
  for (const char* text : {"", "1 2", "1 2 3 4"}) {
    EXPECT_EQ(rule_of([&] { parse_vec3(text); }), "expected three numbers x y z") << text;
  }
  EXPECT_EQ(rule_of([] { parse_vec3("1 y 3"); }), "not a number");
  EXPECT_EQ(rule_of([] { parse_vec3("1 inf 3"); }), "must be finite");
}

TEST(ValueText, WrittenValuesReadBackAsTheSameBits) {
  const Eigen::Vector3d v(0.1, -2.0, 1e-300);
  EXPECT_EQ(format_vec3(v), "0.1 -2 1e-300");
  const Eigen::Vector3d third(1.0 / 3.0, 0.1 + 0.2, std::nextafter(1.0, 2.0));
  EXPECT_EQ(parse_vec3(format_vec3(third)), third);  // exact: shortest round-trip text
  const std::vector<Eigen::Vector3d> points{{0, 0, 0}, third};
  EXPECT_EQ(parse_points(format_points(points)), points);
  EXPECT_EQ(format_points({{0, 0, 0}, {1, 2, 3}}), "0 0 0; 1 2 3");
}

TEST(ValueText, PointsAreOneToAThousandWithinAMillionMetres) {
  EXPECT_EQ(parse_points("0 0 0; 1 2 3;"),
            (std::vector<Eigen::Vector3d>{{0, 0, 0}, {1, 2, 3}}));  // empty items skipped
  EXPECT_EQ(parse_points("1e6 -1e6 0").size(), 1u);
  EXPECT_EQ(rule_of([] { parse_points(" ; "); }), "expected at least one point 'x y z'");
  EXPECT_EQ(rule_of([] { parse_points("0 0 0; 1000001 0 0"); }),
            "each component must be in [-1e6, 1e6]");
  std::string thousand;
  for (int i = 0; i < 1000; ++i) thousand += "0 0 " + std::to_string(i) + ";";
  EXPECT_EQ(parse_points(thousand).size(), 1000u);
  EXPECT_EQ(rule_of([&] { parse_points(thousand + "1 1 1"); }), "at most 1000 points");

  // The same limits on points set in code, where NaN breaks them too.
  EXPECT_EQ(points_rule({{1e6, -1e6, 0}}), std::nullopt);
  EXPECT_EQ(points_rule({}), "expected at least one point 'x y z'");
  EXPECT_EQ(points_rule({{0, std::nan(""), 0}}), "each component must be in [-1e6, 1e6]");
  EXPECT_EQ(points_rule({{0, 0, -1e6 - 1}}), "each component must be in [-1e6, 1e6]");
  EXPECT_EQ(points_rule(std::vector<Eigen::Vector3d>(1001, Eigen::Vector3d::Zero())),
            "at most 1000 points");
}

TEST(ValueText, TextIsOneLineWithoutCommasOrQuotes) {
  EXPECT_EQ(text_rule("edge-min run 3 (50 m/s)"), std::nullopt);
  EXPECT_EQ(text_rule(""), std::nullopt);
  for (const char* text : {"a,b", "say \"hi\"", "two\nlines"}) {
    EXPECT_EQ(text_rule(text), "must be one line without commas or quotes") << text;
  }
}

}  // namespace
}  // namespace fragsim::settings
