// select_scene_record: the record form from enclosures of F's vertices (select_scene_record.h).

#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/select_scene_record.h>
#include <gmcc/selection/worst_case_illuminant.h>

#include "internal/certified_rule.h"
#include "internal/empty_reason.h"
#include "internal/illuminant_filters.h"
#include "internal/record_values.h"
#include "internal/scene_chromaticities.h"

#include <algorithm>
#include <stdexcept>

namespace gmcc {
namespace {

using internal::accurate;
using internal::enclose;
using internal::in_range;
using internal::to_double;
using Enclosure2 = std::array<Enclosure, 2>;
using Enclosure3 = std::array<Enclosure, 3>;

// The illuminant-space worst case at the exact map enclosed by m, from F's vertex enclosures v
// (docs/derivations.md §3.2). The maximum over F is at a vertex or at a stationary point inside an
// edge; when every edge passes a filter of illuminant_filters.h (no stationary point, or a
// closeness certainly above the least vertex closeness, on each dyadic piece holding a stationary
// point, or its polynomial's Bernstein coefficients showing no interior maximum) no edge point
// beats the best vertex, and the worst case is the largest vertex angle:
// enclosed by the largest ends among the vertices whose closeness may be the least. Nothing when
// an edge may hold it or an enclosure is too wide. \pre m and v certainly > 0.
std::optional<Enclosure> enclosed_illuminant_worst_case(const std::vector<EnclosedVertex>& v, const Enclosure2& m,
                                                        const Enclosure3& c, std::vector<Enclosure>& keys) {
  const Enclosure3 e{c[0] / m[0], c[1] / m[1], c[2]};
  keys.clear();
  double least_upper = Enclosure::unbounded;
  for (const EnclosedVertex& p : v) {
    keys.push_back(internal::closeness_of(e, c, p.x, p.y));
    if (!keys.back().finite()) return std::nullopt;
    least_upper = std::min(least_upper, keys.back().hi());
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    const EnclosedVertex &p = v[i], &q = v[(i + 1) % v.size()];
    if (!internal::edge_cannot_be_worst(e, c, p.x, p.y, q.x, q.y, least_upper) &&
        !internal::no_interior_maximum_bernstein(e, c, p.x, p.y, q.x, q.y) &&
        !internal::edge_skippable(e, c, p.x, p.y, q.x - p.x, q.y - p.y, 0, 1, least_upper, 8))
      return std::nullopt;
  }
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (keys[i].lo() > least_upper) continue;  // certainly a smaller angle than another vertex's
    const Enclosure a = internal::enclosed_angle_deg<Enclosure>(e, {c[0] / v[i].x, c[1] / v[i].y, c[2]});
    lo = std::max(lo, a.lo()), hi = std::max(hi, a.hi());
  }
  const Enclosure worst = Enclosure::between(lo, hi);
  if (!accurate(worst)) return std::nullopt;
  return worst;
}

// The same by the exact route, where the enclosures cannot decide: worst_case_illuminant on the
// exact F at m̂ = m's midpoint (exact doubles), widened by the angle between the illuminants of
// m̂ and of the exact map (the triangle inequality). Absent (an empty inner optional) when F
// touches an axis; nothing when the widened value is not within the accuracy.
std::optional<std::optional<Enclosure>> exact_illuminant_worst_case(const FeasiblePolygon& P, const Enclosure2& m,
                                                                    const Colour& c, const Enclosure3& ce) {
  const ConvexSet2& F = P.exact();
  for (const Point2& x : F.vertices)
    if (sgn(x.x) <= 0 || sgn(x.y) <= 0) return std::optional<Enclosure>{};
  if (!(m[0].mid > 0) || !(m[1].mid > 0)) return std::nullopt;
  const double deg = worst_case_illuminant_deg(F, {Rational(m[0].mid), Rational(m[1].mid)}, c);
  const Enclosure shift = internal::enclosed_angle_deg<Enclosure>(
      {ce[0] / m[0], ce[1] / m[1], ce[2]}, {ce[0] / Enclosure::exact(m[0].mid), ce[1] / Enclosure::exact(m[1].mid), ce[2]});
  const Enclosure w{deg, Enclosure::round_up(std::fabs(deg) * internal::exact_route_accuracy + shift.hi())};
  if (!shift.finite() || !accurate(w)) return std::nullopt;
  return std::optional<Enclosure>{w};
}

// Every rule's certified values in enclosures of type E from F's vertex enclosures v: nothing when
// any is uncertain (certified_rule).
template <class E, class V>
std::optional<PerRule<internal::CertifiedRule<E>>> rule_stage(const std::vector<V>& v, const std::vector<ApproximateLine>& edges,
                                                              const std::optional<Point2>& truth, const Colour& c) {
  for (const V& p : v)
    if (!in_range(p.x) || !in_range(p.y)) return std::nullopt;
  std::optional<std::array<E, 2>> t;
  if (truth) t = std::array<E, 2>{enclose<E>(truth->x), enclose<E>(truth->y)};
  const std::array<E, 3> ce{enclose<E>(c.r), enclose<E>(c.g), enclose<E>(c.b)};
  for (const E& x : ce)
    if (!in_range(x)) return std::nullopt;
  if (t && (!in_range((*t)[0]) || !in_range((*t)[1]))) return std::nullopt;
  PerRule<internal::CertifiedRule<E>> out;
  std::vector<E> keys;
  for (Rule r : all_rules) {
    auto k = internal::certified_rule<E>(r, v, edges, t, ce, keys);
    if (!k) return std::nullopt;
    out[r] = std::move(*k);
  }
  return out;
}

// The record's selections and errors from one stage's values; the illuminant-space worst cases
// from F's double vertex enclosures, by the exact route where they cannot decide. Nothing when
// that too fails the accuracy.
template <class E>
bool fill(SelectRecord& out, const PerRule<internal::CertifiedRule<E>>& values, const FeasiblePolygon& P,
          const Colour& c, bool illuminant_worst_case) {
  const Enclosure3 ce{enclose_rational(c.r), enclose_rational(c.g), enclose_rational(c.b)};
  const std::vector<EnclosedVertex>& v = P.vertices();
  const bool positive_set = std::all_of(v.begin(), v.end(), [](const EnclosedVertex& p) {
    return certainly_positive(p.x) && certainly_positive(p.y);
  });
  std::vector<Enclosure> keys;
  for (Rule r : all_rules) {
    const internal::CertifiedRule<E>& k = values[r];
    RecordSelection& s = out.selections[r].emplace();
    s.map = {to_double(k.map[0]), to_double(k.map[1])};
    s.worst_case_deg = to_double(k.worst);
    if (illuminant_worst_case && k.positive_map) {
      std::optional<Enclosure> w;
      if (positive_set) w = enclosed_illuminant_worst_case(v, s.map, ce, keys);
      if (w) {
        s.worst_case_illuminant_deg = w;
      } else {
        const auto exact = exact_illuminant_worst_case(P, s.map, c, ce);
        if (!exact) return false;
        s.worst_case_illuminant_deg = *exact;
      }
    }
    if (!out.truth) continue;
    RecordErrors& e = out.truth->errors[r].emplace();
    e.map_error_deg = to_double(*k.error);
    if (k.positive_map) e.illuminant_error_deg = to_double(*k.illuminant), e.reproduction_error_deg = to_double(*k.reproduction);
  }
  return true;
}

// The index of F's lexicographically least vertex (x, then y), where the exact set's
// counter-clockwise order starts, when the enclosures certify it: a vertex is certainly below
// another when its x enclosure is, or when the two share an edge parallel to the y axis (b = 0 in
// its double copy, whose signs are exact: then the x are equal) and its y enclosure is below.
// Nothing when some pair is undecided (the exact route orders them).
std::optional<std::size_t> least_vertex(const std::vector<EnclosedVertex>& v, const std::vector<ApproximateLine>& edges) {
  const std::size_t n = v.size();
  // -1: a certainly before b; 1: b certainly before a; 0: not decided here.
  auto order = [&](std::size_t a, std::size_t b) {
    if (v[a].x.hi() < v[b].x.lo()) return -1;
    if (v[b].x.hi() < v[a].x.lo()) return 1;
    const bool vertical = (b == (a + 1) % n && edges[a].b == 0) || (a == (b + 1) % n && edges[b].b == 0);
    if (!vertical) return 0;
    if (v[a].y.hi() < v[b].y.lo()) return -1;
    if (v[b].y.hi() < v[a].y.lo()) return 1;
    return 0;
  };
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const int o = order(best, i);
    if (o == 0) return std::nullopt;
    if (o > 0) best = i;
  }
  return best;  // below every vertex after it, and below those before it by transitivity
}

