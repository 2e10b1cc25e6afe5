#pragma once
/// \file grow_canonical.h
/// A recovery policy for an empty feasible set (docs/math.md §1): grow the canonical gamut until
/// some map fits, as Barnard did (Barnard, Cardei & Funt 2002, Part I §3: the canonical gamut is
/// enlarged when real data leave no feasible map), and say by how much.

#include <gmcc/geometry/convex_set.h>

#include <optional>
#include <vector>

namespace gmcc {

/// How far and how finely to search. Factors F mean s = 1 + F, as ExpansionPolicy::multiplicative.
struct GrowCanonicalOptions {
  Rational start = 0;                      ///< F at which the search starts (F(start) is tested)
  Rational precision = Rational(1, 1 << 24);  ///< bisection stops when hi − lo <= precision
  Rational max_factor = 1 << 20;           ///< give up beyond this factor
};

/// What the search found.
struct GrownFeasibleSet {
  bool found = false;  ///< false: still empty at max_factor (e.g. a zero image component that
                       ///< no multiplicative growth of a positive gamut can reach)
  /// F at `factor` is non-empty and F at `empty_below` is empty, so the least factor with a
  /// non-empty F lies in (empty_below, factor]; factor − empty_below <= precision. When F is
  /// already non-empty at `start`, factor = start and empty_below is unset.
  Rational factor;  ///< the least factor found: F is non-empty here (the bracket's upper end)
  std::optional<Rational> empty_below;  ///< the bracket's lower end, where F is still empty
  ConvexSet2 canonical;  ///< the gamut at `factor` (multiplicative expansion)
  ConvexSet2 feasible;   ///< F at `factor`, intersected with the constraint when one is given
};

/// The least multiplicative expansion factor (ExpansionPolicy::multiplicative, a box in
/// log-chromaticity) at which F = feasible_set(G_c(F), image) [∩ constraint] is non-empty,
/// bracketed to `precision` by exact bisection on dyadic rationals.
///
/// Monotone: for s <= s' the s-expanded gamut lies in the s'-expanded one (each box
/// [x/s, x·s] × [y/s, y·s] lies in the s' box), so F only grows with the factor and bisection
/// is sound. The threshold itself is in general an algebraic number (a vertex of F moving with s
/// meets a constraint), hence the bracket. Doubling from max(2·start, 1) finds an upper end.
/// \param canonical_chromaticities the measured canonical chromaticities (non-empty).
/// \param image image chromaticities (as feasible_set).
/// \param constraint optional set F is intersected with (e.g. illumination_constraint).
/// \param options where the search starts, when bisection stops and where it gives up.
/// \throws as feasible_set; std::invalid_argument for precision <= 0 or start < 0.
/// Complexity O(log2(max_factor/precision)) feasible sets.
GrownFeasibleSet grow_canonical_until_feasible(const std::vector<Point2>& canonical_chromaticities,
                                               const std::vector<Point2>& image,
                                               const std::optional<ConvexSet2>& constraint = {},
                                               const GrowCanonicalOptions& options = {});

}  // namespace gmcc
