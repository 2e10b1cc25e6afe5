#pragma once
// A rule computed in stages, the shape of CGAL's Filtered_predicate applied to a whole rule: each
// filter stage returns std::optional (nothing: it cannot certify its answer); the last stage is
// exact and always answers (docs/architecture.md "Exactness, routes and failures"). Each rule
// counts how often each of its stages answered, so that tests and benchmarks can see the
// fallbacks. Internal to gmcc::selection.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace gmcc::internal {

/// How often each stage of one rule answered, in stage order (shared by every thread).
struct StageCounts {
  std::array<std::atomic<std::uint64_t>, 4> answered{};

  /// A snapshot of answered[k].
  std::uint64_t operator[](std::size_t k) const { return answered[k].load(std::memory_order_relaxed); }
};

namespace detail {
template <class Exact>
auto run_stages(StageCounts& counts, std::size_t k, Exact&& exact) {
  counts.answered[k].fetch_add(1, std::memory_order_relaxed);
  return std::forward<Exact>(exact)();
}
template <class Filter, class... Rest>
auto run_stages(StageCounts& counts, std::size_t k, Filter&& filter, Rest&&... rest) {
  if (auto r = std::forward<Filter>(filter)()) {
    counts.answered[k].fetch_add(1, std::memory_order_relaxed);
    return std::move(*r);
  }
  return run_stages(counts, k + 1, std::forward<Rest>(rest)...);
}
}  // namespace detail

/// The first stage's answer that is not nothing: filters..., then the exact stage (last), each
/// a callable taking no argument; counts records which answered.
template <class... Stages>
auto staged(StageCounts& counts, Stages&&... stages) {
  static_assert(sizeof...(Stages) <= 4, "StageCounts holds four stages");
  return detail::run_stages(counts, 0, std::forward<Stages>(stages)...);
}

}  // namespace gmcc::internal
