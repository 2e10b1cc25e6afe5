// `gmcc merge` of `gmcc benchmark --shard` records (benchmark.h): the shards' records read, checked
// to be one run's, each image under each method exactly once, and the run's outputs written.
#include "benchmark_command.h"

#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>
#include <gmcc/validation/benchmark.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "benchmark_outputs.h"
#include "json_fields.h"
#include "output_files.h"

namespace gmcc::cli {
namespace {

using Json = nlohmann::ordered_json;

std::optional<double> optional_field(const Json& j, const char* name, const Place& at) {
  if (!j.contains(name) || j.at(name).is_null()) return std::nullopt;
  return get<double>(j, name, at);
}

// The JSON lines of a records file: (line number, text).
std::vector<std::pair<std::size_t, std::string>> json_lines(const std::string& file) {
  const std::string text = read_text_file(
      file, {std::size_t(4) << 30, "records file", "JSON Lines from gmcc benchmark --records"});
  std::vector<std::pair<std::size_t, std::string>> out;
  std::size_t line = 0, start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line;
    if (end > start) out.push_back({line, text.substr(start, end - start)});
    start = end + 1;
  }
  return out;
}

}  // namespace

bool is_benchmark_records(const std::string& file) {
  const auto lines = json_lines(file);
  if (lines.size() < 2) return false;
  try {
    const Json j = Json::parse(lines[1].second);
    return j.is_object() && j.contains("benchmark");
  } catch (const Json::exception&) {
    return false;
  }
}

namespace {

// An angle in degrees read from a record: from 0 to 180 or none (a forged value is refused).
std::optional<double> angle_field(const Json& j, const char* name, const Place& at) {
  const std::optional<double> x = optional_field(j, name, at);
  if (x && !(*x >= 0 && *x <= 180)) bad(at, std::string(name) + " " + std::to_string(*x) + " is not an angle from 0 to 180 degrees");
  return x;
}

// One record line of a benchmark's shard (`images` images, `methods` its methods): the record, the
// position of its method in `method`, its image's name and fold noted in `seen` (and checked
// against what earlier records said of that image).
BenchmarkRecord merged_record(const Json& j, const Place& at, std::size_t images, const std::vector<std::string>& methods,
                              std::size_t& method, std::map<std::size_t, std::pair<std::string, int>>& seen) {
  BenchmarkRecord r;
  r.image = get<std::size_t>(j, "index", at);
  if (r.image >= images) bad(at, "image index " + std::to_string(r.image) + " beyond the run's " + std::to_string(images));
  r.method = get<std::string>(j, "method", at);
  const auto m = std::find(methods.begin(), methods.end(), r.method);
  if (m == methods.end()) bad(at, "method " + quoted_text(r.method) + " is not in the run");
  method = static_cast<std::size_t>(m - methods.begin());
  std::pair<std::string, int> image{get<std::string>(j, "image", at), get<int>(j, "fold", at)};
  if (image.second < 0) bad(at, "fold " + std::to_string(image.second) + " is negative");
  const auto [known, fresh] = seen.emplace(r.image, image);
  if (!fresh && known->second != image)
    bad(at, "image index " + std::to_string(r.image) + " is " + quoted_text(image.first) + " in fold " +
                std::to_string(image.second) + " here, " + quoted_text(known->second.first) + " in fold " +
                std::to_string(known->second.second) + " in an earlier record");
  if (!member(j, "light", at).is_null()) {
    r.light = get<std::array<double, 3>>(j, "light", at);
    for (double x : *r.light)
      if (!(x >= 0) || !std::isfinite(x)) bad(at, "light: a channel that is negative or not finite");
  }
  r.error_deg = angle_field(j, "error_deg", at);
  r.answered = get<bool>(j, "answered", at);
  if (!member(j, "fallback", at).is_null()) r.fallback = get<std::string>(j, "fallback", at);
  if (!member(j, "unanswered", at).is_null()) r.unanswered = get<std::string>(j, "unanswered", at);
  if (r.answered == !r.unanswered.empty()) bad(at, "\"answered\" and \"unanswered\" disagree");
  if (j.contains("feasible_set")) {
    const Json& f = j.at("feasible_set");
    r.feasible_kind = get<std::string>(f, "kind", at);
    r.feasible_vertices = get<std::size_t>(f, "vertices", at);
    if (!member(j, "truth_in_feasible", at).is_null()) r.truth_in_feasible = get<bool>(j, "truth_in_feasible", at);
    r.worst_case_deg = angle_field(j, "worst_case_deg", at);
    r.worst_case_space = get<std::string>(j, "worst_case_space", at);
    if (r.worst_case_space != "map" && r.worst_case_space != "illuminant")
      bad(at, "\"worst_case_space\" is " + quoted_text(r.worst_case_space) + ", not \"map\" or \"illuminant\"");
    r.worst_case_space_error_deg = angle_field(j, "worst_case_space_error_deg", at);
  }
  return r;
}

// The images' names and folds once every (image, method) of the header's `images` is read: each
// in range is read at most once, so all are there exactly when the count matches; otherwise the
// first one missing is named (found in the order of the keys read). No two indices may share a
// name. Nothing is made for the header's count before the records bear it out.
template <class Read>
ImageOf complete_images(const Read& read, const std::map<std::size_t, std::pair<std::string, int>>& seen,
                        std::size_t images, const std::vector<std::string>& methods, const std::string& first_file) {
  if (images > read.size() || read.size() != images * methods.size()) {
    std::pair<std::size_t, std::size_t> missing{0, 0};
    for (const auto& [key, value] : read) {
      if (key != missing) break;
      missing = missing.second + 1 < methods.size() ? std::make_pair(key.first, key.second + 1) : std::make_pair(key.first + 1, std::size_t(0));
    }
    const auto name = seen.find(missing.first);
    throw InputError(first_file, 0, "image " + (name != seen.end() ? name->second.first : "#" + std::to_string(missing.first)) +
                                        " under " + methods[missing.second] + " is in none of the files: a shard is missing");
  }
  ImageOf of;
  std::map<std::string, std::size_t> index_of;
  for (const auto& [index, image] : seen) {
    if (const auto [other, fresh] = index_of.emplace(image.first, index); !fresh)
      throw InputError(first_file, 0, "image " + quoted_text(image.first) + " has two indices, " + std::to_string(other->second) +
                                          " and " + std::to_string(index) + ": the records were altered");
    of.name.push_back(image.first);
    of.fold.push_back(image.second);
  }
  return of;
}

}  // namespace

