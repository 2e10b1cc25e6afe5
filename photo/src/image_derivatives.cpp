#include <gmcc/photo/image_derivatives.h>

#include <gmcc/numerics/interrupt.h>

#include "internal/clamped_convolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace gmcc {
namespace {

// The sampled kernel of `order` at scale σ on [−r, r], normalised as image_derivatives.h says.
std::vector<double> kernel(double sigma, int order) {
  const int r = static_cast<int>(std::ceil(3 * sigma));
  std::vector<double> g(static_cast<std::size_t>(2 * r + 1));
  double sum = 0;
  // x = 0 apart: for σ below about 1e-154, σ² is 0 and 0/0 would make the centre NaN.
  for (int x = -r; x <= r; ++x) sum += g[static_cast<std::size_t>(x + r)] = x == 0 ? 1.0 : std::exp(-0.5 * x * x / (sigma * sigma));
  for (double& v : g) v /= sum;
  if (order == 0) return g;
  std::vector<double> k(g.size());
  if (order == 1) {
    double moment = 0;
    for (int x = -r; x <= r; ++x) moment += x * (k[static_cast<std::size_t>(x + r)] = -x * g[static_cast<std::size_t>(x + r)]);
    // Below σ ≈ 0.026 the tails g(±1) underflow to 0 and so does the moment: the kernel is then
    // its limit as σ → 0, which the normalisation makes the central difference (±1/2 at ∓1).
    if (moment == 0)
      for (int x = -r; x <= r; ++x) k[static_cast<std::size_t>(x + r)] = x == -1 ? 0.5 : x == 1 ? -0.5 : 0.0;
    else
      for (double& v : k) v /= -moment;  // Σ x·k(x) = −1
    return k;
  }
  double mean = 0;
  for (int x = -r; x <= r; ++x)
    mean += k[static_cast<std::size_t>(x + r)] =
        g[static_cast<std::size_t>(x + r)] == 0 ? 0.0
        : x == 0                              ? -g[static_cast<std::size_t>(x + r)]  // 0/σ² is NaN once σ² underflows
                                              : (x * x / (sigma * sigma) - 1) * g[static_cast<std::size_t>(x + r)];
  mean /= static_cast<double>(k.size());
  double moment = 0;
  for (int x = -r; x <= r; ++x) {
    double& v = k[static_cast<std::size_t>(x + r)];
    v -= mean;
    moment += 0.5 * x * x * v;
  }
  for (double& v : k) v /= moment;  // Σ x²/2·k(x) = 1: a parabola's curvature exactly
  return k;
}

// out[i] = (…((0 + k[0]·in[0][i]) + k[1]·in[1][i]) + …) + k[m−1]·in[m−1][i] for i < n: each
// product rounded, then each sum, in the order of the terms (a convolution's sum term by term),
// for K kernels k[j] over the same terms at once into out[j]: each term read once for all K.
// 4·lanes outputs of each kernel at a time, their partial sums held in registers while the terms
// stream past.
template <long K, long lanes>
inline __attribute__((always_inline)) void sums_of(const double* const* k, const double* const* in, long m,
                                                   double* const* out, long n) {
  typedef double Four __attribute__((vector_size(32)));
  // A store to out: unaligned, and of the alias set of double (as GCC's own __m256d_u).
  typedef double UnalignedFour __attribute__((vector_size(32), aligned(8), __may_alias__));
  long i = 0;
  for (; i + 4 * lanes <= n; i += 4 * lanes) {
    Four sum[K][lanes];
    for (long j = 0; j < K; ++j)
      for (long l = 0; l < lanes; ++l) sum[j][l] = Four{0.0, 0.0, 0.0, 0.0};
    for (long t = 0; t < m; ++t) {
      Four kt[K];
      for (long j = 0; j < K; ++j) kt[j] = Four{k[j][t], k[j][t], k[j][t], k[j][t]};
      const double* p = in[t] + i;
      for (long l = 0; l < lanes; ++l) {
        Four x;
        std::memcpy(&x, p + 4 * l, sizeof x);
        for (long j = 0; j < K; ++j) sum[j][l] += kt[j] * x;
      }
    }
    // Each register stored whole: a copy through memory read back in halves stalled.
    for (long j = 0; j < K; ++j)
      for (long l = 0; l < lanes; ++l) *reinterpret_cast<UnalignedFour*>(out[j] + i + 4 * l) = sum[j][l];
  }
  for (; i < n; ++i)
    for (long j = 0; j < K; ++j) {
      double sum = 0.0;
      for (long t = 0; t < m; ++t) sum += k[j][t] * in[t][i];
      out[j][i] = sum;
    }
}

// sums_of for `count` kernels, three at a time. On x86-64 ELF with GCC it is compiled twice and the
// loader picks the clone the processor supports (as GMCC_DW_FMA_CLONES, numerics/internal): the
// AVX2 clone makes the same operations four at a time, with no fused multiply-add (AVX2 does not
// enable FMA), so the same bytes.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void weighted_sums(const double* const* k, long count, const double* const* in, long m, double* const* out, long n) {
  for (long first = 0; first < count; first += 3) {
    const long left = count - first;
    if (left == 1) sums_of<1, 8>(k + first, in, m, out + first, n);
    else if (left == 2) sums_of<2, 4>(k + first, in, m, out + first, n);
    else sums_of<3, 4>(k + first, in, m, out + first, n);
  }
}

