// Fuzz target: adversarial geometry at sizes fuzz_geometry never reaches, run with a per-input
// time limit (scripts/fuzz: -timeout=10 for this target), so that an input the pipeline is slow on
// is a finding as much as a wrong answer. The bytes choose a family and its parameters:
//  - canonical gamuts of up to 2000 points on a convex curve — a parabola (nearly flat ones give
//    nearly parallel edges), a circle (exact rational points), an ellipse thin as 2^-60 (a
//    sliver), a tiny circle (near-duplicates), the hyperbola xy = 1 (a wide dynamic range) — or a
//    few points from the bytes; scaled by powers of two, expanded or not;
//  - images of 1–4 points, of points a hair apart (q and q·(1 + 2^-k): nearly parallel
//    constraints), of up to 500 points on a small circle (a many-vertex image hull), of the
//    canonical points scaled (F shrinks to a point), or of a point far out (F empty);
// and checks, exactly, what fuzz_geometry checks, on samples where a check would cost more than
// the pipeline itself (the brute-force definition uses the image hull's vertices, which is
// equivalent: m ⊙ q is linear in q and G is convex; it is left out when one test would take more
// than 200000 exact orientations; membership in F is the target's own rational test, `inside`):
//  - the gamut, F and F's kind in canonical form; the gamut holds sampled canonical points, and
//    without expansion its vertices are input points; F independent of the image order;
//  - sampled vertices of F are feasible; candidates (sampled vertices, edge midpoints, nudged
//    vertices, gamut vertex ⊘ image point) are in F exactly when m ⊙ q ∈ G for every q;
//  - feasible_polygon: F's kind and exact set, contains() on the candidates, and when enclosed()
//    every vertex in its enclosure and every edge line within 6u (check_enclosed);
//  - select_maps as `gmcc select` calls it (the illuminant worst cases included): max-area in F
//    and beating every candidate in F, the 2-D mean F's centroid, the 3-D mean valid with an
//    enclosure meeting F, worst cases at least the angle to sampled vertices of F;
//  - an empty F: min_violation's least violation positive, attained (gamut_violation) at a vertex
//    of its minimisers;
//  - in one run in four (at most 200 canonical and 50 image points), Forsyth's 3-D CRULE on the
//    same chromaticities as colours (r, g, b) = b·(x, y, 1): F3 in canonical form, max-volume's
//    exact map in F3, the centroid F3's centroid, and (black included, no expansion) every
//    vertex d of F3 with d3 > 0 has its perspective (d1/d3, d2/d3) in F.

#include "fuzz_support.h"
#include "geometry_checks.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/min_violation.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/selection/worst_case_illuminant.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace {
using gmcc::ConvexKind;
using gmcc::ConvexSet2;
using gmcc::Point2;
using gmcc::Rational;
using namespace gmcc::fuzz;

Rational two_to(int e) {
  return e >= 0 ? Rational(power_of_two(static_cast<unsigned>(e))) : reduced(1, power_of_two(static_cast<unsigned>(-e)));
}

// The point of the unit circle at parameter t (tan of half the angle): exactly on the circle.
Point2 circle_point(const Rational& t) {
  const Rational den = 1 + t * t;
  return {Rational((1 - t * t) / den), Rational(2 * t / den)};
}

