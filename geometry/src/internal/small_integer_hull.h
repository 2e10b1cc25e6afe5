#pragma once
// The traits under which CGAL's 3-D hull (convex_hull_3, extreme_points_3) runs on pixel colours:
// points whose channels are integers in [0, 2^16), held as doubles, every predicate the hull asks
// evaluated exactly in 64-bit integers (docs/math.md §1b "The prepared route"). Internal to
// gmcc::geometry; included only by CGAL translation units.
//
// Why not Epick: its filtered predicates are exact too, but on integer pixel colours many points
// lie exactly on a candidate plane or tie in distance, where its interval filter fails and every
// such test is redone in GMP rationals. Here no test needs more than 51 bits.
//
// The bounds: a coordinate difference has |d| < 2^16; a 2 × 2 minor of differences is below 2^33
// in magnitude; a 3 × 3 determinant of differences (orientation, comparing signed distances to a
// plane) is a sum of three minors times differences, below 3·2^49 < 2^51; a squared distance is
// below 3·2^32. All fit in std::int64_t with room to spare.

#include <CGAL/Convex_hull_traits_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/enum.h>

#include <cstdint>

namespace gmcc::internal {

/// Simple_cartesian<double>'s types and constructions, with the predicates convex_hull_3 calls
/// replaced by exact integer ones. Only for points whose coordinates are small_integer
/// (crule_exact.h).
struct SmallIntegerKernel : CGAL::Simple_cartesian<double> {
  using Base = CGAL::Simple_cartesian<double>;
  using Point_3 = Base::Point_3;
  using I = std::int64_t;

  struct Diff {
    I x, y, z;
  };
  static Diff diff(const Point_3& a, const Point_3& b) {
    return {static_cast<I>(a.x()) - static_cast<I>(b.x()), static_cast<I>(a.y()) - static_cast<I>(b.y()),
            static_cast<I>(a.z()) - static_cast<I>(b.z())};
  }
  // sign det[a; b; c] for rows of differences (|entries| < 2^16: below 2^51, see above).
  static int sign_det(const Diff& a, const Diff& b, const Diff& c) {
    const I d = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
    return (d > 0) - (d < 0);
  }

  struct Orientation_3 {
    using result_type = CGAL::Orientation;
    // CGAL's convention: the sign of det[q − p; r − p; s − p].
    CGAL::Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) const {
      return static_cast<CGAL::Orientation>(sign_det(diff(q, p), diff(r, p), diff(s, p)));
    }
  };
  struct Coplanar_3 {
    using result_type = bool;
    bool operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) const {
      return Orientation_3()(p, q, r, s) == CGAL::COPLANAR;
    }
  };
  struct Collinear_3 {
    using result_type = bool;
    // (q − p) × (r − p) = 0: three 2 × 2 minors, each below 2^33.
    bool operator()(const Point_3& p, const Point_3& q, const Point_3& r) const {
      const Diff a = diff(q, p), b = diff(r, p);
      return a.y * b.z == a.z * b.y && a.z * b.x == a.x * b.z && a.x * b.y == a.y * b.x;
    }
  };
  struct Less_distance_to_point_3 {
    using result_type = bool;
    // |q − p|² < |r − p|², each below 3·2^32.
    bool operator()(const Point_3& p, const Point_3& q, const Point_3& r) const {
      const Diff a = diff(q, p), b = diff(r, p);
      return a.x * a.x + a.y * a.y + a.z * a.z < b.x * b.x + b.y * b.y + b.z * b.z;
    }
  };
  struct Less_signed_distance_to_plane_3 {
    using result_type = bool;
    // s is nearer the negative side of plane (p, q, r) than t: n·(s − t) < 0 for
    // n = (q − p) × (r − p), i.e. det[q − p; r − p; s − t] < 0 (CGAL's cmp_signed_dist_to_planeC3).
    bool operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s, const Point_3& t) const {
      return sign_det(diff(q, p), diff(r, p), diff(s, t)) < 0;
    }
  };

  Orientation_3 orientation_3_object() const { return {}; }
  Coplanar_3 coplanar_3_object() const { return {}; }
  Collinear_3 collinear_3_object() const { return {}; }
  Less_distance_to_point_3 less_distance_to_point_3_object() const { return {}; }
  Less_signed_distance_to_plane_3 less_signed_distance_to_plane_3_object() const { return {}; }
};

/// convex_hull_3's traits over SmallIntegerKernel (no filtering: the predicates are exact).
using SmallIntegerHullTraits = CGAL::Convex_hull_traits_3<SmallIntegerKernel, CGAL::Default, CGAL::Tag_false>;

}  // namespace gmcc::internal
