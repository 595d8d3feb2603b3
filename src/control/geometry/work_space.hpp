#pragma once
// Work arrays sized ahead of the steps that use them, with their pages touched. Reserving alone
// leaves a large block unmapped until its first write, so the first step that fills it pays one
// page fault per 4 KiB (2,277 of them, tens of milliseconds, for `edge` at 15,625 fragments), which
// in a game is a hitch on the explosion's first frame. Writing the block once here moves that cost
// to reset(), before the explosion.

#include <cstddef>

namespace fragsim {

// Room for n elements in v, every byte of it written once; v keeps its elements (a vector in use
// keeps its contents; room only grows).
template <class Vector>
void reserve_touched(Vector& v, std::size_t n) {
  if (n <= v.size()) return;
  const std::size_t keep = v.size();
  v.reserve(n);
  v.resize(n);  // value-initialises, so every new element's bytes are written
  v.resize(keep);
}

}  // namespace fragsim
