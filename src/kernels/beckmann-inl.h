// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann SIMD kernels, float lanes; the scalar twins are in
// include/brdfbake/models/beckmann.h, slope_ndf.h and brdf.h (BeckmannNdf<T>::D,
// ::Lambda, SampleNdf, Brdf).
//
//   D(m) = exp(-r2) / (pi ax ay m.z^4),  r2 = (m.x^2/ax^2 + m.y^2/ay^2) / m.z^2
//     ([Ribardiere17] eq. 10 and the gamma -> inf limit of eq. 13);
//   Lambda(w) = ierfc(a) / (2 a) = exp(-a^2) h(a) / (2 sqrt(pi) a),
//     a = w.z / sqrt(ax^2 w.x^2 + ay^2 w.y^2) ([Ribardiere17] Table 1, gamma -> inf,
//     rewritten with h of kernels/math-inl.h so that nothing cancels:
//     exp(-a^2)/(a sqrt(pi)) - erfc(a) loses 2 a^2 digits and is never formed).
//
// The BRDF needs four divisions, no square root and three approximate
// reciprocal square roots refined by a Newton step (FMA units):
//   s = wi + wo, L = |s|^2; 1/s.z^2 (division 1) gives r2 of the half vector
//     and D(h) = exp(-r2) L^2 / (pi ax ay s.z^4) (D is homogeneous of degree
//     0 in h: no normalization);
//   per direction a = w.z rsqrt(p), p = ax^2 w.x^2 + ay^2 w.y^2, and the
//     variable s_a = (2 - a)/(2 + a) of h (divisions 2, 3), so that
//     Lambda = N / M with N = exp(-a^2) Q(s_a), M = 2 sqrt(pi) a (1 + 2 a^2);
//   height-correlated G2 = 1 / (1 + N_i/M_i + N_o/M_o)
//     = M_i M_o / (M_i M_o + N_i M_o + N_o M_i), separable
//     G1 G1 = M_i M_o / ((M_i + N_i)(M_o + N_o)): one division (4) for
//     G2 / (4 wi.z wo.z) and D together;
//   wo.h = (wo.s) rsqrt(L), F = F0 + (1 - F0)(1 - wo.h)^5.
// Operation count per lane (AVX2): 4 div, 3 rsqrt + Newton, 3 exp (Highway
// Exp, ~12 FMA each), 2 degree-12 Horner, ~45 other mul/add/FMA.
//
// Error against the double reference at the same float inputs (the bounds
// of kernel_bounds.h, asserted on every target by
// tests/kernels/simd_beckmann_test.cc, which prints the observed maxima):
//   D:      relative 1e-6 + 3e-7 r2 (the exponent r2 is rounded like any
//           float expression of the inputs, 5 ulp at most, and exp
//           multiplies that relative error by r2);
//   Lambda: |err| <= 1e-6 max(1, Lambda) + 3e-7 a^2 Lambda (the a^2 term is
//           the same amplification of the rounding of a);
//   BRDF:   relative 2e-6 + 3.6e-7 r2 (the exponent is formed from
//           s = wi + wo: one ulp more).
// Where exp(-r2) is below FLT_MIN (r2 > 87.3) it is a subnormal, and 0 for
// r2 > 104; the batch functions flush subnormals to zero, so their D and BRDF
// are 0 there (src/kernels/batch.cc).
// a is clamped to 1e4 (Lambda is exactly 0 beyond a = 10.2) so that M_i M_o D
// stays below 1e34.

#if defined(BRDFBAKE_SRC_KERNELS_BECKMANN_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_BECKMANN_INL_H_
#undef BRDFBAKE_SRC_KERNELS_BECKMANN_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_BECKMANN_INL_H_
#endif

