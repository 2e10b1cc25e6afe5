#pragma once
/// \file gehler_shi_experiment.h
/// The real-camera test of Finlayson & Hordley (1999) §4 (their Fig. 5) on the measured chart
/// colours of the Gehler–Shi set (gehler_shi.h): an experiment setup for run_gamut_experiment in
/// which every image is a test light with its own true map, drawn from its own usable patches
/// (docs/reproduction.md "Real camera data (Gehler-Shi)").

#include <gmcc/geometry/rational.h>
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/gehler_shi.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace gmcc {

/// How the Gehler–Shi test is run: which canonical gamut each image is tested against
/// (`gmcc reproduce gehler-shi --protocol`; docs/reproduction.md "Real camera data (Gehler-Shi)").
enum class GehlerShiProtocol {
  /// Image i's canonical gamut: the hull of every other same-camera image's usable patches, each
  /// divided componentwise by its own ground truth (canonical light white (1, 1, 1)).
  leave_one_out,
  /// One canonical chart per camera (the daylight images nearest the camera's median daylight),
  /// test images grouped into yellowish (tungsten-like) and bluish daylight by their ground truth.
  paper,
};

/// `leave-one-out`, `paper`; and back (\throws std::invalid_argument naming the valid ones).
std::string to_string(GehlerShiProtocol protocol);
/// Inverse of to_string(GehlerShiProtocol). \throws std::invalid_argument naming the valid ones.
GehlerShiProtocol gehler_shi_protocol_from_string(const std::string& name);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> gehler_shi_protocol_names();

/// The options of the Gehler–Shi experiment (`gmcc reproduce gehler-shi`).
struct GehlerShiOptions {
  GehlerShiProtocol protocol = GehlerShiProtocol::leave_one_out;  ///< leave-one-out or the paper's
  std::vector<std::string> cameras{"Canon1D", "Canon5D"};  ///< in report order
  /// A patch is usable when every channel c has dark < c < clip (near-black and clipped
  /// patches dropped, and counted).
  ///@{
  Rational dark{1, 500}, clip{19, 20};
  ///@}
  /// Patch numbers (1–24) left out of every image, canonical gamuts and scenes alike (e.g. the
  /// achromatic row 19–24, on which the ground truth was measured).
  std::vector<std::uint32_t> exclude_patches;
};

/// What the setup is made of, per camera, for the report.
struct GehlerShiCamera {
  std::string camera;  ///< its name in the data (`Canon1D`, `Canon5D`)
  std::size_t images = 0;            ///< of this camera in the data
  std::size_t usable_patches = 0;    ///< over its images
  std::size_t dropped_patches = 0;   ///< measured but near-black or clipped
  std::size_t missing_patches = 0;   ///< no measurement in the data
  std::size_t excluded_patches = 0;  ///< measured but left out by GehlerShiOptions::exclude_patches
  std::size_t hull_vertices = 0;     ///< of the camera's canonical gamut (leave-one-out: of all images)
  /// leave-one-out: the images with a patch at a vertex of the all-images hull, whose own
  /// gamut was computed without them (every other image uses the all-images hull).
  std::size_t recomputed_hulls = 0;
  std::vector<std::string> canonical_images;  ///< paper: the canonical chart's images
  /// paper: test images per group, and the rest
  ///@{
  std::size_t yellowish = 0, bluish = 0, untested = 0;
  ///@}
};

/// The experiment made from the data (gehler_shi_setup), and what it used per camera.
struct GehlerShiSetup {
  ExperimentSetup setup;  ///< lights = test images (group: camera, or camera and light group)
  std::vector<GehlerShiCamera> cameras;  ///< in GehlerShiOptions::cameras order
};

/// The setup of `protocol` for `cameras`. Each test image is a TestLight with its usable patches
/// (raw camera RGB; surface ids = patch numbers 1–24), true map (e_b/e_r, e_b/e_g) from its
/// ground truth e, canonical light (1, 1, 1); images with fewer usable patches than a cell's
/// count draw no scenes there (ExperimentSetup::skip_short_lights); baselines on.
/// Paper protocol: τ = log2(e_b/e_r) of the ground truth; daylight images have τ ≥ 0; the
/// canonical chart is the union of the 3 daylight images whose τ is nearest the daylight median
/// (the lower median; ties by file order); yellowish: τ < −1/2; bluish: τ > that median (bluer
/// than the canonical chart's light); the canonical images and the rest are not tested.
/// \throws GehlerShiNothingUsable when a camera's images are there but the options (dark, clip,
///         excluded patches) leave none of its patches usable; std::invalid_argument for an
///         unknown camera, one without images or without a usable patch in the data, or an
///         excluded patch number outside 1–24.
GehlerShiSetup gehler_shi_setup(const ChartDataset& data, const GehlerShiOptions& options);

/// The options, not the data, left a camera nothing: front ends blame their dark, clip and
/// exclude-patches options (the message names the camera, the counts and the thresholds).
struct GehlerShiNothingUsable : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace gmcc
