#pragma once
// std::mt19937_64 with the same output, twisting its state lazily: the standard engine twists
// all 312 words before its first output, and an experiment scene draws a dozen numbers from a
// freshly seeded engine. The twist runs in place in index order ([rand.eng.mers]), so twisting
// word k only when output k is needed gives the same words. Internal to gmcc::validation;
// tested against std::mt19937_64.

#include <array>
#include <cstddef>
#include <cstdint>

namespace gmcc::internal {

class LazyMt19937_64 {
 public:
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type(0); }

  /// Seeded as std::mt19937_64(q) is ([rand.eng.mers]/8: two 32-bit words per state word).
  template <class SeedSequence>
  explicit LazyMt19937_64(SeedSequence& q) {
    std::array<std::uint32_t, 2 * n> a;
    q.generate(a.begin(), a.end());
    bool zero = true;
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] = a[2 * i] | (static_cast<std::uint64_t>(a[2 * i + 1]) << 32);
      zero = zero && (i == 0 ? (x_[0] & upper) == 0 : x_[i] == 0);
    }
    if (zero) x_[0] = std::uint64_t(1) << 63;
  }

  result_type operator()() {
    if (p_ == n) p_ = 0, twisted_ = 0;  // a new generation, twisted in place again
    for (; twisted_ <= p_; ++twisted_) {
      const std::size_t k = twisted_;
      const std::uint64_t y = (x_[k] & upper) | (x_[k + 1 == n ? 0 : k + 1] & lower);
      x_[k] = x_[k + m < n ? k + m : k + m - n] ^ (y >> 1) ^ ((y & 1) ? matrix : 0);
    }
    std::uint64_t z = x_[p_++];
    z ^= (z >> 29) & 0x5555555555555555u;
    z ^= (z << 17) & 0x71d67fffeda60000u;
    z ^= (z << 37) & 0xfff7eee000000000u;
    return z ^ (z >> 43);
  }

 private:
  static constexpr std::size_t n = 312, m = 156;
  static constexpr std::uint64_t matrix = 0xb5026f5aa96619e9u;
  static constexpr std::uint64_t upper = ~std::uint64_t(0) << 31, lower = ~upper;  // r = 31
  std::array<std::uint64_t, n> x_{};
  std::size_t p_ = 0, twisted_ = 0;  // next output; words [0, twisted_) are of this generation
};

}  // namespace gmcc::internal
