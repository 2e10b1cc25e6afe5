#include <gmcc/geometry/colour_hull_sieve.h>

#include "internal/crule_exact.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace gmcc {

ExtremeColours::ExtremeColours() {
  std::size_t k = 0;
  for (int x = 0; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y > 0 || (y == 0 && z > 0)) v_[k++] = {double(x), double(y), double(z)};
  top_.fill(-HUGE_VAL);
  bottom_.fill(HUGE_VAL);
}

std::vector<std::size_t> ExtremeColours::indices() const {
  std::vector<std::size_t> out;
  if (!any_) return out;
  for (std::size_t j = 0; j < directions; ++j) out.push_back(hi_[j]), out.push_back(lo_[j]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

ColourHullSieve::ColourHullSieve(const std::vector<std::array<double, 3>>& corners) {
  for (const auto& c : corners)
    for (double x : c)
      if (!internal::small_integer(x))
        throw std::invalid_argument("ColourHullSieve: a channel that is not an integer in [0, 2^16)");
  std::vector<std::size_t> all(corners.size());
  std::iota(all.begin(), all.end(), std::size_t(0));
  for (const auto& t : internal::hull_triangles_3(corners, all)) {
    const auto &a = corners[t[0]], &b = corners[t[1]], &c = corners[t[2]];
    const double u0 = b[0] - a[0], u1 = b[1] - a[1], u2 = b[2] - a[2];
    const double v0 = c[0] - a[0], v1 = c[1] - a[1], v2 = c[2] - a[2];
    const double n0 = u1 * v2 - u2 * v1, n1 = u2 * v0 - u0 * v2, n2 = u0 * v1 - u1 * v0;
    planes_.push_back({n0, n1, n2, n0 * a[0] + n1 * a[1] + n2 * a[2]});
  }
  if (planes_.empty()) return;
  // The grid: integer steps covering [low, high], the corners' box, in `grid` cells a side.
  std::array<double, 3> step;
  for (std::size_t k = 0; k < 3; ++k) {
    double lo = corners[0][k], hi = corners[0][k];
    for (const auto& c : corners) lo = std::min(lo, c[k]), hi = std::max(hi, c[k]);
    low_[k] = lo, high_[k] = hi;
    while (double(grid) * std::ldexp(1.0, static_cast<int>(shift_[k])) < hi - lo + 1) ++shift_[k];
    step[k] = std::ldexp(1.0, static_cast<int>(shift_[k]));  // grid steps cover [lo, hi]
  }
  sort_planes_into_cells(step);
}

void ColourHullSieve::sort_planes_into_cells(const std::array<double, 3>& step) {
  const std::size_t cells = grid * grid * grid;
  outside_cell_.assign(cells, 0);
  cell_first_.assign(cells + 1, 0);
  std::vector<std::array<double, 4>> crossing;
  for (std::size_t i = 0; i < cells; ++i) {
    cell_first_[i] = static_cast<std::uint32_t>(cell_planes_.size());
    // The closed cell [lo, hi]: integers below 2^18 (low_ below 2^16, 16 steps below 2^17), so
    // with |n| below 2^33 every product is below 2^51 and every sum below 2^53: exact.
    const std::array<std::size_t, 3> at = {i / (grid * grid), i / grid % grid, i % grid};
    std::array<double, 3> lo, hi;
    for (std::size_t k = 0; k < 3; ++k) lo[k] = low_[k] + step[k] * double(at[k]), hi[k] = lo[k] + step[k];
    crossing.clear();
    for (const std::array<double, 4>& f : planes_) {
      // The least and the largest of n·x over the cell, at the corners the signs of n pick.
      double least = 0, largest = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        const double a = f[k] * lo[k], b = f[k] * hi[k];
        least += std::min(a, b), largest += std::max(a, b);
      }
      if (!(least < f[3])) {  // no point of the cell strictly inside this plane
        outside_cell_[i] = 1;
        crossing.clear();
        break;
      }
      if (!(largest < f[3])) crossing.push_back(f);  // the plane crosses the cell
    }
    for (std::size_t j = 0; j < crossing.size(); j += 4) {
      Planes four;
      for (std::size_t l = 0; l < 4; ++l) {
        const std::array<double, 4> f = j + l < crossing.size() ? crossing[j + l] : std::array<double, 4>{0, 0, 0, 1};
        four.n[0][l] = f[0], four.n[1][l] = f[1], four.n[2][l] = f[2], four.d[l] = f[3];
      }
      cell_planes_.push_back(four);
    }
  }
  cell_first_[cells] = static_cast<std::uint32_t>(cell_planes_.size());
}

}  // namespace gmcc
