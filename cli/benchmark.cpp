#include "benchmark_command.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>
#include <gmcc/input/truth_table.h>

#include "dataset_layouts.h"
#include <gmcc/validation/benchmark.h>
#include <gmcc/validation/error_statistics.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "benchmark_outputs.h"
#include "exit_cleanup.h"
#include "integer_option.h"
#include "json_fields.h"
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
  if (o.layout == "table" && o.truths_path.empty())
    throw InputError("--truths", 0, "required with --layout table (a dataset as shipped: --layout nus or cube+)");
  if (o.layout != "table" && !o.truths_path.empty())
    throw InputError("--truths", 0, "not with --layout " + o.layout + ": the layout's own files give the lights");
  std::map<std::string, int> shipped_folds;
  const std::vector<TruthRow> rows = o.layout == "table" ? read_truth_table(o.truths_path)
                                                         : read_dataset(o.layout, o.images_dir, shipped_folds);
  if (o.layout == "table") require_paths_under_folder(rows, o.truths_path);
  if (o.folds_path.empty() && o.folds.empty() && !shipped_folds.empty())
    return benchmark_dataset(o.images_dir, rows, &shipped_folds,
                             (std::filesystem::path(o.images_dir) / "threefoldCVsplit.mat").string(), 0);
  if (!o.folds_path.empty()) {
    if (!o.folds.empty()) throw InputError("--folds", 0, "give --folds K or --folds-file F.csv, not both");
    const std::map<std::string, int> folds = read_folds_file(o.folds_path);
    return benchmark_dataset(o.images_dir, rows, &folds, o.folds_path, 0);
  }
  if (o.folds.empty())
    throw InputError("--folds", 0, "required: --folds K (fold = line index mod K) or --folds-file F.csv (a "
                                   "Gehler-Shi folder with threefoldCVsplit.mat brings its own)");
  return benchmark_dataset(o.images_dir, rows, nullptr, "",
                           static_cast<int>(integer_option("--folds", o.folds, 2, 1000000)));
}

std::string table(const BenchmarkResult& r) {
  std::ostringstream t;
  char line[256];
  int w = 16;  // the method column: as wide as the longest name asked for
  for (const BenchmarkSummary& s : r.summaries) w = std::max(w, static_cast<int>(s.method.size()));
  std::snprintf(line, sizeof line, "%-*s %6s %8s %7s %7s %7s %7s %7s %7s %7s %7s %7s\n", w, "method", "images",
                "answered", "mean", "median", "trimean", "best25", "worst25", "p95", "max", "in F", "wc>=err");
  t << line;
  for (const BenchmarkSummary& s : r.summaries) {
    const ErrorStatistics& e = s.errors;
    const bool gamut = is_gamut_method(s.method);
    std::snprintf(line, sizeof line, "%-*s %6zu %8zu %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7s %7s\n", w,
                  s.method.c_str(), s.images, s.answered, e.mean, e.median, e.trimean, e.best25, e.worst25, e.p95,
                  e.max, gamut ? (fixed(100.0 * double(s.truth_in_feasible) / double(s.images), 1) + "%").c_str() : "",
                  s.worst_case_covers ? (fixed(100.0 * *s.worst_case_covers, 1) + "%").c_str() : "");
    t << line;
  }
  t << "recovery angular error in degrees; a gamut method with no estimate (F empty, no positive map, or "
       "no feasible set) takes grey world's; in F: images whose true light lies in the feasible set "
       "(decided exactly); wc>=err: answered images whose error is at most the rule's certified worst "
       "case, both in the worst case's space (2-D: illuminant, or map where F touches an axis; 3-D: map)\n";
  return t.str();
}

