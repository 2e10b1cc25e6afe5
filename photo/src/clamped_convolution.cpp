// Clamped convolutions by FFT (clamped_convolution.h; Cooley & Tukey 1965, Gentleman & Sande 1966).
#include "internal/clamped_convolution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gmcc::internal {
namespace {

// a·b written out (std::complex's operator* checks for infinities through a library call).
std::complex<double> times(const std::complex<double>& a, const std::complex<double>& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// a·conj(b) written out.
std::complex<double> times_conj(const std::complex<double>& a, const std::complex<double>& b) {
  return {a.real() * b.real() + a.imag() * b.imag(), a.imag() * b.real() - a.real() * b.imag()};
}

std::size_t power_of_two_at_least(std::size_t n) {
  std::size_t p = 2;
  while (p < n) p *= 2;
  return p;
}

}  // namespace

Fft::Fft(std::size_t n) : n_(n), w_(n / 2), rev_(n) {
  if (n < 2 || (n & (n - 1)) != 0) throw std::invalid_argument("Fft: the length is a power of 2, at least 2");
  // The twiddles in long double, rounded once to double; 1 and −i exactly.
  const long double pi = 3.141592653589793238462643383279502884L;
  for (std::size_t k = 0; k < n / 2; ++k) {
    const long double a = -2 * pi * static_cast<long double>(k) / static_cast<long double>(n);
    w_[k] = {static_cast<double>(std::cos(a)), static_cast<double>(std::sin(a))};
  }
  w_[0] = {1.0, 0.0};
  if (n >= 4) w_[n / 4] = {0.0, -1.0};
  // Each stage's twiddles in a row (the stage of `half` reads w_[j·n/(2·half)] for j < half): the
  // same values, at n/2 + half − 1 + j, so that a stage reads them one after the other.
  w_.reserve(n / 2 + n - 1);
  for (std::size_t half = 1; half < n; half *= 2)
    for (std::size_t j = 0; j < half; ++j) w_.push_back(w_[j * (n / (2 * half))]);
  std::size_t bits = 0;
  while ((std::size_t(1) << bits) < n) ++bits;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t r = 0;
    for (std::size_t b = 0; b < bits; ++b) r |= ((i >> b) & 1) << (bits - 1 - b);
    rev_[i] = r;
  }
}

// On x86-64 ELF with GCC compiled twice, the loader picking the clone the processor supports (as
// image_derivatives.cpp's weighted_sums): the AVX2 clone makes the same operations (no fused
// multiply-add), so the same bytes.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void Fft::forward(std::complex<double>* a) const {
  // Decimation in frequency: stages from the longest; each butterfly (u, v) → (u + v, (u − v)·w).
  for (std::size_t half = n_ / 2; half >= 4; half /= 2) {
    const std::complex<double>* w = w_.data() + n_ / 2 - 1 + half;  // this stage's, in a row
    for (std::size_t i = 0; i < n_; i += 2 * half)
      for (std::size_t j = 0; j < half; ++j) {
        const std::complex<double> u = a[i + j], v = a[i + j + half];
        a[i + j] = u + v;
        a[i + j + half] = times(u - v, w[j]);
      }
  }
  if (n_ >= 4)  // twiddles 1 and −i: (x, y)·(−i) = (y, −x)
    for (std::size_t i = 0; i < n_; i += 4) {
      const std::complex<double> u0 = a[i], u1 = a[i + 1], v0 = a[i + 2], v1 = a[i + 3];
      const std::complex<double> d1 = u1 - v1;
      a[i] = u0 + v0, a[i + 2] = u0 - v0;
      a[i + 1] = u1 + v1, a[i + 3] = {d1.imag(), -d1.real()};
    }
  for (std::size_t i = 0; i < n_; i += 2) {  // twiddle 1
    const std::complex<double> u = a[i], v = a[i + 1];
    a[i] = u + v, a[i + 1] = u - v;
  }
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void Fft::inverse(std::complex<double>* a) const {
  // Decimation in time on the bit-reversed spectrum, conjugate twiddles: (u, v) → (u ± v·w̄).
  for (std::size_t i = 0; i < n_; i += 2) {  // twiddle 1
    const std::complex<double> u = a[i], v = a[i + 1];
    a[i] = u + v, a[i + 1] = u - v;
  }
  if (n_ >= 4)  // twiddles 1 and +i: (x, y)·i = (−y, x)
    for (std::size_t i = 0; i < n_; i += 4) {
      const std::complex<double> u0 = a[i], u1 = a[i + 1], v0 = a[i + 2], t = a[i + 3];
      const std::complex<double> v1{-t.imag(), t.real()};
      a[i] = u0 + v0, a[i + 2] = u0 - v0;
      a[i + 1] = u1 + v1, a[i + 3] = u1 - v1;
    }
  for (std::size_t half = 4; half < n_; half *= 2) {
    const std::complex<double>* w = w_.data() + n_ / 2 - 1 + half;
    for (std::size_t i = 0; i < n_; i += 2 * half)
      for (std::size_t j = 0; j < half; ++j) {
        const std::complex<double> u = a[i + j], v = times_conj(a[i + j + half], w[j]);
        a[i + j] = u + v;
        a[i + j + half] = u - v;
      }
  }
}

ClampedFftConvolution::ClampedFftConvolution(const std::vector<const std::vector<double>*>& kernels,
                                             std::size_t outputs)
    : r_(static_cast<long>(kernels.front()->size() / 2)),
      fft_(power_of_two_at_least(outputs + kernels.front()->size() - 1)) {  // n + 2r
  // The kernel at 0 … 2r, zero-padded; 1/N is a power of 2 (exact). Its spectrum in bit-reversed
  // order, as transform leaves z's.
  const double scale = 1.0 / static_cast<double>(fft_.size());
  for (const std::vector<double>* k : kernels) {
    std::vector<std::complex<double>> s(fft_.size());
    for (std::size_t j = 0; j < k->size(); ++j) s[j] = (*k)[j] * scale;
    fft_.forward(s.data());
    spectra_.push_back(std::move(s));
  }
}

void ClampedFftConvolution::apply(std::size_t k, const std::complex<double>* z, std::complex<double>* out) const {
  const std::vector<std::complex<double>>& s = spectra_[k];
  for (std::size_t i = 0; i < s.size(); ++i) out[i] = times(z[i], s[i]);
  fft_.inverse(out);
}

std::vector<double> clamped_convolution_fft(const std::vector<double>& in, const std::vector<double>& kernel) {
  const ClampedFftConvolution c({&kernel}, in.size());
  const long r = c.radius(), n = static_cast<long>(in.size());
  std::vector<std::complex<double>> z(c.size()), out(c.size());
  for (long m = 0; m < n + 2 * r; ++m) z[static_cast<std::size_t>(m)] = in[static_cast<std::size_t>(std::clamp(m - r, 0L, n - 1))];
  c.transform(z.data());
  c.apply(0, z.data(), out.data());
  std::vector<double> result(in.size());
  for (long x = 0; x < n; ++x) result[static_cast<std::size_t>(x)] = out[static_cast<std::size_t>(x + 2 * r)].real();
  return result;
}

}  // namespace gmcc::internal
