#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/internal_check.h>
#include <gmcc/selection/max_volume.h>

#include "internal/interval.h"
#include "internal/max_volume_route.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace gmcc {
namespace {
using internal::Interval;

// The exact square root of a non-negative rational, when it is rational.
std::optional<Rational> rational_sqrt(const Rational& x) {
  if (!mpz_perfect_square_p(x.get_num_mpz_t()) || !mpz_perfect_square_p(x.get_den_mpz_t()))
    return std::nullopt;
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
  Rational r(n, d);
  r.canonicalize();
  return r;
}

// An irrational edge candidate: on the edge from vertex i to vertex j of F, p + t·u with
// t = (−b + sign·√disc)/(2a), kept in integers: p = P/S and u = U/S (S > 0) from the vertices'
// homogeneous coordinates, a, b, disc the derivative's coefficients for (P, U) — positive
// multiples (S³, S³, S⁶) of those for (p, u), so the same roots — without a gcd.
Interval integer_interval(const mpz_class& z, mpfr_prec_t bits) {
  Interval r(bits);
  mpfi_set_z(r.get(), z.get_mpz_t());
  return r;
}
struct EdgeRoot {
  std::size_t i, j;
  std::array<mpz_class, 3> P, U;
  mpz_class S, a, b, disc;
  int sign;
  Interval t(mpfr_prec_t bits) const {
    const Interval s = sqrt(integer_interval(disc, bits));
    Interval num = integer_interval(mpz_class(-b), bits) + (sign > 0 ? s : Interval(0, bits) - s);
    return num / integer_interval(mpz_class(2 * a), bits);
  }
  std::array<Interval, 3> point(mpfr_prec_t bits) const {
    const Interval tt = t(bits), s = integer_interval(S, bits);
    std::array<Interval, 3> out{Interval(bits), Interval(bits), Interval(bits)};
    for (std::size_t k = 0; k < 3; ++k) out[k] = (integer_interval(P[k], bits) + tt * integer_interval(U[k], bits)) / s;
    return out;
  }
};

// Max-volume's candidate arithmetic, written once for every number type: ℚ (Point3, the exact
// answer's form), ℤ (homogeneous, the exact stage's decisions) and double enclosures
// (Enclosure3, the filter), in the same operations and order.
const Rational& at(const Point3& p, int k) { return coord(p, k); }
const Enclosure& at(const Enclosure3& p, int k) { return p[static_cast<std::size_t>(k)]; }
const mpz_class& at(const std::array<mpz_class, 3>& p, int k) { return p[static_cast<std::size_t>(k)]; }
Rational constant(const Rational&, int c) { return c; }
Enclosure constant(const Enclosure&, int c) { return Enclosure::exact(c); }
mpz_class constant(const mpz_class&, int c) { return c; }

// On the edge p + t·u, f(t) = ∏_k (p_k + t·u_k) = A t³ + B t² + C t + D has the derivative
// f′(t) = a t² + b t + c, a = 3A, b = 2B, c = C, of discriminant b² − 4ac (docs/derivations.md §2.4).
template <class T>
struct EdgeDerivative {
  T a, b, c, disc;
};
template <class P>
auto edge_derivative(const P& p, const P& u) {
  using T = std::decay_t<decltype(at(p, 0))>;
  const T& p0 = at(p, 0);
  const T& p1 = at(p, 1);
  const T& p2 = at(p, 2);
  const T& u0 = at(u, 0);
  const T& u1 = at(u, 1);
  const T& u2 = at(u, 2);
  const T a = constant(p0, 3) * (u0 * u1 * u2);
  const T b = constant(p0, 2) * (p0 * u1 * u2 + u0 * p1 * u2 + u0 * u1 * p2);
  const T c = p0 * p1 * u2 + p0 * u1 * p2 + u0 * p1 * p2;
  const T disc = b * b - constant(p0, 4) * a * c;
  return EdgeDerivative<T>{a, b, c, disc};
}

// A rational candidate and its value d1·d2·d3 = num/den (den > 0, not in lowest terms: values
// are compared by cross-multiplication, without a gcd): vertex `vertex` of F, made exact only
// where it is the answer or ties, or else (vertex == none) `point`.
constexpr std::size_t none = static_cast<std::size_t>(-1);
struct RationalCandidate {
  std::size_t vertex = none;
  Point3 point;
  mpz_class num, den;
};
RationalCandidate point_candidate(Point3 p) {
  RationalCandidate c{none, std::move(p), 1, 1};
  for (int k = 0; k < 3; ++k) c.num *= coord(c.point, k).get_num(), c.den *= coord(c.point, k).get_den();
  return c;
}
// From the homogeneous coordinates (X, Y, Z, W), W > 0: XYZ/W³; from the exact vertex where F was
// made exact (its homogeneous form would cost a gcd).
RationalCandidate vertex_candidate(const LazyConvexSet3& F, std::size_t i) {
  if (F.exact_vertices() == F.size()) {
    RationalCandidate c = point_candidate(F.vertex(i));
    c.vertex = i;
    return c;
  }
  const std::array<mpz_class, 4>& h = F.homogeneous(i);
  return {i, {}, h[0] * h[1] * h[2], h[3] * h[3] * h[3]};
}
const Point3& where(const LazyConvexSet3& F, const RationalCandidate& c) {
  return c.vertex == none ? c.point : F.vertex(c.vertex);
}
// a's value above b's, or equal and a lexicographically first (vertices: the canonical order is
// the lexicographic one).
bool better(const LazyConvexSet3& F, const RationalCandidate& a, const RationalCandidate& b) {
  if (const int s = sgn(mpz_class(a.num * b.den - b.num * a.den))) return s > 0;
  if (a.vertex != none && b.vertex != none) return a.vertex < b.vertex;
  return where(F, a) < where(F, b);
}

// The candidates for the maximum of d1·d2·d3 on F among `which`: rational ones (vertices, facet
// stationary points, rational edge roots) and the edges' irrational roots.
struct Candidates {
  std::vector<RationalCandidate> rational;
  std::vector<EdgeRoot> irrational;
};
Candidates candidates(const LazyConvexSet3& F, const internal::MaxVolumeCandidates& which) {
  const auto v = [&F](std::size_t i) -> const Point3& { return F.vertex(i); };
  Candidates out;
  std::vector<RationalCandidate>& rational = out.rational;
  std::vector<EdgeRoot>& irrational = out.irrational;
  for (std::size_t i : which.vertices) rational.push_back(vertex_candidate(F, i));
  for (std::size_t face : which.faces) {  // polytope facets, or the polygon
    // The stationary point d = k/(3n) of the facet's plane n·x = k (any nonzero multiple of it:
    // the same d and signs), in integers.
    const auto [n, k] = F.facet_plane(face);
    if (sgn(n[0]) == 0 || sgn(n[1]) == 0 || sgn(n[2]) == 0) continue;
    if (sgn(k) * sgn(n[0]) <= 0 || sgn(k) * sgn(n[1]) <= 0 || sgn(k) * sgn(n[2]) <= 0) continue;
    Point3 d{Rational(k, 3 * n[0]), Rational(k, 3 * n[1]), Rational(k, 3 * n[2])};
    d.x.canonicalize(), d.y.canonicalize(), d.z.canonicalize();
    if (contains(F, d)) rational.push_back(point_candidate(std::move(d)));
  }
  for (const auto& edge : which.edges) {
    const std::size_t i = edge.first, j = edge.second;  // named, not bound: the lambda below captures them
    const auto &hp = F.homogeneous(i), &hq = F.homogeneous(j);
    EdgeRoot e{i, j, {}, {}, hp[3] * hq[3], 0, 0, 0, 1};
    for (std::size_t k = 0; k < 3; ++k) e.P[k] = hp[k] * hq[3], e.U[k] = hq[k] * hp[3] - e.P[k];
    const auto [a, b, c, disc] = edge_derivative(e.P, e.U);
    auto consider = [&](const Rational& t) {
      if (sgn(t) > 0 && t < 1) rational.push_back(point_candidate(add(v(i), scale(sub(v(j), v(i)), t))));
    };
    if (sgn(a) == 0) {
      if (sgn(b) != 0) {
        Rational t(-c, b);
        t.canonicalize();
        consider(t);
      }
      continue;
    }
    if (sgn(disc) < 0) continue;
    if (const auto r = rational_sqrt(Rational(disc))) {
      consider(Rational((-b + *r) / (2 * a)));
      consider(Rational((-b - *r) / (2 * a)));
      continue;
    }
    e.a = a, e.b = b, e.disc = disc;
    for (int sign : {1, -1}) {
      e.sign = sign;
      irrational.push_back(e);
    }
  }
  return out;
}

// An irrational winner's map enclosed tightly enough for a double (at least `bits`), reported
// with its exact form.
MapEstimate3 edge_root_estimate(const LazyConvexSet3& F, const EdgeRoot& e, mpfr_prec_t bits) {
  const auto d = e.point(std::max<mpfr_prec_t>(bits, 256));
  MapEstimate3 out;
  out.rule = "max_volume";
  out.method = "certified";
  for (int k = 0; k < 3; ++k) {
    const auto [m, bound] = internal::nearest_with_bound(d[k]);
    const auto [lo, hi] = internal::outward_doubles(d[k]);
    out.map[k] = m;
    out.error_bound = std::max(out.error_bound, bound);
    out.enclosure[k] = {lo, hi};
  }
  // The exact description in the edge's own rationals: its ends in lowest terms and the
  // derivative's coefficients for them (the integer ones above are multiples of these).
  const Point3 &p = F.vertex(e.i), &q = F.vertex(e.j);
  const auto [a, b, c, disc] = edge_derivative(p, sub(q, p));
  out.edge_root = MapEstimate3::EdgeRoot{p, q, a, b, c, e.sign};
  return out;
}

// The filter's arithmetic: double enclosures (geometry/enclosure.h) of exact coordinates.
using E3 = Enclosure3;
Enclosure product(const E3& d) { return d[0] * d[1] * d[2]; }
bool finite(const E3& a) { return a[0].finite() && a[1].finite() && a[2].finite(); }
// A certain upper end of |x|.
double magnitude(const Enclosure& x) { return std::max(std::fabs(x.lo()), std::fabs(x.hi())); }

// One candidate as the filter sees it: where it is, how large its value can be, and what is known:
// `in_f3`, certainly a point of F (a vertex, a stationary point certainly inside, an edge root
// certainly within its edge), so its value's lower end is attained; `maybe_in_f3`, its value
// enclosed but not whether it lies in F; `bound_only`, a sign the filter could not decide, so
// only `upper` (a bound over the whole facet or edge) is known and the exact stage decides.
enum class Slot { vertex, face, edge };
enum class Known { in_f3, maybe_in_f3, bound_only };
struct Seen {
  Slot slot;
  std::size_t index;  // into vertices, faces or the edge list
  double lower, upper;
  Known known;
};

// Every vertex's largest |d_k| (certain upper ends), for hull_bound.
using Magnitudes = std::vector<std::array<double, 3>>;
Magnitudes magnitudes(const std::vector<E3>& e) {
  Magnitudes m(e.size());
  for (std::size_t i = 0; i < e.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) m[i][k] = magnitude(e[i][k]);
  return m;
}

// An upper end of d1·d2·d3 on the convex hull of `points`: each |d_k| is at most its largest |d_k|
// there (|·| is convex). For a candidate the filter cannot place, and a cap on the value of any
// candidate on that hull (a facet's stationary point in F lies in the facet, an edge's root on the
// edge).
template <class Indices>
double hull_bound(const Magnitudes& mag, const Indices& points) {
  double m[3] = {0, 0, 0};
  for (std::size_t i : points)
    for (std::size_t k = 0; k < 3; ++k) m[k] = std::max(m[k], mag[i][k]);
  return Enclosure::round_up(m[0] * m[1] * m[2]);
}

// A facet's stationary point d = k/(3n) (docs/derivations.md §2.4) as the filter sees it, not yet
// placed against the other facets; nothing when it is certainly no candidate (some k·n_k <= 0).
// `bound` is hull_bound over the facet's vertices.
std::optional<Seen> face_candidate(const EnclosedPlane& h, std::size_t index, double bound, E3& point) {
  const Seen unplaced{Slot::face, index, 0, bound, Known::bound_only};
  const Enclosure* c[4] = {&h.n[0], &h.n[1], &h.n[2], &h.k};
  for (const Enclosure* x : c)
    if (!certainly_nonzero(*x)) return unplaced;
  for (int k = 0; k < 3; ++k)
    if (certainly_positive(*c[k]) != certainly_positive(h.k)) return std::nullopt;
  const Enclosure three = Enclosure::exact(3);
  point = {h.k / (three * h.n[0]), h.k / (three * h.n[1]), h.k / (three * h.n[2])};
  const Enclosure value = product(point);
  if (!value.finite()) return unplaced;
  return Seen{Slot::face, index, value.lo(), std::min(value.hi(), bound), Known::maybe_in_f3};
}

// 0: the point is certainly inside every facet but `self`; -1: certainly outside one; 1: unsure.
int placed(const std::vector<EnclosedPlane>& planes, std::size_t self, const E3& d) {
  int unsure = 0;
  for (std::size_t g = 0; g < planes.size(); ++g) {
    if (g == self) continue;
    const Enclosure s = side(planes[g], d);
    if (certainly_positive(s)) return -1;
    if (!certainly_negative(s)) unsure = 1;
  }
  return unsure;
}

// An edge p + t·u's roots of f'(t) = a t² + b t + c in (0, 1) as the filter sees them (see
// candidates()), appended to `seen`: each root certainly inside, or else one bound_only entry for
// the whole edge, whose upper end is `bound`, hull_bound over the edge's ends.
void edge_candidates(const std::vector<E3>& e, std::size_t index, std::size_t i, std::size_t j, double bound,
                     std::vector<Seen>& seen) {
  const E3& p = e[i];
  const E3 u = e[j] - p;
  const auto [a, b, c, disc] = edge_derivative(p, u);
  const Enclosure two = Enclosure::exact(2);
  const Seen unplaced{Slot::edge, index, 0, bound, Known::bound_only};
  if (!certainly_nonzero(a) || !disc.finite()) return seen.push_back(unplaced);
  if (certainly_negative(disc)) return;  // no real root
  if (!certainly_positive(disc)) return seen.push_back(unplaced);
  std::array<Seen, 2> roots;
  std::size_t found = 0;
  const Enclosure root = sqrt(disc), one = Enclosure::exact(1);
  for (const Enclosure& t : {(-b + root) / (two * a), (-b - root) / (two * a)}) {
    if (!t.finite() || !certainly_nonzero(t)) return seen.push_back(unplaced);  // t at 0 unsure
    if (certainly_negative(t)) continue;
    const Enclosure beyond = t - one;
    if (certainly_positive(beyond)) continue;
    if (!certainly_negative(beyond)) return seen.push_back(unplaced);  // t at 1 unsure
    const Enclosure value = product({p[0] + t * u[0], p[1] + t * u[1], p[2] + t * u[2]});
    if (!value.finite()) return seen.push_back(unplaced);
    roots[found++] = {Slot::edge, index, value.lo(), std::min(value.hi(), bound), Known::in_f3};
  }
  seen.insert(seen.end(), roots.begin(), roots.begin() + static_cast<std::ptrdiff_t>(found));
}

// The facets' stationary points whose value could win (see max_volume_contenders), appended to
// `seen`, each placed against the outward planes (all made at the first placement); `best` grows
// as they are placed.
void facet_candidates(const LazyConvexSet3& F, const Magnitudes& mag, double& best, std::vector<Seen>& seen) {
  const std::vector<E3>& e = F.enclosures();
  std::vector<std::pair<Seen, E3>> faces;
  for (std::size_t f = 0; f < F.faces().size(); ++f) {
    const double bound = hull_bound(mag, F.faces()[f]);
    if (bound < best) continue;
    E3 point{};
    const std::optional<Seen> s = face_candidate(enclosed_facet_plane(e, F.faces()[f]), f, bound, point);
    if (s && s->upper >= best) faces.push_back({*s, point});
  }
  std::vector<EnclosedPlane> planes;
  for (auto& [s, point] : faces) {
    if (s.upper < best) continue;
    if (s.known == Known::bound_only) {  // the exact stage decides
      seen.push_back(s);
      continue;
    }
    if (planes.empty())
      for (const auto& f : F.faces()) planes.push_back(enclosed_facet_plane(e, f));
    const int where = placed(planes, s.index, point);
    if (where < 0) continue;
    if (where == 0) s.known = Known::in_f3, best = std::max(best, s.lower);
    seen.push_back(s);
  }
}

// F's edges, each (smaller index, larger), sorted.
std::vector<std::pair<std::size_t, std::size_t>> edges_of(const LazyConvexSet3& F) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& f : F.faces())
    for (std::size_t i = 0; i < f.size(); ++i) edges.push_back(std::minmax(f[i], f[(i + 1) % f.size()]));
  if (F.kind() == ConvexKind3::segment) edges.push_back({0, 1});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