#include <cmath>
#include <limits>

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/common-inl.h"
#include "kernels/math-inl.h"
#include "kernels/math_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants of the Beckmann kernels (alpha clamped at 1e-4 as in
// slope_ndf.h), in the lanes' type: the kernels below are generic over the
// descriptor D (float or double lanes).
template <class D>
struct BeckmannConsts {
  using T = hn::TFromD<D>;
  hn::Vec<D> ax, ay, ax2, ay2, inv_ax2, inv_ay2, inv_pi_axay, f0;
  BeckmannConsts(D d, T ax_, T ay_, T f0_) {
    ax_ = ax_ < T(1e-4) ? T(1e-4) : ax_;
    ay_ = ay_ < T(1e-4) ? T(1e-4) : ay_;
    ax = hn::Set(d, ax_);
    ay = hn::Set(d, ay_);
    ax2 = hn::Set(d, ax_ * ax_);
    ay2 = hn::Set(d, ay_ * ay_);
    inv_ax2 = hn::Set(d, static_cast<T>(1.0 / (double(ax_) * ax_)));
    inv_ay2 = hn::Set(d, static_cast<T>(1.0 / (double(ay_) * ay_)));
    inv_pi_axay = hn::Set(d, static_cast<T>(0.31830988618379067 / (double(ax_) * ay_)));
    f0 = hn::Set(d, f0_);
  }
  // Per-element widths and F0, one per lane (WidthLanes).
  BeckmannConsts(D d, hn::Vec<D> ax_, hn::Vec<D> ay_, hn::Vec<D> f0_) {
    const WidthLanes<D> w(d, ax_, ay_);
    ax = w.ax;
    ay = w.ay;
    ax2 = w.ax2;
    ay2 = w.ay2;
    inv_ax2 = w.inv_ax2;
    inv_ay2 = w.inv_ay2;
    inv_pi_axay = w.inv_pi_axay;
    f0 = f0_;
  }
};

// Where exp(-r2) leaves the lanes' range: D and the BRDF are 0 beyond. Float:
// exp(-r2) is flushed to zero for r2 > 104 (and 0 * inf must not leak);
// double: hn::Exp's range ends at -708, and exp(-706) is below the smallest
// normal double.
template <class T>
constexpr T BeckmannMaxR2() {
  return sizeof(T) == 8 ? T(706) : T(104);
}

// RsqrtNewton, CosAtHalf and SchlickFresnel come from kernels/common-inl.h.

template <class D, class V>
HWY_INLINE V BeckmannD(D d, const BeckmannConsts<D>& c, V mx, V my, V mz) {
  const V z2 = hn::Mul(mz, mz);
  using T = hn::TFromD<D>;
  const V iz2 = hn::Div(hn::Set(d, T(1)), z2);
  const V q = hn::MulAdd(hn::Mul(mx, mx), c.inv_ax2, hn::Mul(hn::Mul(my, my), c.inv_ay2));
  const V r2 = hn::Mul(q, iz2);
  const V e = hn::Exp(d, hn::Neg(r2));
  // The exponential last: when it is subnormal nothing else rounds on its scale.
  const V dv = hn::Mul(hn::Mul(hn::Mul(c.inv_pi_axay, iz2), iz2), e);
  const auto valid =
      hn::And(hn::Gt(mz, hn::Zero(d)), hn::Lt(r2, hn::Set(d, BeckmannMaxR2<T>())));
  return hn::IfThenElseZero(valid, dv);
}

// Lambda = N / M for w.z > 0 (see the header comment); a from w.z and
// p = ax^2 w.x^2 + ay^2 w.y^2 (p = 0, normal incidence, gives the clamp a = 1e4).
template <class D, class V>
HWY_INLINE void BeckmannLambdaParts(D d, const BeckmannConsts<D>& c, V wx, V wy, V wz, V* num,
                                    V* den) {
  using T = hn::TFromD<D>;
  const V p = hn::MulAdd(hn::Mul(wx, wx), c.ax2, hn::Mul(hn::Mul(wy, wy), c.ay2));
  const V a = hn::Min(hn::Mul(wz, RsqrtNewton(d, hn::Max(p, hn::Set(d, T(1e-36))))),
                      hn::Set(d, T(1e4)));
  if constexpr (sizeof(T) == 8) {
    // Double lanes: Lambda itself (math_f64-inl.h, 2e-15 of max(1, Lambda)).
    *num = BeckmannLambdaF64(d, a);
    *den = hn::Set(d, T(1));
  } else {
    V q, one_2a2;
    IerfcScaled(d, a, &q, &one_2a2);
    *num = hn::Mul(hn::Exp(d, hn::Neg(hn::Mul(a, a))), q);
    *den = hn::Mul(hn::Mul(hn::Set(d, 3.5449077018110318f), a), one_2a2);  // 2 sqrt(pi)
  }
}

