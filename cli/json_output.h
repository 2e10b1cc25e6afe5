#pragma once
// What `gmcc select` prints: the JSON contract of SPEC §5 and a short summary for people.

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/select_maps.h>

#include <cstddef>
#include <string>

namespace gmcc::cli {

struct SelectReport {
  Expansion expansion;
  Colour canonical_illuminant{1, 1, 1};
  std::size_t canonical_colours = 0, canonical_dropped = 0;
  std::size_t image_colours = 0, image_dropped = 0;
  ConvexSet2 canonical_gamut;
  ConvexSet2 feasible;
  Selections selections;
};

/// One JSON object, pretty-printed, ending in a newline.
std::string select_json(const SelectReport& report);
/// A short readable summary.
std::string select_text(const SelectReport& report);

}  // namespace gmcc::cli
