#include "benchmark.h"

#include <gmcc/input/input_error.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/validation/benchmark.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "integer_option.h"
#include "output_files.h"
#include "provenance.h"
#include "write_stdout.h"

namespace gmcc::cli {
namespace {

using Json = nlohmann::ordered_json;

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// A CSV number: shortest round trip, or empty for none.
std::string number(std::optional<double> x) {
  if (!x || !std::isfinite(*x)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", *x);
  return buf;
}

Json optional_json(const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); }

std::vector<BenchmarkImage> dataset(const BenchmarkCliOptions& o) {
  const std::vector<TruthRow> rows = read_truth_table(o.truths_path);
  if (!o.folds_path.empty()) {
    if (!o.folds.empty()) throw InputError("--folds", 0, "give --folds K or --folds-file F.csv, not both");
    const std::map<std::string, int> folds = read_folds_file(o.folds_path);
    return benchmark_dataset(o.images_dir, rows, &folds, o.folds_path, 0);
  }
  if (o.folds.empty())
    throw InputError("--folds", 0, "required: --folds K (fold = line index mod K) or --folds-file F.csv");
  return benchmark_dataset(o.images_dir, rows, nullptr, "",
                           static_cast<int>(integer_option("--folds", o.folds, 2, 1000000)));
}

std::string table(const BenchmarkResult& r) {
  std::ostringstream t;
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %6s %8s %7s %7s %7s %7s %7s %7s %7s %7s %7s\n", "method", "images",
                "answered", "mean", "median", "trimean", "best25", "worst25", "p95", "max", "in F", "wc>=err");
  t << line;
  for (const BenchmarkSummary& s : r.summaries) {
    const ErrorStatistics& e = s.errors;
    const bool gamut = s.method.rfind("gm", 0) == 0;
    std::snprintf(line, sizeof line, "%-16s %6zu %8zu %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7s %7s\n",
                  s.method.c_str(), s.images, s.answered, e.mean, e.median, e.trimean, e.best25, e.worst25, e.p95,
                  e.max, gamut ? (fixed(100.0 * double(s.truth_in_feasible) / double(s.images), 1) + "%").c_str() : "",
                  s.worst_case_covers ? (fixed(100.0 * *s.worst_case_covers, 1) + "%").c_str() : "");
    t << line;
  }
  t << "recovery angular error in degrees; a gamut method with no estimate (F empty, or no positive map) "
       "takes grey world's; in F: images whose true light lies in the feasible set; wc>=err: answered "
       "images whose error is at most the rule's worst case\n";
  return t.str();
}

std::string csv(const BenchmarkResult& r) {
  std::string out = provenance_csv_line(true);
  out += "method,images,answered,empty,fallback,mean_deg,median_deg,trimean_deg,best25_deg,worst25_deg,p95_deg,"
         "max_deg,truth_in_feasible,worst_case_covers,worst_case_correlation\n";
  for (const BenchmarkSummary& s : r.summaries) {
    const ErrorStatistics& e = s.errors;
    const bool gamut = s.method.rfind("gm", 0) == 0;
    const bool any = e.n > 0;
    auto stat = [&](double x) { return any ? number(x) : std::string(); };
    out += s.method + "," + std::to_string(s.images) + "," + std::to_string(s.answered) + "," +
           (gamut ? std::to_string(s.empty) : "") + "," + (gamut ? "grey_world" : "") + "," + stat(e.mean) + "," +
           stat(e.median) + "," + stat(e.trimean) + "," + stat(e.best25) + "," + stat(e.worst25) + "," +
           stat(e.p95) + "," + stat(e.max) + "," +
           (gamut ? number(double(s.truth_in_feasible) / double(s.images)) : "") + "," + number(s.worst_case_covers) +
           "," + number(s.worst_case_correlation) + "\n";
  }
  return out;
}

Json summary_json(const BenchmarkSummary& s) {
  const ErrorStatistics& e = s.errors;
  const bool any = e.n > 0;
  auto stat = [&](double x) { return any ? Json(x) : Json(nullptr); };
  Json j = {{"method", s.method},
            {"images", s.images},
            {"answered", s.answered},
            {"errors_deg",
             {{"n", e.n}, {"mean", stat(e.mean)}, {"median", stat(e.median)}, {"trimean", stat(e.trimean)},
              {"best25", stat(e.best25)}, {"worst25", stat(e.worst25)}, {"p95", stat(e.p95)}, {"max", stat(e.max)}}}};
  if (s.method.rfind("gm", 0) == 0) {
    j["empty"] = s.empty;
    j["fallback"] = "grey_world";
    j["truth_in_feasible"] = s.truth_in_feasible;
    j["worst_case_covers"] = optional_json(s.worst_case_covers);
    j["worst_case_correlation"] = optional_json(s.worst_case_correlation);
  }
  return j;
}

Json record_json(const BenchmarkRecord& r, const std::vector<BenchmarkImage>& images) {
  const BenchmarkImage& im = images[r.image];
  Json j = {{"image", im.name}, {"fold", im.fold}, {"method", r.method}};
  j["light"] = r.light ? Json(*r.light) : Json(nullptr);
  j["error_deg"] = optional_json(r.error_deg);
  j["answered"] = r.answered;
  j["fallback"] = r.fallback.empty() ? Json(nullptr) : Json(r.fallback);
  if (!r.feasible_kind.empty()) {
    j["feasible_set"] = {{"kind", r.feasible_kind}, {"vertices", r.feasible_vertices}};
    j["truth_in_feasible"] = r.truth_in_feasible ? Json(*r.truth_in_feasible) : Json(nullptr);
    j["worst_case_deg"] = optional_json(r.worst_case_deg);
  }
  return j;
}

}  // namespace

