// Fuzz target: `gmcc merge` of `gmcc reproduce --shard K/N --scenes-out` parts (cli/merge.h,
// run_merge in-process, the whole command line compiled into the target).
//
// The bytes are one or two part files, separated by a line "--part--". Either the merge writes
// its CSV and returns 0, or it throws gmcc::InputError naming one of the parts (or an option) in
// one line, and writes nothing: no output file, no temporary file left in the folder.

#include "fuzz_support.h"

#include "merge.h"

#include <gmcc/input/input_error.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n--part--\n";
  std::vector<std::string> parts;
  const std::size_t cut = text.find(separator);
  parts.push_back(text.substr(0, cut));
  if (cut != std::string::npos) parts.push_back(text.substr(cut + separator.size()));
  char dir_template[] = "/tmp/gmcc_fuzz_merge_XXXXXX";
  FUZZ_CHECK(mkdtemp(dir_template) != nullptr, "mkdtemp");
  const fs::path dir = fs::path(dir_template) / "w";
  fs::create_directory(dir);
  gmcc::cli::MergeOptions options;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const fs::path p = fs::path(dir_template) / ("part" + std::to_string(i + 1) + ".jsonl");
    std::ofstream(p, std::ios::binary) << parts[i];
    options.files.push_back(p.string());
  }
  options.csv_path = (dir / "merged.csv").string();
  bool ok = false;
  try {
    FUZZ_CHECK(gmcc::cli::run_merge(options) == 0, "a merge that returns without an error must succeed");
    ok = true;
  } catch (const gmcc::InputError& e) {
    const std::string message = e.what();
    bool names = message.rfind("--", 0) == 0;
    for (const std::string& f : options.files) names = names || message.rfind(f, 0) == 0;
    FUZZ_CHECK(names, "the message names no part and no option: " + message);
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
  }
  std::size_t written = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    (void)entry;
    ++written;
  }
  FUZZ_CHECK(ok ? written == 1 && fs::exists(options.csv_path) : written == 0,
             ok ? "the merged CSV is missing, or more was written" : "a failed merge wrote something");
  fs::remove_all(dir_template);
  return 0;
}
