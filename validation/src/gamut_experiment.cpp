#include <gmcc/validation/gamut_experiment.h>

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/rule_errors.h>
#include <gmcc/selection/select_maps.h>

#include "lazy_mt19937_64.h"
#include "seed_sequence.h"

#include <mpfr.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <mutex>
#include <thread>

namespace gmcc {
namespace {

// Up to `count` threads running `f`: fewer if the system refuses one (a thread's stack is
// address space, so under gmcc's --memory-limit a thread may not be made). The work is shared
// out by an atomic counter and the results do not depend on the number of threads, so the run
// goes on with the threads there are, rather than std::terminate for threads left unjoined.
template <class F>
std::vector<std::thread> start_threads(std::size_t count, const F& f) {
  std::vector<std::thread> threads;
  threads.reserve(count);  // no reallocation below, with threads already running
  for (std::size_t t = 0; t < count; ++t) {
    try {
      threads.emplace_back(f);
    } catch (const std::exception&) {  // std::system_error, or std::bad_alloc for its state
      break;
    }
  }
  return threads;
}

// Uniform integer in [0, n), unbiased (Lemire's multiply-and-reject), platform-independent.
// The scene generator: std::mt19937_64's output, twisted lazily (a scene draws a dozen numbers).
using Generator = internal::LazyMt19937_64;

std::uint64_t below(Generator& g, std::uint64_t n) {
  unsigned __int128 m = static_cast<unsigned __int128>(g()) * n;
  auto low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = static_cast<unsigned __int128>(g()) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return static_cast<std::uint64_t>(m >> 64);
}

double uniform01(Generator& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }

// Standard normal by Box–Muller (one of the pair), from the scene's own generator.
double normal(Generator& g) {
  const double u = 1 - uniform01(g), v = uniform01(g);  // u in (0, 1]
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const std::size_t h = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(h), v.end());
  const double upper = v[h];
  if (v.size() % 2) return upper;
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<long>(h));
  return (lower + upper) / 2;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;  // in scene order: deterministic
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}

Point2 exact_map(const MapEstimate& e) {
  return e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
}

