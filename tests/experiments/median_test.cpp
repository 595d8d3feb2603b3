// The median every timing figure is given as.
#include "experiments/median.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

TEST(Median, OfAnOddSampleIsItsMiddleValue) {
  EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);
}

TEST(Median, OfAnEvenSampleIsTheMeanOfItsTwoMiddleValues) {
  EXPECT_EQ(median({4.0, 1.0, 2.0, 10.0}), 3.0);
}

TEST(Median, OfNothingIsZero) {
  EXPECT_EQ(median({}), 0.0);
}

}  // namespace
}  // namespace fragsim
