// Fuzz target: Forsyth's CRULE feasible set in 3-D by the prepared route (CanonicalConstraints3,
// the filtered clip) against the LP route it replaced (test::feasible_set_3d_reference), on
// recipes of small, huge, tiny and long rationals, duplicates, coplanar and collinear gamuts,
// images of scaled canonical colours (F3 a point), zero channels (unbounded) and images large
// enough for the image-hull prefilter (fuzz/README.md). Then the filtered selections on F3:
// max_volume's staged answer is its exact stage's over every candidate, max_trace and the worst
// case are the vertices' best in ℚ, the certified centroid encloses the exact one, and contains()
// agrees with every facet's plane in ℚ (points 10^-9 and 2^-80 beyond each vertex). Last, the
// lazy route (feasible_set_3d_lazy: F3 kept symbolic, vertices made exact only on request) gives
// F3's kind, faces, zero flags and enclosures bit for bit, and the selections' and contains()'s
// answers on F3, each on a fresh lazy set so that an exact stage makes what it needs.
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/lazy_convex_set_3.h>

#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/max_volume.h>

#include "fuzz_support.h"
#include "internal/crule_exact.h"
#include "support/cgal_references.h"
#include "internal/max_volume_route.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

// A Rational is always in canonical form (docs/conventions.md §1): every value made here from a
// numerator and a denominator is canonicalised.
Rational reduced(Rational r) {
  r.canonicalize();
  return r;
}

Rational number(fuzz::ByteReader& in) {
  const std::uint8_t kind = in.byte();
  const long v = static_cast<long>(in.byte());
  switch (kind % 6) {
    case 0: return Rational(v % 8);
    case 1: return reduced(Rational(v, 1 + in.byte()));
    case 2: {  // a power of two, 2^-60 … 2^60, times a small odd number
      Rational r(1 + 2 * (v % 4));
      const int e = static_cast<int>(in.byte() % 121) - 60;
      if (e >= 0) r *= Rational(mpz_class(1) << e);
      else r /= Rational(mpz_class(1) << -e);
      return r;
    }
    case 3: {  // a long numerator over a long denominator
      mpz_class n(1 + v), d(1 + in.byte());
      for (int i = 0; i < 4; ++i) n = n * 257 + in.byte(), d = d * 263 + in.byte();
      return reduced(Rational(n, d));
    }
    case 4: return reduced(Rational(v % 4, 3));
    default: return Rational(v);
  }
}

Colour colour(fuzz::ByteReader& in) { return {number(in), number(in), number(in)}; }

bool same(const ConvexSet3& a, const ConvexSet3& b) { return a == b; }

// Whether two estimates are the same answer: method, doubles, enclosure, bound, exact map or
// edge root.
bool same_estimate(const MapEstimate3& a, const MapEstimate3& b) {
  return a.method == b.method && a.map == b.map && a.enclosure == b.enclosure && a.error_bound == b.error_bound &&
         a.exact.has_value() == b.exact.has_value() && (!a.exact || *a.exact == *b.exact) &&
         a.edge_root.has_value() == b.edge_root.has_value() &&
         (!a.edge_root || (a.edge_root->from == b.edge_root->from && a.edge_root->to == b.edge_root->to &&
                           a.edge_root->a == b.edge_root->a && a.edge_root->b == b.edge_root->b &&
                           a.edge_root->c == b.edge_root->c && a.edge_root->sign == b.edge_root->sign));
}

// Points a hair beyond each vertex of F (probes for contains()).
std::vector<Point3> probes(const ConvexSet3& F) {
  std::vector<Point3> out;
  for (const Rational& hair : {reduced(Rational(1, 1000000007)), Rational(1, mpz_class(1) << 80)})
    for (const Point3& v : F.vertices)
      out.push_back({Rational(v.x * (1 + hair)), Rational(v.y * (1 + hair)), Rational(v.z * (1 - hair))});
  return out;
}