std::vector<Point2> canonical_points(ByteReader& in, unsigned family, int n) {
  std::vector<Point2> p;
  switch (family) {
    case 0: {  // parabola y = 1 + c·t², t in [0, 1]; c = 2^-k makes successive edges nearly parallel
      const Rational c = two_to(-static_cast<int>(in.byte() % 100));
      for (int i = 0; i < n; ++i) {
        const Rational t = reduced(i, n);
        p.push_back({Rational(1 + t), Rational(1 + c * t * t)});
      }
      // Close it from above so that the hull is the whole arc.
      p.push_back({Rational(1), Rational(2 + c)});
      p.push_back({Rational(2), Rational(2 + c)});
      break;
    }
    case 1:    // circle about (2, 2), radius 1
    case 2:    // ellipse about (2, 2), half-axes 1 and 2^-k: a sliver
    case 3: {  // tiny circle about (1, 1), radius 2^-k: near-duplicates
      const int k = 1 + in.byte() % 60;
      const Rational ry = family == 2 ? two_to(-k) : Rational(1);
      const Rational r = family == 3 ? two_to(-k) : Rational(1);
      const Point2 centre = family == 3 ? Point2{1, 1} : Point2{2, 2};
      for (int i = 0; i < n; ++i) {
        // t from -1 to 1 covers the right half; the mirror covers the left half.
        const Rational t = reduced(2 * (i / 2) - n / 2, n / 2 + 1);
        Point2 u = circle_point(t);
        if (i % 2) u.x = -u.x;
        p.push_back({Rational(centre.x + r * u.x), Rational(centre.y + r * ry * u.y)});
      }
      break;
    }
    case 4: {  // hyperbola x·y = 1 (with the corner that closes it): a range of 1 to n in each coordinate
      for (int i = 1; i <= n; ++i) p.push_back({Rational(i), reduced(1, i)});
      p.push_back({Rational(n), Rational(n)});
      break;
    }
    default: {  // a few points from the bytes
      for (int i = 0; i < 3 + n % 5; ++i) p.push_back({reduced(1 + in.byte(), 16), reduced(1 + in.byte(), 16)});
      break;
    }
  }
  return p;
}

std::vector<Point2> image_points(ByteReader& in, unsigned family, const std::vector<Point2>& canonical) {
  std::vector<Point2> q;
  switch (family) {
    case 1: {  // pairs a hair apart: nearly parallel constraints
      const Point2 base{reduced(16 + in.byte(), 64), reduced(16 + in.byte(), 64)};
      const Rational h = 1 + two_to(-1 - static_cast<int>(in.byte() % 120));
      q = {base, {Rational(base.x * h), base.y}, {base.x, Rational(base.y * h)}};
      if (in.byte() % 2) q.push_back({Rational(base.x * h), Rational(base.y * h)});
      break;
    }
    case 2: {  // many points on a small circle about (1, 1): a many-vertex image hull
      const int m = 3 + static_cast<int>(in.bytes(2) % 500);
      const Rational r = two_to(-2 - static_cast<int>(in.byte() % 30));
      for (int i = 0; i < m; ++i) {
        Point2 u = circle_point(reduced(2 * (i / 2) - m / 2, m / 2 + 1));
        if (i % 2) u.x = -u.x;
        q.push_back({Rational(1 + r * u.x), Rational(1 + r * u.y)});
      }
      break;
    }
    case 3: {  // the canonical points scaled by s: F shrinks to the point 1/s
      const Point2 s{reduced(1 + in.byte(), 32), reduced(1 + in.byte(), 32)};
      for (const Point2& c : canonical) q.push_back({Rational(c.x * s.x), Rational(c.y * s.y)});
      break;
    }
    case 4:  // one point far out, with one ordinary: F is likely empty
      q = {{Rational(1), Rational(1)}, {two_to(in.byte() % 64), reduced(1, 1 + in.byte())}};
      break;
    default:  // 1–4 points near (1, 1)
      for (int i = 0, m = 1 + in.byte() % 4; i < m; ++i)
        q.push_back({reduced(8 + in.byte() % 32, 16), reduced(8 + in.byte() % 32, 16)});
      break;
  }
  return q;
}

// With GMCC_FUZZ_TIMES set, each stage's wall time goes to stderr: a timeout names no stage, and
// this tells which one to report.
void stage(const char* name) {
  static const bool on = std::getenv("GMCC_FUZZ_TIMES") != nullptr;
  if (!on) return;
  using Clock = std::chrono::steady_clock;
  static Clock::time_point last = Clock::now();
  const Clock::time_point now = Clock::now();
  std::fprintf(stderr, "  %-28s %8.3f s\n", name, std::chrono::duration<double>(now - last).count());
  last = now;
}

// How many brute-force membership tests (each |image hull| · |G| exact orientations, on numbers as
// long as the inputs') fit in about as much time as the pipeline itself takes: at most 16, and none
// beyond 200000 orientations a test (one such test alone can take longer than the time limit).
std::size_t brute_force_budget(std::size_t hull, std::size_t gamut) {
  return std::min<std::size_t>(200000 / std::max<std::size_t>(1, hull * gamut), 16);
}

