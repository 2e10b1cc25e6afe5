#pragma once
// Andrew's monotone chain (Andrew 1979, "Another efficient algorithm for convex hulls in two
// dimensions", IPL 9(5)): the one 2-D hull walk behind every hull gmcc takes — of exact points
// (convex_hull.cpp), of an image's points in the feasible polygon (image_hull.cpp) and of
// colours' chromaticities (chromaticity_hull.cpp). Each caller sorts its points and supplies its
// own exact (filtered) orientation test. Internal to gmcc::geometry.

#include <cstddef>
#include <numeric>
#include <vector>

namespace gmcc::internal {

/// The convex hull of m points, sorted lexicographically (x, then y) and distinct, as their
/// positions 0..m−1: counter-clockwise from the first (the lexicographically smallest), with no
/// three consecutive vertices collinear. `left(a, b, c)` says whether point c lies strictly left
/// of the directed line a → b, decided exactly. Fewer than 3 points are their own hull; points
/// all on one line give its two ends. O(m) calls of `left`.
template <class Left>
std::vector<std::size_t> monotone_chain(std::size_t m, Left&& left) {
  std::vector<std::size_t> h(m < 3 ? m : 2 * m);
  if (m < 3) {
    std::iota(h.begin(), h.end(), std::size_t(0));
    return h;
  }
  std::size_t k = 0;
  for (std::size_t i = 0; i < m; ++i) {  // lower chain, left to right
    while (k >= 2 && !left(h[k - 2], h[k - 1], i)) --k;
    h[k++] = i;
  }
  for (std::size_t i = m - 1, t = k + 1; i-- > 0;) {  // upper chain, right to left
    while (k >= t && !left(h[k - 2], h[k - 1], i)) --k;
    h[k++] = i;
  }
  h.resize(k - 1);  // the last vertex is the first again
  return h;
}

}  // namespace gmcc::internal
