// Evaluations through bytes and back, as they come from worker processes: every double bit for bit
// (thirds, subnormals, negative zero, NaN), every length kept, and truncated or padded bytes
// refused instead of read as something else.

#include "experiments/evaluation_codec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/run_summary.hpp"

namespace fragsim {
namespace {

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(bits(a[i]), bits(b[i])) << i;
}

// An evaluation whose numbers a text form or a float would not keep.
Evaluation awkward() {
  Evaluation e;
  RunSummary& s = e.summary;
  s.scene = "front";
  s.strategy = "edge-min";
  s.seed = std::numeric_limits<std::uint64_t>::max();
  s.dt_s = 1.0 / 60.0;
  s.intersections.near_fragments = 3;
  s.deviation.mean_m = 0.1 + 0.2;
  s.activity.min_near_m = std::nextafter(0.05, 1.0);
  s.cost.physics_ms_median = 1.0 / 3.0;
  s.cost.strategy_ms_p95 = -0.0;
  s.cost.wall_s = 12.5;
  e.has_deviation = true;
  e.near_per_step = {0, 2, 1};
  e.candidates_per_step = {46, 40, 0};
  e.occlusion_per_step = {0.0, std::numeric_limits<double>::quiet_NaN(), 1.0 / 3.0};
  e.central_occlusion_per_step = {-0.0, std::numeric_limits<double>::denorm_min(), 1.0};
  e.physics_s_per_step = {1e-9, 2e-9, 3e-9};
  e.strategy_s_per_step = {};
  e.camera.resize(2);
  e.camera[1].eye_m = {0.1, 1.6, -1.0 / 3.0};
  e.camera[1].near_m = 0.05;
  e.camera[1].fovy_deg = 59.999999999999993;
  return e;
}

TEST(EvaluationCodec, RoundTripKeepsEveryBit) {
  const Evaluation e = awkward();
  const std::string bytes = encode_evaluation(e);
  const Evaluation back = decode_evaluation(bytes);
  EXPECT_EQ(summary_fields(back.summary), summary_fields(e.summary));
  EXPECT_EQ(back.summary.seed, std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(bits(back.summary.deviation.mean_m), bits(0.1 + 0.2));
  EXPECT_EQ(bits(back.summary.activity.min_near_m), bits(std::nextafter(0.05, 1.0)));
  EXPECT_EQ(bits(back.summary.cost.physics_ms_median), bits(1.0 / 3.0));
  EXPECT_EQ(bits(back.summary.cost.strategy_ms_p95), bits(-0.0));
  EXPECT_EQ(back.summary.cost.wall_s, 12.5);
  EXPECT_TRUE(back.has_deviation);
  EXPECT_EQ(back.near_per_step, e.near_per_step);
  EXPECT_EQ(back.candidates_per_step, e.candidates_per_step);
  expect_same_bits(back.occlusion_per_step, e.occlusion_per_step);
  expect_same_bits(back.central_occlusion_per_step, e.central_occlusion_per_step);
  expect_same_bits(back.physics_s_per_step, e.physics_s_per_step);
  EXPECT_TRUE(back.strategy_s_per_step.empty());
  ASSERT_EQ(back.camera.size(), 2u);
  EXPECT_EQ(back.camera[1].eye_m, e.camera[1].eye_m);
  EXPECT_EQ(back.camera[1].near_m, 0.05);
  EXPECT_EQ(back.camera[1].fovy_deg, 59.999999999999993);
  EXPECT_EQ(back.camera[0].forward, e.camera[0].forward);
  EXPECT_EQ(encode_evaluation(back), bytes);  // nothing the encoding carries was lost
}

TEST(EvaluationCodec, SeveralKeepTheirOrder) {
  Evaluation none;
  none.summary.strategy = "none";
  const std::vector<Evaluation> three{none, awkward(), Evaluation{}};
  const std::vector<Evaluation> back = decode_evaluations(encode_evaluations(three));
  ASSERT_EQ(back.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(encode_evaluation(back[i]), encode_evaluation(three[i])) << i;
  }
  EXPECT_EQ(back[0].summary.strategy, "none");
  EXPECT_EQ(back[1].summary.strategy, "edge-min");
  EXPECT_TRUE(decode_evaluations(encode_evaluations({})).empty());
}

TEST(EvaluationCodec, TruncatedOrPaddedBytesAreRefused) {
  const std::string bytes = encode_evaluation(awkward());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_THROW(decode_evaluation(bytes.substr(0, n)), std::runtime_error) << n;
  }
  EXPECT_THROW(decode_evaluation(bytes + '\0'), std::runtime_error);
  const std::string several = encode_evaluations({awkward(), awkward()});
  EXPECT_THROW(decode_evaluations(several.substr(0, several.size() - 1)), std::runtime_error);
  EXPECT_THROW(decode_evaluations(several + "x"), std::runtime_error);
  // A count larger than the bytes could hold is refused before anything is allocated for it.
  EXPECT_THROW(decode_evaluations(std::string(8, '\xff')), std::runtime_error);
}

}  // namespace
}  // namespace fragsim
