#pragma once
// A seeded, named generator of hard convex sets for the 3-D mean (Finlayson & Hordley 1999 §3.2;
// docs/math.md §2 and docs/accuracy.md "Reading" on thin sets): exact rational vertices in the positive quadrant,
// by category, plus the two fixed reproducers of the accuracy audit. Used by
// tests/selection/test_mean_3d_honesty.cpp and bench/accuracy_sweep.cpp.
//
// Reproducible everywhere: every case has its own std::mt19937_64 seeded from (seed, category,
// index) by SplitMix64, and integers are drawn by the mapping of uniform_below (documented in
// hard_polygons.cpp), not by std::uniform_*_distribution, whose output is implementation-defined.
// No floating-point function is used, so the vertices are the same bytes on every platform.

#include <gmcc/geometry/convex_set.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace gmcc::test {

/// The kinds of hard sets.
enum class HardCategory {
  random,     ///< 3–12 vertices, size 0.1–10, near maps 0.1–10
  sliver,     ///< 3–40 vertices, relative width 1e-6 … 1e-15 (c + t·d + s·ε·n, ε = 10^-k)
  far,        ///< maps near 1e6 … 1e12, sizes relative 1 … 1e-10
  small,      ///< maps near 1e-6 … 1e-12
  collinear,  ///< nearly collinear, image-hull-like: vertices on a chord with a tiny bulge
  many,       ///< 28–200 vertices on an ellipse arc (thin ones included)
  segment,    ///< two points: random, short, far, small, radial
  point,      ///< one point (non-dyadic rational coordinates)
};

/// Every category, in the order above.
const std::vector<HardCategory>& hard_categories();
/// `random`, `sliver`, `far`, `small`, `collinear`, `many`, `segment`, `point`.
std::string to_string(HardCategory category);

/// One generated set with its name (`category#index`, or `reproducer-a`/`reproducer-b`).
struct HardCase {
  std::string name;
  std::string category;  ///< to_string of the category, or `reproducer`
  ConvexSet2 set;
};

/// Case `index` of `category` for `seed`: the same set for the same three numbers, whatever else
/// was generated before.
HardCase make_hard_case(HardCategory category, std::uint64_t seed, unsigned index);

/// `count` cases cycling through hard_categories() (case i is category i mod 8, index i / 8).
std::vector<HardCase> hard_cases(std::uint64_t seed, unsigned count);

/// Case `index` of a separate, easy category `wide` (name `wide#index`): 3–12 vertices on an
/// axis-aligned ellipse around a centre in [1/2, 3/2]², 3/4 to all of the room the quadrant
/// allows, so its cone spans a few tenths of a steradian: enough for Monte Carlo at 10^5 samples.
HardCase make_wide_case(std::uint64_t seed, unsigned index);

/// Reproducer (a): F for canonical 1,1,1 · 2,3,1 · 3/2,2.000000000000001,1 and a white image:
/// the triangle (1, 1), (2, 3), (3/2, 2.000000000000001) (built through feasible_set).
HardCase reproducer_thin_triangle();

/// Reproducer (b): feasible_set(convex_hull(canonical chromaticities), image chromaticities) for
/// the six canonical and three image colours of the audit; the second coordinate of its 3-D
/// mean is nearest the double reproducer_b_map1.
HardCase reproducer_feasible_set();
inline constexpr double reproducer_b_map1 = 3.3384690469431035;

/// The integer mapping used throughout: uniform on {0, …, n − 1} by rejection (draws v ≥
/// 2^64 − (2^64 mod n) are redrawn, then v mod n). \pre n > 0.
std::uint64_t uniform_below(std::mt19937_64& rng, std::uint64_t n);

}  // namespace gmcc::test
