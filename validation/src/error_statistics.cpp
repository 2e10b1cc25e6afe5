#include <gmcc/validation/error_statistics.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmcc {

double sorted_quantile(const std::vector<double>& x, double p) {
  const double h = static_cast<double>(x.size() - 1) * p;
  const auto i = static_cast<std::size_t>(std::floor(h));
  const double f = h - static_cast<double>(i);
  if (f == 0 || i + 1 >= x.size()) return x[std::min(i, x.size() - 1)];
  return (1 - f) * x[i] + f * x[i + 1];
}

ErrorStatistics error_statistics(std::vector<double> v) {
  ErrorStatistics s;
  s.n = v.size();
  if (v.empty()) {  // nothing to summarise: every statistic undefined (NaN; null or empty in reports)
    s.mean = s.standard_error = s.median = s.trimean = s.best25 = s.worst25 = s.p95 = s.max =
        std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  const double n = static_cast<double>(v.size());
  double sum = 0;
  for (double x : v) sum += x;  // in the order given
  s.mean = sum / n;
  if (v.size() < 2) {
    s.standard_error = std::numeric_limits<double>::quiet_NaN();
  } else {
    double squares = 0;
    for (double x : v) squares += (x - s.mean) * (x - s.mean);
    s.standard_error = std::sqrt(squares / (n - 1)) / std::sqrt(n);
  }
  std::sort(v.begin(), v.end());
  s.median = sorted_quantile(v, 0.5);
  s.trimean = (sorted_quantile(v, 0.25) + 2 * s.median + sorted_quantile(v, 0.75)) / 4;
  s.p95 = sorted_quantile(v, 0.95);
  s.max = v.back();
  const std::size_t quarter = (v.size() + 3) / 4;  // ⌈n/4⌉ ≥ 1
  double low = 0, high = 0;
  for (std::size_t i = 0; i < quarter; ++i) low += v[i];                     // ascending
  for (std::size_t i = v.size() - quarter; i < v.size(); ++i) high += v[i];  // ascending
  s.best25 = low / static_cast<double>(quarter);
  s.worst25 = high / static_cast<double>(quarter);
  return s;
}

}  // namespace gmcc