template <class D, class V>
HWY_INLINE V BeckmannLambda(D d, const BeckmannConsts<D>& c, V wx, V wy, V wz) {
  V num, den;
  BeckmannLambdaParts(d, c, wx, wy, wz, &num, &den);
  return hn::IfThenElse(hn::Gt(wz, hn::Zero(d)), hn::Div(num, den),
                        hn::Set(d, std::numeric_limits<hn::TFromD<D>>::infinity()));
}

template <class D, class V, class Fr>
HWY_INLINE V BeckmannBrdf(D d, const BeckmannConsts<D>& c, bool separable, V ix, V iy, V iz, V ox, V oy,
                          V oz, const Fr& fresnel) {
  using T = hn::TFromD<D>;
  const V sx = hn::Add(ix, ox), sy = hn::Add(iy, oy), sz = hn::Add(iz, oz);
  const V len2 = hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(sz, sz)));
  const V iz2 = hn::Div(hn::Set(d, T(1)), hn::Mul(sz, sz));
  const V q = hn::MulAdd(hn::Mul(sx, sx), c.inv_ax2, hn::Mul(hn::Mul(sy, sy), c.inv_ay2));
  const V r2 = hn::Mul(q, iz2);
  const V l_iz2 = hn::Mul(len2, iz2);
  // D(h) = exp(-r2) (L / s.z^2)^2 / (pi ax ay); L / s.z^2 = 1 + tan^2(theta_h)
  // is at most 1 + 104 max(ax, ay)^2 where r2 < 104.
  const V e = hn::Exp(d, hn::Neg(r2));
  const V d_rest = hn::Mul(c.inv_pi_axay, hn::Mul(l_iz2, l_iz2));
  V ni, mi, no, mo;
  BeckmannLambdaParts(d, c, ix, iy, iz, &ni, &mi);
  BeckmannLambdaParts(d, c, ox, oy, oz, &no, &mo);
  const V mm = hn::Mul(mi, mo);
  V g_den;
  if (separable) {
    g_den = hn::Mul(hn::Add(mi, ni), hn::Add(mo, no));
  } else {
    g_den = hn::MulAdd(ni, mo, hn::MulAdd(no, mi, mm));
  }
  const V f = fresnel(d, CosAtHalf(d, ox, oy, oz, sx, sy, sz, len2));
  const V four_zz = hn::Mul(hn::Set(d, T(4)), hn::Mul(iz, oz));
  // The exponential multiplies last (see BeckmannD).
  const V val = hn::Mul(hn::Mul(hn::Div(hn::Mul(f, mm), hn::Mul(g_den, four_zz)), d_rest), e);
  const auto valid = hn::And(hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d))),
                             hn::And(hn::Gt(len2, hn::Set(d, T(1e-30))),
                                     hn::Lt(r2, hn::Set(d, BeckmannMaxR2<T>()))));
  return hn::IfThenElseZero(valid, val);
}

// cos(2 pi u), sin(2 pi u) for any u (float or double lanes). u is reduced
// exactly, in turns, to v = u - k/4 with |v| <= 1/8 and k in {-2..2}, so
// that Cos and Sin only see |2 pi v| <= pi/4 and the quadrant is a swap
// and sign flips: near the zeros of cos and sin the result keeps its
// relative accuracy (with 2 pi u rounded to float, cos(2 pi u) near u =
// 1/4 would be off by 1e-7 absolute, which the stretch by alpha_x /
// alpha_y = 1000 amplifies).
// Error: 4 ulp relative per component.
template <class D, class V>
HWY_INLINE void CosSinTurns(D d, V u, V* cos_out, V* sin_out) {
  using T = hn::TFromD<D>;
  const V w = hn::Sub(u, hn::Round(u));                                  // [-1/2, 1/2]
  const V k = hn::Round(hn::Mul(w, hn::Set(d, T(4))));                   // -2..2
  const V v = hn::NegMulAdd(k, hn::Set(d, T(0.25)), w);                  // exact
  const V phi = hn::Mul(v, hn::Set(d, T(6.283185307179586)));
  const V c = hn::Cos(d, phi), s = hn::Sin(d, phi);
  const V ak = hn::Abs(k);
  const auto swap = hn::Eq(ak, hn::Set(d, T(1)));                        // odd quadrant
  const V c1 = hn::IfThenElse(swap, s, c), s1 = hn::IfThenElse(swap, c, s);
  // Quadrant q = k mod 4: cos flips for q = 1, 2 (k = 1, +-2), sin for
  // q = 2, 3 (k = +-2, -1).
  const auto two = hn::Eq(ak, hn::Set(d, T(2)));
  const auto cos_neg = hn::Or(two, hn::Eq(k, hn::Set(d, T(1))));
  const auto sin_neg = hn::Or(two, hn::Eq(k, hn::Set(d, T(-1))));
  *cos_out = hn::IfThenElse(cos_neg, hn::Neg(c1), c1);
  *sin_out = hn::IfThenElse(sin_neg, hn::Neg(s1), s1);
}

