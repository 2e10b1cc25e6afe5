// The benchmark's statistics per method (benchmark.h): error statistics, and how the worst case
// covers and ranks the error.
#include <gmcc/validation/benchmark.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace gmcc {
namespace {

// Spearman's rank correlation (average ranks for ties); absent below 3 pairs or with no spread.
std::optional<double> spearman(const std::vector<std::pair<double, double>>& xy) {
  const std::size_t n = xy.size();
  if (n < 3) return std::nullopt;
  auto ranks = [n](std::vector<double> v) {
    std::vector<std::size_t> idx(n);
    for (std::size_t i = 0; i < n; ++i) idx[i] = i;
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    std::vector<double> r(n);
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i;
      while (j + 1 < n && v[idx[j + 1]] == v[idx[i]]) ++j;
      for (std::size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * double(i + j) + 1;
      i = j + 1;
    }
    return r;
  };
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = xy[i].first, y[i] = xy[i].second;
  const std::vector<double> rx = ranks(x), ry = ranks(y);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += rx[i], my += ry[i];
  mx /= double(n), my /= double(n);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (rx[i] - mx) * (ry[i] - my);
    sxx += (rx[i] - mx) * (rx[i] - mx);
    syy += (ry[i] - my) * (ry[i] - my);
  }
  if (sxx == 0 || syy == 0) return std::nullopt;
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace

std::vector<BenchmarkSummary> summarise_benchmark(const std::vector<BenchmarkRecord>& records,
                                                  const std::vector<std::string>& methods) {
  std::vector<BenchmarkSummary> out;
  for (const std::string& m : methods) {
    BenchmarkSummary s;
    s.method = m;
    std::vector<double> errors;
    std::vector<std::pair<double, double>> wc;
    std::size_t covered = 0;
    bool gamut = false;
    for (const BenchmarkRecord& r : records) {
      if (r.method != m) continue;
      ++s.images;
      gamut = gamut || !r.feasible_kind.empty();
      if (r.answered) ++s.answered;
      else if (r.unanswered == "empty" || r.unanswered == "no_positive_map") ++s.empty;
      else ++s.unanswered_other;
      if (r.error_deg) errors.push_back(*r.error_deg);
      if (r.truth_in_feasible && *r.truth_in_feasible) ++s.truth_in_feasible;
      const std::optional<double>& e = r.worst_case_space_error_deg;
      if (r.answered && r.worst_case_deg && e) {
        wc.push_back({*r.worst_case_deg, *e});
        covered += *e <= *r.worst_case_deg;
      }
    }
    s.errors = error_statistics(errors);
    if (gamut && !wc.empty()) {
      s.worst_case_covers = double(covered) / double(wc.size());
      s.worst_case_correlation = spearman(wc);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace gmcc
