#pragma once
/// \file gcie.h
/// Gamut-constrained illuminant estimation (Finlayson, Hordley & Tastl 2006): illuminant
/// estimation recast as classification among plausible lights. Each plausible light is
/// represented by the canonical gamut mapped to it, and the image is given the light whose gamut
/// is most consistent with its colours, consistency measured by non-negative least squares
/// (docs/math.md §1f, which says which variant this is and why).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/cone_distance.h>
#include <gmcc/geometry/point.h>

#include <cstddef>
#include <vector>

namespace gmcc {

/// What gcie_select decided.
struct GcieSelection {
  std::size_t light = 0;     ///< index of the selected plausible light
  Rational score;            ///< its score (gcie_score), the least: 0 when some light is consistent
  std::size_t tied = 0;      ///< lights sharing the least score (1 when it is unique)
  std::size_t consistent = 0;  ///< lights consistent with every image colour (score 0)
};

/// The plausible lights' gamut cones, built once (per fold of a benchmark) for many images.
class GcieGamuts {
 public:
  /// Arguments as gcie_select's. \throws as gcie_select. O(L·m) exact operations.
  GcieGamuts(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
             std::vector<Colour> lights);
  /// gcie_select for these lights. \throws std::invalid_argument for a negative channel.
  GcieSelection select(const std::vector<Colour>& image_colours) const;
  /// gcie_score of light i (< lights().size()).
  Rational score(std::size_t i, const std::vector<Colour>& image_colours) const;
  /// The plausible lights, in the order given (GcieSelection::light indexes them).
  const std::vector<Colour>& lights() const { return lights_; }

 private:
  std::vector<Colour> lights_;
  std::vector<PolygonalCone> cones_;
  std::vector<mpz_class> chromaticities_;  // the lights' r, g chromaticities over one denominator
};

/// The score of plausible light l: Σ_j dist²(p_j, cone_l) over the image colours p_j, each
/// distance the value of a non-negative least-squares problem (cone_distance.h), exactly; cone_l
/// as in gcie_select. 0 exactly when every colour is consistent with l. \throws as gcie_select.
/// O(m + n·m) exact operations for m chromaticities and n colours.
Rational gcie_score(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
                    const Colour& light, const std::vector<Colour>& image_colours);

/// The plausible light whose gamut is most consistent with the image colours, exactly
/// (docs/math.md §1f). Light l's gamut is the canonical gamut under l: with intensity unknown,
/// the cone {Σ λ_k ((l ⊘ c) ⊙ (x_k, y_k, 1)) : λ_k >= 0} over the canonical perspective
/// chromaticities (x_k, y_k) (Finlayson 1996 §2) — every colour the canonical surfaces give
/// under l at any intensity. The score of l is Σ_j dist²(p_j, cone_l) over the image colours p_j,
/// each distance the value of a non-negative least-squares problem (cone_distance.h); 0 exactly
/// when every image colour is consistent with l, i.e. when l's map lies in the feasible set.
/// The least score wins. Lights consistent with every colour are found first, by exact (filtered)
/// cone membership, and their score 0 needs no distance; only when none is consistent are the
/// scores computed. Of lights tied on the least score (typically several with 0, the plausible
/// lights whose maps lie in the feasible set), the one whose chromaticity r/(r+g+b), g/(r+g+b) is nearest the mean of theirs, then
/// the first.
/// \param canonical_chromaticities the canonical gamut's perspective hull, counter-clockwise
///        (CanonicalLearner2::gamut(); one vertex or two are a ray or a wedge).
/// \param canonical_light c, every channel > 0. \param lights at least one, every channel > 0.
/// \param image_colours the image's colours (its 3-D hull's vertices suffice for the cone test,
///        and are what the benchmark passes), every channel >= 0.
/// \throws std::invalid_argument for no light, no canonical chromaticity, or a channel out of
///         range. Complexity O(L·(m + n·m)) exact operations for L lights, m chromaticities and
///         n colours.
GcieSelection gcie_select(const std::vector<Point2>& canonical_chromaticities, const Colour& canonical_light,
                          const std::vector<Colour>& lights, const std::vector<Colour>& image_colours);

}  // namespace gmcc
