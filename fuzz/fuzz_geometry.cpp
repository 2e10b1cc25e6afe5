// Fuzz target: the exact geometry pipeline and the selection rules on structured random
// rationals — huge and tiny magnitudes, long numerators and denominators, duplicates, collinear
// and coincident points. Checked exactly, against the definitions rather than the algorithms:
//  - hulls, gamuts and feasible sets are in canonical form (ConvexSet2);
//  - the canonical gamut contains every canonical chromaticity;
//  - UnboundedFeasibleSet is thrown exactly when every image r/b or every image g/b is 0;
//  - F does not depend on the order of the image chromaticities;
//  - every vertex of F maps every image chromaticity into the gamut, and candidate maps
//    (vertices, edge midpoints, nudged vertices, gamut vertex ⊘ image chromaticity, random
//    points) lie in F exactly when m ⊙ q ∈ G_c for every q (brute force);
//  - max-area and the 2-D mean lie in F, and max-area's m1·m2 beats every candidate in F;
//  - the 3-D mean's certified enclosure meets F (the mean is irrational: an exact box test);
//  - every rule's worst cases are at least the angle to every vertex and candidate in F;
//  - the certified route (feasible_polygon.h, certified_rule_errors.h): feasible_polygon throws
//    UnboundedFeasibleSet exactly when feasible_set does; its kind() is F's kind, exact() is F
//    (also from the image by address); when enclosed(), each vertex of F lies in its enclosure
//    (mid ± rad, exactly, for one rotation of the cycle) and each edge's approximate line is
//    within a relative 6·2^-53 of a positive multiple of the exact one; contains() agrees with
//    F on every candidate; certified_rule_errors answers only when enclosed(), and then every angle (map
//    error against a positive truth, worst case, illuminant and reproduction errors under a
//    positive light, all from fuzz bytes) is within its stated accuracy of the exact route's;
//    each vertex of F also lies in its extended_vertices() enclosure (the same order as
//    vertices(), exactly: a long double's value is k/2^64·2^e, from frexp), of relative radius
//    at most 2^-60;
//  - a map constraint C from fuzz bytes (the hull of a few points near a map of F, near the truth,
//    far away or anywhere; F itself; a piece of an edge of F; a triangle on an edge's line, outside
//    or inside; a box about F; empty; so C is a polygon, segment, point or empty and F ∩ C any
//    kind): feasible_set and feasible_polygon with CanonicalConstraints(G, C) give
//    intersection(F, C), with its kind; contains() agrees with m ∈ F and m ∈ C (brute force) on
//    the candidates, C's and F ∩ C's vertices and edge midpoints and nudged vertices; when
//    enclosed(), vertices(), extended_vertices() and edges() hold as above; certified_rule_errors answers
//    only when enclosed(), and then agrees with the exact route on F ∩ C as above.

#include "fuzz_support.h"
#include "geometry_checks.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/intersection.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/worst_case.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
using gmcc::ConvexKind;
using gmcc::ConvexSet2;
using gmcc::Point2;
using gmcc::Rational;
using namespace gmcc::fuzz;  // the shared checks (geometry_checks.h)

// One non-negative coordinate; `pool` holds earlier ones, for duplicates and near-duplicates.
Rational coordinate(ByteReader& in, const std::vector<Rational>& pool) {
  const unsigned a = in.byte(), b = in.byte();
  switch (in.byte() % 8) {
    case 0: return reduced(a, 1 + b % 16);                            // small
    case 1: return pool.empty() ? Rational(a) : pool[b % pool.size()];  // duplicate
    case 2: return reduced(mpz_class(1 + a) * power_of_two(b), 1);  // huge, up to 2^263
    case 3: return reduced(1 + a, power_of_two(b));                 // tiny
    case 4: return Rational(0);
    case 5: return reduced(mpz_class(std::to_string(in.bytes(4))), mpz_class(std::to_string(1 + in.bytes(4))));
    case 6: {  // a hair above an earlier value
      const Rational base = pool.empty() ? Rational(1) : pool[a % pool.size()];
      return Rational(base + reduced(1, power_of_two(1 + b % 128)));
    }
    default: {  // decimal scales
      mpz_class ten;
      mpz_ui_pow_ui(ten.get_mpz_t(), 10, b % 40);
      return a % 2 ? reduced(1 + a, ten) : reduced(mpz_class(1 + a) * ten, 1);
    }
  }
}

