#pragma once
// What the scene benchmarks share: their own flags, taken from the command line before Google
// Benchmark sees it (--scenes N scenes per test light, --surfaces K, --data DIR; a flag a
// benchmark does not have, a null pointer below, is left to Google Benchmark), and the paper's
// synthetic setup.

#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace gmcc::bench {

struct SceneFlags {
  std::uint64_t* scenes = nullptr;  ///< --scenes N
  int* surfaces = nullptr;          ///< --surfaces K
  std::string* data_dir = nullptr;  ///< --data DIR
};

/// Reads our flags into `f`'s targets, then initialises Google Benchmark with the rest.
inline void initialise(int argc, char** argv, const SceneFlags& f) {
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const bool value = i + 1 < argc;
    if (value && f.scenes && !std::strcmp(argv[i], "--scenes")) *f.scenes = std::stoull(argv[++i]);
    else if (value && f.surfaces && !std::strcmp(argv[i], "--surfaces")) *f.surfaces = std::stoi(argv[++i]);
    else if (value && f.data_dir && !std::strcmp(argv[i], "--data")) *f.data_dir = argv[++i];
    else rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
}

/// The synthetic experiment's setup (Munsell chips, CIE daylight, canonical D55; test lights D75,
/// D100, P2856, P15000) from the data folder.
inline ExperimentSetup paper_setup(const std::string& data_dir) {
  return synthetic_setup(read_spectral_csv(data_dir + "/munsell_matt_1269_joensuu_5nm.csv"),
                         read_spectral_csv(data_dir + "/cie_daylight_basis_S0_S1_S2.csv"), "D55",
                         {"D75", "D100", "P2856", "P15000"});
}

}  // namespace gmcc::bench
