// The scene keys of the library's strategies (edge-min, edge, deflect-all) against the library's
// ranges (strategies/param_range.hpp, the tables the C API checks a def by): every key that holds
// a number takes exactly the values its range admits, every range has its key, and the keys
// without one are the choices. Probed at and beside each end, inside and far outside, and with
// inf, -inf and nan.

#include "strategies/range_keys.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/number_format.hpp"
#include "strategies/deflect_all_keys.hpp"
#include "strategies/edge_keys.hpp"
#include "strategies/edge_min_keys.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// `v` as a scene file writes it: a whole number's digits for a whole-number key ("100000000",
// which such a key reads, not "1e+08").
std::string text_of(double v, bool whole) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (whole && v == std::floor(v) && std::abs(v) < 1e18) {
    return std::to_string(static_cast<long long>(v));
  }
  return format_double(v);
}

// Values at, beside and between the ends of `r`, far beyond them and not finite.
std::vector<double> probes(const ParamRange& r) {
  std::vector<double> v{r.lo, r.hi, 0.0, -1.0, 1.0, 0.5, 1e300, -1e300, kInf, -kInf};
  v.push_back(std::numeric_limits<double>::quiet_NaN());
  if (std::isfinite(r.lo) && std::isfinite(r.hi)) {
    v.push_back(r.lo + (r.hi - r.lo) / 2);
    v.push_back(r.lo + (r.hi - r.lo) * 0.37);
  }
  for (double end : {r.lo, r.hi}) {
    if (!std::isfinite(end)) continue;
    v.push_back(std::nextafter(end, -kInf));
    v.push_back(std::nextafter(end, kInf));
    v.push_back(end - 1);
    v.push_back(end + 1);
    v.push_back(end + 0.5);
  }
  return v;
}

// What the library admits for a key of this range: a whole number too when the range is whole.
bool library_admits(const ParamRange& r, double v) {
  return r.admits(v) && (!r.whole || v == std::floor(v));
}

// Whether `key` reads `text`; if it does, the value held keeps the key's rule.
template <class Params>
bool key_reads(const settings::Key<Params>& key, const std::string& text) {
  Params p;
  try {
    key.parse(p, text);
  } catch (const settings::ValueError&) {
    return false;
  }
  EXPECT_FALSE(key.broken(p).has_value()) << key.name << " = " << text;
  return true;
}

// Every key of `spec` against `ranges`: the numbers it reads are the ones the library admits;
// the keys with no range are exactly `choices`, and every range has a key.
template <class Params>
void expect_library_ranges(const ParamSpec<Params>& spec, std::span<const ParamRange> ranges,
                           const std::set<std::string>& choices) {
  std::set<std::string> without_range;
  std::set<std::string> keys;
  for (const settings::Key<Params>& key : spec.keys) {
    keys.insert(key.name);
    const ParamRange* r = find_range(ranges, key.name);
    if (r == nullptr) {
      without_range.insert(key.name);
      continue;
    }
    for (double v : probes(*r)) {
      const std::string text = text_of(v, r->whole);
      // The edge weights are four numbers, each in the range: the others stay at 1.
      const std::string key_text = key.name == "edge_weights" ? text + " 1 1 1" : text;
      EXPECT_EQ(key_reads(key, key_text), library_admits(*r, v))
          << key.name << " = '" << key_text << "' against the library's range";
    }
  }
  EXPECT_EQ(without_range, choices);
  for (const ParamRange& r : ranges) EXPECT_TRUE(keys.count(r.name)) << r.name << " has no key";
}

TEST(RangeKeys, EdgeMinKeysHaveTheLibrarysRanges) {
  expect_library_ranges(edge_min_param_spec(), kEdgeMinRanges, {"camera_model"});
}

TEST(RangeKeys, EdgeKeysHaveTheLibrarysRanges) {
  expect_library_ranges(edge_param_spec(), kEdgeRanges,
                        {"predictor", "reach", "horizon", "replan"});
}

TEST(RangeKeys, DeflectAllKeysHaveTheLibrarysRanges) {
  expect_library_ranges(deflect_all_param_spec(), kDeflectAllRanges, {});
}

// The edge weights' rule beyond each weight's range is the library's too: not all four zero.
TEST(RangeKeys, EdgeWeightsRefuseAllZeroAsTheLibraryDoes) {
  const settings::Key<EdgeMinParams>* weights = nullptr;
  for (const auto& k : edge_min_param_spec().keys) {
    if (k.name == "edge_weights") weights = &k;
  }
  ASSERT_NE(weights, nullptr);
  EXPECT_FALSE(some_edge_allowed({0.0, 0.0, 0.0, 0.0}));
  EXPECT_FALSE(key_reads(*weights, "0 0 0 0"));
  for (int k = 0; k < 4; ++k) {
    std::array<double, 4> w{0.0, 0.0, 0.0, 0.0};
    w[static_cast<std::size_t>(k)] = 2.0;
    EXPECT_TRUE(some_edge_allowed(w));
    std::string text;
    for (double v : w) text += (text.empty() ? "" : " ") + format_double(v);
    EXPECT_TRUE(key_reads(*weights, text)) << text;
  }
}

TEST(RangeKeys, AKeyTheLibraryHasNoRangeForIsAnError) {
  EXPECT_THROW(library_range(kEdgeRanges, "margin_m"), std::logic_error);
  EXPECT_EQ(&library_range(kEdgeRanges, "k"), &kEdgeRanges[0]);
}

}  // namespace
}  // namespace fragsim