ExperimentCell run_cell(const ExperimentSetup& setup, const ExperimentConfig& config,
                        const CanonicalConstraints& gamut, const std::vector<Point2>& chromaticities,
                        std::size_t light_index, int n, std::atomic<std::uint64_t>& done) {
  const TestLight& light = setup.lights[light_index];
  ExperimentCell cell;
  cell.light = light.name;
  cell.surfaces = n;
  const std::size_t R = config.crule ? 5 : 3;
  std::vector<std::vector<double>> error(R), worst(R), illuminant(R), reproduction(R);
  cell.rules.resize(R);
  std::vector<std::size_t> pool(light.surfaces.size());
  SelectionOptions selection;
  selection.mean3d = config.mean3d;
  for (std::uint64_t s = 0; s < config.scenes; ++s, ++done) {
    // std::seed_seq{these six words}, computed faster with the same output.
    internal::SeedSequence<6> seq({static_cast<std::uint32_t>(config.seed), static_cast<std::uint32_t>(config.seed >> 32),
                                   static_cast<std::uint32_t>(light_index), static_cast<std::uint32_t>(n),
                                   static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(s >> 32)});
    Generator g(seq);
    for (std::size_t i = 0; i < pool.size(); ++i) pool[i] = i;
    // The surfaces first (partial Fisher–Yates: n distinct), then noise and shading factors from
    // the same generator, so that options which draw more numbers never change the surfaces.
    for (int i = 0; i < n; ++i)
      std::swap(pool[static_cast<std::size_t>(i)],
                pool[static_cast<std::size_t>(i) + below(g, pool.size() - static_cast<std::size_t>(i))]);
    // The scene's chromaticities by address: the light's precomputed ones, or this scene's own.
    std::vector<const Point2*> image;
    std::vector<Point2> own;
    own.reserve(static_cast<std::size_t>(n));
    std::vector<Colour> image_colours;
    for (int i = 0; i < n; ++i) {
      const std::size_t surface = pool[static_cast<std::size_t>(i)];
      // Without noise the chromaticities are the light's, computed once (shading scales a
      // colour, not its chromaticity); the colours themselves are kept only for 3-D CRULE.
      if (config.noise <= 0 && !config.crule) {
        if (sgn(light.surfaces[surface].b) > 0) image.push_back(&chromaticities[surface]);
        continue;
      }
      Colour c = light.surfaces[surface];
      if (config.noise > 0)
        for (Rational* x : {&c.r, &c.g, &c.b})
          *x *= rational_from_double(std::max(0.0, 1 + config.noise * normal(g)));
      if (config.shading > 0) {
        const Rational scale = rational_from_double(config.shading + (1 - config.shading) * uniform01(g));
        for (Rational* x : {&c.r, &c.g, &c.b}) *x *= scale;
      }
      if (sgn(c.b) > 0) own.push_back(perspective_chromaticity(c)), image.push_back(&own.back());
      image_colours.push_back(std::move(c));
    }
    ++cell.scenes;
    if (image.empty()) {
      ++cell.empty;
      continue;
    }
    const FeasiblePolygon P = feasible_polygon(gamut, image);
    if (P.kind() == ConvexKind::empty) {
      ++cell.empty;
      continue;
    }
    // With Finlayson's constraint, `gamut` carries C too: P is F ∩ C.
    const bool truth_inside = P.contains(light.true_map);
    auto record = [&](std::size_t r, double map_error, double worst_case, bool truth) {
      error[r].push_back(map_error);
      worst[r].push_back(worst_case);
      cell.rules[r].truth_in_feasible_set += truth;
    };
    auto score = [&](std::size_t r, const Point2& m, double worst_case, bool truth) {
      record(r, map_angular_error_deg(m, light.true_map), worst_case, truth);
      if (sgn(m.x) > 0 && sgn(m.y) > 0) {
        illuminant[r].push_back(illuminant_angular_error_deg(m, light.true_map, setup.canonical_light));
        reproduction[r].push_back(reproduction_angular_error_deg(m, light.true_map));
      }
    };
    // The fast certified route (rule_errors.h) where it applies and can certify its angles;
    // otherwise the exact maps and angles. Both agree within rule_errors_accuracy.
    std::optional<std::array<RuleErrors, 3>> fast;
    if (config.certified_fast_route && config.mean3d.method == Mean3dMethod::analytic && config.mean3d.precision_bits == 0)
      fast = rule_errors(P, light.true_map, setup.canonical_light);
    if (fast) {
      for (std::size_t r = 0; r < 3; ++r) {
        const RuleErrors& x = (*fast)[r];
        record(r, x.map_error_deg, x.worst_case_deg, truth_inside);
        if (x.positive_map) {
          illuminant[r].push_back(x.illuminant_error_deg);
          reproduction[r].push_back(x.reproduction_error_deg);
        }
      }
    } else {
      const Selections sel = select_maps(P.exact(), selection);
      const std::array<const std::optional<Selection>*, 3> rules{&sel.max_area, &sel.mean_2d, &sel.mean_3d};
      for (std::size_t r = 0; r < 3; ++r) {
        const Selection& x = **rules[r];
        if (x.estimate.valid) score(r, exact_map(x.estimate), *x.worst_case_deg, truth_inside);
      }
    }
    if (config.crule) {  // the same scene in 3-D; maps scored by their perspective (d1/d3, d2/d3)
      const Crule3d c3 = crule_3d(setup.canonical_surfaces, image_colours);
      const bool truth3_inside = contains(c3.feasible, light.true_diagonal_map);
      const std::array<const std::optional<Selection3>*, 2> rules3{&c3.max_volume, &c3.centroid};
      for (std::size_t r = 0; r < 2; ++r) {
        if (!*rules3[r] || !(*rules3[r])->worst_case_deg) continue;
        const MapEstimate3& e = (*rules3[r])->estimate;
        const Point3 d = e.exact ? *e.exact
                                 : Point3{rational_from_double(e.map[0]), rational_from_double(e.map[1]),
                                          rational_from_double(e.map[2])};
        if (sgn(d.z) <= 0) continue;  // the zero map has no perspective
        score(3 + r, {Rational(d.x / d.z), Rational(d.y / d.z)}, *(*rules3[r])->worst_case_deg, truth3_inside);
      }
    }
  }
  for (std::size_t r = 0; r < R; ++r) {
    RuleStats& st = cell.rules[r];
    st.mean_error_deg = mean(error[r]);
    st.median_error_deg = median(error[r]);
    st.max_error_deg = error[r].empty() ? 0 : *std::max_element(error[r].begin(), error[r].end());
    st.mean_worst_case_deg = mean(worst[r]);
    st.median_worst_case_deg = median(worst[r]);
    st.mean_illuminant_error_deg = mean(illuminant[r]);
    st.median_illuminant_error_deg = median(illuminant[r]);
    st.mean_reproduction_error_deg = mean(reproduction[r]);
  }
  return cell;
}

}  // namespace

