#pragma once
/// \file estimate_3d.h
/// 3-D gamut mapping on a photograph (Forsyth 1990's CRULE on pixel colours; Gijsenij, Gevers &
/// van de Weijer 2010 §3): the exact feasible set F3 of diagonal maps from the image's pixel
/// colours into a prepared canonical gamut, and the three 3-D rules on it, each with the light
/// it implies (docs/photographs.md §3 "3-D gamut mapping on images").
///
/// The rules: max-volume (CRULE-MV, argmax d1·d2·d3, max_volume.h), the centroid (CRULE-AVE,
/// centroid_3.h) and max-trace (argmax d1 + d2 + d3, max_trace.h: the selection of Gijsenij et
/// al.'s pixel, edge and intersection gamut mapping). A map d takes the image to the canonical
/// light c, so the light it implies is e = c ⊘ d (docs/conventions.md §2).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/rule_3.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// One 3-D rule's answer on an image: the map, its worst case in F3, and the light it implies.
struct ImageSelection3 {
  Selection3 selection;  ///< the map d and its map-space worst case (crule_3d.h)
  /// e = c ⊘ d with unit length, from the map as measured (measured_map); absent when d has a
  /// zero component (F3 = {0} or a face of it on a coordinate plane: no light)
  std::optional<std::array<double, 3>> light;
  /// With a true light e (Estimate3Options::truth), the errors of this answer, each in its own
  /// space (docs/photographs.md §8):
  /// - `map_error_deg`: the angle between the map d and the true map c ⊘ e, the space of
  ///   Selection3::worst_case_deg, which bounds it whenever the truth is in F3
  ///   (ImageEstimate3::truth_in_feasible); absent when d = 0;
  /// - `recovery_error_deg`: the angle between `light` and e (Hordley & Finlayson 2006), what
  ///   benchmarks report; absent without a light.
  ///@{
  std::optional<double> map_error_deg, recovery_error_deg;
  ///@}
};

/// F3 of one image and the rules asked for. Absent rules were not asked for, or F3 is empty.
struct ImageEstimate3 {
  /// F3, exactly: filled when Estimate3Options::exact_feasible_set asks (the default); otherwise
  /// empty, and F3 is in `lazy_feasible`
  ConvexSet3 feasible;
  /// F3 with its vertices made exact only on request (lazy_convex_set_3.h), always filled: its
  /// kind and vertex count, and exact() for the whole set (equal to `feasible` when that is filled)
  LazyConvexSet3 lazy_feasible;
  /// the rules' answers, by rule (rule_3.h)
  PerRule3<std::optional<ImageSelection3>> selections;
  /// With a true light e (Estimate3Options::truth): whether some positive multiple of the true
  /// map c ⊘ e lies in F3, decided exactly on F3's rows (feasible_ray_3d.h), whatever F3's kind
  /// and whether or not F3 holds maps with a zero component; absent without a truth.
  std::optional<bool> truth_in_feasible;
  /// The answer of `rule` (an absent one when not asked for or F3 is empty).
  ///@{
  const std::optional<ImageSelection3>& operator[](Rule3 rule) const { return selections[rule]; }
  std::optional<ImageSelection3>& operator[](Rule3 rule) { return selections[rule]; }
  ///@}
};

/// What estimate_3d computes.
struct Estimate3Options {
  std::vector<Rule3> rules{all_rules_3.begin(), all_rules_3.end()};  ///< the rules to apply
  /// `certified`: the centroid as a certified double (what a benchmark needs); `exact`: in ℚ.
  /// F3, max-volume and max-trace are exact on either route.
  Crule3dRoute route = Crule3dRoute::certified;
  Colour canonical_light{Rational(1), Rational(1), Rational(1)};  ///< c, every channel > 0
  /// Whether ImageEstimate3::feasible is filled with F3 in lowest terms (every vertex's gcds:
  /// about a third of F3's cost on a photograph). The rules' answers are the same either way; a
  /// caller that prints only doubles (the CLI, Python) leaves it false and reads lazy_feasible.
  bool exact_feasible_set = true;
  /// The true light e, every channel > 0, when known: then ImageEstimate3::truth_in_feasible and
  /// each rule's map-space and recovery errors are filled.
  std::optional<Colour> truth;
  /// Plausible lights (camera RGB, every channel > 0): when given, F3 is intersected with the
  /// cone of their maps c ⊘ l (the illumination constraint in 3-D, Barnard's ECRULE;
  /// illumination_cone_3d.h) and every rule, worst case and truth test reads F3 ∩ cone; empty:
  /// no constraint.
  std::vector<Colour> illuminants;
};

/// Gamut mapping in 3-D on one image's colours.
/// \param canonical the canonical gamut, prepared once (feasible_set_3d.h).
/// \param image the image's pixel colours (image_pixels.h, ColourSet distinct or hull_3d).
/// \param options the rules, the centroid's route and the canonical light.
/// \throws std::invalid_argument if `image` holds chromaticity lifts (ColourSet::hull: they are
///         not pixel colours, and F3 from them would be meaningless), has no colour, or the
///         canonical light, the truth or a plausible light has a channel <= 0;
///         UnboundedFeasibleSet (feasible_set.h) when every colour has some channel 0.
ImageEstimate3 estimate_3d(const CanonicalConstraints3& canonical, const ImageColours& image,
                           const Estimate3Options& options = {});

/// Gamut mapping in 3-D with several gamut types at once: F3 the maps taking every type's image
/// colours into its own canonical gamut (feasible_set_3d.h, GamutConstraint3), and the rules on
/// it — Gijsenij, Gevers & van de Weijer (2010) §4.3's intersection of the pixel and edge
/// feasible sets ("1-jet": pixels and 1st-order edges; "2-jet": with 2nd-order edges too), where
/// max-trace is their selection. Every type's canonical gamut must share one intensity scale
/// (docs/photographs.md §5). One constraint is estimate_3d above on its colours.
/// \throws std::invalid_argument if `constraints` is empty or the canonical light, the truth or
///         a plausible light has a channel <= 0, and as feasible_set_3d.
ImageEstimate3 estimate_3d(const std::vector<GamutConstraint3>& constraints, const Estimate3Options& options = {});

/// The light a 3-D map implies, e = c ⊘ d, with unit length (docs/conventions.md §2); absent
/// when a component of d is 0. e is formed exactly and scaled by a power of two (exact) so that
/// its largest component is near 1 before it is rounded and normalised: the same light for d and
/// 2^k·d at any representable scale, never an overflow, an underflow of the largest component or
/// a NaN. O(1).
std::optional<std::array<double, 3>> light_of_map_3(const Point3& d, const Colour& canonical_light);

/// The light a perspective map m implies (the 2-D route: d = (m1, m2, 1), e = c ⊘ d), unit
/// length, by light_of_map_3 on the lift taken exactly; absent unless m1, m2 > 0. O(1).
std::optional<std::array<double, 3>> light_of_perspective_map(const std::array<double, 2>& m,
                                                              const Colour& canonical_light);

/// The recovery angular error (degrees) between a light estimate and the true light: the angle
/// between them as 3-vectors (Hordley & Finlayson 2006), computed as every angle in gmcc
/// (angular_error.h) from the exact truth and the estimate taken exactly. \throws
/// std::invalid_argument if either is 0.
double recovery_angular_error_deg(const std::array<double, 3>& estimate, const Colour& truth);

}  // namespace gmcc
