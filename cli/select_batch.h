#pragma once
// `gmcc select --images FILE`: many images against one canonical gamut in one process, the
// canonical side prepared once; JSON Lines in and out (docs/cli.md "Batch selection").

#include "json_output.h"
#include "select.h"

#include <string>

namespace gmcc::cli {

/// Largest scene file accepted, in bytes (read whole, like a colour file).
inline constexpr std::size_t max_scene_file_bytes = std::size_t(1) << 30;
/// Most scenes in one file (each record is written to stdout as it is made, so memory holds the
/// scene file and one record, not the output).
inline constexpr std::size_t max_batch_scenes = 100000;

/// One scene of a scene file, as read from its line.
struct BatchScene {
  std::size_t line = 0;
  Json id;                      // null when the line gives none
  std::vector<Colour> colours;
  std::optional<Colour> truth;
};

/// Parse one line of a scene file: {"id": …, "colours": [[r,g,b], …], "truth": [r,g,b]}; every
/// number read exactly from its text (a JSON number or a string holding a decimal or p/q).
/// \throws InputError(file, line, problem) for a malformed line; `scene.id` is set as soon as it
///         is read, so an error record can carry it.
void parse_batch_scene(const std::string& text, const std::string& file, BatchScene& scene);

/// Run the batch: one record a scene on stdout, each written as it is made; returns 0 when
/// every scene was selected, 2 when any line gave an error record. Problems with the canonical
/// side or the scene file as a whole throw InputError (exit 2, nothing written).
int run_select_batch(const SelectOptions& options, const SelectSettings& settings);

}  // namespace gmcc::cli