// k indices spread evenly over 0..n-1 (all of them when n <= k).
std::vector<std::size_t> sample(std::size_t n, std::size_t k) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < std::min(n, k); ++i) out.push_back(n <= k ? i : i * n / k);
  return out;
}

void check_3d(const std::vector<Point2>& canonical, const std::vector<Point2>& image, const ConvexSet2& F,
              bool include_black, bool compare_with_F) {
  std::vector<gmcc::Colour> c3, i3;
  for (const Point2& p : canonical) c3.push_back({p.x, p.y, Rational(1)});
  for (std::size_t i = 0; i < image.size(); ++i) {
    const Rational b(static_cast<long>(1 + i % 3));  // intensities vary: shading is allowed in 3-D
    i3.push_back({Rational(image[i].x * b), Rational(image[i].y * b), b});
  }
  const gmcc::Crule3d r =
      gmcc::crule_3d(c3, i3, include_black ? gmcc::CanonicalBlack::include : gmcc::CanonicalBlack::exclude);
  const gmcc::ConvexSet3& F3 = r.feasible;
  FUZZ_CHECK(gmcc::canonical_convex_set_3(F3.kind, F3.vertices, F3.faces) == F3, "F3 not in canonical form");
  FUZZ_CHECK(r.volume && *r.volume == gmcc::volume(F3) && sgn(*r.volume) >= 0, "F3's volume");
  FUZZ_CHECK(!include_black || F3.kind != gmcc::ConvexKind3::empty, "F3 empty though black is canonical");
  FUZZ_CHECK((F3.kind == gmcc::ConvexKind3::empty) == !r.max_volume && !r.max_volume == !r.centroid,
             "3-D selections present iff F3 is not empty");
  if (r.max_volume && r.max_volume->estimate.exact)
    FUZZ_CHECK(gmcc::contains(F3, *r.max_volume->estimate.exact), "max-volume's map not in F3");
  if (r.centroid)
    FUZZ_CHECK(r.centroid->estimate.exact && *r.centroid->estimate.exact == gmcc::centroid(F3),
               "the 3-D centroid is not F3's centroid");
  if (!include_black || !compare_with_F) return;
  for (std::size_t i : sample(F3.vertices.size(), 16)) {
    const gmcc::Point3& d = F3.vertices[i];
    if (sgn(d.z) <= 0) continue;
    const Point2 m{Rational(d.x / d.z), Rational(d.y / d.z)};
    FUZZ_CHECK(inside(F, m), "a vertex of F3 whose perspective " + text(m) + " is not in F");
  }
}

// A target input's recipe: flags, canonical points of one family, scaled per axis by powers of
// two (2^-20 to 2^20), and image points under the same scale (F stays about 1).
struct Recipe {
  std::uint8_t flags;
  std::vector<Point2> canonical, image;
};
Recipe read_recipe(ByteReader& in) {
  Recipe r;
  r.flags = in.byte();
  const unsigned family = in.byte() % 6;
  // One size byte in two: up to 64 points; otherwise up to 2000 (hundreds to thousands of vertices).
  const unsigned size_byte = in.byte();
  const int n = size_byte & 1 ? 3 + static_cast<int>(in.bytes(2) % 1998) : 3 + size_byte / 2 % 62;
  r.canonical = canonical_points(in, family, n);
  const Rational sx = two_to(static_cast<int>(in.byte() % 41) - 20), sy = two_to(static_cast<int>(in.byte() % 41) - 20);
  for (Point2& p : r.canonical) p = {Rational(p.x * sx), Rational(p.y * sy)};
  r.image = image_points(in, in.byte() % 5, r.canonical);
  for (Point2& q : r.image) q = {Rational(q.x * sx), Rational(q.y * sy)};  // the same scale: F stays about 1
  return r;
}

