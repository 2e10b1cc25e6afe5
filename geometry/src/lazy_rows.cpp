// F3's clip with its rows generated lazily (internal/lazy_rows.h, docs/derivations.md §4.6).
#include "internal/lazy_rows.h"
#include "internal/clip_filter.h"
#include "internal/scaled_point.h"

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/geometry/rational_enclosure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

namespace gmcc::internal {
namespace {

// Row (a ⊙ p)·x <= b's filter copy into r (a~ ⊙ p~, b~·2^-e: each coefficient within 6u relative
// of the exact row's times a power of 2, its signs the exact ones); false when not usable.
bool row_filter(const ClipFacets& facets, std::size_t f, const ScaledPoint& q, double* r) {
  if (!q.usable || !facets.usable[f]) return false;
  const std::array<double, 4>& a = facets.filters[f];
  r[0] = a[0] * q.c[0], r[1] = a[1] * q.c[1], r[2] = a[2] * q.c[2], r[3] = a[3] * q.scale;
  return filter_range(r[0]) && filter_range(r[1]) && filter_range(r[2]) && filter_range(r[3]);
}

// The half-space a·x <= b (a filter copy as row_filter's) holds on the box lo <= x <= hi
// (0 <= lo), strictly unless every term is 0 (docs/derivations.md §4.6, "Rows generated lazily":
// with P = Σ_{a_k > 0} a_k hi_k and N = Σ_{a_k < 0} |a_k| lo_k computed, max over the box of the
// exact a·x − b is at most P~ − (N~ + b~) + 11.5u·T~, T~ = P~ + N~ + |b~|, so the test
// P~ − (N~ + b~) <= −16u·T~ shows it below 0 when T~ > 0 and equal to 0 when T~ = 0; the same
// test as the clip's group boxes: box_below_plane, clip_filter.h). With `strict`, a box where
// T~ = 0 (the half-space's plane through it, a point of it) does not pass. `excess` is
// P~ − (N~ + b~), about the largest a·x − b over the box (a heuristic's guide only).
bool box_holds(const double* a, const double* lo, const double* hi, double& excess, bool strict) {
  double total;
  return box_below_plane(a, lo, hi, excess, total) && (!strict || total > 0);
}

// The vertices of a polytope as certified boxes (their enclosures; 0 <= lo, as every vertex of
// the clip is in the box x >= 0), in a tree of boxes: a row that holds on a node's box holds at
// its vertices.
class VertexTree {
 public:
  // False when a vertex's bound is not finite or out of box_range (nothing is then certified).
  bool build(const std::vector<Enclosure3>& enclosures) {
    const std::size_t n = enclosures.size();
    boxes_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        const Enclosure& x = enclosures[i][k];
        const bool zero = x.mid == 0 && x.rad == 0;  // exactly 0 (lo() and hi() would pad it)
        const double lo = zero ? 0 : std::max(0.0, x.lo()), hi = zero ? 0 : x.hi();
        if (!(lo <= hi) || !box_range(lo) || !box_range(hi)) return false;
        boxes_[i][k] = lo, boxes_[i][k + 3] = hi, boxes_[i][k + 6] = x.mid;
      }
    order_.resize(n);
    for (std::size_t i = 0; i < n; ++i) order_[i] = static_cast<int>(i);
    nodes_.clear();
    if (n > 0) split(0, n);
    return true;
  }

