/// \file module.cpp
/// gmcc._core: the pybind11 extension behind the Python package gmcc (docs/python.md). A thin
/// layer over the library: Python values are converted to exact C++ values (convert.h) while the
/// GIL is held, the library call runs with the GIL released, and its result is wrapped
/// (results.h). No geometry or selection is done here.

#include "convert.h"
#include "interrupt.h"
#include "photo.h"
#include "pixels.h"
#include "results.h"

#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/selection/worst_case_illuminant.h>
#include <gmcc/input/build_info.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/input/raw_file.h>
#include <gmcc/validation/camera_experiment.h>
#include <gmcc/validation/error_statistics.h>
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/gehler_shi.h>
#include <gmcc/validation/gehler_shi_experiment.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace gmcc::python {
namespace {

// ---- options (the command line's checks, with the Python argument names) ----

// The expansion of the canonical gamut (`expand`, `expand_policy`), checked as the command line
// checks --expand and --expand-policy.
Expansion expansion_from(py::handle expand, const std::string& expand_policy) {
  Expansion x;
  try {
    x.policy = expansion_policy_from_string(expand_policy);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("expand_policy: ") + e.what());
  }
  x.factor = number_from(expand, "expand");
  if (sgn(x.factor) < 0) throw py::value_error("expand: must be >= 0");
  if (sgn(x.factor) > 0 && x.policy == ExpansionPolicy::none)
    throw py::value_error("expand: needs expand_policy='centroid-clip' or 'multiplicative'");
  return x;
}

SelectSceneOptions scene_options(py::handle expand, const std::string& expand_policy, py::handle illuminants,
                                 py::handle canonical_illuminant, const std::string& on_empty,
                                 const std::string& mean3d, py::handle precision, py::handle order,
                                 py::handle samples, py::handle seed, bool illuminant_worst_case,
                                 const std::string& nonpositive_blue) {
  SelectSceneOptions o;
  try {
    o.on_empty = recovery_policy_from_string(on_empty);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("on_empty: ") + e.what());
  }
  if (nonpositive_blue != "drop" && nonpositive_blue != "reject")
    throw py::value_error("nonpositive_blue: " + quoted_text(nonpositive_blue) + " is not one of drop, reject");
  o.nonpositive_blue = nonpositive_blue == "reject" ? NonPositiveBluePolicy::reject : NonPositiveBluePolicy::drop;
  o.expansion = expansion_from(expand, expand_policy);
  if (o.on_empty == RecoveryPolicy::grow_canonical && o.expansion.policy == ExpansionPolicy::centroid_clip)
    throw py::value_error("on_empty: grow-canonical grows the gamut by the multiplicative policy; it cannot "
                          "continue a centroid-clip expansion (use expand_policy='multiplicative')");
  o.illuminant_worst_case = illuminant_worst_case;
  o.canonical_illuminant = light_from(canonical_illuminant, "canonical_illuminant");
  if (!illuminants.is_none()) o.illuminants = colours_from(illuminants, "illuminants");
  Mean3dOptions& m = o.mean3d;
  try {
    m.method = mean3d_method_from_string(mean3d);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("mean3d: ") + e.what());
  }
  // Read within the library's ranges (mean_3d.h), then the library's own check; only the names
  // are Python's.
  m.precision_bits = integer_in<unsigned>(precision, "precision", mean3d_precision_range);
  m.order = integer_in<unsigned>(order, "order", mean3d_order_range);
  m.samples = integer_in<std::uint64_t>(samples, "samples", mean3d_samples_range);
  m.seed = integer_in<std::uint64_t>(seed, "seed", mean3d_seed_range);
  try {
    check_options(m);
  } catch (const OptionError& e) {
    throw py::value_error(e.option + ": " + e.what());
  }
  return o;
}

// A SceneInputError as ValueError, naming the Python argument and the row (0-based).
[[noreturn]] void raise_scene_error(const SceneInputError& e) {
  static const char* names[] = {"canonical", "image", "illuminants", "truth",
                                "canonical_illuminant", "expand", "on_empty"};
  std::string m = names[static_cast<int>(e.input)];
  if (e.index) m += ": row " + std::to_string(*e.index);
  m += std::string(": ") + e.what();
  if (e.problem == SceneProblem::nonpositive_blue) m += "; use nonpositive_blue='drop' to skip such colours";
  throw py::value_error(m);
}

