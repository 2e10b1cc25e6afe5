#include <gmcc/selection/certified_rule_errors.h>

#include "internal/certified_rule.h"

#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
using internal::enclose;
using internal::in_range;

// One stage: every value in enclosures of type E, from F's vertex enclosures v.
template <class E, class V>
std::optional<PerRule<RuleErrors>> stage(const std::vector<V>& v, const std::vector<ApproximateLine>& edges,
                                               const Point2& truth, const Colour& canonical_illuminant) {
  for (const V& p : v)
    if (!in_range(p.x) || !in_range(p.y)) return std::nullopt;
  const E t1 = enclose<E>(truth.x), t2 = enclose<E>(truth.y);
  const E cr = enclose<E>(canonical_illuminant.r), cg = enclose<E>(canonical_illuminant.g),
          cb = enclose<E>(canonical_illuminant.b);
  for (const E* x : {&t1, &t2, &cr, &cg, &cb})
    if (!in_range(*x)) return std::nullopt;
  PerRule<RuleErrors> out{};
  std::vector<E> keys;
  keys.reserve(v.size());
  const std::optional<std::array<E, 2>> t{std::array<E, 2>{t1, t2}};
  for (Rule r : all_rules) {
    const std::optional<internal::CertifiedRule<E>> k = internal::certified_rule<E>(r, v, edges, t, {cr, cg, cb}, keys);
    if (!k) return std::nullopt;
    RuleErrors& e = out[r];
    e.map_error_deg = static_cast<double>(k->error->mid);
    e.worst_case_deg = static_cast<double>(k->worst.mid);
    e.map = {static_cast<double>(k->map[0].mid), static_cast<double>(k->map[1].mid)};
    e.positive_map = k->positive_map;
    if (e.positive_map) {
      e.illuminant_error_deg = static_cast<double>(k->illuminant->mid);
      e.reproduction_error_deg = static_cast<double>(k->reproduction->mid);
    }
  }
  return out;
}

}  // namespace

std::optional<PerRule<RuleErrors>> certified_rule_errors(const FeasiblePolygon& F, const Point2& truth,
                                                        const Colour& canonical_illuminant) {
  for (const Rational* x : {&truth.x, &truth.y, &canonical_illuminant.r, &canonical_illuminant.g, &canonical_illuminant.b})
    if (sgn(*x) <= 0) throw std::invalid_argument("certified_rule_errors: the true map and the illuminant must be > 0");
  if (!F.enclosed()) return std::nullopt;
  if (auto out = stage<Enclosure>(F.vertices(), F.edges(), truth, canonical_illuminant)) return out;
  // Thin sets (F ∩ C along the daylight locus, small cones): the same in extended precision,
  // from vertex enclosures about 2^11 times tighter.
  if (numerics::extended_precision_active() && !F.extended_vertices().empty())
    return stage<LongEnclosure>(F.extended_vertices(), F.edges(), truth, canonical_illuminant);
  return std::nullopt;
}

}  // namespace gmcc
