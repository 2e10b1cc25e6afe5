#include <gmcc/photo/image_hull_sets.h>

#include <gmcc/geometry/chromaticity_hull.h>
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/colour_hull_sieve.h>

#include "internal/colour_keys.h"
#include "internal/sort_keys.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace gmcc {
namespace {

// Pixel i's linear colour as exact doubles.
std::array<double, 3> linear_colour(const RgbImage& image, std::uint32_t black_level, std::size_t i) {
  const auto c = internal::linear_channels(image, black_level, i);
  return {double(c[0]), double(c[1]), double(c[2])};
}

std::array<double, 3> colour_of(std::uint64_t key) {
  const auto c = internal::key_channels(key);
  return {double(c[0]), double(c[1]), double(c[2])};
}

// How many slabs of red the sieve cuts the colours into (8: measured on full-size stand-ins, where
// one Q for the whole image kept about 18% of the pixels for the exact hull).
constexpr std::size_t slabs = 8;
// About how many kept pixels the sieves' corners are chosen from.
constexpr std::size_t sample = 1 << 18;
// Up to how many kept pixels the exact hull takes every kept colour, without the sieves.
constexpr std::size_t few = 1 << 15;

// The keys of the kept pixels' colours that their slab's sieve keeps, in pixel order (the slab
// of a linear red r is slab_of_red[r]). On x86-64 ELF with GCC it is compiled twice and the loader
// picks the clone the processor supports, so that the sieve's tests of four planes at a time are
// vector instructions: exact in either, every product and sum an integer below 2^53.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void sieve_pass(const RgbImage& image, std::uint32_t black_level, const std::vector<bool>& kept,
                const std::vector<std::uint8_t>& slab_of_red, const std::vector<ColourHullSieve>& sieves,
                std::vector<std::uint64_t>& keys) {
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (kept[i]) {
      const auto c = internal::linear_channels(image, black_level, i);
      if (!sieves[slab_of_red[c[0]]].strictly_inside({double(c[0]), double(c[1]), double(c[2])}))
        keys.push_back(internal::colour_key(c));
    }
}

// The keys of the kept pixels' colours that may be vertices of their hull: every kept colour for
// an image of at most `few` kept pixels, where building the sieves costs more than the exact
// hull's own filter spends on all of them; else those the sieves of slabs of red keep.
std::vector<std::uint64_t> candidate_keys(const RgbImage& image, std::uint32_t black_level, const KeptPixels& kept) {
  std::vector<std::uint64_t> keys;
  if (kept.counts.kept <= few) {
    keys.reserve(kept.counts.kept);
    for (std::size_t i = 0; i < kept.kept.size(); ++i)
      if (kept.kept[i]) keys.push_back(internal::colour_key(internal::linear_channels(image, black_level, i)));
    return keys;
  }
  // The sieves' corners from a sample of the kept pixels (about `sample` of them, every
  // stride-th pixel): any colours of the image will do, since a colour strictly inside the hull of
  // some of its colours is a vertex of neither hull; every kept pixel would give colours only
  // slightly more extreme, at the cost of two more sweeps of the image.
  const std::size_t n = image.width * image.height, stride = std::max<std::size_t>(1, kept.counts.kept / sample);
  const auto each_sampled_colour = [&](const auto& f) {
    for (std::size_t i = 0; i < n; i += stride)
      if (kept.kept[i]) f(i, linear_colour(image, black_level, i));
  };
  // The sample's range of red; the colours fall into slabs of red, each with its own sieve: a
  // slab's hull is thin along red, so its few extreme colours leave far fewer inside candidates
  // than one Q for the whole image. Colours beyond the sample's range go to the end slabs.
  double low = HUGE_VAL, high = -HUGE_VAL;
  each_sampled_colour([&](std::size_t, const std::array<double, 3>& c) {
    low = std::min(low, c[0]), high = std::max(high, c[0]);
  });
  // A slab from red by one product, monotone in red.
  const double per_red = double(slabs) / (high - low + 1);
  const auto slab = [&](const std::array<double, 3>& c) {
    return c[0] <= low ? 0 : std::min(slabs - 1, static_cast<std::size_t>((c[0] - low) * per_red));
  };
  // Each slab's extreme colours among the sample's with b > 0 (S+, the colours with a
  // chromaticity), so that Q ⊆ conv(S+) ⊆ conv(S): a colour strictly inside it is a vertex of
  // neither hull, and one with b = 0 is never inside. Then every kept colour its sieve keeps.
  std::vector<ExtremeColours> extremes(slabs);
  each_sampled_colour([&](std::size_t i, const std::array<double, 3>& c) {
    if (c[2] > 0) extremes[slab(c)].add(i, c);
  });
  std::vector<ColourHullSieve> sieves;
  for (const ExtremeColours& e : extremes) {
    std::vector<std::array<double, 3>> corners;
    for (std::size_t i : e.indices()) corners.push_back(linear_colour(image, black_level, i));
    sieves.emplace_back(corners);
  }
  std::vector<std::uint8_t> slab_of_red(1 << 16);
  for (std::size_t r = 0; r < slab_of_red.size(); ++r) slab_of_red[r] = static_cast<std::uint8_t>(slab({double(r), 0, 0}));
  sieve_pass(image, black_level, kept.kept, slab_of_red, sieves, keys);
  return keys;
}

}  // namespace

std::vector<ImageColours> image_hull_sets(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept,
                                          const std::vector<ColourSet>& sets) {
  const bool hulls = !sets.empty() && std::all_of(sets.begin(), sets.end(), [](ColourSet s) {
    return s == ColourSet::hull_3d || s == ColourSet::hull;
  });
  if (!hulls || rules.bin != 1 || rules.prefilter_sigma > 0 || kept.counts.kept == 0 ||
      kept.kept.size() != image.width * image.height)
    return image_colour_sets(image, rules, kept, sets);
  std::vector<std::uint64_t> keys = candidate_keys(image, rules.black_level, kept);
  // The colours kept, distinct and sorted.
  internal::sort_keys_in_place(keys);
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<ImageColours> out;
  for (ColourSet set : sets) {
    ImageColours c;
    c.counts = kept.counts;
    c.set = set;
    if (set == ColourSet::hull_3d) {
      // Their exact hull (its own filter first: a Q from their extreme colours, which the
      // sample's need not be). One hull over every slab's colours measured faster than a hull
      // per slab and then the hull of their vertices.
      std::vector<std::array<double, 3>> candidates;
      candidates.reserve(keys.size());
      for (std::uint64_t k : keys) candidates.push_back(colour_of(k));
      for (std::size_t i : colour_hull_vertex_indices(candidates))
        c.colours.push_back({Rational(candidates[i][0]), Rational(candidates[i][1]), Rational(candidates[i][2])});
    } else {  // the survivors hold every vertex of conv(S+): its chromaticity hull is theirs
      std::vector<std::array<std::uint16_t, 3>> pixels;
      for (std::uint64_t key : keys) {
        const auto k = internal::key_channels(key);
        pixels.push_back({std::uint16_t(k[0]), std::uint16_t(k[1]), std::uint16_t(k[2])});
      }
      for (const Point2& p : chromaticity_hull_of_pixels(pixels).hull.vertices) c.colours.push_back({p.x, p.y, Rational(1)});
    }
    c.counts.hull_vertices = c.colours.size();
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace gmcc
