// The run summary's field table (metrics/run_summary.cpp), the one list behind summary.csv and the
// codec: each field as text in the table's order, numbers as shortest round-trip text, and text
// read back into a summary to the last bit. Values by hand.

#include "metrics/run_summary.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace fragsim {
namespace {

// The position of column `name` in the table.
std::size_t column(const char* name) {
  const auto& cols = summary_field_table();
  for (std::size_t i = 0; i < cols.size(); ++i) {
    if (std::strcmp(cols[i].name, name) == 0) return i;
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

RunSummary hand_made() {
  RunSummary s;
  s.scene = "hand";
  s.strategy = "edge-min";
  s.seed = 18446744073709551615ull;  // the largest seed: every digit kept
  s.dt_s = 1.0 / 60.0;
  s.fragments = 125;
  s.steps = 180;
  s.intersections.near_fragments = 3;
  s.intersections.camera_hit_fragments = 1;
  s.deviation.mean_m = 0.1;
  s.deviation.max_m = 2.5;
  return s;
}

TEST(RunSummary, FieldsAreTheTableInOrderAsText) {
  const std::vector<std::string> f = summary_fields(hand_made());
  ASSERT_EQ(f.size(), summary_field_table().size());
  EXPECT_EQ(column("scene"), 0u);
  EXPECT_EQ(column("strategy"), 1u);
  EXPECT_EQ(f[column("scene")], "hand");
  EXPECT_EQ(f[column("strategy")], "edge-min");
  EXPECT_EQ(f[column("seed")], "18446744073709551615");
  EXPECT_EQ(f[column("dt_s")], "0.016666666666666666");  // shortest text that reads back 1/60
  EXPECT_EQ(f[column("fragments")], "125");
  EXPECT_EQ(f[column("steps")], "180");
  EXPECT_EQ(f[column("near_fragments")], "3");
  EXPECT_EQ(f[column("camera_hit_fragments")], "1");
  EXPECT_EQ(f[column("deviation_mean_m")], "0.1");
  EXPECT_EQ(f[column("deviation_max_m")], "2.5");
  EXPECT_EQ(f[column("exits_top")], "0");
}

TEST(RunSummary, TextReadsBackToTheSameBits) {
  const RunSummary s = hand_made();
  RunSummary back;
  set_summary_fields(back, summary_fields(s));
  EXPECT_EQ(back.scene, "hand");
  EXPECT_EQ(back.seed, s.seed);
  EXPECT_EQ(back.dt_s, 1.0 / 60.0);
  EXPECT_EQ(back.deviation.mean_m, 0.1);
  EXPECT_EQ(back.intersections.near_fragments, 3);
  EXPECT_EQ(summary_fields(back), summary_fields(s));
  std::vector<std::string> short_row = summary_fields(s);
  short_row.pop_back();
  EXPECT_THROW(set_summary_fields(back, short_row), std::runtime_error);
}

}  // namespace
}  // namespace fragsim
