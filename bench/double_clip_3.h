#pragma once
// Incremental clipping of a box by half-spaces, in plain doubles: the feasible-set half of
// bench/double_crule.h (Forsyth's CRULE scene in doubles, the same-run baseline of bench_crule's
// certified scene; issue 28 item 3), the same algorithm as the library's exact clip
// (geometry/src/polytope_clip.cpp: implied rows dropped, deepest rows first, a box test, then a
// pass over the vertices, faces as vertex cycles, each cut closing a new face) with every side
// decided in doubles.
//
// A BASELINE, NOT THE LIBRARY: sides are decided with a relative tolerance (a vertex within
// kTolerance·(Σ|c_k|·box_k + |b|) of a plane counts as on it), which the house rules forbid in
// geometry/ and selection/ and which is allowed here only because this code answers "what would
// a competent plain-double implementation cost". It certifies nothing; bench_crule checks it
// against the exact route in its set-up (check_double_crule). Only the 3-dimensional case is
// handled: a cut leaving the set flat reports `flat` (the library's LP route), none `empty`.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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
    for (int i : order_) {
      const DoublePolytope::Kind k = cut(rows_[static_cast<std::size_t>(i)]);
      if (k != DoublePolytope::Kind::polytope) return finish(k);
    }
    return finish(DoublePolytope::Kind::polytope);
  }
  // How many cuts the last feasible_set made, and how many rows it tested.
  std::size_t cuts() const { return cuts_; }
  std::size_t rows() const { return order_.size(); }
  // Since construction: rows that needed a scan of the vertices (the bounding box did not settle
  // them), and the vertices those scans read.
  std::size_t scans() const { return scans_; }
  std::size_t scanned() const { return scanned_; }

 private:
  struct Row {
    DPlane p;
    double eps, depth;
  };
  struct Vertex {
    D3 x;
    double s;      // side value of the current row, c·x − b
    int cap_next;  // the next vertex on the cap face being built, or -1
  };
  struct CutEdge {
    int kept, out, made;
    int faces[2];  // the two faces through the edge (-1 until the second is seen)
  };

  // The rows not implied by another of the same facet (p' dominates p for facet c when
  // sign(c_k)·p_k <= sign(c_k)·p'_k for every k: then (c ⊙ p)·d <= (c ⊙ p')·d on d >= 0, as the
  // library's mark_implied), deepest first (their planes' signed distance beyond the box's
  // centre, as its deepest_first, by a counting sort into bands); rows the whole box satisfies
  // are dropped at once. False when a row 0 <= b fails (no map at all).
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
        double support = -f.b;
        for (std::size_t k = 0; k < 3; ++k) support += std::max(r.p.c[k], 0.0) * box[k];
        if (support <= r.eps) continue;
        r.depth = (r.p.c[0] * centre[0] + r.p.c[1] * centre[1] + r.p.c[2] * centre[2] - f.b) / std::sqrt(norm);
        rows_.push_back(r);
      }
    }
    deepest_first();
    return true;
  }
  // order_: the rows by decreasing depth, in `levels` equal bands (each in row order).
  void deepest_first() {
    constexpr std::size_t levels = 1024;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Row& r : rows_) lo = std::min(lo, r.depth), hi = std::max(hi, r.depth);
    const double scale = hi > lo ? double(levels - 1) / (hi - lo) : 0;
    band_.resize(rows_.size());
    count_.assign(levels + 1, 0);
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      band_[i] = static_cast<std::uint16_t>((hi - rows_[i].depth) * scale);
      ++count_[band_[i] + 1u];
    }
    for (std::size_t b = 0; b < levels; ++b) count_[b + 1] += count_[b];
    order_.resize(rows_.size());
    for (std::size_t i = 0; i < rows_.size(); ++i) order_[count_[band_[i]]++] = static_cast<int>(i);
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
      verts_.push_back({{c & 1 ? box[0] : 0, c & 2 ? box[1] : 0, c & 4 ? box[2] : 0}, 0, -1});
    static constexpr int cycles[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    len_.clear();
    plane_.clear();
    if (slots_.size() < 64 * kSlot) slots_.resize(64 * kSlot);
    for (int f = 0; f < 6; ++f) {
      std::copy(cycles[f], cycles[f] + 4, slots_.begin() + f * kSlot);
      len_.push_back(4);
      D3 c{0, 0, 0};
      c[static_cast<std::size_t>(f / 2)] = f % 2 ? 1 : -1;
      plane_.push_back({c, f % 2 ? box[static_cast<std::size_t>(f / 2)] : 0});
    }
    free_.clear();
    face_seen_.assign(6, 0);
    degree_.assign(8, 0);
    if (incident_.size() < 8 * kDegree) incident_.resize(8 * kDegree);
    for (int f = 0; f < 6; ++f)
      for (int j = 0; j < 4; ++j) add_incident(cycles[f][j], f);
    live_ = {0, 1, 2, 3, 4, 5, 6, 7};
    out_flag_.assign(8, 0);
    lx_.clear(), ly_.clear(), lz_.clear();
    for (const Vertex& v : verts_) lx_.push_back(v.x[0]), ly_.push_back(v.x[1]), lz_.push_back(v.x[2]);
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
    ++scans_;
    scanned_ += live_.size();
    if (support(c) - r.p.b <= r.eps) return DoublePolytope::Kind::polytope;
    bool inside = false;
    outside_.clear();
    for (int v : live_) {
      Vertex& x = verts_[static_cast<std::size_t>(v)];
      x.s = c[0] * x.x[0] + c[1] * x.x[1] + c[2] * x.x[2] - r.p.b;
      const bool out = x.s > r.eps;
      out_flag_[static_cast<std::size_t>(v)] = out;
      if (out) outside_.push_back(v);
      inside = inside || x.s < -r.eps;
    }
    if (!inside) {
      for (int v : live_)
        if (verts_[static_cast<std::size_t>(v)].s <= r.eps) return DoublePolytope::Kind::flat;
      return DoublePolytope::Kind::empty;
    }
    ++cuts_;
    const std::size_t made = verts_.size();
    made_from_ = made;
    cut_edges_.clear();
    int cap_first = -1, cap_edges = 0;
    crossed_.clear();  // the faces of the outside vertices: the only ones the cut changes
    for (int v : outside_)
      for (std::size_t j = 0; j < degree_[static_cast<std::size_t>(v)]; ++j) {
        const int f = incident_[static_cast<std::size_t>(v) * kDegree + j];
        if (face_seen_[static_cast<std::size_t>(f)] == cuts_) continue;
        face_seen_[static_cast<std::size_t>(f)] = static_cast<unsigned>(cuts_);
        crossed_.push_back(f);
      }
    for (int f : crossed_)
      if (!cut_face(static_cast<std::size_t>(f), r.eps, cap_first, cap_edges)) return DoublePolytope::Kind::flat;
    refine_made(r.p);
    for (int f : crossed_)
      if (len_[static_cast<std::size_t>(f)] == 0) free_.push_back(f);
    if (!close_cap(r.p, cap_first, cap_edges)) return DoublePolytope::Kind::flat;
    relive(made);
    return DoublePolytope::Kind::polytope;
  }

  // max c·x over the live vertices (their coordinates kept contiguous, four running maxima).
  double support(const D3& c) const {
    const std::size_t n = lx_.size();
    const double *x = lx_.data(), *y = ly_.data(), *z = lz_.data();
    double m0 = -HUGE_VAL, m1 = -HUGE_VAL, m2 = -HUGE_VAL, m3 = -HUGE_VAL;
    std::size_t j = 0;
    for (; j + 4 <= n; j += 4) {
      const double v0 = c[0] * x[j] + c[1] * y[j] + c[2] * z[j];
      const double v1 = c[0] * x[j + 1] + c[1] * y[j + 1] + c[2] * z[j + 1];
      const double v2 = c[0] * x[j + 2] + c[1] * y[j + 2] + c[2] * z[j + 2];
      const double v3 = c[0] * x[j + 3] + c[1] * y[j + 3] + c[2] * z[j + 3];
      m0 = v0 > m0 ? v0 : m0, m1 = v1 > m1 ? v1 : m1, m2 = v2 > m2 ? v2 : m2, m3 = v3 > m3 ? v3 : m3;
    }
    for (; j < n; ++j) {
      const double v = c[0] * x[j] + c[1] * y[j] + c[2] * z[j];
      m0 = v > m0 ? v : m0;
    }
    return std::max(std::max(m0, m1), std::max(m2, m3));
  }

  // Face f cut by the current row, in place (length 0: removed); its cap edge entry → exit noted.
  // False when the face's outside vertices are not one run (an inconsistent side decision).
  bool cut_face(std::size_t f, double eps, int& cap_first, int& cap_edges) {
    int* cyc = slots_.data() + f * kSlot;
    const int L = len_[f];
    const unsigned char* o = out_flag_.data();
    auto out = [&](int i) { return out_flag_[static_cast<std::size_t>(cyc[i])] != 0; };  // o moves when a vertex is made
    int entry_at = -1, runs = 0;  // kept after out: branch-free (most faces are kept whole)
    for (int i = 0, prev = o[cyc[L - 1]]; i < L; ++i) {
      const int now = o[cyc[i]], starts = prev & (now ^ 1);
      runs += starts;
      entry_at = starts ? i : entry_at;
      prev = now;
    }
    if (runs == 0) {
      if (out(0)) len_[f] = 0;  // wholly removed (else wholly kept, untouched)
      return true;
    }
    const int fi = static_cast<int>(f);
    if (runs > 1) return false;
    if (static_cast<std::size_t>(L) + 1 > kSlot) too_long();
    int n = 0, cycle[kSlot];
    const int first = cyc[entry_at];
    const int entry = on_or_cut(first, cyc[entry_at == 0 ? L - 1 : entry_at - 1], eps, f);
    if (entry != first) cycle[n++] = entry;
    int i = entry_at, last = first;
    while (!out(i)) {
      last = cycle[n++] = cyc[i];
      i = i + 1 == L ? 0 : i + 1;
    }
    const int exit = on_or_cut(last, cyc[i], eps, f);
    if (exit != last) cycle[n++] = exit;
    len_[f] = n >= 3 ? n : 0;
    std::copy_n(cycle, len_[f], cyc);
    if (n < 3)  // removed: its vertices left (on the plane) no longer on it
      for (int j = 0; j < n; ++j) remove_incident(cycle[j], fi);
    else
      for (int j = 0; j < n; ++j)
        if (static_cast<std::size_t>(cycle[j]) >= made_from_) add_incident(cycle[j], fi);
    if (entry != exit) {
      verts_[static_cast<std::size_t>(entry)].cap_next = exit;
      if (cap_first < 0) cap_first = entry;
      ++cap_edges;
    }
    return true;
  }
  // Each made vertex as the intersection of its edge's two face planes and the row's plane
  // (Cramer's rule): errors then do not accumulate along chains of interpolations, which left
  // vertices a few 1e-11 apart where the exact set has one. Kept interpolated when the three
  // planes are nearly dependent.
  void refine_made(const DPlane& p) {
    for (const CutEdge& e : cut_edges_) {
      if (e.faces[1] < 0) continue;
      const DPlane &a = plane_[static_cast<std::size_t>(e.faces[0])], &b = plane_[static_cast<std::size_t>(e.faces[1])];
      const D3 bc = cross(b.c, p.c), ca = cross(p.c, a.c), ab = cross(a.c, b.c);
      const double det = a.c[0] * bc[0] + a.c[1] * bc[1] + a.c[2] * bc[2];
      const double scale = norm(a.c) * norm(b.c) * norm(p.c);
      if (!(std::abs(det) > 1e-6 * scale)) continue;
      D3& x = verts_[static_cast<std::size_t>(e.made)].x;
      for (std::size_t k = 0; k < 3; ++k) x[k] = (a.b * bc[k] + b.b * ca[k] + p.b * ab[k]) / det;
    }
  }
  static D3 cross(const D3& u, const D3& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  }
  static double norm(const D3& u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); }
  [[noreturn]] static void too_long() {
    std::fprintf(stderr, "double_clip_3.h: a face of more than %zu vertices\n", kSlot);
    std::abort();
  }
  // The kept vertex itself when it is on the plane, else the edge's crossing (made once per edge,
  // by interpolation; refine_made then recomputes it from its three planes).
  int on_or_cut(int kept, int out, double eps, std::size_t face) {
    if (verts_[static_cast<std::size_t>(kept)].s >= -eps) return kept;
    for (CutEdge& e : cut_edges_)
      if (e.kept == kept && e.out == out) {
        e.faces[1] = static_cast<int>(face);
        return e.made;
      }
    const Vertex &a = verts_[static_cast<std::size_t>(kept)], &b = verts_[static_cast<std::size_t>(out)];
    const double t = a.s / (a.s - b.s);
    const int made = static_cast<int>(verts_.size());
    verts_.push_back({{a.x[0] + t * (b.x[0] - a.x[0]), a.x[1] + t * (b.x[1] - a.x[1]), a.x[2] + t * (b.x[2] - a.x[2])},
                      0, -1});
    out_flag_.push_back(0);
    degree_.push_back(0);
    if (incident_.size() < verts_.size() * kDegree) incident_.resize(2 * verts_.size() * kDegree);
    cut_edges_.push_back({kept, out, made, {static_cast<int>(face), -1}});
    return made;
  }
  // The cap face: its edges entry → exit chained into one cycle, on the row's plane.
  bool close_cap(const DPlane& p, int first, int edges) {
    if (edges < 3) return false;
    if (static_cast<std::size_t>(edges) > kSlot) too_long();
    std::size_t f = len_.size();
    if (!free_.empty()) f = static_cast<std::size_t>(free_.back()), free_.pop_back();
    if (slots_.size() < (f + 1) * kSlot) slots_.resize((f + 1) * kSlot);
    int* cyc = slots_.data() + f * kSlot;
    int v = first, n = 0;
    do {
      cyc[n] = v;
      const int next = verts_[static_cast<std::size_t>(v)].cap_next;
      verts_[static_cast<std::size_t>(v)].cap_next = -1;
      v = next;
    } while (v >= 0 && v != first && ++n < edges);
    if (v != first || n + 1 != edges) return false;  // one cycle through every cap edge
    if (f == len_.size()) len_.push_back(0), plane_.push_back(p), face_seen_.push_back(0);
    len_[f] = edges, plane_[f] = p;
    for (int j = 0; j < edges; ++j) add_incident(cyc[j], static_cast<int>(f));
    return true;
  }
  // Vertex v's faces (at most kDegree: a vertex where more faces meet aborts, loudly).
  void add_incident(int v, int f) {
    std::size_t& d = degree_[static_cast<std::size_t>(v)];
    if (d == kDegree) {
      std::fprintf(stderr, "double_clip_3.h: a vertex on more than %zu faces\n", kDegree);
      std::abort();
    }
    incident_[static_cast<std::size_t>(v) * kDegree + d++] = f;
  }
  void remove_incident(int v, int f) {
    std::size_t& d = degree_[static_cast<std::size_t>(v)];
    int* a = incident_.data() + static_cast<std::size_t>(v) * kDegree;
    for (std::size_t j = 0; j < d; ++j)
      if (a[j] == f) {
        a[j] = a[--d];
        return;
      }
  }
  // The live vertices after a cut: those not outside it and those it made (from `made` on),
  // their coordinates contiguous, and their bounding box. (A vertex on the plane whose faces all
  // went stays live though on no face: a point of the set, harmless to the tests; finish drops it.)
  void relive(std::size_t made) {
    std::size_t n = 0;
    for (int v : live_)
      if (!out_flag_[static_cast<std::size_t>(v)]) live_[n++] = v;
    live_.resize(n);
    for (std::size_t v = made; v < verts_.size(); ++v) live_.push_back(static_cast<int>(v));
    const std::size_t m = live_.size();
    lx_.resize(m), ly_.resize(m), lz_.resize(m);
    D3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::size_t j = 0; j < m; ++j) {
      const D3& x = verts_[static_cast<std::size_t>(live_[j])].x;
      lx_[j] = x[0], ly_[j] = x[1], lz_[j] = x[2];
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], x[k]), hi[k] = std::max(hi[k], x[k]);
    }
    lo_ = lo, hi_ = hi;
  }

  // The result, its live vertices renumbered.
  const DoublePolytope& finish(DoublePolytope::Kind kind) {
    out_.kind = kind;
    out_.vertices.clear();
    out_.start.clear();
    out_.index.clear();
    out_.plane.clear();
    if (kind != DoublePolytope::Kind::polytope) return out_;
    number_.assign(verts_.size(), -1);
    out_.start.push_back(0);
    for (std::size_t f = 0; f < len_.size(); ++f) {
      if (len_[f] == 0) continue;  // a free slot
      out_.plane.push_back(plane_[f]);
      for (int j = 0; j < len_[f]; ++j) {
        int& k = number_[static_cast<std::size_t>(slots_[f * kSlot + static_cast<std::size_t>(j)])];
        if (k < 0) {
          k = static_cast<int>(out_.vertices.size());
          out_.vertices.push_back(verts_[static_cast<std::size_t>(slots_[f * kSlot + static_cast<std::size_t>(j)])].x);
        }
        out_.index.push_back(k);
      }
      out_.start.push_back(static_cast<int>(out_.index.size()));
    }
    return out_;
  }

  std::vector<Row> rows_;
  std::vector<int> order_;
  std::vector<std::uint16_t> band_;
  std::vector<std::size_t> count_;
  std::vector<double> lx_, ly_, lz_;
  std::vector<unsigned char> out_flag_;  // per vertex: outside the current row
  std::array<std::vector<char>, 27> dominated_;
  std::vector<Vertex> verts_;
  std::vector<int> number_;  // finish: each vertex's number in the result
  std::vector<int> live_;
  // Face f: its cycle slots_[f·kSlot ..][0 .. len_[f]) (fixed slots, so a cut rewrites only the
  // faces it crosses; length 0: a free slot), its plane plane_[f].
  static constexpr std::size_t kSlot = 128;
  std::vector<int> slots_, len_;
  std::vector<DPlane> plane_;
  std::vector<CutEdge> cut_edges_;
  // Each vertex's faces: incident_[v·kDegree ..][0 .. degree_[v]); the free face slots; the
  // outside vertices and the faces the current cut crosses; the cut that last listed each face.
  static constexpr std::size_t kDegree = 16;
  std::vector<int> incident_, free_, outside_, crossed_;
  std::vector<std::size_t> degree_;
  std::vector<unsigned> face_seen_;
  std::size_t made_from_ = 0;
  D3 lo_{}, hi_{};
  std::size_t cuts_ = 0, scans_ = 0, scanned_ = 0;
  DoublePolytope out_;
};

}  // namespace gmcc::bench
