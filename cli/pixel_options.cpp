#include "pixel_options.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/input/input_error.h>

#include "integer_option.h"

#include <filesystem>
#include <optional>
#include <tuple>

namespace gmcc::cli {
namespace {

// "x1,y1,x2,y2,..." in pixel coordinates, read exactly.
std::vector<Point2> polygon(const std::string& text) {
  std::vector<Rational> numbers;
  for (std::size_t start = 0;;) {
    const auto comma = text.find(',', start);
    const std::string field = text.substr(start, comma - start);
    try {
      numbers.push_back(parse_rational(field));
    } catch (const std::invalid_argument& e) {
      throw InputError("--exclude-polygon", 0, quoted_text(text) + ": " + e.what());
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (numbers.size() % 2 != 0 || numbers.size() < 6)
    throw InputError("--exclude-polygon", 0,
                     quoted_text(text) + ": expected x1,y1,x2,y2,x3,y3[,...], 3 or more vertices");
  std::vector<Point2> p;
  for (std::size_t i = 0; i < numbers.size(); i += 2) p.push_back({numbers[i], numbers[i + 1]});
  return p;
}

// A fraction in [0, 1], read exactly; empty text keeps `given`.
std::optional<Rational> fraction_option(const char* name, const std::string& text,
                                        std::optional<Rational> given) {
  if (text.empty()) return given;
  Rational f;
  try {
    f = parse_rational(text);
  } catch (const std::invalid_argument& e) {
    throw InputError(name, 0, quoted_text(text) + ": " + e.what());
  }
  if (sgn(f) < 0 || f > 1) throw InputError(name, 0, quoted_text(text) + ": expected a fraction from 0 to 1");
  return f;
}

}  // namespace

void add_images_argument(CLI::App& cmd, std::vector<std::string>& images) {
  cmd.add_option("images", images, "image files: linear RGB PNG or TIFF, or camera raw files (DNG, CR2, NEF, ... through LibRaw)")->required();
}

CLI::Option* add_truths_option(CLI::App& cmd, std::string& path, const std::string& use) {
  return cmd.add_option("--truths", path,
                        "CSV with header image,r,g,b: each image's true light (image as given on the "
                        "command line, or its file name)" + use);
}

void add_pixel_options(CLI::App& cmd, PixelOptions& o) {
  o.command = &cmd;
  cmd.add_option("--black-level", o.black_level, "subtracted from every channel, 0 to 65535 (a raw file: replaces its own, subtracted from every photosite)")
      ->capture_default_str();
  cmd.add_option("--saturation", o.saturation,
                 "drop pixels with any raw channel at or above this: a value (a raw file: its white level, replacing its own), max (the file's "
                 "largest code, 2^bits - 1) or none")
      ->capture_default_str();
  cmd.add_option("--exclude-polygon", o.exclude_polygons,
                 "x1,y1,x2,y2,x3,y3[,...]: exclude the pixels whose centres lie in this polygon "
                 "(pixel coordinates, y down; repeatable), e.g. a chart's four corners");
  cmd.add_option("--mask", o.mask_path,
                 "a PNG or TIFF of the image's size: pixels where it is 0 in every channel are "
                 "excluded");
  cmd.add_option("--dark", o.dark,
                 "drop pixels with a channel below this after the black level, 0 to 65535")
      ->capture_default_str();
  for (const auto& [name, value, side, example] : {std::tuple{"--dark-fraction", &o.dark_fraction, "below", "5/255"},
                                                   std::tuple{"--bright-fraction", &o.bright_fraction, "above", "245/255"}})
    cmd.add_option(name, *value,
                   std::string("drop pixels with a channel ") + side + " this fraction (0 to 1, e.g. " + example +
                       ") of the image's largest value after the black level");
  cmd.add_option("--pixel-rule", o.pixel_rule,
                 "none, or gijsenij: Gijsenij et al. (2010)'s rule, the image rescaled to a "
                 "maximum of 255 and pixels with a channel below 5 or above 245 dropped "
                 "(--dark-fraction 5/255 --bright-fraction 245/255)")
      ->check(CLI::IsMember({"none", "gijsenij"}))
      ->capture_default_str();
  cmd.add_option("--prefilter", o.prefilter,
                 "smooth the image with a Gaussian of this sigma (pixels, 0 to 64) before taking the "
                 "kept pixels' colours; 0 for none")
      ->capture_default_str();
  cmd.add_option("--bin", o.bin,
                 "average the kept pixels of each BxB block into one colour, 1 to 4096")
      ->capture_default_str();
  cmd.add_option("--colour-set", o.colour_set,
                 "the colours passed on: hull (the pixels whose chromaticities are vertices of "
                 "the exact chromaticity hull: all the 2-D feasible set depends on, passed as "
                 "chromaticity lifts), distinct (every distinct colour, at most 10^6) or hull-3d "
                 "(the colours on their exact 3-D hull: all the 3-D feasible set depends on)")
      ->check(CLI::IsMember(colour_set_names()))
      ->capture_default_str();
}

PixelSettings pixel_settings(const PixelOptions& o) {
  PixelSettings s;
  PixelRules& r = s.run.rules;
  r.black_level = static_cast<std::uint32_t>(integer_option("--black-level", o.black_level, 0, 65535));
  s.run.black_level_given = o.command && o.command->count("--black-level");
  if (o.saturation == "max") {
    s.run.saturation_max = true;
  } else if (o.saturation != "none") {
    r.saturation = static_cast<std::uint32_t>(integer_option("--saturation", o.saturation, 1, 65536));
  }
  for (const std::string& text : o.exclude_polygons) r.exclude_polygons.push_back(polygon(text));
  r.bin = static_cast<std::uint32_t>(integer_option("--bin", o.bin, 1, 4096));
  r.colour_set = colour_set_from_string(o.colour_set);
  if (const auto dark = integer_option("--dark", o.dark, 0, 65535)) r.dark_below = static_cast<std::uint32_t>(dark);
  if (o.pixel_rule == "gijsenij") {
    for (const char* name : {"--dark-fraction", "--bright-fraction"})
      if (o.command && o.command->count(name))
        throw InputError(name, 0, "--pixel-rule gijsenij sets it (5/255 and 245/255); give one or the other");
    r = gijsenij_pixel_rules(std::move(r));
  }
  {
    Rational sigma;
    try {
      sigma = parse_rational(o.prefilter);
    } catch (const std::invalid_argument& e) {
      throw InputError("--prefilter", 0, quoted_text(o.prefilter) + ": " + e.what());
    }
    if (sgn(sigma) < 0 || sigma > 64) throw InputError("--prefilter", 0, "expected a sigma from 0 to 64 pixels");
    r.prefilter_sigma = to_double_nearest(sigma);
    if (r.prefilter_sigma > 0 && r.bin > 1)
      throw InputError("--prefilter", 0, "not with --bin: give one or the other");
  }
  r.dark_below_fraction = fraction_option("--dark-fraction", o.dark_fraction, r.dark_below_fraction);
  r.bright_above_fraction = fraction_option("--bright-fraction", o.bright_fraction, r.bright_above_fraction);
  if (r.bin > 1 && o.command && o.command->count("--colour-set"))
    throw InputError("--colour-set", 0,
                     "with --bin the binned colours are passed as they are (their hull is taken "
                     "by the geometry); give one of --bin or --colour-set");
  if (!o.mask_path.empty()) {
    s.mask = read_mask_image(o.mask_path);
    s.mask_path = o.mask_path;
  }
  return s;
}

ImageColours image_colours_of(const std::string& path, const PixelSettings& s, RgbImage* image_out,
                              PixelRules* rules_out, const TruthRow* row, const std::string& truths_path,
                              RawImage* raw_out) {
  const ImagePixelRules own = row ? image_pixel_rules(*row) : ImagePixelRules{};
  CameraImage read = read_camera_image(path, levels_to_read(s.run, own));
  std::optional<RgbImage> own_mask;
  std::string own_mask_path;
  if (row && !row->mask.empty()) {
    own_mask_path = (std::filesystem::path(truths_path).parent_path() / row->mask).string();
    own_mask = read_mask_image(own_mask_path);
  }
  const RgbImage* mask = own_mask ? &*own_mask : s.mask ? &*s.mask : nullptr;
  PixelRules rules = rules_for_image(s.run, own, read, path, mask, own_mask ? own_mask_path : s.mask_path);
  RgbImage& image = read.image;
  ImageColours colours;
  try {
    colours = image_colours(image, rules);
  } catch (const std::length_error& e) {
    throw InputError(path, 0, std::string(e.what()) + " (--colour-set hull, --bin)");
  } catch (const std::invalid_argument& e) {  // the rules against this image (polygon work)
    throw InputError(path, 0, e.what());
  }
  if (colours.colours.empty())
    throw InputError(path, 0,
                     "no usable pixel after the mask, saturation and dark or bright rules (" +
                         std::to_string(colours.counts.masked) + " masked, " +
                         std::to_string(colours.counts.saturated) + " saturated, " +
                         std::to_string(colours.counts.dark) + " dark, " +
                         std::to_string(colours.counts.bright) + " bright" +
                         (colours.counts.no_chromaticity
                              ? ", " + std::to_string(colours.counts.no_chromaticity) +
                                    " distinct colours with b = 0"
                              : std::string()) +
                         ")");
  if (image_out) *image_out = std::move(image);
  if (rules_out) *rules_out = std::move(rules);
  if (raw_out) *raw_out = std::move(read.raw);
  return colours;
}

}  // namespace gmcc::cli
