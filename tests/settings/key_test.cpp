// A key's one rule, applied to a text (the parser) and to a value set in code (the registry, the
// C API): out of range, non-finite and a bad choice each give one line naming the key.

#include "settings/key.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace fragsim::settings {
namespace {

enum class Mode { kSlow, kFast };

struct Probe {
  double length_m = 1.0;
  double rate_hz = 2.0;
  int count = 3;
  Mode mode = Mode::kSlow;
  Eigen::Vector3d offset_m{0.0, 0.0, 0.0};
};

const Keys<Probe>& keys() {
  static const Keys<Probe> k{
      real("length_m", "m", "how long", &Probe::length_m, open_closed(0, 10)),
      real_or_inf("rate_hz", "Hz", "how often (inf: always)", &Probe::rate_hz, open_closed(0, 100)),
      integer("count", "", "how many", &Probe::count, 1, 5),
      choice("mode", "how fast", &Probe::mode, {{"slow", Mode::kSlow}, {"fast", Mode::kFast}}),
      vec3("offset_m", "m", "where", &Probe::offset_m, closed(-1, 1)),
  };
  return k;
}

const Key<Probe>& key(const std::string& name) {
  for (const Key<Probe>& k : keys()) {
    if (k.name == name) return k;
  }
  throw std::logic_error("no key " + name);
}

// The message of setting `name` from `text`, or "" when it is accepted.
std::string text_error(const std::string& name, const std::string& text) {
  Probe p;
  try {
    apply(key(name), p, text, "probe.ini:4");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string value_error(const Probe& p) {
  try {
    check(keys(), p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Key, HelpIsChoicesUnitAndMeaning) {
  EXPECT_EQ(key("length_m").help, "m; how long");
  EXPECT_EQ(key("count").help, "how many");
  EXPECT_EQ(key("mode").help, "slow | fast; how fast");
}

TEST(Key, TextOutOfRangeNamesPlaceKeyValueAndRule) {
  EXPECT_EQ(text_error("length_m", "12"), "probe.ini:4: length_m = '12': must be in (0, 10]");
  EXPECT_EQ(text_error("length_m", " 0 "), "probe.ini:4: length_m = '0': must be in (0, 10]");
  EXPECT_EQ(text_error("count", "9"), "probe.ini:4: count = '9': must be a whole number in [1, 5]");
  EXPECT_EQ(text_error("count", "2.5"), "probe.ini:4: count = '2.5': not a whole number");
  EXPECT_EQ(text_error("rate_hz", "200"),
            "probe.ini:4: rate_hz = '200': must be in (0, 100], or inf");
  EXPECT_EQ(text_error("offset_m", "0 2 0"),
            "probe.ini:4: offset_m = '0 2 0': each component must be in [-1, 1]");
  EXPECT_EQ(text_error("length_m", "5"), "");
  EXPECT_EQ(text_error("rate_hz", "inf"), "");
}

TEST(Key, NonFiniteTextIsRefused) {
  for (const char* t : {"nan", "inf", "-inf"}) {
    EXPECT_EQ(text_error("length_m", t),
              std::string("probe.ini:4: length_m = '") + t + "': must be finite");
  }
  EXPECT_EQ(text_error("rate_hz", "nan"),
            "probe.ini:4: rate_hz = 'nan': must be in (0, 100], or inf");
  EXPECT_EQ(text_error("rate_hz", "-inf"),
            "probe.ini:4: rate_hz = '-inf': must be in (0, 100], or inf");
  EXPECT_EQ(text_error("length_m", "two"), "probe.ini:4: length_m = 'two': not a number");
  EXPECT_EQ(text_error("length_m", "1e400"), "probe.ini:4: length_m = '1e400': not a number");
}

// Every spelling strtod takes for +infinity (C11 7.22.1.3: INF or INFINITY, ignoring case, with
// an optional sign) is a key's inf.
TEST(Key, InfinityInEverySpellingStrtodAccepts) {
  for (const char* t : {"inf", "Inf", "INF", "infinity", "Infinity", "INFINITY", "iNfInItY", "+inf",
                        "+Infinity", " inf "}) {
    EXPECT_EQ(text_error("rate_hz", t), "") << t;
  }
  EXPECT_EQ(text_error("rate_hz", "infinit"), "probe.ini:4: rate_hz = 'infinit': not a number");
  EXPECT_EQ(text_error("rate_hz", "++inf"), "probe.ini:4: rate_hz = '++inf': not a number");
}

TEST(Key, BadChoiceListsTheChoices) {
  EXPECT_EQ(text_error("mode", "quick"), "probe.ini:4: mode = 'quick': expected slow | fast");
}

TEST(Key, ValueSetInCodeIsCheckedByTheSameRule) {
  EXPECT_EQ(value_error(Probe{}), "");
  Probe p;
  p.length_m = 12.0;
  EXPECT_EQ(value_error(p), "length_m = 12: must be in (0, 10]");
  p = {};
  p.length_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(value_error(p), "length_m = nan: must be finite");
  p = {};
  p.rate_hz = std::numeric_limits<double>::infinity();
  EXPECT_EQ(value_error(p), "");
  p.rate_hz = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(value_error(p), "rate_hz = -inf: must be in (0, 100], or inf");
  p = {};
  p.count = 0;
  EXPECT_EQ(value_error(p), "count = 0: must be a whole number in [1, 5]");
  p = {};
  p.mode = static_cast<Mode>(7);
  EXPECT_EQ(value_error(p), "mode = ?: expected slow | fast");
  p = {};
  p.offset_m.y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(value_error(p), "offset_m = 0 inf 0: each component must be finite");
}

TEST(Key, FormatReadsBackAsTheSameValue) {
  Probe p;
  p.length_m = 1.0 / 3.0;
  p.rate_hz = std::numeric_limits<double>::infinity();
  p.count = 5;
  p.mode = Mode::kFast;
  p.offset_m = {0.1, -1.0 / 7.0, 1.0};
  Probe back;
  for (const Key<Probe>& k : keys()) apply(k, back, k.format(p), "roundtrip");
  EXPECT_EQ(back.length_m, p.length_m);
  EXPECT_EQ(back.rate_hz, p.rate_hz);
  EXPECT_EQ(back.count, p.count);
  EXPECT_EQ(back.mode, p.mode);
  EXPECT_EQ(back.offset_m, p.offset_m);
}

TEST(Key, SectionNamesTheKeyAndReachesTheMember) {
  struct Outer {
    Probe probe;
  };
  const Keys<Outer> outer = in_section<Outer>(
      "probe", keys(), [](auto& o) -> auto& { return o.probe; });
  ASSERT_EQ(outer.size(), keys().size());
  EXPECT_EQ(outer[0].name, "probe.length_m");
  Outer o;
  try {
    apply(outer[0], o, "-1", "--probe.length_m");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--probe.length_m: probe.length_m = '-1': must be in (0, 10]");
  }
  apply(outer[0], o, "2.5", "--probe.length_m");
  EXPECT_EQ(o.probe.length_m, 2.5);
  EXPECT_EQ(outer[0].format(o), "2.5");
}

}  // namespace
}  // namespace fragsim::settings
