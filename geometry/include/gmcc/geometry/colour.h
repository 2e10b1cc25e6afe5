#pragma once
/// \file colour.h
/// A colour: a linear sensor response (r, g, b), exact, finite and >= 0 (docs/conventions.md §1).

#include <gmcc/geometry/rational.h>

namespace gmcc {

/// A linear three-channel sensor response, held exactly.
struct Colour {
  Rational r;  ///< red (long-wave) channel, >= 0, in the sensor's linear units
  Rational g;  ///< green (middle-wave) channel, >= 0
  Rational b;  ///< blue (short-wave) channel, >= 0; the perspective chromaticity divides by it
};

/// Exact equality, channel by channel (rationals in lowest terms: no tolerance).
inline bool operator==(const Colour& a, const Colour& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

}  // namespace gmcc
