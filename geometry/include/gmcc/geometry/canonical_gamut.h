#pragma once
/// \file canonical_gamut.h
/// The canonical gamut G_c: the convex hull of the canonical chromaticities (Forsyth 1990;
/// Finlayson 1996 §3), optionally expanded as the seed paper did (Finlayson & Hordley 1999 §4:
/// "expanded by 10%"), by a named policy that keeps chromaticities positive (docs/math.md §1).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set.h>

#include <string>
#include <vector>

namespace gmcc {

/// How to enlarge the canonical gamut by a factor F >= 0 (s = 1 + F).
enum class ExpansionPolicy {
  none,            ///< G_c as measured (the default)
  centroid_clip,   ///< scale about the area centroid by s, then clip each axis at
                   ///< (original minimum) / s: never below the measured gamut's own
                   ///< multiplicative reach, so chromaticities stay > 0 when they were
  multiplicative,  ///< a box in log-chromaticity: the hull of (x·s^±1, y·s^±1) over the
                   ///< hull's vertices; exact, and positive whenever the input is
};

/// `none`, `centroid-clip`, `multiplicative`.
std::string to_string(ExpansionPolicy policy);
/// Inverse of to_string. \throws std::invalid_argument listing the valid names.
ExpansionPolicy expansion_policy_from_string(const std::string& name);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> expansion_policy_names();

/// The expansion to apply: policy and factor F (0.1 means 10%).
struct Expansion {
  ExpansionPolicy policy = ExpansionPolicy::none;  ///< how to expand; `none` leaves G_c as it is
  Rational factor = 0;  ///< F >= 0, exact: 0.1 enlarges by 10%; 0 with every policy but `none` is a no-op
};

/// Checks an expansion: the factor >= 0, and a policy other than none for a factor > 0.
/// \throws OptionError (option_error.h) naming `expand` or `expand_policy`.
void check_options(const Expansion& expansion);

/// G_c: the exact hull of `chromaticities`, expanded by `expansion`.
/// \throws OptionError (a std::invalid_argument) as check_options.
/// Complexity O(n log n).
ConvexSet2 canonical_gamut(const std::vector<Point2>& chromaticities,
                           const Expansion& expansion = {});

}  // namespace gmcc
