// Per-scene cost of the synthetic experiment (issue "Performance"): the exact pipeline gmcc runs
// for every scene (exact feasible set, the three rules with their map-space worst cases, the
// map, illuminant and reproduction errors), against the same pipeline on plain doubles written
// the straightforward way (the ratio's baseline; no filters, no certification, no exactness).
// Both run on the same scenes, one after the other, in this one process; CPU time is reported.
//
//   bench_scene [--scenes N] [--surfaces K] [--data DIR]
//
// Scenes: N per test light (D75, D100, P2856, P15000), K Munsell chips each (default 11, the
// issue's "11 image colours"; 0 cycles K through 1..11 like the experiment).
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/validation/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <vector>

#ifndef GMCC_DATA_DIR
#define GMCC_DATA_DIR "data"
#endif

namespace {
using namespace gmcc;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// ---------------------------------------------------------------- the plain-double pipeline
using P = std::array<double, 2>;

double cross(const P& o, const P& a, const P& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

std::vector<P> hull(std::vector<P> p) {  // Andrew's monotone chain, CCW, collinear dropped
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<P> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

struct DLine {
  double a, b, c;  // a·x + b·y <= c
};

void clip(std::vector<P>& poly, const DLine& l, std::vector<P>& out) {
  out.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % n];
    const double sp = l.a * p[0] + l.b * p[1] - l.c, sq = l.a * q[0] + l.b * q[1] - l.c;
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  poly.swap(out);
}

struct DoubleScene {
  std::array<P, 3> maps;
  std::array<double, 3> error, worst, illuminant, reproduction;
  bool empty = false;
};

double angle(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  const double c0 = u[1] * v[2] - u[2] * v[1], c1 = u[2] * v[0] - u[0] * v[2], c2 = u[0] * v[1] - u[1] * v[0];
  return std::atan2(std::sqrt(c0 * c0 + c1 * c1 + c2 * c2), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) * (180 / M_PI);
}
double map_angle(const P& m, const P& t) { return angle({m[0], m[1], 1}, {t[0], t[1], 1}); }

DoubleScene double_scene(const std::vector<DLine>& gamut, const P& gamut_max, const std::vector<P>& image,
                         const P& truth, const std::array<double, 3>& c) {
  DoubleScene s;
  const std::vector<P> qs = hull(image);
  double q1 = 0, q2 = 0;
  for (const P& q : qs) q1 = std::max(q1, q[0]), q2 = std::max(q2, q[1]);
  std::vector<P> poly{{0, 0}, {gamut_max[0] / q1, 0}, {gamut_max[0] / q1, gamut_max[1] / q2}, {0, gamut_max[1] / q2}};
  std::vector<P> buffer;
  for (const P& q : qs)
    for (const DLine& g : gamut) {
      clip(poly, {g.a * q[0], g.b * q[1], g.c}, buffer);
      if (poly.empty()) {
        s.empty = true;
        return s;
      }
    }
  // max-area: vertices and edge stationary points
  const std::size_t n = poly.size();
  P best = poly[0];
  double best_value = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % n];
    if (p[0] * p[1] > best_value) best_value = p[0] * p[1], best = p;
    const double da = q[0] - p[0], db = q[1] - p[1];
    if (da * db < 0) {
      const double t = -(da * p[1] + db * p[0]) / (2 * da * db);
      const P m{p[0] + t * da, p[1] + t * db};
      if (t > 0 && t < 1 && m[0] * m[1] > best_value) best_value = m[0] * m[1], best = m;
    }
  }
  s.maps[0] = best;
  // 2-D mean: area centroid by a fan from vertex 0
  double w_sum = 0, x_sum = 0, y_sum = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double w = cross(poly[0], poly[i], poly[i + 1]);
    w_sum += w, x_sum += w * (poly[0][0] + poly[i][0] + poly[i + 1][0]), y_sum += w * (poly[0][1] + poly[i][1] + poly[i + 1][1]);
  }
  s.maps[1] = w_sum > 0 ? P{x_sum / (3 * w_sum), y_sum / (3 * w_sum)} : poly[0];
  // 3-D mean: τ = ½ Σ θ_i c_i/|c_i|
  double t[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const P& a = poly[i];
    const P& b = poly[(i + 1) % n];
    const double c0 = a[1] - b[1], c1 = b[0] - a[0], c2 = a[0] * b[1] - a[1] * b[0];
    const double norm = std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
    if (norm == 0) continue;
    const double w = std::atan2(norm, a[0] * b[0] + a[1] * b[1] + 1) / norm;
    t[0] += w * c0, t[1] += w * c1, t[2] += w * c2;
  }
  s.maps[2] = t[2] != 0 ? P{t[0] / t[2], t[1] / t[2]} : poly[0];
  for (int r = 0; r < 3; ++r) {
    const P& m = s.maps[r];
    s.error[r] = map_angle(m, truth);
    s.worst[r] = 0;
    for (const P& v : poly) s.worst[r] = std::max(s.worst[r], map_angle(m, v));
    s.illuminant[r] = angle({c[0] / m[0], c[1] / m[1], c[2]}, {c[0] / truth[0], c[1] / truth[1], c[2]});
    s.reproduction[r] = angle({m[0] / truth[0], m[1] / truth[1], 1}, {1, 1, 1});
  }
  return s;
}

