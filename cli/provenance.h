#pragma once
// Provenance of every output the command line writes (docs/cli.md
// "Provenance"): the gmcc version and git commit of the build, the command and
// its content-determining options (with their defaults, seeds included), and
// the size and SHA-256 of every input file read. Output destinations (--csv,
// --plot, --scenes-out, ...), --shard and the resource limits are not recorded:
// they do not change what is written, so a merged sharded run and the whole run
// carry the same record.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace gmcc::cli {

/// Remember the parsed command line (call once, after parsing).
void record_command(const CLI::App& app);

/// Amend the recorded options to what the run put in effect: `name` recorded with `value` (a
/// default the route replaces, a level read from a file), or left out (an option of another route
/// that this run does not use: a default of the 2-D route on a 3-D run records nothing).
///@{
void record_option_in_effect(const std::string& name, const std::string& value);
void drop_recorded_option(const std::string& name);
///@}

/// The record: {"software", "version", "commit", "command", "options",
/// "inputs"}, inputs being the files read so far, in the order read, or sorted by path when
/// `inputs_by_path` (a run that reads its inputs in parallel: the same record every run).
nlohmann::ordered_json provenance_json(bool inputs_by_path = false);

/// The record as one CSV comment line, "# gmcc-provenance: {compact JSON}\n",
/// for the top of a CSV file (gmcc's readers, and pandas with comment='#', skip
/// it).
std::string provenance_csv_line(bool inputs_by_path = false);

/// "gmcc 0.2.0 (commit <hash>, <date>)".
std::string version_line();

/// A BibTeX entry citing this build: version, commit and commit date.
std::string bibtex_of_this_build();

}  // namespace gmcc::cli
