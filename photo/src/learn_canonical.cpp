#include <gmcc/photo/learn_canonical.h>

#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_hull.h>

#include <algorithm>
#include <stdexcept>

namespace gmcc {
namespace {

void check_light(const Colour& e) {
  if (sgn(e.r) <= 0 || sgn(e.g) <= 0 || sgn(e.b) <= 0)
    throw std::invalid_argument("a training light needs every channel > 0");
}

// Re-hull once the new candidates outnumber the last hull's vertices (and at least this many):
// the work stays linear in what is added, the memory in the gamut's size.
constexpr std::size_t compact_from = 4096;

}  // namespace

std::string to_string(CanonicalIntensity intensity) {
  return intensity == CanonicalIntensity::max ? "max" : "none";
}

CanonicalIntensity canonical_intensity_from_string(const std::string& text) {
  if (text == "max") return CanonicalIntensity::max;
  if (text == "none") return CanonicalIntensity::none;
  throw std::invalid_argument("\"" + text + "\" is not one of max, none");
}

std::vector<std::string> canonical_intensity_names() {
  return {to_string(CanonicalIntensity::max), to_string(CanonicalIntensity::none)};
}

Rational white_balanced_maximum(const std::vector<Colour>& colours, const Colour& light) {
  Rational top = 0;
  if (sgn(light.r) > 0 && sgn(light.g) > 0 && sgn(light.b) > 0) {
    // Each channel's largest value over the light's (e_k > 0: max over c of c_k/e_k is
    // (max over c of c_k)/e_k): comparisons a colour, three divisions in all.
    if (colours.empty()) return top;
    Colour m = colours.front();
    for (const Colour& c : colours) {
      if (c.r > m.r) m.r = c.r;
      if (c.g > m.g) m.g = c.g;
      if (c.b > m.b) m.b = c.b;
    }
    return std::max({top, Rational(m.r / light.r), Rational(m.g / light.g), Rational(m.b / light.b)});
  }
  for (const Colour& c : colours)
    top = std::max({top, Rational(c.r / light.r), Rational(c.g / light.g), Rational(c.b / light.b)});
  return top;
}

CanonicalLearner3::CanonicalLearner3(CanonicalIntensity intensity) : intensity_(intensity) {}

void CanonicalLearner3::add(const std::vector<Colour>& colours, const Colour& light) {
  add_scaled(colours, light, nullptr, false);
}

void CanonicalLearner3::add(const std::vector<Colour>& colours, const Colour& light, const Rational& scale) {
  if (sgn(scale) <= 0) throw std::invalid_argument("an intensity scale must be > 0");
  add_scaled(colours, light, &scale, false);
}

void CanonicalLearner3::add_hull_vertices(const std::vector<Colour>& vertices, const Colour& light) {
  add_scaled(vertices, light, nullptr, true);
}

void CanonicalLearner3::add_hull_vertices(const std::vector<Colour>& vertices, const Colour& light,
                                          const Rational& scale) {
  if (sgn(scale) <= 0) throw std::invalid_argument("an intensity scale must be > 0");
  add_scaled(vertices, light, &scale, true);
}

void CanonicalLearner3::add_scaled(const std::vector<Colour>& colours, const Colour& light, const Rational* scale,
                                   bool vertices) {
  check_light(light);
  ++images_;
  if (colours.empty()) return;
  // Only the image's hull vertices can be vertices of the union; the diagonal map and the
  // scaling keep them vertices (and keep every other point a non-vertex: given vertices, or a
  // superset of them, the union's hull is the same).
  std::vector<Colour> v;
  if (vertices) {
    for (const Colour& c : colours)
      if (sgn(c.r) < 0 || sgn(c.g) < 0 || sgn(c.b) < 0)
        throw std::invalid_argument("colour_hull_vertices: a negative channel");
    v = colours;
  } else {
    v = colour_hull_vertices(colours);
  }
  // Only black (every channel 0, the light's > 0: white_balanced_maximum 0): nothing a hull with
  // black lacks. The factor itself only where it divides.
  const bool own = !scale && intensity_ == CanonicalIntensity::max;
  const Rational top = own ? white_balanced_maximum(v, light) : Rational(0);
  if (own ? sgn(top) == 0 : std::all_of(v.begin(), v.end(), [](const Colour& c) {
        return sgn(c.r) == 0 && sgn(c.g) == 0 && sgn(c.b) == 0;
      }))
    return;
  // c ⊘ e, then divided by the factor: c ⊘ (e·factor) exactly, one division a channel.
  const Rational* divide = scale ? scale : own ? &top : nullptr;
  const Colour by = divide ? Colour{light.r * *divide, light.g * *divide, light.b * *divide} : light;
  for (Colour& c : v) c = {c.r / by.r, c.g / by.g, c.b / by.b};
  ++contributing_;
  points_.insert(points_.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  if (points_.size() - hulled_ > std::max(hulled_, compact_from)) compact();
}

void CanonicalLearner3::compact() const {
  if (hulled_ == points_.size()) return;
  points_ = colour_hull_vertices(points_);
  hulled_ = points_.size();
}

std::vector<Colour> CanonicalLearner3::gamut() const {
  if (points_.empty()) return {};
  compact();
  return points_;
}

void CanonicalLearner2::add(const std::vector<Colour>& colours, const Colour& light) {
  check_light(light);
  ++images_;
  // Under the white light (r/e_r)/(b/e_b) = x·e_b/e_r, with x = r/b.
  const Rational fx = light.b / light.r, fy = light.b / light.g;
  for (const Colour& c : colours) {
    if (sgn(c.b) <= 0) continue;
    points_.push_back({c.r / c.b * fx, c.g / c.b * fy});
  }
  if (points_.size() - hulled_ > std::max(hulled_, compact_from)) compact();
}

void CanonicalLearner2::compact() const {
  if (hulled_ == points_.size()) return;
  points_ = convex_hull(points_).vertices;
  hulled_ = points_.size();
}

std::vector<Point2> CanonicalLearner2::gamut() const {
  if (points_.empty()) return {};
  compact();
  return points_;
}

}  // namespace gmcc
