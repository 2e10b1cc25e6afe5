#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/numerics/may_be_largest.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_volume.h>

#include "internal/angle.h"

#include <array>
#include <cstddef>
#include <stdexcept>

namespace gmcc {
namespace {

// (m·v)²/|v|², which is cos²∠(m, v) times |m|², for v ≠ 0, in the kind of P: Point3 in ℚ (the
// exact comparisons) or Enclosure3 (the filter). Written once, so the filter encloses exactly
// what the exact stage compares.
template <class P, class T>
auto cos2_times_m2(const P& m, const P& v, const T& v2) {  // v2 = v·v
  const auto mv = dot(m, v);
  return decltype(mv)(mv * mv / v2);
}
template <class P>
auto cos2_times_m2(const P& m, const P& v) {
  return cos2_times_m2(m, v, dot(v, v));
}

// The filter of worst_case_map_deg_3d: the non-zero vertices whose cos² to m (as −(m·v)²/|v|²,
// cos² times −|m|², in double enclosures) may be the least, in vertex order.
std::vector<std::size_t> worst_case_contenders(const LazyConvexSet3& F, const Point3& m) {
  const std::vector<Enclosure3>& e = F.enclosures();
  std::vector<std::size_t> nonzero;
  std::vector<Enclosure> minus_cos2;
  nonzero.reserve(e.size());
  minus_cos2.reserve(e.size());
  const Enclosure3 em = enclose_point(m);
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (F.is_zero(i)) continue;
    nonzero.push_back(i);
    const Enclosure v2 = dot(e[i], e[i]);
    minus_cos2.push_back(certainly_positive(v2) ? -cos2_times_m2(em, e[i], v2) : Enclosure{0, Enclosure::unbounded});
  }
  std::vector<std::size_t> out = numerics::may_be_largest(minus_cos2);
  for (std::size_t& k : out) k = nonzero[k];
  return out;
}

}  // namespace

Selection3 with_worst_case(const ConvexSet3& F, MapEstimate3 e) {
  return with_worst_case(LazyConvexSet3(F), std::move(e));
}

Selection3 with_worst_case(const LazyConvexSet3& F, MapEstimate3 e) {
  const Point3 m = measured_map(e);
  Selection3 s{std::move(e), std::nullopt};
  bool nonzero_vertex = false;
  for (std::size_t i = 0; i < F.size(); ++i) nonzero_vertex = nonzero_vertex || !F.is_zero(i);
  if (!is_zero(m) && nonzero_vertex) s.worst_case_deg = worst_case_map_deg_3d(F, m);
  return s;
}

namespace {
// The primitive integer vector on u's ray (u times the lcm of its denominators, divided by the
// gcd of the results): the same for every positive multiple of u.
std::array<Rational, 3> ray_of(const Point3& u) {
  const mpz_class l = lcm_of_denominators_of(u.x, u.y, u.z);
  mpz_class z[3] = {times_lcm(u.x, l), times_lcm(u.y, l), times_lcm(u.z, l)};
  divide_by_content_of(z[0], z[1], z[2]);
  return {Rational(z[0]), Rational(z[1]), Rational(z[2])};
}
// A positive multiple of u's ray without a gcd: u_k times the other two denominators.
std::array<mpz_class, 3> multiple_of_ray(const Point3& u) {
  const mpz_class &d0 = u.x.get_den(), &d1 = u.y.get_den(), &d2 = u.z.get_den();
  return {u.x.get_num() * d1 * d2, u.y.get_num() * d0 * d2, u.z.get_num() * d0 * d1};
}
// The same for the point (X/W, Y/W, Z/W), W > 0, from its homogeneous integers: (X, Y, Z) divided
// by its content is that primitive vector, without the point's lowest terms.
std::array<Rational, 3> ray_of(const std::array<mpz_class, 4>& h) {
  mpz_class z[3] = {h[0], h[1], h[2]};
  divide_by_content_of(z[0], z[1], z[2]);
  return {Rational(z[0]), Rational(z[1]), Rational(z[2])};
}
}  // namespace

double diagonal_map_angular_error_deg(const Point3& u, const Point3& v) {
  if (is_zero(u) || is_zero(v))
    throw std::invalid_argument("diagonal_map_angular_error_deg: a zero map has no direction");
  // Rays, not points: the same angle, rounded the same way, for every positive multiple of
  // either map (so that a worst case and an error to the same ray are equal doubles).
  return internal::angle_deg(ray_of(u), ray_of(v));
}

double worst_case_map_deg_3d(const ConvexSet3& F, const Point3& m) {
  return worst_case_map_deg_3d(LazyConvexSet3(F), m);
}

double worst_case_map_deg_3d(const LazyConvexSet3& F, const Point3& m) {
  // Largest angle = smallest cos² = (m·v)²/(|m|²|v|²) (m·v >= 0 on the octant), compared exactly
  // among the filter's contenders (in vertex order, so that ties go to the first vertex as over
  // all of them); a lone contender is the worst vertex without a comparison.
  const std::vector<std::size_t> contenders = worst_case_contenders(F, m);
  if (contenders.size() == 1 && !is_zero(m)) {  // diagonal_map_angular_error_deg's rays (a non-zero vertex)
    // Their double from any multiples when the filter settles it (ray_angle_deg), else from the
    // rays themselves.
    const std::array<mpz_class, 4>& h = F.homogeneous(contenders[0]);
    const std::array<mpz_class, 3> mm = multiple_of_ray(m);
    if (const std::optional<double> deg = internal::ray_angle_deg({&mm[0], &mm[1], &mm[2]}, {&h[0], &h[1], &h[2]}))
      return *deg;
    return internal::angle_deg(ray_of(m), ray_of(h));
  }
  const Point3* worst = nullptr;
  Rational worst_cos2;
  for (std::size_t i : contenders) {
    const Point3& v = F.vertex(i);
    Rational cos2 = cos2_times_m2(m, v);
    if (!worst || cos2 < worst_cos2) worst = &v, worst_cos2 = std::move(cos2);
  }
  if (!worst || is_zero(m)) throw std::invalid_argument("worst_case_map_deg_3d: no direction");
  return diagonal_map_angular_error_deg(m, *worst);
}

Crule3d crule_3d(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                 CanonicalBlack black) {
  return crule_3d(CanonicalConstraints3(canonical, black), image);
}

Crule3dSelections crule_3d_selections(const LazyConvexSet3& F3, Crule3dRoute route) {
  Crule3dSelections s;
  if (F3.kind() != ConvexKind3::empty) {
    s.max_volume = with_worst_case(F3, max_volume(F3));
    s.centroid = with_worst_case(F3, centroid_3(F3, route));
  }
  return s;
}

Crule3d crule_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image, Crule3dRoute route) {
  Crule3d r;
  const LazyConvexSet3 F = feasible_set_3d_lazy({{&canonical, &image}});
  Crule3dSelections s = crule_3d_selections(F, route);
  r.max_volume = std::move(s.max_volume), r.centroid = std::move(s.centroid);
  r.feasible = F.exact();
  if (route == Crule3dRoute::exact) r.volume = volume(r.feasible);
  return r;
}

}  // namespace gmcc
