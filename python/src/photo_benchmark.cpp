/// \file photo_benchmark.cpp
/// gmcc._core's benchmark of the gamut-mapping methods on photographs with known lights
/// (benchmark.h): run_benchmark's summaries and records as dicts.

#include "docstrings.h"
#include "photo_bindings.h"

#include <gmcc/input/input_error.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/validation/benchmark.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <map>

namespace gmcc::python {
namespace {

py::object optional_light(const std::optional<std::array<double, 3>>& e) {
  return e ? py::object(py::make_tuple((*e)[0], (*e)[1], (*e)[2])) : py::object(py::none());
}

py::dict summary_dict(const BenchmarkSummary& s) {
  py::dict d;
  d["method"] = s.method;
  d["images"] = s.images;
  d["answered"] = s.answered;
  const bool any = s.errors.n > 0;
  auto stat = [&](double x) { return any ? py::object(py::float_(x)) : py::object(py::none()); };
  d["mean_deg"] = stat(s.errors.mean);
  d["median_deg"] = stat(s.errors.median);
  d["trimean_deg"] = stat(s.errors.trimean);
  d["best25_deg"] = stat(s.errors.best25);
  d["worst25_deg"] = stat(s.errors.worst25);
  d["p95_deg"] = stat(s.errors.p95);
  d["max_deg"] = stat(s.errors.max);
  const bool gamut = is_gamut_method(s.method);
  d["empty"] = gamut ? py::object(py::int_(s.empty)) : py::object(py::none());
  d["unanswered_other"] = s.unanswered_other;
  d["truth_in_feasible"] = gamut ? py::object(py::float_(double(s.truth_in_feasible) / double(s.images)))
                                 : py::object(py::none());
  d["worst_case_covers"] = optional_double(s.worst_case_covers);
  d["worst_case_correlation"] = optional_double(s.worst_case_correlation);
  return d;
}

// The benchmark's images: `truths` read, each image given its fold (`folds` K or `folds_file`).
std::vector<BenchmarkImage> benchmark_images(const std::string& images, const std::string& truths,
                                             const py::object& folds, const py::object& folds_file) {
  std::vector<BenchmarkImage> dataset;
  try {
    const std::vector<TruthRow> rows = read_truth_table(truths);
    require_paths_under_folder(rows, truths);
    if (!folds_file.is_none()) {
      if (!folds.is_none()) throw py::value_error("folds, folds_file: give one, not both");
      const std::string path = py::str(folds_file);
      const std::map<std::string, int> f = read_folds_file(path);
      dataset = benchmark_dataset(images, rows, &f, path, 0);
    } else {
      if (folds.is_none()) throw py::value_error("folds: give folds=K or folds_file=path");
      dataset = benchmark_dataset(images, rows, nullptr, "", integer_in<int>(folds, "folds", 2, 1000000));
    }
  } catch (const InputError& e) {
    throw py::value_error(e.what());
  }
  return dataset;
}

// The summary and records as pandas DataFrames when `frame` and pandas imports, else the lists.
py::tuple as_frames(const py::list& summaries, const py::list& records, bool frame) {
  if (frame) {
    try {
      const py::module_ pandas = py::module_::import("pandas");
      return py::make_tuple(pandas.attr("DataFrame")(summaries), pandas.attr("DataFrame")(records));
    } catch (py::error_already_set& e) {
      if (!e.matches(PyExc_ImportError)) throw;
    }
  }
  return py::make_tuple(summaries, records);
}

}  // namespace

void bind_benchmark(py::module_& m) {
  m.def(
      "benchmark",
      [](py::handle images_folder, py::handle truths_file, py::object folds, py::object folds_file,
         py::object methods, const std::string& intensity, const std::string& black, unsigned threads,
         py::object black_level, py::object saturation, py::object dark, py::object dark_fraction,
         py::object bright_fraction, const std::string& pixel_rule, double edge_sigma, bool frame) {
        const std::string images = py::str(images_folder), truths = py::str(truths_file);  // or os.PathLike
        BenchmarkOptions o;
        o.edge_sigma = edge_sigma;
        const std::vector<BenchmarkImage> dataset = benchmark_images(images, truths, folds, folds_file);
        if (!methods.is_none()) {
          o.methods.clear();
          for (py::handle x : methods) {
            const std::string name = py::str(x);
            const auto& all = benchmark_methods();
            if (std::find(all.begin(), all.end(), name) == all.end())
              throw py::value_error("methods: " + quoted_text(name) + " is not a benchmark method");
            o.methods.push_back(name);
          }
        }
        try {
          o.intensity = canonical_intensity_from_string(intensity);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("intensity: ") + e.what());
        }
        o.black = black_from(black);
        o.threads = threads;
        // The run's pixel rules, through the same checks as images (a 1×1 image is not needed:
        // the integer route's checks are the arguments').
        // Absent: 0 for PNG and TIFF, a raw file's own black levels (camera_image.h).
        o.pixels.black_level_given = !black_level.is_none();
        if (o.pixels.black_level_given) o.pixels.rules.black_level = integer_in<std::uint32_t>(black_level, "black_level", 0, 65535);
        if (!saturation.is_none()) o.pixels.rules.saturation = integer_in<std::uint32_t>(saturation, "saturation", 1, 65536);
        if (const auto d = integer_in<std::uint32_t>(dark, "dark", 0, 65535)) o.pixels.rules.dark_below = d;
        PixelArgs args;
        args.dark_fraction = dark_fraction;
        args.bright_fraction = bright_fraction;
        args.pixel_rule = pixel_rule;
        pixel_fractions(args, o.pixels.rules.dark_below_fraction, o.pixels.rules.bright_above_fraction);
        BenchmarkResult r;
        try {
          InterruptibleRelease nogil;
          r = run_benchmark(dataset, o);
        } catch (const InputError& e) {
          throw py::value_error(e.what());
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
        py::list summaries, records;
        for (const BenchmarkSummary& s : r.summaries) summaries.append(summary_dict(s));
        for (const BenchmarkRecord& rec : r.records) {
          py::dict d;
          d["image"] = dataset[rec.image].name;
          d["fold"] = dataset[rec.image].fold;
          d["method"] = rec.method;
          d["light"] = optional_light(rec.light);
          d["error_deg"] = optional_double(rec.error_deg);
          d["answered"] = rec.answered;
          d["fallback"] = rec.fallback.empty() ? py::object(py::none()) : py::object(py::str(rec.fallback));
          d["feasible_kind"] = rec.feasible_kind.empty() ? py::object(py::none()) : py::object(py::str(rec.feasible_kind));
          d["feasible_vertices"] = rec.feasible_kind.empty() ? py::object(py::none()) : py::object(py::int_(rec.feasible_vertices));
          d["truth_in_feasible"] =
              rec.truth_in_feasible ? py::object(py::bool_(*rec.truth_in_feasible)) : py::object(py::none());
          d["worst_case_deg"] = optional_double(rec.worst_case_deg);
          d["worst_case_space"] =
              rec.worst_case_space.empty() ? py::object(py::none()) : py::object(py::str(rec.worst_case_space));
          d["worst_case_space_error_deg"] = optional_double(rec.worst_case_space_error_deg);
          d["unanswered"] = rec.unanswered.empty() ? py::object(py::none()) : py::object(py::str(rec.unanswered));
          records.append(d);
        }
        return as_frames(summaries, records, frame);
      },
      py::arg("images"), py::arg("truths"), py::kw_only(), py::arg("folds") = py::none(),
      py::arg("folds_file") = py::none(), py::arg("methods") = py::none(), py::arg("intensity") = "max",
      py::arg("black") = "include", py::arg("threads") = 0, py::arg("black_level") = py::none(),
      py::arg("saturation") = py::none(), py::arg("dark") = 0, py::arg("dark_fraction") = py::none(),
      py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none", py::arg("edge_sigma") = 1.0,
      py::arg("frame") = true, doc::benchmark.c_str());
}

}  // namespace gmcc::python
