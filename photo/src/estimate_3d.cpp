#include <gmcc/photo/estimate_3d.h>

#include <gmcc/geometry/feasible_ray_3d.h>
#include <gmcc/geometry/illumination_cone_3d.h>

#include <climits>
#include <cmath>
#include <stdexcept>

namespace gmcc {

std::optional<std::array<double, 3>> light_of_map_3(const Point3& d, const Colour& c) {
  if (sgn(d.x) == 0 || sgn(d.y) == 0 || sgn(d.z) == 0) return std::nullopt;
  // e = c ⊘ d in ℚ, scaled by 2^-s so that the largest component lies in [2^-2, 2^2] (s from
  // the bit lengths: x ∈ [2^(nb - db - 1), 2^(nb - db + 1)) for nb, db those of its numerator and
  // denominator), then to doubles and unit length (a reported direction, not a decision).
  Rational e[3] = {Rational(c.r / d.x), Rational(c.g / d.y), Rational(c.b / d.z)};
  long s = LONG_MIN;
  for (const Rational& x : e)
    s = std::max(s, static_cast<long>(mpz_sizeinbase(x.get_num_mpz_t(), 2)) -
                        static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2)));
  double v[3];
  for (int k = 0; k < 3; ++k) {
    if (s > 0) mpq_div_2exp(e[k].get_mpq_t(), e[k].get_mpq_t(), static_cast<mp_bitcnt_t>(s));
    else mpq_mul_2exp(e[k].get_mpq_t(), e[k].get_mpq_t(), static_cast<mp_bitcnt_t>(-s));
    v[k] = to_double_nearest(e[k]);
  }
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return std::array<double, 3>{v[0] / n, v[1] / n, v[2] / n};
}

std::optional<std::array<double, 3>> light_of_perspective_map(const std::array<double, 2>& m, const Colour& c) {
  if (!(m[0] > 0 && m[1] > 0)) return std::nullopt;
  return light_of_map_3(Point3{Rational(m[0]), Rational(m[1]), Rational(1)}, c);
}

double recovery_angular_error_deg(const std::array<double, 3>& estimate, const Colour& truth) {
  return diagonal_map_angular_error_deg({estimate[0], estimate[1], estimate[2]},
                                        {truth.r, truth.g, truth.b});
}

ImageEstimate3 estimate_3d(const CanonicalConstraints3& canonical, const ImageColours& image,
                           const Estimate3Options& o) {
  if (!pixel_colours(image.set))
    throw std::invalid_argument(
        "the image's colours are chromaticity lifts (x, y, 1) of the 2-D hull colour set, not "
        "pixel colours: 3-D gamut mapping needs ColourSet distinct or hull_3d");
  if (image.colours.empty()) throw std::invalid_argument("the image has no colour");
  return estimate_3d(std::vector<GamutConstraint3>{{&canonical, &image.colours, image.set == ColourSet::hull_3d}}, o);
}

ImageEstimate3 estimate_3d(const std::vector<GamutConstraint3>& constraints, const Estimate3Options& o) {
  const Colour& c = o.canonical_light;
  if (sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument("the canonical light needs every channel > 0");
  if (o.truth && (sgn(o.truth->r) <= 0 || sgn(o.truth->g) <= 0 || sgn(o.truth->b) <= 0))
    throw std::invalid_argument("the true light needs every channel > 0");

  ImageEstimate3 out;
  // The true map c ⊘ e (its ray: F3 knows the light only up to intensity).
  std::optional<Point3> true_map;
  if (o.truth) true_map = Point3{Rational(c.r / o.truth->r), Rational(c.g / o.truth->g), Rational(c.b / o.truth->b)};
  auto light_of = [&](Selection3 s) {
    ImageSelection3 i{std::move(s), std::nullopt};
    const Point3 m = measured_map(i.selection.estimate);
    i.light = light_of_map_3(m, c);
    if (true_map) {
      if (sgn(m.x) != 0 || sgn(m.y) != 0 || sgn(m.z) != 0)
        i.map_error_deg = diagonal_map_angular_error_deg(m, *true_map);
      if (i.light) i.recovery_error_deg = recovery_angular_error_deg(*i.light, *o.truth);
    }
    return i;
  };
  // With plausible lights, their maps' cone as one more gamut type, truncated beyond F3's box.
  std::vector<GamutConstraint3> all = constraints;
  std::optional<CanonicalConstraints3> cone;
  if (!o.illuminants.empty()) {
    cone.emplace(illumination_cone_3d(o.illuminants, c, feasible_set_3d_box(constraints)));
    all.push_back({&*cone, &illumination_cone_colour(), false});
  }
  out.lazy_feasible = feasible_set_3d_lazy(all);
  if (true_map) out.truth_in_feasible = feasible_set_3d_meets_ray(all, *true_map);
  const LazyConvexSet3& F = out.lazy_feasible;
  if (F.kind() != ConvexKind3::empty)
    for (Rule3 r : o.rules)
      if (!out[r]) out[r] = light_of(with_worst_case(F, select_rule_3(r, F, o.route)));
  if (o.exact_feasible_set) out.feasible = F.exact();
  return out;
}

}  // namespace gmcc
