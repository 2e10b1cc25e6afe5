#pragma once
// std::seed_seq's generate(), computed faster with the same output (C++17 [rand.util.seedseq]
// defines it exactly): the experiment seeds one mt19937_64 per scene from six words, and the
// standard library's general version (modulo indexing, a heap buffer) cost more than the scene's
// whole geometry. Internal to gmcc::validation; tested against std::seed_seq.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

namespace gmcc::internal {

template <std::size_t S>
class SeedSequence {
 public:
  using result_type = std::uint32_t;
  explicit SeedSequence(const std::array<std::uint32_t, S>& v) : v_(v) {}

  std::size_t size() const { return S; }
  template <class It>
  void param(It out) const { std::copy(v_.begin(), v_.end(), out); }

  // [rand.util.seedseq]/8, with the indices k mod n, (k + p) mod n and (k + q) mod n stepped
  // instead of divided.
  template <class It>
  void generate(It begin, It end) const {
    const std::size_t n = static_cast<std::size_t>(end - begin);
    if (n == 0) return;
    std::fill(begin, end, 0x8b8b8b8bu);
    const std::size_t s = S;
    const std::size_t t = n >= 623 ? 11 : n >= 68 ? 7 : n >= 39 ? 5 : n >= 7 ? 3 : (n - 1) / 2;
    const std::size_t p = (n - t) / 2, q = p + t, m = std::max(s + 1, n);
    auto T = [](std::uint32_t x) { return x ^ (x >> 27); };
    auto at = [&](std::size_t i) -> std::uint32_t& { return *(begin + static_cast<std::ptrdiff_t>(i)); };
    std::size_t k0 = 0, kp = p % n, kq = q % n;  // k, k+p, k+q, all mod n
    // Element (k − 1) mod n is always the value the previous step stored last (its own k), so it
    // is kept in a register: the loops' dependency chain no longer passes through memory.
    std::uint32_t previous = at(n - 1);
    auto step = [n](std::size_t& i) { i = i + 1 == n ? 0 : i + 1; };
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t r1 = 1664525u * T(at(k0) ^ at(kp) ^ previous);
      const std::uint32_t r2 = r1 + static_cast<std::uint32_t>(
                                        k == 0 ? s : k <= s ? k0 + v_[k - 1] : k0);
      at(kp) += r1;
      at(kq) += r2;
      at(k0) = r2;
      previous = r2;
      step(k0), step(kp), step(kq);
    }
    for (std::size_t k = m; k < m + n; ++k) {
      const std::uint32_t r3 = 1566083941u * T(at(k0) + at(kp) + previous);
      const std::uint32_t r4 = r3 - static_cast<std::uint32_t>(k0);
      at(kp) ^= r3;
      at(kq) ^= r4;
      at(k0) = r4;
      previous = r4;
      step(k0), step(kp), step(kq);
    }
  }

 private:
  std::array<std::uint32_t, S> v_;
};

}  // namespace gmcc::internal
