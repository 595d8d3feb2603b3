// The game's allocator hook as a MemoryResource (api/hook_resource.cpp): each allocation and free
// reaches the hook with its size, alignment and user pointer; a NULL from the hook is
// std::bad_alloc; without a hook the C++ runtime's new and delete serve.

#include "control/api/hook_resource.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <new>

namespace {

using fragsim::control::HookResource;

struct Log {
  alignas(64) unsigned char buffer[256];
  bool give = true;
  int allocs = 0;
  int frees = 0;
  std::size_t size = 0;
  std::size_t alignment = 0;
  void* freed = nullptr;
  std::size_t freed_size = 0;
  std::size_t freed_alignment = 0;
};

void* log_alloc(std::size_t size, std::size_t alignment, void* user) {
  Log& log = *static_cast<Log*>(user);
  ++log.allocs;
  log.size = size;
  log.alignment = alignment;
  return log.give ? log.buffer : nullptr;
}

void log_free(void* p, std::size_t size, std::size_t alignment, void* user) {
  Log& log = *static_cast<Log*>(user);
  ++log.frees;
  log.freed = p;
  log.freed_size = size;
  log.freed_alignment = alignment;
}

fragsim_controller_def hooked_def(Log& log) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.alloc_fn = log_alloc;
  def.free_fn = log_free;
  def.alloc_user = &log;
  return def;
}

TEST(HookResource, EachCallReachesTheHookWithItsSizeAlignmentAndUser) {
  Log log;
  HookResource r(hooked_def(log));
  EXPECT_TRUE(r.hooked());
  void* p = r.allocate(48, 16);
  EXPECT_EQ(p, log.buffer);
  EXPECT_EQ(log.allocs, 1);
  EXPECT_EQ(log.size, 48u);
  EXPECT_EQ(log.alignment, 16u);
  EXPECT_EQ(log.frees, 0);
  r.deallocate(p, 48, 16);
  EXPECT_EQ(log.frees, 1);
  EXPECT_EQ(log.freed, log.buffer);
  EXPECT_EQ(log.freed_size, 48u);
  EXPECT_EQ(log.freed_alignment, 16u);
  EXPECT_EQ(log.allocs, 1);
}

TEST(HookResource, NullFromTheHookIsBadAlloc) {
  Log log;
  log.give = false;
  HookResource r(hooked_def(log));
  EXPECT_THROW(r.allocate(32, 8), std::bad_alloc);
  EXPECT_EQ(log.allocs, 1);
  EXPECT_EQ(log.frees, 0);
}

TEST(HookResource, WithoutAHookTheRuntimeServesAtTheAlignmentAsked) {
  const fragsim_controller_def def = fragsim_default_controller_def();
  HookResource r(def);
  EXPECT_FALSE(r.hooked());
  for (std::size_t alignment : {8u, 16u, 64u}) {
    void* p = r.allocate(40, alignment);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignment, 0u) << alignment;
    r.deallocate(p, 40, alignment);
  }
}

}  // namespace
