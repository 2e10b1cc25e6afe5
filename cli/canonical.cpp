#include "canonical.h"

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_lights.h>
#include <gmcc/input/text_file.h>

#include <filesystem>
#include <map>
#include <set>

#include "output_files.h"
#include "provenance.h"
#include "write_stdout.h"

namespace gmcc::cli {
namespace {

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
  add_images_argument(*cmd, o.images);
  add_truths_option(*cmd, o.truths_path, "")->required();
  cmd->add_option("--out", o.out_path, "write the colour file here (default: stdout)");
  add_pixel_options(*cmd, o.pixels);
  return cmd;
}

int run_canonical(const CanonicalOptions& o) {
  const PixelSettings settings = pixel_settings(o.pixels);
  const std::map<std::string, Colour> truths = read_image_lights(o.truths_path);
  std::optional<PendingFile> out;
  if (!o.out_path.empty()) out.emplace(o.out_path);
  const bool hull = settings.rules.colour_set == ColourSet::hull && settings.rules.bin == 1;
  std::vector<Point2> points;     // hull: canonical chromaticities
  std::set<std::array<Rational, 3>> colours;  // otherwise: canonical colours, distinct
  std::uint64_t pixels = 0;
  for (const std::string& path : o.images) {
    const Colour& e = light_of_image(truths, path, o.truths_path);
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