std::string csv(const BenchmarkResult& r) {
  std::string out = "method,images,answered,empty,unanswered_other,fallback,mean_deg,median_deg,trimean_deg,best25_deg,worst25_deg,p95_deg,"
         "max_deg,truth_in_feasible,worst_case_covers,worst_case_correlation\n";
  for (const BenchmarkSummary& s : r.summaries) {
    const ErrorStatistics& e = s.errors;
    const bool gamut = is_gamut_method(s.method);
    const bool any = e.n > 0;
    auto stat = [&](double x) { return any ? number(x) : std::string(); };
    out += s.method + "," + std::to_string(s.images) + "," + std::to_string(s.answered) + "," +
           (gamut ? std::to_string(s.empty) : "") + "," + std::to_string(s.unanswered_other) + "," +
           (gamut ? "grey_world" : "") + "," + stat(e.mean) + "," +
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
            {"unanswered_other", s.unanswered_other},
            {"errors_deg",
             {{"n", e.n}, {"mean", stat(e.mean)}, {"median", stat(e.median)}, {"trimean", stat(e.trimean)},
              {"best25", stat(e.best25)}, {"worst25", stat(e.worst25)}, {"p95", stat(e.p95)}, {"max", stat(e.max)}}}};
  if (is_gamut_method(s.method)) {
    j["empty"] = s.empty;
    j["fallback"] = "grey_world";
    j["truth_in_feasible"] = s.truth_in_feasible;
    j["worst_case_covers"] = optional_json(s.worst_case_covers);
    j["worst_case_correlation"] = optional_json(s.worst_case_correlation);
  }
  return j;
}

Json record_json(const BenchmarkRecord& r, const ImageOf& images) {
  Json j = {{"index", r.image}, {"image", images.name[r.image]}, {"fold", images.fold[r.image]}, {"method", r.method}};
  j["light"] = r.light ? Json(*r.light) : Json(nullptr);
  j["error_deg"] = optional_json(r.error_deg);
  j["answered"] = r.answered;
  j["fallback"] = r.fallback.empty() ? Json(nullptr) : Json(r.fallback);
  j["unanswered"] = r.unanswered.empty() ? Json(nullptr) : Json(r.unanswered);
  if (!r.feasible_kind.empty()) {
    j["feasible_set"] = {{"kind", r.feasible_kind}, {"vertices", r.feasible_vertices}};
    j["truth_in_feasible"] = r.truth_in_feasible ? Json(*r.truth_in_feasible) : Json(nullptr);
    j["worst_case_deg"] = optional_json(r.worst_case_deg);
    j["worst_case_space"] = r.worst_case_space;
    j["worst_case_space_error_deg"] = optional_json(r.worst_case_space_error_deg);
  }
  return j;
}

// The header line after the provenance: what run the records are of, and which part.
Json header_json(std::size_t images, const std::vector<std::string>& methods, const std::string& shard) {
  return Json{{"benchmark", {{"images", images}, {"methods", methods}, {"shard", shard}}}};
}

