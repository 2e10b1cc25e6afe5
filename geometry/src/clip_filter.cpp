// The clip's certified box and all-inside tests over the live vertices (internal/clip_filter.h).
#include "internal/clip_filter.h"
#include <gmcc/numerics/filter_bounds.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gmcc::internal {
namespace {

constexpr double u = numerics::unit_roundoff;

}  // namespace

// x_k = X/W <= (h_k + err_k)/(h_3 − err_3) when W~ > err_3 (settled when the vertex was made)
// and >= (h_k − err_k)/(h_3 + err_3) when that is positive, else >= 0 (every vertex satisfies the
// box rows x_k >= 0); 1 ± 8u covers the roundings.
void VertexDoubles::settle() {
  const double a = std::fabs(h[0]) + std::fabs(h[1]) + std::fabs(h[2]), e = err[0] + err[1] + err[2];
  alpha = e + numerics::filter_bound::polytope_side * (a + e);
  beta = err[3] + numerics::filter_bound::polytope_side * (std::fabs(h[3]) + err[3]);
  const double w_lo = h[3] - err[3], w_hi = h[3] + err[3];
  bounded = filtered && w_lo > 0;
  if (!bounded) return;
  for (std::size_t c = 0; c < 3; ++c) {
    hi[c] = std::max(0.0, (h[c] + err[c]) / w_lo * (1 + 8 * u));
    lo[c] = std::max(0.0, (h[c] - err[c]) / w_hi * (1 - 8 * u));
  }
  in_range = box_range(lo[0]) && box_range(lo[1]) && box_range(lo[2]) && box_range(hi[0]) && box_range(hi[1]) &&
             box_range(hi[2]);
}

void LiveVertexFilter::add(const VertexDoubles& v) {
  vertices_.push_back(v);
  where_.push_back({0, 0});
}

// Vertex v's record appended to its octant's group, the group's box widened to hold it.
void LiveVertexFilter::place(int v) {
  const VertexDoubles& x = vertices_[static_cast<std::size_t>(v)];
  const std::size_t o = octant(x);
  Group& g = groups_[o];
  const std::size_t at = g.used;
  where_[static_cast<std::size_t>(v)] = {o, at};
  if (at + 6 > g.packed.size()) g.packed.resize(2 * (at + 6));
  g.used = at + 6;
  double* r = &g.packed[at];
  r[0] = x.h[0], r[1] = x.h[1], r[2] = x.h[2], r[3] = x.h[3], r[4] = x.alpha, r[5] = x.beta;
  if (!box_ok_) return;
  // group_inside reads only the group's bounds: those must be in range, as they are when every
  // vertex's are (each bound is one of them).
  for (std::size_t c = 0; c < 3; ++c) g.lo[c] = std::min(g.lo[c], x.lo[c]), g.hi[c] = std::max(g.hi[c], x.hi[c]);
  g.boxed = g.boxed && x.in_range;
}

void LiveVertexFilter::rebuild(const std::vector<int>& live) {
  const std::size_t n = live.size();
  all_filtered_ = box_ok_ = true;
  top_ = {0, 0, 0};
  double centre[3] = {0, 0, 0};
  for (int v : live) {
    const VertexDoubles& x = vertices_[static_cast<std::size_t>(v)];
    all_filtered_ = all_filtered_ && x.filtered;
    box_ok_ = box_ok_ && x.bounded;
    if (!box_ok_) continue;
    for (std::size_t c = 0; c < 3; ++c) top_[c] = std::max(top_[c], x.hi[c]), centre[c] += x.lo[c] + x.hi[c];
  }
  box_ok_ = box_ok_ && all_filtered_;
  // The groups: the octant of each vertex's box centre about the mean of those centres (one group
  // when the bounds are not known).
  for (std::size_t c = 0; c < 3; ++c) centre_[c] = n > 0 ? centre[c] / double(n) : 0;
  for (Group& g : groups_) {
    g.used = 0;
    g.boxed = box_ok_;
    for (std::size_t c = 0; c < 3; ++c) g.lo[c] = HUGE_VAL, g.hi[c] = 0;
  }
  for (int v : live) place(v);
  changed_ = 0;
}

// A removed vertex's record becomes (0, 0, 0, 0) with α = β = 0: none_outside reads it as a vertex
// exactly on every plane, which never fails the test; its group's box still holds the others.
void LiveVertexFilter::update(const std::vector<int>& live, const std::vector<int>& removed,
                              const std::vector<int>& added) {
  changed_ += removed.size() + added.size();
  bool fresh = !box_ok_ || changed_ >= live.size();
  for (int v : added) fresh = fresh || !vertices_[static_cast<std::size_t>(v)].bounded;
  if (fresh) return rebuild(live);
  // top_, the largest upper bounds over the live vertices: a maximum over the vertices kept is the
  // old one unless a removed vertex attained it (then made anew), and the added ones join it.
  bool attained = false;
  for (int v : removed) {
    const std::array<std::size_t, 2>& w = where_[static_cast<std::size_t>(v)];
    std::fill_n(groups_[w[0]].packed.begin() + static_cast<std::ptrdiff_t>(w[1]), 6, 0.0);
    const double* hi = vertices_[static_cast<std::size_t>(v)].hi;
    attained = attained || hi[0] == top_[0] || hi[1] == top_[1] || hi[2] == top_[2];
  }
  for (int v : added) place(v);
  const std::vector<int>& over = attained ? live : added;
  if (attained) top_ = {0, 0, 0};
  for (int v : over)
    for (std::size_t c = 0; c < 3; ++c) top_[c] = std::max(top_[c], vertices_[static_cast<std::size_t>(v)].hi[c]);
}

// A vertex: s = a·(X, Y, Z) − b·W < −bound with the side test's bound enlarged (1 + 64u for its
// evaluation, 1 + 16u more for α, β); a zero bound means every term is exactly zero (the vertex
// exactly on the plane). Inside: v < −bound, which is sign_within(v, bound) certainly negative
// (bound >= 0: a sum of products of non-negative numbers), or exactly 0 with a zero bound; a
// group's vertices tested without a branch each (most groups pass whole), the group then.
bool LiveVertexFilter::none_outside(const double* a) const {
  if (!all_filtered_) return false;
  const double m = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}) * (1 + numerics::filter_bound::polytope_quick_evaluation);
  const double b = std::fabs(a[3]) * (1 + numerics::filter_bound::polytope_quick_evaluation);
  for (const Group& g : groups_) {
    if (g.used == 0 || group_inside(g, a)) continue;
    bool inside = true;
    const double* p = g.packed.data();
    for (std::size_t k = 0; k < g.used; k += 6) {
      const double* h = p + k;
      const double v = a[0] * h[0] + a[1] * h[1] + a[2] * h[2] - a[3] * h[3], bound = m * h[4] + b * h[5];
      inside &= (v < -bound) | ((bound == 0) & (v == 0));
    }
    if (!inside) return false;
  }
  return true;
}

}  // namespace gmcc::internal
