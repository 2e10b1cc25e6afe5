#pragma once
// A plain double-precision gamut-mapping pipeline, written the way a researcher usually would:
// chromaticities r/b in doubles, Andrew's monotone-chain hull, Sutherland–Hodgman clipping with
// `a·x + b·y <= c` as the inside test, the kind read off the vertex count, max-area and the 2-D
// mean by the textbook formulas. No epsilons and no special cases — it is the baseline that
// docs/degenerate.md compares gmcc with, used by tests, and the hull by the benchmarks' double
// baselines. Not part of any library.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace gmcc::baseline {

struct P {
  double x, y;
};
inline bool operator==(const P& a, const P& b) { return a.x == b.x && a.y == b.y; }

// Coordinates of a point given as P or as std::array<double, 2> (the benchmarks' points).
inline double px(const P& p) { return p.x; }
inline double py(const P& p) { return p.y; }
inline double px(const std::array<double, 2>& p) { return p[0]; }
inline double py(const std::array<double, 2>& p) { return p[1]; }

template <class Pt>
double cross(const Pt& o, const Pt& a, const Pt& b) {
  return (px(a) - px(o)) * (py(b) - py(o)) - (py(a) - py(o)) * (px(b) - px(o));
}

/// Colours (r, g, b) to chromaticities (r/b, g/b): b = 0 gives inf or NaN, as plain code does.
inline std::vector<P> chromaticities(const std::vector<std::array<double, 3>>& rgb) {
  std::vector<P> out;
  for (const auto& c : rgb) out.push_back({c[0] / c[2], c[1] / c[2]});
  return out;
}

/// Andrew's monotone chain, counter-clockwise, collinear points dropped (cross <= 0 pops).
template <class Pt>
std::vector<Pt> hull(std::vector<Pt> p) {
  std::sort(p.begin(), p.end(),
            [](const Pt& a, const Pt& b) { return px(a) < px(b) || (px(a) == px(b) && py(a) < py(b)); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Pt> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// Sutherland–Hodgman: the part of `poly` with a·x + b·y <= c.
inline std::vector<P> clip(const std::vector<P>& poly, double a, double b, double c) {
  std::vector<P> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % n];
    const double sp = a * p.x + b * p.y - c, sq = a * q.x + b * q.y - c;
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

/// F = ⋂_q (G ⊘ q): the box [0, X/Q1] × [0, Y/Q2] clipped by the hull edges of G scaled by
/// every image-hull vertex, consecutive duplicates dropped.
inline std::vector<P> feasible_set(const std::vector<P>& canonical, const std::vector<P>& image) {
  const std::vector<P> g = hull(canonical), im = hull(image);
  double X = 0, Y = 0, Q1 = 0, Q2 = 0;
  for (const P& v : g) X = std::max(X, v.x), Y = std::max(Y, v.y);
  for (const P& q : im) Q1 = std::max(Q1, q.x), Q2 = std::max(Q2, q.y);
  std::vector<P> f{{0, 0}, {X / Q1, 0}, {X / Q1, Y / Q2}, {0, Y / Q2}};
  for (const P& q : im)
    for (std::size_t i = 0; i < g.size() && g.size() >= 2; ++i) {
      const P& p = g[i];
      const P& r = g[(i + 1) % g.size()];
      const double a = r.y - p.y, b = p.x - r.x;  // outward normal of a CCW edge
      f = clip(f, a * q.x, b * q.y, a * p.x + b * p.y);
    }
  std::vector<P> out;
  for (const P& v : f)
    if (out.empty() || !(out.back() == v)) out.push_back(v);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

/// The kind a vertex count suggests: 0 empty, 1 point, 2 segment, otherwise polygon.
inline std::string kind(const std::vector<P>& f) {
  return f.empty() ? "empty" : f.size() == 1 ? "point" : f.size() == 2 ? "segment" : "polygon";
}

/// argmax x·y over the vertices and the edge stationary points (docs/derivations.md §2.3 in
/// doubles).
inline P max_area(const std::vector<P>& f) {
  P best{NAN, NAN};
  double bv = -INFINITY;
  auto consider = [&](const P& p) {
    if (p.x * p.y > bv) bv = p.x * p.y, best = p;
  };
  for (std::size_t i = 0; i < f.size(); ++i) {
    const P& p = f[i];
    const P& q = f[(i + 1) % f.size()];
    consider(p);
    const double da = q.x - p.x, db = q.y - p.y;
    if (da * db < 0) {
      const double t = -(da * p.y + db * p.x) / (2 * da * db);
      if (t > 0 && t < 1) consider({p.x + t * da, p.y + t * db});
    }
  }
  return best;
}

/// Area centroid by the shoelace formula (NaN when the area is 0).
inline P mean_2d(const std::vector<P>& f) {
  double a = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const P& p = f[i];
    const P& q = f[(i + 1) % f.size()];
    const double w = p.x * q.y - q.x * p.y;
    a += w, cx += (p.x + q.x) * w, cy += (p.y + q.y) * w;
  }
  return {cx / (3 * a), cy / (3 * a)};
}

}  // namespace gmcc::baseline
