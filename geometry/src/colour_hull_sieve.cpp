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
  // The cell (a0, a1, a2) is the box of [lo_k, hi_k] = [low_k + a_k·step_k, lo_k + step_k]: the
  // least and the largest of n·x over it are sums over k of the least and largest of n_k·x_k over
  // [lo_k, hi_k], made once per plane, axis and a_k. Each is an integer below 2^51 in magnitude
  // (|n_k| below 2^33, lo_k and hi_k integers below 2^18: low_ below 2^16, `grid` steps below
  // 2^17), so every sum of three is exact in double.
  const std::size_t m = planes_.size();
  std::vector<double> least_term(m * 3 * grid), largest_term(m * 3 * grid);
  for (std::size_t p = 0; p < m; ++p)
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t a = 0; a < grid; ++a) {
        const double lo = low_[k] + step[k] * double(a), x = planes_[p][k] * lo, y = planes_[p][k] * (lo + step[k]);
        least_term[(p * 3 + k) * grid + a] = std::min(x, y), largest_term[(p * 3 + k) * grid + a] = std::max(x, y);
      }
  const auto over_cell = [&](const std::vector<double>& term, std::size_t p, const std::array<std::size_t, 3>& a) {
    return term[(p * 3) * grid + a[0]] + term[(p * 3 + 1) * grid + a[1]] + term[(p * 3 + 2) * grid + a[2]];
  };
  std::vector<std::array<double, 4>> crossing;
  std::size_t last_out = 0;  // the plane that last put a cell outside, tried first (neighbours share it)
  for (std::size_t i = 0; i < cells; ++i) {
    cell_first_[i] = static_cast<std::uint32_t>(cell_planes_.size());
    const std::array<std::size_t, 3> at = {i / (grid * grid), i / grid % grid, i % grid};
    bool outside = !(over_cell(least_term, last_out, at) < planes_[last_out][3]);
    crossing.clear();
    for (std::size_t p = 0; p < m && !outside; ++p) {
      if (!(over_cell(least_term, p, at) < planes_[p][3]))  // no point of the cell strictly inside
        outside = true, last_out = p;
      else if (!(over_cell(largest_term, p, at) < planes_[p][3]))  // the plane crosses the cell
        crossing.push_back(planes_[p]);
    }
    if (outside) {
      outside_cell_[i] = 1;
      continue;
    }
    for (std::size_t j = 0; j < crossing.size(); j += 4) {
      Planes four;
      for (std::size_t l = 0; l < 4; ++l) {
        const std::array<double, 4> f = j + l < crossing.size() ? crossing[j + l] : std::array<double, 4>{0, 0, 0, 1};
        for (std::size_t k = 0; k < 4; ++k) four[k][l] = f[k];
      }
      cell_planes_.push_back(four);
    }
  }
  cell_first_[cells] = static_cast<std::uint32_t>(cell_planes_.size());
}

}  // namespace gmcc
