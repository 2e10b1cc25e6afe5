#pragma once
// max_volume's stages, reachable for the tests that compare them (Forsyth 1990, CRULE-MV;
// docs/derivations.md §2.4). Internal to gmcc::selection.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/map_estimate_3.h>

#include "internal/staged.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace gmcc::internal {

/// Which of F3's candidates for argmax d1·d2·d3 a stage examines: vertices (indices into
/// F3.vertices), facets' stationary points (indices into F3.faces) and edges' roots (pairs of
/// vertex indices, smaller first).
struct MaxVolumeCandidates {
  /// the candidates, each list sorted
  ///@{
  std::vector<std::size_t> vertices, faces;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  ///@}
};

/// Every candidate of F3 (docs/derivations.md §2.4): all vertices, faces and edges.
MaxVolumeCandidates all_max_volume_candidates(const ConvexSet3& F3);
/// The same for F3 with vertices made exact on request (lazy_convex_set_3.h).
MaxVolumeCandidates all_max_volume_candidates(const LazyConvexSet3& F3);

/// The filter: every candidate's position and value d1·d2·d3 in double enclosures
/// (numerics/enclosure.h), a facet's stationary point tested against the other facets only when
/// its value could win, an edge or facet passed over when its hull bound (the product of its
/// vertices' largest |d_k|) is below a value certainly attained (docs/derivations.md §2.4). Returns the candidates whose value may reach the largest value certainly
/// attained (the maximiser is among them), or nothing when F3 is not a polytope or a vertex is
/// out of the enclosures' range. \pre F3 not empty.
std::optional<MaxVolumeCandidates> max_volume_contenders(const ConvexSet3& F3);
/// The same from F3's enclosures alone (lazy_convex_set_3.h): no vertex is made exact.
std::optional<MaxVolumeCandidates> max_volume_contenders(const LazyConvexSet3& F3);

/// The exact stage over `which`: rational candidates compared in ℚ (ties to the
/// lexicographically least), irrational edge roots separated in MPFI. \pre `which` holds the
/// maximiser and at least one vertex.
MapEstimate3 max_volume_over(const ConvexSet3& F3, const MaxVolumeCandidates& which);
/// The same making exact only the vertices the candidates in `which` are built from.
MapEstimate3 max_volume_over(const LazyConvexSet3& F3, const MaxVolumeCandidates& which);

/// How often each stage answered max_volume, since the start: 0, the filter alone (one vertex
/// left); 1, the exact stage over the filter's contenders; 2, the exact stage over every
/// candidate.
const StageCounts& max_volume_stage_counts();

}  // namespace gmcc::internal