  // Vertex v's midpoint coordinates (doubles near its exact ones).
  const double* mid(int v) const { return &boxes_[static_cast<std::size_t>(v)][6]; }
  // True when the row a (a filter copy) certainly holds at every vertex; otherwise `worst` is the
  // vertex not cleared where the row's approximate value a·x − b is largest.
  // Branch and bound: a node whose box holds is skipped; once a vertex is not cleared, so is a
  // node whose box's excess is below that vertex's value (the choice of `worst` is a heuristic).
  // With `strict`, true only when the row holds strictly at every vertex (box_holds).
  bool holds(const double* a, int& worst, bool strict = false) const {
    worst = -1;
    if (nodes_.empty()) return true;
    double value = -HUGE_VAL, excess;
    std::pair<int, double> stack[64];  // nodes whose box does not hold, with their excess
    int top = 0;
    if (box_holds(a, nodes_[0].lo, nodes_[0].hi, excess, strict)) return true;
    stack[top++] = {0, excess};
    while (top > 0) {
      const auto [index, bound] = stack[--top];
      if (worst >= 0 && bound <= value) continue;
      const Node& x = nodes_[static_cast<std::size_t>(index)];
      if (x.left < 0) {
        for (int j = x.first; j < x.first + x.count; ++j) {
          const int v = order_[static_cast<std::size_t>(j)];
          const std::array<double, 9>& b = boxes_[static_cast<std::size_t>(v)];
          if (box_holds(a, &b[0], &b[3], excess, strict)) continue;
          const double s = a[0] * b[6] + a[1] * b[7] + a[2] * b[8] - a[3];
          if (worst < 0 || s > value) worst = v, value = s;
        }
        if (value > 0) return false;  // violated (about): the first such leaf's worst vertex
        continue;
      }
      double el, er;
      const bool hl = box_holds(a, nodes_[static_cast<std::size_t>(x.left)].lo, nodes_[static_cast<std::size_t>(x.left)].hi, el, strict);
      const bool hr = box_holds(a, nodes_[static_cast<std::size_t>(x.right)].lo, nodes_[static_cast<std::size_t>(x.right)].hi, er, strict);
      // The child with the larger excess popped first.
      if (el >= er) {
        if (!hr) stack[top++] = {x.right, er};
        if (!hl) stack[top++] = {x.left, el};
      } else {
        if (!hl) stack[top++] = {x.left, el};
        if (!hr) stack[top++] = {x.right, er};
      }
    }
    return worst < 0;
  }

