#pragma once
// One pass of Sutherland–Hodgman clipping (Sutherland & Hodgman 1974, "Reentrant polygon
// clipping", CACM 17(1)): the walk written once for both of gmcc's clippers — exact rational
// points (half_plane.cpp) and vertices kept as pairs of lines (convex_clip.cpp), which differ only
// in how a vertex is kept and a crossing formed. Internal to gmcc::geometry.

#include <cstddef>
#include <vector>

namespace gmcc::internal {

/// A convex cycle of n = s.size() vertices clipped to a closed half-plane, from each vertex's
/// exact side s[i] (< 0 inside, 0 on the boundary line, > 0 outside). Walking the edges i → j,
/// `keep(i, j)` is called for each vertex inside or on the line, and `cross(i, j)` for each edge
/// that crosses the line strictly (s[i]·s[j] < 0), in cycle order. Returns false, calling
/// neither, when every vertex is inside or on the line: the cycle is its own clip.
template <class Keep, class Cross>
bool sutherland_hodgman(const std::vector<int>& s, Keep&& keep, Cross&& cross) {
  const std::size_t n = s.size();
  bool all_inside = true;
  for (std::size_t i = 0; i < n; ++i) all_inside = all_inside && s[i] <= 0;
  if (all_inside) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (s[i] <= 0) keep(i, j);
    if (s[i] * s[j] < 0) cross(i, j);
  }
  return true;
}

}  // namespace gmcc::internal
