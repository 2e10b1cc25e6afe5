#pragma once
// What the benchmark's files share (benchmark.cpp, benchmark_images.cpp, benchmark_statistics.cpp):
// the methods' names, what an image is reduced to, and what the methods asked for need of it.
// Internal to gmcc::validation.

#include <gmcc/validation/benchmark.h>

#include <gmcc/photo/grey_edge.h>
#include <gmcc/selection/rule.h>
#include <gmcc/selection/rule_3.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gmcc::internal {

// Gamut-constrained illuminant estimation among the fold's training lights (gcie.h).
inline const char* const kGcie = "gcie";
// A key with dashes for underscores: how methods are named.
inline std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

// The 3-D pixel-gamut method of `rule` (gm3d-max-trace, …), and the same with the illumination
// constraint (gm3d-max-trace-constrained, …).
inline std::string gm3d_method(Rule3 rule) { return "gm3d-" + dashed(to_string(rule)); }
inline std::string gm3d_constrained_method(Rule3 rule) { return gm3d_method(rule) + "-constrained"; }
// The 3-D rules in the benchmark's order: max-trace (the field's selection) first, then the others.
inline std::vector<Rule3> benchmark_rules_3() {
  std::vector<Rule3> out{Rule3::max_trace};
  for (Rule3 r : all_rules_3)
    if (r != Rule3::max_trace) out.push_back(r);
  return out;
}
// The 2-D perspective route's method for `rule` (gm2d-max-area, …), and a baseline's (grey-world, …).
inline std::string gm2d_method(Rule rule) { return "gm2d-" + dashed(to_string(rule)); }
inline std::string gm2d_constrained_method(Rule rule) { return gm2d_method(rule) + "-constrained"; }
inline std::string baseline_method(std::size_t b) { return dashed(to_string(all_baselines[b])); }
// The edge-based methods (max-trace): edge-1, edge-2, 1-jet (pixel ∩ edge-1), 2-jet (∩ edge-2).
inline const char* const kEdge[4] = {"gm3d-edge1-max-trace", "gm3d-edge2-max-trace", "gm3d-1jet-max-trace",
                                     "gm3d-2jet-max-trace"};
// Which gamut types edge-based method k intersects: pixel, 1st-order, 2nd-order.
inline constexpr bool kEdgeTypes[4][3] = {{false, true, false}, {false, false, true}, {true, true, false}, {true, true, true}};

// What an image is reduced to: all the methods need of it.
struct Reduced {
  std::vector<Colour> hull3;  // pixel colours on their 3-D hull (Needs::hull3 or gcie)
  Colour top;                 // the pixel colours' largest channels (Needs::gm3d): their intensity scale
  std::vector<Colour> lifts;  // chromaticity lifts of their 2-D hull
  std::vector<Colour> edges[2];  // 1st- and 2nd-order edge colours on their 3-D hull
  std::array<std::optional<std::array<double, 3>>, all_baselines.size()> baselines;
};

// Which families the methods asked for need.
struct Needs {
  bool gm3d = false, gm2d = false;  // gm3d: the pixel colours' scale (their largest channels)
  bool hull3 = false;  // the pixel colours' 3-D hull (the pixel rules and the n-jets, not edge1 or edge2)
  bool gamut3 = false;  // the pixel colours' 3-D canonical gamut (not the edge methods' own)
  PerRule3<bool> rule3{};
  PerRule<bool> rule2{};
  // The rules with the illumination constraint (the fold's training lights).
  PerRule3<bool> rule3c{};
  PerRule<bool> rule2c{};
  bool gm2dc = false;
  bool gcie = false;  // the pixel colours' 3-D hull and the canonical perspective chromaticities
  std::array<bool, 4> edge{};  // the edge-based methods
  std::array<bool, 2> order{};  // the 1st- and 2nd-order edge colours and canonical gamuts
  std::array<bool, all_baselines.size()> baseline{};
};

// The families `methods` need. \throws std::invalid_argument for an unknown method.
Needs needs_of(const std::vector<std::string>& methods);

// Image `im` read (the run's levels and pixel rules with its own, its mask) and reduced to what
// the methods need. \throws InputError naming the image.
Reduced reduce(const BenchmarkImage& im, const BenchmarkOptions& o, const Needs& n);

}  // namespace gmcc::internal
