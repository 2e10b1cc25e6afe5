#pragma once
// `gmcc select --images --record`: one scene's record in the record contract (docs/cli.md
// "Record contract"; the library's select_scene_record.h).

#include "json_output.h"

#include <gmcc/selection/select_scene_record.h>

namespace gmcc::cli {

/// The members of one scene's record after `line` and `id`: `record` (the contract's version),
/// input, feasible_set, constraint, recovery, selections, truth.
Json record_json(const SelectRecord& record);

}  // namespace gmcc::cli