 private:
  struct Node {
    double lo[3], hi[3];
    int first, count, left, right;  // left < 0: a leaf, order_[first, first + count)
  };
  // The node for order_[b, e) (its index returned): split at the median of the boxes' mids along
  // its widest side, down to leaves of at most 16 (depth below 40 for any count that fits in int;
  // leaves of 16 measured faster than 2, 4 or 8 on Gehler–Shi thumbnails at σ = 16).
  int split(std::size_t b, std::size_t e) {
    Node x{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {0, 0, 0}, static_cast<int>(b), static_cast<int>(e - b), -1, -1};
    for (std::size_t j = b; j < e; ++j)
      for (std::size_t k = 0; k < 3; ++k) {
        const std::array<double, 9>& v = boxes_[static_cast<std::size_t>(order_[j])];
        x.lo[k] = std::min(x.lo[k], v[k]), x.hi[k] = std::max(x.hi[k], v[k + 3]);
      }
    const int self = static_cast<int>(nodes_.size());
    nodes_.push_back(x);
    if (e - b <= 16) return self;
    std::size_t axis = 0;
    for (std::size_t k = 1; k < 3; ++k)
      if (x.hi[k] - x.lo[k] > x.hi[axis] - x.lo[axis]) axis = k;
    const std::size_t m = b + (e - b) / 2;
    const auto at = [&](std::size_t j) { return order_.begin() + static_cast<std::ptrdiff_t>(j); };
    std::nth_element(at(b), at(m), at(e), [&](int i, int j) {
      return boxes_[static_cast<std::size_t>(i)][axis + 6] < boxes_[static_cast<std::size_t>(j)][axis + 6];
    });
    const int left = split(b, m), right = split(m, e);
    nodes_[static_cast<std::size_t>(self)].left = left, nodes_[static_cast<std::size_t>(self)].right = right;
    return self;
  }
  std::vector<std::array<double, 9>> boxes_;  // per vertex: lo, hi, mid
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

// One canonical facet of one group: that facet alone (for clip_polytope), the points whose rows
// are in the subset (indices, and the points for clip_polytope), and those whose rows are neither
// in it nor cleared yet.
struct Part {
  const ClipGroup* group;
  std::size_t facet;
  ClipFacets alone;
  std::vector<std::uint32_t> chosen;
  std::vector<Point3> chosen_points;
  std::vector<std::uint32_t> pending;
};

// Facet f of `facets` as a ClipFacets of its own (no incidences: ClipFacets::on is an accelerator).
ClipFacets facet_alone(const ClipFacets& facets, std::size_t f) {
  ClipFacets out;
  out.planes = {facets.planes[f]};
  out.filters = {facets.filters[f]};
  out.usable = {facets.usable[f]};
  out.wide = {facets.wide[f]};
  return out;
}

// One round's check of part's rows against the polytope P's vertex tree. A row of the subset that
// holds strictly at every vertex leaves it: its plane misses P, so the rows left still cut P
// exactly, and every later round's polytope lies in P; it holds on them all, cleared for good, as
// are the pending rows that hold at every vertex. Of the pending rows not cleared, for each vertex
// the one most violated there (approximately) joins the subset, as does every row without a
// usable filter copy. Returns how many joined.
std::size_t check_part(Part& part, const std::vector<ScaledPoint>& scaled, const VertexTree& tree,
                       std::vector<std::pair<double, std::uint32_t>>& best, std::vector<int>& touched) {
  const ClipFacets& facets = *part.group->facets;
  const std::vector<Point3>& points = *part.group->points;
  std::vector<std::uint32_t> kept;
  std::vector<std::uint32_t> join;
  touched.clear();
  part.chosen.erase(std::remove_if(part.chosen.begin(), part.chosen.end(),
                                   [&](std::uint32_t p) {
                                     double r[4];
                                     int worst;
                                     return row_filter(facets, part.facet, scaled[p], r) && tree.holds(r, worst, true);
                                   }),
                    part.chosen.end());
  for (const std::uint32_t p : part.pending) {
    double r[4];
    int worst = -1;
    if (!row_filter(facets, part.facet, scaled[p], r)) {
      join.push_back(p);
      continue;
    }
    if (tree.holds(r, worst)) continue;
    kept.push_back(p);
    const double* m = tree.mid(worst);
    const double value = r[0] * m[0] + r[1] * m[1] + r[2] * m[2] - r[3];
    std::pair<double, std::uint32_t>& b = best[static_cast<std::size_t>(worst)];
    if (b.second == UINT32_MAX) touched.push_back(worst), b = {value, p};
    else if (value > b.first) b = {value, p};
  }
  for (const int v : touched) {
    join.push_back(best[static_cast<std::size_t>(v)].second);
    best[static_cast<std::size_t>(v)] = {0, UINT32_MAX};
  }
  std::sort(join.begin(), join.end());
  join.erase(std::unique(join.begin(), join.end()), join.end());
  part.chosen.insert(part.chosen.end(), join.begin(), join.end());
  part.chosen_points.clear();
  for (const std::uint32_t p : part.chosen) part.chosen_points.push_back(points[p]);
  part.pending.clear();
  for (const std::uint32_t p : kept)
    if (!std::binary_search(join.begin(), join.end(), p)) part.pending.push_back(p);
  return join.size();
}

// Each point's rank in each coordinate (equal coordinates, equal ranks), compared exactly.
std::vector<std::array<int, 3>> ranks(const std::vector<Point3>& points) {
  const std::size_t n = points.size();
  std::vector<std::array<int, 3>> rank(n);
  std::vector<std::size_t> by(n);
  for (int k = 0; k < 3; ++k) {
    const auto less = [&](std::size_t i, std::size_t j) { return cmp(coord(points[i], k), coord(points[j], k)) < 0; };
    for (std::size_t i = 0; i < n; ++i) by[i] = i;
    std::sort(by.begin(), by.end(), less);
    int r = 0;
    for (std::size_t t = 0; t < n; ++t) {
      if (t > 0 && less(by[t - 1], by[t])) ++r;
      rank[by[t]][static_cast<std::size_t>(k)] = r;
    }
  }
  return rank;
}

// The points whose rows a facet with coefficient signs s needs (indices, increasing): a point p
// is left out when another p' has s_k·p_k <= s_k·p'_k for every k (strictly for some k, or else
// p' comes first), for then on x >= 0, which holds on the box, (a ⊙ p)·x <= (a ⊙ p')·x and row p'
// implies row p (the clip's own mark_implied, polytope_clip.cpp). A skyline pass in decreasing
// order of Σ s_k·rank_k, each point compared with the points kept so far.
std::vector<std::uint32_t> undominated(const std::vector<std::array<int, 3>>& rank, const std::array<int, 3>& s) {
  const std::size_t n = rank.size();
  std::vector<std::array<int, 3>> t(n);
  std::vector<std::pair<int, std::uint32_t>> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) t[i][k] = s[k] * rank[i][k];
    order[i] = {-(t[i][0] + t[i][1] + t[i][2]), static_cast<std::uint32_t>(i)};
  }
  std::sort(order.begin(), order.end());
  std::vector<std::uint32_t> sky;
  for (const auto& [key, i] : order) {
    bool dominated = false;
    for (std::size_t j = 0; j < sky.size() && !dominated; ++j) {
      const std::array<int, 3>& d = t[sky[j]];
      dominated = d[0] >= t[i][0] && d[1] >= t[i][1] && d[2] >= t[i][2];
    }
    if (!dominated) sky.push_back(i);
  }
  std::sort(sky.begin(), sky.end());
  return sky;
}

}  // namespace

