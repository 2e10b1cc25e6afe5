// The clip's final vertices kept symbolic (internal/plane_meets.h).
#include "internal/plane_meets.h"

#include <gmcc/numerics/dw_integer.h>
#include <gmcc/numerics/dw_rounding.h>

#include <algorithm>
#include <cmath>

namespace gmcc::internal {

std::optional<WidePlane> wide_plane(const IntegerPlane3& p) { return wide_plane({&p.a[0], &p.a[1], &p.a[2], &p.b}); }

std::optional<WidePlane> wide_plane(const std::array<const mpz_class*, 4>& z) {
  long E = 0;
  for (const mpz_class* c : z) E = std::max(E, static_cast<long>(mpz_sizeinbase(c->get_mpz_t(), 2)));
  WidePlane out;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::optional<numerics::DWEnclosure> x = numerics::dw_integer(z[k]->get_mpz_t(), E);
    if (!x) return std::nullopt;
    out[k] = *x;
  }
  return out;
}

GMCC_DW_FMA_CLONES std::optional<WidePlane> wide_row(const WidePlane& facet, const WidePlane& point) {
  WidePlane out;
  for (std::size_t k = 0; k < 4; ++k) {
    out[k] = facet[k] * point[k];
    if (!out[k].finite()) return std::nullopt;
  }
  return out;
}

void homogeneous_meet(const IntegerPlane3& p, const IntegerPlane3& q, const IntegerPlane3& r,
                      std::array<std::array<mpz_class, 3>, 3>& c, std::array<mpz_class, 4>& h) {
  // In place (mpz_mul, mpz_addmul, mpz_submul), without a temporary per product.
  auto cross = [](const IntegerPlane3& s, const IntegerPlane3& u, std::array<mpz_class, 3>& out) {
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      mpz_mul(out[k].get_mpz_t(), s.a[i].get_mpz_t(), u.a[j].get_mpz_t());
      mpz_submul(out[k].get_mpz_t(), s.a[j].get_mpz_t(), u.a[i].get_mpz_t());
    }
  };
  cross(q, r, c[0]), cross(r, p, c[1]), cross(p, q, c[2]);
  for (int k = 0; k < 3; ++k) {
    mpz_mul(h[k].get_mpz_t(), p.b.get_mpz_t(), c[0][k].get_mpz_t());
    mpz_addmul(h[k].get_mpz_t(), q.b.get_mpz_t(), c[1][k].get_mpz_t());
    mpz_addmul(h[k].get_mpz_t(), r.b.get_mpz_t(), c[2][k].get_mpz_t());
  }
  mpz_mul(h[3].get_mpz_t(), p.a[0].get_mpz_t(), c[0][0].get_mpz_t());
  mpz_addmul(h[3].get_mpz_t(), p.a[1].get_mpz_t(), c[0][1].get_mpz_t());
  mpz_addmul(h[3].get_mpz_t(), p.a[2].get_mpz_t(), c[0][2].get_mpz_t());
}

GMCC_DW_FMA_CLONES WideCross wide_cross(const WidePlane& s, const WidePlane& u) {
  WideCross out;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    out[k] = s[i] * u[j] - s[j] * u[i];
  }
  return out;
}

WideCross negated(const WideCross& c) { return {-c[0], -c[1], -c[2]}; }

std::optional<LazyConvexSet3::TruncatedVertex> truncated_meet(const WidePlane& p, const WidePlane& q,
                                                              const WidePlane& r, const std::array<bool, 3>& zero_axis) {
  return truncated_meet(p, q, r, wide_cross(q, r), wide_cross(r, p), wide_cross(p, q), zero_axis);
}

// The same Cramer's rule on enclosures (dw_enclosure.h: every operation's enclosure contains the
// exact result of the operation on any points of its operands' enclosures), so each x_k = X_k/W
// is enclosed; its truncation is then decided exactly (truncate_to_double) or not at all.
GMCC_DW_FMA_CLONES std::optional<LazyConvexSet3::TruncatedVertex> truncated_meet(
    const WidePlane& p, const WidePlane& q, const WidePlane& r, const WideCross& c_qr, const WideCross& c_rp,
    const WideCross& c_pq, const std::array<bool, 3>& zero_axis) {
  using numerics::DWEnclosure;
  const DWEnclosure w = p[0] * c_qr[0] + p[1] * c_qr[1] + p[2] * c_qr[2];
  LazyConvexSet3::TruncatedVertex out{{0, 0, 0}, zero_axis[0] && zero_axis[1] && zero_axis[2]};
  for (std::size_t k = 0; k < 3; ++k) {
    if (zero_axis[k]) continue;  // exactly 0
    const DWEnclosure x = (p[3] * c_qr[k] + q[3] * c_rp[k] + r[3] * c_pq[k]) / w;
    const std::optional<double> t = numerics::truncate_to_double(x);
    if (!t || *t == 0 || !(std::fabs(*t) >= 0x1p-136 && std::fabs(*t) <= 0x1p136)) return std::nullopt;
    out.truncated[k] = *t;
  }
  return out;
}

std::array<mpz_class, 4> PlaneMeets::homogeneous(std::size_t i) {
  if (sgn(made[i][3]) != 0) return made[i];
  std::array<mpz_class, 4> h;
  const std::array<int, 3>& t = meets[i];
  homogeneous_meet(plane(static_cast<std::size_t>(t[0])), plane(static_cast<std::size_t>(t[1])),
                   plane(static_cast<std::size_t>(t[2])), scratch, h);
  return h;
}

const IntegerPlane3& PlaneMeets::plane(std::size_t k) {
  IntegerPlane3& p = planes[k];
  Row& r = rows[k];
  if (r.facet) {  // the row (a ⊙ P)·x <= b·L, as the clip makes it
    const IntegerPlane3& a = *r.facet;
    const std::array<mpz_class, 4>& q = points[r.point];
    for (int j = 0; j < 3; ++j) mpz_mul(p.a[j].get_mpz_t(), a.a[j].get_mpz_t(), q[static_cast<std::size_t>(j)].get_mpz_t());
    mpz_mul(p.b.get_mpz_t(), a.b.get_mpz_t(), q[3].get_mpz_t());
    r.facet = nullptr;
  }
  return p;
}

}  // namespace gmcc::internal