// The image's rows as doubles: the linear image of an RgbImage (black level removed, clamped at
// 0: exact) or a DoubleImage's own samples.
struct LinearRows {
  const RgbImage& image;
  std::uint32_t black;
  void operator()(std::size_t y, double* out) const {
    const std::size_t n = 3 * image.width, first = y * n;
    for (std::size_t i = 0; i < n; ++i) out[i] = double(std::max<std::uint32_t>(image.samples[first + i], black) - black);
  }
  bool same(std::size_t i, std::size_t j) const {  // linear samples i and j equal
    const auto level = [&](std::uint32_t v) { return v > black ? v - black : 0u; };
    return level(image.samples[i]) == level(image.samples[j]);
  }
};
struct DoubleRows {
  const DoubleImage& image;
  void operator()(std::size_t y, double* out) const {
    const std::size_t n = 3 * image.width;
    std::copy(image.samples.begin() + static_cast<long>(y * n), image.samples.begin() + static_cast<long>((y + 1) * n), out);
  }
  bool same(std::size_t i, std::size_t j) const { return image.samples[i] == image.samples[j]; }
};

// The separable passes along x of several kernels (all of radius r), each kept for the rows the
// passes along y need: a ring of `slots` rows (at least min(h, 2r + 1)), row y in slot y mod
// slots. Rows are made in increasing order, each source row converted once; the edge is
// replicated. Directly (the sums term by term) up to radius kFftMinRadius, by FFT above it.
template <class Source>
class XPasses {
 public:
  // The rings in `storage` when given (each at least slots·3w values; their contents are
  // overwritten before they are read), else in the object's own.
  XPasses(const Source& source, std::size_t w, std::vector<const std::vector<double>*> kernels, long slots,
          std::vector<std::vector<double>>* storage = nullptr)
      : source_(source), kernels_(std::move(kernels)), w_(static_cast<long>(w)),
        r_(static_cast<long>(kernels_.front()->size() / 2)), slots_(slots), in_(3 * w),
        rings_(storage ? *storage : own_rings_) {
    // along_x() holds the kernels in arrays of three: g, d1 and d2 at most (sweep_plan).
    if (kernels_.size() > 3) throw std::logic_error("at most three kernels along x");
    if (!storage) own_rings_.assign(kernels_.size(), std::vector<double>(static_cast<std::size_t>(slots_) * 3 * w));
    if (r_ >= internal::kFftMinRadius && w > 0) {  // a row of no pixels has nothing to transform
      fft_.emplace(kernels_, w);
      z_.resize(fft_->size()), t_.resize(fft_->size());
    }
  }
  // Rows 0 to `last` made.
  void make_to(long last) {
    for (; next_ <= last; ++next_) {
      // A row costs 3·w·(2r + 1) products per kernel directly, at most a few milliseconds (σ = 64
      // on a 16,000-pixel row): Ctrl-C in the Python module is answered within that at any σ.
      check_interrupt();
      source_(static_cast<std::size_t>(next_), in_.data());
      if (fft_) {
        along_x_fft();
        continue;
      }
      along_x();
    }
  }
  // Kernel k's pass along x at row y (made, and within the last `slots` made).
  const double* row(std::size_t k, long y) const { return rings_[k].data() + (y % slots_) * 3 * w_; }
  long radius() const { return r_; }

