#include "canonical.h"

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/validation/input_error.h>
#include <gmcc/validation/colour_csv.h>
#include <gmcc/validation/text_file.h>

#include <filesystem>
#include <map>
#include <set>

#include "output_files.h"
#include "provenance.h"
#include "write_stdout.h"

namespace gmcc::cli {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// The truth file: a header `image,r,g,b`, then one line per image, its name (as given on the
// command line, or its file name) and its light, channels > 0, read exactly.
std::map<std::string, Colour> read_truths(const std::string& path) {
  const std::string text =
      read_text_file(path, {std::size_t(64) << 20, "truth file", "text lines image,r,g,b"});
  std::map<std::string, Colour> truths;
  std::string_view rest(text);
  bool header = false;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const auto end = rest.find('\n');
    const std::string_view line = trim(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string_view> f;
    for (std::size_t start = 0;;) {
      const auto comma = line.find(',', start);
      f.push_back(trim(line.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (!header) {
      if (f != std::vector<std::string_view>{"image", "r", "g", "b"})
        throw InputError(path, number, "expected the header image,r,g,b");
      header = true;
      continue;
    }
    if (f.size() != 4)
      throw InputError(path, number, "expected 4 values image,r,g,b, found " + std::to_string(f.size()));
    Rational c[3];
    static const char* names[] = {"r", "g", "b"};
    for (int k = 0; k < 3; ++k) {
      try {
        c[k] = parse_rational(f[1 + k]);
      } catch (const std::invalid_argument& e) {
        throw InputError(path, number, std::string(names[k]) + ": " + e.what());
      }
      if (sgn(c[k]) <= 0)
        throw InputError(path, number, std::string(names[k]) + " must be > 0 (a light's response)");
    }
    if (!truths.emplace(std::string(f[0]), Colour{c[0], c[1], c[2]}).second)
      throw InputError(path, number, "image " + quoted_text(f[0]) + " listed twice");
  }
  if (truths.empty()) throw InputError(path, 0, "no lights (expected lines image,r,g,b)");
  return truths;
}

std::string exact(const Rational& q) { return to_string(q); }

}  // namespace

CLI::App* add_canonical_command(CLI::App& app, CanonicalOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "canonical",
      "Make a canonical gamut: with --from-images, from linear camera images and their true "
      "lights (each image's pixels divided by its light, so the canonical light is white), "
      "written as a colour file for --canonical.");
  cmd->add_flag("--from-images", o.from_images, "learn the gamut from IMAGE... (required)")
      ->required();
  cmd->add_option("images", o.images, "image files (PNG or TIFF, linear RGB)")->required();
  cmd->add_option("--truths", o.truths_path,
                  "CSV with header image,r,g,b: each image's true light (image as given on the "
                  "command line, or its file name)")
      ->required();
  cmd->add_option("--out", o.out_path, "write the colour file here (default: stdout)");
  add_pixel_options(*cmd, o.pixels);
  return cmd;
}

int run_canonical(const CanonicalOptions& o) {
  const PixelSettings settings = pixel_settings(o.pixels);
  const std::map<std::string, Colour> truths = read_truths(o.truths_path);
  std::optional<PendingFile> out;
  if (!o.out_path.empty()) out.emplace(o.out_path);
  const bool hull = settings.rules.colour_set == ColourSet::hull && settings.rules.bin == 1;
  std::vector<Point2> points;     // hull: canonical chromaticities
  std::set<std::array<Rational, 3>> colours;  // otherwise: canonical colours, distinct
  std::uint64_t pixels = 0;
  for (const std::string& path : o.images) {
    auto t = truths.find(path);
    if (t == truths.end()) t = truths.find(std::filesystem::path(path).filename().string());
    if (t == truths.end())
      throw InputError(o.truths_path, 0,
                       "no light for image " + path + " (nor for its file name)");
    const Colour& e = t->second;
    const ImageColours c = image_colours_of(path, settings);
    pixels += c.counts.kept;
    for (const Colour& p : c.colours) {
      if (hull) {
        // (x, y, 1) with x = r/b, y = g/b: under a white light (r/e_r)/(b/e_b) = x·e_b/e_r.
        points.push_back({p.r * e.b / e.r, p.g * e.b / e.g});
      } else {
        colours.insert({p.r / e.r, p.g / e.g, p.b / e.b});
        if (colours.size() > max_colours)
          throw InputError(path, 0, "more than " + std::to_string(max_colours) +
                                        " distinct canonical colours (use --colour-set hull or --bin)");
      }
    }
  }
  std::string text = provenance_csv_line();
  text += "# gmcc canonical --from-images: " + std::to_string(o.images.size()) + " images, " +
          std::to_string(pixels) + " pixels kept, each divided by its image's light (the "
          "canonical light is white, 1,1,1)";
  if (hull) {
    const ConvexSet2 g = convex_hull(points);
    text += "; the vertices of the hull of their chromaticities, as r/b,g/b,1\n";
    text += "r,g,b\n";
    for (const Point2& v : g.vertices) text += exact(v.x) + "," + exact(v.y) + ",1\n";
  } else {
    text += "; every distinct colour\nr,g,b\n";
    for (const auto& c : colours) text += exact(c[0]) + "," + exact(c[1]) + "," + exact(c[2]) + "\n";
  }
  if (out) out->commit(text);
  else write_stdout(text);
  return 0;
}

}  // namespace gmcc::cli
