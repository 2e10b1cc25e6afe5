#pragma once
// What `gmcc benchmark` (benchmark.cpp) and the merge of its shards (benchmark_merge.cpp) write:
// the images' names and folds, the run's outputs and its plot.

#include <gmcc/validation/benchmark.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "output_files.h"

namespace gmcc::cli {

// An image's name and fold, by its index in the dataset.
struct ImageOf {
  std::vector<std::string> name;
  std::vector<int> fold;
};

// Every output of a run (or of merged shards): the CSV, the JSON, the records, the table.
void write_outputs(const BenchmarkResult& result, const ImageOf& images, const std::vector<std::string>& methods,
                   const std::string& shard, const nlohmann::ordered_json& provenance,
                   std::optional<PendingFile>& csv_file, std::optional<PendingFile>& json_file,
                   std::optional<PendingFile>& records_file);

// --plot's folder and its two files, opened before any work (as reproduce does), so a folder that
// cannot be written is reported before the run and nothing else is written; none when dir is empty.
struct PlotFiles {
  explicit PlotFiles(const std::string& plot_dir);
  std::string dir;
  std::optional<PendingFile> dat, gp;
};

// The plot into `plot`'s files (none when its dir is empty), drawn with gnuplot; the exit status.
int draw(const BenchmarkResult& result, PlotFiles& plot, const nlohmann::ordered_json& provenance);

}  // namespace gmcc::cli
