#include "select_3d.h"

#include "json_output.h"

#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/illumination_cone_3d.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/input/colour_csv.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <sstream>

namespace gmcc::cli {
namespace {

Json exact3(const Point3& p) { return Json::array({to_string(p.x), to_string(p.y), to_string(p.z)}); }
Json approx3(const Point3& p) {
  return Json::array({to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)});
}

Json selection_json(const Selection3& s) {
  const MapEstimate3& e = s.estimate;
  Json j;
  j["map"] = Json::array({e.map[0], e.map[1], e.map[2]});
  if (e.exact) j["map_exact"] = exact3(*e.exact);
  j["error_bound"] = e.error_bound;
  j["enclosure"] = Json::array();
  for (const auto& c : e.enclosure) j["enclosure"].push_back(Json::array({c[0], c[1]}));
  j["method"] = e.method;
  if (e.edge_root) {
    const auto& r = *e.edge_root;
    j["exact_form"] = {{"edge_from", exact3(r.from)},
                       {"edge_to", exact3(r.to)},
                       {"quadratic", Json::array({to_string(r.a), to_string(r.b), to_string(r.c)})},
                       {"t", r.sign > 0 ? "(-b + sqrt(b^2 - 4ac)) / (2a)" : "(-b - sqrt(b^2 - 4ac)) / (2a)"}};
  }
  if (s.worst_case_deg) j["worst_case_deg"] = *s.worst_case_deg;
  return j;
}

// CRULE on F3 ∩ the cone of the plausible lights' maps (the illumination constraint in 3-D,
// Barnard's ECRULE; illumination_cone_3d.h), the canonical light white: F3 exact with its volume,
// max-volume and the centroid exact, as crule_3d.
Crule3d constrained_crule_3d(const ColourTable& canonical, const ColourTable& image, CanonicalBlack black,
                             const std::string& lights_path) {
  const std::vector<Colour> lights = plausible_lights(lights_path);
  const CanonicalConstraints3 prepared(canonical.colours, black);
  std::vector<GamutConstraint3> types{{&prepared, &image.colours}};
  const CanonicalConstraints3 cone =
      illumination_cone_3d(lights, Colour{Rational(1), Rational(1), Rational(1)}, feasible_set_3d_box(types));
  types.push_back({&cone, &illumination_cone_colour()});
  const LazyConvexSet3 F = feasible_set_3d_lazy(types);
  Crule3dSelections s = crule_3d_selections(F, Crule3dRoute::exact);
  Crule3d r;
  r.feasible = F.exact();
  r.volume = volume(r.feasible);
  r.max_volume = std::move(s.max_volume), r.centroid = std::move(s.centroid);
  return r;
}

}  // namespace

int run_select_3d(const SelectOptions& o) {
  // The options that cannot apply to the 3-D route were refused by select_settings.
  const CanonicalBlack black = canonical_black_from_string(o.black);
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  const ColourTable image = read_colour_csv(o.image_path);
  require_pixel_colours(canonical, "select --space 3d");
  require_pixel_colours(image, "select --space 3d");
  Crule3d r;
  try {
    r = o.illuminants_path.empty() ? crule_3d(canonical.colours, image.colours, black)
                                   : constrained_crule_3d(canonical, image, black, o.illuminants_path);
  } catch (const UnboundedFeasibleSet& e) {
    throw InputError(o.image_path, 0, e.what());
  }

  std::ostringstream out;
  if (o.json) {
    Json j;
    j["space"] = "3d";
    Json f;
    f["kind"] = to_string(r.feasible.kind);
    f["vertices"] = Json::array();
    f["vertices_approx"] = Json::array();
    for (const Point3& v : r.feasible.vertices) {
      f["vertices"].push_back(exact3(v));
      f["vertices_approx"].push_back(approx3(v));
    }
    f["faces"] = r.feasible.faces;
    f["volume"] = to_string(*r.volume);
    f["volume_approx"] = to_double_nearest(*r.volume);
    j["feasible_set"] = f;
    Json sel = Json::object();
    if (r.max_volume) sel["max_volume"] = selection_json(*r.max_volume);
    if (r.centroid) sel["centroid"] = selection_json(*r.centroid);
    j["selections"] = sel;
    j["canonical_gamut"] = {{"black", to_string(black)},
                            {"colours", canonical.colours.size()}};
    j["input"] = {{"canonical_colours", canonical.colours.size()},
                  {"image_colours", image.colours.size()}};
    if (!o.illuminants_path.empty()) j["constraint"] = {{"illuminants_file", o.illuminants_path}};
    finish_document(j);
    out << j.dump(2) << "\n";
  } else {
    out << "3-D feasible set of diagonal maps (CRULE; canonical gamut "
        << (black == CanonicalBlack::include ? "with" : "without") << " black): "
        << to_string(r.feasible.kind) << ", " << r.feasible.vertices.size() << " vertices, "
        << r.feasible.faces.size() << " faces, volume " << fmt(to_double_nearest(*r.volume)) << "\n";
    if (r.feasible.kind == ConvexKind3::empty)
      out << "no diagonal map takes every image colour into the canonical gamut\n";
    auto line = [&out](const char* name, const Selection3& s) {
      const auto& m = s.estimate.map;
      out << "  " << name << "  (" << fmt(m[0]) << ", " << fmt(m[1]) << ", " << fmt(m[2]) << ")";
      if (s.worst_case_deg) out << "  worst case " << fmt(*s.worst_case_deg) << " deg";
      out << (s.estimate.exact ? "  exact" : "  certified ± " + fmt(s.estimate.error_bound)) << "\n";
    };
    if (r.max_volume) line("max-volume", *r.max_volume);
    if (r.centroid) line("centroid  ", *r.centroid);
  }
  std::cout << out.str() << std::flush;
  return 0;
}

}  // namespace gmcc::cli
