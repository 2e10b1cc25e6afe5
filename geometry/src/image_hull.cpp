#include "internal/image_hull.h"
#include <gmcc/numerics/filter_bounds.h>

#include "internal/extended_value.h"
#include "internal/integer_line.h"
#include "internal/monotone_chain.h"

#include <algorithm>
#include <cmath>

namespace gmcc::internal {
namespace {

// The sign of orientation(a, b, c) = (b−a)×(c−a) of exact points, filtered: from coordinates
// truncated to double (relative error below 2u each) each difference is within 3.01u of
// |b_x| + |a_x| (and so on), each product within 6.1u of (|b_x|+|a_x|)(|c_y|+|a_y|), and the last
// product and difference round by u each: 12u of the computed magnitudes covers it.
int orientation_sign(const Point2& a, const Point2& b, const Point2& c, const std::array<double, 2>& fa,
                     const std::array<double, 2>& fb, const std::array<double, 2>& fc, bool filtered) {
  if (filtered) {
    const double l = (fb[0] - fa[0]) * (fc[1] - fa[1]), r = (fb[1] - fa[1]) * (fc[0] - fa[0]);
    const double mag = (std::fabs(fb[0]) + std::fabs(fa[0])) * (std::fabs(fc[1]) + std::fabs(fa[1])) +
                       (std::fabs(fb[1]) + std::fabs(fa[1])) * (std::fabs(fc[0]) + std::fabs(fa[0]));
    const numerics::UncertainSign s = numerics::sign_within(l - r, numerics::filter_bound::image_hull_orientation * mag);
    if (s.is_certain()) return s.lo;
  }
  return sgn(orientation(a, b, c));
}

}  // namespace

ImagePoint image_point(const Point2& q) {
  ImagePoint p{&q, {0, 0}, {0, 0}, true, numerics::extended_precision_compiled};
  for (int k = 0; k < 2; ++k) {
    const Rational& c = k ? q.y : q.x;
    const auto l = numerics::extended_precision_compiled ? top_bits(c) : std::nullopt;
    p.extended = p.extended && l;
    p.l[k] = l.value_or(0);
    const std::optional<double> f = approx(c, l);
    p.filtered = p.filtered && f;
    p.f[k] = f.value_or(0);
  }
  return p;
}

std::vector<ImagePoint> image_hull_vertices(const std::vector<const Point2*>& image) {
  std::vector<ImagePoint> p;
  p.reserve(image.size());
  bool filtered = true;
  for (const Point2* q : image) {
    p.push_back(image_point(*q));
    filtered = filtered && p.back().filtered;
  }
  // x̂ within 2u|x| of x: x̂_a − x̂_b beyond 4.01u(|x̂_a| + |x̂_b|) (with the subtraction's own
  // rounding) has the sign of x_a − x_b.
  auto compare = [filtered](const ImagePoint& a, const ImagePoint& b, int k) {
    if (filtered) {
      const numerics::UncertainSign s =
          numerics::sign_within(a.f[k] - b.f[k], numerics::filter_bound::image_hull_order * (std::fabs(a.f[k]) + std::fabs(b.f[k])));
      if (s.is_certain()) return s.lo;
    }
    return cmp(k ? a.exact->y : a.exact->x, k ? b.exact->y : b.exact->x);
  };
  auto less = [&](const ImagePoint& a, const ImagePoint& b) {
    const int x = compare(a, b, 0);
    return x ? x < 0 : compare(a, b, 1) < 0;
  };
  auto equal = [&](const ImagePoint& a, const ImagePoint& b) { return compare(a, b, 0) == 0 && compare(a, b, 1) == 0; };
  std::sort(p.begin(), p.end(), less);
  p.erase(std::unique(p.begin(), p.end(), equal), p.end());
  const std::vector<std::size_t> h = monotone_chain(p.size(), [&](std::size_t a, std::size_t b, std::size_t c) {
    return orientation_sign(*p[a].exact, *p[b].exact, *p[c].exact, p[a].f, p[b].f, p[c].f, filtered) > 0;
  });
  std::vector<ImagePoint> out;
  out.reserve(h.size());
  for (std::size_t i : h) out.push_back(p[i]);
  return out;  // all collinear: the two extreme points
}

}  // namespace gmcc::internal