// The canonical gamut (expanded as the flags say) and its checks: every canonical point inside,
// every vertex an input point when not expanded.
ConvexSet2 checked_gamut(const std::vector<Point2>& canonical, const gmcc::Expansion& expansion) {
  const ConvexSet2 G = gmcc::canonical_gamut(canonical, expansion);
  stage("canonical_gamut");
  check_canonical(G, "canonical gamut");
  for (std::size_t i : sample(canonical.size(), brute_force_budget(1, G.vertices.size())))
    FUZZ_CHECK(inside(G, canonical[i]), "gamut misses " + text(canonical[i]));
  if (expansion.policy == gmcc::ExpansionPolicy::none) {
    const std::set<Point2> inputs(canonical.begin(), canonical.end());
    for (const Point2& v : G.vertices) FUZZ_CHECK(inputs.count(v), "hull vertex not an input point: " + text(v));
  }
  return G;
}

// Candidate maps about F's sampled vertices (the vertex, an edge midpoint, two nearby points)
// and gamut vertices over image points, checked against the target's membership test, contains,
// the definition (within the budget) and the feasible polygon; those in F.
std::vector<Point2> check_candidates(ByteReader& in, const ConvexSet2& G, const std::vector<Point2>& image,
                                     const ConvexSet2& F, const gmcc::FeasiblePolygon& P,
                                     const std::vector<Point2>& hull, std::size_t budget) {
  std::vector<Point2> candidates;
  const auto& fv = F.vertices;
  // Four candidates about each sampled vertex, and gamut vertices over image points: a budget's worth.
  for (std::size_t i : sample(fv.size(), std::max<std::size_t>(1, budget / 4))) {
    const Point2& v = fv[i];
    candidates.push_back(v);
    if (fv.size() >= 2) {
      const Point2& w = fv[(i + 1) % fv.size()];
      candidates.push_back({Rational((v.x + w.x) / 2), Rational((v.y + w.y) / 2)});
    }
    const unsigned b = in.byte();
    const Rational d = Rational(v.x + v.y + 1) / Rational(power_of_two(1 + b % 100));
    const int s = b & 128 ? 1 : -1;
    candidates.push_back({Rational(v.x + s * d), Rational(v.y + s * d)});
    candidates.push_back({Rational(v.x - s * d), Rational(v.y + s * d)});
  }
  for (std::size_t i : sample(G.vertices.size() * image.size(), std::max<std::size_t>(1, budget / 2))) {
    const Point2& g = G.vertices[i % G.vertices.size()];
    const Point2& q = image[i / G.vertices.size()];
    candidates.push_back({Rational(g.x / q.x), Rational(g.y / q.y)});
  }
  // Membership by the target's own test; gmcc::contains (slow on many-vertex sets: README) on a
  // few candidates only when F is large; the definition by brute force within the budget.
  std::vector<Point2> in_F;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Point2& m = candidates[k];
    const bool in = inside(F, m);
    if (fv.size() <= 300 || k < 4) FUZZ_CHECK(gmcc::contains(F, m) == in, "gmcc::contains(F, " + text(m) + ") is wrong");
    if (budget > 0)
      FUZZ_CHECK(in == feasible(G, hull, m), "map " + text(m) + (in ? " in F but not feasible" : " feasible but not in F"));
    FUZZ_CHECK(P.contains(m) == in, "feasible_polygon: contains(" + text(m) + ") is not " + (in ? "true" : "false"));
    if (in) in_F.push_back(m);
  }
  FUZZ_CHECK(P.exact() == F, "feasible_polygon: exact() is not F");
  return in_F;
}

// An empty F: min_violation finds a positive least violation, attained at its minimisers.
void check_min_violation(const ConvexSet2& G, const std::vector<Point2>& image) {
  const gmcc::MinViolation v = gmcc::min_violation(G, image);
  stage("min_violation");
  FUZZ_CHECK(sgn(v.violation) > 0, "min_violation: violation <= 0 for an empty F");
  FUZZ_CHECK(v.feasible.kind != ConvexKind::empty, "min_violation: no minimiser");
  check_canonical(v.feasible, "min_violation's minimisers");
  FUZZ_CHECK(gmcc::gamut_violation(G, image, v.feasible.vertices[0]) == v.violation,
             "min_violation: the violation is not attained at a minimiser");
  stage("min_violation checks");
}

