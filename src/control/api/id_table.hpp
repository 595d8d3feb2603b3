#pragma once
// Fragment ids to indices, for the controller's per-fragment state across calls, in an open-address
// hash table (linear probing, power-of-two capacity, at most half full) that is cleared in O(1) by
// a generation stamp, so a step does not pay for clearing or allocating once the table has grown to
// the largest fragment count seen.
//
// Every growth builds the new arrays aside and swaps them in, so an allocation that fails leaves
// the table as it was (the controller's promise after FRAGSIM_ERROR_OUT_OF_MEMORY).

#include <cstdint>
#include <vector>

#include "control/memory/memory_resource.hpp"

namespace fragsim::control {

class IdTable {
 public:
  // Its slots are allocated from `mem` (the controller's allocator).
  explicit IdTable(MemoryResource* mem) : slots_(mem) {}
  // Room for n ids without growing, keeping the ids in the table.
  void reserve(std::size_t n);
  // Empties the table and makes room for n ids without growing.
  void clear(std::size_t n);
  // Adds id -> index; false (and nothing changed) if the id is already in the table. The table
  // must have room (clear or reserve for at least size() + 1).
  bool insert(std::uint64_t id, std::int32_t index);
  // The index stored for id, or -1.
  std::int32_t find(std::uint64_t id) const;
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return slots_.size() / 2; }

 private:
  static std::uint64_t hash(std::uint64_t id) {
    // splitmix64's finaliser, as engine ids are often sequential or pointer-like, and linear
    // probing needs them spread over the whole table.
    id ^= id >> 30;
    id *= 0xbf58476d1ce4e5b9ULL;
    id ^= id >> 27;
    id *= 0x94d049bb133111ebULL;
    id ^= id >> 31;
    return id;
  }

  // One slot in 16 bytes, key, value and stamp together, so a probe touches one cache line where
  // three arrays would touch three (the explosion's step inserts every id at random places).
  struct Slot {
    std::uint64_t key = 0;
    std::int32_t value = -1;
    std::uint32_t stamp = 0;  // the slot is used when its stamp is generation_
  };
  ResourceVector<Slot> slots_;
  std::uint32_t generation_ = 1;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace fragsim::control