// Library calls with the GIL released; SceneInputError and std::invalid_argument as ValueError.
template <class F>
auto released(F f) {
  try {
    InterruptibleRelease nogil;
    return f();
  } catch (const SceneInputError& e) {
    raise_scene_error(e);
  }
}

// The 3-D mean's parameters with the library's defaults (Mean3dOptions).
#define GMCC_MEAN3D_PARAMETER_ARGS                                                                \
  py::arg("precision") = Mean3dOptions{}.precision_bits, py::arg("order") = Mean3dOptions{}.order, \
  py::arg("samples") = Mean3dOptions{}.samples, py::arg("seed") = Mean3dOptions{}.seed

#define GMCC_OPTION_ARGS                                                                          \
  py::arg("expand") = 0, py::arg("expand_policy") = "none", py::arg("illuminants") = py::none(),   \
  py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1), py::arg("on_empty") = "none",        \
  py::arg("mean3d") = to_string(Mean3dOptions{}.method), GMCC_MEAN3D_PARAMETER_ARGS,               \
  py::arg("illuminant_worst_case") = true,                                                         \
  py::arg("nonpositive_blue") = "drop"

std::shared_ptr<PreparedCanonical> prepare(py::handle canonical, py::handle expand, const std::string& expand_policy,
                                           py::handle illuminants, py::handle canonical_illuminant,
                                           const std::string& on_empty, const std::string& mean3d,
                                           py::handle precision, py::handle order, py::handle samples,
                                           py::handle seed, bool illuminant_worst_case,
                                           const std::string& nonpositive_blue) {
  const std::vector<Colour> colours = colours_from(canonical, "canonical");
  const SelectSceneOptions options =
      scene_options(expand, expand_policy, illuminants, canonical_illuminant, on_empty, mean3d, precision, order,
                    samples, seed, illuminant_worst_case, nonpositive_blue);
  return released([&] { return std::make_shared<PreparedCanonical>(prepare_canonical(colours, options)); });
}


// The prepared canonical side's per-scene choices with those given here (None: keep it).
SceneChoices scene_choices(const PreparedCanonical& canonical, const py::dict& given) {
  SceneChoices c = canonical.options;
  Mean3dOptions& m = c.mean3d;
  auto has = [&](const char* name) { return given.contains(name) && !given[name].is_none(); };
  if (has("mean3d")) {
    try {
      m.method = mean3d_method_from_string(given["mean3d"].cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("mean3d: ") + e.what());
    }
  }
  if (has("precision")) m.precision_bits = integer_in<unsigned>(given["precision"], "precision", mean3d_precision_range);
  if (has("order")) m.order = integer_in<unsigned>(given["order"], "order", mean3d_order_range);
  if (has("samples")) m.samples = integer_in<std::uint64_t>(given["samples"], "samples", mean3d_samples_range);
  if (has("seed")) m.seed = integer_in<std::uint64_t>(given["seed"], "seed", mean3d_seed_range);
  if (has("illuminant_worst_case")) c.illuminant_worst_case = given["illuminant_worst_case"].cast<bool>();
  try {
    check_options(m);
  } catch (const OptionError& e) {
    throw py::value_error(e.option + ": " + e.what());
  }
  return c;
}

Scene run_scene(const std::shared_ptr<PreparedCanonical>& canonical, py::handle image, py::handle truth,
                const PixelArgs& pixels, bool select, const SceneChoices* choices = nullptr) {
  Scene scene;
  scene.canonical = canonical;
  std::vector<Colour> colours;
  if (is_image(image)) {
    PyImageColours c = image_colours_of(image, pixels);
    scene.pixels = c.counts;
    colours = std::move(c.colours);
    if (colours.empty())
      throw py::value_error("image: no usable pixel (every pixel masked, saturated or with b = 0)");
  } else {
    if (!pixels.plain())
      throw py::value_error("mask, black_level, saturation and the dark and bright rules apply to an image of shape "
                            "(H, W, 3), not to colours");
    colours = colours_from(image, "image");
  }
  std::optional<Colour> t;
  if (!truth.is_none()) t = light_from(truth, "truth");
  scene.result = released([&] {
    if (!select) return scene_feasible_set(*canonical, colours);
    return choices ? select_scene(*canonical, colours, t, *choices) : select_scene(*canonical, colours, t);
  });
  return scene;
}