int merge_benchmark(const std::vector<std::string>& files, const std::string& csv_path, const std::string& json_path,
                    const std::string& records_path, const std::string& plot_dir) {
  std::optional<PendingFile> csv_file, json_file, records_file;
  if (!csv_path.empty()) csv_file.emplace(csv_path);
  if (!json_path.empty()) json_file.emplace(json_path);
  if (!records_path.empty()) records_file.emplace(records_path);
  PlotFiles plot(plot_dir);
  std::optional<Json> provenance, setup;
  std::string first_file;
  std::size_t images = 0;
  std::vector<std::string> methods;
  // (index, method position) -> record, and where it was read.
  std::map<std::pair<std::size_t, std::size_t>, std::pair<BenchmarkRecord, Place>> read;
  // Each image's name and fold as the records give them; the header's image count is checked
  // against the records read before anything is made for that many.
  std::map<std::size_t, std::pair<std::string, int>> seen;
  std::set<std::string> shards;
  for (const std::string& file : files) {
    const auto lines = json_lines(file);
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const Place at{file, lines[k].first};
      Json j;
      try {
        j = Json::parse(lines[k].second);
      } catch (const Json::exception&) {
        bad(at, "not a JSON object");
      }
      if (k == 0) {
        if (!j.is_object() || j.size() != 1 || !j.contains("provenance")) bad(at, "expected the provenance line");
        if (!provenance) provenance = j.at("provenance");
        else if (*provenance != j.at("provenance"))
          bad(at, "another run's provenance than " + first_file + "'s (the shards of one run record the same)");
        continue;
      }
      if (k == 1) {
        if (!j.is_object() || !j.contains("benchmark")) bad(at, "expected the benchmark's header line");
        Json h = j.at("benchmark");
        const std::string shard = get<std::string>(h, "shard", at);
        if (!shards.insert(shard).second) bad(at, "shard " + shard + " is already in another file");
        h.erase("shard");
        if (!setup) {
          setup = h;
          first_file = file;
          images = get<std::size_t>(h, "images", at);
          methods = get<std::vector<std::string>>(h, "methods", at);
          if (methods.empty()) bad(at, "a run of no methods");
        } else if (*setup != h) {
          bad(at, "another run than " + first_file + "'s (only \"shard\" may differ)");
        }
        continue;
      }
      std::size_t method = 0;
      BenchmarkRecord r = merged_record(j, at, images, methods, method, seen);
      const auto key = std::make_pair(r.image, method);
      if (const auto earlier = read.find(key); earlier != read.end())
        bad(at, "image " + seen.at(r.image).first + " under " + r.method + " is already in " + earlier->second.second.file +
                           ":" + std::to_string(earlier->second.second.line));
      read.emplace(key, std::make_pair(std::move(r), at));
    }
  }
  if (!setup) throw InputError(files.front(), 0, "no benchmark records");
  const ImageOf of = complete_images(read, seen, images, methods, first_file);
  BenchmarkResult result;
  for (auto& [key, value] : read) result.records.push_back(std::move(value.first));
  result.summaries = summarise_benchmark(result.records, methods);
  write_outputs(result, of, methods, "1/1", *provenance, csv_file, json_file, records_file);
  return draw(result, plot, *provenance);
}

}  // namespace gmcc::cli