CLI::App* add_benchmark_command(CLI::App& app, BenchmarkCliOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "benchmark",
      "Run a colour-constancy dataset: per cross-validation fold, canonical gamuts learned from the "
      "other folds; every gamut method and baseline on the same pixels; the recovery-error table "
      "(docs/photographs.md §6).");
  cmd->add_option("--images", o.images_dir, "the folder the truth table's image paths are relative to")->required();
  cmd->add_option("--truths", o.truths_path,
                  "CSV image,r,g,b[,black_level][,saturation][,mask][,chart]: each image's measured light "
                  "(and its own pixel rules), in the dataset's order")
      ->required();
  cmd->add_option("--folds", o.folds, "K folds: the image on data line i (from 0) is in fold i mod K");
  cmd->add_option("--folds-file", o.folds_path, "CSV image,fold: the dataset's own split");
  cmd->add_option("--methods", o.methods,
                  "the methods, of gm3d-max-trace, gm3d-max-volume, gm3d-centroid, gm2d-max-area, "
                  "gm2d-mean-2d, gm2d-mean-3d, grey-world, white-patch, shades-of-grey, grey-edge-1, "
                  "grey-edge-2 (default all)")
      ->delimiter(',')
      ->check(CLI::IsMember(benchmark_methods()));
  cmd->add_option("--intensity", o.intensity, "3-D canonical learning: max or none (as gmcc canonical)")
      ->check(CLI::IsMember({"max", "none"}))
      ->capture_default_str();
  cmd->add_option("--black", o.black, "include or exclude black in the 3-D canonical gamut")
      ->check(CLI::IsMember({"include", "exclude"}))
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "worker threads, 0 for the machine's cores")->capture_default_str();
  cmd->add_option("--csv", o.csv_path, "write one row per method to this CSV file");
  cmd->add_option("--json", o.json_path, "write the summaries as one JSON document to this file");
  cmd->add_option("--records", o.records_path, "write one JSON line per image and method to this file");
  cmd->add_flag("--no-progress", o.no_progress, "no progress line on stderr");
  add_pixel_options(*cmd, o.pixels);
  // The colour set and binning are the methods' own, a mask is per image (the truth table).
  for (const char* name : {"--colour-set", "--bin", "--mask"}) cmd->remove_option(cmd->get_option(name));
  return cmd;
}

int run_benchmark_command(const BenchmarkCliOptions& o) {
  const PixelSettings settings = pixel_settings(o.pixels);
  const std::vector<BenchmarkImage> images = dataset(o);
  BenchmarkOptions options;
  if (!o.methods.empty()) options.methods = o.methods;
  options.pixels = settings.rules;
  options.saturation_max = settings.saturation_max;
  options.intensity = canonical_intensity_from_string(o.intensity);
  options.black = o.black == "exclude" ? CanonicalBlack::exclude : CanonicalBlack::include;
  options.threads = static_cast<unsigned>(integer_option("--threads", o.threads, 0, 1024));
  std::optional<PendingFile> csv_file, json_file, records_file;
  if (!o.csv_path.empty()) csv_file.emplace(o.csv_path);
  if (!o.json_path.empty()) json_file.emplace(o.json_path);
  if (!o.records_path.empty()) records_file.emplace(o.records_path);
  const auto start = std::chrono::steady_clock::now();
  if (!o.no_progress)
    options.progress = [start](std::size_t done, std::size_t total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s < 2 && done < total) return;
      std::cerr << "\rgmcc benchmark: " << done << " of " << total << " images, " << fixed(s, 1) << " s"
                << (done == total ? "\n" : "") << std::flush;
    };
  const BenchmarkResult result = run_benchmark(images, options);
  if (csv_file) csv_file->commit(csv(result));
  if (json_file) {
    Json j;
    j["provenance"] = provenance_json(true);
    j["images"] = images.size();
    j["methods"] = Json::array();
    for (const BenchmarkSummary& s : result.summaries) j["methods"].push_back(summary_json(s));
    json_file->commit(j.dump(2) + "\n");
  }
  if (records_file) {
    std::string text = Json{{"provenance", provenance_json(true)}}.dump() + "\n";
    for (const BenchmarkRecord& r : result.records) text += record_json(r, images).dump() + "\n";
    records_file->commit(text);
  }
  write_stdout(table(result));
  return 0;
}

}  // namespace gmcc::cli