std::vector<Point2> points(ByteReader& in, int n, std::vector<Rational>& pool) {
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    const unsigned how = in.byte() % 4;
    if (how == 0 && !p.empty()) {  // coincident
      p.push_back(p[in.byte() % p.size()]);
    } else if (how == 1 && p.size() >= 2) {  // collinear: on the segment between two earlier
      const Point2 a = p[in.byte() % p.size()], b = p[in.byte() % p.size()];
      const Rational t = reduced(in.byte(), 255);
      p.push_back({Rational(a.x + t * (b.x - a.x)), Rational(a.y + t * (b.y - a.y))});
    } else {
      Rational x = coordinate(in, pool);
      Rational y = coordinate(in, pool);
      p.push_back({x, y});
    }
    pool.push_back(p.back().x);
    pool.push_back(p.back().y);
  }
  return p;
}


// A rule's selection as select_maps makes it, without the illuminant worst case.
gmcc::Selection rule_selection(const ConvexSet2& F, gmcc::MapEstimate e) {
  gmcc::Selection sel{e, std::nullopt, std::nullopt};
  if (e.valid)
    sel.worst_case_deg = gmcc::worst_case_map_deg(
        F, e.exact ? *e.exact : Point2{gmcc::rational_from_double(e.map[0]), gmcc::rational_from_double(e.map[1])});
  return sel;
}

// certified_rule_errors against the exact route (as tests/selection/test_rule_errors.cpp: its accuracy,
// the exact route's 2^-50 and the 3-D mean's rounding to doubles allowed for); the exact route's
// 3-D mean at the default precision.
void check_agreement(const gmcc::PerRule<gmcc::RuleErrors>& fast, const gmcc::Selection* const (&exact_route)[3],
                     const Point2& truth, const gmcc::Colour& light, const std::string& where) {
  for (int r = 0; r < 3; ++r) {
    const gmcc::MapEstimate& e = exact_route[r]->estimate;
    FUZZ_CHECK(e.valid && exact_route[r]->worst_case_deg, where + e.rule + ": no exact map at the default precision");
    const Point2 m = e.exact ? *e.exact : Point2{gmcc::rational_from_double(e.map[0]), gmcc::rational_from_double(e.map[1])};
    const gmcc::RuleErrors& f = fast.values[static_cast<std::size_t>(r)];
    auto agree = [&](double fast_value, double exact_value, const char* what) {
      const bool close = std::fabs(fast_value - exact_value) <=
                         gmcc::rule_errors_accuracy * (1 + std::fabs(exact_value)) +
                             0x1p-48 * std::fabs(exact_value) + 1e-13;
      char values[96];
      std::snprintf(values, sizeof values, " %.17g, exact route %.17g", fast_value, exact_value);
      FUZZ_CHECK(close, where + "certified_rule_errors " + e.rule + " " + what + values + "; truth " + text(truth) +
                            ", map " + text(m));
    };
    agree(f.map_error_deg, gmcc::map_angular_error_deg(m, truth), "map error");
    agree(f.worst_case_deg, *exact_route[r]->worst_case_deg, "worst case");
    FUZZ_CHECK(f.positive_map == positive(m), where + "certified_rule_errors " + e.rule + ": positive_map wrong for " + text(m));
    if (f.positive_map) {
      agree(f.illuminant_error_deg, gmcc::illuminant_angular_error_deg(m, truth, light), "illuminant error");
      agree(f.reproduction_error_deg, gmcc::reproduction_angular_error_deg(m, truth), "reproduction error");
    }
  }
}

Rational fraction(ByteReader& in, int lo, int den) { return reduced(int(in.byte()) + lo, den); }

