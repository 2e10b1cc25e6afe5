// The projection of a colour onto a polygonal cone, exactly (cone_distance.h; docs/math.md §1f).
#include <gmcc/geometry/cone_distance.h>

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/enclosure.h>

#include <stdexcept>
#include <utility>

namespace gmcc {

PolygonalCone::PolygonalCone(std::vector<Point3> generators) : g_(std::move(generators)) {
  if (g_.empty()) throw std::invalid_argument("a cone needs at least one generator");
  for (const Point3& g : g_) {
    if (is_zero(g)) throw std::invalid_argument("a cone's generator is zero");
    gg_.push_back(dot(g, g));
  }
  const std::size_t m = g_.size();
  const std::size_t facets = m == 1 ? 0 : m == 2 ? 1 : m;
  for (std::size_t k = 0; k < facets; ++k) {
    const Point3& a = g_[k];
    const Point3& b = g_[(k + 1) % m];
    n_.push_back(cross(a, b));
    nn_.push_back(dot(n_.back(), n_.back()));
    gnext_.push_back(dot(a, b));
    const Point3& n = n_.back();
    n_double_.push_back({to_double_nearest(n.x), to_double_nearest(n.y), to_double_nearest(n.z)});
    // Parallel generators span no facet; opposite ones no pointed cone.
    if (sgn(nn_.back()) == 0)
      throw std::invalid_argument(sgn(gnext_.back()) < 0 ? "a cone's generators are opposite"
                                                         : "a cone's consecutive generators are parallel");
  }
}

bool PolygonalCone::contains(const Point3& p) const {
  return contains(p, {to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)});
}

bool PolygonalCone::contains(const Point3& p, const std::array<double, 3>& p_nearest) const {
  if (g_.size() < 3) return sgn(project_onto_cone(p, *this).squared_distance) == 0;
  using E = numerics::BasicEnclosure<double>;
  const E q[3] = {E::relative(p_nearest[0], E::u), E::relative(p_nearest[1], E::u), E::relative(p_nearest[2], E::u)};
  for (std::size_t k = 0; k < n_.size(); ++k) {
    const std::array<double, 3>& n = n_double_[k];
    const E s = E::relative(n[0], E::u) * q[0] + E::relative(n[1], E::u) * q[1] + E::relative(n[2], E::u) * q[2];
    const numerics::UncertainSign sign = numerics::sign(s);
    if (sign.lo >= 0) continue;        // certainly >= 0
    if (sign.hi < 0) return false;     // certainly < 0
    if (sgn(dot(p, n_[k])) < 0) return false;
  }
  return true;
}

namespace {

// The better of the current candidate and (q, d²).
void keep_nearer(ConeProjection& best, Point3 q, Rational d2) {
  if (d2 < best.squared_distance) best = {std::move(q), std::move(d2)};
}

}  // namespace

ConeProjection project_onto_cone(const Point3& p, const PolygonalCone& cone) {
  const std::size_t m = cone.g_.size();
  std::vector<Rational> pn(cone.n_.size());
  bool inside = m >= 3;
  for (std::size_t k = 0; k < cone.n_.size(); ++k) {
    pn[k] = dot(p, cone.n_[k]);
    if (sgn(pn[k]) < 0) inside = false;
  }
  if (inside) return {p, Rational(0)};
  const Rational pp = dot(p, p);
  ConeProjection best{Point3{Rational(0), Rational(0), Rational(0)}, pp};  // the apex
  std::vector<Rational> pg(m);
  for (std::size_t k = 0; k < m; ++k) {
    pg[k] = dot(p, cone.g_[k]);
    if (sgn(pg[k]) > 0) {
      const Rational t = pg[k] / cone.gg_[k];
      keep_nearer(best, scale(cone.g_[k], t), Rational(pp - t * pg[k]));
    }
  }
  // A facet's candidate: only where p lies outside it (m >= 3) — the nearest point of a facet's
  // relative interior is reached along its outward normal — or on either side of a wedge's plane.
  for (std::size_t k = 0; k < cone.n_.size(); ++k) {
    if (m >= 3 && sgn(pn[k]) >= 0) continue;
    const std::size_t j = (k + 1) % m;
    // Gram system [gg_k, c; c, gg_j] (α, β) = (pg_k, pg_j), determinant |n_k|² > 0.
    const Rational alpha = cone.gg_[j] * pg[k] - cone.gnext_[k] * pg[j];
    const Rational beta = cone.gg_[k] * pg[j] - cone.gnext_[k] * pg[k];
    if (sgn(alpha) < 0 || sgn(beta) < 0) continue;
    const Rational s = pn[k] / cone.nn_[k];
    keep_nearer(best, sub(p, scale(cone.n_[k], s)), Rational(s * pn[k]));
  }
  return best;
}

}  // namespace gmcc
