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
  const Rational top = white_balanced_maximum(v, light);
  if (sgn(top) == 0) return;  // only black: nothing a hull with black lacks
  for (Colour& c : v) c = {c.r / light.r, c.g / light.g, c.b / light.b};
  const Rational* divide = scale ? scale : intensity_ == CanonicalIntensity::max ? &top : nullptr;
  if (divide)
    for (Colour& c : v) c = {c.r / *divide, c.g / *divide, c.b / *divide};
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
