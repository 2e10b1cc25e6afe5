#pragma once
// `gmcc benchmark`: a colour-constancy dataset in one command (docs/cli.md "gmcc benchmark";
// gmcc/validation/benchmark.h): folds, canonical gamuts learned per fold, every gamut method and
// baseline on the same pixels, the field's table, records per image.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "pixel_options.h"

namespace gmcc::cli {

struct BenchmarkCliOptions {
  std::string images_dir;
  std::string truths_path;
  std::string layout = "table";  // table | nus | cube+
  std::string folds = "";        // K: fold = line index mod K
  std::string folds_path;        // image,fold
  std::vector<std::string> methods;
  std::string intensity = "max";
  std::string black = "include";
  std::string edge_sigma = "1";  // the edge-based methods' derivative scale, pixels
  std::string threads = "0";
  std::string csv_path, json_path, records_path, plot_dir;
  bool no_progress = false;
  std::string shard;  // K/N: estimate only part K of N (every image still read)
  PixelOptions pixels;
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_benchmark_command(CLI::App& app, BenchmarkCliOptions& options);

/// Run it. \throws InputError.
int run_benchmark_command(const BenchmarkCliOptions& options);

/// Whether a records file's second line is a benchmark's header (gmcc merge dispatches on it).
bool is_benchmark_records(const std::string& file);

/// `gmcc merge` of the --records files of one benchmark's shards: every image of the run
/// exactly once, the whole run's table on stdout and its CSV, JSON and records, byte for byte.
/// \throws InputError naming the file and line of a problem.
int merge_benchmark(const std::vector<std::string>& files, const std::string& csv_path,
                    const std::string& json_path, const std::string& records_path, const std::string& plot_dir);

}  // namespace gmcc::cli
