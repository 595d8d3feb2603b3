// The library's MemoryResource and ResourceVector: every allocation of a vector goes through the
// resource it was built with, with the element's size and alignment, and stays there when the
// vector is copied or assigned, as a controller's containers must (all of a controller's memory
// comes through the game's hook).
#include "control/memory/memory_resource.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

namespace fragsim {
namespace {

// Counts what it hands out, from the default resource.
class CountingResource final : public MemoryResource {
 public:
  void* allocate(std::size_t bytes, std::size_t alignment) override {
    ++allocations;
    bytes_live += bytes;
    last_alignment = alignment;
    return default_memory_resource()->allocate(bytes, alignment);
  }
  void deallocate(void* p, std::size_t bytes, std::size_t alignment) override {
    ++deallocations;
    bytes_live -= bytes;
    default_memory_resource()->deallocate(p, bytes, alignment);
  }
  int allocations = 0;
  int deallocations = 0;
  std::size_t bytes_live = 0;
  std::size_t last_alignment = 0;
};

struct alignas(64) Wide {
  double x[8];
};

TEST(MemoryResource, AVectorAllocatesItsElementsFromItsResource) {
  CountingResource mem;
  {
    ResourceVector<double> v(&mem);
    v.reserve(100);
    EXPECT_EQ(mem.allocations, 1);
    EXPECT_EQ(mem.bytes_live, 100 * sizeof(double));
    EXPECT_EQ(mem.last_alignment, alignof(double));
    v.assign(100, 1.5);  // within the reserve: no allocation
    EXPECT_EQ(mem.allocations, 1);
  }
  EXPECT_EQ(mem.deallocations, 1);
  EXPECT_EQ(mem.bytes_live, 0u);
}

TEST(MemoryResource, AnOverAlignedElementAsksForItsAlignment) {
  CountingResource mem;
  ResourceVector<Wide> v(&mem);
  v.resize(3);
  EXPECT_EQ(mem.last_alignment, 64u);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % 64, 0u);
}

TEST(MemoryResource, ACopyKeepsTheResourceOfWhatItCopies) {
  CountingResource mem;
  ResourceVector<int> a(&mem);
  a.assign(10, 7);
  const ResourceVector<int> b(a);
  EXPECT_EQ(b.get_allocator().resource(), &mem);
  EXPECT_EQ(mem.allocations, 2);
}

TEST(MemoryResource, AnAssignedVectorKeepsItsOwnResource) {
  CountingResource mine;
  CountingResource theirs;
  ResourceVector<int> a(&mine);
  ResourceVector<int> b(&theirs);
  b.assign(10, 3);
  a = b;
  EXPECT_EQ(a.get_allocator().resource(), &mine);
  EXPECT_EQ(mine.allocations, 1);
  ResourceVector<int> c(&mine);
  c = std::move(b);  // another resource: the elements are moved, the memory is c's own
  EXPECT_EQ(c.get_allocator().resource(), &mine);
  EXPECT_EQ(mine.allocations, 2);
  EXPECT_EQ(c.size(), 10u);
}

TEST(MemoryResource, TheDefaultResourceIsTheDefaultOfEveryVector) {
  const ResourceVector<int> v;
  EXPECT_EQ(v.get_allocator().resource(), default_memory_resource());
}

}  // namespace
}  // namespace fragsim