const ConvexSet2& nonempty(const ConvexSet2& F, const char* what) {
  if (F.kind == ConvexKind::empty) throw py::value_error(std::string(what) + ": the feasible set is empty");
  return F;
}

// ---- experiments ----

// One record per scene as columns (name -> list or array), in ExperimentResult::scenes order.
// `setup`: given for an experiment whose lights are grouped (gehler-shi): then a `group` column
// after `light`, and each rule's `truth_in_feasible_set`. Baselines, when the run has them, follow
// the rules: their map and errors (no worst case: a baseline has no feasible set).
py::dict records_columns(const ExperimentResult& r, const ExperimentSetup* setup = nullptr) {
  const std::size_t n = r.scenes.size();
  py::dict cols;
  std::vector<std::string> light(n), kind(n), drawn(n);
  std::vector<std::int64_t> surfaces(n), scene(n);
  std::vector<double> area(n);
  for (std::size_t i = 0; i < n; ++i) {
    const SceneRecord& s = r.scenes[i];
    light[i] = r.lights[s.light];
    kind[i] = to_string(s.kind);
    surfaces[i] = s.surfaces;
    scene[i] = static_cast<std::int64_t>(s.scene);
    area[i] = s.area;
    for (std::size_t k = 0; k < s.drawn.size(); ++k) drawn[i] += (k ? " " : "") + std::to_string(s.drawn[k]);
  }
  cols["light"] = light;
  if (setup) {
    std::vector<std::string> group(n);
    for (std::size_t i = 0; i < n; ++i) {
      const TestLight& t = setup->lights.at(r.scenes[i].light);
      group[i] = t.group.empty() ? t.name : t.group;
    }
    cols["group"] = group;
  }
  cols["surfaces"] = py::array(py::cast(surfaces));
  cols["scene"] = py::array(py::cast(scene));
  cols["kind"] = kind;
  cols["area"] = py::array(py::cast(area));
  cols["drawn"] = drawn;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Rules (k < rules) and then baselines: the map and errors of one estimate per scene, NaN
  // where it gave none.
  for (std::size_t k = 0; k < r.rules.size() + r.baselines.size(); ++k) {
    const bool baseline = k >= r.rules.size();
    std::vector<double> mx(n, nan), my(n, nan), err(n, nan), wc(n, nan), il(n, nan), rep(n, nan);
    std::vector<std::uint8_t> in_f(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const std::vector<RuleRecord>& records = baseline ? r.scenes[i].baselines : r.scenes[i].rules;
      const std::size_t j = baseline ? k - r.rules.size() : k;
      if (j >= records.size() || !records[j].scored) continue;
      const RuleRecord& q = records[j];
      mx[i] = q.map[0];
      my[i] = q.map[1];
      err[i] = q.error_deg;
      wc[i] = q.worst_case_deg;
      in_f[i] = q.truth_in_feasible_set;
      if (q.positive_map) {
        il[i] = q.illuminant_error_deg;
        rep[i] = q.reproduction_error_deg;
      }
    }
    const std::string p = baseline ? r.baselines[k - r.rules.size()] : r.rules[k];
    cols[(p + "_map_x").c_str()] = py::array(py::cast(mx));
    cols[(p + "_map_y").c_str()] = py::array(py::cast(my));
    cols[(p + "_error_deg").c_str()] = py::array(py::cast(err));
    if (!baseline) cols[(p + "_worst_case_deg").c_str()] = py::array(py::cast(wc));
    cols[(p + "_illuminant_error_deg").c_str()] = py::array(py::cast(il));
    cols[(p + "_reproduction_error_deg").c_str()] = py::array(py::cast(rep));
    if (setup && !baseline)
      cols[(p + "_truth_in_feasible_set").c_str()] =
          py::module_::import("numpy").attr("array")(py::cast(in_f), "bool");
  }
  return cols;
}

