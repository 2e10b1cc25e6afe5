#pragma once
/// \file colour_hull_3.h
/// The colours that are vertices of the convex hull of a set of colours in 3-D (RGB space): all a
/// 3-D gamut method depends on, since the hull of the vertices is the hull of the set
/// (Forsyth 1990 §3: only the image gamut's extreme points constrain the diagonal maps;
/// docs/math.md §1b "The prepared route").

#include <gmcc/geometry/colour.h>

#include <array>
#include <cstddef>
#include <vector>

namespace gmcc {

/// The vertices of conv(colours), exactly, sorted lexicographically (r, g, b), without repeats,
/// whatever its dimension: flat colours (affinely at most 2-dimensional) give the vertices of
/// their polygon (the exact 2-D hull of a one-to-one projection), a segment's two ends or the
/// one colour. A double
/// filter with a proven bound first drops colours certified strictly inside a small hull of
/// extreme colours; CGAL's exact 3-D hull (Epeck) decides the rest (the same image-hull step
/// as feasible_set_3d's prepared route).
/// \throws std::invalid_argument if `colours` is empty or has a negative channel.
/// Complexity O(n) filtered tests, then O(m log m) for the m colours the filter keeps.
std::vector<Colour> colour_hull_vertices(const std::vector<Colour>& colours);

/// The same for colours whose channels are doubles, each taken exactly (integer pixel values, or
/// float samples): the indices of the distinct colours that are vertices of the hull, in
/// increasing (r, g, b) order of the colours (one index per distinct vertex; flat colours' own
/// extreme points, as above). The filter runs on the doubles themselves and CGAL's Epick kernel,
/// whose predicates are exact on double input, decides the rest; only the vertices found are
/// made rational (for the flatness test and a flat set's extreme points).
/// \throws std::invalid_argument if `colours` is empty or a channel is negative or not finite.
std::vector<std::size_t> colour_hull_vertex_indices(const std::vector<std::array<double, 3>>& colours);

}  // namespace gmcc
