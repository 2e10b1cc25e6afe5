/// \file experiments.cpp
/// gmcc._core's experiments with their per-scene records (synthetic, camera, gehler-shi), and the
/// benchmark's C++ loop.

#include "bindings.h"
#include "options.h"
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

  // For bench/python_overhead.py only: the same scenes through select_scene in a C++ loop (the
  // inputs converted first, outside the clock), seconds per call, to compare a call from Python
  // with the C++ call in one run.
void bind_time_select_scene(py::module_& m) {
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
}

// The synthetic and camera experiments (`gmcc reproduce synthetic|camera`).
void bind_run_experiment(py::module_& m) {
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
}

  // `gmcc reproduce gehler-shi` (cli/reproduce.cpp), option by option with the command line's
  // checks: the setup of gehler_shi_experiment.h on the shipped chart data, run with every
  // scene's record.
void bind_run_gehler_shi(py::module_& m) {
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

void bind_experiments(py::module_& m) {
  bind_time_select_scene(m);
  bind_run_experiment(m);
  bind_run_gehler_shi(m);
}

}  // namespace gmcc::python
