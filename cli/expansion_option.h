#pragma once
// The canonical gamut's expansion as `select`, `estimate` and `reproduce` read it.

#include <gmcc/geometry/canonical_gamut.h>

#include <string>

namespace gmcc::cli {

/// The canonical gamut's expansion from --expand and --expand-policy, read exactly and checked by
/// the library (check_options, canonical_gamut.h). \throws InputError naming the option.
Expansion expansion_option(const std::string& factor, const std::string& policy);

}  // namespace gmcc::cli