ClippedPolytope clip_polytope_lazy_rows(const Point3& box, const std::vector<ClipGroup>& groups, ClipCounts* counts) {
  std::vector<Part> parts;
  std::vector<std::vector<ScaledPoint>> scaled(groups.size());
  std::size_t rows = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::vector<Point3>& points = *groups[g].points;
    if (points.size() >= UINT32_MAX) return clip_polytope(box, groups, counts);
    for (const Point3& p : points) scaled[g].push_back(scaled_point(p));
    const std::vector<std::array<int, 3>> rank = ranks(points);
    std::array<std::vector<std::uint32_t>, 27> needed;  // per sign pattern, made on first use
    for (std::size_t f = 0; f < groups[g].facets->planes.size() && !points.empty(); ++f) {
      const IntegerPlane3& a = groups[g].facets->planes[f];
      const std::array<int, 3> s{sgn(a.a[0]), sgn(a.a[1]), sgn(a.a[2])};
      std::vector<std::uint32_t>& need = needed[static_cast<std::size_t>((s[0] + 1) + 3 * (s[1] + 1) + 9 * (s[2] + 1))];
      if (need.empty()) need = undominated(rank, s);
      parts.push_back({&groups[g], f, facet_alone(*groups[g].facets, f), {}, {}, need});
      rows += points.size();
    }
  }
  std::vector<std::size_t> group_of(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) group_of[k] = static_cast<std::size_t>(parts[k].group - groups.data());
  std::size_t chosen = 0;  // rows that joined the subset so far
  VertexTree tree;
  std::vector<std::pair<double, std::uint32_t>> best;
  std::vector<int> touched;
  for (;;) {
    std::vector<ClipGroup> subset;
    for (const Part& part : parts)
      if (!part.chosen.empty()) subset.push_back({&part.alone, &part.chosen_points});
    ClippedPolytope r = clip_polytope(box, subset, counts);
    if (r.outcome == ClippedPolytope::Outcome::empty) return r;  // F3 ⊆ the subset's set
    // A flat set, or vertices beyond the filter's range: the whole clip decides.
    if (r.outcome == ClippedPolytope::Outcome::flat || !tree.build(r.set.enclosures()))
      return clip_polytope(box, groups, counts);
    best.assign(r.set.size(), {0, UINT32_MAX});
    std::size_t joined = 0;
    for (std::size_t k = 0; k < parts.size(); ++k) joined += check_part(parts[k], scaled[group_of[k]], tree, best, touched);
    if (joined == 0) return r;  // every row in the subset or cleared at every vertex: r is F3
    chosen += joined;
    // One point (which a row left alone) not yet cleared, or a subset grown past half the rows:
    // the whole clip, which costs no more.
    if (r.set.kind() == ConvexKind3::point || 2 * chosen > rows) return clip_polytope(box, groups, counts);
  }
}

}  // namespace gmcc::internal
