#pragma once
/// \file convex_set_3.h
/// The value type of an exact 3-D convex set — Forsyth's (1990) feasible set of diagonal maps
/// (d1, d2, d3) — with its degenerate forms, and its exact measures.

#include <gmcc/geometry/rational.h>

#include <cstddef>
#include <string>
#include <vector>

namespace gmcc {

/// An exact point of space: a colour or a diagonal map (d1, d2, d3).
struct Point3 {
  /// coordinates: (r, g, b) of a colour, or (d1, d2, d3) of a map
  ///@{
  Rational x, y, z;
  ///@}
};
/// Exact equality of all three coordinates.
inline bool operator==(const Point3& a, const Point3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
/// Not operator==.
inline bool operator!=(const Point3& a, const Point3& b) { return !(a == b); }
/// Lexicographic order (x, y, z).
inline bool operator<(const Point3& a, const Point3& b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

/// What an exact 3-D convex set turned out to be; degenerate kinds are results, not errors:
/// `polytope` (3-dimensional), `polygon` (2), `segment` (1), `point` (0), `empty`.
enum class ConvexKind3 { polytope, polygon, segment, point, empty };

/// `polytope`, `polygon`, `segment`, `point` or `empty`.
std::string to_string(ConvexKind3 kind);

/// An exact closed convex set of space, in canonical form:
/// - vertices: its extreme points, sorted lexicographically;
/// - polytope (3-dimensional): `faces` are its facets, each a cycle of vertex indices,
///   counter-clockwise seen from outside, starting at its smallest index; facets sorted;
/// - polygon (2-dimensional): one face, its cycle, starting at index 0, the second index the
///   smaller neighbour (orientation-free);
/// - segment: 2 vertices; point: 1; empty: none (no faces for these).
/// Two ConvexSet3 describe the same set iff they compare equal.
struct ConvexSet3 {
  ConvexKind3 kind = ConvexKind3::empty;  ///< its dimension: polytope (3) down to empty
  std::vector<Point3> vertices;  ///< extreme points, sorted lexicographically
  std::vector<std::vector<std::size_t>> faces;  ///< facet cycles of indices into vertices, as above
};
/// The same set: equal kinds, vertices and faces (canonical form makes this set equality).
inline bool operator==(const ConvexSet3& a, const ConvexSet3& b) {
  return a.kind == b.kind && a.vertices == b.vertices && a.faces == b.faces;
}

/// Exact volume (0 for the lower-dimensional kinds): a tetrahedral decomposition, the facets
/// fan-triangulated and coned from the first vertex. O(total facet size).
Rational volume(const ConvexSet3& set);

/// Exact centroid of the set's uniform measure in its own dimension: the volume centroid of a
/// polytope (tetrahedra as in volume(), each centroid weighted by its volume), the area centroid
/// of a polygon (fan triangles weighted by their areas projected to the coordinate plane with
/// the largest projection — a constant multiple of the true areas, so the centroid is exact),
/// the midpoint of a segment, the point itself. \pre not empty. O(total facet size).
Point3 centroid(const ConvexSet3& set);

/// True iff p lies in the closed set (exact). O(total facet size).
bool contains(const ConvexSet3& set, const Point3& p);

/// The canonical form described at ConvexSet3 from vertices and faces in any order (faces of a
/// polytope must already be counter-clockwise seen from outside). Used by the constructors.
ConvexSet3 canonical_convex_set_3(ConvexKind3 kind, std::vector<Point3> vertices,
                                  std::vector<std::vector<std::size_t>> faces);

}  // namespace gmcc
