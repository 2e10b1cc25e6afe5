/// \file pixels.cpp
/// Images from Python through the pixel rules (pixels.h).

#include "pixels.h"

#include "convert.h"

#include <gmcc/photo/image_pixels.h>

#include <cstring>
#include <optional>
#include <type_traits>

namespace gmcc::python {
namespace {

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

PyImageColours run_pixel_rules(const RgbImage& img, std::vector<bool> keep, const PixelArgs& args);

// A fraction argument in [0, 1], exactly; None stays absent.
std::optional<Rational> fraction_from(py::handle x, const char* name) {
  if (x.is_none()) return std::nullopt;
  const Rational f = number_from(x, name);
  if (sgn(f) < 0 || f > 1) throw py::value_error(std::string(name) + ": must be from 0 to 1");
  return f;
}

// Step 4's fractions from dark_fraction, bright_fraction and pixel_rule.
void fractions_of_impl(const PixelArgs& args, std::optional<Rational>& dark, std::optional<Rational>& bright) {
  if (args.pixel_rule != "none" && args.pixel_rule != "gijsenij")
    throw py::value_error("pixel_rule: " + quoted_text(args.pixel_rule) + " is not one of none, gijsenij");
  if (args.pixel_rule == "gijsenij") {
    if (!args.dark_fraction.is_none() || !args.bright_fraction.is_none())
      throw py::value_error("pixel_rule: 'gijsenij' sets dark_fraction and bright_fraction (5/255, 245/255); give one or the other");
    const PixelRules g = gijsenij_pixel_rules();
    dark = g.dark_below_fraction;
    bright = g.bright_above_fraction;
    return;
  }
  dark = fraction_from(args.dark_fraction, "dark_fraction");
  bright = fraction_from(args.bright_fraction, "bright_fraction");
}

// The library's pixel rules on an image, with the GIL released; its input errors as ValueError.
template <class Image, class Rules>
PyImageColours colours_by_rules(const Image& img, const Rules& rules) {
  PyImageColours out;
  try {
    py::gil_scoped_release nogil;
    ImageColours c = image_colours(img, rules);
    out.colours = std::move(c.colours);
    out.set = c.set;
    out.counts = c.counts;
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("image: ") + e.what());
  }
  return out;
}

}  // namespace

void pixel_fractions(const PixelArgs& args, std::optional<Rational>& dark, std::optional<Rational>& bright) {
  fractions_of_impl(args, dark, bright);
}

double sigma_from(py::handle x) {
  const Rational s = number_from(x, "prefilter");
  if (sgn(s) < 0 || s > 64) throw py::value_error("prefilter: a sigma from 0 to 64 pixels");
  return to_double_nearest(s);
}

bool PixelArgs::plain() const {
  return mask.is_none() && saturation.is_none() && dark_fraction.is_none() && bright_fraction.is_none() &&
         pixel_rule == "none" && py::isinstance<py::int_>(black_level) && black_level.cast<long long>() == 0 &&
         py::isinstance<py::int_>(dark) && dark.cast<long long>() == 0 && sigma_from(prefilter) == 0;
}

ColourSet colour_set_from(const std::string& name) {
  try {
    return colour_set_from_string(name);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("colour_set: ") + e.what());
  }
}

bool is_image(py::handle x) { return py::isinstance<py::array>(x) && py::reinterpret_borrow<py::array>(x).ndim() == 3; }

