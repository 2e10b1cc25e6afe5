#include <gmcc/photo/grey_edge.h>

#include "internal/names.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace gmcc {

std::string to_string(Baseline b) {
  switch (b) {
    case Baseline::grey_world: return "grey_world";
    case Baseline::white_patch: return "white_patch";
    case Baseline::shades_of_grey: return "shades_of_grey";
    case Baseline::grey_edge_1: return "grey_edge_1";
    case Baseline::grey_edge_2: return "grey_edge_2";
  }
  return "?";
}

Baseline baseline_from_string(const std::string& text) {
  for (Baseline b : all_baselines)
    if (internal::names_match(text, to_string(b))) return b;
  throw std::invalid_argument("\"" + text +
                              "\" is not one of grey-world, white-patch, shades-of-grey, grey-edge-1, grey-edge-2");
}

GreyEdgeParameters baseline_parameters(Baseline b) {
  switch (b) {
    case Baseline::grey_world: return {DerivativeOrder::zero, 1, 0};
    case Baseline::white_patch: return {DerivativeOrder::zero, HUGE_VAL, 0};
    case Baseline::shades_of_grey: return {DerivativeOrder::zero, 6, 0};
    case Baseline::grey_edge_1: return {DerivativeOrder::first, 1, 1};
    case Baseline::grey_edge_2: return {DerivativeOrder::second, 1, 1};
  }
  return {};
}