// A map constraint C from fuzz bytes, of any kind, placed so that F ∩ C is of any kind too.
ConvexSet2 map_constraint(ByteReader& in, std::vector<Rational>& pool, const ConvexSet2& F,
                          const std::vector<Point2>& in_F, const std::vector<Point2>& candidates, const Point2& truth) {
  const auto& v = F.vertices;
  const unsigned mode = in.byte() % 8;
  switch (mode) {
    case 2:  // F itself: every line of C is a line of F
      if (!v.empty()) return F;
      break;
    case 3:  // a piece of an edge of F (or of its line beyond), or a vertex
    case 4: {  // a triangle on an edge's line, outside F (F ∩ C a piece of the edge) or inside
      if (v.empty()) break;
      const std::size_t i = in.byte() % v.size();
      const Point2& p = v[i];
      const Point2& q = v[(i + 1) % v.size()];
      auto along = [&](const Rational& t) { return Point2{Rational(p.x + t * (q.x - p.x)), Rational(p.y + t * (q.y - p.y))}; };
      const Point2 a = along(fraction(in, -64, 128)), b = along(fraction(in, -64, 128));  // t in [-1/2, 3/2)
      if (mode == 3) return gmcc::convex_hull({a, b});
      // (q.y − p.y, p.x − q.x) points out of F for its counter-clockwise edge p → q.
      const unsigned k = in.byte();
      const Rational s = Rational(k & 1 ? 1 : -1) / Rational(power_of_two(k / 2 % 64));
      const Point2 mid{Rational((a.x + b.x) / 2), Rational((a.y + b.y) / 2)};
      const Point2 r{Rational(mid.x + s * (q.y - p.y)), Rational(mid.y + s * (p.x - q.x))};
      return gmcc::convex_hull({a, b, r});
    }
    case 5: return ConvexSet2{};
    case 6: {  // anywhere
      std::vector<Point2> pts;
      for (int j = 1 + in.byte() % 4; j > 0; --j) {
        Rational x = coordinate(in, pool);
        Rational y = coordinate(in, pool);
        pts.push_back({x, y});
      }
      return gmcc::convex_hull(pts);
    }
    case 7: {  // F's bounding box, grown or shrunk by a fraction of its span (or exactly it)
      if (v.empty()) break;
      Rational lo[2] = {v[0].x, v[0].y}, hi[2] = {v[0].x, v[0].y};
      for (const Point2& w : v) {
        lo[0] = std::min(lo[0], w.x), hi[0] = std::max(hi[0], w.x);
        lo[1] = std::min(lo[1], w.y), hi[1] = std::max(hi[1], w.y);
      }
      for (int k = 0; k < 2; ++k) {
        const Rational d = Rational(hi[k] - lo[k]) * fraction(in, -128, 256);
        lo[k] -= d, hi[k] += d;
      }
      return gmcc::convex_hull({{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}});
    }
    default: break;
  }
  // The hull of 1–4 points near a centre: a map in F, the truth, a candidate, or far away.
  const unsigned c = in.byte();
  Point2 centre = truth;
  if (c % 4 == 0 && !in_F.empty()) centre = in_F[c / 4 % in_F.size()];
  if (c % 4 == 2 && !candidates.empty()) centre = candidates[c / 4 % candidates.size()];
  if (c % 4 == 3) {
    const Rational f(power_of_two(1 + c / 4 % 64));
    centre = c & 128 ? Point2{Rational(centre.x * f), Rational(centre.y * f)} : Point2{Rational(centre.x / f), Rational(centre.y / f)};
  }
  const unsigned b = in.byte();
  const Rational scale = Rational(abs(centre.x) + abs(centre.y) + (b & 1 ? 1 : 0)) / Rational(power_of_two(1 + b / 2 % 48));
  std::vector<Point2> pts;
  // Offsets in [-1, 1) of the scale; all-zero bytes (an input that ends early) give a triangle
  // about the centre.
  for (int j = 0, n = 1 + (in.byte() + 2) % 4; j < n; ++j) {
    if (pts.size() >= 2 && in.byte() % 4 == 3) {  // collinear with two earlier ones
      const Point2 a = pts[in.byte() % pts.size()], e = pts[in.byte() % pts.size()];
      const Rational t = fraction(in, 0, 255);
      pts.push_back({Rational(a.x + t * (e.x - a.x)), Rational(a.y + t * (e.y - a.y))});
    } else {
      const Rational dx = reduced(int((in.byte() + 85 * j) % 256) - 128, 128);
      const Rational dy = reduced(int((in.byte() + 170 * j + 64) % 256) - 128, 128);
      pts.push_back({Rational(centre.x + scale * dx), Rational(centre.y + scale * dy)});
    }
  }
  return gmcc::convex_hull(pts);
}