// The filtered selections against their exact routes (docs/math.md §1b).
void check_selections(const ConvexSet3& F) {
  if (F.kind == ConvexKind3::empty) return;
  FUZZ_CHECK(same_estimate(max_volume(F), internal::max_volume_over(F, internal::all_max_volume_candidates(F))),
             "max_volume's filter gives its exact stage's answer");
  // max_trace and the worst case from the centroid against every vertex in ℚ.
  const Point3* trace = &F.vertices.front();
  for (const Point3& v : F.vertices)
    if (v.x + v.y + v.z > trace->x + trace->y + trace->z) trace = &v;
  FUZZ_CHECK(*max_trace(F).exact == *trace, "max_trace is the first vertex of largest trace");
  const Point3 c = centroid(F);
  const MapEstimate3 certified = centroid_3(F, Crule3dRoute::certified);
  const Rational* ck[3] = {&c.x, &c.y, &c.z};
  for (std::size_t k = 0; k < 3; ++k)
    FUZZ_CHECK(certified.method == "exact" ? certified.exact && *certified.exact == c
                                           : rational_from_double(certified.enclosure[k][0]) <= *ck[k] &&
                                                 *ck[k] <= rational_from_double(certified.enclosure[k][1]),
               "the certified centroid encloses the exact one");
  if (F.kind != ConvexKind3::polytope) return;
  // contains(): the centroid and points a hair beyond each vertex, against the facets in ℚ.
  auto inside = [&](const Point3& p) {
    for (const auto& f : F.faces) {
      const Point3 &o = F.vertices[f[0]], &a = F.vertices[f[1]], &b = F.vertices[f[2]];
      const Rational ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z, bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
      const Rational side = (ay * bz - az * by) * (p.x - o.x) + (az * bx - ax * bz) * (p.y - o.y) + (ax * by - ay * bx) * (p.z - o.z);
      if (sgn(side) > 0) return false;
    }
    return true;
  };
  FUZZ_CHECK(contains(F, c), "the centroid is in F3");
  if (sgn(c.x) != 0 || sgn(c.y) != 0 || sgn(c.z) != 0) {
    auto dot = [](const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); };
    const Point3* worst = nullptr;
    Rational least;
    for (const Point3& v : F.vertices) {
      if (sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0) continue;
      const Rational cv = dot(c, v), cos2 = cv * cv / dot(v, v);
      if (!worst || cos2 < least) worst = &v, least = cos2;
    }
    FUZZ_CHECK(worst_case_map_deg_3d(F, c) == diagonal_map_angular_error_deg(c, *worst),
               "the worst case from the centroid is the vertex of least cos² in ℚ");
  }
  for (const Point3& out : probes(F)) FUZZ_CHECK(contains(F, out) == inside(out), "contains() agrees with the facets in ℚ");
}