 private:
  double* slot(std::size_t k, long y) { return rings_[k].data() + (y % slots_) * 3 * w_; }
  // Every kernel along the source row in_ into its slot of row next_: per value, Σ_t k(t)·in(x − t)
  // with t from −r to r in that order, x − t clamped (the edge replicated): the columns whose
  // terms all lie inside the row by weighted_sums (each term read once for every kernel), the r
  // at each end one by one.
  void along_x() {
    const long inner_first = std::min(r_, w_), inner_end = std::max(inner_first, w_ - r_);
    const double* k[3];  // at most g, d1 and d2 (sweep_plan)
    double* out[3];
    for (std::size_t j = 0; j < kernels_.size(); ++j) {
      k[j] = kernels_[j]->data(), out[j] = slot(j, next_);
      const auto one = [&](long x) {
        for (long c = 0; c < 3; ++c) {
          double sum = 0.0;
          for (long t = -r_; t <= r_; ++t)
            sum += k[j][t + r_] * in_[static_cast<std::size_t>(3 * std::min(std::max(x - t, 0L), w_ - 1) + c)];
          out[j][3 * x + c] = sum;
        }
      };
      for (long x = 0; x < inner_first; ++x) one(x);
      for (long x = inner_end; x < w_; ++x) one(x);
    }
    if (inner_end > inner_first) {
      for (long t = -r_; t <= r_; ++t) terms_[static_cast<std::size_t>(t + r_)] = in_.data() + 3 * (inner_first - t);
      for (std::size_t j = 0; j < kernels_.size(); ++j) out[j] += 3 * inner_first;
      weighted_sums(k, static_cast<long>(kernels_.size()), terms_.data(), 2 * r_ + 1, out, 3 * (inner_end - inner_first));
    }
  }
  // Every kernel along in_ by FFT (clamped_convolution.h): channels r and g as one complex
  // sequence, then b alone.
  void along_x_fft() {
    for (long pair = 0; pair < 2; ++pair) {
      std::fill(z_.begin(), z_.end(), std::complex<double>());
      for (long m = 0; m < w_ + 2 * r_; ++m) {
        const long x = std::min(std::max(m - r_, 0L), w_ - 1);
        z_[static_cast<std::size_t>(m)] = {in_[static_cast<std::size_t>(3 * x + 2 * pair)],
                                           pair == 0 ? in_[static_cast<std::size_t>(3 * x + 1)] : 0.0};
      }
      fft_->transform(z_.data());
      for (std::size_t k = 0; k < kernels_.size(); ++k) {
        fft_->apply(k, z_.data(), t_.data());
        double* out = slot(k, next_);
        for (long x = 0; x < w_; ++x) {
          const std::complex<double>& v = t_[static_cast<std::size_t>(x + 2 * r_)];
          out[3 * x + 2 * pair] = v.real();
          if (pair == 0) out[3 * x + 1] = v.imag();
        }
      }
    }
  }

  const Source& source_;
  std::vector<const std::vector<double>*> kernels_;
  long w_, r_, slots_, next_ = 0;
  std::vector<double> in_;
  mutable std::vector<const double*> terms_ = std::vector<const double*>(2 * static_cast<std::size_t>(r_) + 1);  // along_x's rows of terms
  std::vector<std::vector<double>> own_rings_;
  std::vector<std::vector<double>>& rings_;
  std::optional<internal::ClampedFftConvolution> fft_;  // above kFftMinRadius
  std::vector<std::complex<double>> z_, t_;
};

