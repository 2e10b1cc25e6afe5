// An exact 3-D convex set whose vertices are made exact on request (lazy_convex_set_3.h).
#include <gmcc/geometry/lazy_convex_set_3.h>

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/internal_check.h>
#include <gmcc/numerics/rational_to_float.h>
#include <gmcc/numerics/truncated_quotient.h>

#include "internal/facet_filter.h"
#include "internal/homogeneous_plane.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <optional>

namespace gmcc {

struct LazyConvexSet3::State {
  ConvexKind3 kind = ConvexKind3::empty;
  std::vector<std::vector<std::size_t>> faces;
  std::vector<Enclosure3> enclosures;
  std::vector<std::array<mpz_class, 4>> homogeneous;  // (X, Y, Z, W), W > 0 (W = 0: not made yet)
  std::vector<std::optional<Point3>> exact;           // made so far
  std::vector<char> zero;
  std::size_t made = 0;
  HomogeneousMaker make;  // vertex i's homogeneous coordinates, when not given (from_truncated)
};

namespace {

// x/w (w > 0) as enclose_rational(x/w) would give it from the reduced fraction, without reducing:
// mpq_get_d truncates the quotient whatever the representation, and the range policy's
// magnitude e = bits(|x|) − bits(w) is within 1 of the reduced one's (both bracket log2 |x/w|:
// 2^(e−1) < |x/w| < 2^(e+1)), so |e| <= limit − 1 is in range and |e| >= limit + 2 is out either
// way; between, the fraction is reduced and the policy applied to it. `truncated` gets the
// truncated double (nothing when outside the range).
Enclosure enclose_quotient(const mpz_class& x, const mpz_class& w, std::optional<double>& truncated) {
  if (sgn(x) == 0) {
    truncated = 0.0;
    return Enclosure::exact(0);
  }
  const long e = std::labs(numerics::binary_magnitude(x.get_mpz_t(), w.get_mpz_t()));
  const long limit = numerics::double_magnitude_limit;
  if (e <= limit - 1) {
    truncated = numerics::truncated_double(x.get_mpz_t(), w.get_mpz_t());
  } else if (e >= limit + 2) {
    truncated = std::nullopt;
  } else {
    Rational r(x, w);
    r.canonicalize();
    truncated = numerics::certified_double(r.get_mpq_t());
  }
  if (!truncated) return {0, Enclosure::unbounded};
  return Enclosure::relative(*truncated, 2 * Enclosure::u);
}

// sign(a_k/a_3 − b_k/b_3) for homogeneous points with positive last coordinates, exactly.
int compare_exactly(const std::array<mpz_class, 4>& a, const std::array<mpz_class, 4>& b, int k) {
  const auto i = static_cast<std::size_t>(k);
  return sgn(mpz_class(a[i] * b[3]) - mpz_class(b[i] * a[3]));
}

// Makes W positive (negating the four coordinates: the same point).
void positive_weight(std::array<mpz_class, 4>& h) {
  GMCC_CHECK(sgn(h[3]) != 0, "LazyConvexSet3: a homogeneous vertex has W = 0");
  if (sgn(h[3]) < 0)
    for (mpz_class& c : h) c = -c;
}

// The canonical order of n vertices: lexicographic, comparing truncated doubles where both are
// known and different (truncation is monotone), taking two known zeros as equal (a non-zero
// coordinate's truncation is non-zero: within the range policy's 2^±138) and otherwise comparing
// exactly, by cross-multiplication of the homogeneous coordinates `exact(i)` gives.
template <class Exact>
std::vector<std::size_t> canonical_order(const std::vector<std::array<std::optional<double>, 3>>& key, Exact exact) {
  std::vector<std::size_t> order(key.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    for (int k = 0; k < 3; ++k) {
      const auto& x = key[a][static_cast<std::size_t>(k)];
      const auto& y = key[b][static_cast<std::size_t>(k)];
      if (x && y && *x != *y) return *x < *y;
      if (x && y && *x == 0) continue;  // both exactly 0
      if (const int c = compare_exactly(exact(a), exact(b), k)) return c < 0;
    }
    return false;
  });
  return order;
}

}  // namespace