// The scene pipeline: the canonical side, one scene's selections, its feasible set and the rules
// applied together.
void bind_scene(py::module_& m) {
  m.def("prepare_canonical", &prepare, py::arg("canonical"), py::kw_only(), GMCC_OPTION_ARGS,
        "The canonical side prepared once (prepare_canonical.h; Finlayson & Hordley 1999 eq. 10). Public: gmcc.prepare_canonical.");

  m.def(
      "select_prepared",
      [](const std::shared_ptr<PreparedCanonical>& canonical, py::handle image, py::handle truth, py::object mask,
         py::object black_level, py::object saturation, py::object dark, py::object dark_fraction,
         py::object bright_fraction, const std::string& pixel_rule, const py::dict& choices) {
        const SceneChoices c = scene_choices(*canonical, choices);
        return run_scene(canonical, image, truth,
                         {mask, black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule}, true, &c);
      },
      py::arg("canonical"), py::arg("image"), py::arg("truth") = py::none(), py::arg("mask") = py::none(),
      py::arg("black_level") = 0, py::arg("saturation") = py::none(), py::arg("dark") = 0,
      py::arg("dark_fraction") = py::none(), py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none",
      py::arg("choices") = py::dict(),
        "select_scene (select_scene.h) on colours or an H×W×3 image. Public: gmcc.select.");

  m.def(
      "feasible_prepared",
      [](const std::shared_ptr<PreparedCanonical>& canonical, py::handle image, py::object mask,
         py::object black_level, py::object saturation, py::object dark, py::object dark_fraction,
         py::object bright_fraction, const std::string& pixel_rule) {
        return run_scene(canonical, image, py::none(),
                         {mask, black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule}, false);
      },
      py::arg("canonical"), py::arg("image"), py::arg("mask") = py::none(), py::arg("black_level") = 0,
      py::arg("saturation") = py::none(), py::arg("dark") = 0, py::arg("dark_fraction") = py::none(),
      py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none",
        "scene_feasible_set (select_scene.h): F alone. Public: gmcc.feasible_set.");

  m.def(
      "image_colours",
      [](py::handle image, py::object mask, py::object black_level, py::object saturation, py::object dark,
         py::object dark_fraction, py::object bright_fraction, const std::string& pixel_rule,
         const std::string& colour_set, py::object prefilter) {
        return image_colours_of(image, {mask, black_level, saturation, dark, dark_fraction, bright_fraction,
                                        pixel_rule, colour_set, prefilter});
      },
      py::arg("image"), py::arg("mask") = py::none(), py::arg("black_level") = 0, py::arg("saturation") = py::none(),
      py::arg("dark") = 0, py::arg("dark_fraction") = py::none(), py::arg("bright_fraction") = py::none(),
      py::arg("pixel_rule") = "none", py::arg("colour_set") = "hull", py::arg("prefilter") = 0,
        "The pixel rules (image_pixels.h; docs/conventions.md §8). Public: gmcc.image_colours.");

  m.def(
      "read_image",
      [](const std::string& path, py::object black_level, py::object saturation) {
        ImageLevels levels;
        if (!black_level.is_none()) levels.black = integer_in<std::uint32_t>(black_level, "black_level", 0, 65535);
        if (!saturation.is_none()) levels.saturation = integer_in<std::uint32_t>(saturation, "saturation", 1, 65536);
        PixelRules rules;
        RgbImage image;
        RawImage meta;  // a raw file's metadata (its image is `image`)
        try {
          image = read_camera_image(path, levels, rules, &meta);
        } catch (const std::runtime_error& e) {  // InputError: the file and its problem
          throw py::value_error(e.what());
        }
        py::object raw = py::none();
        if (is_raw_file_name(path)) {
          py::dict info;
          info["pattern"] = meta.pattern;
          info["black_min"] = meta.black_min;
          info["black_max"] = meta.black_max;
          info["white"] = meta.white;
          info["camera"] = meta.camera;
          info["saturated"] = meta.saturated;
          raw = std::move(info);
        }
        py::array_t<std::uint16_t> a({image.height, image.width, std::size_t(3)});
        if (!image.samples.empty()) std::memcpy(a.mutable_data(), image.samples.data(), image.samples.size() * 2);
        py::dict out;
        out["image"] = a;
        out["bits"] = image.bits;
        out["black_level"] = rules.black_level;
        out["saturation"] = rules.saturation ? py::object(py::int_(*rules.saturation)) : py::object(py::none());
        out["raw"] = raw;
        return out;
      },
      py::arg("path"), py::arg("black_level") = py::none(), py::arg("saturation") = py::none(),
      "read_camera_image (camera_image.h, raw_file.h; docs/conventions.md §8). Public: gmcc.read_image.");

  m.def(
      "select_maps",
      [](const ConvexSet2& F, const std::string& mean3d, py::handle precision, py::handle order, py::handle samples,
         py::handle seed, py::handle canonical_illuminant) {
        SelectionOptions o;
        o.mean3d = scene_options(py::int_(0), "none", py::none(), py::make_tuple(1, 1, 1), "none", mean3d, precision,
                                 order, samples, seed, true, "drop")
                       .mean3d;
        if (!canonical_illuminant.is_none())
          o.illuminant_worst_case_for = light_from(canonical_illuminant, "canonical_illuminant");
        const Selections s = released([&] { return select_maps(F, o); });
        return selections_dict(s);
      },
      py::arg("feasible_set"), py::kw_only(), py::arg("mean3d") = to_string(Mean3dOptions{}.method),
      GMCC_MEAN3D_PARAMETER_ARGS, py::arg("canonical_illuminant") = py::none(),
        "The three selection rules with worst cases (select_maps.h; §3, §4). Public: gmcc.select_maps.");
}