// GMCC_FUZZ_TIMES: select_maps's parts one by one, to say which is slow.
void time_selection_parts(const ConvexSet2& F, const gmcc::Colour& light) {
  stage("(before the parts)");
  const gmcc::MapEstimate a = gmcc::max_area(F);
  stage("  max_area");
  const gmcc::MapEstimate b = gmcc::mean_2d(F);
  stage("  mean_2d");
  const gmcc::MapEstimate c = gmcc::mean_3d(F);
  stage("  mean_3d");
  for (const gmcc::MapEstimate* e : {&a, &b, &c}) {
    const Point2 m = e->exact ? *e->exact : Point2{gmcc::rational_from_double(e->map[0]), gmcc::rational_from_double(e->map[1])};
    (void)gmcc::worst_case_map_deg(F, m);
    stage(("  worst_case_map_deg " + e->rule).c_str());
    if (positive(m)) (void)gmcc::worst_case_illuminant_deg(F, m, light);
    stage(("  worst_case_illuminant_deg " + e->rule).c_str());
  }
}

// The three rules on a non-empty F: max-area beats every candidate in F, the 2-D mean is the
// centroid, the 3-D mean's enclosure meets F, and each worst case is at least every probe's.
void check_selections(const ConvexSet2& F, const std::vector<Point2>& in_F, const gmcc::Colour& light) {
  const auto& fv = F.vertices;
  const gmcc::Selections s = gmcc::select_maps(F, gmcc::SelectionOptions{{}, light});
  stage("select_maps");
  FUZZ_CHECK(s[gmcc::Rule::max_area] && s[gmcc::Rule::mean_2d] && s[gmcc::Rule::mean_3d], "a rule is missing for a non-empty F");
  const Point2 best = *s[gmcc::Rule::max_area]->estimate.exact;
  FUZZ_CHECK(inside(F, best), "max-area " + text(best) + " not in F");
  for (const Point2& m : in_F) FUZZ_CHECK(m.x * m.y <= best.x * best.y, "max-area beaten by " + text(m));
  const Point2 g = gmcc::centroid(F);  // once: on a many-vertex F it has 10^5 digits
  FUZZ_CHECK(*s[gmcc::Rule::mean_2d]->estimate.exact == g, "2-D mean not the centroid");
  FUZZ_CHECK(inside(F, g), "the centroid is not in F");
  const gmcc::MapEstimate& m3 = s[gmcc::Rule::mean_3d]->estimate;
  FUZZ_CHECK(m3.valid && m3.enclosure, "3-D mean not valid: " + m3.note);
  if (F.kind == ConvexKind::point) {
    FUZZ_CHECK(m3.exact && *m3.exact == fv[0], "3-D mean of a point is not the point");
  } else {
    const auto& e = *m3.enclosure;
    const Rational lo[2] = {gmcc::rational_from_double(e[0][0]), gmcc::rational_from_double(e[1][0])};
    const Rational hi[2] = {gmcc::rational_from_double(e[0][1]), gmcc::rational_from_double(e[1][1])};
    FUZZ_CHECK(lo[0] <= hi[0] && lo[1] <= hi[1], "3-D mean: enclosure upside down");
    // The exact separating-axis test costs |F|² products: only for F of up to 300 vertices.
    if (fv.size() <= 300) FUZZ_CHECK(box_meets(F, lo, hi), "3-D mean: the enclosure misses F");
  }
  std::vector<Point2> probes;
  for (std::size_t i : sample(fv.size(), 8)) probes.push_back(fv[i]);
  for (const auto* sel : {&*s[gmcc::Rule::max_area], &*s[gmcc::Rule::mean_2d], &*s[gmcc::Rule::mean_3d]}) {
    const gmcc::MapEstimate& est = sel->estimate;
    const Point2 m = est.exact ? *est.exact
                               : Point2{gmcc::rational_from_double(est.map[0]), gmcc::rational_from_double(est.map[1])};
    FUZZ_CHECK(sel->worst_case_deg.has_value(), est.rule + ": no worst case");
    check_worst(*sel->worst_case_deg, probes, [&m](const Point2& x) { return gmcc::map_angular_error_deg(m, x); },
                est.rule + " worst case");
    const bool all_positive = positive(m) && std::all_of(fv.begin(), fv.end(), positive);
    FUZZ_CHECK(sel->worst_case_illuminant_deg.has_value() == all_positive,
               est.rule + ": illuminant worst case present iff F and the map are positive");
    if (all_positive)
      check_worst(*sel->worst_case_illuminant_deg, probes,
                  [&m, &light](const Point2& x) { return gmcc::illuminant_angular_error_deg(m, x, light); },
                  est.rule + " illuminant worst case");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const Recipe r = read_recipe(in);
  const std::uint8_t flags = r.flags;
  const std::vector<Point2>& canonical = r.canonical;
  const std::vector<Point2>& image = r.image;
  stage("recipe");
  gmcc::Expansion expansion;
  if (flags % 4 == 1) expansion = {gmcc::ExpansionPolicy::multiplicative, Rational(1, 10)};
  if (flags % 4 == 2) expansion = {gmcc::ExpansionPolicy::centroid_clip, Rational(1, 10)};
  const ConvexSet2 G = checked_gamut(canonical, expansion);
  stage("gamut checks");
  const ConvexSet2 F = gmcc::feasible_set(G, image);  // images are positive: never unbounded
  stage("feasible_set");
  if (std::getenv("GMCC_FUZZ_TIMES"))
    std::fprintf(stderr, "  (%zu canonical points, G %zu vertices, %zu image points, F a %s of %zu vertices)\n",
                 canonical.size(), G.vertices.size(), image.size(), gmcc::to_string(F.kind).c_str(), F.vertices.size());
  check_canonical(F, "feasible set");
  const std::vector<Point2> reversed(image.rbegin(), image.rend());
  FUZZ_CHECK(gmcc::feasible_set(G, reversed) == F, "F depends on the image order (reversed)");
  stage("feasible_set (reversed)");
  const std::vector<Point2> hull = gmcc::convex_hull(image).vertices;  // as good as the image (above)
  const std::size_t budget = brute_force_budget(hull.size(), G.vertices.size());
  for (std::size_t i : sample(F.vertices.size(), budget))
    FUZZ_CHECK(feasible(G, hull, F.vertices[i]), "vertex " + text(F.vertices[i]) + " of F is not feasible");
  stage("F checks");
  const gmcc::CanonicalConstraints constraints(G);
  const gmcc::FeasiblePolygon P = gmcc::feasible_polygon(constraints, image);
  FUZZ_CHECK(P.kind() == F.kind, "feasible_polygon: kind differs from F's");
  FUZZ_CHECK(!P.enclosed() || P.kind() == ConvexKind::polygon, "feasible_polygon: enclosed but not a polygon");
  stage("feasible_polygon");
  if (P.enclosed()) check_enclosed(P, F);
  stage("check_enclosed");
  const std::vector<Point2> in_F = check_candidates(in, G, image, F, P, hull, budget);
  stage("candidates");
  if (flags & 4 && canonical.size() <= 200 && image.size() <= 50)
    check_3d(canonical, image, F, !(flags & 8), expansion.policy == gmcc::ExpansionPolicy::none);
  stage("crule_3d");
  if (F.kind == ConvexKind::empty) {
    check_min_violation(G, image);
    return 0;
  }
  if (!finite_doubles(F)) return 0;  // beyond the doubles: select_maps refuses (fuzz_geometry checks it)
  const gmcc::Colour light{2, 1, Rational(3, 7)};
  if (const char* path = std::getenv("GMCC_FUZZ_DUMP_F")) {  // F's exact vertices, one "x y" a line
    if (std::FILE* out = std::fopen(path, "w")) {           // (bench_worst_case_illuminant reads them)
      for (const Point2& v : F.vertices) std::fprintf(out, "%s %s\n", v.x.get_str().c_str(), v.y.get_str().c_str());
      std::fclose(out);
    }
  }
  if (std::getenv("GMCC_FUZZ_TIMES")) time_selection_parts(F, light);
  check_selections(F, in_F, light);
  stage("selection checks");
  return 0;
}