// The certified route with a map constraint C: F ∩ C as intersection() gives it, contains() on
// maps in and about it, enclosures, and certified_rule_errors against the exact route on F ∩ C.
void check_constrained(ByteReader& in, std::vector<Rational>& pool, const ConvexSet2& G, const std::vector<Point2>& image,
                       const ConvexSet2& F, const std::vector<Point2>& in_F, const std::vector<Point2>& candidates,
                       const Point2& truth, const gmcc::Colour& light) {
  const ConvexSet2 C = map_constraint(in, pool, F, in_F, candidates, truth);
  check_canonical(C, "map constraint");
  const ConvexSet2 FC = gmcc::intersection(F, C);
  check_canonical(FC, "F ∩ C");
  const std::string where = "with C a " + gmcc::to_string(C.kind) + " (F ∩ C a " + gmcc::to_string(FC.kind) + "): ";
  const gmcc::CanonicalConstraints constraints(G, C);
  FUZZ_CHECK(gmcc::feasible_set(constraints, image) == FC, where + "feasible_set is not intersection(F, C)");
  const gmcc::FeasiblePolygon P = gmcc::feasible_polygon(constraints, image);
  FUZZ_CHECK(P.kind() == FC.kind, where + "feasible_polygon: kind " + gmcc::to_string(P.kind()));
  FUZZ_CHECK(!P.enclosed() || P.kind() == ConvexKind::polygon, where + "feasible_polygon: enclosed but not a polygon");
  if (P.enclosed()) check_enclosed(P, FC);

  std::vector<Point2> maps = candidates;
  for (const ConvexSet2* s : {&C, &FC}) {
    const auto& v = s->vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      maps.push_back(v[i]);
      const Point2& q = v[(i + 1) % v.size()];
      if (v.size() >= 2) maps.push_back({Rational((v[i].x + q.x) / 2), Rational((v[i].y + q.y) / 2)});
    }
  }
  for (std::size_t i = 0; i < FC.vertices.size() && i < 3; ++i) {  // a hair away, both ways
    const Point2& w = FC.vertices[i];
    const unsigned b = in.byte();
    const Rational d = Rational(abs(w.x) + abs(w.y) + 1) / Rational(power_of_two(1 + b % 64));
    const int sx = b & 64 ? 1 : -1, sy = b & 128 ? 1 : -1;
    maps.push_back({Rational(w.x + sx * d), Rational(w.y + sy * d)});
    maps.push_back({Rational(w.x - sx * d), Rational(w.y - sy * d)});
  }
  for (const Point2& m : maps) {
    const bool inside = gmcc::contains(FC, m);
    FUZZ_CHECK(inside == (gmcc::contains(C, m) && feasible(G, image, m)),
               where + "map " + text(m) + (inside ? " in F ∩ C but not in both" : " in F and C but not in F ∩ C"));
    FUZZ_CHECK(P.contains(m) == inside,
               where + "feasible_polygon: contains(" + text(m) + ") is not " + (inside ? "true" : "false"));
  }
  FUZZ_CHECK(P.exact() == FC && P.exact().kind == P.kind(), where + "feasible_polygon: exact() is not F ∩ C");

  const auto fast = gmcc::certified_rule_errors(P, truth, light);
  FUZZ_CHECK(P.enclosed() || !fast, where + "certified_rule_errors answered for a set that is not enclosed");
  if (!fast) return;
  FUZZ_CHECK(finite_doubles(FC), where + "certified_rule_errors answered for F ∩ C beyond the double range");
  const gmcc::Selection s[3] = {rule_selection(FC, gmcc::max_area(FC)), rule_selection(FC, gmcc::mean_2d(FC)),
                                rule_selection(FC, gmcc::mean_3d(FC))};
  const gmcc::Selection* const exact_route[3] = {&s[0], &s[1], &s[2]};
  check_agreement(*fast, exact_route, truth, light, where);
}

