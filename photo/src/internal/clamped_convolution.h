#pragma once
// The Gaussian derivatives' 1-D convolutions at large σ by FFT (image_derivatives.cpp; docs/photographs.md
// "Gaussian derivatives by FFT"): the same truncated, edge-replicated convolution as the direct
// sums, Σ_t k(t)·in(clamp(x − t)) for t in [−r, r], computed as a circular convolution of
// length N ≥ n + 2r (a power of 2) of the edge-extended sequence, two real sequences at once as
// the real and imaginary parts of one complex one (Cooley & Tukey 1965 and Gentleman & Sande 1966,
// radix 2, no reordering). Its cost per
// value is O(log N) whatever the radius; its result differs from the exact sum by round-off only,
// at most 2^-40·Σ|k|·max|in| for N ≤ 2^16 (tested against a long double reference in
// tests/photo/test_edge_colours.cpp; about 2^-50 measured). Deterministic: a fixed order of
// operations and twiddles from std::cos and std::sin, so the same bytes on every run (on every
// platform whose cos and sin round the same, as the direct route's kernel already asks of exp).
// Internal to gmcc::photo.

#include <complex>
#include <cstddef>
#include <vector>

namespace gmcc::internal {

// The FFT route from this kernel radius ⌈3σ⌉ on (σ above 11), the direct route below it (σ = 1 and
// 4 unchanged, bit for bit): where the two cost the same on a 2041 × 1359 photograph (direct
// 1.1 s at σ = 10.4, FFT 1.2 s at any σ; docs/performance-history.md "Edge derivatives at any σ
// (issue 46 item 2)").
inline constexpr long kFftMinRadius = 34;

// The sampled derivative kernel of `order` (0, 1, 2) at scale σ on [−⌈3σ⌉, ⌈3σ⌉], normalised as
// image_derivatives.h says (image_derivatives.cpp).
std::vector<double> derivative_kernel(double sigma, int order);

// A radix-2 complex FFT of one length n (a power of 2, at least 2), unscaled both ways, with no
// reordering pass (docs/photographs.md "Gaussian derivatives by FFT"): the forward transform by
// decimation in frequency (Gentleman & Sande 1966) leaves the spectrum in bit-reversed order, the
// inverse by decimation in time (Cooley & Tukey 1965) reads it in that order, so a convolution
// (spectra multiplied entry by entry, both in that order) never permutes. The stages whose
// twiddles are 1 and ∓i (the two shortest) take no multiplication.
class Fft {
 public:
  explicit Fft(std::size_t n);
  std::size_t size() const { return n_; }
  // a ← DFT(a) in bit-reversed order: a[rev(k)] = Σ_j a_j·e^{−2πijk/n}.
  void forward(std::complex<double>* a) const;
  // a ← n·IDFT of a spectrum in bit-reversed order, in natural order: a[j] = Σ_k A_k·e^{2πijk/n}
  // where A_k is read from a[rev(k)]. inverse(forward(a)) = n·a up to round-off.
  void inverse(std::complex<double>* a) const;
  // rev(k): k's log2(n) bits reversed.
  std::size_t bit_reversed(std::size_t k) const { return rev_[k]; }

 private:
  std::size_t n_;
  std::vector<std::complex<double>> w_;  // e^{−2πik/n}, k < n/2, then each stage's: see forward
  std::vector<std::size_t> rev_;         // bit reversal
};

// Clamped convolutions by FFT with kernels of one radius r, for sequences of up to `outputs`
// values (each taking outputs + 2r extended inputs).
class ClampedFftConvolution {
 public:
  // kernels: each of 2r + 1 values, k[t + r] for t in [−r, r].
  ClampedFftConvolution(const std::vector<const std::vector<double>*>& kernels, std::size_t outputs);
  long radius() const { return r_; }
  std::size_t size() const { return fft_.size(); }
  // z (size() values): z[m] = e0[m] + i·e1[m] for m < n + 2r, e the extended inputs
  // (e[m] = in(clamp(m − r))), the rest 0, as the caller wrote it; transformed in place (its
  // spectrum in bit-reversed order, as apply reads it).
  void transform(std::complex<double>* z) const { fft_.forward(z); }
  // Kernel k applied to a transformed z, into out (size() values): the convolution of e0 at
  // output x (0 <= x < n) is out[x + 2r].real(), of e1 out[x + 2r].imag().
  void apply(std::size_t k, const std::complex<double>* z, std::complex<double>* out) const;

 private:
  long r_;
  Fft fft_;
  std::vector<std::vector<std::complex<double>>> spectra_;  // DFT of each kernel, divided by N
};

// The clamped convolution of `in` with `kernel` (2r + 1 values) by ClampedFftConvolution: for
// tests and the accuracy statement.
std::vector<double> clamped_convolution_fft(const std::vector<double>& in, const std::vector<double>& kernel);

}  // namespace gmcc::internal
