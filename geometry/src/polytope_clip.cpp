// A box clipped by integer half-spaces with filtered exact predicates (docs/derivations.md §4.6).
#include "internal/polytope_clip.h"
#include "internal/scaled_point.h"
#include <gmcc/numerics/filter_bounds.h>

#include "internal/clip_filter.h"
#include "internal/plane_meets.h"

#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/internal_check.h>
#include <gmcc/numerics/rational_to_float.h>
#include <gmcc/numerics/truncated_quotient.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gmcc::internal {
namespace {

// u = 2^-53, the unit roundoff of double.
constexpr double u = numerics::unit_roundoff;
// No index.
constexpr std::size_t none = static_cast<std::size_t>(-1);

// √x, the correctly rounded double std::sqrt gives: one instruction where SSE2 is there (this
// unit is built with -frounding-math, under which the compiler makes std::sqrt a call into libm,
// one per row in deepest_first).
inline double root(double x) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(x)));
#else
  return std::sqrt(x);
#endif
}

// A plane's filter copy: a_k·2^-E and b·2^-E (E the largest binary exponent among them), each
// truncated to 53 bits by mpz_get_d_2exp (relative error below 2u; the scaling by a power of 2 is
// exact and positive, so every sign below is that of the exact plane's). A clipping row
// (a ⊙ p)·x <= b multiplies a facet's copy by p's double (below): relative error below 6u per
// coefficient. A copy is used only when every non-zero coefficient is in [2^-200, 2^200]: products
// of up to four stay normal, so the relative error bounds hold; otherwise the plane is decided
// exactly.
struct Filter {
  double c[4];  // a0, a1, a2, b
  bool usable = false;
};

Filter filter_of(const IntegerPlane3& p) {
  Filter f;
  if (const auto c = plane_filter(p)) {
    for (int k = 0; k < 4; ++k) f.c[k] = (*c)[static_cast<std::size_t>(k)];
    f.usable = true;
  }
  return f;
}


// A face's cycle of vertices: up to 12 of them inside the face, more on the heap (a clip rewrites
// its faces at every cut; most have fewer vertices than that, and then no allocation).
using Cycle = boost::container::small_vector<int, 12>;

// The filter's doubles (VertexDoubles: homogeneous coordinates of the filter planes' solution,
// W > 0, each within err[k] of the exact value, docs/derivations.md §4.6), and:
struct Vertex : VertexDoubles {
  // Each member from its initializer (planes set by add_vertex): emplace_back() would otherwise
  // zero the whole vertex first (a rep stos per vertex).
  Vertex() {}
  std::array<int, 3> planes;  // three independent planes through it
  // Exact homogeneous coordinates of the integer planes' solution (W of either sign), on demand
  // (behind a pointer: few vertices have them, and a small vertex keeps the clip's vector small).
  std::unique_ptr<std::array<mpz_class, 4>> exact;
  // The faces through it (indices into the clip's faces), `degree` of them; -1 when unknown
  // (more than fit here).
  std::array<int, 8> faces{};
  int degree = -1;
};

class Clipper {
  // One ClipGroup's rows: its facets, its points exactly.
  struct Group {
    const ClipFacets* facets;
    int nf;
    std::size_t first;                              // rows of the groups before it
    std::vector<std::array<mpz_class, 4>> points;  // the points as (p·L, L)
    const std::vector<Point3>* source;             // the points as given
    std::vector<std::optional<WidePlane>> wide;    // (p·L, L) as double-word enclosures, scaled
    std::shared_ptr<const void> owner;             // ClipGroup::owner
  };

 public:
  Clipper(const Point3& box, const std::vector<ClipGroup>& groups, ClipCounts* counts) : counts_(counts) {
    // The box: planes 0–2 are -x_k <= 0, planes 3–5 are den·x_k <= num.
    for (int k = 0; k < 3; ++k) {
      IntegerPlane3 p;
      p.a[k] = -1;
      p.b = 0;
      box_.push_back(p);
    }
    for (int k = 0; k < 3; ++k) {
      const Rational& m = k == 0 ? box.x : k == 1 ? box.y : box.z;
      IntegerPlane3 p;
      p.a[k] = m.get_den();
      p.b = m.get_num();
      box_.push_back(p);
    }
    std::size_t rows = 6;
    for (const ClipGroup& g : groups) rows += g.facets->planes.size() * g.points->size();
    filters_.reserve(rows);
    constant_.reserve(rows);
    for (const IntegerPlane3& p : box_)
      filters_.push_back(filter_of(p)), box_wide_.push_back(wide_plane(p)), constant_.push_back(-1);
    // Row 6 + first + i·F + f of a group is (a_f ⊙ p_i)·x <= b_f (F its facets, `first` the
    // rows of the groups before it); its filter copy a~_f ⊙ p~_i, b~_f·2^-e.
    for (const ClipGroup& g : groups) {
      const int nf = static_cast<int>(g.facets->planes.size());
      if (nf == 0 || g.points->empty()) continue;
      groups_.push_back({g.facets, nf, filters_.size() - 6, {}, g.points, {}, g.owner});
      for (const Point3& p : *g.points) add_point(groups_.back(), p);
    }
    rows_.resize(filters_.size());
    std::vector<char> implied(filters_.size(), 0);
    for (const Group& g : groups_) mark_implied(g, implied);
    // Corner (bx, by, bz) is vertex bx + 2by + 4bz; faces counter-clockwise seen from outside.
    vertices_.reserve(384);  // a typical clip's (growing moves every vertex)
    filter_.reserve(384);
    for (int c = 0; c < 8; ++c)
      add_vertex({c & 1 ? 3 : 0, c & 2 ? 4 : 1, c & 4 ? 5 : 2});
    faces_ = {{0, {0, 4, 6, 2}}, {3, {1, 3, 7, 5}}, {1, {0, 1, 5, 4}},
              {4, {2, 6, 7, 3}}, {2, {0, 2, 3, 1}}, {5, {4, 5, 7, 6}}};
    live_ = {0, 1, 2, 3, 4, 5, 6, 7};
    incidence();
    filter_.rebuild(live_);
    // The rows not implied by another (mark_implied), in a fixed pseudo-random order (a
    // multiplicative permutation), then deepest first. The set is the same in any order; the order
    // only decides how many cuts it takes (in point-major order the first point alone gives a copy
    // of G_c3 with all its vertices).
    const std::size_t n = filters_.size() - 6;
    std::size_t step = 2654435761u % (n ? n : 1);
    while (n && std::gcd(step, n) != 1) ++step;
    order_.resize(n);
    std::size_t kept = 0;  // each row written, kept when not implied (no branch: about 2 in 5 are)
    for (std::size_t k = 0, j = 0; k < n; ++k, j = j + step < n ? j + step : j + step - n)  // step < n
      order_[kept] = 6 + j, kept += !implied[6 + j];
    order_.resize(kept);
    deepest_first(box);
  }

