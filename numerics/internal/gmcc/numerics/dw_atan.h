#pragma once
/// \file dw_atan.h
/// The arctangent of a double-word enclosure (dw_enclosure.h), with a rigorous bound computed at
/// run time: what the 3-D mean's double-word stage needs for each edge's angle θ_i (docs/math.md
/// "The double-word stage").
///
/// Method and proof. atan2(y, x) for x > 0 is atan(y/x); atan is odd, and atan(t) = π/2 −
/// atan(1/t) for t > 0, so it suffices to enclose atan(n/d) for enclosures n, d > 0 with n/d about
/// in [0, 1]. With c = k/128 the nearest multiple of 1/128 to n/d,
///     atan(n/d) = atan(c) + atan(ρ),   ρ = (n − c·d)/(d + c·n),   |ρ| <= |n/d − c| <= 2^-8
/// (the addition formula, valid since d + c·n > 0) [Muller2016Elementary, §6.2]. ρ is formed in
/// DWEnclosure arithmetic from the enclosures of n and d, so it covers every point of them. atan(ρ) is its
/// Taylor series ρ − ρ³/3 + ρ⁵/5 − …, alternating with terms decreasing in size for |ρ| < 1, so
/// stopping after the ρ¹³/13 term errs by at most the next term, |ρ|¹⁵/15 < 2^-120
/// [Abramowitz1964Handbook, 4.4.42]. The series is evaluated by Horner's rule, its tail
/// 1/7 − ρ²/9 + ρ⁴/11 − ρ⁶/13 (which enters multiplied by ρ⁶ <= 2^-48) in double midpoint–radius
/// enclosures (enclosure.h, [Rump1999]) and the rest in DWEnclosure arithmetic; every operation
/// bounds its own rounding error, and the truncation bound is added to the radius. The constants atan(k/128), 1/(2j + 1) and π/2 are double-word numbers
/// (hi, lo) = (RN(v), RN(v − hi)) printed by scripts/dw_atan_constants.cpp from MPFR at 400 bits:
/// each is within u·|v − hi| <= u²·|v| < 2^-105·|hi| of v, and is charged 2^-104·|hi|;
/// tests/numerics/test_double_word.cpp checks every one against MPFR.

#include <gmcc/numerics/dw_enclosure.h>
#include <gmcc/numerics/enclosure.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace gmcc::numerics {