LazyConvexSet3::LazyConvexSet3() : state_(std::make_shared<State>()) {}

LazyConvexSet3::LazyConvexSet3(ConvexSet3 exact) : state_(std::make_shared<State>()) {
  State& s = *state_;
  s.kind = exact.kind;
  s.faces = std::move(exact.faces);
  for (Point3& p : exact.vertices) {
    s.enclosures.push_back(enclose_point(p));
    s.zero.push_back(sgn(p.x) == 0 && sgn(p.y) == 0 && sgn(p.z) == 0);
    s.exact.emplace_back(std::move(p));
  }
  s.made = s.exact.size();
}

LazyConvexSet3 LazyConvexSet3::from_homogeneous(ConvexKind3 kind, std::vector<std::array<mpz_class, 4>> h,
                                                std::vector<std::vector<std::size_t>> faces) {
  const std::size_t n = h.size();
  std::vector<Enclosure3> enclosures(n);
  std::vector<std::array<std::optional<double>, 3>> key(n);
  std::vector<char> zero(n);
  for (std::size_t i = 0; i < n; ++i) {
    positive_weight(h[i]);
    for (std::size_t k = 0; k < 3; ++k) enclosures[i][k] = enclose_quotient(h[i][k], h[i][3], key[i][k]);
    zero[i] = sgn(h[i][0]) == 0 && sgn(h[i][1]) == 0 && sgn(h[i][2]) == 0;
  }
  const std::vector<std::size_t> order = canonical_order(key, [&](std::size_t i) -> const auto& { return h[i]; });
  return ordered(kind, order, std::move(h), enclosures, zero, std::move(faces), nullptr);
}

LazyConvexSet3 LazyConvexSet3::from_truncated(ConvexKind3 kind, std::vector<TruncatedVertex> vertices,
                                              std::vector<std::vector<std::size_t>> faces, HomogeneousMaker make) {
  const std::size_t n = vertices.size();
  std::vector<Enclosure3> enclosures(n);
  std::vector<std::array<std::optional<double>, 3>> key(n);
  std::vector<char> zero(n);
  std::vector<std::array<mpz_class, 4>> h(n);  // W = 0: not made
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const double t = vertices[i].truncated[k];
      key[i][k] = t;
      // enclose_quotient's enclosure of the exact coordinate: 0 exactly, else t ± 2u relative.
      enclosures[i][k] = t == 0 ? Enclosure::exact(0) : Enclosure::relative(t, 2 * Enclosure::u);
    }
    zero[i] = vertices[i].zero;
  }
  const std::vector<std::size_t> order =
      canonical_order(key, [&](std::size_t i) -> const std::array<mpz_class, 4>& {
        if (sgn(h[i][3]) == 0) positive_weight(h[i] = make(i));
        return h[i];
      });
  HomogeneousMaker canonical = [make = std::move(make), order](std::size_t i) { return make(order[i]); };
  return ordered(kind, order, std::move(h), enclosures, zero, std::move(faces), std::move(canonical));
}

// The set with its vertices in `order` (order[i]: the given index of canonical vertex i).
LazyConvexSet3 LazyConvexSet3::ordered(ConvexKind3 kind, const std::vector<std::size_t>& order,
                                       std::vector<std::array<mpz_class, 4>> h, const std::vector<Enclosure3>& enclosures,
                                       const std::vector<char>& zero, std::vector<std::vector<std::size_t>> faces,
                                       HomogeneousMaker make) {
  const std::size_t n = order.size();
  LazyConvexSet3 out;
  State& s = *out.state_;
  s.kind = kind;
  std::vector<std::size_t> rank(n);
  s.enclosures.reserve(n), s.zero.reserve(n), s.homogeneous.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    rank[order[i]] = i;
    s.enclosures.push_back(enclosures[order[i]]);
    s.zero.push_back(zero[order[i]]);
    s.homogeneous.push_back(std::move(h[order[i]]));
  }
  s.exact.resize(n);
  s.make = std::move(make);
  s.faces = internal::canonical_faces(kind, std::move(faces), rank);
  return out;
}