  // Sorts order_ by how far each row's plane lies beyond the box's centre c (its filter copy's
  // signed distance (a·c − b)/|a|), largest first, ties in the order they had: rows that cut deep
  // come first, and most later rows then hold on the whole polytope, settled by box_inside or
  // none_outside without a cut. A heuristic in doubles that decides nothing (on the NUS
  // thumbnails, 22% fewer cuts than the pseudo-random order alone; docs/performance-history.md).
  // A row the box's own filter shows to hold on the box (box_inside before the first cut) is
  // left out: every later polytope lies in the box, so the row never cuts, and run() would
  // only have tested it again. The bands are those of every row, so the rows kept are in the
  // order they had among all (a stable sort restricted to them).
  void deepest_first(const Point3& box) {
    double c[3];
    for (int k = 0; k < 3; ++k) c[k] = coord(box, k).get_d() / 2;
    // Each row's distance; a constant row (a = 0) first, one without a filter copy last.
    const std::size_t n = order_.size();
    // Scratch written before it is read, left uninitialised (`new T[n]`, no zeroing pass).
    const std::unique_ptr<double[]> d(new double[n]);
    // kept: positions in order_ of the rows the box does not settle; m how many (each written, kept
    // without a branch).
    const std::unique_ptr<std::uint32_t[]> kept(new std::uint32_t[n]);
    std::size_t m = 0;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (std::size_t k = 0; k < n; ++k) {
      const Filter& f = filters_[order_[k]];
      const double norm = root(f.c[0] * f.c[0] + f.c[1] * f.c[1] + f.c[2] * f.c[2]);
      d[k] = !f.usable ? -HUGE_VAL : norm > 0 ? (f.c[0] * c[0] + f.c[1] * c[1] + f.c[2] * c[2] - f.c[3]) / norm : HUGE_VAL;
      if (std::isfinite(d[k])) lo = std::min(lo, d[k]), hi = std::max(hi, d[k]);
      const bool settled = f.usable ? filter_.box_inside(f.c) : false;
      kept[m] = static_cast<std::uint32_t>(k), m += !settled;
    }
    // A stable sort into `levels` equal bands of distance, deepest band first, each band in the
    // order it had (a comparison sort's mispredicted branches cost more than it gained): band
    // numbers below 2^14, sorted by their low 7 bits, then stably by the high 7 (an LSD radix
    // sort, the same order as one counting pass over every band at a fraction of the counts).
    constexpr std::size_t levels = 4096;
    const double scale = hi > lo ? double(levels - 1) / (hi - lo) : 0;
    const std::unique_ptr<std::uint16_t[]> band(new std::uint16_t[m]);
    for (std::size_t j = 0; j < m; ++j) {
      const double x = d[kept[j]];
      band[j] = x == HUGE_VAL ? 0 : x == -HUGE_VAL || std::isnan(x) ? levels + 1
                : static_cast<std::uint16_t>(1 + std::min(double(levels - 1), std::floor((hi - x) * scale)));
    }
    std::unique_ptr<std::uint32_t[]> index(new std::uint32_t[m]), sorted(new std::uint32_t[m]);
    for (std::size_t j = 0; j < m; ++j) index[j] = static_cast<std::uint32_t>(j);
    for (const int shift : {0, 7}) {
      std::array<std::uint32_t, 129> start{};
      for (std::size_t j = 0; j < m; ++j) ++start[((band[j] >> shift) & 127u) + 1u];
      for (std::size_t b = 0; b + 1 < start.size(); ++b) start[b + 1] += start[b];
      for (std::size_t t = 0; t < m; ++t) sorted[start[(band[index[t]] >> shift) & 127u]++] = index[t];
      index.swap(sorted);
    }
    std::vector<std::size_t> rows(m);
    for (std::size_t j = 0; j < m; ++j) rows[j] = order_[kept[index[j]]];
    order_ = std::move(rows);
    queue_.resize(m);
    for (std::size_t k = 0; k < m; ++k) queue_[k] = filters_[order_[k]];
  }

  // Marks the rows of group g implied by another row of the same facet on x >= 0, which every
  // point of the box satisfies (docs/derivations.md §4.6): for facet a·x <= b and points p, p',
  // (a ⊙ p)·x <= (a ⊙ p')·x for every x >= 0 when s_k·p_k <= s_k·p'_k for each k, s = sign(a);
  // then row p' implies row p. Of points equal in every coordinate where s_k != 0, the first
  // stays. Dropping implied rows leaves the set unchanged.
  void mark_implied(const Group& g, std::vector<char>& implied) const {
    const std::size_t n = g.source->size();
    if (n < 2) return;
    // Each point's rank in each coordinate (equal coordinates, equal ranks), compared exactly: by
    // the coordinates' truncated doubles where both are known and differ (truncation is monotone;
    // certified_double, NaN outside the range policy), else exactly.
    std::vector<std::array<int, 3>> rank(n);
    std::vector<std::array<double, 3>> key(n);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        key[i][static_cast<std::size_t>(k)] =
            numerics::certified_double(coord((*g.source)[i], k).get_mpq_t()).value_or(std::nan(""));
    std::vector<std::size_t> by(n);
    for (int k = 0; k < 3; ++k) {
      auto less = [&](std::size_t i, std::size_t j) {
        const double x = key[i][static_cast<std::size_t>(k)], y = key[j][static_cast<std::size_t>(k)];
        if (x < y || x > y) return x < y;  // both known (a NaN compares false both ways) and different
        return cmp(coord((*g.source)[i], k), coord((*g.source)[j], k)) < 0;
      };
      std::iota(by.begin(), by.end(), std::size_t(0));
      std::sort(by.begin(), by.end(), less);
      int r = 0;
      for (std::size_t t = 0; t < n; ++t) {
        if (t > 0 && less(by[t - 1], by[t])) ++r;
        rank[by[t]][static_cast<std::size_t>(k)] = r;
      }
    }
    std::array<std::vector<char>, 27> dominated;  // per sign pattern of the group's facets
    for (int f = 0; f < g.nf; ++f) {
      const IntegerPlane3& a = g.facets->planes[static_cast<std::size_t>(f)];
      const std::array<int, 3> s{sgn(a.a[0]), sgn(a.a[1]), sgn(a.a[2])};
      std::vector<char>& d = dominated[static_cast<std::size_t>((s[0] + 1) + 3 * (s[1] + 1) + 9 * (s[2] + 1))];
      if (d.empty()) d = dominated_points(rank, s);
      for (std::size_t i = 0; i < n; ++i)  // each row written once (no branch: about 2 in 5 are implied)
        implied[6 + g.first + i * static_cast<std::size_t>(g.nf) + static_cast<std::size_t>(f)] = d[i];
    }
  }

