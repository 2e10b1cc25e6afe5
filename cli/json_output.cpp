#include "json_output.h"

#include "provenance.h"

#include <gmcc/geometry/rational.h>

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstdio>
#include <sstream>

namespace gmcc::cli {
namespace {

Json exact_pair(const Point2& p) { return Json::array({to_string(p.x), to_string(p.y)}); }
Json approx_pair(const Point2& p) {
  const auto d = to_double_nearest(p);
  return Json::array({d[0], d[1]});
}

Json convex_set_json(const ConvexSet2& s) {
  Json vertices = Json::array(), approx = Json::array();
  for (const Point2& v : s.vertices) {
    vertices.push_back(exact_pair(v));
    approx.push_back(approx_pair(v));
  }
  Json j;
  j["kind"] = to_string(s.kind);
  j["vertices"] = vertices;
  j["vertices_approx"] = approx;
  j["area"] = to_string(area(s));
  return j;
}

Json pair(const std::array<double, 2>& p) { return Json::array({p[0], p[1]}); }

Json selection_json(const Selection& s) {
  const MapEstimate& e = s.estimate;
  Json j;
  if (!e.valid) {  // no map: say why, with what was tried
    j["map"] = nullptr;
    j["error_bound"] = nullptr;
    j["error_bounds"] = nullptr;
    j["method"] = e.method;
    j["note"] = e.note;
  } else {
    j["map"] = pair(e.map);
    if (e.exact) j["map_exact"] = exact_pair(*e.exact);
    j["error_bound"] = e.error_bound;
    j["error_bounds"] = pair(e.error_bounds);
    j["correctly_rounded"] = Json::array({e.correctly_rounded[0], e.correctly_rounded[1]});
    if (e.enclosure) j["enclosure"] = Json::array({pair((*e.enclosure)[0]), pair((*e.enclosure)[1])});
    j["method"] = e.method;
    if (!e.note.empty()) j["note"] = e.note;
  }
  if (e.precision_bits) j["precision_bits"] = e.precision_bits;
  if (e.quadrature_order) j["order"] = e.quadrature_order;
  if (e.method == "monte-carlo") {
    j["samples"] = e.samples;
    j["samples_kept"] = e.samples_kept;
    j["seed"] = e.seed;
    j["generator"] = "mt19937_64";
    if (e.valid && !e.exact) j["standard_error"] = pair(e.standard_error);
  }
  if (s.worst_case_deg) j["worst_case_deg"] = *s.worst_case_deg;
  if (s.worst_case_illuminant_deg) j["worst_case_illuminant_deg"] = *s.worst_case_illuminant_deg;
  return j;
}


Json constraint_json(const ConstraintReport& c) {
  Json j = convex_set_json(c.maps);
  j["illuminants"] = c.illuminants;
  j["unconstrained_feasible_set"] = convex_set_json(c.unconstrained);
  return j;
}

Json exact_number(const Rational& x) { return to_string(x); }

void truth_text(std::ostream& out, const TruthReport& t) {
  const auto m = to_double_nearest(t.map);
  out << "against the true light (" << to_string(t.light.r) << ", " << to_string(t.light.g)
      << ", " << to_string(t.light.b) << "): true map (" << fmt(m[0]) << ", " << fmt(m[1]) << "), "
      << (t.in_feasible_set ? "inside" : "outside") << " the feasible set\n";
  for (Rule rule : all_rules) {
    const std::optional<RuleErrors>& e = t.errors[rule];
    if (!e) continue;
    out << "  " << rule_label(rule) << "  map error " << fmt(e->map_error_deg) << " deg";
    if (e->positive_map)
      out << ", illuminant " << fmt(e->illuminant_error_deg) << " deg, reproduction "
          << fmt(e->reproduction_error_deg) << " deg";
    out << "\n";
  }
}

Json recovery_json(const RecoveryReport& rec) {
  Json j;
  j["policy"] = to_string(rec.policy);
  j["applied"] = rec.applied;
  if (!rec.reason.empty()) j["reason"] = rec.reason;
  if (rec.grown) {
    const GrownFeasibleSet& g = *rec.grown;
    j["expansion_policy"] = "multiplicative";
    j["precision"] = exact_number(rec.precision);
    if (g.found) {
      j["factor"] = exact_number(g.factor);
      j["factor_approx"] = to_double_nearest(g.factor);
      if (g.empty_below) j["empty_below"] = exact_number(*g.empty_below);
      j["canonical_gamut"] = convex_set_json(g.canonical);
    } else {
      j["note"] = "still empty at the largest factor tried, " + to_string(*g.empty_below);
    }
  }
  if (rec.min_violation) {
    const MinViolation& v = *rec.min_violation;
    j["measure"] = "chebyshev: max over image colours q of the L-infinity distance from m*q to "
                   "the canonical gamut, in chromaticity units";
    j["violation"] = exact_number(v.violation);
    j["violation_approx"] = to_double_nearest(v.violation);
    j["canonical_gamut"] = convex_set_json(v.canonical);
  }
  return j;
}

Json truth_json(const TruthReport& t) {
  Json j;
  j["light"] = Json::array({to_string(t.light.r), to_string(t.light.g), to_string(t.light.b)});
  j["map"] = approx_pair(t.map);
  j["map_exact"] = exact_pair(t.map);
  j["in_feasible_set"] = t.in_feasible_set;
  Json errors = Json::object();
  for (Rule rule : all_rules) {
    const std::optional<RuleErrors>& e = t.errors[rule];
    if (!e) continue;
    Json x;
    x["map_error_deg"] = e->map_error_deg;
    x["illuminant_error_deg"] = e->positive_map ? Json(e->illuminant_error_deg) : Json();
    x["reproduction_error_deg"] = e->positive_map ? Json(e->reproduction_error_deg) : Json();
    errors[to_string(rule)] = x;
  }
  j["errors"] = errors;
  return j;
}

// Shortest text that reads back as the same double: distinct doubles print distinctly.
std::string shortest(double x) {
  char buf[64];
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  return std::string(buf, end);
}

}  // namespace

std::string fmt(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

Json scene_json(const PreparedCanonical& c, const SceneResult& r, bool canonical_members) {
  Json j;
  j["feasible_set"] = convex_set_json(r.feasible);
  if (!r.empty_reason.empty()) j["feasible_set"]["reason"] = r.empty_reason;
  if (r.constraint) j["constraint"] = constraint_json(*r.constraint);
  if (r.recovery) j["recovery"] = recovery_json(*r.recovery);
  Json sel = Json::object();
  for (Rule rule : all_rules)
    if (r.selections[rule]) sel[to_string(rule)] = selection_json(*r.selections[rule]);
  j["selections"] = sel;
  if (r.truth) j["truth"] = truth_json(*r.truth);
  if (canonical_members) {
    Json cg = convex_set_json(c.gamut);
    cg["expansion"] = {{"policy", to_string(c.options.expansion.policy)},
                       {"factor", to_string(c.options.expansion.factor)}};
    j["canonical_gamut"] = cg;
    const Colour& ci = c.options.canonical_illuminant;
    j["canonical_illuminant"] = Json::array({to_string(ci.r), to_string(ci.g), to_string(ci.b)});
    j["input"] = {{"canonical_colours", c.colours},
                  {"canonical_dropped_nonpositive_blue", c.dropped},
                  {"image_colours", r.image_colours},
                  {"image_dropped_nonpositive_blue", r.image_dropped}};
  } else {
    j["input"] = {{"image_colours", r.image_colours},
                  {"image_dropped_nonpositive_blue", r.image_dropped}};
  }
  return j;
}

void finish_document(Json& document) {
  // Provenance first (version, commit, options, input checksums: docs/cli.md "Provenance"),
  // once for every JSON document select writes.
  Json out;
  out["provenance"] = provenance_json();
  for (auto& [key, value] : document.items()) out[key] = std::move(value);
  document = std::move(out);
}

std::string json_lines_preamble() {
  Json line;
  line["provenance"] = provenance_json();
  return line.dump() + "\n";
}

std::string select_json(const PreparedCanonical& c, const SceneResult& r) {
  Json j = scene_json(c, r, true);
  finish_document(j);
  return j.dump(2) + "\n";
}

namespace {

// The summary's lines on the canonical gamut, the image, the illumination constraint and any
// recovery from an empty feasible set.
void inputs_text(std::ostream& out, const PreparedCanonical& c, const SceneResult& r) {
  const Expansion& expansion = c.options.expansion;
  out << "canonical gamut: " << to_string(c.gamut.kind) << ", "
      << c.gamut.vertices.size() << " vertices from " << c.colours
      << " colours";
  if (c.dropped) out << " (" << c.dropped << " with b <= 0 dropped)";
  if (expansion.policy != ExpansionPolicy::none)
    out << "; expanded by " << to_string(expansion.factor) << " ("
        << to_string(expansion.policy) << ")";
  out << "\nimage: " << r.image_colours << " colours";
  if (r.image_dropped) out << " (" << r.image_dropped << " with b <= 0 dropped)";
  if (r.constraint)
    out << "\nillumination constraint: " << r.constraint->illuminants << " illuminants, maps "
        << to_string(r.constraint->maps.kind) << "; feasible set before it "
        << to_string(r.constraint->unconstrained.kind) << ", area "
        << fmt(to_double_nearest(area(r.constraint->unconstrained)));
  if (r.recovery && r.recovery->applied) {
    out << "\nthe feasible set was empty (" << r.recovery->reason << "); recovered by "
        << to_string(r.recovery->policy) << ": ";
    if (r.recovery->grown)
      out << "canonical gamut grown multiplicatively by "
          << fmt(to_double_nearest(r.recovery->grown->factor)) << " (least factor in ("
          << to_string(*r.recovery->grown->empty_below) << ", "
          << to_string(r.recovery->grown->factor) << "])";
    if (r.recovery->min_violation)
      out << "least Chebyshev violation "
          << to_string(r.recovery->min_violation->violation) << " ≈ "
          << fmt(to_double_nearest(r.recovery->min_violation->violation))
          << " (chromaticity units)";
  }
}

// The feasible set's vertices, one a line.
void vertices_text(std::ostream& out, const std::vector<Point2>& vertices) {
  // Each vertex as the shortest decimals that read back as its nearest doubles; where two
  // distinct vertices round to the same doubles (a sliver), their exact values too.
  std::vector<std::array<double, 2>> approx;
  for (const Point2& v : vertices) approx.push_back(to_double_nearest(v));
  for (std::size_t i = 0; i < approx.size(); ++i) {
    out << "  (" << shortest(approx[i][0]) << ", " << shortest(approx[i][1]) << ")";
    bool shared = false;
    for (std::size_t k = 0; k < approx.size(); ++k) shared = shared || (k != i && approx[k] == approx[i]);
    if (shared)
      out << "  exact (" << to_string(vertices[i].x) << ", "
          << to_string(vertices[i].y) << ")";
    out << "\n";
  }
}

// One rule's line: its map, worst case, and exact value or error bound.
void selection_line(std::ostream& out, const std::string& name, const Selection& s) {
  if (!s.estimate.valid) {
    out << "  " << name << "  none (" << s.estimate.method << "): " << s.estimate.note << "\n";
    return;
  }
  out << "  " << name << "  (" << fmt(s.estimate.map[0]) << ", " << fmt(s.estimate.map[1])
      << ")  worst case " << fmt(*s.worst_case_deg) << " deg";
  if (s.worst_case_illuminant_deg)
    out << " (illuminant " << fmt(*s.worst_case_illuminant_deg) << ")";
  if (s.estimate.exact) {
    const std::string x = to_string(s.estimate.exact->x), y = to_string(s.estimate.exact->y);
    if (x.size() + y.size() <= 40)
      out << "  exact (" << x << ", " << y << ")";
    else
      out << "  exact rational (" << x.size() + y.size() << " digits; see --json)";
  }
  else
    out << "  ± " << fmt(s.estimate.error_bound) << " ("
        << (s.estimate.method == "monte-carlo" ? "monte-carlo, one standard error"
            : s.estimate.method == "quadrature" ? "quadrature, estimated truncation + rounding bound"
                                                : "analytic, certified")
        << (s.estimate.correctly_rounded[0] && s.estimate.correctly_rounded[1]
                ? ", correctly rounded" : "")
        << ")";
  out << "\n";
}

}  // namespace

std::string select_text(const PreparedCanonical& c, const SceneResult& r) {
  std::ostringstream out;
  inputs_text(out, c, r);
  out << "\nfeasible set: " << to_string(r.feasible.kind);
  if (r.feasible.kind == ConvexKind::polygon)
    out << ", " << r.feasible.vertices.size() << " vertices, area "
        << fmt(to_double_nearest(area(r.feasible)));
  out << "\n";
  vertices_text(out, r.feasible.vertices);
  if (r.feasible.kind == ConvexKind::empty) {
    out << r.empty_reason << "\n";
    if (r.recovery && r.recovery->grown && !r.recovery->grown->found)
      out << "grow-canonical: still empty at factor " << to_string(*r.recovery->grown->empty_below)
          << "\n";
    if (r.truth) truth_text(out, *r.truth);
    return out.str();
  }
  out << "selections (perspective map d1/d3, d2/d3; worst-case map-space error):\n";
  for (Rule rule : all_rules) selection_line(out, rule_label(rule), *r.selections[rule]);
  if (r.truth) truth_text(out, *r.truth);
  return out.str();
}

}  // namespace gmcc::cli