// The canonical gamut (expanded as the flags say) and its checks: not empty, every canonical
// point inside, every vertex an input point when not expanded.
ConvexSet2 checked_gamut(const std::vector<Point2>& canonical, std::uint8_t flags) {
  gmcc::Expansion expansion;
  if (flags % 4 == 1) expansion = {gmcc::ExpansionPolicy::centroid_clip, Rational(1, 10)};
  if (flags % 4 == 2) expansion = {gmcc::ExpansionPolicy::multiplicative, Rational(1, 3)};
  const ConvexSet2 G = gmcc::canonical_gamut(canonical, expansion);
  check_canonical(G, "canonical gamut");
  FUZZ_CHECK(G.kind != ConvexKind::empty, "empty gamut from points");
  for (const Point2& p : canonical) FUZZ_CHECK(gmcc::contains(G, p), "gamut misses " + text(p));
  if (expansion.policy == gmcc::ExpansionPolicy::none)
    for (const Point2& v : G.vertices)
      FUZZ_CHECK(std::find(canonical.begin(), canonical.end(), v) != canonical.end(),
                 "hull vertex not an input point: " + text(v));

  return G;
}

// Candidate maps: F's vertices and edge midpoints, points a hair away from the first vertices
// both ways, gamut vertices over image points, and a few points from the fuzz bytes.
std::vector<Point2> candidate_maps(ByteReader& in, std::vector<Rational>& pool, const ConvexSet2& G,
                                   const std::vector<Point2>& image, const ConvexSet2& F) {
  std::vector<Point2> candidates = F.vertices;
  const auto& fv = F.vertices;
  for (std::size_t i = 0; fv.size() >= 2 && i < fv.size(); ++i) {
    const Point2& p = fv[i];
    const Point2& q = fv[(i + 1) % fv.size()];
    candidates.push_back({Rational((p.x + q.x) / 2), Rational((p.y + q.y) / 2)});
  }
  for (std::size_t i = 0; i < fv.size() && i < 4; ++i) {  // a hair away, both ways
    const Point2& v = fv[i];
    const unsigned b = in.byte();
    const Rational d = Rational(v.x + v.y + 1) / Rational(power_of_two(1 + b % 64));
    const int sx = b & 64 ? 1 : -1, sy = b & 128 ? 1 : -1;
    candidates.push_back({Rational(v.x + sx * d), Rational(v.y + sy * d)});
    candidates.push_back({Rational(v.x - sx * d), Rational(v.y - sy * d)});
  }
  for (std::size_t i = 0; i < G.vertices.size() * image.size() && i < 8; ++i) {
    const Point2& g = G.vertices[i % G.vertices.size()];
    const Point2& q = image[i / G.vertices.size()];
    if (positive(q)) candidates.push_back({Rational(g.x / q.x), Rational(g.y / q.y)});
  }
  for (int i = 0; i < 4 && !in.empty(); ++i) {
    Rational x = coordinate(in, pool);
    Rational y = coordinate(in, pool);
    candidates.push_back({x, y});
  }
  return candidates;
}

// The 3-D mean: analytic; valid unless a forced precision is too low (then with a note); a point
// is its own mean; otherwise a finite enclosure that meets F and holds the map.
void check_mean_3d(const ConvexSet2& F, const gmcc::Selection& mean_3d, const gmcc::Mean3dOptions& mean3d) {
  const gmcc::MapEstimate& m3 = mean_3d.estimate;
  FUZZ_CHECK(m3.method == "analytic", "3-D mean: method " + m3.method);
  // Only a forced precision may be too low to bound the closed form.
  FUZZ_CHECK(m3.valid || mean3d.precision_bits != 0, "3-D mean not valid: " + m3.note);
  FUZZ_CHECK(m3.valid == m3.enclosure.has_value(), "3-D mean: enclosure iff valid");
  if (!m3.valid) {
    FUZZ_CHECK(!m3.note.empty() && !mean_3d.worst_case_deg, "3-D mean: invalid without a note");
  } else if (F.kind == ConvexKind::point) {
    FUZZ_CHECK(m3.exact && *m3.exact == F.vertices[0], "3-D mean of a point is not the point");
  } else {
    const auto& e = *m3.enclosure;
    FUZZ_CHECK(std::isfinite(e[0][0]) && std::isfinite(e[0][1]) && std::isfinite(e[1][0]) &&
                   std::isfinite(e[1][1]),
               "3-D mean: enclosure not finite");
    const Rational lo[2] = {gmcc::rational_from_double(e[0][0]), gmcc::rational_from_double(e[1][0])};
    const Rational hi[2] = {gmcc::rational_from_double(e[0][1]), gmcc::rational_from_double(e[1][1])};
    FUZZ_CHECK(lo[0] <= hi[0] && lo[1] <= hi[1], "3-D mean: enclosure upside down");
    FUZZ_CHECK(box_meets(F, lo, hi), "3-D mean: the enclosure misses F");
    for (int k = 0; k < 2; ++k)
      FUZZ_CHECK(e[k][0] <= m3.map[k] && m3.map[k] <= e[k][1], "3-D mean: map outside its enclosure");
  }
}

