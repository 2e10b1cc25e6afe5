#include <gmcc/geometry/enclosure.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_volume.h>

#include "internal/angle.h"

#include <cstddef>
#include <limits>
#include <stdexcept>

namespace gmcc {
namespace {
Rational dot(const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); }
bool is_zero(const Point3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }

// The filter of worst_case_map_deg_3d: (m·v)²/|v|² (cos² times |m|²) of every non-zero vertex in
// double enclosures (numerics/enclosure.h); the vertices whose value may reach the least upper
// end, in order (the smallest cos² is among them). All non-zero vertices where an enclosure is
// not finite.
std::vector<std::size_t> worst_case_contenders(const ConvexSet3& F, const Point3& m) {
  std::vector<std::size_t> nonzero;
  std::vector<Enclosure> value;
  const Enclosure3 em = enclose_point(m);
  bool finite = em[0].finite() && em[1].finite() && em[2].finite();
  double least_upper = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < F.vertices.size(); ++i) {
    const Point3& v = F.vertices[i];
    if (is_zero(v)) continue;
    nonzero.push_back(i);
    const Enclosure3 ev = enclose_point(v);
    const Enclosure mv = em[0] * ev[0] + em[1] * ev[1] + em[2] * ev[2];
    const Enclosure vv = ev[0] * ev[0] + ev[1] * ev[1] + ev[2] * ev[2];
    value.push_back(vv.positive() ? mv * mv / vv : Enclosure{0, Enclosure::unbounded});
    finite = finite && value.back().finite();
    if (finite) least_upper = std::min(least_upper, value.back().hi());
  }
  if (!finite) return nonzero;
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < nonzero.size(); ++k)
    if (value[k].lo() <= least_upper) out.push_back(nonzero[k]);
  return out;
}

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
  return internal::angle_deg({u.x, u.y, u.z}, {v.x, v.y, v.z});
}

double worst_case_map_deg_3d(const ConvexSet3& F, const Point3& m) {
  // Largest angle = smallest cos² = (m·v)²/(|m|²|v|²); m·v >= 0 on the octant, so compare
  // (m·v)²·|w|² against (m·w)²·|v|² exactly, among the filter's contenders (in vertex order, so
  // that ties go to the first vertex as over all of them).
  const Point3* worst = nullptr;
  for (std::size_t i : worst_case_contenders(F, m)) {
    const Point3& v = F.vertices[i];
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

Crule3d crule_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image, Crule3dRoute route) {
  Crule3d r;
  r.feasible = feasible_set_3d(canonical, image);
  if (route == Crule3dRoute::exact) r.volume = volume(r.feasible);
  if (r.feasible.kind == ConvexKind3::empty) return r;
  r.max_volume = with_worst_case(r.feasible, max_volume(r.feasible));
  r.centroid = with_worst_case(r.feasible, centroid_3(r.feasible, route));
  return r;
}

}  // namespace gmcc
