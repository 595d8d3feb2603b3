#include "control/api/controller_slots.hpp"

#include <array>
#include <atomic>
#include <mutex>

namespace fragsim::control {
namespace {

constexpr std::uint32_t kChunkSlots = 256;
constexpr std::uint32_t kChunks = FRAGSIM_MAX_CONTROLLERS / kChunkSlots;
static_assert(kChunks * kChunkSlots == FRAGSIM_MAX_CONTROLLERS);
constexpr std::uint32_t kNoSlot = 0xffffffffu;

struct Slot {
  std::atomic<std::uint32_t> generation{0};
  std::atomic<Controller*> controller{nullptr};
  std::uint32_t next_free = kNoSlot;  // under the lock
};

struct Slots {
  std::array<std::atomic<Slot*>, kChunks> chunks{};
  std::mutex lock;
  std::uint32_t used = 0;  // slots ever handed out; those below it are in use or on the free list
  std::uint32_t free = kNoSlot;
};

// Never destroyed, as a game may destroy its controllers from its own static destructors.
Slots& slots() {
  static Slots* const table = new Slots;
  return *table;
}

Slot* slot_at(Slots& t, std::uint32_t index) {
  Slot* chunk = t.chunks[index / kChunkSlots].load(std::memory_order_acquire);
  return chunk == nullptr ? nullptr : &chunk[index % kChunkSlots];
}

}  // namespace

fragsim_controller_id add_controller(Controller* controller) {
  Slots& t = slots();
  const std::lock_guard<std::mutex> hold(t.lock);
  std::uint32_t index = t.free;
  if (index != kNoSlot) {
    t.free = slot_at(t, index)->next_free;
  } else {
    if (t.used == FRAGSIM_MAX_CONTROLLERS) return {0, 0};
    index = t.used;
    std::atomic<Slot*>& chunk = t.chunks[index / kChunkSlots];
    if (chunk.load(std::memory_order_relaxed) == nullptr) {
      chunk.store(new Slot[kChunkSlots], std::memory_order_release);
    }
    ++t.used;
  }
  Slot* s = slot_at(t, index);
  // Generations start at 1, so no live id is all zero.
  const std::uint32_t generation = s->generation.load(std::memory_order_relaxed) + 1;
  s->controller.store(controller, std::memory_order_release);
  s->generation.store(generation, std::memory_order_release);
  return {index + 1, generation};
}

Controller* find_controller(fragsim_controller_id id) {
  if (id.index1 == 0 || id.index1 > FRAGSIM_MAX_CONTROLLERS) return nullptr;
  Slot* s = slot_at(slots(), id.index1 - 1);
  if (s == nullptr || s->generation.load(std::memory_order_acquire) != id.generation) {
    return nullptr;
  }
  return s->controller.load(std::memory_order_acquire);
}

Controller* remove_controller(fragsim_controller_id id) {
  if (id.index1 == 0 || id.index1 > FRAGSIM_MAX_CONTROLLERS) return nullptr;
  Slots& t = slots();
  const std::lock_guard<std::mutex> hold(t.lock);
  Slot* s = slot_at(t, id.index1 - 1);
  if (s == nullptr || s->generation.load(std::memory_order_relaxed) != id.generation) {
    return nullptr;
  }
  Controller* c = s->controller.load(std::memory_order_relaxed);
  if (c == nullptr) return nullptr;
  // A new generation first, so from here on the stale id finds nothing.
  s->generation.store(id.generation + 1, std::memory_order_release);
  s->controller.store(nullptr, std::memory_order_release);
  s->next_free = t.free;
  t.free = id.index1 - 1;
  return c;
}

}  // namespace fragsim::control
