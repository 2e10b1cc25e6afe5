#pragma once
/// \file mean_3d_double.h
/// The same closed form as mean_3d evaluated naively in double precision (plain 3-vectors of doubles).
/// An inexact baseline, named as such: on a polygon of angular width ε the edge terms are O(ε)
/// while τ is O(ε²), so the sum cancels and the relative error grows like 2^-53/ε²
/// (docs/derivations.md §1.6). It exists for benchmarks and for tests that show why gmcc does not
/// use it.

#include <gmcc/geometry/convex_set.h>

#include <array>

namespace gmcc {

/// Finlayson & Hordley (1999) §3.2 3-D mean via Arvo's τ in doubles; no error bound.
/// \pre F is not empty.
std::array<double, 2> mean_3d_double(const ConvexSet2& F);

}  // namespace gmcc