namespace dw_atan_detail {
/// atan(k/128), k = 0..128, as double-word numbers (hi, lo).
inline constexpr std::array<DoubleWord, 129> atan_table{{
    {0x0p+0, 0x0p+0},
    {0x1.fffd555bbba97p-8, 0x1.68062351fbbe6p-63},
    {0x1.fff555bbb729bp-7, -0x1.220c39d4dff5p-61},
    {0x1.7fee0184a5c36p-6, -0x1.43189fc0a354bp-60},
    {0x1.ffd55bba97625p-6, -0x1.5ec431444912cp-60},
    {0x1.3fd65f169c9d9p-5, 0x1.7230a716461b5p-61},
    {0x1.7fb818430da2ap-5, -0x1.86ef8f794f105p-63},
    {0x1.bf8ddf139c444p-5, -0x1.89fe34b2a7fa8p-59},
    {0x1.ff55bb72cfdeap-5, -0x1.c934d86d23f1dp-60},
    {0x1.1f86dbf082d59p-4, -0x1.095dc7732ef81p-59},
    {0x1.3f59f0e7c559dp-4, 0x1.ac4ce285df847p-58},
    {0x1.5f2324fd2d7b2p-4, 0x1.8a8da4401318ep-58},
    {0x1.7ee182602f10fp-4, -0x1.cfb654c0c3d98p-58},
    {0x1.9e94153cfdcf1p-4, 0x1.a332e1d69c47ep-58},
    {0x1.be39ebe6f07c3p-4, 0x1.f7b8f29a05987p-58},
    {0x1.ddd21701eba6ep-4, 0x1.94effcd76fe58p-58},
    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
    {0x1.0e6adccf40882p-3, -0x1.d71a31bb98d0dp-57},
    {0x1.1e1fafb043727p-3, -0x1.b485914dacf8cp-59},
    {0x1.2dcbdb2fba1ffp-3, 0x1.8f28705561534p-58},
    {0x1.3d6eee8c6626cp-3, 0x1.61a3b0ce9281bp-57},
    {0x1.4d087a9da4f17p-3, 0x1.1f323f1adf158p-57},
    {0x1.5c9811e3ec26ap-3, -0x1.054ab2c010f3dp-58},
    {0x1.6c1d4898933d9p-3, -0x1.2954a7603c427p-58},
    {0x1.7b97b4bce5b02p-3, 0x1.347b0b4f881cap-58},
    {0x1.8b06ee2879c29p-3, -0x1.118cd30308c4fp-57},
    {0x1.9a6a8e96c8626p-3, 0x1.cf601e7b4348ep-59},
    {0x1.a9c231b403279p-3, 0x1.0e8bbe89cca85p-57},
    {0x1.b90d7529260a2p-3, 0x1.17b10d2e0e5abp-61},
    {0x1.c84bf8a742e6ep-3, -0x1.95bdd0682ea26p-58},
    {0x1.d77d5df205736p-3, 0x1.c648d1534597ep-57},
    {0x1.e6a148e96ec4dp-3, 0x1.866b22029f765p-57},
    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0x1.025fa510665b6p-2, -0x1.672df6832fa48p-56},
    {0x1.09dc597d86362p-2, 0x1.62e47390cb865p-56},
    {0x1.1151a362431cap-2, -0x1.4dc8dc9077b9fp-56},
    {0x1.18bf5a30bf178p-2, 0x1.30ca4748b1bf9p-57},
    {0x1.2025567e47c96p-2, -0x1.1832328f4290ep-57},
    {0x1.278372057ef46p-2, -0x1.077cdd36dfc81p-56},
    {0x1.2ed987a823cfep-2, 0x1.b91258ea012cap-57},
    {0x1.362773707ebccp-2, -0x1.963a544b672d8p-57},
    {0x1.3d6d129271134p-2, 0x1.137ca41cc958ap-56},
    {0x1.44aa436c2af0ap-2, -0x1.5d5e43c55b3bap-56},
    {0x1.4bdee586890e7p-2, -0x1.e4dc77c22a757p-57},
    {0x1.530ad9951cd4ap-2, -0x1.2566480884082p-57},
    {0x1.5a2e0175e0f4ep-2, 0x1.13b7a8f82e457p-56},
    {0x1.614840309cfe2p-2, -0x1.a725715711fp-56},
    {0x1.685979f5fa6fep-2, -0x1.257814d1ada9cp-59},
    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
    {0x1.7660752817502p-2, -0x1.dd11791cc76p-59},
    {0x1.7d5604b63b3f7p-2, 0x1.69c885c2b249ap-56},
    {0x1.84422b8df95d7p-2, 0x1.d76a0299b41b6p-56},
    {0x1.8b24d394a1b25p-2, 0x1.b6d0ba3748fa8p-56},
    {0x1.91fde7cd0c662p-2, 0x1.1074188054b53p-56},
    {0x1.98cd5454d6b18p-2, 0x1.9e6c988fd0a77p-56},
    {0x1.9f93066168002p-2, -0x1.c827047c9439ap-56},
    {0x1.a64eec3cc23fdp-2, -0x1.24dec1b50b7ffp-56},
    {0x1.ad00f5422058bp-2, 0x1.fc4c33891d2e8p-56},
    {0x1.b3a911da65c6cp-2, 0x1.ae187b1ca504p-56},
    {0x1.ba473378624a5p-2, 0x1.519a1b46e4affp-56},
    {0x1.c0db4c94ec9fp-2, -0x1.cc1ce70934c34p-56},
    {0x1.c76550aad71f9p-2, -0x1.74b8bff7043e4p-56},
    {0x1.cde53432c1351p-2, -0x1.a2cfa4418f1adp-56},
    {0x1.d45aec9ec862bp-2, 0x1.89421163ef92dp-57},
    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0x1.e127b6b0744bp-2, -0x1.2b0986398d4abp-58},
    {0x1.e77eb7f175a34p-2, 0x1.0e53dc1bf3435p-56},
    {0x1.edcb6d43f8435p-2, -0x1.fc976330884e4p-58},
    {0x1.f40dd0b541418p-2, -0x1.a3992dc382a23p-57},
    {0x1.fa45dd3029259p-2, -0x1.ca563dc28d8b5p-56},
    {0x1.0039c73c1a40cp-1, -0x1.b32c949c9d593p-55},
    {0x1.034b709250488p-1, 0x1.8f9b38d85541p-56},
    {0x1.0657e94db30dp-1, -0x1.d5b495f6349e6p-56},
    {0x1.095f30861a59p-1, -0x1.121b20a15a9f3p-56},
    {0x1.0c6145b5b43dap-1, 0x1.974fa13b5404fp-58},
    {0x1.0f5e28b67e295p-1, 0x1.311b17ec990dp-65},
    {0x1.1255d9bfbd2a9p-1, -0x1.2bdaee1c0ee35p-58},
    {0x1.154859637646ap-1, -0x1.4ba7c548bf3c3p-55},
    {0x1.1835a88be7c13p-1, 0x1.c621cec00c301p-55},
    {0x1.1b1dc87904285p-1, -0x1.21e8c8aef8f29p-57},
    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
    {0x1.20de813e823b2p-1, -0x1.791d753ebb744p-55},
    {0x1.23b71e2cc9e6ap-1, 0x1.c421c9f38224ep-57},
    {0x1.268a940696da6p-1, 0x1.d1348a04c73ccp-58},
    {0x1.2958e59308e31p-1, -0x1.09e73b0c6c087p-56},
    {0x1.2c2215e024466p-1, -0x1.4b810da3a4be1p-59},
    {0x1.2ee628406cbcap-1, 0x1.c5d5e9ff0cf8dp-55},
    {0x1.31a52048874bep-1, 0x1.40cab87a7ac24p-55},
    {0x1.345f01cce37bbp-1, 0x1.1021137c71102p-55},
    {0x1.3713d0df6c504p-1, -0x1.4f789e031606dp-58},
    {0x1.39c391cd4171ap-1, -0x1.2304331d8bf46p-55},
    {0x1.3c6e491c78dc5p-1, -0x1.e145094fd0ba7p-55},
    {0x1.3f13fb89e96f4p-1, 0x1.ecf8b492644fp-56},
    {0x1.41b4ae06fea41p-1, 0x1.3d60a53277652p-57},
    {0x1.445065b795b56p-1, -0x1.f76d0163f79c8p-56},
    {0x1.46e727efe4716p-1, -0x1.39b9b1b844cc9p-57},
    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {0x1.4c05e22de94e5p-1, -0x1.c0ac1f09f2edfp-55},
    {0x1.4e8de5bb6ec04p-1, 0x1.4a33dbeb3796cp-55},
    {0x1.51110adc5ed81p-1, 0x1.23dcd6832a63ep-56},
    {0x1.538f57b89061fp-1, -0x1.1bb74abda520cp-55},
    {0x1.5608d29c70c34p-1, 0x1.9939cf0de8088p-55},
    {0x1.587d81f732fbbp-1, -0x1.5e5c9d8c5a95p-56},
    {0x1.5aed6c5909517p-1, 0x1.7312f714a9436p-55},
    {0x1.5d58987169b18p-1, 0x1.0028e4bc5e7cap-57},
    {0x1.5fbf0d0d5cc4ap-1, -0x1.b4cfd000b7158p-58},
    {0x1.6220d115d7b8ep-1, -0x1.2b785350ee8c1p-57},
    {0x1.647deb8e20b9p-1, -0x1.eca04023a51cfp-58},
    {0x1.66d663923e087p-1, -0x1.6ea6febe8bbbap-56},
    {0x1.692a40556fb6ap-1, 0x1.d94b95a8ea2ccp-55},
    {0x1.6b798920b3d99p-1, -0x1.a80386188c50ep-55},
    {0x1.6dc44551553afp-1, -0x1.bf8863573828ep-58},
    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
    {0x1.724c35b4fae7bp-1, 0x1.948b32db3499bp-58},
    {0x1.748978fba8e0fp-1, 0x1.7b2a6165884a1p-59},
    {0x1.76c24dcc6c6cp-1, 0x1.1952551adc83dp-55},
    {0x1.78f6bbd5d315ep-1, 0x1.406a08980374p-55},
    {0x1.7b26cad2e50fep-1, -0x1.ce80df30411fbp-55},
    {0x1.7d528289fa093p-1, 0x1.560821e2f3aa9p-55},
    {0x1.7f79eacb97898p-1, 0x1.fd5ca80ead221p-55},
    {0x1.819d0b7158a4dp-1, -0x1.bf76229d3b917p-56},
    {0x1.83bbec5cdee22p-1, 0x1.3107104ffc6c3p-57},
    {0x1.85d69576cc2c5p-1, 0x1.6b66e7fc8b8c3p-57},
    {0x1.87ed0eadc5a2ap-1, 0x1.0af5ad957f4bcp-56},
    {0x1.89ff5ff57f1f8p-1, -0x1.55b9a5e177a1bp-55},
    {0x1.8c0d9145cf49dp-1, 0x1.bea4076dc4333p-55},
    {0x1.8e17aa99cc05ep-1, -0x1.ec182ab042f61p-56},
    {0x1.901db3eeef187p-1, 0x1.68665e5603c8fp-55},
    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
}};

