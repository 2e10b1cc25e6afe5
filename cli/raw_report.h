#pragma once
// What a camera raw file's reading used (input/raw_file.h; docs/conventions.md §8), as
// `gmcc estimate` and `gmcc benchmark` report it: the camera, the 2×2 colour filter pattern, the
// black level of each quad position and the white level (each the file's own or given), and the
// quads dropped as saturated.

#include <gmcc/input/raw_file.h>

#include <nlohmann/json.hpp>

#include <string>

namespace gmcc::cli {

/// {"camera", "pattern", "black": [4 levels in the pattern's order], "black_from", "white",
/// "white_from", "saturated_quads"}; *_from is "file" (its metadata) or "given" (--black-level,
/// --saturation or a truth-table column).
inline nlohmann::ordered_json raw_json(const RawImage& raw) {
  return {{"camera", raw.camera},
          {"pattern", raw.pattern},
          {"black", raw.black},
          {"black_from", raw.black_given ? "given" : "file"},
          {"white", raw.white},
          {"white_from", raw.white_given ? "given" : "file"},
          {"saturated_quads", raw.saturated}};
}

/// One summary line: "  raw: Canon EOS Kiss X4, RGGB, black 2056 2056 2056 2056 (the file's),
/// white 15000 (the file's), 12 quads saturated\n".
inline std::string raw_text(const RawImage& raw) {
  std::string black;
  for (std::uint32_t b : raw.black) black += " " + std::to_string(b);
  return "  raw: " + raw.camera + ", " + raw.pattern + ", black" + black +
         (raw.black_given ? " (given)" : " (the file's)") + ", white " + std::to_string(raw.white) +
         (raw.white_given ? " (given)" : " (the file's)") + ", " + std::to_string(raw.saturated) +
         " quads saturated\n";
}

}  // namespace gmcc::cli
