// bench_accuracy_sweep: how honest each route to the 3-D mean (Finlayson & Hordley 1999 §3.2;
// docs/math.md §2) is on seeded hard convex sets (tests/support/hard_polygons.h), measured
// against the independent self-checked 2048-bit MPFR reference (tests/support/mean_3d_reference.h).
// For each route (analytic; quadrature at orders 4, 12, 24) and category it prints one table row:
// cases, invalid answers, the largest error/bound, how many errors exceed their bound, how many
// maps are not the double nearest the reference, and for the analytic route its time per call.
//
//   bench_accuracy_sweep [--cases N] [--seed S] [--verbose]   (defaults: 320 cases, seed 19990301)
//
// --verbose also prints one line per case and route (errors, bounds, nearest or not) on stderr,
// and each row's worst case by name.
//
// It reads only MapEstimate's map, error_bound and valid, so it builds against the API before
// per-coordinate bounds too; with GMCC_SWEEP_NEW_API (set by bench/CMakeLists.txt) it uses
// error_bounds[k] per coordinate and also counts maps claimed correctly rounded that are not.
#include "../tests/support/hard_polygons.h"
#include "../tests/support/mean_3d_reference.h"

#include <gmcc/selection/mean_3d.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace gmcc;
using gmcc::test::Coverage;
using gmcc::test::HardCase;
using gmcc::test::Mean3dReference;

namespace {

struct Row {
  unsigned cases = 0, invalid = 0, over_bound = 0, not_nearest = 0, wrong_claim = 0;
  double max_ratio = 0;
  std::string worst_case;  // the case of max_ratio
  std::vector<double> micros;  // analytic: per-case median time of one call
};

struct Route {
  std::string name;
  std::function<MapEstimate(const ConvexSet2&)> run;
};

double bound_of(const MapEstimate& e, int k) {
#ifdef GMCC_SWEEP_NEW_API
  return e.error_bounds[k];
#else
  (void)k;
  return e.error_bound;
#endif
}

volatile double sink;

// Median time, in microseconds, of `repeats` calls of mean_3d_analytic on F (steady_clock).
double analytic_micros(const ConvexSet2& F, int repeats) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const MapEstimate e = mean_3d_analytic(F);
    const auto stop = std::chrono::steady_clock::now();
    sink = e.map[0];  // keep the call
    t.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

[[noreturn]] void usage(const char* message) {
  std::fprintf(stderr, "bench_accuracy_sweep: %s\nusage: bench_accuracy_sweep [--cases N] [--seed S] [--verbose]\n",
               message);
  std::exit(2);
}

unsigned long long number(const char* text) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (!*text || *end || text[0] == '-') usage("expected a non-negative integer");
  return v;
}

// The sweep's options: --cases N, --seed S, --verbose.
struct Args {
  unsigned cases = 320;
  std::uint64_t seed = 19990301;
  bool verbose = false;
};
Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cases") && i + 1 < argc) {
      a.cases = static_cast<unsigned>(number(argv[++i]));
    } else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) {
      a.seed = number(argv[++i]);
    } else if (!std::strcmp(argv[i], "--verbose")) {
      a.verbose = true;
    } else {
      usage("unknown option or missing value");
    }
  }
  return a;
}

// One route on one case against its reference: the estimate, its largest error/bound ratio, and
// whether it is over its bound, not the nearest double, or wrongly claims correct rounding.
struct Outcome {
  MapEstimate e;
  double ratio = 0, micros = 0;
  bool over = false, off = false, wrong = false;
};
Outcome evaluate(const Route& route, const HardCase& c, const Mean3dReference& ref, bool verbose) {
  Outcome o;
  MapEstimate& e = o.e;
  try {
    e = route.run(c.set);
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "%s %s: threw %s\n", c.name.c_str(), route.name.c_str(), ex.what());
    e.valid = false;
  }
  if (e.valid) {
    for (int k = 0; k < 2; ++k) {
      o.ratio = std::max(o.ratio, ref.error_ratio(e.map[k], bound_of(e, k), k));
      o.over |= ref.covers(e.map[k], bound_of(e, k), k) != Coverage::covered;
      const bool nearest = e.map[k] == ref.nearest_double(k);
      o.off |= !nearest;
#ifdef GMCC_SWEEP_NEW_API
      o.wrong |= e.correctly_rounded[k] && !nearest;
#endif
    }
  }
  o.micros = route.name == "analytic" ? analytic_micros(c.set, 5) : 0;
  if (verbose) {
    std::fprintf(stderr, "%-14s %-14s %-8s %3zu", route.name.c_str(), c.name.c_str(),
                 to_string(c.set.kind).c_str(), c.set.vertices.size());
    for (int k = 0; k < 2 && e.valid; ++k)
      std::fprintf(stderr, "  [%d] map %.17g ref %.17g bound %.3g err/bound %.4g%s", k,
                   e.map[k], ref.nearest_double(k), bound_of(e, k),
                   ref.error_ratio(e.map[k], bound_of(e, k), k),
                   e.map[k] == ref.nearest_double(k) ? "" : " !nearest");
    if (!e.valid) std::fprintf(stderr, "  invalid: %s", e.note.c_str());
    if (o.micros > 0) std::fprintf(stderr, "  %.1f us", o.micros);
    std::fprintf(stderr, "\n");
  }
  return o;
}

