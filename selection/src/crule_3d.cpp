#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_volume.h>

#include <mpfr.h>

#include <stdexcept>

namespace gmcc {
namespace {
Rational dot(const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); }
bool is_zero(const Point3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }

Selection3 with_worst_case(const ConvexSet3& F, MapEstimate3 e) {
  const Point3 m = measured_map(e);
  Selection3 s{std::move(e), std::nullopt};
  bool nonzero_vertex = false;
  for (const Point3& v : F.vertices) nonzero_vertex = nonzero_vertex || !is_zero(v);
  if (!is_zero(m) && nonzero_vertex) s.worst_case_deg = worst_case_map_deg_3d(F, m);
  return s;
}
}  // namespace

double diagonal_map_angular_error_deg(const Point3& u, const Point3& v) {
  if (is_zero(u) || is_zero(v))
    throw std::invalid_argument("diagonal_map_angular_error_deg: a zero map has no direction");
  const Rational c0 = u.y * v.z - u.z * v.y, c1 = u.z * v.x - u.x * v.z, c2 = u.x * v.y - u.y * v.x;
  const Rational cross2 = c0 * c0 + c1 * c1 + c2 * c2;
  const Rational d = dot(u, v);
  mpfr_t s, c, a, pi;
  mpfr_inits2(128, s, c, a, pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(s, cross2.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(s, s, MPFR_RNDN);
  mpfr_set_q(c, d.get_mpq_t(), MPFR_RNDN);
  mpfr_atan2(a, s, c, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_mul_ui(a, a, 180, MPFR_RNDN);
  mpfr_div(a, a, pi, MPFR_RNDN);
  const double deg = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clears(s, c, a, pi, static_cast<mpfr_ptr>(nullptr));
  return deg;
}

double worst_case_map_deg_3d(const ConvexSet3& F, const Point3& m) {
  // Largest angle = smallest cos² = (m·v)²/(|m|²|v|²); m·v >= 0 on the octant, so compare
  // (m·v)²·|w|² against (m·w)²·|v|² exactly.
  const Point3* worst = nullptr;
  for (const Point3& v : F.vertices) {
    if (is_zero(v)) continue;
    if (!worst) {
      worst = &v;
      continue;
    }
    const Rational dv = dot(m, v), dw = dot(m, *worst);
    if (dv * dv * dot(*worst, *worst) < dw * dw * dot(v, v)) worst = &v;
  }
  if (!worst || is_zero(m)) throw std::invalid_argument("worst_case_map_deg_3d: no direction");
  return diagonal_map_angular_error_deg(m, *worst);
}

Crule3d crule_3d(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                 CanonicalBlack black) {
  return crule_3d(CanonicalConstraints3(canonical, black), image);
}

Crule3d crule_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image) {
  Crule3d r;
  r.feasible = feasible_set_3d(canonical, image);
  r.volume = volume(r.feasible);
  if (r.feasible.kind == ConvexKind3::empty) return r;
  r.max_volume = with_worst_case(r.feasible, max_volume(r.feasible));
  r.centroid = with_worst_case(r.feasible, exact_map_estimate_3("centroid", centroid(r.feasible)));
  return r;
}

}  // namespace gmcc
