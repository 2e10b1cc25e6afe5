#pragma once
// `gmcc select --space 3d`: Forsyth's CRULE in 3-D (the feasible set of diagonal maps as an exact
// polytope, max-volume and centroid selections). Options and files as `gmcc select`.

#include "select.h"

#include <string>

namespace gmcc::cli {

/// Run the 3-D path and print JSON or text; bad input throws gmcc::InputError.
int run_select_3d(const SelectOptions& options);

}  // namespace gmcc::cli
