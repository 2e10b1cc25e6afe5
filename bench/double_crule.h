#pragma once
// Forsyth's CRULE scene in plain doubles: the same-run baseline of bench_crule's certified CRULE
// scene (issue 28 item 3), as bench_scene's scene_double is for the 2-D certified scene.
//   F3 = { d ∈ box : d ⊙ p ∈ G for every image colour p },  G = conv(canonical colours ∪ {0}),
// by incremental clipping of the box 0 <= d_k <= X_k/P_k by the rows (a ⊙ p)·d <= b (every facet
// a·x <= b of G, every image colour p; double_clip_3.h), then max-volume (argmax d1·d2·d3:
// vertices, facets' stationary points, edges' roots, as max_volume.h) and the centroid
// (tetrahedra coned from a vertex, as centroid_3.h), each with its worst case (the largest angle
// to a non-zero vertex, as worst_case_map_deg_3d). Plain doubles throughout, with the clip's
// tolerance (double_clip_3.h): a baseline, not the library.

#include <gmcc/geometry/colour.h>

#include "double_clip_3.h"
#include "internal/crule_exact.h"  // geometry/src: G's exact half-spaces (the set-up only)

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace gmcc::bench {

// G = conv(canonical ∪ {0}) from the library's exact half-spaces (hull_half_spaces_3, the same
// CGAL hull the certified route prepares), each rounded to doubles. \pre G is 3-dimensional.
inline DoubleGamut3 double_gamut_3(const std::vector<Colour>& canonical) {
  std::vector<Point3> pts{{0, 0, 0}};
  for (const Colour& x : canonical) pts.push_back({x.r, x.g, x.b});
  pts = internal::sorted_unique(std::move(pts));
  DoubleGamut3 g;
  for (const Point3& p : pts) {
    g.max[0] = std::max(g.max[0], p.x.get_d());
    g.max[1] = std::max(g.max[1], p.y.get_d());
    g.max[2] = std::max(g.max[2], p.z.get_d());
  }
  for (const internal::HalfSpace3& h : internal::hull_half_spaces_3(pts))
    g.facets.push_back({{h.a.x.get_d(), h.a.y.get_d(), h.a.z.get_d()}, h.b.get_d()});
  return g;
}

// ------------------------------------------------------------ the selections, in doubles

// Whether d (on face f's plane) is inside the face: left of every edge seen from outside.
inline bool inside_face(const DoublePolytope& F, std::size_t f, const D3& d) {
  const D3& n = F.plane[f].c;
  for (int i = F.start[f], e = F.start[f + 1]; i < e; ++i) {
    const D3& u = F.vertices[static_cast<std::size_t>(F.index[static_cast<std::size_t>(i)])];
    const D3& w = F.vertices[static_cast<std::size_t>(F.index[static_cast<std::size_t>(i + 1 < e ? i + 1 : F.start[f])])];
    const D3 a{w[0] - u[0], w[1] - u[1], w[2] - u[2]}, b{d[0] - u[0], d[1] - u[1], d[2] - u[2]};
    const double side = (a[1] * b[2] - a[2] * b[1]) * n[0] + (a[2] * b[0] - a[0] * b[2]) * n[1] + (a[0] * b[1] - a[1] * b[0]) * n[2];
    if (side < 0) return false;
  }
  return true;
}
// The stationary points inside edge u → w of Π d_k (none when the edge's box bound loses).
template <class Consider>
void edge_candidates(const D3& u, const D3& w, double best, Consider& consider) {
  if (std::max(u[0], w[0]) * std::max(u[1], w[1]) * std::max(u[2], w[2]) <= best) return;
  const D3 e{w[0] - u[0], w[1] - u[1], w[2] - u[2]};
  const double c3 = e[0] * e[1] * e[2];
  const double c2 = u[0] * e[1] * e[2] + e[0] * u[1] * e[2] + e[0] * e[1] * u[2];
  const double c1 = u[0] * u[1] * e[2] + u[0] * e[1] * u[2] + e[0] * u[1] * u[2];
  const double A = 3 * c3, B = 2 * c2, C = c1;  // f'(t) = A t² + B t + C
  double t[2];
  int n = 0;
  if (A == 0) {
    if (B != 0) t[n++] = -C / B;
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return;
    const double q = -(B + std::copysign(std::sqrt(disc), B)) / 2;
    t[n++] = q / A;
    if (q != 0) t[n++] = C / q;
  }
  for (int i = 0; i < n; ++i)
    if (t[i] > 0 && t[i] < 1) consider(D3{u[0] + t[i] * e[0], u[1] + t[i] * e[1], u[2] + t[i] * e[2]});
}

// argmax d1·d2·d3 over F (max_volume.h's candidates: every vertex; each facet's stationary point
// d_k = b/(3c_k) when it is positive and inside the facet; each edge's roots in (0, 1) of the
// derivative of the cubic Π (u_k + t·e_k)), each candidate set skipped when a bound shows it
// cannot win. A product 0 on all of F: the lexicographically smallest vertex, as the library.
inline D3 double_max_volume(const DoublePolytope& F) {
  double best = -1;
  D3 arg{};
  auto consider = [&](const D3& d) {
    const double v = d[0] * d[1] * d[2];
    if (v > best) best = v, arg = d;
  };
  for (const D3& v : F.vertices) consider(v);
  for (std::size_t f = 0; f < F.faces(); ++f) {
    const DPlane& p = F.plane[f];
    if (p.b <= 0 || p.c[0] <= 0 || p.c[1] <= 0 || p.c[2] <= 0) continue;
    const D3 d{p.b / (3 * p.c[0]), p.b / (3 * p.c[1]), p.b / (3 * p.c[2])};
    if (d[0] * d[1] * d[2] > best && inside_face(F, f, d)) consider(d);
  }
  for (std::size_t f = 0; f < F.faces(); ++f)
    for (int i = F.start[f], e = F.start[f + 1]; i < e; ++i) {
      const int a = F.index[static_cast<std::size_t>(i)], b = F.index[static_cast<std::size_t>(i + 1 < e ? i + 1 : F.start[f])];
      if (a < b) edge_candidates(F.vertices[static_cast<std::size_t>(a)], F.vertices[static_cast<std::size_t>(b)], best, consider);
    }
  if (best <= 0) arg = *std::min_element(F.vertices.begin(), F.vertices.end());
  return arg;
}

// F's volume centroid: tetrahedra coned from its first vertex over the fan-triangulated facets,
// each centroid weighted by its volume (convex_set_3.h centroid()).
inline D3 double_centroid(const DoublePolytope& F) {
  const D3& a = F.vertices[0];
  double volume = 0;
  D3 sum{0, 0, 0};
  for (std::size_t f = 0; f < F.faces(); ++f) {
    const int s = F.start[f], e = F.start[f + 1];
    const D3& b = F.vertices[static_cast<std::size_t>(F.index[static_cast<std::size_t>(s)])];
    for (int i = s + 1; i + 1 < e; ++i) {
      const D3& c = F.vertices[static_cast<std::size_t>(F.index[static_cast<std::size_t>(i)])];
      const D3& d = F.vertices[static_cast<std::size_t>(F.index[static_cast<std::size_t>(i + 1)])];
      const D3 x{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, y{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
          z{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
      const double w = x[0] * (y[1] * z[2] - y[2] * z[1]) + x[1] * (y[2] * z[0] - y[0] * z[2]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
      volume += w;
      for (std::size_t k = 0; k < 3; ++k) sum[k] += w * (a[k] + b[k] + c[k] + d[k]);
    }
  }
  return {sum[0] / (4 * volume), sum[1] / (4 * volume), sum[2] / (4 * volume)};
}

// The angle between u and v in degrees, atan2(|u×v|, u·v) (diagonal_map_angular_error_deg).
inline double double_angle_deg(const D3& u, const D3& v) {
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return std::atan2(std::sqrt(x * x + y * y + z * z), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) * (180 / M_PI);
}
// The largest angle from m to a non-zero vertex of F (worst_case_map_deg_3d: quasi-convexity puts
// it at a vertex), chosen by cos, then measured; absent when m or F is only 0.
inline std::optional<double> double_worst_case_deg(const DoublePolytope& F, const D3& m) {
  if (m[0] == 0 && m[1] == 0 && m[2] == 0) return std::nullopt;
  double least = HUGE_VAL;
  const D3* worst = nullptr;
  for (const D3& v : F.vertices) {
    const double n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (n2 == 0) continue;
    const double c = (v[0] * m[0] + v[1] * m[1] + v[2] * m[2]) / std::sqrt(n2);
    if (c < least) least = c, worst = &v;
  }
  if (!worst) return std::nullopt;
  return double_angle_deg(*worst, m);
}

// One CRULE scene in doubles: F3, max-volume and the centroid, each with its worst case.
struct DoubleCrule3 {
  DoublePolytope::Kind kind = DoublePolytope::Kind::empty;
  D3 max_volume{}, centroid{};
  std::optional<double> max_volume_worst_deg, centroid_worst_deg;
};
inline DoubleCrule3 double_crule_scene(DoubleClip3& clip, const DoubleGamut3& g, const std::vector<D3>& image) {
  const DoublePolytope& F = clip.feasible_set(g, image);
  DoubleCrule3 s;
  s.kind = F.kind;
  if (F.kind != DoublePolytope::Kind::polytope) return s;
  s.max_volume = double_max_volume(F);
  s.max_volume_worst_deg = double_worst_case_deg(F, s.max_volume);
  s.centroid = double_centroid(F);
  s.centroid_worst_deg = double_worst_case_deg(F, s.centroid);
  return s;
}

}  // namespace gmcc::bench
