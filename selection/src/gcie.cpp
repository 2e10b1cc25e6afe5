// Gamut-constrained illuminant estimation (gcie.h; Finlayson, Hordley & Tastl 2006;
// docs/math.md §1f).
#include <gmcc/selection/gcie.h>

#include <gmcc/geometry/cone_distance.h>
#include <gmcc/geometry/integers_over_lcm.h>

#include <algorithm>
#include <stdexcept>

namespace gmcc {
namespace {

void check_positive(const Colour& c, const char* what) {
  if (sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument(std::string(what) + " needs every channel > 0");
}

// Light l's gamut cone: the canonical chromaticities' lifts under l ⊘ c, each generator scaled to
// a primitive integer vector (the cone depends on directions only; integers keep the exact
// arithmetic short).
PolygonalCone light_cone(const std::vector<Point2>& xy, const Colour& c, const Colour& l) {
  const Rational fr = l.r / c.r, fg = l.g / c.g, fb = l.b / c.b;
  std::vector<Point3> g;
  for (const Point2& p : xy) {
    const std::array<Rational, 3> v{Rational(fr * p.x), Rational(fg * p.y), fb};
    std::vector<mpz_class> z = integers_over_lcm(v);
    divide_by_content(z);
    g.push_back({Rational(z[0]), Rational(z[1]), Rational(z[2])});
  }
  return PolygonalCone(std::move(g));
}

// The lights' chromaticities (r, g)/(r + g + b) as integers over one common denominator
// (integers_over_lcm.h): x_0, y_0, x_1, y_1, … — the tie rule's sums need no gcd then.
std::vector<mpz_class> chromaticities_over_lcm(const std::vector<Colour>& lights) {
  std::vector<Rational> q;
  for (const Colour& l : lights) {
    const Rational s = l.r + l.g + l.b;
    q.push_back(l.r / s);
    q.push_back(l.g / s);
  }
  return integers_over_lcm(q);
}

// Of the tied lights, the one whose chromaticity is nearest their mean chromaticity (then the
// first): with T tied and sums S, the least |T·q_i − S|², in integers.
std::size_t nearest_to_mean(const std::vector<mpz_class>& xy, const std::vector<std::size_t>& tied) {
  mpz_class sx = 0, sy = 0;
  for (std::size_t i : tied) {
    sx += xy[2 * i];
    sy += xy[2 * i + 1];
  }
  const mpz_class t = static_cast<unsigned long>(tied.size());
  std::size_t best = tied.front();
  mpz_class best_d2;
  for (std::size_t k = 0; k < tied.size(); ++k) {
    const mpz_class dx = t * xy[2 * tied[k]] - sx, dy = t * xy[2 * tied[k] + 1] - sy;
    const mpz_class d2 = dx * dx + dy * dy;
    if (k == 0 || d2 < best_d2) {
      best = tied[k];
      best_d2 = d2;
    }
  }
  return best;
}

}  // namespace

namespace {

void check_gamuts(const std::vector<Point2>& xy, const Colour& c, const std::vector<Colour>& lights) {
  if (lights.empty()) throw std::invalid_argument("gamut-constrained illuminant estimation needs a plausible light");
  if (xy.empty()) throw std::invalid_argument("the canonical gamut has no chromaticity");
  check_positive(c, "the canonical light");
  for (const Colour& l : lights) check_positive(l, "a plausible light");
}

// The image colours as points. \throws std::invalid_argument for a negative channel.
std::vector<Point3> points_of(const std::vector<Colour>& colours) {
  std::vector<Point3> out;
  for (const Colour& p : colours) {
    if (sgn(p.r) < 0 || sgn(p.g) < 0 || sgn(p.b) < 0) throw std::invalid_argument("an image colour is negative");
    out.push_back({p.r, p.g, p.b});
  }
  return out;
}

Rational score_of(const PolygonalCone& cone, const std::vector<Point3>& colours) {
  Rational score(0);
  for (const Point3& p : colours) score += project_onto_cone(p, cone).squared_distance;
  return score;
}

}  // namespace

GcieGamuts::GcieGamuts(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
                       std::vector<Colour> lights)
    : lights_(std::move(lights)) {
  check_gamuts(canonical_chromaticities, canonical_light, lights_);
  for (const Colour& l : lights_) cones_.push_back(light_cone(canonical_chromaticities, canonical_light, l));
  chromaticities_ = chromaticities_over_lcm(lights_);
}

Rational GcieGamuts::score(std::size_t i, const std::vector<Colour>& image_colours) const {
  return score_of(cones_.at(i), points_of(image_colours));
}

GcieSelection GcieGamuts::select(const std::vector<Colour>& image_colours) const {
  const std::vector<Point3> colours = points_of(image_colours);
  std::vector<std::array<double, 3>> nearest;
  for (const Point3& p : colours) nearest.push_back({to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)});
  std::vector<std::size_t> tied;
  for (std::size_t i = 0; i < cones_.size(); ++i) {
    bool consistent = true;
    for (std::size_t j = 0; j < colours.size() && consistent; ++j) consistent = cones_[i].contains(colours[j], nearest[j]);
    if (consistent) tied.push_back(i);
  }
  GcieSelection s;
  s.consistent = tied.size();
  s.score = 0;
  if (tied.empty()) {  // no light consistent: the least score of all
    for (std::size_t i = 0; i < cones_.size(); ++i) {
      Rational score = score_of(cones_[i], colours);
      if (tied.empty() || score < s.score) {
        tied = {i};
        s.score = std::move(score);
      } else if (score == s.score) {
        tied.push_back(i);
      }
    }
  }
  s.tied = tied.size();
  s.light = nearest_to_mean(chromaticities_, tied);
  return s;
}

Rational gcie_score(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
                    const Colour& light, const std::vector<Colour>& image_colours) {
  return GcieGamuts(canonical_chromaticities, canonical_light, {light}).score(0, image_colours);
}

GcieSelection gcie_select(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
                          const std::vector<Colour>& lights, const std::vector<Colour>& image_colours) {
  return GcieGamuts(canonical_chromaticities, canonical_light, lights).select(image_colours);
}

}  // namespace gmcc
