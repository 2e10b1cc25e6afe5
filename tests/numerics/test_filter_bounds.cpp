// The hand-derived error constants of the ten filter sites (numerics/filter_bounds.h): each is at
// least the γ_n of the rounding steps its derivation counts, and on random and adversarial inputs
// (exponents across the site's stated range, near-cancellation) the exact error of the site's
// double evaluation, computed in rationals, never exceeds the constant times the site's computed
// magnitude sum. Each evaluation below is the site's expression, operation for operation, and its
// exact inputs are what the site's derivation allows: doubles taken exactly, truncations (mpq_get_d,
// within one ulp toward zero) or copies within a relative 6u (resp. u) of the exact value. The
// bounds are relative, so they hold only where every product is normal; each site filters only in
// such a range (the 2-D clip 2^±300, the 3-D clip 2^±200, the image hull 2^±138, chromaticity_hull
// channels 2^±100, Monte Carlo coefficients 2^±900), and the exact path decides outside it
// (tests/geometry/test_chromaticity_hull.cpp, extreme_scales_give_the_same_hull: before that
// guard, colours scaled by 2^±1000 gave chromaticity_hull a wrong hull).
#include <gmcc/numerics/filter_bounds.h>

#include <boost/test/unit_test.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

namespace {

namespace fb = gmcc::numerics::filter_bound;
using gmcc::numerics::gamma_n;
using gmcc::numerics::unit_roundoff;
using Q = mpq_class;

const Q u_exact(1, mpz_class(1) << 53);
constexpr double u = unit_roundoff;
constexpr int trials = 20000;

// The largest error seen, as a fraction of the site's bound, and the inputs that broke it.
struct Record {
  double worst = 0;
  int failures = 0;
  void check(double computed, const Q& exact, double bound) {
    const Q error = abs(Q(computed) - exact);
    if (error > Q(bound)) ++failures;
    if (bound > 0) worst = std::max(worst, Q(error / Q(bound)).get_d());
  }
};

void report(const std::string& site, const Record& r) {
  BOOST_TEST_MESSAGE(site << ": worst error " << r.worst << " of the bound");
  BOOST_TEST(r.failures == 0, site << ": " << r.failures << " errors beyond the bound");
}

struct Draw {
  std::mt19937_64 rng;
  explicit Draw(unsigned seed) : rng(seed) {}
  // A double with a random 53-bit significand and an exponent in [lo, hi].
  double number(int lo, int hi, bool positive = false) {
    const double m = 1 + static_cast<double>(rng() >> 12) * 0x1p-52;
    const double x = std::ldexp(m, lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo + 1)));
    return positive || rng() % 2 ? x : -x;
  }
  // A relative perturbation t·rel: its bounds ±rel (the worst case) or a random value between.
  Q perturbation(double rel) {
    const unsigned k = rng() % 4;
    const Q t = k == 0 ? Q(1) : k == 1 ? Q(-1) : Q(static_cast<long>(rng() % 2049) - 1024, 1024);
    return t * Q(rel);
  }
  // An exact value x with x̃ within rel·|x̃| of it.
  Q copy_of(double x, double rel) { return Q(x) * (1 + perturbation(rel)); }
  // An exact value whose truncation toward zero is x (mpq_get_d's): within one ulp beyond |x|.
  Q truncated_to(double x) {
    if (x == 0) return 0;
    const double a = std::fabs(x), ulp = std::nextafter(a, INFINITY) - a;
    const Q t = rng() % 4 == 0 ? Q(0) : Q(static_cast<long>(rng() % 1048575), 1048576);
    const Q q = Q(a) + t * Q(ulp);
    return x < 0 ? Q(-q) : q;
  }
  // A double a few ulps from x.
  double near(double x) {
    for (int k = static_cast<int>(rng() % 5); k > 0; --k) x = std::nextafter(x, rng() % 2 ? INFINITY : -INFINITY);
    return x;
  }
  bool one_in(unsigned n) { return rng() % n == 0; }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(filter_bounds)