// The passes along y: per result, the pass along x it reads and its kernel.
struct YPass {
  std::size_t along_x;
  const std::vector<double>* kernel;
};

// The passes along y `group` (indices into `passes`, all over the same pass along x) at row y,
// each into its results (3·w values): per value, Σ_t k(t)·row(y − t) with t from −r to r in that
// order, y − t clamped; each row's terms read once for every pass of the group.
template <class Source>
void y_passes(const XPasses<Source>& x, const std::vector<YPass>& passes, const std::vector<std::size_t>& group, long y,
              long w, long h, std::vector<std::vector<double>>& results) {
  const long r = x.radius();
  std::vector<const double*> rows(static_cast<std::size_t>(2 * r + 1));
  for (long t = -r; t <= r; ++t)
    rows[static_cast<std::size_t>(t + r)] = x.row(passes[group.front()].along_x, std::min(std::max(y - t, 0L), h - 1));
  for (std::size_t first = 0; first < group.size(); first += 3) {
    const double* k[3];
    double* out[3];
    const std::size_t count = std::min<std::size_t>(3, group.size() - first);
    for (std::size_t j = 0; j < count; ++j)
      k[j] = passes[group[first + j]].kernel->data(), out[j] = results[group[first + j]].data();
    weighted_sums(k, static_cast<long>(count), rows.data(), 2 * r + 1, out, 3 * w);
  }
}

// The channels constant over the whole image (their derivatives are exactly 0).
template <class Source>
std::array<bool, 3> flat_channels(const Source& source, std::size_t samples) {
  std::array<bool, 3> flat{true, true, true};
  for (std::size_t i = 3; i < samples && (flat[0] || flat[1] || flat[2]); i += 3)  // until none is flat
    for (std::size_t c = 0; c < 3; ++c) flat[c] = flat[c] && source.same(i + c, c);
  return flat;
}

// sqrt(a² + 4c² + b²) (c = 0: the gradient's magnitude), as written; where the sum of squares
// leaves the doubles' normal range (derivatives of about 1e-154 or less, which the Gaussian's
// tails give at σ below about 0.1), from the values scaled by the largest first, so that a
// non-zero derivative never has magnitude 0 (fuzz_edge_colours' finding).
double magnitude(double a, double b, double c, double squares) {
  if (squares >= 0x1p-1000 || (a == 0 && b == 0 && c == 0)) return std::sqrt(squares);
  const double m = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
  a /= m, b /= m, c /= m;
  return m * std::sqrt(a * a + 4 * c * c + b * b);
}

// The orders a sweep makes, each from the passes along y it combines (indices into the sweep's
// YPass list: f_σ; f_x, f_y; or f_xx, f_yy, f_xy).
struct OrderPasses {
  DerivativeOrder order;
  std::vector<std::size_t> passes;
};

// What one sweep hands on per row: each order's values (3·w), null for an order not asked.
using OrderRows = std::array<const double*, 3>;

// Whether a square root `root` (+0 or more, −0 or NaN) may be at most 2^-500 while a, b or c is
// not 0: a root of an exact 0 needs no second look (magnitude() gives the same 0), and flat
// regions of a photograph give many. The root is compared by its bits as a signed integer, which
// orders non-negative doubles as their values do, with no branch; a −0 or a NaN with its sign bit
// set counts, a NaN without it does not: the caller tests each value again.
inline std::int64_t small_root(double root, double a, double b, double c) {
  const std::int64_t bound = 0x20b0000000000000;  // the bits of 2^-500: biased exponent 1023 − 500
  std::int64_t bits;
  std::memcpy(&bits, &root, sizeof bits);
  return (bits <= bound) & ((a != 0) | (b != 0) | (c != 0));
}