// Each rule, worst case and angular error on its own.
void bind_rules(py::module_& m) {
  m.def("rules", [] {
    py::list keys;
    for (Rule rule : all_rules) keys.append(to_string(rule));
    return keys;
  }, R"doc(The selection rules on the 2-D feasible set, in report order (rule.h).

Returns
-------
list of str
    Their names, 'max_area', 'mean_2d', 'mean_3d': the keys of select_maps' and
    SceneResult.selections' dicts and the names of SceneResult's and Truth's per-rule attributes.
)doc");
  m.def("max_area", [](const ConvexSet2& F) {
    nonempty(F, "max_area");
    return released([&] { return max_area(F); });
  }, py::arg("feasible_set"),
        "max_area (max_area.h; Finlayson & Hordley 1999 §3.1).");
  m.def("mean_2d", [](const ConvexSet2& F) {
    nonempty(F, "mean_2d");
    return released([&] { return mean_2d(F); });
  }, py::arg("feasible_set"),
        "mean_2d (mean_2d.h; Finlayson & Hordley 1999 §3.2).");
  m.def(
      "mean_3d",
      [](const ConvexSet2& F, const std::string& method, py::handle precision, py::handle order, py::handle samples,
         py::handle seed) {
        nonempty(F, "mean_3d");
        const Mean3dOptions o = scene_options(py::int_(0), "none", py::none(), py::make_tuple(1, 1, 1), "none", method,
                                              precision, order, samples, seed, true, "drop")
                                    .mean3d;
        return released([&] { return mean_3d(F, o); });
      },
      py::arg("feasible_set"), py::kw_only(), py::arg("method") = to_string(Mean3dOptions{}.method),
      GMCC_MEAN3D_PARAMETER_ARGS,
        "mean_3d by a route (mean_3d.h; Finlayson & Hordley 1999 §3.2, docs/math.md §2).");

  m.def("worst_case_map_deg", [](const ConvexSet2& F, py::handle map) {
    nonempty(F, "worst_case_map_deg");
    const Point2 p = map_from(map, "map");
    return released([&] { return worst_case_map_deg(F, p); });
  }, py::arg("feasible_set"), py::arg("map"),
        "worst_case_map_deg (worst_case.h; Finlayson & Hordley 1999 §4).");
  m.def("worst_case_illuminant_deg", [](const ConvexSet2& F, py::handle map, py::handle c) {
    nonempty(F, "worst_case_illuminant_deg");
    const Point2 p = map_from(map, "map");
    const Colour light = light_from(c, "canonical_illuminant");
    for (const Point2& v : F.vertices)
      if (sgn(v.x) <= 0 || sgn(v.y) <= 0)
        throw py::value_error("feasible_set: a vertex touches an axis (an illuminant needs maps > 0)");
    if (sgn(p.x) <= 0 || sgn(p.y) <= 0) throw py::value_error("map: both components must be > 0");
    return released([&] { return worst_case_illuminant_deg(F, p, light); });
  }, py::arg("feasible_set"), py::arg("map"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        "worst_case_illuminant_deg (worst_case_illuminant.h; docs/derivations.md §3.2).");

  m.def("map_angular_error_deg", [](py::handle estimate, py::handle truth) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    return map_angular_error_deg(e, t);
  }, py::arg("estimate"), py::arg("truth"),
        "map_angular_error_deg (angular_error.h; Finlayson & Hordley 1999 §4).");
  m.def("illuminant_angular_error_deg", [](py::handle estimate, py::handle truth, py::handle c) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    const Colour light = light_from(c, "canonical_illuminant");
    for (const Point2* p : {&e, &t})
      if (sgn(p->x) <= 0 || sgn(p->y) <= 0) throw py::value_error("estimate and truth: components must be > 0");
    return illuminant_angular_error_deg(e, t, light);
  }, py::arg("estimate"), py::arg("truth"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        "illuminant_angular_error_deg (angular_error.h).");
  m.def("reproduction_angular_error_deg", [](py::handle estimate, py::handle truth) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    for (const Point2* p : {&e, &t})
      if (sgn(p->x) <= 0 || sgn(p->y) <= 0) throw py::value_error("estimate and truth: components must be > 0");
    return reproduction_angular_error_deg(e, t);
  }, py::arg("estimate"), py::arg("truth"),
        "reproduction_angular_error_deg (angular_error.h).");

}

