#pragma once
// The plain form of a `gmcc select --images` scene line, read without building a JSON tree:
// {"id": 12 or "name", "colours": [[r, g, b], …], "truth": [r, g, b]} with numbers written as
// non-negative JSON numbers or as strings of printable ASCII without escapes. What a study
// writes; anything else is left to the full reader (parse_batch_scene), which also gives every
// error message. Reading a line this way took a third of `--record`'s time per scene.

#include "select_batch.h"

#include <string_view>

namespace gmcc::cli {

/// Read `text` into `scene` when it is a plain scene line (above) that parse_batch_scene would
/// accept, with the same id, colours and truth; false, with `scene` untouched, for anything else
/// (then parse_batch_scene decides, and names any problem).
bool parse_plain_batch_scene(std::string_view text, BatchScene& scene);

}  // namespace gmcc::cli