// The record from enclosures of the polygon P, or nothing where they cannot decide.
std::optional<SelectRecord> enclosure_route(const FeasiblePolygon& P, const std::optional<Point2>& truth,
                                           const Colour& c, bool illuminant_worst_case) {
  if (!P.enclosed()) return std::nullopt;
  const std::vector<EnclosedVertex>& v = P.vertices();
  const std::optional<std::size_t> first = least_vertex(v, P.edges());
  if (!first) return std::nullopt;
  SelectRecord out;
  out.kind = ConvexKind::polygon;
  if (truth) out.truth.emplace().in_feasible_set = P.contains(*truth);
  if (const auto values = rule_stage<Enclosure>(P.vertices(), P.edges(), truth, c)) {
    if (!fill(out, *values, P, c, illuminant_worst_case)) return std::nullopt;
  } else if (numerics::extended_precision_active() && !P.extended_vertices().empty()) {
    // Thin sets: the same in extended precision, from vertex enclosures about 2^11 times tighter.
    const auto long_values = rule_stage<LongEnclosure>(P.extended_vertices(), P.edges(), truth, c);
    if (!long_values || !fill(out, *long_values, P, c, illuminant_worst_case)) return std::nullopt;
  } else {
    return std::nullopt;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    const EnclosedVertex& p = v[(*first + i) % v.size()];
    out.vertices.push_back({p.x, p.y});
  }
  return out;
}

}  // namespace

