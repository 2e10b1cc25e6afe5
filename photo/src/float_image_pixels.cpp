// The pixel rules on a floating-point image (image_pixels.h, image_colours(FloatRgbImage)): steps
// 1 to 4 compared exactly, the black level subtracted only where that is exact, then step 6.
#include <gmcc/photo/image_pixels.h>

#include <gmcc/geometry/chromaticity_hull.h>
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/input/colour_csv.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gmcc {
namespace {

const char* const channel_names[] = {"r", "g", "b"};

// std::invalid_argument for an image or rules image_colours cannot use (image_pixels.h).
void check_float_rules(const FloatRgbImage& image, const FloatPixelRules& rules) {
  const std::size_t w = image.width, h = image.height;
  if (image.samples.size() != w * h * 3)
    throw std::invalid_argument("the image's samples do not match its size");
  if (!rules.keep.empty() && rules.keep.size() != w * h)
    throw std::invalid_argument("the mask has " + std::to_string(rules.keep.size()) +
                                " pixels, the image " + std::to_string(w * h));
  const double black = rules.black_level;
  if (!std::isfinite(black) || black < 0)
    throw std::invalid_argument("the black level must be finite and >= 0");
  if (rules.saturation && !(*rules.saturation >= 0))
    throw std::invalid_argument("the saturation threshold must be >= 0");
  for (const std::optional<Rational>* f : {&rules.dark_below_fraction, &rules.bright_above_fraction})
    if (*f && (sgn(**f) < 0 || **f > 1))
      throw std::invalid_argument("a dark or bright fraction must lie in [0, 1], not " + to_string(**f));
  if (rules.dark_below && !(*rules.dark_below >= 0 && std::isfinite(*rules.dark_below)))
    throw std::invalid_argument("the dark threshold must be finite and >= 0");
}

// Step 4's thresholds in ℚ: a kept channel below `dark` (when it is > 0) is dark, one above
// `bright` too bright.
struct Thresholds {
  Rational dark;
  std::optional<Rational> bright;
};

// M for step 4: the largest channel after the black level over the pixels the mask keeps (a
// difference at most the sample itself; finite samples are checked again by the pixel loop).
Thresholds step_4_thresholds(const FloatRgbImage& image, const FloatPixelRules& rules) {
  const double black = rules.black_level;
  Thresholds t{rules.dark_below ? Rational(*rules.dark_below) : Rational(0), std::nullopt};
  if (rules.dark_below_fraction || rules.bright_above_fraction) {
    double top = 0;
    for (std::size_t i = 0; i < image.width * image.height; ++i)
      if (rules.keep.empty() || rules.keep[i])
        for (int c = 0; c < 3; ++c) {
          const double v = image.samples[3 * i + static_cast<std::size_t>(c)];
          if (std::isfinite(v) && v > black) top = std::max(top, v);
        }
    const Rational M = top > black ? Rational(top) - Rational(black) : Rational(0);
    if (rules.dark_below_fraction) t.dark = std::max(t.dark, Rational(*rules.dark_below_fraction * M));
    if (rules.bright_above_fraction) t.bright = Rational(*rules.bright_above_fraction * M);
  }
  return t;
}

std::string pixel_name(std::size_t i, std::size_t w, int c) {
  return "pixel (row " + std::to_string(i / w) + ", column " + std::to_string(i % w) + ") channel " +
         channel_names[c];
}

// Pixel i's samples, each a linear sensor response (finite, >= 0) or std::invalid_argument.
std::array<double, 3> checked_samples(const FloatRgbImage& image, std::size_t i) {
  std::array<double, 3> v;
  for (int c = 0; c < 3; ++c) {
    v[c] = image.samples[3 * i + static_cast<std::size_t>(c)];
    if (!std::isfinite(v[c]) || v[c] < 0)
      throw std::invalid_argument(pixel_name(i, image.width, c) + ": " +
                                  (std::isnan(v[c]) ? "NaN" : std::isinf(v[c]) ? "infinity" : "a negative value") +
                                  " is not a linear sensor response (finite, >= 0)");
  }
  return v;
}

// v − black per channel, exactly (0 at or below the black level), or std::invalid_argument.
void subtract_black_exactly(std::array<double, 3>& v, double black, std::size_t i, std::size_t w) {
  for (int c = 0; c < 3; ++c) {
    if (v[c] <= black) {
      v[c] = 0;
      continue;
    }
    // TwoSum (Knuth): s + e = v − black exactly; e = 0 iff the rounded difference is exact.
    const double s = v[c] - black, bv = s - v[c];
    const double e = (v[c] - (s - bv)) + (-black - bv);
    if (e != 0)
      throw std::invalid_argument(pixel_name(i, w, c) +
                                  ": the sample minus the black level is not exact in double; "
                                  "subtract the black level yourself or give integer samples");
    v[c] = s;
  }
}

// Step 6 on the kept colours: distinct or hull_3d as exact colours, or the chromaticity lifts.
ImageColours float_colour_set(std::vector<std::array<double, 3>> kept, ColourSet colour_set, ImageColours out) {
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  out.counts.colours = kept.size();
  if (colour_set != ColourSet::hull) {
    out.set = colour_set;
    for (const auto& v : kept) out.colours.push_back({Rational(v[0]), Rational(v[1]), Rational(v[2])});
    if (colour_set == ColourSet::hull_3d && !out.colours.empty()) {
      out.colours = colour_hull_vertices(out.colours);
      out.counts.hull_vertices = out.colours.size();
    } else if (out.colours.size() > max_colours) {
      throw std::length_error(std::to_string(out.colours.size()) + " distinct colours, more than the " +
                              std::to_string(max_colours) +
                              " a colour set may hold: use the hull colour set or binning");
    }
    return out;
  }
  out.set = ColourSet::hull;
  const ChromaticityHull hull = chromaticity_hull(kept);
  out.counts.no_chromaticity = hull.dropped;  // distinct colours with b = 0, as for integer images
  for (const Point2& p : hull.hull.vertices) out.colours.push_back({p.x, p.y, Rational(1)});
  out.counts.hull_vertices = out.colours.size();
  return out;
}

}  // namespace

ImageColours image_colours(const FloatRgbImage& image, const FloatPixelRules& rules) {
  check_float_rules(image, rules);
  const std::size_t w = image.width, h = image.height;
  const Thresholds t = step_4_thresholds(image, rules);
  ImageColours out;
  out.counts.pixels = w * h;
  std::vector<std::array<double, 3>> kept;
  for (std::size_t i = 0; i < w * h; ++i) {
    if (!rules.keep.empty() && !rules.keep[i]) {
      ++out.counts.masked;
      continue;
    }
    std::array<double, 3> v = checked_samples(image, i);
    bool saturated = false;
    for (double x : v) saturated = saturated || (rules.saturation && x >= *rules.saturation);
    if (saturated) {
      ++out.counts.saturated;
      continue;
    }
    ++out.counts.kept;
    subtract_black_exactly(v, rules.black_level, i, w);
    bool is_dark = false, is_bright = false;
    for (double x : v) {
      is_dark = is_dark || (sgn(t.dark) > 0 && Rational(x) < t.dark);
      is_bright = is_bright || (t.bright && Rational(x) > *t.bright);
    }
    if (is_dark || is_bright) {
      --out.counts.kept;
      ++(is_dark ? out.counts.dark : out.counts.bright);
      continue;
    }
    kept.push_back(v);
  }
  return float_colour_set(std::move(kept), rules.colour_set, std::move(out));
}

}  // namespace gmcc