// Each constant at least γ_n for the n its derivation counts (filter_bounds.h, and the comment
// at each site): room above the first-order figure.
BOOST_AUTO_TEST_CASE(constants_are_at_least_the_cited_gamma) {
  const std::array<std::pair<double, int>, 13> cited = {{
      {fb::chromaticity_order, 3},          // two products and a difference: 3u
      {fb::chromaticity_orientation, 8},    // the cofactor expansion: 8u
      {fb::image_hull_order, 4},            // truncations 2u each, the difference: 4.01u
      {fb::image_hull_orientation, 9},      // products 6.1u, two roundings more: 8.1u
      {fb::clip_weight, 15},                // 12.01u + 2.01u
      {fb::clip_point_side, 12},            // 9.01u + 2.01u
      {fb::clip_vertex_side, 25},           // 18.01u + γ_6: 24.1u
      {fb::polytope_vertex, 24},            // 18u + 5u + O(u²)
      {fb::polytope_side, 11},              // γ_4 + 6.1u
      {fb::polytope_side_evaluation, 8},    // the bound's own chain: 4 + 1 + 1 roundings, its factor
      {fb::polytope_quick_evaluation, 20},  // fewer than twenty roundings
      {fb::monte_carlo_side, 6},            // coefficients u, products and sums about 5u
      {fb::monte_carlo_side, 5},            // x² + y² + z²: three products, two sums
  }};
  for (const auto& [k, n] : cited) BOOST_TEST(k >= gamma_n(n), k / u << "u against γ_" << n);
  BOOST_TEST(Q(fb::polytope_side) == 16 * u_exact);  // the figure docs/derivations.md §4.6 states
}

// chromaticity_hull: compare, sign(a·d − b·c), and orientation3, of exact doubles (colours:
// channels >= 0), over a range wider than the site's (channels 2^±100) where every product is
// normal.
BOOST_AUTO_TEST_CASE(chromaticity_hull_sites) {
  Draw d(44);
  Record order, orientation;
  for (int i = 0; i < trials; ++i) {
    const int e = static_cast<int>(d.rng() % 600) - 300;
    const double p0 = d.number(e - 20, e + 20, true), p2 = d.number(e - 20, e + 20, true),
                 q2 = d.number(e - 20, e + 20, true);
    const double q0 = d.one_in(2) ? d.near(p0 * q2 / p2) : d.number(e - 20, e + 20, true);
    const double a = p0 * q2, b = q0 * p2;
    order.check(a - b, Q(p0) * Q(q2) - Q(q0) * Q(p2), fb::chromaticity_order * (std::fabs(a) + std::fabs(b)));

    std::array<double, 3> p, q, s;
    for (int k = 0; k < 3; ++k) p[k] = d.number(e - 10, e + 10, true), q[k] = d.number(e - 10, e + 10, true);
    const double alpha = d.number(-20, 20, true), beta = d.number(-20, 20, true);
    for (int k = 0; k < 3; ++k)  // s near the plane of p and q: near-zero orientation
      s[k] = d.one_in(3) ? d.number(e - 10, e + 10, true) : d.near(alpha * p[k] + beta * q[k]);
    const double m0 = q[1] * s[2] - s[1] * q[2], m1 = q[0] * s[2] - s[0] * q[2], m2 = q[0] * s[1] - s[0] * q[1];
    const double det = p[0] * m0 - p[1] * m1 + p[2] * m2;
    const double mag = std::fabs(p[0]) * (std::fabs(q[1] * s[2]) + std::fabs(s[1] * q[2])) +
                       std::fabs(p[1]) * (std::fabs(q[0] * s[2]) + std::fabs(s[0] * q[2])) +
                       std::fabs(p[2]) * (std::fabs(q[0] * s[1]) + std::fabs(s[0] * q[1]));
    const Q P[3] = {p[0], p[1], p[2]}, R[3] = {q[0], q[1], q[2]}, S[3] = {s[0], s[1], s[2]};
    const Q exact = P[0] * (R[1] * S[2] - S[1] * R[2]) - P[1] * (R[0] * S[2] - S[0] * R[2]) +
                    P[2] * (R[0] * S[1] - S[0] * R[1]);
    orientation.check(det, exact, fb::chromaticity_orientation * mag);
  }
  report("chromaticity_order", order);
  report("chromaticity_orientation", orientation);
}