// out[i] = sqrt(a[i]² + 4c[i]² + b[i]²) (c null: sqrt(a[i]² + b[i]²)), as magnitude() writes them,
// for i < n, and whether some out[i] is a small_root (the values a[i], b[i], c[i]): a correctly
// rounded square root, so the clones (as weighted_sums') give the same bytes; the sums are
// non-negative, so no errno is ever due (this file is compiled without errno for the math
// functions, photo/CMakeLists.txt: the roots are then vector instructions, and the test on each
// root with them, without a second pass).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
bool root_sum_squares(const double* a, const double* b, const double* c, double* out, std::size_t n) {
  std::int64_t any = 0;
  if (c)
    for (std::size_t i = 0; i < n; ++i) {
      const double root = std::sqrt(a[i] * a[i] + 4 * c[i] * c[i] + b[i] * b[i]);
      out[i] = root;
      any |= small_root(root, a[i], b[i], c[i]);
    }
  else
    for (std::size_t i = 0; i < n; ++i) {
      const double root = std::sqrt(a[i] * a[i] + b[i] * b[i]);
      out[i] = root;
      any |= small_root(root, a[i], b[i], 0.0);
    }
  return any != 0;
}

// magnitude() where it may differ from the root already made: a root at most 2^-500 of values not
// all 0.
bool needs_magnitude(double root, double a, double b, double c) { return root <= 0x1p-500 && (a != 0 || b != 0 || c != 0); }

// One row of results (each 3·w values: f_σ; f_x, f_y; or f_xx, f_yy, f_xy) into out: f_σ, or the
// magnitudes, 0 in the flat channels. The magnitudes are the square roots of the sums of squares
// for all first, then magnitude() where a root is at most 2^-500 and the values are not all 0 (a
// superset of the sums below 2^-1000 it treats apart: the root is monotone and 2^-500 exact; for
// values all 0 it gives the root's 0).
void combine(DerivativeOrder order, const double* const* v, const std::array<bool, 3>& flat, std::vector<double>& out) {
  const double *a = v[0], *b = v[1], *c = order == DerivativeOrder::second ? v[2] : nullptr;
  if (order == DerivativeOrder::zero) {
    std::copy(a, a + out.size(), out.begin());
    return;
  }
  const bool any_small = root_sum_squares(a, b, c, out.data(), out.size());
  const std::array<bool, 3> is_flat = flat;
  if (any_small)
    for (std::size_t first = 0; first < out.size(); first += 3)
      for (std::size_t i = first; i < first + 3; ++i)
        if (!is_flat[i - first] && needs_magnitude(out[i], a[i], b[i], c ? c[i] : 0))
          out[i] = c ? magnitude(a[i], b[i], c[i], a[i] * a[i] + 4 * c[i] * c[i] + b[i] * b[i])
                     : magnitude(a[i], b[i], 0, a[i] * a[i] + b[i] * b[i]);
  if (is_flat[0] || is_flat[1] || is_flat[2])
    for (std::size_t first = 0; first < out.size(); first += 3)
      for (std::size_t k = 0; k < 3; ++k)
        if (is_flat[k]) out[first + k] = 0.0;
}

// Each order's row from the passes' rows `results` (each 3·w values at `offset`), handed to `row`.
struct Combiner {
  const std::vector<OrderPasses>& orders;
  const std::array<bool, 3>& flat;
  std::vector<std::vector<double>> out;  // per order, 3·w
  Combiner(const std::vector<OrderPasses>& o, const std::array<bool, 3>& f, long w)
      : orders(o), flat(f), out(o.size(), std::vector<double>(static_cast<std::size_t>(3 * w))) {}
  void operator()(const std::vector<std::vector<double>>& results, long offset, std::size_t y,
                  const std::function<void(std::size_t, const OrderRows&)>& row) {
    OrderRows rows{nullptr, nullptr, nullptr};
    for (std::size_t k = 0; k < orders.size(); ++k) {
      const double* v[3] = {nullptr, nullptr, nullptr};
      for (std::size_t p = 0; p < orders[k].passes.size(); ++p) v[p] = results[orders[k].passes[p]].data() + offset;
      for (std::size_t p = orders[k].passes.size(); p < 3; ++p) v[p] = v[0];
      combine(orders[k].order, v, flat, out[k]);
      rows[static_cast<std::size_t>(orders[k].order)] = out[k].data();
    }
    row(y, rows);
  }
};