// Lights as maps, the illumination constraint and CRULE in 3-D.
void bind_lights_and_crule(py::module_& m) {
  m.def("illuminant_map", [](py::handle light, py::handle c) {
    return to_fraction_pair(illuminant_map(light_from(light, "light"), light_from(c, "canonical_illuminant")));
  }, py::arg("light"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        "illuminant_map (illumination_constraint.h): c ⊘ e in perspective, exact.");
  m.def("illumination_constraint", [](py::handle illuminants, py::handle c) {
    const std::vector<Colour> lights = colours_from(illuminants, "illuminants");
    const Colour light = light_from(c, "canonical_illuminant");
    try {
      return illumination_constraint(lights, light);
    } catch (const NonPositiveIlluminant& e) {
      throw py::value_error("illuminants: row " + std::to_string(e.index) + ": " + e.what());
    }
  }, py::arg("illuminants"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        "illumination_constraint (illumination_constraint.h; Finlayson 1996 §5).");

  m.def("crule_3d", [](py::handle canonical, py::handle image, const std::string& black) {
    const std::vector<Colour> c = colours_or_pixel_colours(canonical, "canonical"),
                              i = colours_or_pixel_colours(image, "image");
    if (black != "include" && black != "exclude")
      throw py::value_error("black: " + quoted_text(black) + " is not one of include, exclude");
    const CanonicalBlack b = black == "include" ? CanonicalBlack::include : CanonicalBlack::exclude;
    try {
      return released([&] { return crule_3d(c, i, b); });
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("crule_3d: ") + e.what());
    }
  }, py::arg("canonical"), py::arg("image"), py::kw_only(), py::arg("black") = "include",
        "crule_3d (crule_3d.h): Forsyth's CRULE in 3-D.");
}

// Error statistics.
void bind_statistics(py::module_& m) {
  m.def("error_statistics", [](py::handle values) {
    const py::array_t<double, py::array::c_style | py::array::forcecast> a =
        py::module_::import("numpy").attr("asarray")(values, "float64").attr("ravel")();
    std::vector<double> v(a.data(), a.data() + a.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        throw py::value_error("values: element " + std::to_string(i) + " is not finite (NaN or infinity): drop "
                              "scenes without an error first");
    return error_statistics(std::move(v));
  }, py::arg("values"),
        "error_statistics (error_statistics.h; docs/reproduction.md \"Statistics\").");

}

// The benchmark's C++ loop and the experiments with their per-scene records.
void bind_benchmark_and_experiments(py::module_& m) {
  // For bench/python_overhead.py only: the same scenes through select_scene in a C++ loop (the
  // inputs converted first, outside the clock), seconds per call, to compare a call from Python
  // with the C++ call in one run.
  m.def(
      "_time_select_scene",
      [](const std::shared_ptr<PreparedCanonical>& canonical, py::list scenes, int repeats) {
        std::vector<std::vector<Colour>> colours;
        for (py::handle s : scenes) colours.push_back(colours_from(s, "scenes"));
        py::gil_scoped_release nogil;
        std::size_t sink = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int k = 0; k < repeats; ++k)
          for (const auto& c : colours) sink += select_scene(*canonical, c).feasible.vertices.size();
        const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
        if (sink == std::size_t(-1)) std::abort();  // keeps the loop's results used
        return t.count() / (double(repeats) * double(colours.size()));
      },
      py::arg("canonical"), py::arg("scenes"), py::arg("repeats"),
        "For bench/python_overhead.py: seconds per select_scene call in a C++ loop.");

  m.def(
      "run_experiment",
      [](const std::string& experiment, const std::string& data_dir, const std::string& canonical,
         const std::vector<std::string>& lights, const std::string& canonical_surfaces, int min_surfaces,
         int max_surfaces, std::uint64_t scenes, std::uint64_t seed, py::handle expand,
         const std::string& expand_policy, bool crule, unsigned threads) {
        if (experiment != "synthetic" && experiment != "camera")
          throw py::value_error("experiment: " + quoted_text(experiment) + " is not one of synthetic, camera");
        if (canonical_surfaces != "sfu" && canonical_surfaces != "macbeth")
          throw py::value_error("canonical_surfaces: " + quoted_text(canonical_surfaces) + " is not one of sfu, macbeth");
        ExperimentConfig config;
        config.min_surfaces = min_surfaces;
        config.max_surfaces = max_surfaces;
        config.scenes = scenes;
        config.seed = seed;
        config.threads = threads;
        config.crule = crule;
        config.keep_scenes = true;
        config.expansion = expansion_from(expand, expand_policy);
        if (min_surfaces < 1 || max_surfaces < min_surfaces)
          throw py::value_error("surfaces: need 1 <= min_surfaces <= max_surfaces");
        if (scenes < 1) throw py::value_error("scenes: must be >= 1");
        ExperimentResult r;
        try {
          InterruptibleRelease nogil;
          auto table = [&](const char* name) { return read_spectral_csv(data_dir + "/" + name); };
          ExperimentSetup setup;
          if (experiment == "synthetic") {
            setup = synthetic_setup(table("munsell_matt_1269_joensuu_5nm.csv"),
                                    table("cie_daylight_basis_S0_S1_S2.csv"), canonical, lights);
          } else {
            setup = camera_setup(table("camera_sony_dxc930_sfu_4nm.csv"),
                                 table(canonical_surfaces == "macbeth" ? "sfu_macbeth_24_4nm.csv"
                                                                       : "sfu_reflect_db_1995_4nm.csv"),
                                 table("sfu_macbeth_24_4nm.csv"), table("sfu_lab_11_illuminants_4nm.csv"),
                                 canonical, lights);
          }
          r = run_gamut_experiment(setup, config);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        } catch (const std::domain_error& e) {
          throw py::value_error(e.what());
        } catch (const std::runtime_error& e) {  // files (InputError)
          throw py::value_error(e.what());
        }
        py::dict out;
        out["columns"] = records_columns(r);
        out["rules"] = r.rules;
        out["canonical_gamut"] = r.canonical_gamut;
        return out;
      },
      py::arg("experiment"), py::arg("data_dir"), py::arg("canonical"), py::arg("lights"),
      py::arg("canonical_surfaces"), py::arg("min_surfaces"), py::arg("max_surfaces"), py::arg("scenes"),
      py::arg("seed"), py::arg("expand"), py::arg("expand_policy"), py::arg("crule"), py::arg("threads"),
        "run_gamut_experiment on synthetic_setup or camera_setup, with every scene's record (gamut_experiment.h).");

  // `gmcc reproduce gehler-shi` (cli/reproduce.cpp), option by option with the command line's
  // checks: the setup of gehler_shi_experiment.h on the shipped chart data, run with every
  // scene's record.
  m.def(
      "run_gehler_shi",
      [](const std::string& data_dir, const std::string& protocol, const std::vector<std::string>& cameras,
         py::handle dark, py::handle clip, py::handle exclude_patches, py::handle min_surfaces,
         py::handle max_surfaces, py::handle scenes, py::handle seed, py::handle expand,
         const std::string& expand_policy, const std::string& mean3d, py::handle threads) {
        GehlerShiOptions options;
        try {
          options.protocol = gehler_shi_protocol_from_string(protocol);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("protocol: ") + e.what());
        }
        options.cameras.clear();
        for (const std::string& camera : cameras) {
          if (camera != "Canon1D" && camera != "Canon5D")
            throw py::value_error("cameras: unknown camera " + quoted_text(camera) + " (Canon1D, Canon5D)");
          if (std::find(options.cameras.begin(), options.cameras.end(), camera) == options.cameras.end())
            options.cameras.push_back(camera);
        }
        if (options.cameras.empty()) throw py::value_error("cameras: give at least one of Canon1D, Canon5D");
        options.dark = number_from(dark, "dark");
        options.clip = number_from(clip, "clip");
        if (sgn(options.dark) < 0) throw py::value_error("dark: must be >= 0");
        if (sgn(options.clip) < 0) throw py::value_error("clip: must be >= 0");
        if (options.dark >= options.clip) throw py::value_error("dark: must be below clip");
        for (py::handle k : py::reinterpret_borrow<py::iterable>(exclude_patches))
          options.exclude_patches.push_back(integer_in<std::uint32_t>(k, "exclude_patches", 1, chart_patches));
        ExperimentConfig config;
        config.min_surfaces = integer_in<int>(min_surfaces, "min_surfaces", 1, chart_patches);
        config.max_surfaces = integer_in<int>(max_surfaces, "max_surfaces", 1, chart_patches);
        if (config.max_surfaces < config.min_surfaces)
          throw py::value_error("surfaces: need 1 <= min_surfaces <= max_surfaces");
        config.scenes = integer_in<std::uint64_t>(scenes, "scenes", 1, 1000000);
        config.seed = integer_in<std::uint64_t>(seed, "seed", 0, ~0ULL);
        config.threads = integer_in<unsigned>(threads, "threads", 0, 256);
        config.keep_scenes = true;
        config.expansion = expansion_from(expand, expand_policy);
        try {
          config.mean3d.method = mean3d_method_from_string(mean3d);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("mean3d: ") + e.what());
        }
        const std::string patches = data_dir + "/gehler_shi_568_colorchecker_patch_rgb_rec2018.csv";
        const std::string truth = data_dir + "/gehler_shi_568_groundtruth.csv";
        GehlerShiSetup setup;
        ExperimentResult r;
        try {
          InterruptibleRelease nogil;
          const ChartDataset data = read_gehler_shi(patches, truth);
          try {
            setup = gehler_shi_setup(data, options);
          } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(patches + ": " + e.what());
          }
          r = run_gamut_experiment(setup.setup, config);
        } catch (const SceneInputError& e) {
          throw py::value_error(std::string(e.input == SceneInput::expansion ? "expand: " : "") + e.what());
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        } catch (const std::runtime_error& e) {  // files (InputError)
          throw py::value_error(e.what());
        }
        py::dict out;
        out["columns"] = records_columns(r, &setup.setup);
        out["rules"] = r.rules;
        out["baselines"] = r.baselines;
        return out;
      },
      py::arg("data_dir"), py::arg("protocol"), py::arg("cameras"), py::arg("dark"), py::arg("clip"),
      py::arg("exclude_patches"), py::arg("min_surfaces"), py::arg("max_surfaces"), py::arg("scenes"),
      py::arg("seed"), py::arg("expand"), py::arg("expand_policy"), py::arg("mean3d"), py::arg("threads"),
      "run_gamut_experiment on gehler_shi_setup (gehler_shi_experiment.h; Finlayson & Hordley 1999 §4, Fig. 5 "
      "on measured charts), with every scene's record. Public: gmcc.reproduce_gehler_shi.");
}

}  // namespace

}  // namespace gmcc::python

PYBIND11_MODULE(_core, m) {
  using namespace gmcc;
  using namespace gmcc::python;
  m.doc() = "gmcc._core: the compiled half of the Python module gmcc (docs/python.md).";
  register_interrupt(m);
  m.attr("__version__") = std::string(gmcc_version());
  m.attr("__commit__") = std::string(gmcc_commit());
  m.attr("__commit_date__") = std::string(gmcc_commit_date());
  m.attr("__data_dir__") = std::string(GMCC_DATA_DIR);  // the source tree's data/, at build time
  bind_results(m);
  bind_scene(m);
  bind_rules(m);
  bind_lights_and_crule(m);
  bind_photo(m);
  bind_statistics(m);
  bind_benchmark_and_experiments(m);
}