// image_hull: its order and orientation of exact points from their truncations, each coordinate
// within the double range policy (2^±138).
BOOST_AUTO_TEST_CASE(image_hull_sites) {
  Draw d(45);
  Record order, orientation;
  for (int i = 0; i < trials; ++i) {
    const int e = static_cast<int>(d.rng() % 250) - 125;
    const double fa = d.number(e - 8, e + 8), fb2 = d.one_in(2) ? d.near(fa) : d.number(e - 8, e + 8);
    order.check(fa - fb2, d.truncated_to(fa) - d.truncated_to(fb2), fb::image_hull_order * (std::fabs(fa) + std::fabs(fb2)));

    std::array<double, 2> a{d.number(e - 4, e + 4), d.number(e - 4, e + 4)}, b{d.number(e - 4, e + 4), d.number(e - 4, e + 4)}, c;
    const double t = d.number(-6, 2);
    for (int k = 0; k < 2; ++k) c[k] = d.one_in(4) ? d.number(e - 4, e + 4) : d.near(a[k] + t * (b[k] - a[k]));
    const Q A[2] = {d.truncated_to(a[0]), d.truncated_to(a[1])}, B[2] = {d.truncated_to(b[0]), d.truncated_to(b[1])},
            C[2] = {d.truncated_to(c[0]), d.truncated_to(c[1])};
    const double l = (b[0] - a[0]) * (c[1] - a[1]), r = (b[1] - a[1]) * (c[0] - a[0]);
    const double mag = (std::fabs(b[0]) + std::fabs(a[0])) * (std::fabs(c[1]) + std::fabs(a[1])) +
                       (std::fabs(b[1]) + std::fabs(a[1])) * (std::fabs(c[0]) + std::fabs(a[0]));
    orientation.check(l - r, (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]),
                      fb::image_hull_orientation * mag);
  }
  report("image_hull_order", order);
  report("image_hull_orientation", orientation);
}

namespace {

// A line a·x + b·y <= c of the 2-D clip: its double copy, each non-zero coefficient in the
// filter's range [2^-300, 2^300] (integer_line.h), and an exact line whose coefficients the copy
// is within 6u of (the positive multiple taken as 1: it changes no sign and scales both sides).
struct Line2 {
  double a, b, c;
  Q A, B, C;
};
Line2 line2(Draw& d, double a, double b, double c) {
  return {a, b, c, d.copy_of(a, 6 * u), d.copy_of(b, 6 * u), d.copy_of(c, 6 * u)};
}
Line2 random_line2(Draw& d, int e) {
  return line2(d, d.number(e - 30, e + 30), d.number(e - 30, e + 30), d.number(e - 30, e + 30));
}

}  // namespace

// polygon_clipper.h: weight_sign (and enclose_double's determinants), side_of_point (and
// box_side's corners, exact doubles) and side_raw.
BOOST_AUTO_TEST_CASE(polygon_clipper_sites) {
  Draw d(46);
  Record weight, point_side, vertex_side;
  for (int i = 0; i < trials; ++i) {
    const int e = static_cast<int>(d.rng() % 160) - 80;
    const Line2 p = random_line2(d, e);
    const double t = d.number(-30, 30);  // q near p's direction: near-parallel lines
    const Line2 q = d.one_in(2) ? line2(d, d.near(p.a * t), d.near(p.b * t), d.number(e - 30, e + 30)) : random_line2(d, e);
    const double l = p.a * q.b, r = q.a * p.b;
    weight.check(l - r, p.A * q.B - q.A * p.B, fb::clip_weight * (std::fabs(l) + std::fabs(r)));

    const double m0 = d.number(-60, 60), m1 = d.number(-60, 60);
    const Line2 h = line2(d, p.a, p.b, d.one_in(2) ? d.near(p.a * m0 + p.b * m1) : p.c);
    const Q M0 = d.one_in(3) ? Q(m0) : d.truncated_to(m0), M1 = d.one_in(3) ? Q(m1) : d.truncated_to(m1);
    const double x = h.a * m0, y = h.b * m1;
    point_side.check(x + y - h.c, h.A * M0 + h.B * M1 - h.C,
                     fb::clip_point_side * (std::fabs(x) + std::fabs(y) + std::fabs(h.c)));

    // A third line through (about) the meet of p and q.
    const double w = p.a * q.b - q.a * p.b, vx = (p.c * q.b - q.c * p.b) / w, vy = (p.a * q.c - q.a * p.c) / w;
    const double ga = d.number(e - 30, e + 30), gb = d.number(e - 30, e + 30);
    const double gc = d.one_in(3) || !std::isfinite(vx + vy) ? d.number(e - 30, e + 30) : d.near(ga * vx + gb * vy);
    if (gc == 0 || std::fabs(gc) < 0x1p-300 || std::fabs(gc) > 0x1p300) continue;
    const Line2 g = line2(d, ga, gb, gc);
    const double x1 = p.c * q.b, x2 = q.c * p.b, y1 = p.a * q.c, y2 = q.a * p.c, w1 = p.a * q.b, w2 = q.a * p.b;
    const double s = g.a * (x1 - x2) + g.b * (y1 - y2) - g.c * (w1 - w2);
    const double mag = std::fabs(g.a) * (std::fabs(x1) + std::fabs(x2)) + std::fabs(g.b) * (std::fabs(y1) + std::fabs(y2)) +
                       std::fabs(g.c) * (std::fabs(w1) + std::fabs(w2));
    vertex_side.check(s, g.A * (p.C * q.B - q.C * p.B) + g.B * (p.A * q.C - q.A * p.C) - g.C * (p.A * q.B - q.A * p.B),
                      fb::clip_vertex_side * mag);
  }
  report("clip_weight", weight);
  report("clip_point_side", point_side);
  report("clip_vertex_side", vertex_side);
}