namespace {

// `image_obj` as an (H, W, 3) array of unsigned integers or floats (at most double). \throws
// TypeError, ValueError.
py::array checked_image(py::handle image_obj) {
  if (!py::isinstance<py::array>(image_obj))
    throw py::type_error("image: expected a numpy array of shape (H, W, 3), got " +
                         std::string(py::str(py::type::handle_of(image_obj).attr("__name__"))));
  py::array image = py::reinterpret_borrow<py::array>(image_obj);
  if (image.ndim() != 3 || image.shape(2) != 3)
    throw py::value_error("image: expected an array of shape (H, W, 3), got " + shape_of(image));
  const char kind = image.dtype().kind();
  if (kind == 'b' || (kind != 'f' && kind != 'u' && kind != 'i'))
    throw py::type_error("image: dtype " + std::string(py::str(image.dtype())) +
                         " is not a real number type (expected unsigned integers or floats)");
  if (kind == 'f' && image.itemsize() > 8)
    throw py::type_error("image: dtype " + std::string(py::str(image.dtype())) + " has no exact double value");
  return image;
}

// The mask's kept pixels, row-major (empty: no mask). \throws TypeError, ValueError.
std::vector<bool> mask_of(const PixelArgs& args, const py::array& image, std::size_t h, std::size_t w) {
  py::module_ np = py::module_::import("numpy");
  std::vector<bool> keep;
  if (args.mask.is_none()) return keep;
  if (!py::isinstance<py::array>(args.mask))
    throw py::type_error("mask: expected a boolean numpy array of shape (H, W)");
  py::array mask = py::reinterpret_borrow<py::array>(args.mask);
  if (mask.dtype().kind() != 'b') throw py::type_error("mask: expected dtype bool, got " + std::string(py::str(mask.dtype())));
  if (mask.ndim() != 2 || mask.shape(0) != image.shape(0) || mask.shape(1) != image.shape(1))
    throw py::value_error("mask: shape " + shape_of(mask) + " does not match the image's (" + std::to_string(h) +
                          ", " + std::to_string(w) + ")");
  const py::array_t<bool, py::array::c_style> m = np.attr("ascontiguousarray")(mask);
  keep.assign(m.data(), m.data() + h * w);
  return keep;
}

// A float image's colours: the pixel rules with double levels, each of which must be exact.
PyImageColours float_image_colours(const py::array& image, std::size_t h, std::size_t w, std::vector<bool> keep,
                                   const PixelArgs& args) {
  py::module_ np = py::module_::import("numpy");
  FloatRgbImage img;
  img.width = w;
  img.height = h;
  const py::array_t<double, py::array::c_style> a = np.attr("ascontiguousarray")(image, "float64");
  img.samples.assign(a.data(), a.data() + h * w * 3);
  if (sigma_from(args.prefilter) > 0)
    throw py::value_error("prefilter: for integer images (8- or 16-bit samples); smooth a float image yourself");
  FloatPixelRules rules;
  rules.keep = std::move(keep);
  rules.colour_set = colour_set_from(args.colour_set);
  pixel_fractions(args, rules.dark_below_fraction, rules.bright_above_fraction);
  {
    const Rational d = number_from(args.dark, "dark");
    if (sgn(d) < 0) throw py::value_error("dark: must be >= 0");
    if (sgn(d) > 0) {
      rules.dark_below = to_double_nearest(d);
      if (Rational(*rules.dark_below) != d) throw py::value_error("dark: must be a double exactly for a float image");
    }
  }
  const Rational black = number_from(args.black_level, "black_level");
  if (sgn(black) < 0) throw py::value_error("black_level: must be >= 0");
  rules.black_level = to_double_nearest(black);
  if (Rational(rules.black_level) != black)  // exact: every double is a rational
    throw py::value_error("black_level: must be a double exactly for a float image");
  if (!args.saturation.is_none()) {
    const Rational s = number_from(args.saturation, "saturation");
    rules.saturation = to_double_nearest(s);
    if (sgn(s) < 0 || Rational(*rules.saturation) != s)
      throw py::value_error("saturation: must be >= 0 and a double exactly for a float image");
  }
  return colours_by_rules(img, rules);
}

// Integer samples: the library's 16-bit route (exact integer hull).
PyImageColours integer_image_colours(const py::array& image, char kind, std::size_t h, std::size_t w,
                                     std::vector<bool> keep, const PixelArgs& args) {
  py::module_ np = py::module_::import("numpy");
  RgbImage img;
  img.width = w;
  img.height = h;
  img.bits = 16;
  img.samples.resize(h * w * 3);
  if (kind == 'u' && image.itemsize() <= 2) {  // uint8, uint16: every value fits
    const py::array_t<std::uint16_t, py::array::c_style> a = np.attr("ascontiguousarray")(image, "uint16");
    if (!img.samples.empty()) std::memcpy(img.samples.data(), a.data(), img.samples.size() * sizeof(std::uint16_t));
    return run_pixel_rules(img, std::move(keep), args);
  }
  // Wider integers, each checked: unsigned ones as uint64 (2^64 − 1 is not −1), signed as int64.
  auto copy = [&](const auto* p) {
    for (std::size_t i = 0; i < h * w * 3; ++i) {
      bool negative = false;
      if constexpr (std::is_signed_v<std::remove_cv_t<std::remove_pointer_t<decltype(p)>>>) negative = p[i] < 0;
      if (negative || p[i] > 65535) {
        const std::size_t px = i / 3;
        throw py::value_error("image: pixel (row " + std::to_string(px / w) + ", column " + std::to_string(px % w) +
                              ") channel " + "rgb"[i % 3] + ": " + std::to_string(p[i]) +
                              " is outside 0..65535 (integer images are 8- or 16-bit linear samples)");
      }
      img.samples[i] = static_cast<std::uint16_t>(p[i]);
    }
  };
  if (kind == 'u') {
    const py::array_t<std::uint64_t, py::array::c_style> a = np.attr("ascontiguousarray")(image, "uint64");
    copy(a.data());
  } else {
    const py::array_t<std::int64_t, py::array::c_style> a = np.attr("ascontiguousarray")(image, "int64");
    copy(a.data());
  }
  return run_pixel_rules(img, std::move(keep), args);
}

}  // namespace

PyImageColours image_colours_of(py::handle image_obj, const PixelArgs& args) {
  py::array image = checked_image(image_obj);
  const char kind = image.dtype().kind();
  const std::size_t h = static_cast<std::size_t>(image.shape(0)), w = static_cast<std::size_t>(image.shape(1));
  std::vector<bool> keep = mask_of(args, image, h, w);
  if (kind == 'f') return float_image_colours(image, h, w, std::move(keep), args);
  return integer_image_colours(image, kind, h, w, std::move(keep), args);
}

namespace {
PyImageColours run_pixel_rules(const RgbImage& img, std::vector<bool> keep, const PixelArgs& args) {
  PixelRules rules;
  rules.keep = std::move(keep);
  rules.colour_set = colour_set_from(args.colour_set);
  rules.black_level = integer_in<std::uint32_t>(args.black_level, "black_level", 0, 65535);
  if (const auto d = integer_in<std::uint32_t>(args.dark, "dark", 0, 65535)) rules.dark_below = d;
  pixel_fractions(args, rules.dark_below_fraction, rules.bright_above_fraction);
  rules.prefilter_sigma = sigma_from(args.prefilter);
  if (!args.saturation.is_none()) rules.saturation = integer_in<std::uint32_t>(args.saturation, "saturation", 0, 65536);
  return colours_by_rules(img, rules);
}
}  // namespace


}  // namespace gmcc::python
