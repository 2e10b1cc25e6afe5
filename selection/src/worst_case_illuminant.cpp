#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case_illuminant.h>

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gmcc {
namespace {

// A polynomial over ℚ in the edge parameter t: coefficients, constant term first, no trailing
// zeros (the zero polynomial is empty). Degrees here are at most 5, so plain loops suffice.
using Poly = std::vector<Rational>;

void trim(Poly& p) {
  while (!p.empty() && sgn(p.back()) == 0) p.pop_back();
}

Poly add(Poly a, const Poly& b) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  trim(a);
  return a;
}

Poly scaled(Poly a, const Rational& k) {
  for (Rational& x : a) x *= k;
  trim(a);
  return a;
}

Poly sub(const Poly& a, const Poly& b) { return add(a, scaled(b, Rational(-1))); }

Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {};
  Poly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(Rational(p[i] * static_cast<long>(i)));
  trim(d);
  return d;
}

// Quotient and remainder of a by b ≠ 0 (exact long division over ℚ).
std::pair<Poly, Poly> divide(Poly a, const Poly& b) {
  Poly q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0);
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const Rational k = a.back() / b.back();
    q[shift] = k;
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= k * b[i];
    a.pop_back();  // its coefficient is now exactly 0
    trim(a);
  }
  trim(q);
  return {std::move(q), std::move(a)};
}