internal::StageCounts& counts() {
  static internal::StageCounts c;
  return c;
}

}  // namespace

namespace internal {

MaxVolumeCandidates all_max_volume_candidates(const ConvexSet3& F) {
  return all_max_volume_candidates(LazyConvexSet3(F));
}

MaxVolumeCandidates all_max_volume_candidates(const LazyConvexSet3& F) {
  MaxVolumeCandidates all;
  for (std::size_t i = 0; i < F.size(); ++i) all.vertices.push_back(i);
  for (std::size_t f = 0; f < F.faces().size(); ++f) all.faces.push_back(f);
  all.edges = edges_of(F);
  return all;
}

std::optional<MaxVolumeCandidates> max_volume_contenders(const ConvexSet3& F) {
  return max_volume_contenders(LazyConvexSet3(F));
}

std::optional<MaxVolumeCandidates> max_volume_contenders(const LazyConvexSet3& F) {
  if (F.kind() != ConvexKind3::polytope) return std::nullopt;
  const std::vector<E3>& e = F.enclosures();
  for (const E3& x : e)
    if (!finite(x)) return std::nullopt;
  // A candidate whose hull bound (the facet's or edge's) is below a value certainly attained
  // cannot be the maximiser and is passed over before its enclosed arithmetic: its value lies
  // in [lower, upper] and below the hull bound, so it could neither raise `best` (lower < best)
  // nor be needed.
  const Magnitudes mag = magnitudes(e);
  std::vector<Seen> seen;
  seen.reserve(e.size() + 16);
  double best = -std::numeric_limits<double>::infinity();  // the largest value certainly attained
  for (std::size_t i = 0; i < e.size(); ++i) {
    const Enclosure value = product(e[i]);
    if (!value.finite()) return std::nullopt;
    seen.push_back({Slot::vertex, i, value.lo(), value.hi(), Known::in_f3});
    best = std::max(best, value.lo());
  }
  // Edges: the facets are oriented consistently (counter-clockwise seen from outside), so each
  // edge is walked once in each direction, and the walks from the smaller index are each edge
  // once. `edges` holds the ones examined.
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& f : F.faces())
    for (std::size_t i = 0; i < f.size(); ++i) {
      const std::size_t a = f[i], b = f[(i + 1) % f.size()];
      if (a > b) continue;
      const double bound = hull_bound(mag, std::array<std::size_t, 2>{a, b});
      if (bound < best) continue;
      const std::size_t first = seen.size();
      edges.push_back({a, b});
      edge_candidates(e, edges.size() - 1, a, b, bound, seen);
      for (std::size_t s = first; s < seen.size(); ++s)
        if (seen[s].known == Known::in_f3) best = std::max(best, seen[s].lower);
    }
  facet_candidates(F, mag, best, seen);
  // The contenders: every candidate whose value may reach `best`, and a vertex for the exact
  // stage to start from.
  MaxVolumeCandidates out;
  std::size_t start = 0;  // the vertex of largest certain value (seen[i] is vertex i)
  for (std::size_t i = 0; i < e.size(); ++i)
    if (seen[i].lower > seen[start].lower) start = i;
  for (const Seen& s : seen) {
    if (s.upper < best) continue;
    if (s.slot == Slot::vertex) out.vertices.push_back(s.index);
    if (s.slot == Slot::face) out.faces.push_back(s.index);
    if (s.slot == Slot::edge) out.edges.push_back(edges[s.index]);
  }
  out.vertices.push_back(start);
  for (auto* list : {&out.vertices, &out.faces}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  std::sort(out.edges.begin(), out.edges.end());  // edges_of's order
  out.edges.erase(std::unique(out.edges.begin(), out.edges.end()), out.edges.end());
  return out;
}

MapEstimate3 max_volume_over(const ConvexSet3& F, const MaxVolumeCandidates& which) {
  return max_volume_over(LazyConvexSet3(F), which);
}

MapEstimate3 max_volume_over(const LazyConvexSet3& F, const MaxVolumeCandidates& which) {
  Candidates c = candidates(F, which);
  const std::vector<RationalCandidate>& rational = c.rational;
  std::vector<EdgeRoot>& irrational = c.irrational;

  // The best rational candidate, exactly (ties: the lexicographically smallest).
  std::size_t best = 0;
  for (std::size_t i = 1; i < rational.size(); ++i)
    if (better(F, rational[i], rational[best])) best = i;
  const Rational best_value(rational[best].num, rational[best].den);  // not in lowest terms

  // Irrational candidates: drop those outside (0, 1), then separate the winner.
  for (mpfr_prec_t bits = 128; !irrational.empty(); bits *= 2) {
    GMCC_CHECK(bits <= (1 << 16), "max_volume: distinct candidates separate below 2^16 bits");
    std::vector<EdgeRoot> inside;
    bool unsure = false;
    for (const EdgeRoot& e : irrational) {
      const Interval t = e.t(bits);
      const numerics::UncertainSign above_0 = compare(t, 0), above_1 = compare(t, 1);
      if (certainly_positive(above_0) && certainly_negative(above_1)) inside.push_back(e);
      else if (!certainly_nonzero(above_0) || !certainly_nonzero(above_1)) unsure = true, inside.push_back(e);
    }
    if (unsure) continue;
    irrational = std::move(inside);
    if (irrational.empty()) break;
    std::vector<Interval> value;
    for (const EdgeRoot& e : irrational) {
      const auto d = e.point(bits);
      value.push_back(d[0] * d[1] * d[2]);
    }
    // Rational winner: every irrational value surely below best_value.
    bool all_below = true;
    for (const Interval& x : value) all_below = all_below && certainly_negative(compare(x, best_value));
    if (all_below) break;
    // Irrational winner: above best_value and above every other irrational candidate.
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (!certainly_positive(compare(value[i], best_value))) continue;
      bool wins = true;
      for (std::size_t j = 0; j < value.size() && wins; ++j)
        wins = j == i || certainly_positive(compare(value[i], value[j]));
      if (!wins) continue;
      return edge_root_estimate(F, irrational[i], bits);
    }
  }
  return exact_map_estimate_3("max_volume", where(F, rational[best]));
}

const StageCounts& max_volume_stage_counts() { return counts(); }

}  // namespace internal

MapEstimate3 max_volume(const ConvexSet3& F) { return max_volume(LazyConvexSet3(F)); }

MapEstimate3 max_volume(const LazyConvexSet3& F) {
  if (F.kind() == ConvexKind3::empty) throw std::invalid_argument("max_volume: empty feasible set");
  const std::optional<internal::MaxVolumeCandidates> contenders = internal::max_volume_contenders(F);
  return internal::staged(
      counts(),
      [&]() -> std::optional<MapEstimate3> {  // one vertex left: it is the maximiser
        if (!contenders || !contenders->faces.empty() || !contenders->edges.empty() ||
            contenders->vertices.size() != 1)
          return std::nullopt;
        return exact_map_estimate_3("max_volume", F.vertex(contenders->vertices.front()));
      },
      [&]() -> std::optional<MapEstimate3> {
        if (!contenders) return std::nullopt;
        return internal::max_volume_over(F, *contenders);
      },
      [&] { return internal::max_volume_over(F, internal::all_max_volume_candidates(F)); });
}

}  // namespace gmcc
