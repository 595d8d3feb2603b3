#include "api/id_table.hpp"

#include <algorithm>

namespace fragsim::control {

void IdTable::clear(std::size_t n) {
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  size_ = 0;
  if (capacity > keys_.size()) {
    keys_.assign(capacity, 0);
    values_.assign(capacity, -1);
    stamps_.assign(capacity, 0);
    mask_ = capacity - 1;
    generation_ = 1;
    return;
  }
  if (++generation_ == 0) {  // wrapped after 2^32 clears: old stamps could look current
    std::fill(stamps_.begin(), stamps_.end(), 0);
    generation_ = 1;
  }
}

bool IdTable::insert(std::uint64_t id, std::int32_t index) {
  for (std::size_t slot = hash(id) & mask_;; slot = (slot + 1) & mask_) {
    if (stamps_[slot] != generation_) {
      stamps_[slot] = generation_;
      keys_[slot] = id;
      values_[slot] = index;
      ++size_;
      return true;
    }
    if (keys_[slot] == id) return false;
  }
}

std::int32_t IdTable::find(std::uint64_t id) const {
  if (keys_.empty()) return -1;
  for (std::size_t slot = hash(id) & mask_;; slot = (slot + 1) & mask_) {
    if (stamps_[slot] != generation_) return -1;
    if (keys_[slot] == id) return values_[slot];
  }
}

}  // namespace fragsim::control