// --plot: benchmark.dat (per method, index k: its sorted errors and the share of images at or
// below each; then index M: per method its 5th, 25th, 50th, 75th and 95th percentiles) and
// benchmark.gp (cumulative error curves, and the distributions as boxes), drawn by gnuplot.
void write_plot(const BenchmarkResult& result, PlotFiles& plot, const Json& provenance) {
  std::string dat = "# gmcc-provenance: " + provenance.dump() + "\n# gmcc benchmark: recovery angular errors (deg) per method\n";
  std::vector<std::string> names;
  for (const BenchmarkSummary& s : result.summaries) {
    std::vector<double> e;
    for (const BenchmarkRecord& r : result.records)
      if (r.method == s.method && r.error_deg) e.push_back(*r.error_deg);
    std::sort(e.begin(), e.end());
    dat += "# " + s.method + "\n";
    for (std::size_t i = 0; i < e.size(); ++i) dat += number(e[i]) + " " + number(double(i + 1) / double(e.size())) + "\n";
    if (e.empty()) dat += "0 0\n";
    dat += "\n\n";
    names.push_back(s.method);
  }
  dat += "# method index, p5, p25, median, p75, p95\n";
  for (std::size_t k = 0; k < result.summaries.size(); ++k) {
    std::vector<double> e;
    for (const BenchmarkRecord& r : result.records)
      if (r.method == names[k] && r.error_deg) e.push_back(*r.error_deg);
    std::sort(e.begin(), e.end());
    if (e.empty()) continue;
    dat += std::to_string(k + 1);
    for (double q : {0.05, 0.25, 0.5, 0.75, 0.95}) dat += " " + number(sorted_quantile(e, q));
    dat += "\n";
  }
  std::string gp = "# gmcc benchmark: cumulative recovery-error curves and their distributions, per method\n"
                   "if (!exists('png_file')) png_file = 'benchmark.png'\n"
                   "if (!exists('svg_file')) svg_file = 'benchmark.svg'\n"
                   "set datafile commentschars '#'\nset grid lc rgb '#dddddd'\n";
  std::string curves = "plot ", boxes = "set xtics (";
  for (std::size_t k = 0; k < names.size(); ++k) {
    curves += std::string(k ? ", '' " : "'benchmark.dat' ") + "index " + std::to_string(k) +
              " using 1:2 with steps lw 2 dt " + (is_gamut_method(names[k]) ? "1" : "2") + " title '" + names[k] + "'";
    boxes += (k ? ", '" : "'") + names[k] + "' " + std::to_string(k + 1);
  }
  boxes += ") rotate by 45 right\n";
  gp += "do for [term = 1:2] {\n"
        "  if (term == 1) { set terminal pngcairo size 1500,560 font ',9'; set output png_file }\n"
        "  if (term == 2) { set terminal svg size 1500,560 font 'sans,9'; set output svg_file }\n"
        "  set multiplot layout 1,2\n"
        "  set xlabel 'recovery angular error (deg)'; set ylabel 'share of images'; set xrange [0:20]; set yrange [0:1]\n"
        "  set key bottom right\n  " + curves + "\n"
        "  set xlabel ''; set ylabel 'recovery angular error (deg): 5, 25, 50, 75, 95th percentiles'\n"
        "  set xrange [0.5:" + std::to_string(names.size()) + ".5]; set yrange [0:*]; unset key\n"
        "  " + boxes +
        "  set boxwidth 0.5\n"
        "  plot 'benchmark.dat' index " + std::to_string(names.size()) +
        " using 1:3:2:6:5 with candlesticks whiskerbars lw 1.5 lc rgb '#1f77b4', "
        "'' index " + std::to_string(names.size()) + " using 1:4:4:4:4 with candlesticks lw 2 lc rgb '#d62728'\n"
        "  unset xtics; set xtics auto\n  unset multiplot\n  set output\n}\n";
  plot.dat->commit(dat);
  plot.gp->commit(gp);
}

}  // namespace

// Every output of a run (or of merged shards): the CSV, the JSON, the records, the table.
void write_outputs(const BenchmarkResult& result, const ImageOf& images, const std::vector<std::string>& methods,
                   const std::string& shard, const Json& provenance, std::optional<PendingFile>& csv_file,
                   std::optional<PendingFile>& json_file, std::optional<PendingFile>& records_file) {
  if (csv_file) csv_file->commit("# gmcc-provenance: " + provenance.dump() + "\n" + csv(result));
  if (json_file) {
    Json j;
    j["provenance"] = provenance;
    j["images"] = images.name.size();
    j["methods"] = Json::array();
    for (const BenchmarkSummary& s : result.summaries) j["methods"].push_back(summary_json(s));
    json_file->commit(j.dump(2) + "\n");
  }
  if (records_file) {
    std::string text = Json{{"provenance", provenance}}.dump() + "\n";
    text += header_json(images.name.size(), methods, shard).dump() + "\n";
    for (const BenchmarkRecord& r : result.records) text += record_json(r, images).dump() + "\n";
    records_file->commit(text);
  }
  write_stdout(table(result));
}

PlotFiles::PlotFiles(const std::string& plot_dir) : dir(plot_dir) {
  if (dir.empty()) return;
  ensure_directory(dir);
  dat.emplace(std::filesystem::path(dir) / "benchmark.dat");
  gp.emplace(std::filesystem::path(dir) / "benchmark.gp");
}

int draw(const BenchmarkResult& result, PlotFiles& plot, const Json& provenance) {
  if (plot.dir.empty()) return 0;
  write_plot(result, plot, provenance);
  return draw_with_gnuplot(plot.dir, "benchmark", "gmcc benchmark");
}

