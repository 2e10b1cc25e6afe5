#pragma once
/// \file error_statistics.h
/// The summary statistics every experiment reports for a list of angular errors: mean, standard
/// error, median, trimean, best 25%, worst 25%, 95th percentile and maximum, each defined
/// precisely in docs/reproduction.md "Statistics". Deterministic: the same values in the same
/// order give the same bits.

#include <cstdint>
#include <vector>

namespace gmcc {

/// Statistics of n values. With n = 0 every statistic is NaN, undefined (reports write null in JSON
/// and an empty field in CSV);
/// with n = 1 the standard error is NaN (a spread needs two values).
struct ErrorStatistics {
  std::uint64_t n = 0;        ///< how many values (scenes) the statistics are over
  double mean = 0;            ///< Σx / n, summed in the order given
  double standard_error = 0;  ///< s / √n, s² = Σ(x − mean)² / (n − 1) (two passes, same order)
  double median = 0;          ///< sorted_quantile(0.5)
  double trimean = 0;         ///< (Q1 + 2·median + Q3) / 4, Q1 = quantile(0.25), Q3 = quantile(0.75)
  double best25 = 0;          ///< mean of the ⌈n/4⌉ smallest values
  double worst25 = 0;         ///< mean of the ⌈n/4⌉ largest values
  double p95 = 0;             ///< sorted_quantile(0.95)
  double max = 0;            ///< the largest value
};

/// The p-quantile of values sorted ascending (n ≥ 1, 0 ≤ p ≤ 1): linear interpolation between
/// order statistics (Hyndman & Fan's type 7, R's and NumPy's default): h = (n − 1)·p in double,
/// i = ⌊h⌋, f = h − i; Q = x_i when f = 0 (or i = n − 1), else (1 − f)·x_i + f·x_{i+1} (0-based).
double sorted_quantile(const std::vector<double>& sorted, double p);

/// The statistics of `values` (taken by value: sorted inside). NaN values are not allowed.
ErrorStatistics error_statistics(std::vector<double> values);

}  // namespace gmcc
