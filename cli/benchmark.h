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
  std::string folds = "";        // K: fold = line index mod K
  std::string folds_path;        // image,fold
  std::vector<std::string> methods;
  std::string intensity = "max";
  std::string black = "include";
  std::string threads = "0";
  std::string csv_path, json_path, records_path;
  bool no_progress = false;
  PixelOptions pixels;
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_benchmark_command(CLI::App& app, BenchmarkCliOptions& options);

/// Run it. \throws InputError.
int run_benchmark_command(const BenchmarkCliOptions& options);

}  // namespace gmcc::cli
