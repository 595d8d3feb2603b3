#pragma once
// A set of at most a few disjoint time intervals, in order, such as the times a path spends inside
// one of edge-min's slabs (slab_times.hpp) and what intersecting them leaves.

#include <algorithm>
#include <array>
#include <cstddef>

namespace fragsim {

// Room for every set the constant model makes (a parabola meets a slab in at most two pieces;
// intersections of two and three such sets in at most seven). Past that, the last piece is widened
// to hold the rest, giving more times at which a push must clear the box, never fewer. Only the
// first n pieces are set, as a set is made and copied several times per exact solve and clearing
// the rest costs as much as filling it.
struct Intervals {
  std::array<std::array<double, 2>, 8> span;
  int n = 0;
  bool empty() const { return n == 0; }
  void append(double a, double b) {
    if (n < static_cast<int>(span.size())) {
      span[static_cast<std::size_t>(n++)] = {a, b};
    } else {
      span[span.size() - 1][1] = std::max(span[span.size() - 1][1], b);
    }
  }
};

inline Intervals intersect(const Intervals& a, const Intervals& b) {
  Intervals out;
  for (int i = 0; i < a.n; ++i) {
    for (int j = 0; j < b.n; ++j) {
      const auto& x = a.span[static_cast<std::size_t>(i)];
      const auto& y = b.span[static_cast<std::size_t>(j)];
      const double lo = std::max(x[0], y[0]);
      const double hi = std::min(x[1], y[1]);
      if (lo <= hi) out.append(lo, hi);
    }
  }
  return out;
}

// a's pieces, then b's (all of b later than a's), joined where they meet.
inline Intervals unite_in_order(const Intervals& a, const Intervals& b) {
  Intervals out = a;
  for (int j = 0; j < b.n; ++j) {
    const auto& piece = b.span[static_cast<std::size_t>(j)];
    if (out.n > 0 && out.span[static_cast<std::size_t>(out.n - 1)][1] >= piece[0]) {
      auto& last = out.span[static_cast<std::size_t>(out.n - 1)];
      last[1] = std::max(last[1], piece[1]);
    } else {
      out.append(piece[0], piece[1]);
    }
  }
  return out;
}

}  // namespace fragsim