// ---------------------------------------------------------------- the exact pipeline (as run_cell)
double exact_scene(const CanonicalConstraints& gamut, const std::vector<Point2>& image, const Point2& truth,
                   const Colour& c, std::map<unsigned, int>& mean3d_bits, int& truth_inside) {
  const ConvexSet2 F = feasible_set(gamut, image);
  if (F.kind == ConvexKind::empty) return 0;
  truth_inside += contains(F, truth);
  const Selections sel = select_maps(F);
  double sum = 0;
  for (const auto* x : {&sel.max_area, &sel.mean_2d, &sel.mean_3d}) {
    const MapEstimate& e = (*x)->estimate;
    const Point2 m = e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
    sum += map_angular_error_deg(m, truth) + *(*x)->worst_case_deg;
    if (sgn(m.x) > 0 && sgn(m.y) > 0)
      sum += illuminant_angular_error_deg(m, truth, c) + reproduction_angular_error_deg(m, truth);
  }
  ++mean3d_bits[sel.mean_3d->estimate.precision_bits];
  return sum;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t scenes = 500;
  int surfaces = 11;
  std::string data = GMCC_DATA_DIR;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scenes")) scenes = std::stoull(argv[i + 1]);
    if (!std::strcmp(argv[i], "--surfaces")) surfaces = std::stoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--data")) data = argv[i + 1];
  }
  const ExperimentSetup setup = synthetic_setup(read_spectral_csv(data + "/munsell_matt_1269_joensuu_5nm.csv"),
                                                read_spectral_csv(data + "/cie_daylight_basis_S0_S1_S2.csv"), "D55",
                                                {"D75", "D100", "P2856", "P15000"});
  const ConvexSet2 G =
      canonical_gamut(perspective_chromaticities(setup.canonical_surfaces, NonPositiveBluePolicy::drop).points, {});
  const CanonicalConstraints prepared(G);

  // The scenes, as exact chromaticities and as doubles (nearest).
  struct Scene {
    std::size_t light;
    std::vector<Point2> exact;
    std::vector<P> approx;
  };
  std::vector<Scene> all;
  std::mt19937_64 g(6);
  for (std::size_t l = 0; l < setup.lights.size(); ++l)
    for (std::uint64_t s = 0; s < scenes; ++s) {
      const int k = surfaces > 0 ? surfaces : static_cast<int>(1 + s % 11);
      std::vector<std::size_t> pool(setup.lights[l].surfaces.size());
      for (std::size_t i = 0; i < pool.size(); ++i) pool[i] = i;
      std::shuffle(pool.begin(), pool.end(), g);
      Scene sc{l, {}, {}};
      for (int i = 0; i < k; ++i) {
        const Point2 q = perspective_chromaticity(setup.lights[l].surfaces[pool[static_cast<std::size_t>(i)]]);
        sc.approx.push_back(to_double_nearest(q));
        sc.exact.push_back(q);
      }
      all.push_back(std::move(sc));
    }
  // The gamut's edges as double lines a·x + b·y <= c (outward normals of the CCW edges).
  std::vector<DLine> dgamut;
  P gmax{0, 0};
  for (std::size_t i = 0; i < G.vertices.size(); ++i) {
    const P p = to_double_nearest(G.vertices[i]), q = to_double_nearest(G.vertices[(i + 1) % G.vertices.size()]);
    dgamut.push_back({q[1] - p[1], p[0] - q[0], (q[1] - p[1]) * p[0] + (p[0] - q[0]) * p[1]});
    gmax = {std::max(gmax[0], p[0]), std::max(gmax[1], p[1])};
  }
  const std::array<double, 3> cd{to_double_nearest(setup.canonical_light.r), to_double_nearest(setup.canonical_light.g),
                                 to_double_nearest(setup.canonical_light.b)};

  // Plain doubles first, then exact; each over every scene, repeated for a second reading.
  double sink = 0;
  std::map<unsigned, int> bits;
  int inside = 0;
  double t_double = 1e30, t_exact = 1e30;
  for (int rep = 0; rep < 2; ++rep) {
    double t0 = cpu_seconds();
    for (const Scene& s : all) {
      const DoubleScene d = double_scene(dgamut, gmax, s.approx, to_double_nearest(setup.lights[s.light].true_map), cd);
      sink += d.empty ? 0 : d.error[0] + d.worst[2] + d.illuminant[1] + d.reproduction[2];
    }
    t_double = std::min(t_double, cpu_seconds() - t0);
    bits.clear();
    inside = 0;
    t0 = cpu_seconds();
    for (const Scene& s : all)
      sink += exact_scene(prepared, s.exact, setup.lights[s.light].true_map, setup.canonical_light, bits, inside);
    t_exact = std::min(t_exact, cpu_seconds() - t0);
  }
  const double n = static_cast<double>(all.size());
  std::printf("scenes: %zu (%s surfaces), canonical gamut %zu vertices\n", all.size(),
              surfaces > 0 ? std::to_string(surfaces).c_str() : "1-11", G.vertices.size());
  std::printf("exact pipeline:        %8.2f us CPU per scene\n", 1e6 * t_exact / n);
  std::printf("plain-double pipeline: %8.2f us CPU per scene\n", 1e6 * t_double / n);
  std::printf("ratio exact/double:    %8.2f\n", t_exact / t_double);
  std::printf("3-D mean precision (64 = extended fast path):");
  for (const auto& [b, count] : bits) std::printf(" %u bits x%d", b, count);
  std::printf("\ntrue map in F: %d; checksum %.6g\n", inside, sink);
}
