#pragma once
// What `gmcc select` prints: the JSON contract of docs/cli.md "JSON output", the batch records of
// "Batch selection", and a short summary for people.

#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/select_scene.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace gmcc::cli {

using Json = nlohmann::ordered_json;

/// The members of one scene's JSON object: feasible_set, constraint, recovery, selections,
/// truth, and with `canonical_members` canonical_gamut and canonical_illuminant; then input.
Json scene_json(const PreparedCanonical& canonical, const SceneResult& result, bool canonical_members);

/// Every JSON document `gmcc select` writes (the one object, 2-D or 3-D) passes here once,
/// complete, before it is written: the one place where its "provenance" member is to be added
/// (docs/cli.md "Provenance").
void finish_document(Json& document);

/// What a JSON Lines output of `gmcc select --images` starts with, before its records: the one
/// place for its first line {"provenance": …} (docs/cli.md "Provenance"); empty for now.
std::string json_lines_preamble();

/// One JSON object, pretty-printed, ending in a newline.
std::string select_json(const PreparedCanonical& canonical, const SceneResult& result);
/// x in the text summaries: 10 significant digits (%.10g).
std::string fmt(double x);

/// A short readable summary.
std::string select_text(const PreparedCanonical& canonical, const SceneResult& result);

}  // namespace gmcc::cli
