#pragma once
// `gmcc select --images --record`: one scene's record in the record contract (docs/cli.md
// "Record contract"; the library's select_scene_record.h), written straight to text: a record is
// a few dozen numbers, and building a JSON tree for each took as long as selecting the scene.

#include "json_output.h"

#include <gmcc/selection/select_scene_record.h>

#include <cstddef>
#include <string>

namespace gmcc::cli {

/// One scene's record as one line of JSON (ending in a newline): `line`, `id` (unless null),
/// `record` (the contract's version), input, feasible_set, constraint, recovery, selections,
/// truth. Numbers are written as nlohmann::json writes them (the shortest form that reads back as
/// the same double, `1.0` for an integral one), so the record reads as the other outputs do.
std::string record_text(std::size_t line, const Json& id, const SelectRecord& record);

}  // namespace gmcc::cli
