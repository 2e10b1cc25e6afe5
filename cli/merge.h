#pragma once
// `gmcc merge`: the per-scene files of the shards of one `gmcc reproduce` run (--shard K/N
// --scenes-out FILE) combined into the outputs of the whole run, byte for byte
// (docs/reproduction.md "Sharding").

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gmcc::cli {

struct MergeOptions {
  std::vector<std::string> files;  // the shards' --scenes-out files, in any order
  std::string csv_path, json_path, scenes_out_path, plot_dir;
  std::string records_path;  // gmcc benchmark's shards: the whole run's records
};

/// Register `merge`.
CLI::App* add_merge_command(CLI::App& app, MergeOptions& options);

/// Check that the files hold every scene of one run exactly once and write its reports.
/// Returns the exit status. \throws InputError naming the file and line of a problem.
int run_merge(const MergeOptions& options);

}  // namespace gmcc::cli