CLI::App* add_benchmark_command(CLI::App& app, BenchmarkCliOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "benchmark",
      "Run a colour-constancy dataset: per cross-validation fold, canonical gamuts learned from the "
      "other folds; every gamut method and baseline on the same pixels; the recovery-error table "
      "(docs/photographs.md §6).");
  cmd->add_option("--images", o.images_dir, "the folder the truth table's image paths are relative to")->required();
  cmd->add_option("--truths", o.truths_path,
                  "CSV image,r,g,b[,black_level][,saturation][,mask][,chart]: each image's measured light "
                  "(and its own pixel rules), in the dataset's order (--layout table)");
  cmd->add_option("--layout", o.layout,
                  "table (--truths), nus (a NUS 8-camera folder: <camera>_gt.mat and its PNGs), cube+ "
                  "(cube+_gt.txt and its PNGs) or gehler-shi (png/, real_illum_568.mat, coordinates/, and "
                  "threefoldCVsplit.mat: its folds unless --folds or --folds-file is given)")
      ->check(CLI::IsMember([] {
        std::vector<std::string> layouts = dataset_layout_names();
        layouts.insert(layouts.begin(), "table");
        return layouts;
      }()))
      ->capture_default_str();
  cmd->add_option("--folds", o.folds, "K folds: the image on data line i (from 0) is in fold i mod K");
  cmd->add_option("--folds-file", o.folds_path, "CSV image,fold: the dataset's own split");
  cmd->add_option("--methods", o.methods,
                  "the methods, of gm3d-max-trace, gm3d-max-volume, gm3d-centroid, gm2d-max-area, "
                  "gm2d-mean-2d, gm2d-mean-3d, grey-world, white-patch, shades-of-grey, grey-edge-1, "
                  "grey-edge-2 (the default: these eleven), and the edge-based gamut methods with max-trace "
                  "(Gijsenij et al. 2010): gm3d-edge1-max-trace, gm3d-edge2-max-trace (the gamuts of 1st- and "
                  "2nd-order derivative magnitudes), gm3d-1jet-max-trace (pixel and 1st-order feasible sets "
                  "intersected), gm3d-2jet-max-trace (pixel, 1st and 2nd order), and each 3-D and 2-D rule with "
                  "the illumination constraint of the fold's training lights: gm3d-max-trace-constrained, "
                  "gm3d-max-volume-constrained, gm3d-centroid-constrained (F3 within the cone of their maps, "
                  "Barnard's ECRULE), gm2d-max-area-constrained, gm2d-mean-2d-constrained, "
                  "gm2d-mean-3d-constrained (F within the hull of their perspective maps), and gcie (Finlayson, "
                  "Hordley & Tastl's gamut-constrained illuminant estimation: the training light whose gamut is "
                  "most consistent with the image)")
      ->delimiter(',')
      ->check(CLI::IsMember(benchmark_methods()));
  cmd->add_option("--intensity", o.intensity, "3-D canonical learning: max or none (as gmcc canonical)")
      ->check(CLI::IsMember(canonical_intensity_names()))
      ->capture_default_str();
  cmd->add_option("--black", o.black, "include or exclude black in the 3-D canonical gamut")
      ->check(CLI::IsMember(canonical_black_names()))
      ->capture_default_str();
  cmd->add_option("--edge-sigma", o.edge_sigma,
                  "the Gaussian derivative scale of the edge-based methods and the grey-edge baselines, in "
                  "pixels, more than 0 and at most 64")
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "worker threads, 0 for the machine's cores")->capture_default_str();
  cmd->add_option("--csv", o.csv_path, "write one row per method to this CSV file");
  cmd->add_option("--json", o.json_path, "write the summaries as one JSON document to this file");
  cmd->add_option("--records", o.records_path, "write one JSON line per image and method to this file");
  cmd->add_flag("--no-progress", o.no_progress, "no progress line on stderr");
  cmd->add_option("--plot", o.plot_dir,
                  "write benchmark.dat/.gp to this folder (cumulative error curves and each method's "
                  "distribution) and draw .png/.svg with gnuplot");
  cmd->add_option("--shard", o.shard,
                  "K/N: estimate only the images whose data line i has i mod N = K - 1 (every image is still "
                  "read: the canonical gamuts need them all); needs --records, and gmcc merge combines the parts");
  add_pixel_options(*cmd, o.pixels);
  // The colour set and binning are the methods' own, a mask is per image (the truth table).
  for (const char* name : {"--colour-set", "--bin", "--mask"}) cmd->remove_option(cmd->get_option(name));
  return cmd;
}