  // Which points are dominated for sign pattern s (ranks as in mark_implied): point i is, when
  // another j has s_k·rank_jk >= s_k·rank_ik for every k, strictly for some k or else j < i. A
  // skyline pass: in decreasing order of Σ s_k·rank_k (ties by index) a point can be dominated
  // only by an earlier one, and then by an earlier undominated one (domination is transitive), so
  // each point is compared with the undominated points so far.
  static std::vector<char> dominated_points(const std::vector<std::array<int, 3>>& rank, const std::array<int, 3>& s) {
    const std::size_t n = rank.size();
    std::vector<std::array<int, 3>> t(n);
    std::vector<std::pair<int, std::size_t>> order(n);  // (−Σ, index)
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < 3; ++k) t[i][k] = s[k] * rank[i][k];
      order[i] = {-(t[i][0] + t[i][1] + t[i][2]), i};
    }
    std::sort(order.begin(), order.end());
    std::vector<char> d(n, 0);
    std::vector<std::size_t> sky;
    for (const auto& [key, i] : order) {
      for (std::size_t j : sky)
        if (t[j][0] >= t[i][0] && t[j][1] >= t[i][1] && t[j][2] >= t[i][2]) {
          d[i] = 1;
          break;
        }
      if (!d[i]) sky.push_back(i);
    }
    return d;
  }

  // Point p's exact form and signs, and its rows' filter copies and constant_row codes, one per
  // facet of the group.
  void add_point(Group& group, const Point3& p) {
    group.points.push_back(homogeneous_integers(p));
    {
      const std::array<mpz_class, 4>& h = group.points.back();
      group.wide.push_back(wide_plane({&h[0], &h[1], &h[2], &h[3]}));
    }
    const ScaledPoint q = scaled_point(p);
    const ClipFacets& facets = *group.facets;
    // A facet copy's non-zero coefficients are in [2^-151, 1) (plane_filter): when q's non-zero
    // channels are at least 2^-48 (all below 1) and its scale within 2^±48, every product is 0 or
    // in [2^-199, 2^48], in range without a test per row.
    bool in_range_always = q.usable && q.scale >= 0x1p-48 && q.scale <= 0x1p48;
    for (int k = 0; k < 3; ++k) in_range_always = in_range_always && (q.c[k] == 0 || std::fabs(q.c[k]) >= 0x1p-48);
    const int s[3] = {sgn(p.x), sgn(p.y), sgn(p.z)};
    for (std::size_t f = 0; f < facets.planes.size(); ++f) {
      const IntegerPlane3& h = facets.planes[f];
      const bool zero = sgn(h.a[0]) * s[0] == 0 && sgn(h.a[1]) * s[1] == 0 && sgn(h.a[2]) * s[2] == 0;
      constant_.push_back(static_cast<signed char>(!zero ? -1 : sgn(h.b) >= 0 ? 1 : 0));
      // Made in place (a copy from the stack read back wider than it was written, a stall per row).
      Filter& r = filters_.emplace_back();
      const std::array<double, 4>& a = facets.filters[f];
      if (q.usable && facets.usable[f]) {
        r.c[0] = a[0] * q.c[0], r.c[1] = a[1] * q.c[1], r.c[2] = a[2] * q.c[2], r.c[3] = a[3] * q.scale;
        r.usable = in_range_always || (filter_range(r.c[0]) && filter_range(r.c[1]) && filter_range(r.c[2]) && filter_range(r.c[3]));
      }
    }
  }

  // True when the k-th row in clipping order holds on a box containing the polytope (its filter
  // copy read from queue_, in order).
  bool box_inside_queued(std::size_t k) const {
    const Filter& f = queue_[k];
    return f.usable && filter_.box_inside(f.c);
  }

  // True when the filter shows no live vertex strictly outside plane i.
  bool none_outside(int i) const {
    const Filter& f = filters_[static_cast<std::size_t>(i)];
    return f.usable && filter_.none_outside(f.c);
  }

  // Row i when a ⊙ p = 0: it reads 0 <= b, true (1) or no map at all (0); otherwise -1 (add_point).
  int constant_row(std::size_t i) const { return constant_[i]; }

  ClippedPolytope run() {
    for (std::size_t k = 0; k < order_.size(); ++k) {
      const std::size_t i = order_[k];
      if (const int c = constant_row(i); c >= 0) {
        if (c == 0) return {ClippedPolytope::Outcome::empty, {}};
        continue;
      }
      if (box_inside_queued(k)) continue;
      const ClippedPolytope::Outcome o = clip(static_cast<int>(i));
      if (o == ClippedPolytope::Outcome::flat && flat_point_ >= 0) return point(k + 1);
      if (o != ClippedPolytope::Outcome::polytope) return {o, {}};
    }
    return {ClippedPolytope::Outcome::polytope, result()};
  }

  // A row left one vertex v of the polytope on it and the others strictly outside: F3 ⊆ {v}, and
  // v satisfies every row so far and, a point of the box, every row deepest_first left out; so F3
  // is {v} if v satisfies the rows from order_[from] on, else empty (each side decided as every
  // other, by the filter or exactly).
  ClippedPolytope point(std::size_t from) {
    Vertex& v = vertices_[static_cast<std::size_t>(flat_point_)];
    for (std::size_t k = from; k < order_.size(); ++k) {
      const std::size_t i = order_[k];
      if (const int c = constant_row(i); c >= 0) {
        if (c == 0) return {ClippedPolytope::Outcome::empty, {}};
        continue;
      }
      if (side(static_cast<int>(i), v) > 0) return {ClippedPolytope::Outcome::empty, {}};
    }
    if (!v.exact) v.exact = std::make_unique<std::array<mpz_class, 4>>(exact_homogeneous(v.planes));
    return {ClippedPolytope::Outcome::polytope,
            LazyConvexSet3::from_homogeneous(ConvexKind3::point, {*v.exact}, {})};
  }

  // The sign of a 3×3 determinant-like value within its filter's bound (filtered_sign.h).
  static numerics::UncertainSign filtered_sign(double value, double bound) {
    // A zero bound means every term was exactly zero (non-negative sums of products of normal
    // numbers vanish only then), so the value is exact: 0 here.
    if (bound == 0 && value == 0) return numerics::UncertainSign::certain(0);
    return numerics::sign_within(value, bound);
  }

  // Plane i's exact coefficients, built on first use.
  const IntegerPlane3& plane(int i) {
    if (i < 6) return box_[static_cast<std::size_t>(i)];
    std::unique_ptr<IntegerPlane3>& row = rows_[static_cast<std::size_t>(i)];
    if (!row) {
      const RowOf r = row_of(static_cast<std::size_t>(i));
      const IntegerPlane3& a = r.group->facets->planes[r.facet];
      const std::array<mpz_class, 4>& q = r.group->points[r.point];
      row = std::make_unique<IntegerPlane3>(IntegerPlane3{
          {mpz_class(a.a[0] * q[0]), mpz_class(a.a[1] * q[1]), mpz_class(a.a[2] * q[2])}, mpz_class(a.b * q[3])});
    }
    return *row;
  }

  std::array<mpz_class, 4> exact_homogeneous(const std::array<int, 3>& t) {
    homogeneous_meet(plane(t[0]), plane(t[1]), plane(t[2]), cross_, homogeneous_);
    return homogeneous_;
  }

  int add_vertex(const std::array<int, 3>& t) {
    Vertex& v = vertices_.emplace_back();  // built in place (moving one moves its exact integers)
    v.planes = t;
    const Filter &p = filters_[t[0]], &q = filters_[t[1]], &r = filters_[t[2]];
    if (p.usable && q.usable && r.usable) {
      // Each of X, Y, Z, W is a sum of six products of three filter coefficients, evaluated with
      // five roundings after the inputs' own (below 6u each): its error is at most 24u times the
      // sum of the products' magnitudes (`perm`, evaluated here with the same care); 32u leaves
      // room (docs/derivations.md §4.6).
      double c[3][3], ca[3][3];  // c_qr, c_rp, c_pq and their magnitudes' versions
      const Filter* s[3][2] = {{&q, &r}, {&r, &p}, {&p, &q}};
      for (int i = 0; i < 3; ++i) {
        const double* x = s[i][0]->c;
        const double* y = s[i][1]->c;
        c[i][0] = x[1] * y[2] - x[2] * y[1], ca[i][0] = std::fabs(x[1] * y[2]) + std::fabs(x[2] * y[1]);
        c[i][1] = x[2] * y[0] - x[0] * y[2], ca[i][1] = std::fabs(x[2] * y[0]) + std::fabs(x[0] * y[2]);
        c[i][2] = x[0] * y[1] - x[1] * y[0], ca[i][2] = std::fabs(x[0] * y[1]) + std::fabs(x[1] * y[0]);
      }
      const double b[3] = {p.c[3], q.c[3], r.c[3]};
      for (int k = 0; k < 3; ++k) {
        v.h[k] = b[0] * c[0][k] + b[1] * c[1][k] + b[2] * c[2][k];
        v.err[k] = numerics::filter_bound::polytope_vertex * (std::fabs(b[0]) * ca[0][k] + std::fabs(b[1]) * ca[1][k] + std::fabs(b[2]) * ca[2][k]);
      }
      v.h[3] = p.c[0] * c[0][0] + p.c[1] * c[0][1] + p.c[2] * c[0][2];
      v.err[3] = numerics::filter_bound::polytope_vertex * (std::fabs(p.c[0]) * ca[0][0] + std::fabs(p.c[1]) * ca[0][1] + std::fabs(p.c[2]) * ca[0][2]);
      const numerics::UncertainSign ws = filtered_sign(v.h[3], v.err[3]);
      if (ws.is_certain()) {
        const int w = ws.lo;
        count(true);
        if (w < 0)
          for (double& x : v.h) x = -x;
        v.filtered = true;
        GMCC_CHECK(w != 0, "clip_polytope: a vertex's three planes are independent");
      }
    }
    if (!v.filtered) {
      count(false);
      v.exact = std::make_unique<std::array<mpz_class, 4>>(exact_homogeneous(t));
      GMCC_CHECK(sgn((*v.exact)[3]) != 0, "clip_polytope: a vertex's three planes are independent");
    }
    v.settle();
    filter_.add(v);
    return static_cast<int>(vertices_.size()) - 1;
  }

  // sign(a·v - b) for plane i and vertex v, exactly.
  int side(int i, Vertex& v) {
    const Filter& f = filters_[i];
    if (f.usable && v.filtered) {
      // s = a·(X, Y, Z) - b·W; with T = Σ|a_k||X_k| + |b||W| and E = Σ|a_k| err_k + |b| err_W,
      // |s~ - s| <= E + (γ4 + 6.1u)(T + E) <= E + 16u(T + E); the bound's own evaluation (sums
      // and products of non-negative numbers) is covered by the factor 1 + 64u.
      const double* a = f.c;
      const double s = a[0] * v.h[0] + a[1] * v.h[1] + a[2] * v.h[2] - a[3] * v.h[3];
      // First the vertex's own bound (VertexDoubles::alpha, beta: E + 16u(T + E) <= max_k |a_k|·α +
      // |b|·β, made once per vertex), as LiveVertexFilter::none_outside reads it, 1 + 128u covering
      // its evaluation (docs/derivations.md §4.6, "The vertex's own bound"): a few operations, and
      // it settles a vertex clear of the plane (most of them).
      const double quick = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}) * (1 + numerics::filter_bound::polytope_quick_evaluation) * v.alpha +
                           std::fabs(a[3]) * (1 + numerics::filter_bound::polytope_quick_evaluation) * v.beta;
      if (s > quick || s < -quick) {
        count(true);
        return s > 0 ? 1 : -1;
      }
      const double T = std::fabs(a[0] * v.h[0]) + std::fabs(a[1] * v.h[1]) + std::fabs(a[2] * v.h[2]) +
                       std::fabs(a[3] * v.h[3]);
      const double E = std::fabs(a[0]) * v.err[0] + std::fabs(a[1]) * v.err[1] +
                       std::fabs(a[2]) * v.err[2] + std::fabs(a[3]) * v.err[3];
      const numerics::UncertainSign filtered = filtered_sign(s, (E + numerics::filter_bound::polytope_side * (T + E)) * (1 + numerics::filter_bound::polytope_side_evaluation));
      if (filtered.is_certain()) {
        const int sign = filtered.lo;
        count(true);
        return sign;
      }
    }
    if (const numerics::UncertainSign known = same_point_side(i, v); known.is_certain()) {
      const int sign = known.lo;
      if (counts_) ++counts_->incident;
      return sign;
    }
    count(false);
    if (!v.exact) v.exact = std::make_unique<std::array<mpz_class, 4>>(exact_homogeneous(v.planes));
    const auto& h = *v.exact;
    const IntegerPlane3& p = plane(i);
    mpz_class& s = side_;  // a·(X, Y, Z) − b·W, in scratch kept across calls
    mpz_mul(s.get_mpz_t(), p.b.get_mpz_t(), h[3].get_mpz_t());
    mpz_neg(s.get_mpz_t(), s.get_mpz_t());
    for (int k = 0; k < 3; ++k) mpz_addmul(s.get_mpz_t(), p.a[k].get_mpz_t(), h[k].get_mpz_t());
    return sgn(s) * sgn(h[3]);
  }

  // Row i's side at v when v is the meet of three rows of i's own image point p whose facets share
  // a point c of ClipFacets::on (docs/derivations.md §4.6, "Rows of one point"): then p has no zero
  // channel (three rows of a point with p_k = 0 have normals with a zero k-th coordinate, dependent),
  // D_p·v = c (three independent planes meet only there), and row (a ⊙ p)·x <= b reads
  // a·(D_p x) <= b: its side at v is c's for the facet, 0 on it, else −1 (c satisfies every facet).
  // Indeterminate when this does not apply.
  numerics::UncertainSign same_point_side(int i, const Vertex& v) const {
    const numerics::UncertainSign unknown = numerics::UncertainSign::indeterminate();
    if (i < 6 || v.planes[0] < 6 || v.planes[1] < 6 || v.planes[2] < 6) return unknown;
    const RowOf r = row_of(static_cast<std::size_t>(i));
    const std::vector<std::vector<std::uint64_t>>& on = r.group->facets->on;
    if (on.empty()) return unknown;
    std::size_t f[3];
    for (int k = 0; k < 3; ++k) {
      const RowOf q = row_of(static_cast<std::size_t>(v.planes[static_cast<std::size_t>(k)]));
      if (q.group != r.group || q.point != r.point) return unknown;
      f[k] = q.facet;
    }
    const std::vector<std::uint64_t>&a = on[f[0]], &b = on[f[1]], &c = on[f[2]], &d = on[r.facet];
    for (std::size_t w = 0; w < a.size(); ++w)
      if (const std::uint64_t m = a[w] & b[w] & c[w]) {
        GMCC_CHECK((m & (m - 1)) == 0, "clip_polytope: a vertex's three planes are independent");
        return numerics::UncertainSign::certain((m & d[w]) != 0 ? 0 : -1);
      }
    return unknown;
  }

  void count(bool filtered) {
    if (counts_) ++(filtered ? counts_->filtered : counts_->exact);
  }

  // Row i cut from the polytope (run() has found that it may not hold on the bounding box).
  ClippedPolytope::Outcome clip(int i) {
    if (none_outside(i)) {
      if (counts_) counts_->filtered += static_cast<long>(live_.size());
      return ClippedPolytope::Outcome::polytope;
    }
    if (sign_.size() < vertices_.size()) sign_.resize(vertices_.size() + 64);
    int in = 0, out = 0;
    removed_.clear(), on_.clear();
    // side()'s first test inline, its row's factors made once (the same operations, the same
    // decisions); side() for the vertices it leaves.
    const Filter& f = filters_[static_cast<std::size_t>(i)];
    const double* a = f.c;
    const double ma = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}) * (1 + 128 * u);
    const double mb = std::fabs(a[3]) * (1 + 128 * u);
    for (int v : live_) {
      Vertex& x = vertices_[static_cast<std::size_t>(v)];
      int s = 2;
      if (f.usable && x.filtered) {
        const double value = a[0] * x.h[0] + a[1] * x.h[1] + a[2] * x.h[2] - a[3] * x.h[3];
        const double quick = ma * x.alpha + mb * x.beta;
        if (value > quick || value < -quick) count(true), s = value > 0 ? 1 : -1;
      }
      if (s == 2) s = side(i, x);
      sign_[v] = s;
      in += s < 0, out += s > 0;
      if (s > 0) removed_.push_back(v);  // the vertices strictly outside (removed by a cut)
      if (s == 0) on_.push_back(v);
    }
    if (out == 0) return ClippedPolytope::Outcome::polytope;  // nothing to cut
    if (in == 0) {
      if (live_.size() == static_cast<std::size_t>(out)) return ClippedPolytope::Outcome::empty;
      if (live_.size() == static_cast<std::size_t>(out) + 1)  // one vertex on the plane: see point()
        for (int v : live_)
          if (sign_[v] == 0) flat_point_ = v;
      return ClippedPolytope::Outcome::flat;
    }
    const std::size_t on = live_.size() - static_cast<std::size_t>(in + out);  // vertices on the plane
    crossing_edges(i, on);
    cut_faces(i, on);
    return ClippedPolytope::Outcome::polytope;
  }

  // An edge (u < w) crossing a plane strictly: it lies on exactly two faces (n counts those
  // found; their indices in faces_), and `vertex` is where their planes meet the plane.
  struct Cut {
    int u, w, faces[2], n, vertex;
    int next;  // the previous cut of the same outside vertex (find_cut's list), or -1
  };

  // Every live vertex's faces, from the faces' cycles.
  void incidence() {
    for (int v : live_) vertices_[static_cast<std::size_t>(v)].degree = 0;
    for (std::size_t f = 0; f < faces_.size(); ++f)
      for (int v : faces_[f].cycle) {
        Vertex& x = vertices_[static_cast<std::size_t>(v)];
        if (x.degree < 0) continue;
        if (x.degree == static_cast<int>(x.faces.size())) x.degree = -1;
        else x.faces[static_cast<std::size_t>(x.degree++)] = static_cast<int>(f);
      }
  }

  // The faces a cut by a plane can change, into visit_: with at most one live vertex on the plane
  // (`on` of them), those through a vertex strictly outside — every vertex of another face is
  // inside or on the plane, so it stays as it is, and it has no edge in the plane (that would need
  // two vertices on it) — when those vertices know their faces; else every face.
  void faces_to_visit(std::size_t on) {
    visit_.clear();
    bool known = on <= 1;
    for (std::size_t k = 0; k < removed_.size() && known; ++k)  // the vertices strictly outside
      known = vertices_[static_cast<std::size_t>(removed_[k])].degree >= 0;
    if (!known) {
      for (std::size_t f = 0; f < faces_.size(); ++f)
        if (!faces_[f].cycle.empty()) visit_.push_back(f);
      return;
    }
    if (stamp_.size() < faces_.size()) stamp_.resize(faces_.size() + 64, 0);
    ++stamp_now_;
    for (int v : removed_) {
      const Vertex& x = vertices_[static_cast<std::size_t>(v)];
      for (int k = 0; k < x.degree; ++k) {
        const auto f = static_cast<std::size_t>(x.faces[static_cast<std::size_t>(k)]);
        if (stamp_[f] != stamp_now_) stamp_[f] = stamp_now_, visit_.push_back(f);
      }
    }
  }
  // The index in cuts_ of the crossing edge {a, b} (one end strictly outside the plane, by sign_),
  // or -1: a walk of the outside end's own cuts (cut_head_, Cut::next), a few.
  int find_cut(int a, int b) const {
    const int o = sign_[a] > 0 ? a : b;
    if (a > b) std::swap(a, b);
    for (int k = cut_head_[static_cast<std::size_t>(o)]; k >= 0; k = cuts_[static_cast<std::size_t>(k)].next)
      if (cuts_[static_cast<std::size_t>(k)].u == a && cuts_[static_cast<std::size_t>(k)].w == b) return k;
    return -1;
  }

  // One pass over every face's edges (sign_ set for the live vertices): the edges that cross
  // plane i strictly, into cuts_, each with its new vertex (the meet of its two faces' planes and
  // plane i, independent because the edge crosses plane i transversally); and into touched_ the
  // faces the cut changes: those with a vertex strictly outside, and those with an edge in the
  // plane (an edge of the cut facet).
  void crossing_edges(int i, std::size_t on) {
    std::vector<Cut>& cuts = cuts_;
    cuts.clear();
    if (cut_head_.size() < vertices_.size()) cut_head_.resize(vertices_.size() + 64, -1);
    touched_.clear();
    faces_to_visit(on);
    for (const std::size_t f : visit_) {
      const Cycle& c = faces_[f].cycle;
      bool outside = false, on = false;
      int a = c.back(), sa = sign_[a];
      for (const int b : c) {
        const int sb = sign_[b];
        outside = outside || sb > 0;
        on = on || (sa == 0 && sb == 0);
        if (sa * sb < 0) {
          const int k = find_cut(a, b);
          if (k < 0) {
            int& head = cut_head_[static_cast<std::size_t>(sa > 0 ? a : b)];
            cuts.push_back({std::min(a, b), std::max(a, b), {static_cast<int>(f), -1}, 1, -1, head});
            head = static_cast<int>(cuts.size()) - 1;
          } else {
            GMCC_CHECK(cuts[k].n == 1, "clip_polytope: an edge lies on two faces");
            cuts[k].faces[1] = static_cast<int>(f), cuts[k].n = 2;
          }
        }
        a = b, sa = sb;
      }
      if (outside || on) touched_.push_back({f, outside});
    }
    if (sign_.size() < vertices_.size() + cuts.size()) sign_.resize(vertices_.size() + cuts.size() + 64);
    for (Cut& c : cuts) {
      GMCC_CHECK(c.n == 2, "clip_polytope: an edge lies on two faces");
      c.vertex = add_vertex({faces_[static_cast<std::size_t>(c.faces[0])].plane,
                             faces_[static_cast<std::size_t>(c.faces[1])].plane, i});
      sign_[c.vertex] = 0;
    }
  }

  // The faces after the cut by plane i (cuts_ and touched_ from crossing_edges): the touched
  // faces with a vertex strictly outside cut (emptied when fewer than three vertices remain: a
  // face no more, its index kept), the others as they are, and the cap, the new facet in plane i,
  // closed from the edges in the plane (each an edge of the cut facet, traversed the other way).
  // The live vertices are those not strictly outside, and the new ones; their faces: a new
  // vertex's are its edge's two and the cap, one strictly inside keeps its own, and one on the
  // plane (`on` of them) gains the cap and may lose a face: all made anew when several were on
  // it, that one's marked unknown when one was.
  void cut_faces(int i, std::size_t on) {
    if (next_on_cap_.size() < vertices_.size()) next_on_cap_.resize(vertices_.size() + 64, -1);
    int cap_edges = 0, cap_start = -1;
    for (const Touched& t : touched_) {
      Cycle& c = faces_[t.face].cycle;
      if (t.outside) {
        scratch_.clear();
        for (std::size_t k = 0; k < c.size(); ++k) {
          const int a = c[k], b = c[k + 1 == c.size() ? 0 : k + 1];
          if (sign_[a] <= 0) scratch_.push_back(a);
          if (sign_[a] * sign_[b] < 0) scratch_.push_back(cuts_[static_cast<std::size_t>(find_cut(a, b))].vertex);
        }
        c.assign(scratch_.begin(), scratch_.end());
        if (c.size() < 3) {
          c.clear();
          continue;
        }
      }
      int a = c.back();
      for (const int b : c) {
        if (sign_[a] == 0 && sign_[b] == 0) {
          GMCC_CHECK(next_on_cap_[b] == -1, "clip_polytope: the cut facet is a simple cycle");
          next_on_cap_[b] = a, ++cap_edges, cap_start = b;
        }
        a = b;
      }
    }
    for (const Cut& c : cuts_) cut_head_[static_cast<std::size_t>(sign_[c.u] > 0 ? c.u : c.w)] = -1;  // lists emptied
    Face cap{i, {}};
    for (int v = cap_start; v != -1 && static_cast<int>(cap.cycle.size()) <= cap_edges &&
                            (cap.cycle.empty() || v != cap_start);
         v = next_on_cap_[v])
      cap.cycle.push_back(v);
    for (const int v : cap.cycle) next_on_cap_[v] = -1;
    GMCC_CHECK(cap.cycle.size() >= 3 && static_cast<int>(cap.cycle.size()) == cap_edges,
               "clip_polytope: a plane with vertices strictly on both sides cuts a facet");
    const int cap_index = static_cast<int>(faces_.size());
    faces_.push_back(std::move(cap));
    // A vertex not strictly outside stays on a face: one strictly inside keeps every face through
    // it, one on the plane is a vertex of the cap.
    added_.clear();
    live_.erase(std::remove_if(live_.begin(), live_.end(), [&](int v) { return sign_[v] > 0; }), live_.end());
    if (on == 1) vertices_[static_cast<std::size_t>(on_[0])].degree = -1;
    for (const Cut& c : cuts_) {
      live_.push_back(c.vertex), added_.push_back(c.vertex);
      Vertex& x = vertices_[static_cast<std::size_t>(c.vertex)];
      x.faces[0] = c.faces[0], x.faces[1] = c.faces[1], x.faces[2] = cap_index, x.degree = 3;
    }
    if (on > 1) incidence();
    filter_.update(live_, removed_, added_);
  }

  // Plane i's double-word copy: a box side's, or a row's from its facet's and point's (a copy:
  // the next call may move the rows' copies).
  std::optional<WidePlane> wide(int i) {
    if (i < 6) return box_wide_[static_cast<std::size_t>(i)];
    int& k = wide_index_[static_cast<std::size_t>(i)];
    if (k < 0) {
      k = static_cast<int>(wides_.size());
      const RowOf r = row_of(static_cast<std::size_t>(i));
      const std::optional<WidePlane>&f = r.group->facets->wide[r.facet], &q = r.group->wide[r.point];
      wides_.push_back(f && q ? wide_row(*f, *q) : std::nullopt);
    }
    return wides_[static_cast<std::size_t>(k)];
  }

  // Vertex v's truncated coordinates from its planes' double-word copies, when decided, the cross
  // products of its pairs of planes shared with the other vertices on the same two planes.
  std::optional<LazyConvexSet3::TruncatedVertex> truncated(const Vertex& v) {
    const std::optional<WidePlane> p = wide(v.planes[0]), q = wide(v.planes[1]), r = wide(v.planes[2]);
    if (!p || !q || !r) return std::nullopt;
    std::array<bool, 3> zero_axis{};  // on the box side x_k >= 0 (plane k): x_k = 0
    for (int t : v.planes)
      if (t < 3) zero_axis[static_cast<std::size_t>(t)] = true;
    const int a = v.planes[0], b = v.planes[1], c = v.planes[2];
    return truncated_meet(*p, *q, *r, shared_cross(b, c, *q, *r), shared_cross(c, a, *r, *p),
                          shared_cross(a, b, *p, *q), zero_axis);
  }

  // An enclosure of a_s × a_u from the planes' double-word copies ws, wu: made once for each pair
  // of planes (as a_min × a_max, its negation, exact, for the other order), kept in a table
  // (open addressing in `cross_slot_`, home slot from the top bits of a multiplicative hash) that
  // result() clears. A final vertex's three pairs of
  // planes are edges of the polytope where the vertex is simple, each shared with the vertex at
  // the edge's other end.
  WideCross shared_cross(int s, int u, const WidePlane& ws, const WidePlane& wu) {
    const bool swap = s > u;
    const std::uint64_t key = swap ? (std::uint64_t(std::uint32_t(u)) << 32 | std::uint32_t(s))
                                   : (std::uint64_t(std::uint32_t(s)) << 32 | std::uint32_t(u));
    const std::size_t mask = cross_slot_.size() - 1;
    std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - cross_bits_)) & mask;
    while (cross_slot_[h].key != key && cross_slot_[h].key != kNoPair) h = (h + 1) & mask;
    CrossSlot& e = cross_slot_[h];
    if (e.key == kNoPair) {
      e.key = key, e.index = crosses_.size();
      crosses_.push_back(swap ? wide_cross(wu, ws) : wide_cross(ws, wu));
    }
    return swap ? negated(crosses_[e.index]) : crosses_[e.index];
  }

  // The same from exact homogeneous coordinates (as LazyConvexSet3::from_homogeneous reads them:
  // the truncated double of each X/W), when every non-zero coordinate is in the range policy's
  // first range (|binary magnitude| <= limit − 1), else nothing.
  static std::optional<LazyConvexSet3::TruncatedVertex> truncated(std::array<mpz_class, 4> h) {
    if (sgn(h[3]) < 0)
      for (mpz_class& c : h) c = -c;
    LazyConvexSet3::TruncatedVertex out{{0, 0, 0}, true};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::optional<double> t = numerics::truncated_double(h[k].get_mpz_t(), h[3].get_mpz_t());
      if (!t) return std::nullopt;
      out.truncated[k] = *t;
      out.zero = out.zero && *t == 0;
    }
    return out;
  }

  // The polytope: vertices kept symbolic (plane triples, truncated coordinates from the planes'
  // double-word copies), each made exact only when asked (plane_meets.h); a vertex whose
  // truncation the copies leave undecided is made exact now. When one lies outside the range
  // policy's first range, every vertex is made exact (from_homogeneous).
  LazyConvexSet3 result() {
    const std::size_t n = live_.size();
    std::vector<int> index(vertices_.size(), -1);
    for (std::size_t j = 0; j < n; ++j) index[static_cast<std::size_t>(live_[j])] = static_cast<int>(j);
    std::vector<std::vector<std::size_t>> faces;
    faces.reserve(faces_.size());
    for (const Face& f : faces_) {
      if (f.cycle.empty()) continue;  // a face cut away
      std::vector<std::size_t> c;
      c.reserve(f.cycle.size());
      for (int v : f.cycle) c.push_back(static_cast<std::size_t>(index[static_cast<std::size_t>(v)]));
      faces.push_back(std::move(c));
    }
    wide_index_.assign(filters_.size(), -1);
    std::size_t slots = 16;
    cross_bits_ = 4;
    while (slots < 6 * n) slots *= 2, ++cross_bits_;  // at most 3n pairs, the table at most half full
    cross_slot_.assign(slots, CrossSlot{});
    crosses_.clear(), crosses_.reserve(3 * n);
    auto meets = std::make_shared<PlaneMeets>();
    meets->meets.resize(n), meets->made.resize(n), meets->planes.reserve(3 * n), meets->rows.reserve(3 * n);
    std::vector<LazyConvexSet3::TruncatedVertex> vertices;
    vertices.reserve(n);
    std::vector<int> local(filters_.size(), -1);
    std::vector<char> lazy(n);
    for (std::size_t j = 0; j < n; ++j) {
      Vertex& x = vertices_[static_cast<std::size_t>(live_[j])];
      std::optional<LazyConvexSet3::TruncatedVertex> t = x.filtered ? truncated(x) : std::nullopt;
      lazy[j] = t.has_value();
      if (!t) {
        if (!x.exact) x.exact = std::make_unique<std::array<mpz_class, 4>>(exact_homogeneous(x.planes));
        if (!(t = truncated(*x.exact))) return exact_result(std::move(faces));
        // A copy: a later vertex out of range sends every vertex to exact_result, which reads
        // this one's x.exact again (a moved-from one would read W = 0).
        meets->made[j] = *x.exact;
      }
      vertices.push_back(*t);
    }
    // The lazy vertices' planes (the clip reads no row after this: its rows and points move).
    std::vector<std::size_t> points_at(groups_.size(), none);  // a group's first point in meets->points
    for (std::size_t j = 0; j < n; ++j) {
      if (!lazy[j]) continue;
      const Vertex& x = vertices_[static_cast<std::size_t>(live_[j])];
      for (std::size_t k = 0; k < 3; ++k) {
        int& l = local[static_cast<std::size_t>(x.planes[k])];
        if (l < 0) {
          l = static_cast<int>(meets->planes.size());
          meets->planes.emplace_back(), meets->rows.emplace_back();
          keep_plane(x.planes[k], *meets, points_at);
        }
        meets->meets[j][k] = l;
      }
    }
    return LazyConvexSet3::from_truncated(ConvexKind3::polytope, std::move(vertices), std::move(faces),
                                          [meets](std::size_t i) { return meets->homogeneous(i); });
  }

  // Plane i as meets' last plane: a box side's or a row made exactly during the clip, moved; a row
  // of a group with an owner, as its facet and point (the group's points moved into meets once,
  // points_at[g] their first index there), made only when a vertex asks (PlaneMeets::plane);
  // another row made now.
  void keep_plane(int i, PlaneMeets& meets, std::vector<std::size_t>& points_at) {
    IntegerPlane3& out = meets.planes.back();
    if (i < 6) {
      out = box_[static_cast<std::size_t>(i)];
      return;
    }
    std::unique_ptr<IntegerPlane3>& row = rows_[static_cast<std::size_t>(i)];
    const RowOf r = row_of(static_cast<std::size_t>(i));
    if (row || !r.group->owner) {
      plane(i);
      out = std::move(*row);
      return;
    }
    std::size_t& first = points_at[static_cast<std::size_t>(r.group - groups_.data())];
    if (first == none) {
      Group& g = groups_[static_cast<std::size_t>(r.group - groups_.data())];
      first = meets.points.size();
      meets.points.insert(meets.points.end(), std::make_move_iterator(g.points.begin()),
                          std::make_move_iterator(g.points.end()));
      meets.owners.push_back(g.owner);
    }
    meets.rows.back() = {&r.group->facets->planes[r.facet], first + r.point};
  }

  // The polytope with every vertex exact (faces indexed by position in live_).
  LazyConvexSet3 exact_result(std::vector<std::vector<std::size_t>> faces) {
    std::vector<std::array<mpz_class, 4>> points;
    for (int v : live_) {
      Vertex& x = vertices_[static_cast<std::size_t>(v)];
      if (!x.exact) x.exact = std::make_unique<std::array<mpz_class, 4>>(exact_homogeneous(x.planes));
      points.push_back(*x.exact);
    }
    return LazyConvexSet3::from_homogeneous(ConvexKind3::polytope, std::move(points), std::move(faces));
  }

  struct Face {
    int plane;
    Cycle cycle;
  };
  // Row i >= 6: its group, facet and point.
  struct RowOf {
    const Group* group;
    std::size_t facet, point;
  };
  RowOf row_of(std::size_t i) const {
    std::size_t g = groups_.size() - 1;
    while (groups_[g].first > i - 6) --g;
    const std::size_t k = i - 6 - groups_[g].first, nf = static_cast<std::size_t>(groups_[g].nf);
    return {&groups_[g], k % nf, k / nf};
  }
  ClipCounts* counts_;
  std::vector<Group> groups_;
  std::vector<IntegerPlane3> box_;
  std::vector<Filter> filters_;                   // every plane's, box first
  std::vector<signed char> constant_;             // every plane's constant_row
  std::vector<std::unique_ptr<IntegerPlane3>> rows_;  // exact rows, on demand
  std::vector<Vertex> vertices_;
  std::vector<Face> faces_;
  std::vector<int> live_;
  std::vector<Cut> cuts_;        // scratch for clip(): the crossing edges
  std::vector<int> cut_head_;    // per vertex: its last cut in cuts_ while it is outside (-1 otherwise)
  int flat_point_ = -1;          // the one vertex a flat row left (clip()), if it left one
  struct Touched {
    std::size_t face;
    bool outside;  // it has a vertex strictly outside the cutting plane
  };
  std::vector<Touched> touched_;  // scratch for clip(): the faces a cut changes
  std::vector<std::size_t> visit_;  // scratch for faces_to_visit
  std::vector<unsigned> stamp_;     // faces_to_visit: the last cut that listed each face
  unsigned stamp_now_ = 0;
  std::vector<int> scratch_;      // scratch for cut_faces: a cut face's new cycle
  std::vector<int> next_on_cap_;  // scratch for cut_faces (-1 between cuts)
  LiveVertexFilter filter_;             // the live vertices' (after every cut)
  std::vector<int> removed_, on_, added_;  // scratch for clip: the live vertices strictly outside the
                                           // row and on it; the vertices a cut made
  std::vector<std::size_t> order_;  // the rows, in clipping order
  std::vector<Filter> queue_;       // their filter copies, in that order
  std::vector<int> sign_;
  std::array<std::array<mpz_class, 3>, 3> cross_;  // scratch for exact_homogeneous
  std::vector<std::optional<WidePlane>> box_wide_;    // the box sides' double-word copies
  std::vector<int> wide_index_;                        // wide(): each row's index in wides_, or -1
  std::vector<std::optional<WidePlane>> wides_;        // wide(): the rows' copies made so far
  static constexpr std::uint64_t kNoPair = ~std::uint64_t(0);
  struct CrossSlot {
    std::uint64_t key = kNoPair;  // the pair of planes (lower << 32 | higher), or none
    std::size_t index = 0;        // its cross product in crosses_
  };
  std::vector<CrossSlot> cross_slot_;  // shared_cross(): the table of pairs of planes
  unsigned cross_bits_ = 4;            // log2 of its size
  std::vector<WideCross> crosses_;     // shared_cross(): their cross products
  std::array<mpz_class, 4> homogeneous_;           // scratch for exact_homogeneous
  mpz_class side_;                                  // scratch for side
};

}  // namespace

