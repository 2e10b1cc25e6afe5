#pragma once
/// \file learn_canonical.h
/// A canonical gamut learned from photographs with known lights (Forsyth 1990 §3; Barnard,
/// Cardei & Funt 2002 Part I; Gijsenij, Gevers & van de Weijer 2010 §3): each training image's
/// pixel colours p are divided by its light e, p ⊘ e, so that they are the colours of its
/// surfaces under a white canonical light (the diagonal model, docs/conventions.md §2); the
/// canonical gamut is the convex hull of the union over the images
/// (docs/photographs.md §2 "Learning a canonical gamut").
///
/// In 3-D the intensity of a photograph is arbitrary (exposure, aperture, distance), so each
/// image is scaled before the union (CanonicalIntensity); the 3-D rules are scale-equivariant at
/// test time, so only the training side needs it. The 2-D perspective route needs none:
/// chromaticities are intensity-free.
///
/// Only the vertices of each image's hull can be vertices of the union's hull, and a diagonal
/// map keeps vertices vertices, so the learner keeps the running hull's vertices only: memory
/// stays bounded by the gamut's size, not by the number of images.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>

#include <cstddef>
#include <string>
#include <vector>

namespace gmcc {

/// How a training image's white-balanced colours are scaled before they join a 3-D canonical
/// gamut.
enum class CanonicalIntensity {
  max,   ///< the image's largest white-balanced channel becomes 1: its brightest surface, seen
         ///< under the white light, sets the scale (the default)
  none,  ///< p ⊘ e as it is (the images' exposures are comparable, e.g. rendered scenes)
};

/// `max` or `none`.
std::string to_string(CanonicalIntensity intensity);
/// The inverse of to_string. \throws std::invalid_argument naming the accepted values.
CanonicalIntensity canonical_intensity_from_string(const std::string& text);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> canonical_intensity_names();

/// The largest channel of the white-balanced colours p ⊘ e: the factor CanonicalIntensity::max
/// divides an image's colours by (0 for no colour or only black). Edge colours of the same image
/// are divided by the same factor, so that every gamut type shares one intensity scale
/// (docs/photographs.md §5). \pre every channel of `light` > 0. O(n).
Rational white_balanced_maximum(const std::vector<Colour>& colours, const Colour& light);

/// Learns a 3-D canonical gamut image by image (Forsyth's G_c3 from photographs).
class CanonicalLearner3 {
 public:
  /// Starts an empty gamut; images join it with the given intensity scaling.
  explicit CanonicalLearner3(CanonicalIntensity intensity = CanonicalIntensity::max);
  /// Adds one image: its pixel colours (any superset of their hull's vertices; channels >= 0,
  /// not chromaticity lifts) and its light (every channel > 0, any scale).
  /// \throws std::invalid_argument if the light has a channel <= 0 or a colour a negative
  ///         channel. An image with no colour, or only black, adds nothing. O(n) filtered tests
  ///         and the exact hull of the survivors (colour_hull_3.h).
  void add(const std::vector<Colour>& colours, const Colour& light);
  /// Adds one image's colours of another gamut type (edge colours, edge_colours.h) divided by its
  /// light and then by `scale` instead of the learner's own intensity rule: the factor of the
  /// image's pixel colours (white_balanced_maximum), so that every gamut type shares one
  /// intensity scale (docs/photographs.md §5). \throws std::invalid_argument as add above, or if
  /// `scale` <= 0. Complexity as add.
  void add(const std::vector<Colour>& colours, const Colour& light, const Rational& scale);
  /// add above, for colours that are their hull's vertices already (ColourSet::hull_3d, or
  /// edge_colours with it): the same gamut, without hulling them again (any superset of the hull's
  /// vertices still gives the same gamut; only the work differs). O(n) exact divisions.
  /// \throws std::invalid_argument as add above.
  void add_hull_vertices(const std::vector<Colour>& vertices, const Colour& light);
  /// add above with `scale`, for colours that are their hull's vertices already (as
  /// add_hull_vertices). \throws std::invalid_argument as add above, or if `scale` <= 0.
  void add_hull_vertices(const std::vector<Colour>& vertices, const Colour& light, const Rational& scale);
  /// The vertices of the hull of every added image's scaled colours, sorted; empty before any
  /// colour. The canonical light is white (1, 1, 1).
  std::vector<Colour> gamut() const;
  /// Images added, and of them those that added colours.
  ///@{
  std::size_t images() const { return images_; }
  std::size_t contributing() const { return contributing_; }
  ///@}

 private:
  // add, dividing by *scale when given, else by the intensity rule's factor; the colours hulled
  // first unless `vertices` says they are their hull's vertices already.
  void add_scaled(const std::vector<Colour>& colours, const Colour& light, const Rational* scale, bool vertices);
  void compact() const;
  CanonicalIntensity intensity_;
  mutable std::vector<Colour> points_;  // vertices of the hull so far, then new candidates
  mutable std::size_t hulled_ = 0;      // points_[0, hulled_) are the last hull's vertices
  std::size_t images_ = 0, contributing_ = 0;
};

/// Learns a 2-D (perspective) canonical gamut image by image (Finlayson 1996): the hull of the
/// chromaticities (r/b, g/b) of each image's colours under the white light. Colours may be pixel
/// colours or chromaticity lifts (x, y, 1): for both, p ⊘ e has chromaticity
/// (x·e_b/e_r, y·e_b/e_g).
class CanonicalLearner2 {
 public:
  /// Adds one image: its colours (those with b = 0 have no chromaticity and are skipped) and
  /// its light (every channel > 0). \throws std::invalid_argument on a light channel <= 0.
  void add(const std::vector<Colour>& colours, const Colour& light);
  /// The vertices of the hull of every added chromaticity, counter-clockwise (convex_hull.h);
  /// empty before any.
  std::vector<Point2> gamut() const;
  /// Images added.
  std::size_t images() const { return images_; }

 private:
  void compact() const;
  mutable std::vector<Point2> points_;
  mutable std::size_t hulled_ = 0;
  std::size_t images_ = 0;
};

}  // namespace gmcc
