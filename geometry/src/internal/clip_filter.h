#pragma once
// The clip's cheap tests of a half-space against the live vertices of its polytope
// (polytope_clip.cpp, docs/derivations.md §4.6): from the vertices' filtered homogeneous
// coordinates, a bounding box of the polytope and, for the all-inside pass, the vertices grouped
// by octant about a centre of the polytope, each group with a certified box, so that a half-space
// clear of a group's box skips its vertices. Every answer is certified (a true answer is true of
// the exact vertices); a false one decides nothing. Internal to gmcc::geometry.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>
#include <gmcc/numerics/filtered_sign.h>

namespace gmcc::internal {

// A vertex as the filter knows it: homogeneous coordinates (X, Y, Z, W) of the filter planes'
// solution, W > 0, each within err[k] of the exact value; meaningful when `filtered`.
struct VertexDoubles {
  double h[4] = {0, 0, 0, 0};
  double err[4] = {0, 0, 0, 0};
  bool filtered = false;
  // Made once from h and err by settle() (a vertex never changes): α and β with
  // E + 16u(T + E) <= max_k |a_k|·α + |b|·β for any plane (a, b) (T and E as in the clip's side
  // test); certified bounds lo <= x_k <= hi of its coordinates, valid when `bounded`.
  double alpha = 0, beta = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool bounded = false;
  bool in_range = false;  // bounded, and every bound 0 or in [2^-400, 2^400] (a group box may use it)
  void settle();
};

class LiveVertexFilter {
 public:
  // Vertex number add()'s count so far (vertices are numbered in the order they are added).
  void add(const VertexDoubles& v);
  // Room for n vertices without moving the ones added (as the clip reserves its own).
  // Each octant's group is given room for n/16 records at once (a clip's live vertices, about a
  // third of those made, spread over the octants; more grow by doubling).
  void reserve(std::size_t n) {
    vertices_.reserve(n), where_.reserve(n);
    for (Group& g : groups_)
      if (g.packed.size() < 6 * (n / 16)) g.packed.resize(6 * (n / 16));
  }
  // The filter of the polytope whose vertices are `live` (numbers from add()), from scratch: the
  // groups about the mean of the vertices' box centres, each group's box tight.
  void rebuild(const std::vector<int>& live);
  // The same after a cut that removed the vertices `removed` and added `added` (the others stay
  // live): the removed ones' records made inert, the added ones put in their octant's group about
  // the same centre, boxes widened; a rebuild once as many records changed as are live, or when a
  // vertex lacks bounds. `live` is the new live set (for the bounding box, kept tight).
  void update(const std::vector<int>& live, const std::vector<int>& removed, const std::vector<int>& added);
  // True when the half-space a·x <= b (a filter copy: a0, a1, a2, b, each within a relative 6u
  // of the exact plane's scaled by a power of 2) holds on a box containing the polytope.
  bool box_inside(const double* a) const;  // (inline below: it is called for most rows)
  // True when no live vertex is strictly outside the half-space (each strictly inside, exactly
  // on it, or in a group whose box holds in it).
  bool none_outside(const double* a) const;

 private:
  struct Group {
    double lo[3], hi[3];         // certified bounds of its vertices' coordinates (lo >= 0)
    std::vector<double> packed;  // per vertex: h[0..3], then α and β (see none_outside); `used` of them
    std::size_t used = 0;        // doubles in use at the front of `packed` (it only grows)
    bool boxed;                  // the bounds are usable
  };
  bool group_inside(const Group& g, const double* a) const;
  std::size_t octant(const VertexDoubles& v) const;
  void place(int v);
  std::vector<VertexDoubles> vertices_;  // every vertex added, by number
  // Per vertex number: its group and its record's offset in the group's `packed` (live ones).
  std::vector<std::array<std::size_t, 2>> where_;
  std::array<Group, 8> groups_;  // by octant about centre_ (group 0 only, when !box_ok_)
  double centre_[3] = {0, 0, 0};
  std::size_t changed_ = 0;  // records changed since the last rebuild
  std::array<double, 3> top_{};  // the coordinates' upper bounds over the polytope
  bool all_filtered_ = false, box_ok_ = false;
};

// The half-space holds on the box [0, top_] ⊇ the polytope: Σ max(a_k, 0)·top_k <= b, with
// the filter copy's coefficients within 6u of the exact ones (scaled) and the sum's roundings
// covered by 1 + 16u on the left and 1 - 16u on the right.
inline bool LiveVertexFilter::box_inside(const double* a) const {
  constexpr double u = numerics::unit_roundoff;
  if (!box_ok_) return false;
  const double lhs =
      (std::max(a[0], 0.0) * top_[0] + std::max(a[1], 0.0) * top_[1] + std::max(a[2], 0.0) * top_[2]) * (1 + 16 * u);
  return lhs <= a[3] * (1 - 16 * u);
}

// Vertex boxes are used only with non-zero bounds in [2^-400, 2^400]: their products with filter
// coefficients (0 or in [2^-200, 2^200], filter_range in scaled_point.h) are then normal, so each
// rounding is within u relative.
inline bool box_range(double x) { return x == 0 || (x >= 0x1p-400 && x <= 0x1p400); }

// Whether the half-space a·x <= b (a filter copy: each coefficient within 6u of the exact row's,
// scaled) certainly holds on the box lo <= x <= hi (0 <= lo, bounds in box_range): the group
// boxes' test here and the vertex boxes' of the lazy rows (lazy_rows.cpp).
// max over the box of a·x is P − N, P = Σ_{a_k > 0} a_k hi_k and N = Σ_{a_k < 0} |a_k| lo_k
// (both >= 0; summed without branches, max(±a_k, 0) adding exact zeros, the same sums). With each
// coefficient within 6u of the exact one and the sums' roundings, the exact maximum is at most
// P~(1 + 11u) − N~(1 − 11u) and the exact b at least b~ − 6u|b~|; so
// P~ − (N~ + b~) <= −16u(P~ + N~ + |b~|), evaluated with two roundings of at most u·T each
// (T = P~ + N~ + |b~|) and an exact product by 16u, shows the maximum <= b. `excess` is
// P~ − (N~ + b~) and `total` T~ (T~ = 0: every term is 0, and the test shows only a·x − b = 0).
inline bool box_below_plane(const double* a, const double* lo, const double* hi, double& excess, double& total) {
  constexpr double u = numerics::unit_roundoff;
  double p = 0, n = 0;
  for (int k = 0; k < 3; ++k) {
    p += std::max(a[k], 0.0) * hi[k];
    n += std::max(-a[k], 0.0) * lo[k];
  }
  total = p + n + std::fabs(a[3]);
  excess = p - (n + a[3]);
  return excess <= -16 * u * total;
}

// The octant of v's box centre about centre_ (0 when the bounds are not known).
inline std::size_t LiveVertexFilter::octant(const VertexDoubles& v) const {
  std::size_t o = 0;
  if (box_ok_)
    for (std::size_t c = 0; c < 3; ++c)
      if (v.lo[c] + v.hi[c] > centre_[c]) o |= std::size_t(1) << c;
  return o;
}

inline bool LiveVertexFilter::group_inside(const Group& g, const double* a) const {
  double excess, total;
  return g.boxed && box_below_plane(a, g.lo, g.hi, excess, total);
}

}  // namespace gmcc::internal
