#pragma once
/// \file lazy_convex_set_3.h
/// An exact 3-D convex set whose vertices are made exact rationals only on request (issue 28
/// item 3): Forsyth's (1990) feasible set F3 as its selections read it. Every vertex is known from
/// the start as homogeneous integer coordinates (X, Y, Z, W) and as the double enclosure of its
/// exact coordinates; its coordinates in lowest terms — a gcd per coordinate, the dominant cost of
/// building F3 for a photograph (docs/performance.md "3-D gamut mapping on photographs") — are
/// computed for the vertices an exact stage asks for, not for all (docs/math.md §1b "The lazy
/// form").

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/rational_enclosure.h>

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace gmcc {

/// The same set as a ConvexSet3, in the same canonical order (vertices sorted lexicographically,
/// faces as there), whose exact vertices are computed on first request and kept.
///
/// Invariants: enclosure(i) is bit for bit enclose_point(vertex(i)) (geometry/enclosure.h), so a
/// filter reads the same numbers on either form; exact() == the ConvexSet3 of the same set.
/// Copies share the vertices made exact so far; vertex() and exact() fill that shared cache, so
/// one set and its copies are for one thread at a time (the const members otherwise are safe).
class LazyConvexSet3 {
 public:
  /// The empty set.
  LazyConvexSet3();
  /// An exact set: every vertex already exact, the enclosures made from them. O(vertices).
  explicit LazyConvexSet3(ConvexSet3 exact);
  /// A set from vertices in homogeneous integer coordinates: vertex i is (X/W, Y/W, Z/W) for
  /// homogeneous[i] = (X, Y, Z, W), W ≠ 0, no two the same point; faces as in
  /// canonical_convex_set_3 (any vertex order, polytope facets counter-clockwise seen from
  /// outside). Sorted into ConvexSet3's canonical order by comparing the coordinates' truncated
  /// doubles (truncation is monotone) and, on a tie, exactly by cross-multiplication; nothing is
  /// reduced to lowest terms. O(n log n) comparisons for n vertices.
  static LazyConvexSet3 from_homogeneous(ConvexKind3 kind, std::vector<std::array<mpz_class, 4>> homogeneous,
                                         std::vector<std::vector<std::size_t>> faces);

  /// Makes vertex i's homogeneous integer coordinates (X, Y, Z, W), W ≠ 0, on request (i indexes
  /// the vertices as given to from_truncated).
  using HomogeneousMaker = std::function<std::array<mpz_class, 4>(std::size_t)>;
  /// A vertex for from_truncated: known by its coordinates' truncated doubles, its homogeneous
  /// coordinates made only when asked.
  struct TruncatedVertex {
    /// Each coordinate x truncated toward zero to a double (what mpq_get_d gives for x), every
    /// non-zero one within 2^±136 in magnitude (the range policy's own range, so its enclosure is
    /// that double ± 2u relative: numerics/rational_to_float.h).
    std::array<double, 3> truncated;
    bool zero;  ///< whether the vertex is the origin (0, 0, 0)
  };
  /// A set from vertices known by their truncated coordinates (F3 kept symbolic: docs/math.md
  /// §1b "The lazy form"), the homogeneous coordinates of vertex i made by make(i) only when an
  /// exact stage asks (homogeneous(), vertex(), or a tie in the vertex order). The same set,
  /// order, faces and enclosures as from_homogeneous of all the vertices made: the enclosures
  /// come from the truncated doubles exactly as from the exact coordinates, and the order
  /// compares those doubles (truncation is monotone) and, on a tie, the made coordinates.
  static LazyConvexSet3 from_truncated(ConvexKind3 kind, std::vector<TruncatedVertex> vertices,
                                       std::vector<std::vector<std::size_t>> faces, HomogeneousMaker make);

  /// Its dimension, as ConvexSet3::kind.
  ConvexKind3 kind() const;
  /// How many vertices it has.
  std::size_t size() const;
  /// Its faces, as ConvexSet3::faces (indices into the canonical vertex order).
  const std::vector<std::vector<std::size_t>>& faces() const;
  /// Every vertex's enclosure, in the canonical order: enclose_point of the exact vertex.
  const std::vector<Enclosure3>& enclosures() const;
  /// True iff vertex i is the origin (0, 0, 0). O(1).
  bool is_zero(std::size_t i) const;
  /// Vertex i exactly, in lowest terms: made on the first request (a gcd per coordinate), then
  /// kept. \pre i < size().
  const Point3& vertex(std::size_t i) const;
  /// Vertex i in homogeneous integer coordinates (X, Y, Z, W), W > 0, (X/W, Y/W, Z/W) = vertex(i),
  /// not in lowest terms: as the set was made (from_homogeneous), or, for a set made exact,
  /// made on the first request from the exact vertex over the lcm of its denominators, then
  /// kept. For exact stages that need no lowest terms (a facet's plane, an edge's polynomial:
  /// integer arithmetic without a gcd). \pre i < size().
  const std::array<mpz_class, 4>& homogeneous(std::size_t i) const;
  /// Facet k's plane n·x <= c (a polytope's facet, outward; a polygon's plane), integers from the homogeneous
  /// coordinates of its first three vertices a, b, c: (n, c) = W_a W_b W_c ((b − a) × (c − a),
  /// ((b − a) × (c − a))·a), four 3 × 3 determinants, no gcd (docs/derivations.md §2.4).
  /// \pre kind() is polytope or polygon and k < faces().size().
  std::pair<std::array<mpz_class, 3>, mpz_class> facet_plane(std::size_t k) const;
  /// The whole set exactly, every vertex made: equal to the ConvexSet3 of the same set.
  ConvexSet3 exact() const;
  /// How many vertices have been made exact so far (what the lazy route saved is size() minus
  /// this).
  std::size_t exact_vertices() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
  // The set with the vertices given in `order` (canonical vertex i is given vertex order[i]).
  static LazyConvexSet3 ordered(ConvexKind3 kind, const std::vector<std::size_t>& order,
                                std::vector<std::array<mpz_class, 4>> homogeneous,
                                const std::vector<Enclosure3>& enclosures, const std::vector<char>& zero,
                                std::vector<std::vector<std::size_t>> faces, HomogeneousMaker make);
};

/// True iff p lies in the closed set, exactly: contains(set.exact(), p), with a polytope's
/// facets tested by the enclosed filter first and exactly (facet_plane, in integers) only where
/// it cannot decide. O(total facet size).
bool contains(const LazyConvexSet3& set, const Point3& p);

}  // namespace gmcc
