#pragma once
/// \file polytope_moments.h
/// The volume and centroid sums of a convex polytope (Forsyth's 1990 F3 for CRULE-AVE, the hull
/// average of Barnard, Cardei & Funt 2002), written once for every number type: exact rationals
/// (convex_set_3.h volume() and centroid()) and double enclosures (selection's certified
/// centroid, centroid_3.h). docs/math.md §1b.

#include <array>
#include <cstddef>
#include <vector>

namespace gmcc {

/// The sums of one tetrahedral decomposition, in the number type T.
template <class T>
struct PolytopeMoments {
  T six_volume{};                ///< Σ w: six times the volume
  std::array<T, 3> weighted{};   ///< Σ w·(o + a + b + c): the centroid is weighted / (4·six_volume)
};

/// The facets fan-triangulated (f[0], f[i], f[i+1]) and each triangle coned from the first vertex
/// o into a tetrahedron of signed weight w = det(a − o, b − o, c − o) (six times its volume,
/// positive for facets counter-clockwise seen from outside); facets through o (f[0] = 0) add
/// nothing. Every operation is T's own, in this order, so an enclosure kind encloses the exact
/// sums. `with_centroid` false leaves `weighted` zero (volume only).
/// \pre v are a polytope's vertices and faces its facets as in ConvexSet3 (each cycle starting
/// at its smallest index). O(total facet size).
template <class T>
PolytopeMoments<T> polytope_moments(const std::vector<std::array<T, 3>>& v,
                                    const std::vector<std::vector<std::size_t>>& faces, bool with_centroid) {
  using P = std::array<T, 3>;
  auto sub = [](const P& a, const P& b) { return P{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  PolytopeMoments<T> m;
  const P& o = v[0];
  for (const auto& f : faces) {
    if (f[0] == 0) continue;
    const P a = sub(v[f[0]], o);
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const P b = sub(v[f[i]], o), c = sub(v[f[i + 1]], o);
      const T w = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0]);
      m.six_volume = m.six_volume + w;
      if (!with_centroid) continue;
      for (std::size_t k = 0; k < 3; ++k)
        m.weighted[k] = m.weighted[k] + w * (o[k] + v[f[0]][k] + v[f[i]][k] + v[f[i + 1]][k]);
    }
  }
  return m;
}

}  // namespace gmcc