// NDF sampling (slope_ndf.h SampleNdf with BeckmannNdf::UnitSampleR2): the
// standard radial slope r^2 = -log(1 - u2), azimuth 2 pi u1, stretch by
// (ax, ay), m = normalize(-slope, 1). Writes the three components.
// Error: 1e-6 absolute per component in float lanes, 1e-15 in double lanes
// (measured in the tests: CheckBeckmannSampleNdf, CheckBeckmannSamplingF64).
template <class D, class V>
HWY_INLINE void SampleSlopeNormal(D d, V ax, V ay, V r2, V u1, V* mx, V* my, V* mz) {
  using T = hn::TFromD<D>;
  V cos_phi, sin_phi;
  CosSinTurns(d, u1, &cos_phi, &sin_phi);
  const V r = hn::Sqrt(r2);
  const V px = hn::Mul(hn::Mul(r, ax), cos_phi);
  const V py = hn::Mul(hn::Mul(r, ay), sin_phi);
  const V inv = hn::Div(hn::Set(d, T(1)),
                        hn::Sqrt(hn::MulAdd(px, px, hn::MulAdd(py, py, hn::Set(d, T(1))))));
  *mx = hn::Neg(hn::Mul(px, inv));
  *my = hn::Neg(hn::Mul(py, inv));
  *mz = inv;
}

// The largest u2 the radial inverse CDFs take, as the scalar clamp at
// 1 - 2^-53 does in double: 1 - 2^-24 in float lanes (r^2 <= 16.6 for
// Beckmann), 1 - 2^-53 in double lanes (r^2 <= 36.7).
template <class T>
constexpr T SlopeSampleMaxU() {
  return sizeof(T) == 8 ? T(1 - 0x1p-53) : T(0.99999994f);
}

template <class D, class V>
HWY_INLINE void BeckmannSampleNdf(D d, const BeckmannConsts<D>& c, V u1, V u2, V* mx, V* my,
                                  V* mz) {
  const V uc = hn::Min(u2, hn::Set(d, SlopeSampleMaxU<hn::TFromD<D>>()));
  const V r2 = hn::Neg(hn::Log1p(d, hn::Neg(uc)));
  SampleSlopeNormal(d, c.ax, c.ay, r2, u1, mx, my, mz);
}

// The Beckmann kernels as the batch loops take them (kernels/batch_rows-inl.h,
// MicrofacetRows): D, Lambda and the BRDF over its constants (G1 = 1 / (1 +
// Lambda), the NDF density D(m) m.z).
template <class D>
struct BeckmannKernels {
  static constexpr bool kOwnG1 = false;
  static constexpr bool kPdfNdfFromD = true;
  const BeckmannConsts<D>& c;
  template <class V>
  HWY_INLINE V Ndf(D d, V x, V y, V z) const {
    return BeckmannD(d, c, x, y, z);
  }
  template <class V>
  HWY_INLINE V Lambda(D d, V x, V y, V z) const {
    return BeckmannLambda(d, c, x, y, z);
  }
  template <class V, class Fr>
  HWY_INLINE V Brdf(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz, const Fr& fr) const {
    return BeckmannBrdf(d, c, separable, ix, iy, iz, ox, oy, oz, fr);
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_BECKMANN_INL_H_
