#pragma once
// `gmcc accuracy`: how accurate is each route to the 3-D mean (Finlayson & Hordley 1999 §3.2)?
// The options and the files; the study itself, its table, CSV and plot are in
// gmcc/validation/accuracy_study.h (docs/accuracy.md).

#include <CLI/CLI.hpp>

#include <string>

namespace gmcc::cli {

struct AccuracyOptions {
  std::string csv_path;                  ///< long-format CSV; empty: none
  std::string plot_dir;                  ///< accuracy.dat, .gp (and .png, .svg via gnuplot)
  // Integers read exactly like every number gmcc reads (`1e7` is 10000000), and range-checked
  // in run_accuracy (CLI11 would wrap a negative seed to 2^64 − 1).
  std::string seed = "1";           ///< Monte Carlo generator seed (every run), 0 … 2^64 − 1
  std::string max_samples = "1e7";  ///< cap on the Monte Carlo sample counts 10^4 … 10^7
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_accuracy_command(CLI::App& app, AccuracyOptions& options);

/// Run it: every output file is written under a temporary name and renamed when complete.
/// Returns the exit status; unusable output paths throw gmcc::InputError (exit 2 at the edge).
int run_accuracy(const AccuracyOptions& options);

}  // namespace gmcc::cli