ExperimentResult run_gamut_experiment(const ExperimentSetup& setup, const ExperimentConfig& config) {
  if (config.min_surfaces < 1 || config.max_surfaces < config.min_surfaces)
    throw std::invalid_argument("surface counts must satisfy 1 <= min <= max");
  for (const TestLight& l : setup.lights)
    if (static_cast<std::size_t>(config.max_surfaces) > l.surfaces.size())
      throw std::invalid_argument("light " + l.name + " has only " +
                                  std::to_string(l.surfaces.size()) + " surfaces");
  ExperimentResult result;
  result.name = setup.name;
  result.config = config;
  result.config.progress = nullptr;
  result.rules.assign(experiment_rules.begin(), experiment_rules.end());
  if (config.crule) result.rules.insert(result.rules.end(), experiment_rules_3d.begin(), experiment_rules_3d.end());
  result.canonical_gamut =
      canonical_gamut(perspective_chromaticities(setup.canonical_surfaces, NonPositiveBluePolicy::drop).points,
                      config.expansion);

  struct Job {
    std::size_t light;
    int n;
  };
  std::vector<Job> jobs;
  for (std::size_t l = 0; l < setup.lights.size(); ++l)
    for (int n = config.min_surfaces; n <= config.max_surfaces; ++n) jobs.push_back({l, n});
  result.cells.resize(jobs.size());

  // G_c (and Finlayson's constraint C, when given) prepared once for every scene.
  const CanonicalConstraints gamut = config.constraint
                                         ? CanonicalConstraints(result.canonical_gamut, *config.constraint)
                                         : CanonicalConstraints(result.canonical_gamut);
  // Without noise a scene's colours are the light's surfaces as given: their chromaticities are
  // computed once per light (b <= 0 left as a placeholder; scenes skip those surfaces).
  // Lights are shared out among the threads (each light's list is written by one thread only).
  const unsigned threads = config.threads ? config.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::vector<Point2>> chromaticities(setup.lights.size());
  if (config.noise <= 0) {
    std::atomic<std::size_t> next_light{0};
    auto precompute = [&] {
      for (std::size_t l; (l = next_light++) < setup.lights.size();) {
        chromaticities[l].reserve(setup.lights[l].surfaces.size());
        for (const Colour& c : setup.lights[l].surfaces)
          chromaticities[l].push_back(sgn(c.b) > 0 ? perspective_chromaticity(c) : Point2{});
      }
    };
    std::vector<std::thread> helpers =
        start_threads(std::max<std::size_t>(std::min<std::size_t>(threads, setup.lights.size()), 1) - 1,
                      precompute);
    precompute();
    for (std::thread& t : helpers) t.join();
  }
  std::atomic<std::size_t> next{0};
  std::atomic<std::uint64_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};
  auto worker = [&] {
    for (std::size_t j; (j = next++) < jobs.size();) {
      try {
        result.cells[j] = run_cell(setup, config, gamut, chromaticities[jobs[j].light], jobs[j].light, jobs[j].n, done);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
      }
    }
  };
  // A worker thread's MPFR constant caches (π for the angles) are thread-local: free them when
  // the thread ends, or every run leaks them (LeakSanitizer).
  auto thread_worker = [&worker] {
    worker();
    mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  };
  std::vector<std::thread> pool =
      start_threads(std::max<std::size_t>(std::min<std::size_t>(threads, jobs.size()), 1) - 1, thread_worker);
  const std::uint64_t total = config.scenes * jobs.size();
  std::vector<std::thread> reporter_free_worker;
  if (config.progress) reporter_free_worker = start_threads(1, thread_worker);
  if (!reporter_free_worker.empty()) {  // report from this thread while the others work, then join in
    while (done < total && !failed) {
      config.progress(done, total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    reporter_free_worker.front().join();
    config.progress(done, total);
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return result;
}

}  // namespace gmcc
