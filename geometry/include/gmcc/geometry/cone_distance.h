#pragma once
/// \file cone_distance.h
/// The Euclidean projection of a colour onto a polyhedral cone of colours, exactly: the
/// non-negative least-squares problem min_{λ >= 0} ||Σ λ_k g_k − p||² (Lawson & Hanson 1974,
/// ch. 23) that gamut-constrained illuminant estimation solves to measure how far an image colour
/// lies from a light's gamut (Finlayson, Hordley & Tastl 2006; docs/math.md §1f). In three
/// dimensions the nearest point of a cone lies in the relative interior of one of its faces (the
/// apex, an edge ray or a facet), and the projection onto each face's span is rational, so the
/// distance is a rational number computed without rounding.

#include <gmcc/geometry/convex_set_3.h>

#include <array>
#include <vector>

namespace gmcc {

/// The nearest point of K to p and the squared distance to it.
struct ConeProjection {
  Point3 nearest;             ///< the projection of p onto K (p itself when p ∈ K)
  Rational squared_distance;  ///< ||p − nearest||², 0 exactly when p ∈ K
};

/// A pointed polyhedral cone K = {Σ λ_k g_k : λ_k >= 0} given by its extreme rays in the cyclic
/// order of its boundary, counter-clockwise seen from inside (the lifts (x, y, 1) of a
/// counter-clockwise chromaticity polygon, each scaled by a positive diagonal map, are so
/// ordered), with its facet normals g_k × g_{k+1} and the Gram entries the projections need.
/// One generator is a ray, two a planar wedge (angle below π).
class PolygonalCone {
 public:
  /// \param generators the extreme rays, at least one, none zero, in the order above; two
  /// generators must not be opposite. Not checked beyond that: K's convexity is the caller's
  /// (a convex chromaticity polygon's lifts give it). \throws std::invalid_argument for no
  /// generator, a zero one, or two opposite ones.
  /// Complexity O(m) exact operations for m generators.
  explicit PolygonalCone(std::vector<Point3> generators);

  /// The extreme rays g_k, in the order given.
  const std::vector<Point3>& generators() const { return g_; }

  /// p ∈ K, exactly. For m >= 3: n_k · p >= 0 for every facet normal, each sign decided in
  /// double enclosures (numerics/enclosure.h: the normal's and p's nearest doubles, each within a
  /// relative u, and Rump's bound on the rounded dot product) and in ℚ only where the enclosure
  /// holds 0; for a ray or a wedge, a zero distance to p. O(m) operations.
  bool contains(const Point3& p) const;
  /// contains(p) with p's nearest doubles (to_double_nearest of each coordinate) given, for a
  /// colour tested against many cones.
  bool contains(const Point3& p, const std::array<double, 3>& p_nearest) const;

 private:
  friend ConeProjection project_onto_cone(const Point3& p, const PolygonalCone& cone);
  std::vector<Point3> g_;       // g_k
  std::vector<Rational> gg_;    // |g_k|²
  std::vector<Point3> n_;       // g_k × g_{k+1} (cyclic; one facet for a wedge)
  std::vector<Rational> nn_;    // |n_k|²
  std::vector<Rational> gnext_; // g_k · g_{k+1}
  std::vector<std::array<double, 3>> n_double_;  // n_k's nearest doubles, for contains()'s filter
};

/// The projection of p onto K, exactly (docs/math.md §1f). For m >= 3 generators p ∈ K when
/// n_k · p >= 0 for every facet; otherwise the nearest point is the best of the candidates whose
/// projection lies in its face: the apex (0), each ray with p · g_k > 0, each facet with
/// n_k · p < 0 whose projection has both wedge coefficients >= 0. Each candidate is a point of
/// K, so none is nearer than the truth, and the truth is one of them. O(m) exact operations.
ConeProjection project_onto_cone(const Point3& p, const PolygonalCone& cone);

}  // namespace gmcc