// The direct route: each row's passes along y as sums over the ring of 2r + 1 rows along x.
template <class Source>
void direct_rows(const Source& source, long w, long h, const std::vector<const std::vector<double>*>& along_x,
                 const std::vector<YPass>& passes, Combiner& combiner,
                 const std::function<void(std::size_t, const OrderRows&)>& row) {
  XPasses<Source> x(source, static_cast<std::size_t>(w), along_x,
                    std::min<long>(h, 2 * static_cast<long>(along_x.front()->size() / 2) + 1));
  std::vector<std::vector<double>> results(passes.size(), std::vector<double>(static_cast<std::size_t>(3 * w)));
  std::vector<std::vector<std::size_t>> groups(along_x.size());  // the passes along y by the pass along x they read
  for (std::size_t p = 0; p < passes.size(); ++p) groups[passes[p].along_x].push_back(p);
  for (long y = 0; y < h; ++y) {
    x.make_to(std::min(h - 1, y + x.radius()));
    check_interrupt();
    for (const std::vector<std::size_t>& group : groups)
      if (!group.empty()) y_passes(x, passes, group, y, w, h, results);
    combiner(results, 0, static_cast<std::size_t>(y), row);
  }
}

// The FFT route's rings and results: kept by the thread from one call to the next while they
// fit in 8 MiB together (images up to about 180 × 180 at σ = 16; more are made afresh each call),
// so that a dataset of small images does not fault the same pages in anew for every image and
// order (a third of the σ = 16 derivatives' time on 128 × 128 images; docs/performance-history.md
// "Edge and n-jet methods, fifth round"). Every value is written before it is read; one user at a
// time (a nested call gets its own). A buffer kept grows to the largest a call asked of it, so
// calls of different shapes could leave more than 8 MiB: the kept set is freed when a call finds it
// beyond 8 MiB, so that a thread keeps at most twice that.
class KeptBuffers {
 public:
  explicit KeptBuffers(std::size_t doubles) {
    static thread_local std::array<std::vector<std::vector<double>>, 2> kept;
    static thread_local bool busy = false;
    constexpr std::size_t limit = (std::size_t(8) << 20) / sizeof(double);
    if (doubles > limit || busy) {
      sets_ = &own_;
      return;
    }
    std::size_t held = 0;
    for (const auto& set : kept)
      for (const std::vector<double>& b : set) held += b.capacity();
    if (held > limit) kept = {};
    sets_ = &kept, busy_ = &busy, busy = true;
  }
  ~KeptBuffers() {
    if (busy_) *busy_ = false;
  }
  KeptBuffers(const KeptBuffers&) = delete;
  KeptBuffers& operator=(const KeptBuffers&) = delete;
  // Set `which` (0 or 1) as `count` buffers of at least `size` values each.
  std::vector<std::vector<double>>& buffers(std::size_t which, std::size_t count, std::size_t size) {
    std::vector<std::vector<double>>& b = (*sets_)[which];
    if (b.size() < count) b.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      if (b[i].size() < size) b[i].resize(size);
    return b;
  }

 private:
  std::array<std::vector<std::vector<double>>, 2> own_;
  std::array<std::vector<std::vector<double>>, 2>* sets_;
  bool* busy_ = nullptr;
};

