// scene_record: select_scene's result in the record form (select_scene_record.h), the exact route
// of select_scene_record.

#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/select_scene_record.h>

#include "internal/angle.h"
#include "internal/record_values.h"

#include <stdexcept>

namespace gmcc {
namespace {

using internal::record_angle;

// q as a double enclosure, of radius 0 when q is a double.
Enclosure enclose_exact(const Rational& q) {
  const Enclosure e = enclose_rational(q);
  return e.finite() && Rational(e.mid) == q ? Enclosure::exact(e.mid) : e;
}

// The 3-D mean's enclosure from its estimate (the closed form's certified [lo, hi]; a point's
// exact map).
std::array<Enclosure, 2> estimate_enclosure(const MapEstimate& m) {
  if (m.exact) return {enclose_exact(m.exact->x), enclose_exact(m.exact->y)};
  if (!m.enclosure)
    throw std::invalid_argument("scene_record: the 3-D mean has no enclosure (the record needs the closed form)");
  return {Enclosure::between((*m.enclosure)[0][0], (*m.enclosure)[0][1]),
          Enclosure::between((*m.enclosure)[1][0], (*m.enclosure)[1][1])};
}

// How far each kind of angle can move between the measured map m̂ (the estimate's double map,
// exact) and the exact map in `exact`: by the triangle inequality on the sphere, an angle from
// one direction moves by at most the angle between the two directions — in map space (lifted
// maps), illuminant space (c ⊘ (m, 1)) and for the reproduction error (m ⊘ t lifted). Zero when
// the estimate is rational (measured at the exact map).
struct Shift {
  double map = 0, illuminant = 0, reproduction = 0;
};
Shift shift(const MapEstimate& m, const std::array<Enclosure, 2>& exact, const Colour& c, const Point2* truth) {
  if (m.exact) return {};
  const Enclosure one = Enclosure::exact(1), a = Enclosure::exact(m.map[0]), b = Enclosure::exact(m.map[1]);
  Shift s;
  s.map = internal::enclosed_angle_deg<Enclosure>({exact[0], exact[1], one}, {a, b, one}).hi();
  if (m.map[0] > 0 && m.map[1] > 0) {
    const std::array<Enclosure, 3> ce{enclose_rational(c.r), enclose_rational(c.g), enclose_rational(c.b)};
    s.illuminant = internal::enclosed_angle_deg<Enclosure>({ce[0] / exact[0], ce[1] / exact[1], ce[2]},
                                                           {ce[0] / a, ce[1] / b, ce[2]}).hi();
    if (truth) {
      const Enclosure t1 = enclose_rational(truth->x), t2 = enclose_rational(truth->y);
      s.reproduction = internal::enclosed_angle_deg<Enclosure>({exact[0] / t1, exact[1] / t2, one},
                                                               {a / t1, b / t2, one}).hi();
    }
  }
  return s;
}

}  // namespace

SelectRecord scene_record(const SceneResult& r, const Colour& c) {
  SelectRecord out;
  out.exact_route = true;
  out.image_colours = r.image_colours;
  out.image_dropped = r.image_dropped;
  out.kind = r.feasible.kind;
  for (const Point2& v : r.feasible.vertices) out.vertices.push_back({enclose_exact(v.x), enclose_exact(v.y)});
  out.empty_reason = r.empty_reason;
  out.illuminants = r.constraint ? r.constraint->illuminants : 0;
  out.recovery = r.recovery;
  const Point2* truth = r.truth ? &r.truth->map : nullptr;
  if (r.truth) out.truth.emplace().in_feasible_set = r.truth->in_feasible_set;
  for (Rule rule : all_rules) {
    const std::optional<Selection>& s = r.selections[rule];
    if (!s) continue;
    const std::array<Enclosure, 2> map = estimate_enclosure(s->estimate);
    const Shift d = shift(s->estimate, map, c, truth);
    RecordSelection& rs = out.selections[rule].emplace();
    rs.map = map;
    GMCC_CHECK(s->worst_case_deg.has_value(), "scene_record: the closed form always gives a worst case");
    rs.worst_case_deg = record_angle(*s->worst_case_deg, d.map);
    if (s->worst_case_illuminant_deg) rs.worst_case_illuminant_deg = record_angle(*s->worst_case_illuminant_deg, d.illuminant);
    if (!r.truth || !r.truth->errors[rule]) continue;
    const RuleErrors& e = *r.truth->errors[rule];
    RecordErrors& re = out.truth->errors[rule].emplace();
    re.map_error_deg = record_angle(e.map_error_deg, d.map);
    if (e.positive_map) {
      re.illuminant_error_deg = record_angle(e.illuminant_error_deg, d.illuminant);
      re.reproduction_error_deg = record_angle(e.reproduction_error_deg, d.reproduction);
    }
  }
  return out;
}

}  // namespace gmcc
