#pragma once
// The median of a sample, as every timing figure of the benchmarks and reports is given, which is
// the middle value, or the mean of the two middle ones. 0 for an empty sample.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace fragsim {

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace fragsim
