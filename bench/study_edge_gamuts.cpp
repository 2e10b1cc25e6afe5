// Edge-based and intersection gamut mapping on a folder of photographs (issue 26 item 3;
// docs/photographs.md §5): for each image, Gijsenij, Gevers & van de Weijer (2010)'s pixel, edge
// (1st- and 2nd-order magnitudes) and intersection ("1-jet": pixel ∩ 1st order; "2-jet": with the
// 2nd order) gamut mapping with max-trace and max-volume, every feasible set exact, canonical
// gamuts learned from the other folds (image index modulo 3 in gt.csv order).
//
//   study_edge_gamuts CAMERA_DIR [SIGMA]
//
// CAMERA_DIR holds 16-bit linear PNGs <image>.png and gt.csv (image,camera,r,g,b), black level
// already subtracted (the layout of bench/photo_speed.py). Pixels by Gijsenij et al.'s rule, no
// saturation level. Each training image is scaled so that its largest white-balanced pixel
// channel is 1, and its edge colours by the same factor, so that every type's canonical gamut
// has one intensity scale and the joint feasible set is meaningful. A method with no positive map
// takes grey world's estimate on the same pixels and counts the image as empty. Prints one line
// per method: mean and median recovery angular error (degrees) and the empty count.
#include <gmcc/geometry/rational.h>
#include <gmcc/input/image_file.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/grey_edge.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/validation/error_statistics.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

struct Image {
  RgbImage pixels;
  Colour light;
  ImageColours colours, edge1, edge2;
  std::array<double, 3> grey_world{};
  Rational scale;  // white_balanced_maximum of its pixel colours
};


}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: study_edge_gamuts CAMERA_DIR [SIGMA]\n";
    return 2;
  }
  const std::string dir = argv[1];
  EdgeRules first, second;
  first.sigma = second.sigma = argc > 2 ? std::stod(argv[2]) : 1.0;
  second.order = DerivativeOrder::second;
  PixelRules rules = gijsenij_pixel_rules();
  rules.colour_set = ColourSet::hull_3d;

  std::vector<Image> images;
  std::ifstream gt(dir + "/gt.csv");
  std::string line;
  std::getline(gt, line);
  while (std::getline(gt, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::stringstream s(line);
    std::string f[5];
    for (std::string& x : f) std::getline(s, x, ',');
    Image im;
    im.pixels = read_image(dir + "/" + f[0] + ".png");
    im.light = {parse_rational(f[2]), parse_rational(f[3]), parse_rational(f[4])};
    im.colours = image_colours(im.pixels, rules);
    im.edge1 = edge_colours(im.pixels, rules, first);
    im.edge2 = edge_colours(im.pixels, rules, second);
    const KeptPixels kept = kept_pixels(im.pixels, rules);
    const auto g = grey_edge_estimate(im.pixels, 0, kept.kept, baseline_parameters(Baseline::grey_world));
    if (g) im.grey_world = *g;
    im.scale = white_balanced_maximum(im.colours.colours, im.light);
    images.push_back(std::move(im));
  }

  const std::vector<std::string> methods = {"pixel", "edge-1", "edge-2", "1-jet", "2-jet"};
  std::map<std::string, std::vector<double>> errors;
  std::map<std::string, int> empty;
  for (int fold = 0; fold < 3; ++fold) {
    CanonicalLearner3 pixel, edge1, edge2;  // every type divided by the pixel factor
    for (std::size_t i = 0; i < images.size(); ++i) {
      const Image& im = images[i];
      if (static_cast<int>(i % 3) == fold || sgn(im.scale) == 0) continue;
      pixel.add(im.colours.colours, im.light, im.scale);
      if (!im.edge1.colours.empty()) edge1.add(im.edge1.colours, im.light, im.scale);
      if (!im.edge2.colours.empty()) edge2.add(im.edge2.colours, im.light, im.scale);
    }
    const CanonicalConstraints3 cp(pixel.gamut()), ce1(edge1.gamut()), ce2(edge2.gamut());
    for (std::size_t i = fold; i < images.size(); i += 3) {
      const Image& im = images[i];
      const GamutConstraint3 p{&cp, &im.colours.colours}, e1{&ce1, &im.edge1.colours}, e2{&ce2, &im.edge2.colours};
      const std::map<std::string, std::vector<GamutConstraint3>> by_method = {
          {"pixel", {p}}, {"edge-1", {e1}}, {"edge-2", {e2}}, {"1-jet", {p, e1}}, {"2-jet", {p, e1, e2}}};
      for (const std::string& m : methods) {
        std::optional<ImageEstimate3> e;
        try {
          e = estimate_3d(by_method.at(m), Estimate3Options{{Rule3::max_volume, Rule3::max_trace}});
        } catch (const std::exception&) {  // no colour of a type, or an unbounded set
        }
        for (Rule3 rule : {Rule3::max_trace, Rule3::max_volume}) {
          const std::string name = m + " " + to_string(rule);
          std::array<double, 3> light = im.grey_world;
          if (e && (*e)[rule] && (*e)[rule]->light) light = *(*e)[rule]->light;
          else ++empty[name];
          errors[name].push_back(recovery_angular_error_deg(light, im.light));
        }
      }
    }
  }
  std::printf("%s: %zu images, sigma %g\n", dir.c_str(), images.size(), first.sigma);
  for (const std::string& m : methods)
    for (Rule3 rule : {Rule3::max_trace, Rule3::max_volume}) {
      const std::string name = m + " " + to_string(rule);
      const ErrorStatistics e = error_statistics(errors[name]);
      std::printf("  %-22s mean %5.2f  median %5.2f  empty %d\n", name.c_str(), e.mean, e.median, empty[name]);
    }
}
