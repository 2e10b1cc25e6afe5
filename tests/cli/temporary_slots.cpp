// exit_cleanup.h's registry bounds the temporary files alive at once, not those of a process:
// 300 outputs written one after another in one process (every other one abandoned before its
// commit, as a failed run abandons its outputs) all succeed, the committed ones are in place
// with their content, and no temporary is left. Then 64 files pending at once are accepted and
// a 65th is refused. (fuzz_merge ran out of slots after many merges in one process.)
#include "output_files.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const fs::path dir = fs::path(argv[1]);
  fs::remove_all(dir);
  fs::create_directories(dir);
  int failures = 0;
  for (int i = 0; i < 300; ++i) {
    gmcc::cli::PendingFile file(dir / ("out" + std::to_string(i) + ".txt"));
    if (i % 2 == 0) file.commit("file " + std::to_string(i) + "\n");
  }
  std::size_t entries = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++entries;
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) {
      std::cerr << "a temporary left: " << name << "\n";
      ++failures;
    }
  }
  if (entries != 150) {
    std::cerr << entries << " files, expected the 150 committed\n";
    ++failures;
  }
  std::string line;
  std::getline(std::ifstream(dir / "out298.txt"), line);
  if (line != "file 298") {
    std::cerr << "out298.txt holds '" << line << "'\n";
    ++failures;
  }
  std::vector<std::unique_ptr<gmcc::cli::PendingFile>> open;
  for (int i = 0; i < 64; ++i)
    open.push_back(std::make_unique<gmcc::cli::PendingFile>(dir / ("open" + std::to_string(i))));
  try {
    gmcc::cli::PendingFile one_more(dir / "open64");
    std::cerr << "a 65th pending file was accepted\n";
    ++failures;
  } catch (const std::length_error&) {
  }
  open.clear();
  fs::remove_all(dir);
  std::cout << (failures ? "FAILED\n" : "ok\n");
  return failures ? 1 : 0;
}