// The table: a row per route and category.
void print_table(const Args& args, unsigned reference_failures, const std::vector<Route>& routes,
                 const std::map<std::pair<std::string, std::string>, Row>& rows) {
  const bool verbose = args.verbose;
  const unsigned cases = args.cases;
  const std::uint64_t seed = args.seed;
  std::printf("3-D mean accuracy sweep: seed %llu, %u generated cases + 2 reproducers, reference "
              "2048 bits (self-checked at 4096; %u failed)\n",
              static_cast<unsigned long long>(seed), cases, reference_failures);
#ifdef GMCC_SWEEP_NEW_API
  std::printf("bound: error_bounds[k] per coordinate; claimed-CR-wrong: correctly_rounded[k] but "
              "map[k] != nearest\n");
#else
  std::printf("bound: error_bound (old API, one number for both coordinates)\n");
#endif
  std::printf("%-14s %-11s %6s %7s %14s %7s %9s %10s %11s %10s\n", "route", "category", "cases",
              "invalid", "max err/bound", ">bound", "!nearest", "CR-wrong", "median_us", "max_us");
  for (const Route& route : routes) {
    for (const auto& [key, r] : rows) {
      if (key.first != route.name) continue;
      char timing[64] = "         -          -";
      if (!r.micros.empty())
        std::snprintf(timing, sizeof timing, "%11.1f %10.1f", median(r.micros),
                      *std::max_element(r.micros.begin(), r.micros.end()));
#ifdef GMCC_SWEEP_NEW_API
      const std::string claim = std::to_string(r.wrong_claim);
#else
      const std::string claim = "-";
#endif
      std::printf("%-14s %-11s %6u %7u %14.4g %7u %9u %10s %s", key.first.c_str(),
                  key.second.c_str(), r.cases, r.invalid, r.max_ratio, r.over_bound,
                  r.not_nearest, claim.c_str(), timing);
      if (verbose) std::printf("  worst %s", r.worst_case.c_str());
      std::printf("\n");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse_args(argc, argv);
  std::vector<HardCase> all{test::reproducer_thin_triangle(), test::reproducer_feasible_set()};
  for (HardCase& c : test::hard_cases(args.seed, args.cases)) all.push_back(std::move(c));

  const std::vector<Route> routes{
      {"analytic", [](const ConvexSet2& F) { return mean_3d_analytic(F); }},
      {"quadrature-4", [](const ConvexSet2& F) { return mean_3d_quadrature(F, 4); }},
      {"quadrature-12", [](const ConvexSet2& F) { return mean_3d_quadrature(F); }},
      {"quadrature-24", [](const ConvexSet2& F) { return mean_3d_quadrature(F, 24); }},
  };
  std::map<std::pair<std::string, std::string>, Row> rows;
  unsigned reference_failures = 0;
  std::vector<std::string> worst;  // names of cases over their bound, for the reader

  for (const HardCase& c : all) {
    Mean3dReference ref;
    try {
      ref = test::mean_3d_reference_checked(c.set);
    } catch (const std::exception& e) {
      ++reference_failures;
      std::fprintf(stderr, "%s: reference self-check failed: %s\n", c.name.c_str(), e.what());
      continue;
    }
    for (const Route& route : routes) {
      const Outcome o = evaluate(route, c, ref, args.verbose);
      if (o.over) worst.push_back(route.name + " " + c.name);
      for (const std::string& category : {c.category, std::string("all")}) {
        Row& r = rows[{route.name, category}];
        ++r.cases;
        if (!o.e.valid) {
          ++r.invalid;
          continue;
        }
        if (o.ratio >= r.max_ratio) {
          r.max_ratio = o.ratio;
          r.worst_case = c.name;
        }
        r.over_bound += o.over;
        r.not_nearest += o.off;
        r.wrong_claim += o.wrong;
        if (route.name == "analytic") r.micros.push_back(o.micros);
      }
    }
  }

  print_table(args, reference_failures, routes, rows);
  if (!worst.empty()) {
    std::printf("over their bound:");
    for (const std::string& w : worst) std::printf(" %s;", w.c_str());
    std::printf("\n");
  }
  return 0;
}
