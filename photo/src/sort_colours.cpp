// Colours of doubles sorted by buckets of their first channel (internal/sort_colours.h).
#include "internal/sort_colours.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace gmcc::internal {

void sort_double_colours(std::vector<std::array<double, 3>>& colours) {
  const std::size_t n = colours.size();
  const auto pattern = [](double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  bool buckets = n >= 256 && n <= (std::size_t(1) << 20);
  std::uint64_t lo = UINT64_MAX, hi = 0;
  for (std::size_t i = 0; i < n && buckets; ++i) {
    const double x = colours[i][0];
    buckets = x >= 0 && !std::signbit(x);  // false for NaN and −0
    lo = std::min(lo, pattern(x)), hi = std::max(hi, pattern(x));
  }
  if (!buckets) {
    std::sort(colours.begin(), colours.end());
    return;
  }
  // At most 2n buckets: the patterns' leading bits from lo to hi.
  int shift = 0;
  while ((hi >> shift) - (lo >> shift) >= 2 * n) ++shift;
  const std::size_t count = static_cast<std::size_t>((hi >> shift) - (lo >> shift)) + 1;
  const auto bucket = [&](const std::array<double, 3>& c) {
    return static_cast<std::size_t>((pattern(c[0]) >> shift) - (lo >> shift));
  };
  std::vector<std::uint32_t> start(count + 1, 0);
  for (const std::array<double, 3>& c : colours) ++start[bucket(c) + 1];
  for (std::size_t b = 0; b < count; ++b) start[b + 1] += start[b];
  std::vector<std::array<double, 3>> sorted(n);
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (const std::array<double, 3>& c : colours) sorted[next[bucket(c)]++] = c;
  for (std::size_t b = 0; b < count; ++b)
    if (start[b + 1] - start[b] > 1) std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1]);
  colours.swap(sorted);
}

}  // namespace gmcc::internal
