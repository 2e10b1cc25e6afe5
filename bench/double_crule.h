#pragma once
// Forsyth's CRULE scene in plain doubles: the same-run baseline of bench_crule's certified CRULE
// scene (issue 28 item 3), as bench_scene's scene_double is for the 2-D certified scene.
//   F3 = { d ∈ box : d ⊙ p ∈ G for every image colour p },  G = conv(canonical colours ∪ {0}),
// by incremental clipping of the box 0 <= d_k <= X_k/P_k by the rows (a ⊙ p)·d <= b (every facet
// a·x <= b of G, every image colour p), then max-volume (argmax d1·d2·d3: vertices, facets'
// stationary points, edges' roots, as max_volume.h) and the centroid (tetrahedra coned from a
// vertex, as centroid_3.h), each with its worst case (the largest angle to a non-zero vertex, as
// worst_case_map_deg_3d).
//
// A BASELINE, NOT THE LIBRARY: sides are decided in doubles with a relative tolerance (a vertex
// within kTolerance·(Σ|c_k|·box_k + |b|) of a plane counts as on it), which the library's house
// rules forbid in geometry/ and selection/ and which is allowed here only because this code
// answers "what would a competent plain-double implementation cost". It certifies nothing; its
// agreement with the exact route is checked in bench_crule's set-up (check_double_crule).
// Only the 3-dimensional case is handled: a cut leaving F3 flat reports `flat` (the library's
// LP route), the empty set `empty`.

#include <gmcc/geometry/colour.h>

