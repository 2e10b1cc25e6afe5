#pragma once
// Clipping a cycle of symbolic vertices by lines: Sutherland–Hodgman line by line, the convex
// pass that takes a whole family of lines in one turn around a strictly convex cycle, and the
// final reduction (docs/performance-history.md, "Many-vertex canonical gamuts (issue 13)"). Internal to
// gmcc::geometry.

#include "internal/polygon_clipper.h"

#include <cstddef>
#include <vector>

namespace gmcc::internal {

// Sutherland–Hodgman against line `hi`, tracking each output vertex's outgoing line. `out` and
// `s` are reused buffers.
void clip(PolygonClipper& c, const std::vector<Vertex>& cycle, std::size_t hi, std::vector<Vertex>& out,
          std::vector<int>& s);

// What clip_convex did: how many lines it took, and whether the cycle is still strictly convex.
struct ConvexClip {
  std::size_t taken;
  bool strictly_convex;
};

// Clips a strictly convex counter-clockwise cycle (>= 3 vertices) by lines 0, 1, … of a family
// (add_line(e) adds line e to the PolygonClipper and returns its index), one after another, with the
// result of clip() applied line after line: the same vertices, each with the same outgoing line,
// from another start. It stops early, leaving the rest to clip(), once the cycle degenerates
// (fewer than 3 vertices: a segment or a point) or empties, or when it finds the cycle not convex.
//
// Why it is fast (docs/performance-history.md, "Many-vertex canonical gamuts (issue 13)"): the vertices
// strictly outside a line form one arc around the vertex extreme in the direction of the line's
// outward normal n, and there are none when that vertex is not outside. Vertex v is extreme iff
// n lies between the normals of the edges into and out of v: weight_sign(in, h) >= 0 >=
// weight_sign(out, h), an exact test (every vertex passes for a line with a zero normal, and
// then every vertex has the same side). When n turns counter-clockwise by less than π from line
// to line, as along a convex polygon's edges (G_c ⊘ q, the map constraint), the extreme vertex
// moves forward: a pointer advances while the edge out of it comes before n, and the test
// confirms where it stops (a scan of the cycle when it does not: lines in another order, the
// first line). Each line then costs its one side test, plus the arc it removes and the at most
// two crossing vertices it inserts, in a linked cycle: O(|cycle| + lines) for a whole polygon
// instead of clip()'s O(|cycle|) per line.
template <class AddLine>
ConvexClip clip_convex(PolygonClipper& c, std::vector<Vertex>& cycle, std::size_t count, AddLine add_line) {
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<Vertex> node = std::move(cycle);
  const std::size_t n = node.size();
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::size_t live = n, ptr = 0, free_list = none;
  auto finish = [&](std::size_t taken, bool strict) {
    cycle.clear();
    cycle.reserve(live);
    std::size_t i = ptr;
    do cycle.push_back(node[i]), i = next[i];
    while (i != ptr);
    return ConvexClip{taken, strict};
  };
  auto extreme = [&](std::size_t i, std::size_t h) {
    return c.weight_sign(node[prev[i]].out, h) >= 0 && c.weight_sign(node[i].out, h) <= 0;
  };
  auto link = [&](std::size_t from, std::size_t to) { next[from] = to, prev[to] = from; };
  auto allocate = [&](const Vertex& v) {
    if (free_list == none) {
      node.push_back(v), prev.push_back(none), next.push_back(none);
      return node.size() - 1;
    }
    const std::size_t i = free_list;
    free_list = next[i];
    node[i] = v;
    return i;
  };
  for (std::size_t e = 0; e < count; ++e) {
    const std::size_t h = add_line(e);
    // The vertex extreme for h: forward from the last one, else found by a scan.
    for (std::size_t steps = 0; steps < live && c.weight_sign(node[ptr].out, h) > 0; ++steps) ptr = next[ptr];
    if (!extreme(ptr, h)) {
      std::size_t k = 0;
      while (k < live && !extreme(ptr, h)) ptr = next[ptr], ++k;
      if (k == live) {  // no extreme vertex: not convex after all, clip() takes over
        c.drop_last();
        return finish(e, false);
      }
    }
    if (c.side(h, node[ptr]) <= 0) {  // no vertex outside: clip() would leave the cycle as it is
      c.drop_last();
      continue;
    }
    // The arc outside h: back to a, the last vertex before it not outside, on to b, the first after.
    std::size_t a = prev[ptr], b = next[ptr], removed = 1;
    int sa = 0, sb = 0;
    while (a != ptr && (sa = c.side(h, node[a])) > 0) a = prev[a], ++removed;
    if (a == ptr) {  // every vertex outside: F is empty
      cycle.clear();
      return {e + 1, false};
    }
    while ((sb = c.side(h, node[b])) > 0) b = next[b], ++removed;  // stops at a at the latest
    const std::size_t t = prev[b], edge_a = node[a].out, edge_t = node[t].out;
    // The arc's nodes are free for the crossing vertices (as a list through `next`).
    next[t] = free_list, free_list = next[a];
    live -= removed;
    // As clip() does: leaving h's half-plane from a point on h, the boundary follows h; a strict
    // crossing out of it continues along h, one back into it along the crossed edge.
    std::size_t last = a;
    if (sa == 0) node[a].out = h;
    auto append = [&](const Vertex& v) {
      const std::size_t i = allocate(v);
      link(last, i);
      last = i;
      ++live;
    };
    if (sa < 0) append(c.vertex(edge_a, h, h));
    ptr = last;  // its outgoing edge lies on h: extreme for h
    if (sb < 0) append(c.vertex(edge_t, h, edge_t));
    link(last, b);
    if (live < 3) return finish(e + 1, false);  // a segment or a point: clip() from here
  }
  return finish(count, true);
}


// Drop repeated and collinear vertices. Repeats: v equals w iff v lies on both lines meeting in
// w. Collinear: consecutive p, q, r with p != q are collinear iff r lies on the line carrying the
// edge p → q (p.out), so a repeat hands its outgoing line to the vertex it merges into.
std::vector<Vertex> reduced(PolygonClipper& c, const std::vector<Vertex>& cycle);

}  // namespace gmcc::internal
