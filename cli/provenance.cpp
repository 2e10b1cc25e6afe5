#include "provenance.h"

#include "citation_template.h"

#include <gmcc/input/build_info.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/input/file_digest.h>

#include <algorithm>
#include <set>

namespace gmcc::cli {
namespace {

using Json = nlohmann::ordered_json;

struct Command {
  std::string name;  // "select", "reproduce synthetic"
  Json options = Json::object();
};

Command& recorded() {
  static Command c;
  return c;
}

// Options that say where output goes or how long the run may take, not what it
// computes (--threads: results do not depend on it; --json: reproduce's is a
// file name, select's a format flag the output shows by itself).
const std::set<std::string>& not_recorded() {
  static const std::set<std::string> names{
      "--csv",          "--plot", "--scenes-out", "--out",       "--shard", "--time-limit",
      "--memory-limit", "--help", "--version",    "--corrected", "--json",  "--threads",
      "--records",      "--no-progress"};
  return names;
}

// Flags recorded only when given: flags added after the provenance's first contract that select
// another output contract (select's --record, docs/cli.md "Record contract"), so that an output
// made without them keeps its bytes.
const std::set<std::string>& recorded_when_given() {
  static const std::set<std::string> names{"--record"};
  return names;
}

// The options of one (sub)command: given ones with their values, the others
// with their default when CLI11 knows it.
void collect(const CLI::App& app, Json& options) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_lnames().empty()) continue;  // positional or short-only: none in gmcc
    const std::string name = "--" + opt->get_lnames().front();
    if (not_recorded().count(name) || (opt->count() == 0 && recorded_when_given().count(name))) continue;
    if (opt->count() > 0) {
      const std::vector<std::string>& results = opt->results();
      if (opt->get_expected_max() == 0) {  // a flag
        options[name] = true;
      } else {
        std::string joined;
        for (const std::string& r : results) joined += (joined.empty() ? "" : ",") + r;
        options[name] = joined;
      }
    } else if (opt->get_expected_max() == 0) {
      options[name] = false;
    } else if (!opt->get_default_str().empty()) {
      options[name] = opt->get_default_str();
    }
  }
}

}  // namespace

void record_command(const CLI::App& app) {
  Command c;
  Json options = Json::object();
  collect(app,
          options);  // the global options (none recorded today but future ones)
  const CLI::App* current = &app;
  for (;;) {
    const std::vector<const CLI::App*> subs =
        current->get_subcommands([](const CLI::App* a) { return a->parsed(); });
    if (subs.empty()) break;
    current = subs.front();
    c.name += (c.name.empty() ? "" : " ") + current->get_name();
    collect(*current, options);
  }
  c.options = std::move(options);
  recorded() = std::move(c);
}

void record_option_in_effect(const std::string& name, const std::string& value) { recorded().options[name] = value; }

void drop_recorded_option(const std::string& name) { recorded().options.erase(name); }

Json provenance_json(bool inputs_by_path) {
  Json p;
  p["software"] = "gmcc";
  p["version"] = std::string(gmcc_version());
  p["commit"] = std::string(gmcc_commit());
  p["command"] = recorded().name;
  p["options"] = recorded().options;
  Json inputs = Json::array();
  std::vector<FileDigest> files = files_read();
  if (inputs_by_path)
    std::stable_sort(files.begin(), files.end(),
                     [](const FileDigest& a, const FileDigest& b) { return a.path < b.path; });
  for (const FileDigest& f : files)
    inputs.push_back(Json{{"path", f.path}, {"bytes", f.bytes}, {"sha256", f.sha256}});
  p["inputs"] = std::move(inputs);
  // The levels each image was read with (a dataset's or a raw file's own, which the options do
  // not show); only when images were read, so that other outputs keep their bytes.
  std::vector<ImageLevelsUsed> levels = image_levels_used();
  if (inputs_by_path)
    std::stable_sort(levels.begin(), levels.end(),
                     [](const ImageLevelsUsed& a, const ImageLevelsUsed& b) { return a.path < b.path; });
  if (!levels.empty()) {
    Json images = Json::array();
    for (const ImageLevelsUsed& l : levels)
      images.push_back(Json{{"path", l.path},
                            {"black_level", l.black.size() == 1 ? Json(l.black[0]) : Json(l.black)},
                            {"black_from", l.black_from},
                            {"saturation", l.saturation ? Json(*l.saturation) : Json(nullptr)},
                            {"saturation_from", l.saturation_from}});
    p["image_levels"] = std::move(images);
  }
  return p;
}

std::string provenance_csv_line(bool inputs_by_path) {
  return "# gmcc-provenance: " + provenance_json(inputs_by_path).dump() + "\n";
}

std::string version_line() {
  return "gmcc " + std::string(gmcc_version()) + " (commit " + std::string(gmcc_commit()) + ", " +
         std::string(gmcc_commit_date()) + ")";
}

std::string bibtex_of_this_build() {
  // cli/citation.bib.in, the one text of the entries (docs/manual/build_manual.py reads it too),
  // with this build's version, commit and, when the commit's date is known, its year and date.
  const std::string date(gmcc_commit_date());
  const std::string dated = date.size() >= 4 && date != "unknown"
                                ? "  year    = {" + date.substr(0, 4) + "},\n  date    = {" + date + "},\n"
                                : "";
  std::string b = citation_template;
  const std::pair<std::string, std::string> fill[] = {
      {"@VERSION@", std::string(gmcc_version())}, {"@COMMIT@", std::string(gmcc_commit())}, {"@DATED@", dated}};
  for (const auto& [key, value] : fill) b.replace(b.find(key), key.size(), value);
  return b;
}

}  // namespace gmcc::cli
