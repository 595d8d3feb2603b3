#include "control/api/id_table.hpp"

#include <algorithm>

namespace fragsim::control {

void IdTable::reserve(std::size_t n) {
  std::size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  if (capacity <= slots_.size()) return;
  // Built aside, so a throwing allocation changes nothing here.
  IdTable grown(slots_.get_allocator().resource());  // same resource, so the move below steals
  grown.slots_.resize(capacity);
  grown.mask_ = capacity - 1;
  for (const Slot& s : slots_) {
    if (s.stamp == generation_) grown.insert(s.key, s.value);
  }
  *this = std::move(grown);
}

void IdTable::clear(std::size_t n) {
  reserve(n);
  size_ = 0;
  if (++generation_ == 0) {  // wrapped after 2^32 clears, when old stamps could look current
    for (Slot& s : slots_) s.stamp = 0;
    generation_ = 1;
  }
}

bool IdTable::insert(std::uint64_t id, std::int32_t index) {
  for (std::size_t i = hash(id) & mask_;; i = (i + 1) & mask_) {
    Slot& s = slots_[i];
    if (s.stamp != generation_) {
      s = {id, index, generation_};
      ++size_;
      return true;
    }
    if (s.key == id) return false;
  }
}

std::int32_t IdTable::find(std::uint64_t id) const {
  if (slots_.empty()) return -1;
  for (std::size_t i = hash(id) & mask_;; i = (i + 1) & mask_) {
    const Slot& s = slots_[i];
    if (s.stamp != generation_) return -1;
    if (s.key == id) return s.value;
  }
}

}  // namespace fragsim::control