// The FFT route (clamped_convolution.h): rows in blocks of B = N − 2r (N the length of the FFT
// along y, the smallest power of 2 of at least min(h, 2r + 2) + 2r), each block's passes along y
// made column pair by column pair from a ring of min(h, N) rows along x.
template <class Source>
void fft_rows(const Source& source, long w, long h, const std::vector<const std::vector<double>*>& along_x,
              const std::vector<YPass>& passes, Combiner& combiner,
              const std::function<void(std::size_t, const OrderRows&)>& row) {
  const long r = static_cast<long>(along_x.front()->size() / 2);
  std::vector<const std::vector<double>*> kernels;
  for (const YPass& p : passes) kernels.push_back(p.kernel);
  const internal::ClampedFftConvolution fy(kernels, static_cast<std::size_t>(std::min(h, 2 * r + 2)));
  const long n = static_cast<long>(fy.size()), block = n - 2 * r, width = 3 * w;
  const std::size_t ring = static_cast<std::size_t>(std::min(h, n) * width);
  const std::size_t out = static_cast<std::size_t>(std::min(block, h) * width);
  KeptBuffers kept(along_x.size() * ring + passes.size() * out);
  std::vector<std::vector<double>>& rings = kept.buffers(0, along_x.size(), ring);
  std::vector<std::vector<double>>& results = kept.buffers(1, passes.size(), out);
  XPasses<Source> x(source, static_cast<std::size_t>(w), along_x, std::min(h, n), &rings);
  std::vector<std::complex<double>> z(static_cast<std::size_t>(n)), t(static_cast<std::size_t>(n));
  for (long y0 = 0; y0 < h; y0 += block) {
    const long rows = std::min(block, h - y0);
    x.make_to(std::min(h - 1, y0 + rows - 1 + r));
    // Per pass along x, each column pair transformed once for every pass along y that reads it
    // (the 2-jet's five passes along y read three passes along x): the same transform each time.
    for (std::size_t a = 0; a < along_x.size(); ++a)
      for (long i = 0; i < width; i += 2) {
        check_interrupt();
        std::fill(z.begin(), z.end(), std::complex<double>());
        for (long m = 0; m < rows + 2 * r; ++m) {
          const double* in = x.row(a, std::min(std::max(y0 - r + m, 0L), h - 1));
          z[static_cast<std::size_t>(m)] = {in[i], i + 1 < width ? in[i + 1] : 0.0};
        }
        fy.transform(z.data());
        for (std::size_t p = 0; p < passes.size(); ++p) {
          if (passes[p].along_x != a) continue;
          fy.apply(p, z.data(), t.data());
          double* res = results[p].data();
          for (long j = 0; j < rows; ++j) {
            res[j * width + i] = t[static_cast<std::size_t>(j + 2 * r)].real();
            if (i + 1 < width) res[j * width + i + 1] = t[static_cast<std::size_t>(j + 2 * r)].imag();
          }
        }
      }
    for (long j = 0; j < rows; ++j) combiner(results, j * width, static_cast<std::size_t>(y0 + j), row);
  }
}

// The passes of every order asked (each pass once), and each order's indices into them. Order 0:
// g along x, then g along y. Order 1: f_x = d1 then g, f_y = g then d1. Order 2: f_xx = d2 then
// g, f_yy = g then d2, f_xy = d1 then d1. Kernel 0 is g, 1 d1, 2 d2.
struct SweepPlan {
  std::vector<std::size_t> along_x;                    // kernels, each once
  std::vector<std::pair<std::size_t, std::size_t>> y;  // (index into along_x, kernel)
  std::vector<OrderPasses> orders;
};
SweepPlan sweep_plan(const std::array<bool, 3>& asked) {
  static const std::vector<std::pair<std::size_t, std::size_t>> kernels_of[3] = {
      {{0, 0}}, {{1, 0}, {0, 1}}, {{2, 0}, {0, 2}, {1, 1}}};
  SweepPlan plan;
  const auto index_of = [](auto& list, const auto& value) {
    const auto at = std::find(list.begin(), list.end(), value);
    if (at != list.end()) return static_cast<std::size_t>(at - list.begin());
    list.push_back(value);
    return list.size() - 1;
  };
  for (int o = 0; o < 3; ++o) {
    if (!asked[static_cast<std::size_t>(o)]) continue;
    OrderPasses op{static_cast<DerivativeOrder>(o), {}};
    for (const auto& [xk, yk] : kernels_of[o]) op.passes.push_back(index_of(plan.y, std::make_pair(index_of(plan.along_x, xk), yk)));
    plan.orders.push_back(op);
  }
  return plan;
}

