#pragma once
// F3's clip with its rows generated lazily (docs/derivations.md §4.6, "Rows generated lazily"): the
// box clipped by a subset of the rows (a ⊙ p)·x <= b, every other row then checked at the
// result's vertices by a certified filter, the rows it cannot clear added, and the subset clipped
// again until every row is either in it or cleared. The result is the set clip_polytope gives for
// all the rows, exactly. Internal to gmcc::geometry.

#include "internal/polytope_clip.h"

#include <cstddef>
#include <vector>

namespace gmcc::internal {

// From this many rows (points × facets over the groups) feasible_set_3d_lazy takes
// clip_polytope_lazy_rows; below it the whole clip costs little.
constexpr std::size_t lazy_rows_from = 200000;

// The same result as clip_polytope(box, groups, counts), by rounds of clip_polytope on subsets of
// the rows: a round's polytope P contains F3 (fewer rows); when every row outside the subset holds
// at every vertex of P (certified in doubles), P satisfies every row, so P = F3. Otherwise, per
// canonical facet and vertex of P, the row of the point most violating it there joins the subset.
// Falls back to the whole clip when a round's result is flat (and not one point) or when its
// vertices' bounds leave the filter's range. `counts` adds every round's decisions.
ClippedPolytope clip_polytope_lazy_rows(const Point3& box, const std::vector<ClipGroup>& groups,
                                        ClipCounts* counts = nullptr);

}  // namespace gmcc::internal
