// Fragment ids to indices (api/id_table.cpp): what was inserted is found, a repeat is refused, a
// clear empties the table without shrinking it, and growth keeps the ids. Capacities by hand: 16
// slots at least, doubled until at most half full.

#include "control/api/id_table.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace {

using fragsim::control::IdTable;

TEST(IdTable, FindsWhatWasInsertedAndMinusOneForTheRest) {
  IdTable t(fragsim::default_memory_resource());
  EXPECT_EQ(t.find(42), -1);  // never sized: no slot to look in
  t.clear(3);
  EXPECT_EQ(t.capacity(), 8u);  // 16 slots, half of them usable
  EXPECT_TRUE(t.insert(42, 0));
  EXPECT_TRUE(t.insert(7, 1));
  EXPECT_TRUE(t.insert(0, 2));  // id 0 is an id like any other
  EXPECT_FALSE(t.insert(42, 5));
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.find(42), 0);  // the first insert's index, not the refused one's
  EXPECT_EQ(t.find(7), 1);
  EXPECT_EQ(t.find(0), 2);
  EXPECT_EQ(t.find(8), -1);
}

TEST(IdTable, ClearEmptiesWithoutShrinking) {
  IdTable t(fragsim::default_memory_resource());
  t.clear(100);
  EXPECT_EQ(t.capacity(), 128u);  // 256 slots: the first power of two >= 2 x 100
  for (std::uint64_t id = 0; id < 100; ++id) ASSERT_TRUE(t.insert(id * 1000, 1));
  t.clear(3);
  EXPECT_EQ(t.size(), 0u);
  EXPECT_EQ(t.capacity(), 128u);
  for (std::uint64_t id = 0; id < 100; ++id) EXPECT_EQ(t.find(id * 1000), -1) << id;
  EXPECT_TRUE(t.insert(5000, 9));
  EXPECT_EQ(t.find(5000), 9);
}

TEST(IdTable, ReserveGrowsAndKeepsTheIds) {
  IdTable t(fragsim::default_memory_resource());
  t.clear(8);
  for (std::int32_t k = 0; k < 8; ++k) ASSERT_TRUE(t.insert(1000 + 3 * k, k));
  t.reserve(1000);
  EXPECT_EQ(t.capacity(), 1024u);  // 2048 slots >= 2 x 1000
  EXPECT_EQ(t.size(), 8u);
  for (std::int32_t k = 0; k < 8; ++k) EXPECT_EQ(t.find(1000 + 3 * k), k) << k;
  // Sequential ids, as engines hand them out, fill it to the reserved size.
  for (std::int32_t k = 8; k < 1000; ++k) ASSERT_TRUE(t.insert(1000 + 3 * k, k));
  EXPECT_EQ(t.size(), 1000u);
  for (std::int32_t k = 0; k < 1000; ++k) EXPECT_EQ(t.find(1000 + 3 * k), k) << k;
  t.reserve(10);  // never shrinks
  EXPECT_EQ(t.capacity(), 1024u);
}

}  // namespace
