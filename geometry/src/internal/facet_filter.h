#pragma once
// A polytope's containment filter, shared by ConvexSet3 and LazyConvexSet3 (convex_set_3.h,
// lazy_convex_set_3.h): p against each facet's enclosed outward plane (geometry/enclosure.h).
// Internal to gmcc::geometry.

#include <gmcc/geometry/rational_enclosure.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace gmcc::internal {

// Nothing as soon as p is certainly outside a facet; otherwise the facets whose side the filter
// could not decide (p on or near them), which the exact test then takes in ℚ (none: p is inside).
inline std::optional<std::vector<std::size_t>> facets_left_by_filter(const std::vector<Enclosure3>& vertices,
                                                                      const std::vector<std::vector<std::size_t>>& faces,
                                                                      const Point3& p) {
  const Enclosure3 q = enclose_point(p);
  std::vector<std::size_t> unsure;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const Enclosure d = side(enclosed_facet_plane(vertices, faces[k]), q);
    if (certainly_positive(d)) return std::nullopt;
    if (!certainly_negative(d)) unsure.push_back(k);
  }
  return unsure;
}

// A canonical form's faces (convex_set_3.h ConvexSet3) from faces over vertices in any order and
// `rank`, each vertex's index in the sorted order: indices renamed, each cycle started at its
// smallest index (a polygon's second index the smaller neighbour), facets sorted; none for the
// kinds below 2 dimensions.
std::vector<std::vector<std::size_t>> canonical_faces(ConvexKind3 kind, std::vector<std::vector<std::size_t>> faces,
                                                      const std::vector<std::size_t>& rank);

}  // namespace gmcc::internal
