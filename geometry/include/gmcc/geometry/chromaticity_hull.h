#pragma once
/// \file chromaticity_hull.h
/// The exact convex hull of the perspective chromaticities (r/b, g/b) of many colours — an
/// image's gamut (Finlayson 1996 §2) — without constructing a single chromaticity.

#include <gmcc/geometry/convex_set.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gmcc {

/// The hull and how many colours had no chromaticity.
struct ChromaticityHull {
  ConvexSet2 hull;               ///< exact, canonical form (the vertices are exact r/b, g/b)
  std::size_t dropped = 0;       ///< colours with b <= 0
};

/// conv{(r/b, g/b)} of colours given as doubles (each double is an exact rational), exactly.
///
/// A chromaticity is the homogeneous point (r, g, b), so every predicate is a polynomial in the
/// raw channels: x-order is sign(r1·b2 − r2·b1), orientation is sign(det[(r,g,b)_1; _2; _3])
/// (b > 0). Each is evaluated in double with a rigorous error bound and decided exactly (GMP)
/// only when the bound cannot decide — a filtered predicate (Shewchuk 1997; CGAL's filtered
/// kernels), so the answer is exact whatever the input. The bounds are relative: the doubles
/// are used only when every channel is 0 or in [2^-100, 2^100] (every product then normal);
/// otherwise every predicate, and no octagon, is exact. Points strictly inside the octagon of
/// input points extreme in eight directions are discarded first by a conservative double test
/// (Akl & Toussaint 1978), then Andrew's monotone
/// chain (1979) runs on the rest. Complexity O(n) filtered tests plus O(h' log h') for the h'
/// survivors.
/// \throws std::invalid_argument for a non-finite or negative channel.
ChromaticityHull chromaticity_hull(const std::vector<std::array<double, 3>>& colours);

/// chromaticity_hull for colours with integer channels below 2^16 (an image's pixels), in machine
/// integers: x-order is r1·b2 vs r2·b1 in 64 bits, orientation the 3×3 determinant of the raw
/// channels, whose six products of three 16-bit numbers are below 2^48, so the determinant is
/// exact in a signed 64-bit integer (|det| < 2^51). No floating point, no filter, no GMP: as
/// exact as chromaticity_hull and much faster on the many ties and collinear triples of integer
/// data. Andrew's monotone chain; O(n log n).
ChromaticityHull chromaticity_hull_of_pixels(const std::vector<std::array<std::uint16_t, 3>>& colours);

}  // namespace gmcc
