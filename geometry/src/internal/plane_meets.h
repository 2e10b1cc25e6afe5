#pragma once
// The clip's final vertices kept symbolic (issue 28 item 3; docs/math.md §1b "The lazy form",
// docs/derivations.md §4.6): each vertex the meet of three integer planes, its coordinates'
// truncated doubles decided from double-word copies of the planes, its exact homogeneous
// coordinates made only when an exact stage asks. Internal to gmcc::geometry.

#include "internal/polytope_clip.h"

#include <gmcc/geometry/lazy_convex_set_3.h>

#include <gmpxx.h>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace gmcc::internal {

// The plane's WidePlane, or nothing when a non-zero coefficient is beyond 2^±900 of the largest.
std::optional<WidePlane> wide_plane(const IntegerPlane3& p);
// The same for four integers (a point's (P, L)), scaled alike.
std::optional<WidePlane> wide_plane(const std::array<const mpz_class*, 4>& z);
// The WidePlane of the row (a ⊙ P)·x <= b·L from the facet's and the point's (P, L) (a point as
// the four integers of homogeneous_integers, scaled alike); nothing when a product is unbounded.
std::optional<WidePlane> wide_row(const WidePlane& facet, const WidePlane& point);

// The meet of three independent planes in homogeneous integer coordinates (X, Y, Z, W), W of
// either sign: Cramer's rule, c_qr = a_q × a_r etc., W = a_p·c_qr, (X, Y, Z) = b_p c_qr + b_q c_rp
// + b_r c_pq, in place into `out` (scratch: three cross products kept by the caller).
void homogeneous_meet(const IntegerPlane3& p, const IntegerPlane3& q, const IntegerPlane3& r,
                      std::array<std::array<mpz_class, 3>, 3>& scratch, std::array<mpz_class, 4>& out);

// The truncated coordinates of the meet of three planes from their WidePlanes, when every
// coordinate's truncation is decided and in the range policy's range (non-zero coordinates within
// 2^±136), else nothing. `zero_axis[k]`: coordinate k is known to be exactly 0 (the vertex lies on
// the box side x_k >= 0), decided without arithmetic.
std::optional<LazyConvexSet3::TruncatedVertex> truncated_meet(const WidePlane& p, const WidePlane& q,
                                                              const WidePlane& r, const std::array<bool, 3>& zero_axis);

// An enclosure of the cross product a_s × a_u of two planes' normals.
using WideCross = std::array<numerics::DWEnclosure, 3>;
// a_s × a_u from the planes' WidePlanes, each component enclosed (dw_enclosure.h).
WideCross wide_cross(const WidePlane& s, const WidePlane& u);
// −c, exactly (each enclosure's midpoint negated: it encloses −x where c encloses x).
WideCross negated(const WideCross& c);
// truncated_meet with the three cross products given: c_qr ∋ a_q × a_r, c_rp ∋ a_r × a_p,
// c_pq ∋ a_p × a_q (any enclosures of them: wide_cross's, or one's negation for the planes the
// other way round, shared between vertices that meet on the same two planes). A decided
// truncation is the exact coordinate's, whichever enclosures decided it (docs/derivations.md
// §4.6: the enclosures contain the exact cross products, so X_k/W's enclosure contains x_k).
std::optional<LazyConvexSet3::TruncatedVertex> truncated_meet(const WidePlane& p, const WidePlane& q,
                                                              const WidePlane& r, const WideCross& c_qr,
                                                              const WideCross& c_rp, const WideCross& c_pq,
                                                              const std::array<bool, 3>& zero_axis);

// The exact planes of a set's vertices, kept so that each vertex's homogeneous coordinates can be
// made on request (LazyConvexSet3::from_truncated's maker): vertex i is the meet of planes
// meets[i], or given already in made[i] (W != 0). Plane k is planes[k], or, while rows[k].facet
// is set, the row (a ⊙ P)·x <= b·L of that facet a·x <= b and the point points[rows[k].point] =
// (P, L), made on first use (the facets kept alive by `owners`).
struct PlaneMeets {
  struct Row {
    const IntegerPlane3* facet = nullptr;
    std::size_t point = 0;
  };
  std::vector<IntegerPlane3> planes;
  std::vector<Row> rows;
  std::vector<std::array<mpz_class, 4>> points;
  std::vector<std::shared_ptr<const void>> owners;
  std::vector<std::array<int, 3>> meets;
  std::vector<std::array<mpz_class, 4>> made;
  std::array<std::array<mpz_class, 3>, 3> scratch;
  std::array<mpz_class, 4> homogeneous(std::size_t i);
  // Plane k, made now if it was not yet.
  const IntegerPlane3& plane(std::size_t k);
};

}  // namespace gmcc::internal