// F3 kept symbolic (feasible_set_3d_lazy: its vertices known by truncated doubles from the clip,
// made exact only on request; docs/derivations.md §4.6) against F3 made exact: the same set and
// enclosures bit for bit, and the same answers from every rule and from contains(), each asked of
// a fresh lazy set so that its exact stages make the vertices they need.
void check_lazy(const std::vector<GamutConstraint3>& constraints, const ConvexSet3& F) {
  const auto fresh = [&constraints] { return feasible_set_3d_lazy(constraints); };
  const LazyConvexSet3 L = fresh();
  FUZZ_CHECK(L.kind() == F.kind && L.size() == F.vertices.size() && L.faces() == F.faces,
             "the lazy F3 has F3's kind, vertex count and faces");
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Point3& v = F.vertices[i];
    const Enclosure3 want = enclose_point(v);
    for (std::size_t k = 0; k < 3; ++k)
      FUZZ_CHECK(L.enclosures()[i][k].mid == want[k].mid && L.enclosures()[i][k].rad == want[k].rad,
                 "a lazy vertex's enclosure is enclose_point of the exact vertex, bit for bit");
    FUZZ_CHECK(L.is_zero(i) == (sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0), "the lazy zero flags are F3's");
  }
  FUZZ_CHECK(L.exact() == F, "the lazy F3 made exact is F3");
  if (F.kind == ConvexKind3::empty) return;
  FUZZ_CHECK(same_estimate(max_volume(fresh()), max_volume(F)), "max_volume on the lazy F3 is max_volume on F3");
  FUZZ_CHECK(same_estimate(max_trace(fresh()), max_trace(F)), "max_trace on the lazy F3 is max_trace on F3");
  FUZZ_CHECK(same_estimate(centroid_3(fresh(), Crule3dRoute::certified), centroid_3(F, Crule3dRoute::certified)),
             "the certified centroid of the lazy F3 is F3's");
  const Point3 c = centroid(F);
  if (sgn(c.x) != 0 || sgn(c.y) != 0 || sgn(c.z) != 0)
    FUZZ_CHECK(worst_case_map_deg_3d(fresh(), c) == worst_case_map_deg_3d(F, c),
               "the worst case from the centroid on the lazy F3 is F3's");
  const LazyConvexSet3 probed = fresh();
  FUZZ_CHECK(contains(probed, c) == contains(F, c), "contains() on the lazy F3 agrees on the centroid");
  for (const Point3& out : probes(F)) FUZZ_CHECK(contains(probed, out) == contains(F, out), "contains() on the lazy F3 agrees");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader in(data, size);
  const std::uint8_t flags = in.byte();
  const bool black = flags & 1;
  const int shape = (flags >> 1) % 4;  // 0: free, 1: planar, 2: collinear, 3: one colour
  const int n = 1 + in.byte() % 12;
  std::vector<Colour> canonical;
  const Colour p = colour(in), q = colour(in), r = colour(in);
  for (int i = 0; i < n; ++i) {
    if (shape == 0) canonical.push_back(colour(in));
    else {
      const Rational s = reduced(Rational(in.byte() % 5, 4)), t = reduced(Rational(shape == 1 ? in.byte() % 5 : 0, 4));
      // p + s(q - p) + t(r - p), each channel made >= 0 (abs keeps it exact and may unflatten it)
      Colour c{Rational(p.r + s * (q.r - p.r) + t * (r.r - p.r)), Rational(p.g + s * (q.g - p.g) + t * (r.g - p.g)),
               Rational(p.b + s * (q.b - p.b) + t * (r.b - p.b))};
      for (Rational* x : {&c.r, &c.g, &c.b}) *x = abs(*x);
      canonical.push_back(shape == 3 ? p : c);
    }
  }
  const std::uint8_t image_kind = in.byte();
  const int m = image_kind % 8 == 7 ? 64 + in.byte() % 64 : 1 + in.byte() % 8;
  // (1 + n % 7)/(1 + m % 5), the bytes read in order (function arguments are not sequenced).
  auto ratio = [&in] {
    const long n = 1 + in.byte() % 7;
    return reduced(Rational(n, 1 + in.byte() % 5));
  };
  const Colour d{ratio(), ratio(), ratio()};
  std::vector<Colour> image;
  for (int i = 0; i < m; ++i) {
    const std::uint8_t how = in.byte() % 4;
    if (how == 0) image.push_back(colour(in));
    else {  // a canonical colour under the map 1/d, maybe shaded
      const Colour& c = canonical[in.byte() % canonical.size()];
      const Rational f = how == 3 ? reduced(Rational(1 + in.byte() % 16, 16)) : Rational(1);
      image.push_back({Rational(c.r / d.r * f), Rational(c.g / d.g * f), Rational(c.b / d.b * f)});
    }
  }
  const CanonicalBlack b = black ? CanonicalBlack::include : CanonicalBlack::exclude;
  std::string old_error, new_error;
  ConvexSet3 old, now;
  const CanonicalConstraints3 prepared(canonical, b);
  try {
    old = test::feasible_set_3d_reference(canonical, image, b);
  } catch (const UnboundedFeasibleSet&) {
    old_error = "unbounded";
  } catch (const std::invalid_argument&) {
    old_error = "invalid";
  }
  try {
    now = feasible_set_3d(prepared, image);
  } catch (const UnboundedFeasibleSet&) {
    new_error = "unbounded";
  } catch (const std::invalid_argument&) {
    new_error = "invalid";
  }
  FUZZ_CHECK(old_error == new_error, "the same error: '" + old_error + "' against '" + new_error + "'");
  if (!old_error.empty()) return 0;
  FUZZ_CHECK(same(now, old), "the prepared route gives the LP route's F3 (kind " + to_string(now.kind) + " against " +
                                 to_string(old.kind) + ")");
  FUZZ_CHECK(same(canonical_convex_set_3(now.kind, now.vertices, now.faces), now), "F3 in canonical form");
  // Every vertex of F3 maps every image colour into G_c3 (its half-spaces, exactly).
  std::vector<Point3> g;
  for (const Colour& c : canonical) g.push_back({c.r, c.g, c.b});
  if (black) g.push_back({0, 0, 0});
  std::sort(g.begin(), g.end());
  g.erase(std::unique(g.begin(), g.end()), g.end());
  const std::vector<internal::HalfSpace3> G = internal::hull_half_spaces_3(g);
  for (const Point3& v : now.vertices)
    for (const Colour& c : image)
      for (const internal::HalfSpace3& h : G)
        FUZZ_CHECK(h.a.x * v.x * c.r + h.a.y * v.y * c.g + h.a.z * v.z * c.b <= h.b, "a vertex of F3 is feasible");
  check_selections(now);
  check_lazy({GamutConstraint3{&prepared, &image}}, now);
  return 0;
}
