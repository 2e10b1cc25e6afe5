#pragma once
/// \file feasible_set_3d.h
/// Forsyth's CRULE feasible set in 3-D (Forsyth 1990, §3; Barnard, Cardei & Funt 2002 Part I):
/// the diagonal maps d = (d1, d2, d3) that take every image colour into the canonical gamut,
///   F3 = { d : d ⊙ p ∈ G_c3 for every image colour p } = ⋂_p (G_c3 ⊘ p),
/// G_c3 the exact convex hull of the canonical RGBs (optionally with black).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace gmcc {

namespace internal {
struct CanonicalPlanes3;
struct FeasibleSet3Access;
}  // namespace internal

/// Whether the canonical gamut G_c3 includes black (0, 0, 0).
enum class CanonicalBlack {
  include,  ///< the default: darker versions of canonical surfaces are canonical too (intensity
            ///< variation, shading), as in Gijsenij et al. (2010)'s public gamut-mapping code and
            ///< Barnard's CRULE; then 0 ∈ F3, so F3 is never empty and is star-shaped about 0
  exclude,  ///< Forsyth's hull of the canonical colours alone; F3 may be empty
};
/// `include` or `exclude`: the name every front end reads and writes (--black, JSON, Python).
inline std::string to_string(CanonicalBlack black) { return black == CanonicalBlack::include ? "include" : "exclude"; }
/// The inverse of to_string. \throws std::invalid_argument (quoting the text) for any other.
inline CanonicalBlack canonical_black_from_string(const std::string& text) {
  for (CanonicalBlack b : {CanonicalBlack::include, CanonicalBlack::exclude})
    if (text == to_string(b)) return b;
  throw std::invalid_argument(quoted_text(text) + " is not one of include, exclude");
}
/// Every name to_string gives, in declaration order: the choices a front end offers.
inline std::vector<std::string> canonical_black_names() {
  return {to_string(CanonicalBlack::include), to_string(CanonicalBlack::exclude)};
}

/// G_c3 prepared once for many images (docs/math.md §1b "The prepared route"): its exact
/// half-spaces a·x <= b (CGAL::convex_hull_3 over Epeck when it is 3-dimensional; for a planar,
/// collinear or one-point gamut its affine hull as pairs of opposite half-spaces plus its edges
/// or end caps), each also with integer coefficients and the double copies the filters use, and
/// its largest channels X. Immutable once built: share one between threads (copies share it too).
class CanonicalConstraints3 {
 public:
  /// Prepares the hull of `canonical` (with black when `black` says so).
  /// \throws std::invalid_argument if `canonical` is empty or has a negative channel.
  /// Complexity O(n log n) for n canonical colours (one exact 3-D hull).
  explicit CanonicalConstraints3(const std::vector<Colour>& canonical,
                                 CanonicalBlack black = CanonicalBlack::include);
  /// The dimension of G_c3's affine hull, 0 to 3 (3: the filtered clip applies, docs/math.md §1b).
  int dimension() const;
  /// How many half-spaces describe G_c3 (its facets when dimension() is 3).
  std::size_t half_spaces() const;

 private:
  std::shared_ptr<const internal::CanonicalPlanes3> planes_;
  friend struct internal::FeasibleSet3Access;
};

/// F3 from a prepared canonical gamut: the same exact set, kind and canonical form as
/// feasible_set_3d(canonical colours, image, black) below, faster (docs/math.md §1b "The
/// prepared route", docs/performance-history.md "CRULE in 3-D (issue 16)").
///
/// The image hull's vertices are found first (from 64 colours, those certified strictly inside a
/// small hull of extreme image colours by a double filter with a proven bound are dropped; from
/// 32, CGAL's exact hull; below 32 every distinct colour is kept, which gives the same set). When G_c3 is 3-dimensional, the box 0 <= d_k <= X_k/P_k is clipped by the
/// half-spaces (a ⊙ p)·d <= b, integer coefficients, for every canonical facet a·x <= b and image
/// hull vertex p: vertices kept as triples of planes, every side test the sign of an integer
/// polynomial decided by a double filter with a proven error bound or else exactly in GMP
/// integers (docs/derivations.md §4.6). When a half-space leaves no vertex strictly inside but
/// some on it (F3 is flat), or G_c3 is not 3-dimensional, the exact LP route below decides the
/// degenerate kind. Every decision is exact.
/// \param canonical the prepared G_c3. \param image non-empty, channels >= 0.
/// \throws std::invalid_argument on an empty image or a negative channel; UnboundedFeasibleSet
///         (from feasible_set.h) when every image colour has some channel 0.
/// Complexity: the image hull, then O(k·f·v) filtered tests for k image-hull vertices, f canonical
/// facets and v the largest intermediate vertex count.
ConvexSet3 feasible_set_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image);

