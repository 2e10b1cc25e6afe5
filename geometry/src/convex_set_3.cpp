#include <gmcc/geometry/convex_set_3.h>

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/geometry/polytope_moments.h>

#include "internal/facet_filter.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace gmcc {
namespace {
// The vertices as coordinate arrays, for polytope_moments.
std::vector<std::array<Rational, 3>> rational_points(const ConvexSet3& s) {
  std::vector<std::array<Rational, 3>> out;
  out.reserve(s.vertices.size());
  for (const Point3& p : s.vertices) out.push_back({p.x, p.y, p.z});
  return out;
}

}  // namespace

std::string to_string(ConvexKind3 kind) {
  switch (kind) {
    case ConvexKind3::polytope: return "polytope";
    case ConvexKind3::polygon: return "polygon";
    case ConvexKind3::segment: return "segment";
    case ConvexKind3::point: return "point";
    case ConvexKind3::empty: return "empty";
  }
  return "empty";
}

namespace internal {
std::vector<std::vector<std::size_t>> canonical_faces(ConvexKind3 kind, std::vector<std::vector<std::size_t>> faces,
                                                      const std::vector<std::size_t>& rank) {
  if (kind != ConvexKind3::polytope && kind != ConvexKind3::polygon) return {};
  for (auto& f : faces) {
    for (std::size_t& i : f) i = rank[i];
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    if (kind == ConvexKind3::polygon && f.size() > 2 && f.back() < f[1])
      std::reverse(f.begin() + 1, f.end());
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}
}  // namespace internal

ConvexSet3 canonical_convex_set_3(ConvexKind3 kind, std::vector<Point3> vertices,
                                  std::vector<std::vector<std::size_t>> faces) {
  std::vector<std::size_t> order(vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return vertices[a] < vertices[b]; });
  std::vector<std::size_t> rank(vertices.size());
  ConvexSet3 out;
  out.kind = kind;
  for (std::size_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = i;
    out.vertices.push_back(vertices[order[i]]);
  }
  out.faces = internal::canonical_faces(kind, std::move(faces), rank);
  return out;
}

Rational volume(const ConvexSet3& s) {
  if (s.kind != ConvexKind3::polytope) return 0;
  return Rational(polytope_moments(rational_points(s), s.faces, false).six_volume / 6);
}

Point3 centroid(const ConvexSet3& s) {
  const auto& v = s.vertices;
  switch (s.kind) {
    case ConvexKind3::empty: throw std::invalid_argument("centroid of an empty set");
    case ConvexKind3::point: return v[0];
    case ConvexKind3::segment:
      return {Rational((v[0].x + v[1].x) / 2), Rational((v[0].y + v[1].y) / 2),
              Rational((v[0].z + v[1].z) / 2)};
    case ConvexKind3::polygon: {
      const auto& f = s.faces[0];
      const Point3 n = cross(sub(v[f[1]], v[f[0]]), sub(v[f[2]], v[f[0]]));
      // Project on the coordinate plane where the normal is largest: areas scale by one factor.
      const int k = abs(n.x) >= abs(n.y) && abs(n.x) >= abs(n.z) ? 0 : abs(n.y) >= abs(n.z) ? 1 : 2;
      const Point3 axis{k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0};
      Rational w_sum = 0;
      Point3 acc{0, 0, 0};
      for (std::size_t i = 1; i + 1 < f.size(); ++i) {
        const Rational w = dot(cross(sub(v[f[i]], v[f[0]]), sub(v[f[i + 1]], v[f[0]])), axis);
        w_sum += w;
        acc = {Rational(acc.x + w * (v[f[0]].x + v[f[i]].x + v[f[i + 1]].x)),
               Rational(acc.y + w * (v[f[0]].y + v[f[i]].y + v[f[i + 1]].y)),
               Rational(acc.z + w * (v[f[0]].z + v[f[i]].z + v[f[i + 1]].z))};
      }
      return {Rational(acc.x / (3 * w_sum)), Rational(acc.y / (3 * w_sum)), Rational(acc.z / (3 * w_sum))};
    }
    case ConvexKind3::polytope: break;
  }
  const PolytopeMoments<Rational> m = polytope_moments(rational_points(s), s.faces, true);
  const Rational four_w = 4 * m.six_volume;
  return {Rational(m.weighted[0] / four_w), Rational(m.weighted[1] / four_w), Rational(m.weighted[2] / four_w)};
}

bool contains(const ConvexSet3& s, const Point3& p) {
  const auto& v = s.vertices;
  switch (s.kind) {
    case ConvexKind3::empty: return false;
    case ConvexKind3::point: return v[0] == p;
    case ConvexKind3::segment: {
      const Point3 u = sub(v[1], v[0]), w = sub(p, v[0]);
      const Point3 c = cross(u, w);
      if (sgn(c.x) != 0 || sgn(c.y) != 0 || sgn(c.z) != 0) return false;
      const Rational t = dot(u, w);
      return sgn(t) >= 0 && t <= dot(u, u);
    }
    case ConvexKind3::polygon: {
      const auto& f = s.faces[0];
      const Point3 n = cross(sub(v[f[1]], v[f[0]]), sub(v[f[2]], v[f[0]]));
      if (sgn(dot(n, sub(p, v[f[0]]))) != 0) return false;
      // Inside iff p is on the inner side of every edge, within the plane: (e × (p − a))·n >= 0.
      for (std::size_t i = 0; i < f.size(); ++i) {
        const Point3& a = v[f[i]];
        const Point3& b = v[f[(i + 1) % f.size()]];
        if (sgn(dot(cross(sub(b, a), sub(p, a)), n)) < 0) return false;
      }
      return true;
    }
    case ConvexKind3::polytope: {
      std::vector<Enclosure3> e;
      e.reserve(s.vertices.size());
      for (const Point3& x : s.vertices) e.push_back(enclose_point(x));
      const std::optional<std::vector<std::size_t>> unsure = internal::facets_left_by_filter(e, s.faces, p);
      if (!unsure) return false;
      for (std::size_t k : *unsure) {
        const auto& f = s.faces[k];
        const Point3 n = cross(sub(v[f[1]], v[f[0]]), sub(v[f[2]], v[f[0]]));  // outward
        if (sgn(dot(n, sub(p, v[f[0]]))) > 0) return false;
      }
      return true;
    }
  }
  return false;
}

}  // namespace gmcc