// Worst cases against the vertices and a few other points of F (each angle costs an MPFR
// evaluation); the illuminant worst case only on the runs that computed it (`whole`).
void check_worst_cases(const ConvexSet2& F, const std::vector<Point2>& in_F, const gmcc::Selections& s, bool whole,
                       const gmcc::Colour& c) {
  const auto& fv = F.vertices;
  std::vector<Point2> probes = F.vertices;
  for (std::size_t i = F.vertices.size(); i < in_F.size() && i < F.vertices.size() + 2; ++i)
    probes.push_back(in_F[i]);
  for (const auto* sel : {&*s[gmcc::Rule::max_area], &*s[gmcc::Rule::mean_2d], &*s[gmcc::Rule::mean_3d]}) {
    const gmcc::MapEstimate& est = sel->estimate;
    if (!est.valid) continue;
    const Point2 m = est.exact ? *est.exact
                               : Point2{gmcc::rational_from_double(est.map[0]),
                                        gmcc::rational_from_double(est.map[1])};
    FUZZ_CHECK(sel->worst_case_deg.has_value(), est.rule + ": no worst case");
    check_worst(*sel->worst_case_deg, probes,
                [&m](const Point2& x) { return gmcc::map_angular_error_deg(m, x); },
                est.rule + " worst case");
    const bool all_positive = positive(m) && std::all_of(fv.begin(), fv.end(), positive);
    if (!whole) continue;
    FUZZ_CHECK(sel->worst_case_illuminant_deg.has_value() == all_positive,
               est.rule + ": illuminant worst case present iff F and the map are positive");
    if (all_positive)
      check_worst(*sel->worst_case_illuminant_deg, probes,
                  [&m, &c](const Point2& x) { return gmcc::illuminant_angular_error_deg(m, x, c); },
                  est.rule + " illuminant worst case");
  }
}

// F is canonical, independent of the image's order, and its vertices feasible by definition.
void check_feasible_set(const ConvexSet2& G, const std::vector<Point2>& image, const ConvexSet2& F) {
  check_canonical(F, "feasible set");
  std::vector<Point2> reordered(image.rbegin(), image.rend());
  FUZZ_CHECK(gmcc::feasible_set(G, reordered) == F, "F depends on the image order (reversed)");
  std::rotate(reordered.begin(), reordered.begin() + 1, reordered.end());
  FUZZ_CHECK(gmcc::feasible_set(G, reordered) == F, "F depends on the image order (rotated)");
  for (const Point2& v : F.vertices)
    FUZZ_CHECK(feasible(G, image, v), "vertex " + text(v) + " of F is not feasible");
}

// Each candidate's membership in F by contains, the definition and the feasible polygon; those
// in F.
std::vector<Point2> candidates_in_F(const std::vector<Point2>& candidates, const ConvexSet2& G,
                                    const std::vector<Point2>& image, const ConvexSet2& F,
                                    const gmcc::FeasiblePolygon& P) {
  std::vector<Point2> in_F;
  for (const Point2& m : candidates) {
    const bool inside = gmcc::contains(F, m);
    FUZZ_CHECK(inside == feasible(G, image, m),
               "map " + text(m) + (inside ? " in F but not feasible" : " feasible but not in F"));
    FUZZ_CHECK(P.contains(m) == inside, "feasible_polygon: contains(" + text(m) + ") is not " +
                                            (inside ? "true" : "false"));
    if (inside) in_F.push_back(m);
  }
  FUZZ_CHECK(P.exact() == F && P.exact().kind == P.kind(), "feasible_polygon: exact() is not F");
  return in_F;
}

