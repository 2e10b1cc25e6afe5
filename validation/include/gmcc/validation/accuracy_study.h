#pragma once
/// \file accuracy_study.h
/// The accuracy study of the 3-D mean (Finlayson & Hordley 1999 §3.2; docs/accuracy.md): on a
/// fixed 7-gon P(w) of width w = 10 … 1e-12 around the map (1.1, 0.7), the error of each route —
/// the double closed form, the certified closed form, Duffy–Gauss–Legendre quadrature of orders
/// 2–16 and Monte Carlo with 10^4–10^7 samples (docs/math.md §2) — against a 4096-bit certified
/// enclosure; and its reports: the text table, the long-format CSV and the gnuplot data and
/// script. What `gmcc accuracy` prints and scripts/accuracy-doc commits as docs/accuracy.md.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// The study's two settings (docs/cli.md "gmcc accuracy").
struct AccuracySettings {
  std::uint64_t seed = 1;                 ///< Monte Carlo generator seed (mt19937_64), every run
  std::uint64_t max_samples = 10000000;   ///< cap on the Monte Carlo sample counts 10^4 … 10^7
};

/// One estimate of one route at one width (one CSV row).
struct AccuracyMeasurement {
  std::string route;      ///< reference, double, analytic, quadrature, monte-carlo
  std::string parameter;  ///< bits, order or samples; empty for the double closed form
  bool valid = true;      ///< false: Monte Carlo with too few samples in the cone
  /// max_k |m_k − m*_k| against the rounded reference m*: the exact difference of doubles,
  /// rounded once.
  double error_abs = 0;
  double error_rel = 0;  ///< error_abs / max_k |m*_k|
  std::optional<double> bound;  ///< the route's own error statement, where it has one
  std::string extra;            ///< key=value;… (the CSV's `extra` column)
  unsigned precision_bits = 0;  ///< analytic: working precision
  std::uint64_t kept = 0;       ///< monte-carlo: samples inside the cone
  bool rounded = false;         ///< analytic, quadrature: both components correctly rounded
};

/// Every route measured at one width.
struct AccuracyWidth {
  std::string width;  ///< as in accuracy_widths(): the exact value, read by parse_rational
  std::size_t vertices = 0;  ///< of P(w)
  MapEstimate reference;     ///< mean_3d_analytic at 4096 bits
  std::vector<AccuracyMeasurement> rows;  ///< the reference, then every route (CSV order)
};

/// The widths w of the study, as text ("10", "1", "1e-1", … "1e-12"), widest first.
const std::vector<std::string>& accuracy_widths();

/// The test polygon P(w): the hull of (11/10, 7/10) + w·o_i over a fixed, strictly convex,
/// counter-clockwise 7-gon o_i of height 1 with no symmetry, each coordinate clipped to >= 1/100
/// (only w = 10 is clipped). \throws InternalError if it is not a polygon (never, for w > 0).
ConvexSet2 accuracy_test_polygon(const Rational& w);

/// Every route at width `width` (text as in accuracy_widths()). Cost: dominated by the
/// 4096-bit reference and Monte Carlo's samples (about a second per width at 10^7).
AccuracyWidth measure_accuracy(const std::string& width, const AccuracySettings& settings);

/// The text table `gmcc accuracy` prints: the closed forms, the quadrature and Monte Carlo,
/// one row per width.
std::string accuracy_table(const std::vector<AccuracyWidth>& results, const AccuracySettings& settings);

/// The long-format CSV: width,route,parameter,error_abs,error_rel,reported_bound,extra (with its
/// header line, without a provenance line).
std::string accuracy_csv(const std::vector<AccuracyWidth>& results);

/// accuracy.dat: one gnuplot data block per plotted line (width, relative error or bound; zero
/// drawn at 1e-17).
std::string accuracy_plot_data(const std::vector<AccuracyWidth>& results, const AccuracySettings& settings);

/// accuracy.gp: the gnuplot script that draws accuracy.dat into accuracy.png and accuracy.svg.
std::string accuracy_plot_script(const AccuracySettings& settings);

}  // namespace gmcc
