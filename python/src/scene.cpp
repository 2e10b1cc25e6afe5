/// \file scene.cpp
/// gmcc._core's scene pipeline: the canonical side prepared once, one scene's selections and its
/// feasible set, an image's pixel colours and a camera file read.

#include "bindings.h"
#include "docstrings.h"
#include "options.h"
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
  const Mean3dOptions& m = c.mean3d;
  // Each choice given here (not None), else the prepared one.
  const auto arg = [&](const char* name, py::object prepared) {
    return given.contains(name) && !given[name].is_none() ? py::object(given[name]) : prepared;
  };
  c.mean3d = mean3d_from(arg("mean3d", py::str(to_string(m.method))), arg("precision", py::int_(m.precision_bits)),
                         arg("order", py::int_(m.order)), arg("samples", py::int_(m.samples)),
                         arg("seed", py::int_(m.seed)));
  c.illuminant_worst_case = arg("illuminant_worst_case", py::bool_(c.illuminant_worst_case)).cast<bool>();
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

// The canonical side, one scene's selections and its feasible set.
void bind_select(py::module_& m) {
  m.def("prepare_canonical", &prepare, py::arg("canonical"), py::kw_only(), GMCC_OPTION_ARGS,
        doc::prepare_canonical.c_str());
  m.def(
      "canonical_gamut",
      [](py::handle canonical, py::handle expand, const std::string& expand_policy,
         const std::string& nonpositive_blue) {
        const Mean3dOptions d{};  // no selection is made: the 3-D mean's options are unused
        return prepare(canonical, expand, expand_policy, py::none(), py::make_tuple(1, 1, 1), "none",
                       to_string(d.method), py::int_(d.precision_bits), py::int_(d.order), py::int_(d.samples),
                       py::int_(d.seed), true, nonpositive_blue)
            ->gamut;
      },
      py::arg("canonical"), py::kw_only(), py::arg("expand") = 0, py::arg("expand_policy") = "none",
      py::arg("nonpositive_blue") = "drop", doc::canonical_gamut.c_str());

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
}

// An image's colours by the pixel rules, and a camera file read.
void bind_images(py::module_& m) {
  m.def(
      "image_colours",
      [](py::handle image, py::object mask, py::object black_level, py::object saturation, py::object dark,
         py::object dark_fraction, py::object bright_fraction, const std::string& pixel_rule,
         const std::string& colour_set, py::object prefilter) {
        return image_colours_of(image, {mask, black_level, saturation, dark, dark_fraction, bright_fraction,
                                        pixel_rule, colour_set, prefilter});
      },
      py::arg("image"), py::kw_only(), py::arg("mask") = py::none(), py::arg("black_level") = 0,
      py::arg("saturation") = py::none(), py::arg("dark") = 0, py::arg("dark_fraction") = py::none(),
      py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none", py::arg("colour_set") = "hull",
      py::arg("prefilter") = 0, doc::image_colours.c_str());

  m.def(
      "read_image",
      [](py::handle path_like, py::object black_level, py::object saturation) {
        const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
        ImageLevels levels;
        if (!black_level.is_none()) levels.black = integer_in<std::uint32_t>(black_level, "black_level", 0, 65535);
        if (!saturation.is_none()) levels.saturation = integer_in<std::uint32_t>(saturation, "saturation", 1, 65536);
        CameraImage read;
        try {
          read = read_camera_image(path, levels);
        } catch (const std::runtime_error& e) {  // InputError: the file and its problem
          throw py::value_error(e.what());
        }
        py::object raw = py::none();
        const RawImage& meta = read.raw;  // a raw file's metadata
        const RgbImage& image = read.image;
        if (!meta.pattern.empty()) {  // a raw file, by its name or its content
          py::dict info;
          info["pattern"] = meta.pattern;
          info["black_min"] = meta.black_min;
          info["black_max"] = meta.black_max;
          py::list black;
          for (std::uint32_t b : meta.black) black.append(b);
          info["black"] = std::move(black);
          info["white"] = meta.white;
          info["camera"] = meta.camera;
          info["saturated"] = meta.saturated;
          raw = std::move(info);
        }
        py::array_t<std::uint16_t> a({image.height, image.width, std::size_t(3)});
        if (!image.samples.empty()) std::memcpy(a.mutable_data(), image.samples.data(), image.samples.size() * 2);
        py::dict levels_found;  // the pixel rules to pass on as **rules
        levels_found["black_level"] = read.black_level;
        levels_found["saturation"] =
            read.saturation ? py::object(py::int_(*read.saturation)) : py::object(py::none());
        py::dict info;
        info["bits"] = image.bits;
        info["raw"] = raw;
        return py::make_tuple(a, levels_found, info);
      },
      py::arg("path"), py::kw_only(), py::arg("black_level") = py::none(), py::arg("saturation") = py::none(),
      doc::read_image.c_str());
}

// The rules applied together on a feasible set.
void bind_select_maps(py::module_& m) {
  m.def(
      "select_maps",
      [](const ConvexSet2& F, const std::string& mean3d, py::handle precision, py::handle order, py::handle samples,
         py::handle seed, py::handle canonical_illuminant) {
        SelectionOptions o;
        o.mean3d = mean3d_from(py::str(mean3d), precision, order, samples, seed);
        if (!canonical_illuminant.is_none())
          o.illuminant_worst_case_for = light_from(canonical_illuminant, "canonical_illuminant");
        const Selections s = released([&] { return select_maps(F, o); });
        return selections_dict(s);
      },
      py::arg("feasible_set"), py::kw_only(), py::arg("mean3d") = to_string(Mean3dOptions{}.method),
      GMCC_MEAN3D_PARAMETER_ARGS, py::arg("canonical_illuminant") = py::none(), doc::select_maps.c_str());
}

}  // namespace

void bind_scene_functions(py::module_& m) {
  bind_select(m);
  bind_images(m);
  bind_select_maps(m);
}

}  // namespace gmcc::python