namespace {

// A plane a·x <= b of the 3-D clip: its filter copy c (coefficients in [2^-200, 2^200],
// polytope_clip.cpp) and exact coefficients the copy is within 6u of.
struct Plane3 {
  std::array<double, 4> c;
  std::array<Q, 4> exact;
};
Plane3 plane3(Draw& d, const std::array<double, 4>& c) {
  Plane3 p{c, {}};
  for (int k = 0; k < 4; ++k) p.exact[k] = d.copy_of(c[k], 6 * u);
  return p;
}
Plane3 random_plane3(Draw& d, int e) {
  return plane3(d, {d.number(e - 40, e + 40), d.number(e - 40, e + 40), d.number(e - 40, e + 40), d.number(e - 40, e + 40)});
}

// The vertex of planes p, q, r as add_vertex makes it: h = (X, Y, Z, W) and err.
struct Vertex3 {
  std::array<double, 4> h, err;
  std::array<Q, 4> exact;
};
Vertex3 vertex3(const Plane3& p, const Plane3& q, const Plane3& r) {
  Vertex3 v;
  double c[3][3], ca[3][3];
  Q C[3][3];
  const Plane3* s[3][2] = {{&q, &r}, {&r, &p}, {&p, &q}};
  for (int i = 0; i < 3; ++i) {
    const double* x = s[i][0]->c.data();
    const double* y = s[i][1]->c.data();
    const auto& X = s[i][0]->exact;
    const auto& Y = s[i][1]->exact;
    c[i][0] = x[1] * y[2] - x[2] * y[1], ca[i][0] = std::fabs(x[1] * y[2]) + std::fabs(x[2] * y[1]);
    c[i][1] = x[2] * y[0] - x[0] * y[2], ca[i][1] = std::fabs(x[2] * y[0]) + std::fabs(x[0] * y[2]);
    c[i][2] = x[0] * y[1] - x[1] * y[0], ca[i][2] = std::fabs(x[0] * y[1]) + std::fabs(x[1] * y[0]);
    C[i][0] = X[1] * Y[2] - X[2] * Y[1], C[i][1] = X[2] * Y[0] - X[0] * Y[2], C[i][2] = X[0] * Y[1] - X[1] * Y[0];
  }
  const double b[3] = {p.c[3], q.c[3], r.c[3]};
  for (int k = 0; k < 3; ++k) {
    v.h[k] = b[0] * c[0][k] + b[1] * c[1][k] + b[2] * c[2][k];
    v.err[k] = fb::polytope_vertex * (std::fabs(b[0]) * ca[0][k] + std::fabs(b[1]) * ca[1][k] + std::fabs(b[2]) * ca[2][k]);
    v.exact[k] = p.exact[3] * C[0][k] + q.exact[3] * C[1][k] + r.exact[3] * C[2][k];
  }
  v.h[3] = p.c[0] * c[0][0] + p.c[1] * c[0][1] + p.c[2] * c[0][2];
  v.err[3] = fb::polytope_vertex * (std::fabs(p.c[0]) * ca[0][0] + std::fabs(p.c[1]) * ca[0][1] + std::fabs(p.c[2]) * ca[0][2]);
  v.exact[3] = p.exact[0] * C[0][0] + p.exact[1] * C[0][1] + p.exact[2] * C[0][2];
  return v;
}

}  // namespace

