#pragma once
// Max-area's candidates (Finlayson & Hordley 1999 §3.1; docs/derivations.md §2.3), written once
// for every number type and every description of F: argmax m1·m2 over a convex polygon or
// segment is a vertex, or the stationary point of m1·m2 inside an edge of its north-east chain
// (Δm1·Δm2 < 0, where m1·m2 is concave along the edge). max_area.cpp enumerates them from exact
// vertices (in ℚ, and in x87 intervals); certified_rule_errors.cpp from vertex enclosures and edge lines.
// Internal to gmcc::selection.

#include <gmcc/numerics/enclosure.h>
#include <gmcc/numerics/may_be_largest.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace gmcc::internal {

/// One candidate's m1·m2 in number type N; `index` is a vertex (< n), or n + i for the
/// stationary point inside the edge from vertex i.
template <class N>
struct AreaCandidate {
  N value;
  std::size_t index;
};

/// The candidates of F with n vertices and `edges` edges (n for a polygon, 1 for a segment):
/// every vertex's `k.product(i)`, then each edge i → i+1's `k.stationary(i, j)`, which is nothing
/// when the kind cannot decide (then so is the answer), an empty inner optional when the edge
/// has no stationary point strictly inside it, else its value.
template <class Kind>
auto area_candidates(std::size_t n, std::size_t edges, const Kind& k)
    -> std::optional<std::vector<AreaCandidate<typename Kind::Number>>> {
  using N = typename Kind::Number;
  std::vector<AreaCandidate<N>> out;
  out.reserve(n + edges);
  for (std::size_t i = 0; i < n; ++i) out.push_back({k.product(i), i});
  for (std::size_t i = 0; i < edges; ++i) {
    const std::optional<std::optional<N>> s = k.stationary(i, (i + 1) % n);
    if (!s) return std::nullopt;
    if (*s) out.push_back({std::move(**s), n + i});
  }
  return out;
}

/// The position of the candidate whose enclosure (a kind of numerics/enclosure.h) lies strictly
/// above every other's: the one candidate that may be the largest (numerics/may_be_largest.h:
/// the largest lower end, every other upper end below it); nothing on a near-tie, which only a
/// finer kind can settle, or when a NaN touched another candidate.
template <class N>
std::optional<std::size_t> unique_maximum(const std::vector<AreaCandidate<N>>& c) {
  const std::vector<std::size_t> kept =
      numerics::may_be_largest(c, [](const AreaCandidate<N>& a) -> const N& { return a.value; });
  if (kept.size() != 1) return std::nullopt;
  return kept.front();
}

}  // namespace gmcc::internal