// A positive truth (a positive candidate in F, or one from fuzz bytes) and a positive light from
// fuzz bytes (huge and tiny ones too: certified_rule_errors must then decline).
std::pair<Point2, gmcc::Colour> truth_and_light(ByteReader& in, std::vector<Rational>& pool,
                                                const std::vector<Point2>& in_F) {
  auto positive_or_one = [](const Rational& x) { return sgn(x) > 0 ? x : Rational(1); };
  std::vector<Point2> positive_in_F;
  std::copy_if(in_F.begin(), in_F.end(), std::back_inserter(positive_in_F), positive);
  const unsigned pick = in.byte();
  Point2 truth{1, 1};
  if (pick % 4 != 0 && !positive_in_F.empty()) {
    truth = positive_in_F[pick / 4 % positive_in_F.size()];
  } else {
    truth.x = positive_or_one(coordinate(in, pool));
    truth.y = positive_or_one(coordinate(in, pool));
  }
  gmcc::Colour light{1, 1, 1};
  for (Rational* k : {&light.r, &light.g, &light.b}) *k = positive_or_one(coordinate(in, pool));
  return {truth, light};
}

// The three rules: all of select_maps (`whole`), or the rules one by one without the
// illuminant worst case; nothing (after checking that this is right) for F beyond the doubles.
std::optional<gmcc::Selections> selections(const ConvexSet2& F, const gmcc::Mean3dOptions& mean3d,
                                           const gmcc::Colour& c, bool whole, bool fast) {
  gmcc::Selections s;
  if (whole) {
    try {
      s = gmcc::select_maps(F, gmcc::SelectionOptions{mean3d, c});
    } catch (const std::domain_error&) {
      FUZZ_CHECK(!finite_doubles(F), "domain_error though F is within the double range");
      FUZZ_CHECK(!fast, "certified_rule_errors answered for F beyond the double range");
      return std::nullopt;
    }
    FUZZ_CHECK(finite_doubles(F), "no domain_error though F is beyond the double range");
  } else {
    if (!finite_doubles(F)) {
      FUZZ_CHECK(!fast, "certified_rule_errors answered for F beyond the double range");
      return std::nullopt;
    }
    s[gmcc::Rule::max_area] = rule_selection(F, gmcc::max_area(F));
    s[gmcc::Rule::mean_2d] = rule_selection(F, gmcc::mean_2d(F));
    s[gmcc::Rule::mean_3d] = rule_selection(F, gmcc::mean_3d(F, mean3d));
  }
  return s;
}