#include "internal/crule_exact.h"  // geometry/src: G's exact half-spaces (the set-up only)

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace gmcc::bench {

using D3 = std::array<double, 3>;
// The half-space c·x <= b.
struct DPlane {
  D3 c;
  double b;
};

// G prepared once (as CanonicalConstraints3 is): its facets as doubles, its largest channels X.
struct DoubleGamut3 {
  std::vector<DPlane> facets;
  D3 max{0, 0, 0};
};

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

// A convex polytope in doubles: vertices, faces as index cycles counter-clockwise seen from
// outside (face f is index[start[f] .. start[f + 1])), each face's plane (outward normal).
struct DoublePolytope {
  enum class Kind { polytope, empty, flat } kind = Kind::empty;
  std::vector<D3> vertices;
  std::vector<int> start, index;
  std::vector<DPlane> plane;
  std::size_t faces() const { return plane.size(); }
};

// The clip's workspace, reused from scene to scene so that no row allocates.
class DoubleClip3 {
 public:
  // Relative tolerance of a side decision (see the file comment).
  static constexpr double kTolerance = 1e-12;

  // F3 of `image` (channels >= 0, each channel positive in some colour) against `g`.
  const DoublePolytope& feasible_set(const DoubleGamut3& g, const std::vector<D3>& image) {
    D3 box;
    for (int k = 0; k < 3; ++k) {
      double P = 0;
      for (const D3& p : image) P = std::max(P, p[static_cast<std::size_t>(k)]);
      box[static_cast<std::size_t>(k)] = g.max[static_cast<std::size_t>(k)] / P;
    }
    if (!make_rows(g, image, box)) return finish(DoublePolytope::Kind::empty);
    start_box(box);
    for (const Row& r : rows_) {
      const DoublePolytope::Kind k = cut(r);
      if (k != DoublePolytope::Kind::polytope) return finish(k);
    }
    return finish(DoublePolytope::Kind::polytope);
  }
  // How many cuts the last feasible_set made, and how many rows it tested.
  std::size_t cuts() const { return cuts_; }
  std::size_t rows() const { return rows_.size(); }

 private:
  struct Row {
    DPlane p;
    double eps, depth;
  };
  struct Vertex {
    D3 x;
    double s;       // side value of the current row, c·x − b
    int cap_next;   // the next vertex on the cap face being built, or -1
    unsigned stamp;  // the cut that last saw it in a face
  };
  struct CutEdge {
    int kept, out, made;
  };

  // The rows not implied by another of the same facet (p' dominates p for facet c when
  // sign(c_k)·p_k <= sign(c_k)·p'_k for every k: then (c ⊙ p)·d <= (c ⊙ p')·d on d >= 0, as the
  // library's mark_implied), deepest first (their planes' signed distance beyond the box's
  // centre, as its deepest_first). False when a row 0 <= b fails (no map at all).
  bool make_rows(const DoubleGamut3& g, const std::vector<D3>& image, const D3& box) {
    rows_.clear();
    const std::size_t n = image.size();
    for (std::array<std::vector<char>, 27>::size_type i = 0; i < 27; ++i) dominated_[i].clear();
    const D3 centre{box[0] / 2, box[1] / 2, box[2] / 2};
    for (const DPlane& f : g.facets) {
      const int s[3] = {(f.c[0] > 0) - (f.c[0] < 0), (f.c[1] > 0) - (f.c[1] < 0), (f.c[2] > 0) - (f.c[2] < 0)};
      std::vector<char>& dom = dominated_[static_cast<std::size_t>((s[0] + 1) + 3 * (s[1] + 1) + 9 * (s[2] + 1))];
      if (dom.empty()) mark_dominated(image, s, dom);
      for (std::size_t i = 0; i < n; ++i) {
        if (dom[i]) continue;
        Row r;
        double mag = std::abs(f.b), norm = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          r.p.c[k] = f.c[k] * image[i][k];
          mag += std::abs(r.p.c[k]) * box[k];
          norm += r.p.c[k] * r.p.c[k];
        }
        r.p.b = f.b;
        if (norm == 0) {
          if (f.b < 0) return false;
          continue;
        }
        r.eps = kTolerance * mag;
        r.depth = (r.p.c[0] * centre[0] + r.p.c[1] * centre[1] + r.p.c[2] * centre[2] - f.b) / std::sqrt(norm);
        rows_.push_back(r);
      }
    }
    std::sort(rows_.begin(), rows_.end(), [](const Row& a, const Row& b) { return a.depth > b.depth; });
    return true;
  }
  // dom[i] = 1 when another colour dominates colour i for sign pattern s (ties: the first stays).
  static void mark_dominated(const std::vector<D3>& image, const int s[3], std::vector<char>& dom) {
    const std::size_t n = image.size();
    dom.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n && !dom[i]; ++j) {
        if (j == i || dom[j]) continue;
        bool ge = true, gt = false;
        for (std::size_t k = 0; k < 3 && ge; ++k) {
          const double a = s[k] * image[j][k], b = s[k] * image[i][k];
          ge = a >= b;
          gt = gt || a > b;
        }
        dom[i] = ge && (gt || j < i);
      }
  }

  // The box 0 <= x_k <= box_k: corner (bx, by, bz) is vertex bx + 2by + 4bz.
  void start_box(const D3& box) {
    verts_.clear();
    for (int c = 0; c < 8; ++c)
      verts_.push_back({{c & 1 ? box[0] : 0, c & 2 ? box[1] : 0, c & 4 ? box[2] : 0}, 0, -1, 0});
    static constexpr int cycles[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    start_.assign(1, 0);
    index_.clear();
    plane_.clear();
    for (int f = 0; f < 6; ++f) {
      index_.insert(index_.end(), cycles[f], cycles[f] + 4);
      start_.push_back(static_cast<int>(index_.size()));
      D3 c{0, 0, 0};
      c[static_cast<std::size_t>(f / 2)] = f % 2 ? 1 : -1;
      plane_.push_back({c, f % 2 ? box[static_cast<std::size_t>(f / 2)] : 0});
    }
    live_ = {0, 1, 2, 3, 4, 5, 6, 7};
    lo_ = {0, 0, 0};
    hi_ = box;
    cuts_ = 0;
  }

  // Clips by row r: polytope (changed or not), empty or flat.
  DoublePolytope::Kind cut(const Row& r) {
    const D3& c = r.p.c;
    // The support over the bounding box: no vertex can be outside.
    double m = -r.p.b;
    for (std::size_t k = 0; k < 3; ++k) m += c[k] > 0 ? c[k] * hi_[k] : c[k] * lo_[k];
    if (m <= r.eps) return DoublePolytope::Kind::polytope;
    double smax = -HUGE_VAL;
    bool inside = false;
    for (int v : live_) {
      Vertex& x = verts_[static_cast<std::size_t>(v)];
      x.s = c[0] * x.x[0] + c[1] * x.x[1] + c[2] * x.x[2] - r.p.b;
      smax = std::max(smax, x.s);
      inside = inside || x.s < -r.eps;
    }
    if (smax <= r.eps) return DoublePolytope::Kind::polytope;
    if (!inside) {
      for (int v : live_)
        if (verts_[static_cast<std::size_t>(v)].s <= r.eps) return DoublePolytope::Kind::flat;
      return DoublePolytope::Kind::empty;
    }
    ++cuts_;
    cut_edges_.clear();
    nstart_.assign(1, 0);
    nindex_.clear();
    nplane_.clear();
    int cap_first = -1, cap_edges = 0;
    for (std::size_t f = 0; f + 1 < start_.size(); ++f)
      if (!cut_face(f, r.eps, cap_first, cap_edges)) return DoublePolytope::Kind::flat;
    if (!close_cap(r.p, cap_first, cap_edges)) return DoublePolytope::Kind::flat;
    std::swap(start_, nstart_);
    std::swap(index_, nindex_);
    std::swap(plane_, nplane_);
    relive();
    return DoublePolytope::Kind::polytope;
  }

  // Face f cut by the current row into the new face buffers; its cap edge entry → exit noted.
  // False when the face's outside vertices are not one run (an inconsistent side decision).
  bool cut_face(std::size_t f, double eps, int& cap_first, int& cap_edges) {
    const int* cyc = index_.data() + start_[f];
    const int L = start_[f + 1] - start_[f];
    auto out = [&](int i) { return verts_[static_cast<std::size_t>(cyc[(i + L) % L])].s > eps; };
    int entry_at = -1, runs = 0;
    for (int i = 0; i < L; ++i)
      if (!out(i) && out(i - 1)) entry_at = i, ++runs;
    if (runs == 0) {
      if (!out(0)) copy_face(f);  // wholly kept (else wholly removed)
      return true;
    }
    if (runs > 1) return false;
    const std::size_t begin = nindex_.size();
    const int first = cyc[entry_at];
    const int entry = on_or_cut(first, cyc[(entry_at + L - 1) % L], eps);
    if (entry != first) nindex_.push_back(entry);
    int i = entry_at;
    for (; !out(i); ++i) nindex_.push_back(cyc[i % L]);
    const int last = cyc[(i - 1) % L];
    const int exit = on_or_cut(last, cyc[i % L], eps);
    if (exit != last) nindex_.push_back(exit);
    if (nindex_.size() - begin >= 3) {
      nstart_.push_back(static_cast<int>(nindex_.size()));
      nplane_.push_back(plane_[f]);
    } else {
      nindex_.resize(begin);
    }
    if (entry != exit) {
      verts_[static_cast<std::size_t>(entry)].cap_next = exit;
      if (cap_first < 0) cap_first = entry;
      ++cap_edges;
    }
    return true;
  }
  void copy_face(std::size_t f) {
    nindex_.insert(nindex_.end(), index_.begin() + start_[f], index_.begin() + start_[f + 1]);
    nstart_.push_back(static_cast<int>(nindex_.size()));
    nplane_.push_back(plane_[f]);
  }
  // The kept vertex itself when it is on the plane, else the edge's crossing (made once per edge).
  int on_or_cut(int kept, int out, double eps) {
    if (verts_[static_cast<std::size_t>(kept)].s >= -eps) return kept;
    for (const CutEdge& e : cut_edges_)
      if (e.kept == kept && e.out == out) return e.made;
    const Vertex &a = verts_[static_cast<std::size_t>(kept)], &b = verts_[static_cast<std::size_t>(out)];
    const double t = a.s / (a.s - b.s);
    const int made = static_cast<int>(verts_.size());
    verts_.push_back({{a.x[0] + t * (b.x[0] - a.x[0]), a.x[1] + t * (b.x[1] - a.x[1]), a.x[2] + t * (b.x[2] - a.x[2])},
                      0, -1, 0});
    cut_edges_.push_back({kept, out, made});
    return made;
  }
  // The cap face: its edges entry → exit chained into one cycle, on the row's plane.
  bool close_cap(const DPlane& p, int first, int edges) {
    if (edges < 3) return false;
    int v = first, n = 0;
    do {
      nindex_.push_back(v);
      const int next = verts_[static_cast<std::size_t>(v)].cap_next;
      verts_[static_cast<std::size_t>(v)].cap_next = -1;
      v = next;
    } while (v >= 0 && v != first && ++n < edges);
    if (v != first || n + 1 != edges) return false;  // one cycle through every cap edge
    nstart_.push_back(static_cast<int>(nindex_.size()));
    nplane_.push_back(p);
    return true;
  }
  // The live vertices (those on a face) and their bounding box, after a cut.
  void relive() {
    live_.clear();
    lo_ = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    hi_ = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int v : index_) {
      Vertex& x = verts_[static_cast<std::size_t>(v)];
      if (x.stamp == cuts_) continue;
      x.stamp = static_cast<unsigned>(cuts_);
      live_.push_back(v);
      for (std::size_t k = 0; k < 3; ++k) lo_[k] = std::min(lo_[k], x.x[k]), hi_[k] = std::max(hi_[k], x.x[k]);
    }
  }

  // The result, its live vertices renumbered.
  const DoublePolytope& finish(DoublePolytope::Kind kind) {
    out_.kind = kind;
    out_.vertices.clear();
    out_.start.clear();
    out_.index.clear();
    out_.plane.clear();
    if (kind != DoublePolytope::Kind::polytope) return out_;
    for (int v : live_) {
      verts_[static_cast<std::size_t>(v)].cap_next = static_cast<int>(out_.vertices.size());  // new number
      out_.vertices.push_back(verts_[static_cast<std::size_t>(v)].x);
    }
    for (int v : index_) out_.index.push_back(verts_[static_cast<std::size_t>(v)].cap_next);
    out_.start = start_;
    out_.plane = plane_;
    return out_;
  }

  std::vector<Row> rows_;
  std::array<std::vector<char>, 27> dominated_;
  std::vector<Vertex> verts_;
  std::vector<int> live_, start_, index_, nstart_, nindex_;
  std::vector<DPlane> plane_, nplane_;
  std::vector<CutEdge> cut_edges_;
  D3 lo_{}, hi_{};
  std::size_t cuts_ = 0;
  DoublePolytope out_;
};

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
