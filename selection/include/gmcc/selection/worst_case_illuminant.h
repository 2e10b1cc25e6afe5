#pragma once
/// \file worst_case_illuminant.h
/// Worst-case illuminant recovery error of a selection: the largest angle between the illuminant
/// it implies and the illuminant implied by any map of the feasible set (docs/derivations.md §3.2,
/// illuminant space; the measure of Hordley & Finlayson 2006 [Hordley2006Reevaluation]).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set.h>

namespace gmcc {

/// The worst case and where it is attained.
struct IlluminantWorstCase {
  /// max_{x ∈ F} illuminant_angular_error_deg(m, x, c), in degrees.
  double angle_deg = 0;
  /// Where: the maximising vertex exactly when `at_vertex`; otherwise an exact rational point of
  /// the maximising edge p + t(q − p) whose parameter t lies within 2^-100 of the maximiser's.
  Point2 location;
  /// True iff the maximum is attained at a vertex of F (when an edge maximum and a vertex tie
  /// exactly, the vertex is reported).
  bool at_vertex = true;
};

/// Worst-case illuminant angular error of the map m over the feasible set F, and its location:
/// max over x ∈ F of ∠(c ⊘ (m, 1), c ⊘ (x, 1)) for the canonical illuminant c.
///
/// The vertex rule of worst_case_map_deg is not exact here: the componentwise reciprocal does not
/// preserve convexity (docs/derivations.md §3.2 gives a 3.5° counter-example). The maximum lies on
/// ∂F (the angle to a fixed direction has no interior maximum on a region of the positive octant).
/// On an edge x(t) = p + t(q − p), t ∈ [0, 1], the implied illuminant has direction
/// v(t) = (c1·b(t), c2·a(t), c3·a(t)·b(t)) (c ⊘ (a, b, 1) times a·b > 0), and with e the
/// estimate's illuminant the angle is stationary where (e·v′)|v|² − (e·v)(v·v′) = 0, a quartic
/// (its t⁵ terms cancel; the code checks this). Its coefficients are built exactly in ℚ, its
/// distinct real roots in (0, 1] are isolated with a Sturm sequence of its square-free part and
/// refined by exact bisection to width ≤ 2^-100. The candidates (vertices and refined roots, all
/// exact rational points) are compared exactly by cos² in ℚ; the winner's angle is evaluated as
/// illuminant_angular_error_deg (MPFR). The refined point is within 2^-100·|q − p| of an edge
/// maximiser, where the angle is stationary, so the angle error is O(2^-200): far below a double.
///
/// \param F the feasible set: polygon, segment (one edge) or point (its vertex); all vertex
///          components > 0.
/// \param m the selected perspective map (d1/d3, d2/d3); components > 0.
/// \param canonical_illuminant c, components > 0.
/// \throws std::invalid_argument for an empty F or a component ≤ 0.
/// Complexity: O(n) edges, each O(1) polynomial operations on degree ≤ 5 plus O(100 + log(1/s))
/// Sturm evaluations, s the separation of that edge's roots. Filters skip that work wherever it
/// cannot change the answer (the same answer, bit for bit): double enclosures, for an edge whose
/// quartic certainly has no zero or whose closeness certainly exceeds a vertex's, and for a
/// vertex whose closeness is certainly not the least; then, on what they leave, the same tests
/// on sin² = |e × w|²/|w|² written in x − m, without cancellation, in MPFI from 128 bits (on a
/// set whose vertices agree to 2^-53, where no double decides); last, an edge whose quartic has
/// no sign variation after t = 1/(1 + u) has no stationary point inside (Descartes' rule) and
/// needs no Sturm sequence. On many-vertex sets nearly every edge and vertex is skipped so.
IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m,
                                          const Colour& canonical_illuminant);

/// worst_case_illuminant(F, m, canonical_illuminant).angle_deg: the worst-case illuminant
/// angular error in degrees. Same definition, preconditions and complexity.
double worst_case_illuminant_deg(const ConvexSet2& F, const Point2& m,
                                 const Colour& canonical_illuminant);

}  // namespace gmcc