// F, or nothing when it is unbounded — exactly when a component is unconstrained (every image
// point has it 0), and then feasible_polygon says so too.
std::optional<ConvexSet2> bounded_feasible_set(const ConvexSet2& G, const gmcc::CanonicalConstraints& constraints,
                                               const std::vector<Point2>& image) {
  const bool unbounded = std::all_of(image.begin(), image.end(), [](const Point2& q) { return sgn(q.x) == 0; }) ||
                         std::all_of(image.begin(), image.end(), [](const Point2& q) { return sgn(q.y) == 0; });
  try {
    ConvexSet2 F = gmcc::feasible_set(G, image);
    FUZZ_CHECK(!unbounded, "no UnboundedFeasibleSet though a component is unconstrained");
    return F;
  } catch (const gmcc::UnboundedFeasibleSet&) {
    FUZZ_CHECK(unbounded, "UnboundedFeasibleSet for a bounded feasible set");
    bool thrown = false;
    try {
      (void)gmcc::feasible_polygon(constraints, image);
    } catch (const gmcc::UnboundedFeasibleSet&) {
      thrown = true;
    }
    FUZZ_CHECK(thrown, "feasible_polygon: no UnboundedFeasibleSet where feasible_set throws it");
    return std::nullopt;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const std::uint8_t flags = in.byte();
  std::vector<Rational> pool;
  // Few points keep each run to milliseconds (10^6 runs); degeneracies need only a few.
  const int n_canonical = 1 + in.byte() % 7, n_image = 1 + in.byte() % 5;
  const std::vector<Point2> canonical = points(in, n_canonical, pool);
  const std::vector<Point2> image = points(in, n_image, pool);

  const ConvexSet2 G = checked_gamut(canonical, flags);

  const gmcc::CanonicalConstraints constraints(G);
  const std::optional<ConvexSet2> bounded = bounded_feasible_set(G, constraints, image);
  if (!bounded) return 0;
  const ConvexSet2& F = *bounded;
  check_feasible_set(G, image, F);

  // The certified route on the same scene: its kind, enclosures and membership tests are
  // checked before its exact set is built (exact() is built on demand), then that set.
  const gmcc::FeasiblePolygon P = gmcc::feasible_polygon(constraints, image);
  FUZZ_CHECK(P.kind() == F.kind, "feasible_polygon: kind differs from F's");
  FUZZ_CHECK(!P.enclosed() || P.kind() == ConvexKind::polygon, "feasible_polygon: enclosed but not a polygon");
  if (P.enclosed()) check_enclosed(P, F);
  {
    std::vector<const Point2*> by_address;  // the image by address, in reverse order
    for (auto q = image.rbegin(); q != image.rend(); ++q) by_address.push_back(&*q);
    const gmcc::FeasiblePolygon Q = gmcc::feasible_polygon(constraints, by_address);
    FUZZ_CHECK(Q.kind() == F.kind && Q.exact() == F, "feasible_polygon by address (reversed) is not F");
  }

  // Candidate maps, each checked against the definition.
  const std::vector<Point2> candidates = candidate_maps(in, pool, G, image, F);
  const std::vector<Point2> in_F = candidates_in_F(candidates, G, image, F, P);

  // certified_rule_errors against a positive truth and light.
  const auto [truth, light] = truth_and_light(in, pool, in_F);
  const auto fast = gmcc::certified_rule_errors(P, truth, light);
  FUZZ_CHECK(P.enclosed() || !fast, "certified_rule_errors answered for a feasible set that is not enclosed");
  check_constrained(in, pool, G, image, F, in_F, candidates, truth, light);
  if (F.kind == ConvexKind::empty) return 0;

  gmcc::Mean3dOptions mean3d;
  if (flags & 4) mean3d.precision_bits = 60;
  const gmcc::Colour c = flags & 8 ? gmcc::Colour{2, 1, Rational(3, 7)} : gmcc::Colour{1, 1, 1};
  // Seven runs in eight take the rules one by one without the illuminant worst case (15 times
  // the cost of the rest of the selection), so that 10^6 runs take hours rather than days; the
  // eighth calls select_maps, all of it.
  const bool whole = (flags >> 4) % 8 == 0;
  auto rule = [&F](gmcc::MapEstimate e) { return rule_selection(F, std::move(e)); };
  const std::optional<gmcc::Selections> selected = selections(F, mean3d, c, whole, fast.has_value());
  if (!selected) return 0;
  const gmcc::Selections& s = *selected;
  FUZZ_CHECK(s[gmcc::Rule::max_area] && s[gmcc::Rule::mean_2d] && s[gmcc::Rule::mean_3d], "a rule is missing for a non-empty F");

  const Point2 best = *s[gmcc::Rule::max_area]->estimate.exact;
  FUZZ_CHECK(gmcc::contains(F, best), "max-area " + text(best) + " not in F");
  for (const Point2& m : in_F)
    FUZZ_CHECK(m.x * m.y <= best.x * best.y, "max-area beaten by " + text(m));
  FUZZ_CHECK(*s[gmcc::Rule::mean_2d]->estimate.exact == gmcc::centroid(F) && gmcc::contains(F, gmcc::centroid(F)),
             "2-D mean not the centroid in F");

  check_mean_3d(F, *s[gmcc::Rule::mean_3d], mean3d);

  // certified_rule_errors against the exact route. Its 3-D mean is at the default precision: a forced one
  // is recomputed (only when certified_rule_errors answered).
  if (fast) {
    std::optional<gmcc::Selection> mean_3d_default;
    if (mean3d.precision_bits != 0) mean_3d_default = rule(gmcc::mean_3d(F));
    const gmcc::Selection* const exact_route[3] = {&*s[gmcc::Rule::max_area], &*s[gmcc::Rule::mean_2d],
                                                   mean_3d_default ? &*mean_3d_default : &*s[gmcc::Rule::mean_3d]};
    check_agreement(*fast, exact_route, truth, light, "");
  }

  check_worst_cases(F, in_F, s, whole, c);
  return 0;
}
