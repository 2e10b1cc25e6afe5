#include <gmcc/photo/image_pixels.h>

#include <gmcc/geometry/chromaticity_hull.h>
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/photo/image_derivatives.h>
#include <gmcc/input/colour_csv.h>

#include "internal/sort_colours.h"
#include "internal/colour_keys.h"
#include "internal/sort_keys.h"

#include <gmcc/numerics/interrupt.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <set>
#include <stdexcept>
#include <string>

namespace gmcc {
namespace {

constexpr long kFar = 1L << 40;  // beyond any image side: clamping here changes no pixel

// floor(q) (up = false) or ceil(q) (up = true), clamped to [-kFar, kFar].
long long rounded(const Rational& q, bool up) {
  mpz_class r;
  (up ? mpz_cdiv_q : mpz_fdiv_q)(r.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  if (r > kFar) return kFar;
  if (r < -kFar) return -kFar;
  return r.get_si();
}
long long floor_of(const Rational& q) { return rounded(q, false); }
long long ceil_of(const Rational& q) { return rounded(q, true); }

// Colours a hull is taken of at once (image_colours' working copies: 24 MiB at most).
constexpr std::size_t colour_chunk = std::size_t(1) << 20;

// Keys a least-significant-digit pass sorts through a buffer (8 MiB at most).
constexpr std::size_t lsd_keys = std::size_t(1) << 20;

// Least-significant-digit radix sort of [first, last) on bits [0, bits) (the keys equal above),
// through `buffer`, in passes of 8-bit digits below 2^16 keys and 16-bit digits from there.
void sort_keys_lsd(std::uint64_t* first, std::uint64_t* last, int bits, std::vector<std::uint64_t>& buffer) {
  const std::size_t n = static_cast<std::size_t>(last - first);
  if (buffer.size() < n) buffer.resize(n);
  const int digit = n < (std::size_t(1) << 16) ? 8 : 16;
  std::vector<std::size_t> count(std::size_t(1) << digit);
  const std::uint64_t mask = (std::uint64_t(1) << digit) - 1;
  std::uint64_t *from = first, *to = buffer.data();
  for (int shift = 0; shift < bits; shift += digit) {
    std::fill(count.begin(), count.end(), 0);
    for (const std::uint64_t* k = from; k != from + n; ++k) ++count[(*k >> shift) & mask];
    std::size_t sum = 0;
    for (std::size_t& c : count) {
      const std::size_t m = c;
      c = sum;
      sum += m;
    }
    for (const std::uint64_t* k = from; k != from + n; ++k) to[count[(*k >> shift) & mask]++] = *k;
    std::swap(from, to);
  }
  if (from != first) std::copy(from, from + n, first);
}

// Sort 48-bit keys ascending, in place: most-significant-digit radix sort on bytes (American
// flag sort: McIlroy, Bostic & McIlroy 1993), buckets of fewer than 64 keys by std::sort and of
// at most lsd_keys by sort_keys_lsd through `buffer` (the keys' own memory and 8 MiB more).
void sort_keys_from(std::uint64_t* first, std::uint64_t* last, int shift, std::vector<std::uint64_t>& buffer) {
  const std::size_t n = static_cast<std::size_t>(last - first);
  if (n < 64 || shift < 0) {
    std::sort(first, last);
    return;
  }
  if (n <= lsd_keys) {
    sort_keys_lsd(first, last, shift + 8, buffer);
    return;
  }
  std::size_t count[256] = {}, next[256], end[256];
  for (const std::uint64_t* k = first; k != last; ++k) ++count[(*k >> shift) & 0xff];
  std::size_t sum = 0;
  for (int d = 0; d < 256; ++d) {
    next[d] = sum;
    sum += count[d];
    end[d] = sum;
  }
  for (int d = 0; d < 256; ++d)
    while (next[d] < end[d]) {  // carry the key at next[d] round its cycle until one belongs here
      std::uint64_t k = first[next[d]];
      int kd = static_cast<int>((k >> shift) & 0xff);
      while (kd != d) {
        std::swap(k, first[next[kd]++]);
        kd = static_cast<int>((k >> shift) & 0xff);
      }
      first[next[d]++] = k;
    }
  if (shift == 0) return;
  std::size_t begin = 0;
  for (int d = 0; d < 256; ++d) {
    if (count[d] > 1) sort_keys_from(first + begin, first + begin + count[d], shift - 8, buffer);
    begin += count[d];
  }
}

// Sort 48-bit keys ascending: std::sort for a few, else by their top byte in place and each
// bucket's rest through a buffer of at most 2^20 keys (issue 42: a whole buffer as large as the
// keys was 8 bytes a kept pixel more; this is about as fast: docs/performance-history.md). The same
// sequence either way.
void sort_keys(std::vector<std::uint64_t>& keys) {
  if (keys.size() < 64)
    std::sort(keys.begin(), keys.end());
  else
    internal::sort_keys_in_place(keys);
}

}  // namespace

namespace {

// An edge's rows: those whose centre line y = j + ½ meets its closed y-span, clipped to
// [first, last]; the only rows where it can cross, touch or lie on the line.
struct EdgeRows {
  long long from, to;
  std::size_t edge;
};

// The rows of the image (height `height`) each edge of `polygon` spans, in order of `from`.
std::vector<EdgeRows> edge_rows(const std::vector<Point2>& polygon, std::size_t height) {
  std::vector<EdgeRows> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    const long long from = std::max<long long>(0, ceil_of(std::min(a.y, b.y) - Rational(1, 2)));
    const long long to = std::min<long long>(static_cast<long long>(height) - 1, floor_of(std::max(a.y, b.y) - Rational(1, 2)));
    if (from <= to) out.push_back({from, to, i});
  }
  std::sort(out.begin(), out.end(), [](const EdgeRows& p, const EdgeRows& q) { return p.from < q.from; });
  return out;
}

}  // namespace

std::uint64_t polygon_work(const std::vector<Point2>& polygon, std::size_t height) {
  std::uint64_t work = polygon.size();
  for (const EdgeRows& e : edge_rows(polygon, height)) work += static_cast<std::uint64_t>(e.to - e.from + 1);
  return work;
}

std::vector<bool> polygon_cover(const std::vector<Point2>& polygon, std::size_t width,
                                std::size_t height) {
  if (polygon.size() < 3) throw std::invalid_argument("a mask polygon needs at least 3 vertices");
  std::vector<bool> cover(width * height, false);
  const std::size_t n = polygon.size();
  // Row j's centres lie on y = j + ½. The centres inside (even–odd) lie between
  // pairs of the sorted crossings of the non-horizontal edges, counted
  // half-open at their lower end so that a vertex on the line is crossed once
  // or not at all; the boundary is added by closed intervals: crossings
  // themselves, vertices on the line, and horizontal edges on it. A sweep over
  // the rows keeps the edges whose y-span holds the row (edge_rows), so a row
  // costs its own edges only, and each edge's slope is divided once.
  const std::vector<EdgeRows> rows = edge_rows(polygon, height);
  std::vector<Rational> slope(n);
  std::vector<bool> has_slope(n, false);
  std::vector<Rational> crossings;
  auto mark = [&](long long row, const Rational& lo, const Rational& hi) {
    const long long a = std::max<long long>(0, ceil_of(lo - Rational(1, 2)));
    const long long b =
        std::min<long long>(static_cast<long long>(width) - 1, floor_of(hi - Rational(1, 2)));
    for (long long x = a; x <= b; ++x) cover[static_cast<std::size_t>(row) * width + x] = true;
  };
  std::vector<EdgeRows> active;
  std::size_t next = 0;
  for (long long row = rows.empty() ? 0 : rows.front().from; next < rows.size() || !active.empty(); ++row) {
    if (active.empty() && next < rows.size()) row = std::max(row, rows[next].from);
    while (next < rows.size() && rows[next].from <= row) active.push_back(rows[next++]);
    active.erase(std::remove_if(active.begin(), active.end(), [&](const EdgeRows& e) { return e.to < row; }),
                 active.end());
    if (active.empty()) continue;
    check_interrupt();
    const Rational y = Rational(static_cast<long>(2 * row + 1), 2);
    crossings.clear();
    for (const EdgeRows& e : active) {
      const std::size_t i = e.edge;
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % n];
      if (a.y == y && b.y == y) {
        mark(row, std::min(a.x, b.x), std::max(a.x, b.x));
        continue;
      }
      if (a.y == y) mark(row, a.x, a.x);
      if ((a.y <= y) != (b.y <= y)) {
        if (!has_slope[i]) slope[i] = (b.x - a.x) / (b.y - a.y), has_slope[i] = true;
        crossings.push_back(a.x + slope[i] * (y - a.y));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
      mark(row, crossings[k], crossings[k + 1]);
  }
  return cover;
}

namespace {

// The pixels the rules leave out: inside an excluded polygon, or not kept by the mask.
std::vector<bool> excluded_pixels(const PixelRules& rules, std::size_t w, std::size_t h) {
  // The exact cover costs a rational crossing per edge and row the edge spans, and a few rational
  // operations per vertex: bounded before any work (docs/cli.md "Resource limits").
  std::uint64_t work = 0;
  for (const std::vector<Point2>& polygon : rules.exclude_polygons) {
    work += polygon.size() > max_polygon_work ? max_polygon_work + 1 : polygon_work(polygon, h);
    if (work > max_polygon_work)
      throw std::invalid_argument("the exclusion polygons (" + std::to_string(polygon.size()) +
                                  " vertices in the last) on " + std::to_string(h) +
                                  " rows would take more than 2^20 exact edge crossings and vertices: "
                                  "give fewer vertices, or a mask image");
  }
  std::vector<bool> excluded(w * h, false);
  for (const std::vector<Point2>& polygon : rules.exclude_polygons) {
    const std::vector<bool> cover = polygon_cover(polygon, w, h);
    for (std::size_t i = 0; i < cover.size(); ++i)
      if (cover[i]) excluded[i] = true;
  }
  if (!rules.keep.empty())
    for (std::size_t i = 0; i < w * h; ++i)
      if (!rules.keep[i]) excluded[i] = true;
  return excluded;
}

// Without binning: the distinct kept pixels (keys r·2^32 + g·2^16 + b, increasing, each once),
// or their hull's vertices, into out.
ImageColours colours_of_keys(const std::vector<std::uint64_t>& keys, ColourSet colour_set, ImageColours out) {
  out.counts.colours = keys.size();
  const auto channels = internal::key_channels;
  // The hulls are taken chunk by chunk of the sorted keys: a hull's vertices are among its
  // parts' hulls' vertices, so the hull of the chunks' vertices is the whole set's, while the
  // working copies stay at a chunk's size (colour_chunk colours) whatever the image's.
  if (colour_set == ColourSet::hull) {
    out.set = ColourSet::hull;
    std::vector<Point2> vertices;
    std::vector<std::array<std::uint16_t, 3>> colours;
    colours.reserve(std::min(keys.size(), colour_chunk));
    for (std::size_t begin = 0; begin < keys.size(); begin += colour_chunk) {
      const std::size_t end = std::min(keys.size(), begin + colour_chunk);
      colours.clear();
      for (std::size_t i = begin; i < end; ++i) {
        const auto c = channels(keys[i]);
        colours.push_back({std::uint16_t(c[0]), std::uint16_t(c[1]), std::uint16_t(c[2])});
      }
      ChromaticityHull hull = chromaticity_hull_of_pixels(colours);
      out.counts.no_chromaticity += hull.dropped;
      vertices.insert(vertices.end(), hull.hull.vertices.begin(), hull.hull.vertices.end());
    }
    if (keys.size() > colour_chunk) vertices = convex_hull(vertices).vertices;
    for (const Point2& p : vertices) out.colours.push_back({p.x, p.y, Rational(1)});
    out.counts.hull_vertices = out.colours.size();
    return out;
  }
  if (colour_set == ColourSet::hull_3d) {
    // Integers are doubles exactly: the hull's vertices are found without making a rational.
    out.set = ColourSet::hull_3d;
    std::vector<std::uint64_t> vertex_keys;  // increasing, as the keys
    std::vector<std::array<double, 3>> colours;
    colours.reserve(std::min(keys.size(), colour_chunk));
    auto hull_of = [&](const std::uint64_t* first, const std::uint64_t* last) {
      colours.clear();
      for (const std::uint64_t* k = first; k != last; ++k) {
        const auto c = channels(*k);
        colours.push_back({double(c[0]), double(c[1]), double(c[2])});
      }
      std::vector<std::uint64_t> chosen;
      for (std::size_t i : colour_hull_vertex_indices(colours)) chosen.push_back(first[i]);
      return chosen;
    };
    for (std::size_t begin = 0; begin < keys.size(); begin += colour_chunk) {
      const std::size_t end = std::min(keys.size(), begin + colour_chunk);
      const std::vector<std::uint64_t> chosen = hull_of(keys.data() + begin, keys.data() + end);
      vertex_keys.insert(vertex_keys.end(), chosen.begin(), chosen.end());
    }
    if (keys.size() > colour_chunk)
      vertex_keys = hull_of(vertex_keys.data(), vertex_keys.data() + vertex_keys.size());
    for (std::uint64_t key : vertex_keys) {
      const auto c = channels(key);
      out.colours.push_back({Rational(c[0]), Rational(c[1]), Rational(c[2])});
    }
    out.counts.hull_vertices = out.colours.size();
    return out;
  }
  if (keys.size() > max_colours)
    throw std::length_error(std::to_string(keys.size()) + " distinct colours, more than the " +
                            std::to_string(max_colours) +
                            " a colour set may hold: use the hull colour set or binning");
  out.colours.reserve(keys.size());
  for (std::uint64_t key : keys) {
    const auto c = channels(key);
    out.colours.push_back({Rational(c[0]), Rational(c[1]), Rational(c[2])});
  }
  return out;
}

}  // namespace

void internal::sort_keys_in_place(std::vector<std::uint64_t>& keys) {
  std::vector<std::uint64_t> buffer;
  sort_keys_from(keys.data(), keys.data() + keys.size(), 40, buffer);
}

std::string to_string(ColourSet set) {
  switch (set) {
    case ColourSet::distinct: return "distinct";
    case ColourSet::hull: return "hull";
    case ColourSet::hull_3d: return "hull-3d";
  }
  return "?";
}

namespace {
constexpr ColourSet all_colour_sets[] = {ColourSet::hull, ColourSet::distinct, ColourSet::hull_3d};
}  // namespace

ColourSet colour_set_from_string(const std::string& text) {
  for (ColourSet set : all_colour_sets)
    if (text == to_string(set)) return set;
  if (text == "hull_3d") return ColourSet::hull_3d;
  throw std::invalid_argument(quoted_text(text) + " is not one of hull, distinct, hull-3d");
}

std::vector<std::string> colour_set_names() {
  std::vector<std::string> names;
  for (ColourSet set : all_colour_sets) names.push_back(to_string(set));
  return names;
}

PixelRules gijsenij_pixel_rules(PixelRules base) {
  base.dark_below_fraction = Rational(5, 255);
  base.bright_above_fraction = Rational(245, 255);
  return base;
}

KeptPixels kept_pixels(const RgbImage& image, const PixelRules& rules) {
  const std::size_t w = image.width, h = image.height;
  if (!rules.keep.empty() && rules.keep.size() != w * h)
    throw std::invalid_argument("the mask has " + std::to_string(rules.keep.size()) +
                                " pixels, the image " + std::to_string(w * h));
  for (const std::optional<Rational>* f : {&rules.dark_below_fraction, &rules.bright_above_fraction})
    if (*f && (sgn(**f) < 0 || **f > 1))
      throw std::invalid_argument("a dark or bright fraction must lie in [0, 1], not " + to_string(**f));
  const std::vector<bool> excluded = excluded_pixels(rules, w, h);
  const bool any_excluded = std::find(excluded.begin(), excluded.end(), true) != excluded.end();
  const std::uint64_t black = rules.black_level;
  // M, the largest channel after the black level over the pixels the mask keeps (the level of the
  // largest sample, the level being monotone), and step 4's integer thresholds: v < f·M iff
  // v < ceil(f·M); v > f·M iff v > floor(f·M) (v an integer).
  std::uint16_t largest = 0;
  if (!any_excluded)
    largest = image.samples.empty() ? 0 : *std::max_element(image.samples.begin(), image.samples.end());
  else
    for (std::size_t i = 0; i < w * h; ++i)
      if (!excluded[i])
        for (std::size_t c = 0; c < 3; ++c) largest = std::max(largest, image.samples[3 * i + c]);
  const std::uint64_t M = largest > black ? largest - black : 0;
  std::uint64_t dark = rules.dark_below.value_or(0);
  if (rules.dark_below_fraction)
    dark = std::max<std::uint64_t>(dark, static_cast<std::uint64_t>(ceil_of(*rules.dark_below_fraction * M)));
  // The same rules on the raw samples v: level(v) < dark iff v < black + dark (dark > 0), and
  // level(v) > bright iff v > black + bright.
  const std::uint64_t dark_raw = dark > 0 ? black + dark : 0;
  std::uint64_t bright_raw = UINT64_MAX;
  if (rules.bright_above_fraction)
    bright_raw = black + static_cast<std::uint64_t>(floor_of(*rules.bright_above_fraction * M));
  const std::uint64_t saturation = rules.saturation ? *rules.saturation : UINT64_MAX;

  KeptPixels out;
  out.kept.assign(w * h, false);
  out.counts.pixels = static_cast<std::uint64_t>(w) * h;
  for (std::size_t i = 0; i < w * h; ++i) {
    const std::uint16_t* v = image.samples.data() + 3 * i;
    const std::uint64_t low = std::min({v[0], v[1], v[2]}), high = std::max({v[0], v[1], v[2]});
    if (any_excluded && excluded[i])
      ++out.counts.masked;
    else if (high >= saturation)
      ++out.counts.saturated;
    else if (low < dark_raw)
      ++out.counts.dark;
    else if (high > bright_raw)
      ++out.counts.bright;
    else
      ++out.counts.kept, out.kept[i] = true;
  }
  return out;
}

namespace {

// The pre-filtered route: the smoothed image's values at the kept pixels, as exact colours.
ImageColours prefiltered_colours(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept) {
  // Row by row: no image of doubles (docs/cli.md "Resource limits").
  std::vector<std::array<double, 3>> colours;
  colours.reserve(static_cast<std::size_t>(kept.counts.kept));
  const std::size_t w = image.width;
  gaussian_derivative_rows(image, rules.black_level, rules.prefilter_sigma, DerivativeOrder::zero,
                           [&](std::size_t y, const double* smooth) {
                             for (std::size_t x = 0; x < w; ++x)
                               if (kept.kept[y * w + x]) colours.push_back({smooth[3 * x], smooth[3 * x + 1], smooth[3 * x + 2]});
                           });
  return colour_set_of_doubles(std::move(colours), rules.colour_set, kept.counts);
}

}  // namespace

ImageColours hull_3d_of_doubles(std::vector<std::array<double, 3>> colours, const PixelCounts& counts) {
  ImageColours out;
  out.counts = counts;
  out.counts.colours = 0;
  out.set = ColourSet::hull_3d;
  if (colours.empty()) return out;
  // Chunk by chunk, as colours_of_keys: the hull of the chunks' vertices is the whole set's, its
  // vertices the same, and the working copies a chunk's size. colour_hull_vertex_indices gives
  // one index per distinct vertex in increasing colour order, in any order of its input.
  const std::size_t n = colours.size();
  std::vector<std::array<double, 3>> vertices;
  if (n <= colour_chunk) {  // one chunk: the colours themselves, no copy
    for (std::size_t i : colour_hull_vertex_indices(colours)) vertices.push_back(colours[i]);
  } else {
    std::vector<std::array<double, 3>> chunk, parts;
    for (std::size_t begin = 0; begin < n; begin += colour_chunk) {
      const std::size_t end = std::min(n, begin + colour_chunk);
      chunk.assign(colours.begin() + static_cast<long>(begin), colours.begin() + static_cast<long>(end));
      for (std::size_t i : colour_hull_vertex_indices(chunk)) parts.push_back(chunk[i]);
    }
    std::vector<std::array<double, 3>>().swap(colours);
    std::vector<std::array<double, 3>>().swap(chunk);
    for (std::size_t i : colour_hull_vertex_indices(parts)) vertices.push_back(parts[i]);
  }
  for (const auto& c : vertices) out.colours.push_back({Rational(c[0]), Rational(c[1]), Rational(c[2])});
  out.counts.hull_vertices = out.colours.size();
  return out;
}

ImageColours colour_set_of_doubles(std::vector<std::array<double, 3>> colours, ColourSet colour_set,
                                   const PixelCounts& counts) {
  ImageColours out;
  out.counts = counts;
  internal::sort_double_colours(colours);  // as std::sort, faster on edge colours
  colours.erase(std::unique(colours.begin(), colours.end()), colours.end());
  out.counts.colours = colours.size();
  out.set = colour_set;
  if (colours.empty()) return out;
  if (colour_set == ColourSet::hull) {
    const ChromaticityHull hull = chromaticity_hull(colours);
    out.counts.no_chromaticity = hull.dropped;
    for (const Point2& p : hull.hull.vertices) out.colours.push_back({p.x, p.y, Rational(1)});
    out.counts.hull_vertices = out.colours.size();
    return out;
  }
  if (colour_set == ColourSet::hull_3d) {
    ImageColours hull = hull_3d_of_doubles(std::move(colours), out.counts);
    hull.counts.colours = out.counts.colours;
    return hull;
  }
  if (colours.size() > max_colours)
    throw std::length_error(std::to_string(colours.size()) + " distinct colours, more than the " +
                            std::to_string(max_colours) + " a colour set may hold: use the hull colour set");
  for (const auto& c : colours) out.colours.push_back({Rational(c[0]), Rational(c[1]), Rational(c[2])});
  return out;
}

namespace {

void check_binning_and_prefilter(const PixelRules& rules) {
  if (rules.bin == 0) throw std::invalid_argument("the binning block size must be at least 1");
  if (!(rules.prefilter_sigma >= 0 && rules.prefilter_sigma <= 64))
    throw std::invalid_argument("the pre-filter's sigma must be from 0 to 64");
  if (rules.prefilter_sigma > 0 && rules.bin > 1)
    throw std::invalid_argument("a pre-filter and binning do not go together: give one");
}

// The kept pixels' colours after the black level as keys r·2^32 + g·2^16 + b, increasing, each
// once (step 6's distinct colours, before any hull).
std::vector<std::uint64_t> distinct_keys(const RgbImage& image, std::uint32_t black_level, const KeptPixels& kept) {
  std::vector<std::uint64_t> keys;
  keys.reserve(static_cast<std::size_t>(kept.counts.kept));
  const std::size_t n = image.width * image.height;
  for (std::size_t i = 0; i < n; ++i) {
    if (kept.kept[i]) keys.push_back(internal::colour_key(internal::linear_channels(image, black_level, i)));
  }
  sort_keys(keys);
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace

std::vector<ImageColours> image_colour_sets(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept,
                                            const std::vector<ColourSet>& sets) {
  check_binning_and_prefilter(rules);
  if (kept.kept.size() != image.width * image.height)
    throw std::invalid_argument("the kept pixels are not this image's");
  std::vector<ImageColours> out;
  if (rules.bin > 1 || rules.prefilter_sigma > 0) {
    for (ColourSet set : sets) {
      PixelRules r = rules;
      r.colour_set = set;
      out.push_back(image_colours(image, r));
    }
    return out;
  }
  std::vector<std::uint64_t> keys;
  if (!sets.empty()) keys = distinct_keys(image, rules.black_level, kept);
  for (ColourSet set : sets) {
    ImageColours colours;
    colours.counts = kept.counts;
    out.push_back(colours_of_keys(keys, set, std::move(colours)));
  }
  return out;
}

ImageColours image_colours(const RgbImage& image, const PixelRules& rules) {
  check_binning_and_prefilter(rules);
  const std::size_t w = image.width, h = image.height;
  KeptPixels kept = kept_pixels(image, rules);
  if (rules.prefilter_sigma > 0) return prefiltered_colours(image, rules, kept);
  if (rules.bin == 1) return std::move(image_colour_sets(image, rules, kept, {rules.colour_set}).front());

  ImageColours out;
  out.counts = kept.counts;
  const std::uint32_t b = rules.bin;
  const std::size_t bw = (w + b - 1) / b, bh = (h + b - 1) / b;
  // Per block: the sums of the kept pixels' channels (exact integers) and their
  // number.
  struct Block {
    std::uint64_t sum[3] = {0, 0, 0};
    std::uint64_t n = 0;
  };
  std::vector<Block> blocks(bw * bh);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t i = y * w + x;
      if (!kept.kept[i]) continue;
      std::uint32_t v[3];
      for (int c = 0; c < 3; ++c) {
        v[c] = image.samples[3 * i + static_cast<std::size_t>(c)];
        v[c] = v[c] > rules.black_level ? v[c] - rules.black_level : 0;
      }
      Block& block = blocks[(y / b) * bw + x / b];
      for (int c = 0; c < 3; ++c) block.sum[c] += v[c];
      ++block.n;
    }
  {
    std::set<std::array<Rational, 3>> distinct;  // ordered: increasing (r, g, b)
    for (const Block& block : blocks) {
      if (block.n == 0) continue;
      std::array<Rational, 3> mean;
      for (int c = 0; c < 3; ++c) {
        mean[c] = Rational(mpz_class(static_cast<unsigned long>(block.sum[c])),
                           mpz_class(static_cast<unsigned long>(block.n)));
        mean[c].canonicalize();
      }
      distinct.insert(std::move(mean));
      if (distinct.size() > max_colours)  // memory: each block mean is three exact rationals
        throw std::length_error("more than " + std::to_string(max_colours) +
                                " distinct block means, more than a colour set may hold: use larger blocks");
    }
    for (const auto& mean : distinct) out.colours.push_back({mean[0], mean[1], mean[2]});
  }
  out.counts.colours = out.colours.size();
  if (rules.colour_set == ColourSet::hull_3d && !out.colours.empty()) {
    out.set = ColourSet::hull_3d;
    out.colours = colour_hull_vertices(out.colours);
    out.counts.hull_vertices = out.colours.size();
  }
  return out;
}

}  // namespace gmcc
