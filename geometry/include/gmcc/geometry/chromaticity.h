#pragma once
/// \file chromaticity.h
/// Perspective chromaticity q = (r/b, g/b): Finlayson (1996) "Color in perspective", and
/// Finlayson & Hordley (1999) eq. (10).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace gmcc {

/// What to do with colours whose blue channel is <= 0: they have no perspective chromaticity.
enum class NonPositiveBluePolicy {
  drop,    ///< skip them and count them (the default of `gmcc select`)
  reject,  ///< throw NonPositiveBlue naming the first offending colour
};
/// `drop` or `reject`: the name every front end reads and writes (--nonpositive-blue, Python).
std::string to_string(NonPositiveBluePolicy policy);
/// The inverse of to_string. \throws std::invalid_argument (quoting the text) for any other.
NonPositiveBluePolicy nonpositive_blue_policy_from_string(const std::string& text);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> nonpositive_blue_policy_names();

/// Thrown by perspective_chromaticities under NonPositiveBluePolicy::reject: input the function
/// cannot use (docs/conventions.md §9), so a std::invalid_argument.
struct NonPositiveBlue : std::invalid_argument {
  std::size_t index;  ///< position of the offending colour in the input (0-based)
  /// what(): "colour <index> has b <= 0: it has no perspective chromaticity (r/b, g/b)".
  explicit NonPositiveBlue(std::size_t i)
      : std::invalid_argument("colour " + std::to_string(i) +
                              " has b <= 0: it has no perspective chromaticity (r/b, g/b)"),
        index(i) {}
};

/// The chromaticities of the colours that have one, in input order, and how many were dropped.
struct Chromaticities {
  std::vector<Point2> points;  ///< q = (r/b, g/b) of each colour with b > 0, exact, in input order
  std::vector<std::size_t> source_index;  ///< for each point, the index of its colour
  std::size_t dropped = 0;                ///< colours with b <= 0 skipped under `drop`
};

/// q = (r/b, g/b) for every colour with b > 0, exactly (eq. 10 of the seed paper).
/// \throws NonPositiveBlue under NonPositiveBluePolicy::reject. O(n).
Chromaticities perspective_chromaticities(const std::vector<Colour>& colours,
                                          NonPositiveBluePolicy policy);

/// q = (r/b, g/b) of one colour. Precondition: c.b > 0.
Point2 perspective_chromaticity(const Colour& c);

}  // namespace gmcc