namespace {

// One baseline's sums over the kept pixels, in pixel order: its largest structure value per
// channel and, for p = 1, Σ v as it goes; for another finite p, in a second sweep, Σ (v/largest)^p
// (each channel scaled by its largest value first: no overflow for large p).
struct Norm {
  GreyEdgeParameters parameters;
  std::array<double, 3> top{0, 0, 0}, sum{0, 0, 0}, plain{0, 0, 0};  // plain: Σ v for p = 1
  bool zero() const { return top[0] == 0 || top[1] == 0 || top[2] == 0; }
  // p = 1 summed as it goes, unscaled (no overflow: below 2^62 for any image within the limits)
  // unless the values are so small that their sum could lose bits to the subnormals.
  bool one_sweep() const { return parameters.p == 1 && std::max({top[0], top[1], top[2]}) >= 0x1p-500; }
  bool sums() const { return std::isfinite(parameters.p) && !zero() && !one_sweep(); }  // a second sweep
  // (v/largest)^p, the second sweep's term. At σ = 0 a value is a linear sample, an integer from
  // 0 to the channel's largest: below 2^20 the terms are a table made once per channel, the same
  // std::pow of the same quotient, so the same bits at far fewer calls.
  std::array<std::vector<double>, 3> powers;
  void make_powers() {
    if (parameters.sigma != 0 || parameters.p == 1) return;
    for (int c = 0; c < 3; ++c) {
      if (!(top[c] <= 0x1p20)) return;
      powers[c].resize(static_cast<std::size_t>(top[c]) + 1);
      for (std::size_t v = 0; v < powers[c].size(); ++v) powers[c][v] = std::pow(double(v) / top[c], parameters.p);
    }
  }
  double term(int c, double v) const {
    if (parameters.p == 1) return v / top[c];
    if (!powers[2].empty()) return powers[c][static_cast<std::size_t>(v)];
    return std::pow(v / top[c], parameters.p);
  }
};

// One sweep of the structure at one σ for the baselines `norms` names (indices into all): each
// gets f(norm, row, kept columns) for every row in order, to take |value| at every kept pixel of
// the row in pixel order.
template <class F>
void sweep(const RgbImage& image, std::uint32_t black_level, const std::vector<bool>& kept, std::vector<Norm>& all,
           const std::vector<std::size_t>& norms, const F& f) {
  if (norms.empty()) return;
  std::array<bool, 3> orders{};
  for (std::size_t k : norms) orders[static_cast<std::size_t>(all[k].parameters.order)] = true;
  const std::size_t w = image.width;
  std::vector<std::size_t> row_kept;  // a row's kept columns, found once for every baseline
  gaussian_derivative_rows(image, black_level, all[norms.front()].parameters.sigma, orders,
                           [&](std::size_t y, const std::array<const double*, 3>& rows) {
                             row_kept.clear();
                             for (std::size_t x = 0; x < w; ++x)
                               if (kept[y * w + x]) row_kept.push_back(3 * x);
                             for (std::size_t k : norms)
                               f(all[k], rows[static_cast<std::size_t>(all[k].parameters.order)], row_kept);
                           });
}

// At σ = 0 a baseline's values are the linear samples: max(s, black) − black of each 16-bit
// sample s, integers (image_derivatives.h's linear image; internal::linear_channels' level, written
// out here without its branch: through it the sweeps measured 3% slower). Per kept pixel in pixel order,
// f(v0, v1, v2) with its three values; f keeps its sums in locals of its own (in registers: sums
// in an array that a lambda captures went through memory at every pixel).
template <class F>
void kept_linear_samples(const RgbImage& image, std::uint32_t black, const std::vector<bool>& kept, F&& f) {
  const std::uint16_t* s = image.samples.data();
  for (auto k = kept.begin(); k != kept.end(); ++k, s += 3)  // the mask's bits one after another
    if (*k)
      f(std::max<std::uint32_t>(s[0], black) - black, std::max<std::uint32_t>(s[1], black) - black,
        std::max<std::uint32_t>(s[2], black) - black);
}

// The first sweep at σ = 0 (order 0: the largest values and Σ v) in integers. Σ v in doubles in
// pixel order is exact while the total is below 2^53, every partial sum being an integer at most
// the total: the integer total converted is then the same double. False, and `n` untouched, when
// some channel's total is not (more than 2^37 kept pixels): the double sweep is then due.
bool integer_first_sweep(const RgbImage& image, std::uint32_t black, const std::vector<bool>& kept, Norm& n) {
  struct {
    std::uint32_t t0 = 0, t1 = 0, t2 = 0;
    std::uint64_t s0 = 0, s1 = 0, s2 = 0;  // below 2^64: at most 2^16 a sample, 2^28 pixels (max_image_pixels)
    void operator()(std::uint32_t v0, std::uint32_t v1, std::uint32_t v2) {
      t0 = std::max(t0, v0), t1 = std::max(t1, v1), t2 = std::max(t2, v2);
      s0 += v0, s1 += v1, s2 += v2;
    }
  } f;
  kept_linear_samples(image, black, kept, f);
  for (std::uint64_t t : {f.s0, f.s1, f.s2})
    if (t >= (std::uint64_t{1} << 53)) return false;
  n.top = {double(f.t0), double(f.t1), double(f.t2)}, n.plain = {double(f.s0), double(f.s1), double(f.s2)};
  return true;
}

// The second sweep at σ = 0 from the samples, when the terms are tables (Norm::make_powers): the
// same terms summed in pixel order. False, and `n` untouched, without the tables.
bool integer_sums(const RgbImage& image, std::uint32_t black, const std::vector<bool>& kept, Norm& n) {
  if (n.powers[2].empty()) return false;
  struct {
    const double *p0, *p1, *p2;
    double s0, s1, s2;
    void operator()(std::uint32_t v0, std::uint32_t v1, std::uint32_t v2) { s0 += p0[v0], s1 += p1[v1], s2 += p2[v2]; }
  } f{n.powers[0].data(), n.powers[1].data(), n.powers[2].data(), n.sum[0], n.sum[1], n.sum[2]};
  kept_linear_samples(image, black, kept, f);
  n.sum = {f.s0, f.s1, f.s2};
  return true;
}

// The light from a baseline's sums: unit length, absent when some channel's structure is 0.
std::optional<std::array<double, 3>> light_of(const Norm& n) {
  if (n.zero()) return std::nullopt;
  // Structure reached only through the Gaussian's tails (σ below about 0.1: weights near 1e-240,
  // or subnormal) can be so small that the light top·‖v/top‖ and the squares of its length
  // underflow, to an imprecise direction or a length of 0 (fuzz_edge_colours' findings): the light
  // is a direction, so the largest values are then brought near 1 by a power of 2 (exactly) first.
  std::array<double, 3> scaled = n.top;
  const double largest = std::max({n.top[0], n.top[1], n.top[2]});
  if (largest < 0x1p-500)
    for (double& t : scaled) t = std::ldexp(t, -std::ilogb(largest));
  std::array<double, 3> e = n.one_sweep() ? n.plain : scaled;
  if (std::isfinite(n.parameters.p) && !n.one_sweep())
    for (int c = 0; c < 3; ++c) e[c] = scaled[c] * std::pow(n.sum[c], 1 / n.parameters.p);
  const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return std::array<double, 3>{e[0] / length, e[1] / length, e[2] / length};
}

}  // namespace

