#pragma once
// `gmcc dataset`: what a dataset layout's reader (input/datasets/dataset_layouts.h) reads from a
// dataset's own files, written as the truth table `gmcc benchmark --truths` reads
// (docs/cli.md "gmcc dataset"; docs/photographs.md §6): each image's path, its light, its black
// level and saturation, and its chart polygon, numbers exact; and the shipped split as a folds
// file. It lets a user (and scripts/verify-datasets) check the reading against the files.

#include <CLI/CLI.hpp>

#include <string>

namespace gmcc::cli {

struct DatasetOptions {
  std::string layout;      // nus | cube+ | gehler-shi
  std::string images_dir;  // the dataset's folder
  std::string folds_out;   // where to write the shipped split (image,fold); empty: not written
};

/// Register `dataset`.
CLI::App* add_dataset_command(CLI::App& app, DatasetOptions& options);

/// Read the layout and write its truth table to stdout (provenance line first). Returns the exit
/// status. \throws InputError naming the file of a problem (nothing written).
int run_dataset(const DatasetOptions& options);

}  // namespace gmcc::cli