/// 1/3, 1/5, …, 1/13: the Taylor coefficients of atan after the first.
inline constexpr std::array<DoubleWord, 6> odd_reciprocals{{
    {0x1.5555555555555p-2, 0x1.5555555555555p-56},  // 1/3
    {0x1.999999999999ap-3, -0x1.999999999999ap-57},  // 1/5
    {0x1.2492492492492p-3, 0x1.2492492492492p-57},  // 1/7
    {0x1.c71c71c71c71cp-4, 0x1.c71c71c71c71cp-58},  // 1/9
    {0x1.745d1745d1746p-4, -0x1.745d1745d1746p-59},  // 1/11
    {0x1.3b13b13b13b14p-4, -0x1.3b13b13b13b14p-58},  // 1/13
}};

/// π/2.
inline constexpr DoubleWord half_pi{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};

/// A tabulated constant as an enclosure: radius 2^-104·|hi| (see the file comment).
inline DWEnclosure constant(const DoubleWord& v) { return {v, std::fabs(v.hi) * 0x1p-104}; }

/// atan(n/d) for enclosures n, d with d > 0 and n/d about in [0, 1]: with c = k/128 nearest
/// n/d, atan(n/d) = atan(c) + atan(ρ), ρ = (n − c·d)/(d + c·n), valid where d + c·n > 0 (checked:
/// certainly nonzero, positive midpoint); the table and the series. Unbounded when |ρ| may
/// exceed 2^-8 (barely: k is chosen from the leading doubles).
inline DWEnclosure atan_reduced(const DWEnclosure& n, const DWEnclosure& d) {
  const double scaled = std::clamp(n.mid.hi / d.mid.hi * 128, 0.0, 128.0);
  const int k = static_cast<int>(scaled + 0.5);
  const double c = k / 128.0;  // exact: k/128 is a dyadic double
  const DWEnclosure den = d + n * c;
  if (!(den.mid.hi > 0)) return DWEnclosure::unbounded();
  const DWEnclosure rho = (n - d * c) / den;
  const double bound = rho.magnitude() + rho.rad;  // |ρ| <= bound·(1 + u)
  if (!rho.finite() || !(bound <= 0x1.02p-8)) return DWEnclosure::unbounded();
  const DWEnclosure rho2 = sqr(rho);
  // The tail 1/7 − ρ²/9 + ρ⁴/11 − ρ⁶/13 enters multiplied by ρ⁶ <= 2^-48: in double enclosures
  // (BasicEnclosure, enclosure.h) its relative error of about 2^-50 costs 2^-98 of atan(ρ)/ρ.
  using D = BasicEnclosure<double>;
  const D r2{rho2.mid.hi, D::round_up(std::fabs(rho2.mid.lo) + rho2.rad)};
  D q = D::relative(1.0 / 13, 0x1p-53);  // 1/(2j + 1) rounded to nearest: within u of it
  for (const double k : {1.0 / 11, 1.0 / 9, 1.0 / 7}) q = D::relative(k, 0x1p-53) - r2 * q;
  DWEnclosure p = DWEnclosure{{q.mid, 0}, q.rad};
  for (int j = 2; j >= 1; --j) p = constant(odd_reciprocals[static_cast<std::size_t>(j - 1)]) - rho2 * p;
  p = rho * (-(rho2 * p) + 1.0);
  const double b2 = bound * bound, b4 = b2 * b2, b8 = b4 * b4;
  const double truncation = b8 * b4 * b2 * bound;  // |ρ|^15 >= |ρ|^15/15
  const DWEnclosure head = constant(atan_table[static_cast<std::size_t>(k)]);
  return head + DWEnclosure{p.mid, DWEnclosure::round_up(p.rad + truncation)};
}
}  // namespace dw_atan_detail

