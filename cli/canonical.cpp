#include "canonical.h"

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/input/text_file.h>
#include <gmcc/photo/learn_canonical.h>

#include <filesystem>
#include <algorithm>
#include <map>
#include <set>

#include "option_choices.h"
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
  cmd->add_option("--space", o.space,
                  "2d: the hull of the white-balanced chromaticities, written as chromaticity "
                  "lifts r/b,g/b,1 (the perspective route); 3d: the hull of the white-balanced "
                  "pixel colours, written as r,g,b (3-D gamut mapping, estimate --space 3d)")
      ->check(CLI::IsMember(space_choices))
      ->capture_default_str();
  cmd->add_option("--intensity", o.intensity,
                  "3d: max (each image scaled so that its largest white-balanced channel is 1) "
                  "or none")
      ->check(CLI::IsMember(canonical_intensity_names()))
      ->capture_default_str();
  add_pixel_options(*cmd, o.pixels);
  return cmd;
}

int run_canonical(const CanonicalOptions& o) {
  const bool space_3d = o.space == "3d";
  PixelOptions pixel_options = o.pixels;
  if (space_3d) {
    if (o.pixels.command && o.pixels.command->count("--colour-set") && o.pixels.colour_set == "hull")
      throw InputError("--colour-set", 0, "hull passes chromaticity lifts; --space 3d learns from pixel colours (hull-3d or distinct)");
    if (!(o.pixels.command && o.pixels.command->count("--colour-set"))) pixel_options.colour_set = "hull-3d";
  } else if (o.pixels.command && o.pixels.command->count("--intensity")) {
    throw InputError("--intensity", 0, "applies to --space 3d (chromaticities have no intensity)");
  }
  const PixelSettings settings = pixel_settings(pixel_options);
  const std::map<std::string, TruthRow> truths = truth_rows_by_image(read_truth_table(o.truths_path));
  std::optional<PendingFile> out;
  if (!o.out_path.empty()) out.emplace(o.out_path);
  const bool lifts = !space_3d && settings.run.rules.colour_set == ColourSet::hull && settings.run.rules.bin == 1;
  CanonicalLearner2 learner2;
  CanonicalLearner3 learner3(canonical_intensity_from_string(o.intensity));
  std::set<std::array<Rational, 3>> colours;  // 2-D with distinct colours: every one
  std::uint64_t pixels = 0;
  for (const std::string& path : o.images) {
    const TruthRow& row = truth_of_image(truths, path, o.truths_path);
    const Colour& e = row.light;
    const ImageColours c = image_colours_of(path, settings, nullptr, nullptr, &row, o.truths_path);
    pixels += c.counts.kept;
    if (space_3d) {
      learner3.add(c.colours, e);
    } else if (lifts) {
      learner2.add(c.colours, e);
    } else {
      for (const Colour& p : c.colours) {
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
  if (space_3d) {
    const std::vector<Colour> gamut = learner3.gamut();
    if (std::all_of(gamut.begin(), gamut.end(), [](const Colour& c) { return sgn(c.r) == 0 && sgn(c.g) == 0 && sgn(c.b) == 0; }))
      throw InputError(o.images.size() == 1 ? o.images.front() : "--from-images", 0,
                       "no canonical colour: every kept pixel of " +
                           std::string(o.images.size() == 1 ? "the image" : "every image") +
                           " is black (0,0,0) after the black level, so the 3-D gamut would be empty or black only");
    text += o.intensity == "max" ? ", each image scaled so that its largest channel is 1" : "";
    text += "; the vertices of the hull of their colours (3-D)\nr,g,b\n";
    for (const Colour& c : gamut) text += exact(c.r) + "," + exact(c.g) + "," + exact(c.b) + "\n";
  } else if (lifts) {
    text += "; the vertices of the hull of their chromaticities, as chromaticity lifts r/b,g/b,1\n";
    text += "r/b,g/b,1\n";
    for (const Point2& v : learner2.gamut()) text += exact(v.x) + "," + exact(v.y) + ",1\n";
  } else {
    text += "; every distinct colour\nr,g,b\n";
    for (const auto& c : colours) text += exact(c[0]) + "," + exact(c[1]) + "," + exact(c[2]) + "\n";
  }
  if (out) out->commit(text);
  else write_stdout(text);
  return 0;
}

}  // namespace gmcc::cli
