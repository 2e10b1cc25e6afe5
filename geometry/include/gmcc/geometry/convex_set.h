#pragma once
/// \file convex_set.h
/// The value type of an exact 2-D convex set: a polygon, or one of its degenerate forms.

#include <gmcc/geometry/point.h>

#include <string>
#include <vector>

namespace gmcc {

/// What an exact convex set turned out to be. Degenerate kinds are results, not errors:
/// `polygon` (2-dimensional, >= 3 vertices), `segment` (1-dimensional, 2 vertices), `point`
/// (1 vertex), `empty` (no vertex; e.g. no map fits every image chromaticity).
enum class ConvexKind { polygon, segment, point, empty };

/// `polygon`, `segment`, `point` or `empty`.
std::string to_string(ConvexKind kind);

/// An exact closed convex set of the plane, in canonical form:
/// - polygon: >= 3 vertices, strictly convex (no collinear triples), counter-clockwise,
///   starting at the lexicographically smallest vertex;
/// - segment: 2 distinct vertices, the lexicographically smaller first;
/// - point: 1 vertex; empty: none.
/// Two ConvexSet2 describe the same set iff they compare equal.
struct ConvexSet2 {
  ConvexKind kind = ConvexKind::empty;  ///< polygon, segment, point or empty; fixes vertices.size()
  std::vector<Point2> vertices;  ///< the extreme points in the canonical order above
};

/// The same set: equal kinds and vertex lists (canonical form makes this set equality).
inline bool operator==(const ConvexSet2& a, const ConvexSet2& b) {
  return a.kind == b.kind && a.vertices == b.vertices;
}

/// Canonical form of the convex hull of a vertex cycle that is already convex in order
/// (counter-clockwise, possibly with repeated or collinear vertices, possibly degenerate):
/// drops repeats and collinear vertices, classifies the kind, rotates to the canonical start.
/// Precondition (not checked beyond what classification needs): the cycle is convex and CCW.
/// Complexity O(n).
ConvexSet2 canonical_convex_set(std::vector<Point2> cycle);

/// Exact area (0 for degenerate kinds). Shoelace formula; O(n).
Rational area(const ConvexSet2& set);

/// Exact centroid of the set's uniform measure in its own dimension: the area centroid of a
/// polygon (fan triangulation from the first vertex, each triangle's centroid weighted by its
/// signed area), the midpoint of a segment, the point itself. Precondition: not empty. O(n).
Point2 centroid(const ConvexSet2& set);

/// True iff p lies in the closed set (exact). O(n).
bool contains(const ConvexSet2& set, const Point2& p);

}  // namespace gmcc
