#pragma once
// Fragment ids to indices, for the controller's per-fragment state across calls: an open-address
// hash table (linear probing, power-of-two capacity, at most half full) that is cleared in O(1)
// by a generation stamp, so a step does not pay for clearing or allocating once the table has
// grown to the largest fragment count seen.

#include <cstdint>
#include <vector>

namespace fragsim::control {

class IdTable {
 public:
  // Empties the table and makes room for n ids without growing.
  void clear(std::size_t n);
  // Adds id -> index; false (and nothing changed) if the id is already in the table.
  bool insert(std::uint64_t id, std::int32_t index);
  // The index stored for id, or -1.
  std::int32_t find(std::uint64_t id) const;
  std::size_t size() const { return size_; }

 private:
  static std::uint64_t hash(std::uint64_t id) {
    // splitmix64's finaliser: engine ids are often sequential or pointer-like, and linear probing
    // needs them spread over the whole table.
    id ^= id >> 30;
    id *= 0xbf58476d1ce4e5b9ULL;
    id ^= id >> 27;
    id *= 0x94d049bb133111ebULL;
    id ^= id >> 31;
    return id;
  }

  std::vector<std::uint64_t> keys_;
  std::vector<std::int32_t> values_;
  std::vector<std::uint32_t> stamps_;  // a slot is used when its stamp is generation_
  std::uint32_t generation_ = 0;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace fragsim::control
