#pragma once
/// \file point.h
/// Exact 2-D points: perspective chromaticities (r/b, g/b) and perspective diagonal maps
/// (d1/d3, d2/d3) are both pairs of rationals (Finlayson 1996, "Color in perspective").

#include <gmcc/geometry/rational.h>

#include <array>

namespace gmcc {

/// An exact point of the plane. Used for chromaticities and for perspective maps.
struct Point2 {
  Rational x;  ///< first coordinate: r/b of a chromaticity, or d1/d3 of a map
  Rational y;  ///< second coordinate: g/b of a chromaticity, or d2/d3 of a map
};

/// Exact equality of both coordinates.
inline bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
/// Not operator==.
inline bool operator!=(const Point2& a, const Point2& b) { return !(a == b); }
/// Lexicographic order (x, then y): used to give results a canonical starting vertex.
inline bool operator<(const Point2& a, const Point2& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// Twice the signed area of triangle (a, b, c): > 0 when a, b, c turn counter-clockwise.
inline Rational orientation(const Point2& a, const Point2& b, const Point2& c) {
  return Rational((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// The double nearest to each coordinate.
std::array<double, 2> to_double_nearest(const Point2& p);

}  // namespace gmcc