// polytope_clip.cpp: the vertex's X, Y, Z, W within err (add_vertex), the side of a plane within
// the full bound (side) and within the vertex's own bound, α and β as VertexDoubles::settle makes
// them (side's first test, LiveVertexFilter::none_outside).
BOOST_AUTO_TEST_CASE(polytope_clip_sites) {
  Draw d(47);
  Record vertex, side, quick;
  for (int i = 0; i < trials; ++i) {
    const int e = static_cast<int>(d.rng() % 200) - 100;
    const Plane3 p = random_plane3(d, e), q = random_plane3(d, e);
    const double t = d.number(-10, 10, true), t2 = d.number(-10, 10, true);
    Plane3 r = random_plane3(d, e);
    if (d.one_in(3))  // r near a combination of p and q: W near 0
      r = plane3(d, {d.near(t * p.c[0] + t2 * q.c[0]), d.near(t * p.c[1] + t2 * q.c[1]), d.near(t * p.c[2] + t2 * q.c[2]), r.c[3]});
    const Vertex3 v = vertex3(p, q, r);
    for (int k = 0; k < 4; ++k) vertex.check(v.h[k], v.exact[k], v.err[k]);

    Plane3 a = random_plane3(d, e);
    if (d.one_in(2) && v.h[3] != 0) {  // a plane through (about) the vertex
      const double b = (a.c[0] * v.h[0] + a.c[1] * v.h[1] + a.c[2] * v.h[2]) / v.h[3];
      if (std::fabs(b) >= 0x1p-200 && std::fabs(b) <= 0x1p200) a = plane3(d, {a.c[0], a.c[1], a.c[2], d.near(b)});
    }
    const double* c = a.c.data();
    const double s = c[0] * v.h[0] + c[1] * v.h[1] + c[2] * v.h[2] - c[3] * v.h[3];
    const Q exact = a.exact[0] * v.exact[0] + a.exact[1] * v.exact[1] + a.exact[2] * v.exact[2] - a.exact[3] * v.exact[3];
    const double T = std::fabs(c[0] * v.h[0]) + std::fabs(c[1] * v.h[1]) + std::fabs(c[2] * v.h[2]) + std::fabs(c[3] * v.h[3]);
    const double E = std::fabs(c[0]) * v.err[0] + std::fabs(c[1]) * v.err[1] + std::fabs(c[2]) * v.err[2] + std::fabs(c[3]) * v.err[3];
    side.check(s, exact, (E + fb::polytope_side * (T + E)) * (1 + fb::polytope_side_evaluation));

    const double sum = std::fabs(v.h[0]) + std::fabs(v.h[1]) + std::fabs(v.h[2]), e3 = v.err[0] + v.err[1] + v.err[2];
    const double alpha = e3 + fb::polytope_side * (sum + e3);
    const double beta = v.err[3] + fb::polytope_side * (std::fabs(v.h[3]) + v.err[3]);
    const double bound = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])}) * (1 + fb::polytope_quick_evaluation) * alpha +
                         std::fabs(c[3]) * (1 + fb::polytope_quick_evaluation) * beta;
    quick.check(s, exact, bound);
  }
  report("polytope_vertex", vertex);
  report("polytope_side", side);
  report("polytope_quick", quick);
}

// mean_3d_monte_carlo.cpp: side_sign, nearest-double coefficients (within u) at sample doubles
// in [0, 1), and in_unit_ball of exact doubles.
BOOST_AUTO_TEST_CASE(monte_carlo_sites) {
  Draw d(48);
  Record side, ball;
  auto sample = [&d] { return static_cast<double>(d.rng() >> 11) * 0x1p-53; };
  for (int i = 0; i < trials; ++i) {
    const int e = static_cast<int>(d.rng() % 400) - 200;
    const double x = sample(), y = sample(), z = d.one_in(50) ? 0x1p-53 : sample();
    const double ad = d.number(e - 20, e + 20), bd = d.number(e - 20, e + 20);
    const double cd = d.one_in(2) && z > 0 ? d.near(-(ad * x + bd * y) / z) : d.number(e - 20, e + 20);
    if (cd == 0) continue;
    const Q A = d.copy_of(ad, u), B = d.copy_of(bd, u), C = d.copy_of(cd, u);
    side.check(ad * x + bd * y + cd * z, A * Q(x) + B * Q(y) + C * Q(z),
               fb::monte_carlo_side * (std::fabs(ad) * x + std::fabs(bd) * y + std::fabs(cd) * z));
    const double r2 = x * x + y * y + z * z;
    ball.check(r2, Q(x) * Q(x) + Q(y) * Q(y) + Q(z) * Q(z), fb::monte_carlo_side * r2);
  }
  report("monte_carlo_side", side);
  report("monte_carlo_ball", ball);
}

BOOST_AUTO_TEST_SUITE_END()