int run_benchmark_command(const BenchmarkCliOptions& o) {
  const PixelSettings settings = pixel_settings(o.pixels);
  const std::vector<BenchmarkImage> images = dataset(o);
  BenchmarkOptions options;
  for (std::size_t i = 0; i < o.methods.size(); ++i)
    if (std::find(o.methods.begin(), o.methods.begin() + static_cast<std::ptrdiff_t>(i), o.methods[i]) !=
        o.methods.begin() + static_cast<std::ptrdiff_t>(i))
      throw InputError("--methods", 0, quoted_text(o.methods[i]) + " is given twice");
  if (!o.methods.empty()) options.methods = o.methods;
  options.pixels = settings.run;
  options.intensity = canonical_intensity_from_string(o.intensity);
  options.black = canonical_black_from_string(o.black);
  options.threads = static_cast<unsigned>(integer_option("--threads", o.threads, 0, 1024));
  const bool edges = std::any_of(options.methods.begin(), options.methods.end(), is_edge_gamut_method);
  Rational sigma;
  try {
    sigma = parse_rational(o.edge_sigma);
  } catch (const std::invalid_argument& e) {
    throw InputError("--edge-sigma", 0, quoted_text(o.edge_sigma) + ": " + e.what());
  }
  if (sgn(sigma) <= 0 || sigma > 64) throw InputError("--edge-sigma", 0, "expected a sigma above 0 and at most 64 pixels");
  options.edge_sigma = to_double_nearest(sigma);
  if (edges && options.pixels.rules.prefilter_sigma != 0)
    throw InputError("--prefilter", 0, "not with the edge-based methods: their derivatives are Gaussian already");
  std::string shard = "1/1";
  if (!o.shard.empty()) {
    const auto slash = o.shard.find('/');
    const std::string why = "expected K/N with 1 <= K <= N, not " + quoted_text(o.shard);
    if (slash == std::string::npos) throw InputError("--shard", 0, why);
    options.shard_index = integer_option("--shard", o.shard.substr(0, slash), 1, 1000000);
    options.shard_count = integer_option("--shard", o.shard.substr(slash + 1), 1, 1000000);
    if (options.shard_index > options.shard_count) throw InputError("--shard", 0, why);
    if (o.records_path.empty())
      throw InputError("--shard", 0, "a shard needs --records FILE: gmcc merge combines the shards' records");
    for (const std::string* p : {&o.csv_path, &o.json_path, &o.plot_dir})
      if (!p->empty())
        throw InputError(p == &o.csv_path ? "--csv" : p == &o.json_path ? "--json" : "--plot", 0,
                         "not with --shard: a shard's statistics cover only its part; gmcc merge writes the whole "
                         "run's");
    shard = std::to_string(options.shard_index) + "/" + std::to_string(options.shard_count);
  }
  std::optional<PendingFile> csv_file, json_file, records_file;
  if (!o.csv_path.empty()) csv_file.emplace(o.csv_path);
  if (!o.json_path.empty()) json_file.emplace(o.json_path);
  if (!o.records_path.empty()) records_file.emplace(o.records_path);
  PlotFiles plot(o.plot_dir);
  const auto start = std::chrono::steady_clock::now();
  if (!o.no_progress)
    options.progress = [start](std::size_t done, std::size_t total) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s < 2) return;
      std::cerr << "\rgmcc benchmark: " << done << " of " << total << " images, " << fixed(s, 1) << " s"
                << (done == total ? "\n" : "") << std::flush;
      set_progress_line_open(done != total);
    };
  const BenchmarkResult result = run_benchmark(images, options);
  ImageOf of;
  for (const BenchmarkImage& im : images) of.name.push_back(im.name), of.fold.push_back(im.fold);
  write_outputs(result, of, options.methods, shard, provenance_json(true), csv_file, json_file, records_file);
  return draw(result, plot, provenance_json(true));
}

}  // namespace gmcc::cli
