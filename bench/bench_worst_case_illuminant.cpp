// bench_worst_case_illuminant: the illuminant-space worst case (worst_case_illuminant, docs/math.md
// §3) of each rule's map on one feasible set, by each route of
// selection/src/internal/worst_case_illuminant_route.h, with the CPU time of each call and a check
// that every route gives the same answer (angle, location, at_vertex) as the first one run.
//
//   bench_worst_case_illuminant F.txt [--routes exact,double_filtered,certified]
//                               [--rules max_area,mean_2d,mean_3d] [--repeat N]
//
// F.txt: F's exact vertices in canonical order (docs: convex_set.h), one "x y" a line as GMP
// rationals; `GMCC_FUZZ_DUMP_F=F.txt build/fuzz/fuzz_hard_geometry FINDING` writes a fuzz
// input's F so (fuzz/README.md). The canonical illuminant is fuzz_hard_geometry's, (2, 1, 3/7).
// Exit status 1 when two routes disagree.
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/mean_3d.h>

#include "internal/worst_case_illuminant_route.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s F.txt [--routes R,..] [--rules R,..] [--repeat N]\n", argv[0]);
    return 2;
  }
  std::vector<std::string> routes{"double_filtered", "certified"}, rules{"max_area", "mean_2d", "mean_3d"};
  int repeat = 1;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--routes")) routes = split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--rules")) rules = split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
  }
  const std::map<std::string, internal::IlluminantRoute> by_name{
      {"exact", internal::IlluminantRoute::exact},
      {"double_filtered", internal::IlluminantRoute::double_filtered},
      {"certified", internal::IlluminantRoute::certified}};
  std::ifstream file(argv[1]);
  std::vector<Point2> cycle;
  for (std::string x, y; file >> x >> y;) cycle.push_back({Rational(x), Rational(y)});
  const ConvexSet2 F = canonical_convex_set(cycle);
  std::size_t bits = 0;
  for (const Point2& v : F.vertices)
    for (const Rational* q : {&v.x, &v.y})
      bits = std::max(bits, mpz_sizeinbase(q->get_num_mpz_t(), 2) + mpz_sizeinbase(q->get_den_mpz_t(), 2));
  std::printf("F: %s of %zu vertices, longest coordinate %zu bits (numerator and denominator)\n",
              to_string(F.kind).c_str(), F.vertices.size(), bits);
  const Colour light{2, 1, Rational(3, 7)};
  bool same = true;
  for (const std::string& rule : rules) {
    const MapEstimate e = rule == "max_area" ? max_area(F) : rule == "mean_2d" ? mean_2d(F) : mean_3d(F);
    const Point2 m = e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
    std::optional<IlluminantWorstCase> first;
    for (const std::string& route : routes) {
      double best = 1e300;
      IlluminantWorstCase w;
      internal::IlluminantRouteWork work;
      for (int r = 0; r < repeat; ++r) {
        const double t0 = cpu_seconds();
        w = internal::worst_case_illuminant(F, m, light, by_name.at(route), &work);
        best = std::min(best, cpu_seconds() - t0);
      }
      const bool agrees = !first || (w.angle_deg == first->angle_deg && w.location == first->location &&
                                     w.at_vertex == first->at_vertex);
      same = same && agrees;
      if (!first) first = w;
      std::printf("%-9s %-16s %10.4f s  %.17g deg  %-14s  exact: %zu vertices, %zu edges, %zu Sturm%s\n",
                  rule.c_str(), route.c_str(), best, w.angle_deg, w.at_vertex ? "at a vertex" : "inside an edge",
                  work.exact_vertices, work.exact_edges, work.sturm_edges, agrees ? "" : "  DIFFERS");
    }
  }
  return same ? 0 : 1;
}
