#include <gmcc/validation/gehler_shi_experiment.h>

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/convex_hull.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gmcc {
namespace {

// One image's usable patches: raw colours, patch numbers, and (divided by the image's ground
// truth) the canonical chromaticities they give.
struct Usable {
  const ChartImage* image = nullptr;
  std::vector<Colour> colours;
  std::vector<std::uint32_t> ids;
  std::vector<Point2> canonical;
};

TestLight test_light(const Usable& u, const std::string& group, std::size_t canonical) {
  const Colour& e = u.image->truth;
  TestLight t;
  t.name = u.image->name;
  t.group = group;
  t.canonical = canonical;
  t.surfaces = u.colours;
  t.surface_ids = u.ids;
  t.true_map = {Rational(e.b / e.r), Rational(e.b / e.g)};
  t.true_diagonal_map = {Rational(1 / e.r), Rational(1 / e.g), Rational(1 / e.b)};
  return t;
}

double tau(const ChartImage& image) {  // log2(e_b / e_r): the grouping only, not geometry
  return std::log2(to_double_nearest(Rational(image.truth.b / image.truth.r)));
}

}  // namespace

std::string to_string(GehlerShiProtocol p) { return p == GehlerShiProtocol::paper ? "paper" : "leave-one-out"; }

GehlerShiProtocol gehler_shi_protocol_from_string(const std::string& name) {
  if (name == "leave-one-out") return GehlerShiProtocol::leave_one_out;
  if (name == "paper") return GehlerShiProtocol::paper;
  throw std::invalid_argument("unknown protocol \"" + name + "\" (leave-one-out, paper)");
}

std::vector<std::string> gehler_shi_protocol_names() {
  return {to_string(GehlerShiProtocol::leave_one_out), to_string(GehlerShiProtocol::paper)};
}

namespace {

// One camera's chart images with their usable patches (inside (dark, clip), not excluded), and
// the counts of what was dropped.
std::vector<Usable> usable_images(const ChartDataset& data, const std::string& camera, const GehlerShiOptions& o,
                                  GehlerShiCamera& info) {
  std::vector<Usable> images;
  for (const ChartImage& im : data.images) {
    if (im.camera != camera) continue;
    ++info.images;
    Usable& u = images.emplace_back();
    u.image = &im;
    for (std::size_t k = 0; k < chart_patches; ++k) {
      if (!im.patches[k]) {
        ++info.missing_patches;
        continue;
      }
      if (std::find(o.exclude_patches.begin(), o.exclude_patches.end(), k + 1) != o.exclude_patches.end()) {
        ++info.excluded_patches;
        continue;
      }
      const Colour& c = *im.patches[k];
      bool usable = true;
      for (const Rational* x : {&c.r, &c.g, &c.b}) usable = usable && *x > o.dark && *x < o.clip;
      if (!usable) {
        ++info.dropped_patches;
        continue;
      }
      u.colours.push_back(c);
      u.ids.push_back(static_cast<std::uint32_t>(k + 1));
      u.canonical.push_back(perspective_chromaticity(
          {Rational(c.r / im.truth.r), Rational(c.g / im.truth.g), Rational(c.b / im.truth.b)}));
    }
    info.usable_patches += u.colours.size();
  }
  return images;
}

// Leave-one-out: every image is a test light against the hull of the other images' patches.
void leave_one_out_lights(const std::vector<Usable>& images, const std::string& camera, ExperimentSetup& setup,
                          GehlerShiCamera& info) {
  // The all-images hull serves every image that has no patch at one of its vertices (taking
  // such an image out cannot change the hull); the others get the hull without them.
  std::vector<Point2> all;
  for (const Usable& u : images) all.insert(all.end(), u.canonical.begin(), u.canonical.end());
  const ConvexSet2 hull = convex_hull(all);
  info.hull_vertices = hull.vertices.size();
  const std::size_t shared = setup.canonical_chromaticity_sets.size();
  setup.canonical_chromaticity_sets.push_back(hull.vertices);
  for (std::size_t i = 0; i < images.size(); ++i) {
    const Usable& u = images[i];
    std::size_t canonical = shared;
    const bool at_vertex = std::any_of(u.canonical.begin(), u.canonical.end(), [&](const Point2& p) {
      return std::find(hull.vertices.begin(), hull.vertices.end(), p) != hull.vertices.end();
    });
    if (at_vertex) {
      std::vector<Point2> others;
      for (std::size_t j = 0; j < images.size(); ++j)
        if (j != i) others.insert(others.end(), images[j].canonical.begin(), images[j].canonical.end());
      canonical = setup.canonical_chromaticity_sets.size();
      setup.canonical_chromaticity_sets.push_back(convex_hull(others).vertices);
      ++info.recomputed_hulls;
    }
    setup.lights.push_back(test_light(u, camera, canonical));
  }
}

// The paper's protocol: a daylight chart as the canonical gamut, yellowish and bluish lights tested.
void paper_lights(const std::vector<Usable>& images, const std::string& camera, ExperimentSetup& setup,
                  GehlerShiCamera& info) {
  // Daylight: τ >= 0. Its lower median; the 3 daylight images nearest it make the chart.
  std::vector<std::size_t> daylight;
  for (std::size_t i = 0; i < images.size(); ++i)
    if (tau(*images[i].image) >= 0 && !images[i].colours.empty()) daylight.push_back(i);
  if (daylight.empty())
    throw std::invalid_argument("camera \"" + camera + "\" has no daylight image (log2(b/r) >= 0)");
  std::vector<double> taus;
  for (std::size_t i : daylight) taus.push_back(tau(*images[i].image));
  std::sort(taus.begin(), taus.end());
  const double median = taus[(taus.size() - 1) / 2];
  std::stable_sort(daylight.begin(), daylight.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(tau(*images[a].image) - median) < std::abs(tau(*images[b].image) - median);
  });
  daylight.resize(std::min<std::size_t>(3, daylight.size()));
  std::sort(daylight.begin(), daylight.end());
  std::vector<Point2> chart;
  for (std::size_t i : daylight) {
    chart.insert(chart.end(), images[i].canonical.begin(), images[i].canonical.end());
    info.canonical_images.push_back(images[i].image->name);
  }
  const std::size_t canonical = setup.canonical_chromaticity_sets.size();
  const ConvexSet2 hull = convex_hull(chart);
  info.hull_vertices = hull.vertices.size();
  setup.canonical_chromaticity_sets.push_back(hull.vertices);
  std::vector<TestLight> yellowish, bluish;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const double t = tau(*images[i].image);
    if (std::find(daylight.begin(), daylight.end(), i) != daylight.end()) continue;
    if (t < -0.5) yellowish.push_back(test_light(images[i], camera + " yellowish", canonical));
    else if (t > median) bluish.push_back(test_light(images[i], camera + " bluish", canonical));
    else ++info.untested;
  }
  info.yellowish = yellowish.size();
  info.bluish = bluish.size();
  for (auto* group : {&yellowish, &bluish})
    for (TestLight& t : *group) setup.lights.push_back(std::move(t));
}

}  // namespace