std::vector<std::optional<std::array<double, 3>>> grey_edge_estimates(const RgbImage& image, std::uint32_t black_level,
                                                                     const std::vector<bool>& kept,
                                                                     const std::vector<GreyEdgeParameters>& parameters) {
  if (kept.size() != image.width * image.height)
    throw std::invalid_argument("the kept-pixel mask does not match the image");
  std::vector<Norm> all;
  for (const GreyEdgeParameters& p : parameters) {
    if (!(p.p >= 1)) throw std::invalid_argument("the Minkowski norm p must be >= 1");
    all.push_back({p});
  }
  // The baselines of one σ share their sweeps (no image of doubles: docs/cli.md "Resource
  // limits"): the largest values (and p = 1's sums), then the sums of another finite p.
  std::vector<bool> done(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (done[i]) continue;
    std::vector<std::size_t> group = {i}, summed;  // a NaN σ alone: the sweep refuses it
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (!done[j] && all[j].parameters.sigma == all[i].parameters.sigma) group.push_back(j), done[j] = true;
    // The largest values and Σ v depend on the order alone: made once per order, then copied.
    std::array<std::size_t, 3> first_of{all.size(), all.size(), all.size()};
    std::vector<std::size_t> firsts;
    for (std::size_t k : group) {
      std::size_t& first = first_of[static_cast<std::size_t>(all[k].parameters.order)];
      if (first == all.size()) first = k, firsts.push_back(k);
    }
    // At σ = 0 (order 0 alone: another order refuses σ 0 in the sweep) from the samples.
    const bool linear = all[i].parameters.sigma == 0 && firsts.size() == 1 &&
                        all[firsts.front()].parameters.order == DerivativeOrder::zero;
    if (linear && integer_first_sweep(image, black_level, kept, all[firsts.front()])) firsts.clear();
    // Each sum in its own variable, in pixel order (the same bytes as summing into the Norm).
    sweep(image, black_level, kept, all, firsts, [](Norm& n, const double* s, const std::vector<std::size_t>& columns) {
      std::array<double, 3> top = n.top, plain = n.plain;
      for (std::size_t i : columns)
        for (std::size_t c = 0; c < 3; ++c) {
          const double v = std::fabs(s[i + c]);
          top[c] = std::max(top[c], v);
          plain[c] += v;
        }
      n.top = top, n.plain = plain;
    });
    for (std::size_t k : group) {
      const Norm& first = all[first_of[static_cast<std::size_t>(all[k].parameters.order)]];
      all[k].top = first.top, all[k].plain = first.plain;
    }
    for (std::size_t k : group)
      if (all[k].sums()) summed.push_back(k), all[k].make_powers();
    // At σ = 0 with the terms' tables, from the samples: the others in a second sweep.
    if (linear)
      summed.erase(std::remove_if(summed.begin(), summed.end(),
                                  [&](std::size_t k) { return integer_sums(image, black_level, kept, all[k]); }),
                   summed.end());
    sweep(image, black_level, kept, all, summed, [](Norm& n, const double* s, const std::vector<std::size_t>& columns) {
      std::array<double, 3> sum = n.sum;
      for (std::size_t i : columns)
        for (std::size_t c = 0; c < 3; ++c) sum[c] += n.term(static_cast<int>(c), std::fabs(s[i + c]));
      n.sum = sum;
    });
  }
  std::vector<std::optional<std::array<double, 3>>> out;
  for (const Norm& n : all) out.push_back(light_of(n));
  return out;
}

std::optional<std::array<double, 3>> grey_edge_estimate(const RgbImage& image, std::uint32_t black_level,
                                                        const std::vector<bool>& kept, const GreyEdgeParameters& o) {
  return grey_edge_estimates(image, black_level, kept, {o}).front();
}

}  // namespace gmcc