ConvexKind3 LazyConvexSet3::kind() const { return state_->kind; }
std::size_t LazyConvexSet3::size() const { return state_->enclosures.size(); }
const std::vector<std::vector<std::size_t>>& LazyConvexSet3::faces() const { return state_->faces; }
const std::vector<Enclosure3>& LazyConvexSet3::enclosures() const { return state_->enclosures; }
bool LazyConvexSet3::is_zero(std::size_t i) const { return state_->zero[i] != 0; }
std::size_t LazyConvexSet3::exact_vertices() const { return state_->made; }

const std::array<mpz_class, 4>& LazyConvexSet3::homogeneous(std::size_t i) const {
  State& s = *state_;
  if (s.homogeneous.size() < s.exact.size()) s.homogeneous.resize(s.exact.size());  // built exact
  std::array<mpz_class, 4>& h = s.homogeneous[i];
  if (sgn(h[3]) == 0) {
    if (s.exact[i]) h = homogeneous_integers(*s.exact[i]);
    else positive_weight(h = s.make(i));
  }
  return h;
}

const Point3& LazyConvexSet3::vertex(std::size_t i) const {
  State& s = *state_;
  std::optional<Point3>& v = s.exact[i];
  if (!v) {
    const std::array<mpz_class, 4>& h = homogeneous(i);
    Point3 p{Rational(h[0], h[3]), Rational(h[1], h[3]), Rational(h[2], h[3])};
    p.x.canonicalize(), p.y.canonicalize(), p.z.canonicalize();
    v = std::move(p);
    ++s.made;
  }
  return *v;
}

std::pair<std::array<mpz_class, 3>, mpz_class> LazyConvexSet3::facet_plane(std::size_t k) const {
  const std::vector<std::size_t>& f = state_->faces[k];
  return internal::plane_through(homogeneous(f[0]), homogeneous(f[1]), homogeneous(f[2]));
}

ConvexSet3 LazyConvexSet3::exact() const {
  ConvexSet3 out;
  out.kind = state_->kind;
  out.faces = state_->faces;
  for (std::size_t i = 0; i < size(); ++i) out.vertices.push_back(vertex(i));
  return out;
}

bool contains(const LazyConvexSet3& s, const Point3& p) {
  if (s.kind() != ConvexKind3::polytope) return contains(s.exact(), p);
  const std::optional<std::vector<std::size_t>> unsure = internal::facets_left_by_filter(s.enclosures(), s.faces(), p);
  if (!unsure) return false;
  // p = (P_0/Q_0, P_1/Q_1, P_2/Q_2), Q_k > 0: n·p − c has the sign of
  // Σ n_k P_k Π_{j≠k} Q_j − c Π_j Q_j.
  const mpz_class &q0 = p.x.get_den(), &q1 = p.y.get_den(), &q2 = p.z.get_den();
  const mpz_class q01 = q0 * q1, q02 = q0 * q2, q12 = q1 * q2, q012 = q01 * q2;
  const mpz_class w[3] = {p.x.get_num() * q12, p.y.get_num() * q02, p.z.get_num() * q01};
  mpz_class side;
  for (std::size_t k : *unsure) {
    const auto [n, c] = s.facet_plane(k);  // outward
    mpz_mul(side.get_mpz_t(), c.get_mpz_t(), q012.get_mpz_t());
    mpz_neg(side.get_mpz_t(), side.get_mpz_t());
    for (std::size_t j = 0; j < 3; ++j) mpz_addmul(side.get_mpz_t(), n[j].get_mpz_t(), w[j].get_mpz_t());
    if (sgn(side) > 0) return false;
  }
  return true;
}

}  // namespace gmcc