Poly gcd(Poly a, Poly b) {
  while (!b.empty()) {
    Poly r = divide(a, b).second;
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

// p scaled by a positive rational to coprime integer coefficients: the same signs everywhere,
// and integer arithmetic from then on (the coefficients inherit the size of the map m, which for
// the 2-D mean can have hundreds of digits).
Poly primitive(Poly p) {
  if (p.empty()) return p;
  mpz_class den_lcm = 1, num_gcd = 0;
  for (const Rational& c : p) {
    mpz_lcm(den_lcm.get_mpz_t(), den_lcm.get_mpz_t(), c.get_den_mpz_t());
    mpz_gcd(num_gcd.get_mpz_t(), num_gcd.get_mpz_t(), c.get_num_mpz_t());
  }
  const Rational k(den_lcm, num_gcd);  // > 0
  return scaled(std::move(p), k);
}

// The sign of an integer-coefficient p at t = a/b (b > 0), from the homogeneous form
// Σ c_i a^i b^(d−i): integer arithmetic only, no rational normalisation.
int sign_at(const Poly& p, const Rational& t) {
  if (p.empty()) return 0;
  const mpz_class& a = t.get_num();
  const mpz_class& b = t.get_den();
  // Horner on the homogeneous form: r ← r·a + c_i·b^(d−i), from i = d − 1 down to 0.
  mpz_class r = p.back().get_num(), b_power = 1;
  for (std::size_t i = p.size() - 1; i-- > 0;) {
    b_power *= b;
    r = r * a + p[i].get_num() * b_power;
  }
  return sgn(r);
}

// Sign variations of a Sturm sequence at t, zeros skipped.
int variations(const std::vector<Poly>& chain, const Rational& t) {
  int count = 0, last = 0;
  for (const Poly& p : chain) {
    const int s = sign_at(p, t);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

// The distinct real roots of p ≠ 0 in (0, 1], each as an exact rational: the root itself when a
// bisection point hits it, otherwise the right end of an interval (lo, hi] of width ≤ 2^-100
// holding exactly one root. Sturm's theorem on the square-free part s = p / gcd(p, p′):
// #roots in (lo, hi] = V(lo) − V(hi), also when lo or hi is a root (Basu, Pollack & Roy,
// "Algorithms in Real Algebraic Geometry", Thm 2.50 and its proof).
std::vector<Rational> roots_in_unit_interval(const Poly& p) {
  const Poly s = primitive(divide(p, gcd(p, derivative(p))).first);
  if (s.size() < 2) return {};
  const Poly ds = primitive(derivative(s));
  std::vector<Poly> chain{s, ds};
  for (;;) {  // positive scalings keep a Sturm sequence's signs
    Poly r = primitive(scaled(divide(chain[chain.size() - 2], chain.back()).second, Rational(-1)));
    if (r.empty()) break;
    chain.push_back(std::move(r));
  }
  const Rational width = Rational(1) >> 100;
  struct Interval {
    Rational lo, hi;
    int v_lo, v_hi;
  };
  std::vector<Interval> todo{{Rational(0), Rational(1), variations(chain, Rational(0)),
                              variations(chain, Rational(1))}};
  std::vector<Rational> roots;
  while (!todo.empty()) {
    Interval iv = std::move(todo.back());
    todo.pop_back();
    const int count = iv.v_lo - iv.v_hi;
    if (count == 0) continue;
    if (count == 1) {
      // One simple root in (lo, hi]: bisect on the sign of s alone. Just right of lo, s has
      // the sign of s(lo), or of s′(lo) where lo is itself a (simple) root of s.
      int sign_lo = sign_at(s, iv.lo);
      if (sign_lo == 0) sign_lo = sign_at(ds, iv.lo);
      while (iv.hi - iv.lo > width && sign_at(s, iv.hi) != 0) {
        Rational mid = (iv.lo + iv.hi) / 2;
        const int sign_mid = sign_at(s, mid);
        if (sign_mid == 0) {
          iv.hi = std::move(mid);
          break;
        }
        (sign_mid == sign_lo ? iv.lo : iv.hi) = std::move(mid);
      }
      roots.push_back(iv.hi);
      continue;
    }
    Rational mid = (iv.lo + iv.hi) / 2;
    const int v_mid = variations(chain, mid);
    todo.push_back({iv.lo, mid, iv.v_lo, v_mid});
    todo.push_back({std::move(mid), iv.hi, v_mid, iv.v_hi});
  }
  return roots;
}

}  // namespace

IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& c) {
  if (F.kind == ConvexKind::empty)
    throw std::invalid_argument("worst_case_illuminant: empty feasible set");
  for (const Rational* x : {&m.x, &m.y, &c.r, &c.g, &c.b})
    if (sgn(*x) <= 0)
      throw std::invalid_argument("worst_case_illuminant: map and illuminant must be > 0");
  for (const Point2& v : F.vertices)
    if (sgn(v.x) <= 0 || sgn(v.y) <= 0)
      throw std::invalid_argument("worst_case_illuminant: feasible maps must be > 0");

  // e: the estimate's illuminant c ⊘ (m, 1). A candidate x implies the direction c ⊘ (x, 1); the
  // angle grows as cos²/|e|² = (e·w)²/|w|² falls, compared exactly (e·w > 0: all positive).
  const std::array<Rational, 3> e{Rational(c.r / m.x), Rational(c.g / m.y), c.b};
  auto closeness = [&](const Point2& x) {
    const Rational w0 = c.r / x.x, w1 = c.g / x.y;
    const Rational ew = e[0] * w0 + e[1] * w1 + e[2] * c.b;
    return Rational(ew * ew / (w0 * w0 + w1 * w1 + c.b * c.b));
  };
  IlluminantWorstCase worst;
  worst.location = F.vertices.front();
  Rational worst_closeness = closeness(worst.location);
  auto consider = [&](Point2 x, bool at_vertex) {
    Rational k = closeness(x);
    if (k < worst_closeness) {
      worst_closeness = std::move(k);
      worst.location = std::move(x);
      worst.at_vertex = at_vertex;
    }
  };
  for (const Point2& v : F.vertices) consider(v, true);

  // A segment has one edge, a polygon n, a point none.
  const auto& vs = F.vertices;
  const std::size_t edges =
      F.kind == ConvexKind::polygon ? vs.size() : F.kind == ConvexKind::segment ? 1 : 0;
  for (std::size_t i = 0; i < edges; ++i) {
    const Point2& p = vs[i];
    const Point2& q = vs[(i + 1) % vs.size()];
    const Rational da = q.x - p.x, db = q.y - p.y;
    Poly a{p.x, da}, b{p.y, db};
    trim(a);
    trim(b);
    // v(t) = a·b · (c ⊘ (a, b, 1)) = (c1·b, c2·a, c3·a·b).
    const std::array<Poly, 3> v{scaled(b, c.r), scaled(a, c.g), scaled(mul(a, b), c.b)};
    const std::array<Poly, 3> dv{derivative(v[0]), derivative(v[1]), derivative(v[2])};
    Poly e_v, e_dv, v_v, v_dv;
    for (int j = 0; j < 3; ++j) {
      e_v = add(e_v, scaled(v[j], e[j]));
      e_dv = add(e_dv, scaled(dv[j], e[j]));
      v_v = add(v_v, mul(v[j], v[j]));
      v_dv = add(v_dv, mul(v[j], dv[j]));
    }
    // d/dt (e·v)/|v| = [(e·v′)|v|² − (e·v)(v·v′)] / |v|³. The product is degree 5 term by term;
    // the t⁵ terms cancel (both are 2·e3·c3³·(Δa·Δb)³), which we check rather than assume.
    const Poly stationary = sub(mul(e_dv, v_v), mul(e_v, v_dv));
    if (stationary.size() > 5)
      throw std::logic_error("worst_case_illuminant: edge polynomial is not a quartic");
    if (stationary.empty()) continue;  // constant angle along the edge: its ends suffice
    for (const Rational& t : roots_in_unit_interval(stationary)) {
      if (t == 1) continue;  // the vertex q, already a candidate
      consider({Rational(p.x + t * da), Rational(p.y + t * db)}, false);
    }
  }
  worst.angle_deg = illuminant_angular_error_deg(m, worst.location, c);
  return worst;
}

double worst_case_illuminant_deg(const ConvexSet2& F, const Point2& m, const Colour& c) {
  return worst_case_illuminant(F, m, c).angle_deg;
}

}  // namespace gmcc
