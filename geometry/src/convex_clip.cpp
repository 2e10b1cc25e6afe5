#include "internal/convex_clip.h"
#include "internal/sutherland_hodgman.h"

namespace gmcc::internal {

void clip(PolygonClipper& c, const std::vector<Vertex>& cycle, std::size_t hi, std::vector<Vertex>& out,
          std::vector<int>& s) {
  const std::size_t n = cycle.size();
  s.resize(n);
  out.clear();
  for (std::size_t i = 0; i < n; ++i) s[i] = c.side(hi, cycle[i]);
  const bool clipped = sutherland_hodgman(
      s,
      [&](std::size_t i, std::size_t j) {
        Vertex v = cycle[i];
        // Leaving the half-plane from a point on its line: the boundary follows h from here.
        if (s[i] == 0 && s[j] > 0) v.out = hi;
        out.push_back(v);
      },
      [&](std::size_t i, std::size_t) {  // exiting continues along h, entering along the edge
        const std::size_t edge = cycle[i].out;
        out.push_back(c.vertex(edge, hi, s[i] < 0 ? hi : edge));
      });
  if (!clipped) out = cycle;
}

std::vector<Vertex> reduced(PolygonClipper& c, const std::vector<Vertex>& cycle) {
  std::vector<Vertex> v;
  v.reserve(cycle.size());
  for (const Vertex& p : cycle) {
    if (!v.empty() && c.same_point(v.back(), p))
      v.back().out = p.out;
    else
      v.push_back(p);
  }
  while (v.size() > 1 && c.same_point(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return v;
  std::vector<Vertex> out;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (c.side(v[(i + n - 1) % n].out, v[(i + 1) % n]) != 0) out.push_back(v[i]);
  // All collinear: keep the cycle for canonical_convex_set to take the extreme points of.
  return out.size() >= 3 ? out : v;
}

}  // namespace gmcc::internal