// gaussian_derivative's values of every order asked, row by row, from `source` (a w × h image).
template <class Source>
void derivative_rows(const Source& source, std::size_t w, std::size_t h, double sigma, const std::array<bool, 3>& asked,
                     const std::function<void(std::size_t, const OrderRows&)>& row) {
  if (!std::isfinite(sigma) || sigma < 0 || sigma > 64) throw std::invalid_argument("sigma must be from 0 to 64");
  if (sigma == 0 && (asked[1] || asked[2])) throw std::invalid_argument("a derivative needs sigma > 0");
  if (sigma == 0) {
    std::vector<double> out(3 * w);
    for (std::size_t y = 0; y < h; ++y) {
      check_interrupt();
      source(y, out.data());
      row(y, OrderRows{out.data(), nullptr, nullptr});
    }
    return;
  }
  const std::vector<double> kernels[3] = {kernel(sigma, 0), asked[1] || asked[2] ? kernel(sigma, 1) : std::vector<double>{},
                                          asked[2] ? kernel(sigma, 2) : std::vector<double>{}};
  const SweepPlan plan = sweep_plan(asked);
  std::vector<const std::vector<double>*> along_x;
  for (std::size_t k : plan.along_x) along_x.push_back(&kernels[k]);
  std::vector<YPass> passes;
  for (const auto& [xi, yk] : plan.y) passes.push_back({xi, &kernels[yk]});
  // A channel constant over the image has derivatives exactly 0 (the edge is replicated): they
  // are set so, where the convolutions would leave round-off that reads as a direction.
  const std::array<bool, 3> flat = asked[1] || asked[2] ? flat_channels(source, 3 * w * h) : std::array<bool, 3>{};
  Combiner combiner(plan.orders, flat, static_cast<long>(w));
  const long W = static_cast<long>(w), H = static_cast<long>(h);
  // Rows of no pixels (w = 0) take the direct route, which hands on h empty rows: the FFT's
  // clamped row would read the sample before the first.
  if (static_cast<long>(kernels[0].size() / 2) >= internal::kFftMinRadius && w > 0)
    fft_rows(source, W, H, along_x, passes, combiner, row);
  else
    direct_rows(source, W, H, along_x, passes, combiner, row);
}

// One order's rows, through derivative_rows.
template <class Source>
void one_order_rows(const Source& source, std::size_t w, std::size_t h, double sigma, DerivativeOrder order,
                    const std::function<void(std::size_t, const double*)>& row) {
  std::array<bool, 3> asked{};
  asked[static_cast<std::size_t>(order)] = true;
  derivative_rows(source, w, h, sigma, asked,
                  [&](std::size_t y, const OrderRows& rows) { row(y, rows[static_cast<std::size_t>(order)]); });
}

}  // namespace

std::vector<double> internal::derivative_kernel(double sigma, int order) { return kernel(sigma, order); }

DoubleImage linear_image(const RgbImage& image, std::uint32_t black_level) {
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  for (std::size_t i = 0; i < image.samples.size(); ++i)
    out.samples[i] = image.samples[i] > black_level ? double(image.samples[i] - black_level) : 0.0;
  return out;
}

DoubleImage gaussian_derivative(const DoubleImage& image, double sigma, DerivativeOrder order) {
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  one_order_rows(DoubleRows{image}, image.width, image.height, sigma, order, [&](std::size_t y, const double* row) {
    std::copy(row, row + 3 * image.width, out.samples.begin() + static_cast<long>(3 * image.width * y));
  });
  return out;
}

void gaussian_derivative_rows(const RgbImage& image, std::uint32_t black_level, double sigma, DerivativeOrder order,
                              const std::function<void(std::size_t, const double*)>& row) {
  one_order_rows(LinearRows{image, black_level}, image.width, image.height, sigma, order, row);
}

void gaussian_derivative_rows(const RgbImage& image, std::uint32_t black_level, double sigma,
                              const std::array<bool, 3>& orders,
                              const std::function<void(std::size_t, const std::array<const double*, 3>&)>& row) {
  derivative_rows(LinearRows{image, black_level}, image.width, image.height, sigma, orders, row);
}

}  // namespace gmcc