GehlerShiSetup gehler_shi_setup(const ChartDataset& data, const GehlerShiOptions& o) {
  GehlerShiSetup out;
  ExperimentSetup& setup = out.setup;
  setup.name = "gehler-shi";
  setup.figure = o.protocol == GehlerShiProtocol::paper ? "Fig. 5 on measured Gehler-Shi charts"
                                                        : "Fig. 5 on measured Gehler-Shi charts, leave-one-out";
  setup.canonical_light = {1, 1, 1};
  setup.skip_short_lights = true;
  setup.baselines = true;
  setup.surface_indices = "chart patch numbers 1-24";
  for (std::uint32_t k : o.exclude_patches)
    if (k < 1 || k > chart_patches)
      throw std::invalid_argument("patch " + std::to_string(k) + " does not exist (patches are 1-24)");
  for (const std::string& camera : o.cameras) {
    GehlerShiCamera info;
    info.camera = camera;
    const std::vector<Usable> images = usable_images(data, camera, o, info);
    if (info.usable_patches == 0 && info.dropped_patches + info.excluded_patches > 0)
      throw GehlerShiNothingUsable(
          "camera \"" + camera + "\": no usable patch is left of its " + std::to_string(info.images) + " images: " +
          std::to_string(info.dropped_patches) + " patches have a channel at or below dark " + to_string(o.dark) +
          " or at or above clip " + to_string(o.clip) +
          (info.excluded_patches ? ", " + std::to_string(info.excluded_patches) + " are excluded" : std::string()));
    if (info.usable_patches == 0)
      throw std::invalid_argument("camera \"" + camera + "\" has no usable patches in the data");

    if (o.protocol == GehlerShiProtocol::leave_one_out) leave_one_out_lights(images, camera, setup, info);
    else paper_lights(images, camera, setup, info);
    out.cameras.push_back(std::move(info));
  }
  return out;
}

}  // namespace gmcc