SelectRecord select_scene_record(const PreparedCanonical& pc, const std::vector<Colour>& image,
                                const std::optional<Colour>& truth, const SceneChoices& choices) {
  check_options(choices.mean3d);
  if (choices.mean3d.method != Mean3dMethod::analytic || choices.mean3d.precision_bits != 0)
    throw OptionError("mean3d", "the record form scores the exact 3-D mean: its route must be the closed form "
                                "(analytic) at the automatic precision");
  const SelectSceneOptions& o = pc.options;
  auto exact_route = [&] { return scene_record(select_scene(pc, image, truth, choices), o.canonical_illuminant); };
  std::optional<Point2> true_map;
  if (truth) {
    if (sgn(truth->r) <= 0 || sgn(truth->g) <= 0 || sgn(truth->b) <= 0) return exact_route();  // it throws
    true_map = illuminant_map(*truth, o.canonical_illuminant);
  }
  const Chromaticities iq = internal::scene_chromaticities(image, o.nonpositive_blue, SceneInput::image);
  // F (F ∩ C in one pass with illuminants) and, with them, F alone: for the reason an F ∩ C is
  // empty, and for the range the exact route checks on both (vertices certainly below 2^100).
  FeasiblePolygon P, U;
  try {
    P = feasible_polygon(pc.constrained ? *pc.constrained : pc.constraints, iq.points);
    if (pc.constrained) U = feasible_polygon(pc.constraints, iq.points);
  } catch (const UnboundedFeasibleSet& e) {
    throw SceneInputError(SceneInput::image, SceneProblem::unbounded, std::nullopt, e.what());
  }
  if (pc.constrained && U.kind() != ConvexKind::empty &&
      (!U.enclosed() || !std::all_of(U.vertices().begin(), U.vertices().end(), [](const EnclosedVertex& v) {
        return in_range(v.x) && in_range(v.y);
      })))
    return exact_route();
  std::optional<SelectRecord> out;
  if (P.kind() != ConvexKind::empty) {
    out = enclosure_route(P, true_map, o.canonical_illuminant, choices.illuminant_worst_case);
  } else if (o.on_empty == RecoveryPolicy::none) {
    out.emplace().empty_reason = internal::empty_reason(!pc.constrained || U.kind() == ConvexKind::empty);
    if (truth) out->truth.emplace();
  }
  if (!out) return exact_route();
  out->image_colours = image.size();
  out->image_dropped = iq.dropped;
  out->illuminants = pc.constrained ? o.illuminants->size() : 0;
  return *out;
}

}  // namespace gmcc