/// One gamut type's constraint on a map, for the joint feasible set below: a prepared canonical
/// gamut of that type and the image's colours of the same type (pixel colours, or derivative
/// magnitudes for edge gamuts; channels >= 0, any superset of their hull's vertices).
struct GamutConstraint3 {
  const CanonicalConstraints3* canonical;  ///< the type's prepared canonical gamut
  const std::vector<Colour>* image;        ///< the image's colours of that type
  /// True when `image` holds its hull's vertices already (ColourSet::hull_3d): the hull step is
  /// skipped. Only a saving: F3 is the same set from any superset of the hull's vertices.
  bool hull_vertices = false;
};

/// The maps d that take every type's image colours into its own canonical gamut at once: the
/// intersection of the types' F3 (Gijsenij, Gevers & van de Weijer 2010 §4.3, the intersection of
/// the pixel, edge and 2nd-order feasible sets, there by a float LP). Exact, every kind: the box
/// of every type (the smallest X_k/P_k) clipped by every type's rows in one pass as above, the LP
/// route over all the rows for the degenerate kinds. One constraint gives feasible_set_3d above.
/// \throws std::invalid_argument if `constraints` is empty or as feasible_set_3d for any of them.
/// Complexity: as feasible_set_3d with the rows of every type.
ConvexSet3 feasible_set_3d(const std::vector<GamutConstraint3>& constraints);

/// The same F3 as feasible_set_3d(constraints) above, its vertices in lowest terms made only on
/// request (lazy_convex_set_3.h): from the clip, each vertex's homogeneous integer coordinates and
/// the enclosures of its exact coordinates; exact() is feasible_set_3d(constraints), which calls
/// this. What estimate_3d's rules read (their filters need only the enclosures, their exact stages
/// a few vertices: docs/math.md §1b "The lazy form"). Degenerate kinds (the LP route) come exact.
/// \throws as feasible_set_3d. Complexity: as feasible_set_3d, less the lowest terms.
LazyConvexSet3 feasible_set_3d_lazy(const std::vector<GamutConstraint3>& constraints);

/// F3, exactly, with its kind (polytope, polygon, segment, point or empty): the same as
/// feasible_set_3d(CanonicalConstraints3(canonical, black), image), which it calls; the route
/// the prepared form keeps for the degenerate kinds is described here.
///
/// G_c3 is written as closed half-spaces a·x <= b: its facets (CGAL::convex_hull_3 over
/// Epeck) when it is 3-dimensional; for a planar, collinear or one-point gamut its affine hull
/// as pairs of opposite half-spaces plus the hull's edges in that plane (or its end caps). Only
/// the image hull's vertices p matter; each gives the half-spaces (a ⊙ p)·d <= b. With the
/// implied box 0 <= d_k <= X_k/P_k (X, P the largest canonical and image channels), an exact LP
/// maximises the common slack s of all inequalities (CGAL's QP solver): s* < 0 means F3 is
/// empty; s* = 0 means some inequalities hold with equality on all of F3 — the LP's non-zero
/// multipliers name them (complementary slackness) and they become equalities, until s* > 0.
/// The equalities' rank r gives the dimension 3 − r: a polytope by CGAL::halfspace_intersection_3
/// around the strictly interior LP point (docs/derivations.md §4.4; facets re-derived exactly from
/// the constraint planes), a polygon by exact 2-D clipping in its plane, a segment by an exact
/// interval on its line, or the LP point itself.
/// \param canonical non-empty, channels >= 0. \param image non-empty, channels >= 0.
/// \param black whether the black colour (0, 0, 0) joins the canonical colours' hull (CanonicalBlack).
/// \throws std::invalid_argument on empty or negative input; UnboundedFeasibleSet (from
///         feasible_set.h) when every image colour has some channel 0 (that d_k is free).
/// Complexity: hulls O(n log n); one LP per detected equality set (at most 4) over
/// k·f + 6 rows for k image-hull vertices and f canonical facets; the intersection O(kf log kf).
ConvexSet3 feasible_set_3d(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                           CanonicalBlack black = CanonicalBlack::include);

}  // namespace gmcc