/// atan2(y, x) = atan(y/x) for every (x, y) in the enclosures, x certainly positive (unbounded
/// otherwise): the angle of (x, y) in (−π/2, π/2) ([Muller2016Elementary], §6.2; the proof is the
/// file comment). For |y| <= x about, atan_reduced(|y|, x); beyond, π/2 − atan_reduced(x, |y|),
/// with y certainly nonzero; the sign of y's midpoint restored (atan is odd).
inline DWEnclosure atan2(const DWEnclosure& y, const DWEnclosure& x) {
  if (!certainly_positive(x) || !y.finite()) return DWEnclosure::unbounded();
  const bool negative = y.mid.hi < 0;
  const DWEnclosure ay = negative ? -y : y;
  DWEnclosure a;
  if (ay.mid.hi > x.mid.hi) {
    if (!certainly_positive(ay)) return DWEnclosure::unbounded();
    a = dw_atan_detail::constant(dw_atan_detail::half_pi) - dw_atan_detail::atan_reduced(x, ay);
  } else {
    a = dw_atan_detail::atan_reduced(ay, x);
  }
  return negative ? -a : a;
}

/// atan(x) for every x in the enclosure: atan2(x, 1).
inline DWEnclosure atan(const DWEnclosure& x) { return atan2(x, DWEnclosure::exact(1.0)); }

}  // namespace gmcc::numerics
