#include <gtest/gtest.h>
#include "sim/scene.hpp"
TEST(Smoke, Builds) { EXPECT_EQ(fragsim::Scene{}.fragment_count(), 1728); }
