#pragma once
// The double filters of the illuminant-space worst case (docs/derivations.md §3.2): the
// closeness (e·w)²/|w|² of a map to the estimate's illuminant e, and the tests that an edge of F
// cannot hold the worst case. worst_case_illuminant.cpp uses them to skip exact work;
// scene_record.cpp to enclose the worst case at a vertex without any. Internal to gmcc::selection.

#include <gmcc/geometry/rational_enclosure.h>

#include <algorithm>
#include <array>

namespace gmcc::internal {

// The cos²-closeness (e·w)²/|w|² of the map (x, y), w = c ⊘ (x, y, 1), in the number type T:
// exactly in ℚ (the exact route's comparisons), or enclosed (the filters). Written once, so the
// filters enclose exactly what the exact route compares.
template <class T>
T closeness_of(const std::array<T, 3>& e, const std::array<T, 3>& c, const T& x, const T& y) {
  const T w0 = c[0] / x, w1 = c[1] / y;
  const T ew = e[0] * w0 + e[1] * w1 + e[2] * c[2];
  return T(ew * ew / (w0 * w0 + w1 * w1 + c[2] * c[2]));
}

// True when the edge polynomial (e·v′)|v|² − (e·v)(v·v′) certainly has no zero for t in [0, 1]:
// then the angle has no stationary point on the edge and roots_in_unit_interval finds no root.
// The polynomial is one in a(t), b(t), Δa, Δb (v = (c1·b, c2·a, c3·a·b), v′ its derivative), so
// its enclosure over the box [min a, max a] × [min b, max b], which holds the whole edge, holds
// its values on the edge (a positive scaling, as the exact route applies, changes no sign).
inline bool no_stationary_point(const std::array<Enclosure, 3>& e, const std::array<Enclosure, 3>& c,
                         const Enclosure& px, const Enclosure& py, const Enclosure& qx, const Enclosure& qy) {
  const Enclosure a = Enclosure::between(std::min(px.lo(), qx.lo()), std::max(px.hi(), qx.hi()));
  const Enclosure b = Enclosure::between(std::min(py.lo(), qy.lo()), std::max(py.hi(), qy.hi()));
  const Enclosure da = qx - px, db = qy - py;
  const std::array<Enclosure, 3> v{c[0] * b, c[1] * a, c[2] * a * b};
  const std::array<Enclosure, 3> dv{c[0] * db, c[1] * da, c[2] * (a * db + b * da)};
  Enclosure ev = e[0] * v[0], edv = e[0] * dv[0], vv = v[0] * v[0], vdv = v[0] * dv[0];
  for (int j = 1; j < 3; ++j) {
    ev = ev + e[j] * v[j], edv = edv + e[j] * dv[j];
    vv = vv + v[j] * v[j], vdv = vdv + v[j] * dv[j];
  }
  const Enclosure s = edv * vv - ev * vdv;
  return s.finite() && certainly_nonzero(s);
}

// True when every point of the edge is certainly less close (a larger angle's opposite: a larger
// closeness) than `least_upper`, an upper bound of the least vertex closeness: the closeness over
// the edge's bounding box, enclosed, starts above it. Then no point of the edge can be the worst
// case (which the exact route takes only where the closeness is strictly below every vertex's),
// and its quartic need not be solved. On a round F only the edges near the worst direction are
// left (issue 13's 876/414 fuzz finding: 40 s to 4 s). Where the vertices' closenesses agree
// beyond a double's precision it decides nothing: the sin² filter below takes over.
inline bool edge_cannot_be_worst(const std::array<Enclosure, 3>& e, const std::array<Enclosure, 3>& c,
                          const Enclosure& px, const Enclosure& py, const Enclosure& qx,
                          const Enclosure& qy, double least_upper) {
  const Enclosure a = Enclosure::between(std::min(px.lo(), qx.lo()), std::max(px.hi(), qx.hi()));
  const Enclosure b = Enclosure::between(std::min(py.lo(), qy.lo()), std::max(py.hi(), qy.hi()));
  if (!(a.lo() > 0) || !(b.lo() > 0)) return false;
  const Enclosure k = closeness_of(e, c, a, b);
  return k.finite() && k.lo() > least_upper;
}

// True when no point of the edge p + t(q − p), t ∈ [0, 1], can replace the worst case: the edge
// split into dyadic pieces [k/2^d, (k+1)/2^d] (d ≤ max_depth, halved where needed), each piece
// passing one of the two tests above on the box of its ends' enclosures. The exact route's
// candidates on the edge are its quartic's roots, each refined to a dyadic interval of depth 100
// (or hit exactly), so each candidate lies in the closed piece that holds its root: that piece has
// a stationary point, so it passed the closeness test, and the candidate's exact closeness is
// above least_upper, never below the worst so far. Skipping the edge changes nothing, bit for bit;
// near the least vertex, where the whole edge's box is too coarse, small pieces often decide.
inline bool edge_skippable(const std::array<Enclosure, 3>& e, const std::array<Enclosure, 3>& c,
                    const Enclosure& px, const Enclosure& py, const Enclosure& dx,
                    const Enclosure& dy, double t0, double t1, double least_upper, int depth) {
  const Enclosure a0 = px + Enclosure::exact(t0) * dx, b0 = py + Enclosure::exact(t0) * dy;
  const Enclosure a1 = px + Enclosure::exact(t1) * dx, b1 = py + Enclosure::exact(t1) * dy;
  if (edge_cannot_be_worst(e, c, a0, b0, a1, b1, least_upper) || no_stationary_point(e, c, a0, b0, a1, b1))
    return true;
  if (depth == 0) return false;
  const double mid = (t0 + t1) / 2;  // exact: dyadic
  return edge_skippable(e, c, px, py, dx, dy, t0, mid, least_upper, depth - 1) &&
         edge_skippable(e, c, px, py, dx, dy, mid, t1, least_upper, depth - 1);
}

/// True when the angle between e and the illuminant c ⊘ (x, 1) certainly has no interior maximum
/// on the edge x = p + t·(q − p), t ∈ (0, 1). The edge polynomial s(t) = (e·v′)|v|² − (e·v)(v·v′)
/// of no_stationary_point is |v|³ times the derivative of |e|·cos, so the angle falls where s > 0.
/// Its coefficients in t (degree <= 5) are enclosed from the vertices' enclosures and taken to the
/// Bernstein basis of degree 5 on [0, 1]; with every coefficient's sign certain, the number of
/// roots in (0, 1) is at most the number of sign variations and of the same parity (Descartes'
/// rule for the Bernstein basis). No variation: no stationary point. One, from + to −: exactly one,
/// where the angle stops falling and starts rising, a minimum. Either way no interior maximum.
/// Unlike the box of no_stationary_point it keeps a and b's dependence on t, so it decides long
/// edges without splitting them.
inline bool no_interior_maximum_bernstein(const std::array<Enclosure, 3>& e, const std::array<Enclosure, 3>& c,
                                          const Enclosure& px, const Enclosure& py, const Enclosure& qx,
                                          const Enclosure& qy) {
  using P = std::array<Enclosure, 6>;  // coefficients of t^0 … t^5
  auto mul = [](const P& f, const P& g, int df, int dg) {
    P h{};
    for (int i = 0; i <= df; ++i)
      for (int j = 0; j <= dg; ++j) h[static_cast<std::size_t>(i + j)] = h[static_cast<std::size_t>(i + j)] + f[static_cast<std::size_t>(i)] * g[static_cast<std::size_t>(j)];
    return h;
  };
  auto add = [](const P& f, const P& g, const Enclosure& k) {
    P h;
    for (std::size_t i = 0; i < 6; ++i) h[i] = f[i] + k * g[i];
    return h;
  };
  const Enclosure da = qx - px, db = qy - py, one = Enclosure::exact(1);
  // v = (c1·b, c2·a, c3·a·b) and v′, a = px + t·da, b = py + t·db.
  const P v0{c[0] * py, c[0] * db}, v1{c[1] * px, c[1] * da}, v2{c[2] * px * py, c[2] * (px * db + da * py), c[2] * da * db};
  const P d0{c[0] * db}, d1{c[1] * da}, d2{c[2] * (px * db + da * py), Enclosure::exact(2) * c[2] * da * db};
  const P ev = add(add(mul(v0, {e[0]}, 1, 0), v1, e[1]), v2, e[2]);
  const P edv = add(add(mul(d0, {e[0]}, 0, 0), d1, e[1]), d2, e[2]);
  const P vv = add(add(mul(v0, v0, 1, 1), mul(v1, v1, 1, 1), one), mul(v2, v2, 2, 2), one);
  const P vdv = add(add(mul(v0, d0, 1, 0), mul(v1, d1, 1, 0), one), mul(v2, d2, 2, 1), one);
  const P s = add(mul(edv, vv, 1, 4), mul(ev, vdv, 2, 3), Enclosure::exact(-1));
  // Bernstein coefficients of degree 5: b_j = Σ_{i<=j} C(j, i)/C(5, i) · s_i.
  static constexpr double binom[6][6] = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}, {1, 4, 6, 4, 1}, {1, 5, 10, 10, 5, 1}};
  int first = 0, last = 0, variations = 0;
  for (int j = 0; j <= 5; ++j) {
    Enclosure b{};
    for (int i = 0; i <= j; ++i)
      b = b + Enclosure::exact(binom[j][i]) * s[static_cast<std::size_t>(i)] / Enclosure::exact(binom[5][i]);
    if (!b.finite() || !certainly_nonzero(b)) return false;
    const int sign = certainly_positive(b) ? 1 : -1;
    if (last && sign != last) ++variations;
    if (!first) first = sign;
    last = sign;
  }
  return variations == 0 || (variations == 1 && first > 0);
}

}  // namespace gmcc::internal