std::optional<std::array<double, 4>> plane_filter(const IntegerPlane3& p) {
  const mpz_class* z[4] = {&p.a[0], &p.a[1], &p.a[2], &p.b};
  double m[4];
  long e[4];
  long top = 0;
  bool any = false;
  for (int k = 0; k < 4; ++k) {
    m[k] = mpz_get_d_2exp(&e[k], z[k]->get_mpz_t());
    if (m[k] != 0) top = any ? std::max(top, e[k]) : e[k], any = true;
  }
  std::array<double, 4> c{};
  for (int k = 0; k < 4; ++k) {
    if (m[k] == 0) continue;
    if (e[k] - top < -150) return std::nullopt;
    c[static_cast<std::size_t>(k)] = std::ldexp(m[k], static_cast<int>(e[k] - top));
  }
  return c;
}

ClipFacets clip_facets(std::vector<IntegerPlane3> planes, const std::vector<Point3>& vertices) {
  ClipFacets out;
  // Each point's doubles (certified_double: within 2u, in the range policy) where they exist, and
  // its exact homogeneous integers (X, Y, Z, L), L > 0, made when a side needs them.
  std::vector<std::array<double, 3>> d(vertices.size());
  std::vector<char> filtered(vertices.size(), 1);
  for (std::size_t j = 0; j < vertices.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      const std::optional<double> x = numerics::certified_double(coord(vertices[j], k).get_mpq_t());
      if (x) d[j][static_cast<std::size_t>(k)] = *x;
      else filtered[j] = 0;
    }
  std::vector<std::optional<std::array<mpz_class, 4>>> h(vertices.size());
  mpz_class side;
  for (const IntegerPlane3& p : planes) {
    const Filter f = filter_of(p);
    out.filters.push_back({f.c[0], f.c[1], f.c[2], f.c[3]});
    out.usable.push_back(f.usable);
    out.wide.push_back(wide_plane(p));
    if (vertices.empty()) continue;
    std::vector<std::uint64_t>& on = out.on.emplace_back((vertices.size() + 63) / 64, 0);
    for (std::size_t j = 0; j < vertices.size(); ++j) {
      // Strictly inside by the filter (the image-hull prefilter's model, docs/derivations.md §4.6:
      // s = a·p − b within 16u·T of s~): most points of a facet's gamut are.
      if (f.usable && filtered[j]) {
        const double s = f.c[0] * d[j][0] + f.c[1] * d[j][1] + f.c[2] * d[j][2] - f.c[3];
        const double T = std::fabs(f.c[0] * d[j][0]) + std::fabs(f.c[1] * d[j][1]) + std::fabs(f.c[2] * d[j][2]) +
                         std::fabs(f.c[3]);
        if (s < -16 * u * T) continue;
      }
      if (!h[j]) h[j] = homogeneous_integers(vertices[j]);
      const std::array<mpz_class, 4>& x = *h[j];
      side = p.a[0] * x[0] + p.a[1] * x[1] + p.a[2] * x[2] - p.b * x[3];  // sign(a·X − b·L), exactly
      if (sgn(side) > 0) throw std::invalid_argument("clip_facets: a point outside a half-space");
      if (sgn(side) == 0) on[j / 64] |= std::uint64_t(1) << (j % 64);
    }
  }
  out.planes = std::move(planes);
  return out;
}

ClippedPolytope clip_polytope(const Point3& box, const ClipFacets& facets, const std::vector<Point3>& points,
                              ClipCounts* counts) {
  return Clipper(box, {{&facets, &points}}, counts).run();
}

ClippedPolytope clip_polytope(const Point3& box, const std::vector<ClipGroup>& groups, ClipCounts* counts) {
  return Clipper(box, groups, counts).run();
}

ClippedPolytope clip_polytope(const Point3& box, const std::vector<IntegerPlane3>& planes, ClipCounts* counts) {
  const ClipFacets facets = clip_facets(planes);
  return clip_polytope(box, facets, {Point3{1, 1, 1}}, counts);
}

}  // namespace gmcc::internal
