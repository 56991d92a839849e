// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// STD (Student's t slopes, [Ribardiere17]) unit-roughness Smith Lambda for double
// lanes, for the integration core: the f64 twin of StudentTLambdaAbove in
// src/kernels/std-inl.h. Scalar reference: StudentTNdf<double>::UnitLambda
// (include/brdfbake/models/std_ndf.h, whose header comment defines kt, u = m^2,
// forms (Y) and (S)). a = cot(theta) / alpha; gamma is a per-call constant
// and everything that depends on it alone (kt, series coefficients,
// quadrature nodes) is computed once by StudentTLambdaF64Consts, in plain
// double code.
//
// Three forms, chosen per lane by a select; a branch skips a form only when
// no lane of the vector needs it. u = a^2 / (gamma - 1), x0 = 1 / (1 + u),
// e = (1 + u)^(3/2 - gamma) = exp(-(gamma - 3/2) log1p(u)):
//  (Y) u < 1 and a < 4: form (Y) of std_ndf.h,
//        Lambda = kt / a e P_Y(w) - 1/2,  w = a^2 x0,
//        P_Y(w) = (gamma-1)/(2 gamma-3) + sum_n c_n w^(n+1),
//        c_0 = 1, c_(n+1) = c_n (gamma - 1/2 + n) / ((gamma - 1)(n + 3/2)).
//  (X) u >= 1: form (S) of std_ndf.h with G v = x0 2F1(nu, 1; nu + 3/2; x0)
//      (v = 1/u, nu = gamma - 1/2; the Pfaff identity quoted there) by its
//      series:
//        Lambda = kt / (2a) e P_X(x0),
//        P_X(x0) = 1/(2 gamma - 3) + sum_n h_n / (2 gamma) x0^(n+1),
//        h_0 = 1, h_(n+1) = h_n (gamma - 1/2 + n) / (gamma + 1 + n).
//      (std_ndf.h avoids x0 for large gamma because x0^(nu-1) amplifies
//      its rounding; here e comes from u, not from x0, and the series has
//      condition number (1 + u)/u <= 2 in x0.)
//  (L) u < 1 and a >= 4 (only for gamma > 17): form (S) with G by 8-point
//      Gauss-Laguerre of the Euler integral, as in std-inl.h:
//        Lambda = kt / (2a) e [1/(2 gamma - 3) + (gamma-1)/(2 gamma) G / a^2],
//        G ~ sum_k W_k (1 + E_k / a^2)^(-3/2),  E_k = -(gamma-1) expm1(-x_k/gamma).
// All three are sums of positive terms; (Y) has one subtraction, of 1/2.
//
// Why these regions (measured with mpmath, 30 digits): Gauss-Laguerre
// converges like exp(-4 sqrt(n rho)), rho = gamma log1p(u) the distance of
// the integrand's singularity, so 1e-15 at the float kernel's switch point
// (a = 1.25 or u = 1, rho down to ~1) would need 60 to 80 nodes, each a
// square root and a division. A Horner term is one FMA, so the series take
// over everything but the tail: (Y) and (X) meet at u = 1, where their
// term ratios tend to y0 = u/(1+u) and x0, both <= 1/2, and (L) is kept
// only where a >= 4, so rho >= min(17 log 2, 16) = 11.8 and 8 nodes leave
// a relative error of 5e-12 at a = 4 (where Lambda <= 9e-8), below 1e-14
// from a = 5 on (24 nodes would be needed at a = 2). The term counts are
// chosen per call: the constructor sums until a tail bound (every later
// term ratio is at most the current or the limit one) is below 2^-56 of
// the sum, at the largest argument the form can get. (Y) takes 36
// coefficients at gamma = 1.5+1e-6, 57 at 2, 62 at large gamma and at most
// 104 (gamma ~ 17, where u < 1 and a < 4 meet: w <= 8 and the terms grow
// like n^(gamma-2) before 2^-n wins); (X) 30 to 57. Chebyshev economization
// would save ~40% of the terms but needs Clenshaw's 2 ops per term (the
// monomial form of a Chebyshev fit of an e^w-like function is unstable).
//
// Range, error and cost: see StudentTLambdaF64 below.

// Plain part, compiled once: the per-call constants (no Highway types).
#ifndef BRDFBAKE_SRC_KERNELS_STD_F64_INL_H_
#define BRDFBAKE_SRC_KERNELS_STD_F64_INL_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/models/std_ndf.h"

namespace brdfbake {

// Everything StudentTLambdaF64 needs that depends on gamma alone. Built once
// per call (per texel) in plain double code: two recurrences of up to 104
// and 57 steps (one division each) and 8 expm1, plus kt by
// student_t_detail::StudentTKt (Boost's tgamma_delta_ratio, as the scalar twin).
// Measured ~1 us (0.73 us of it in StudentTKt); 1.5 KB. It holds no Highway
// type, so one object serves every target.
struct StudentTLambdaF64Consts {
  // Form (Y) for u < 1 and a < kSeriesMaxA, (X) for u >= 1, (L) elsewhere.
  static constexpr double kSeriesMaxA = 4.0;
  // Capacities (multiples of 4; the largest counts needed are 104 and 57).
  static constexpr int kMaxY = 112, kMaxX = 64;
  static constexpr int kLaguerrePoints = 8;

  double gm1_inv;      // 1 / (gamma - 1)
  double log_gm1_inv;  // log(1 / (gamma - 1))
  double gm32;         // gamma - 3/2
  double kt;           // Gamma(gamma - 1/2) / (sqrt(pi) Gamma(gamma - 1) sqrt(gamma - 1))
  double half_kt;      // kt / 2
  double c1;           // 1 / (2 gamma - 3)
  double c2;           // (gamma - 1) / (2 gamma)
  int y_blocks;        // P_Y has 4 y_blocks coefficients
  int x_blocks;        // P_X has 4 x_blocks coefficients
  // P_Y(w) and P_X(x0) in blocks of 4, highest degrees first: block i holds
  // the coefficients of degrees 4 (blocks - 1 - i) + j, j = 0..3 (leading
  // zeros pad the degree up to a multiple of 4).
  double y_coef[kMaxY];
  double x_coef[kMaxX];
  double lag_e[kLaguerrePoints];  // E_k = -(gamma - 1) expm1(-x_k / gamma)
  double lag_w[kLaguerrePoints];  // W_k

  // gamma in [kMinStudentTGamma, kStudentTBeckmannLimitGamma) (clamped below).
  explicit StudentTLambdaF64Consts(double gamma) {
    const double g = std::max(gamma, kMinStudentTGamma<double>);
    const double gm1 = g - 1;
    gm1_inv = 1 / gm1;
    log_gm1_inv = -std::log(gm1);
    gm32 = g - 1.5;
    kt = student_t_detail::StudentTKt(g);
    half_kt = kt / 2;
    c1 = 1 / (2 * g - 3);
    c2 = gm1 / (2 * g);
    constexpr double kTol = 1.3877787807814457e-17;  // 2^-56
    // (Y) at w_max = max of a^2 / (1 + u) over u < 1, a < 4.
    {
      double p[kMaxY];
      const double a2 = kSeriesMaxA * kSeriesMaxA;
      const double w = std::min(gm1 / 2, a2 / (1 + a2 * gm1_inv)) * (1 + 1e-9);
      const double y_lim = w * gm1_inv;  // limit of the term ratio
      p[0] = (g - 1) / (2 * g - 3);
      double cn = 1, term = w, sum = p[0];
      int n = 0;
      for (;;) {
        p[n + 1] = cn;
        sum += term;
        const double ratio = (g - 0.5 + n) / (gm1 * (n + 1.5));
        const double r = std::max(ratio * w, y_lim);
        if ((r < 1 && term * r <= kTol * sum * (1 - r)) || n + 2 == kMaxY) break;
        cn *= ratio;
        term *= ratio * w;
        ++n;
      }
      y_blocks = Pack(p, n + 2, y_coef);
    }
    // (X) at x0_max = 1/2 (u >= 1).
    {
      double p[kMaxX];
      const double x = 0.5, inv_2g = 1 / (2 * g);
      p[0] = c1;
      double hn = 1, term = x * inv_2g, sum = p[0];
      int n = 0;
      for (;;) {
        p[n + 1] = hn * inv_2g;
        sum += term;
        // Later ratios are below x (they increase towards it).
        if (term * x <= kTol * sum * (1 - x) || n + 2 == kMaxX) break;
        const double ratio = (g - 0.5 + n) / (g + 1 + n);
        hn *= ratio;
        term *= ratio * x;
        ++n;
      }
      x_blocks = Pack(p, n + 2, x_coef);
    }
    // 8-point Gauss-Laguerre rule (nodes: roots of L_8; weights
    // x / (9 L_9(x))^2), computed with mpmath at 30 digits.
    static constexpr double kLaguerre8[kLaguerrePoints][2] = {
        {0.17027963230510099979, 0.36918858934163752992},
        {0.90370177679937991219, 0.41878678081434295608},
        {2.2510866298661306893, 0.1757949866371718057},
        {4.2667001702876587936, 0.033343492261215651522},
        {7.0459054023934656973, 0.0027945362352256725249},
        {10.758516010180995224, 0.000090765087733582131042},
        {15.740678641278004578, 8.4857467162725315449e-7},
        {22.863131736889264106, 1.0480011748715103816e-9}};
    for (int k = 0; k < kLaguerrePoints; ++k) {
      lag_e[k] = -gm1 * std::expm1(-kLaguerre8[k][0] / g);
      lag_w[k] = kLaguerre8[k][1];
    }
  }

 private:
  // Copies the count coefficients p[0..count) (lowest degree first) into the
  // block layout described above; returns the number of blocks.
  static int Pack(const double* p, int count, double* out) {
    const int blocks = (count + 3) / 4;
    for (int i = 0; i < blocks; ++i) {
      for (int j = 0; j < 4; ++j) {
        const int deg = 4 * (blocks - 1 - i) + j;
        out[4 * i + j] = deg < count ? p[deg] : 0.0;
      }
    }
    return blocks;
  }
};

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_STD_F64_INL_H_

// SIMD part, compiled once per target.
#if defined(BRDFBAKE_SIMD_STD_F64_INL_TOGGLE_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SIMD_STD_F64_INL_TOGGLE_
#undef BRDFBAKE_SIMD_STD_F64_INL_TOGGLE_
#else
#define BRDFBAKE_SIMD_STD_F64_INL_TOGGLE_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// sum_j x^j P_j(x^4), the four P_j by Horner in x^4 side by side (a quarter
// of the latency of one chain); coef in the block layout of
// StudentTLambdaF64Consts. Positive coefficients and x >= 0: no cancellation.
template <class D, class V>
HWY_INLINE V StudentTF64Poly4(D d, const double* coef, int blocks, V x) {
  const V x2 = hn::Mul(x, x);
  const V x4 = hn::Mul(x2, x2);
  V p0 = hn::Set(d, coef[0]), p1 = hn::Set(d, coef[1]);
  V p2 = hn::Set(d, coef[2]), p3 = hn::Set(d, coef[3]);
  for (int i = 1; i < blocks; ++i) {
    const double* c = coef + 4 * i;
    p0 = hn::MulAdd(p0, x4, hn::Set(d, c[0]));
    p1 = hn::MulAdd(p1, x4, hn::Set(d, c[1]));
    p2 = hn::MulAdd(p2, x4, hn::Set(d, c[2]));
    p3 = hn::MulAdd(p3, x4, hn::Set(d, c[3]));
  }
  return hn::MulAdd(hn::MulAdd(hn::MulAdd(p3, x, p2), x, p1), x, p0);
}

// STD unit-roughness Smith Lambda(a), a = cot(theta) / alpha, for the gamma
// of c (forms (Y), (X), (L) at the top of this file).
//
// Range: gamma in [1.5 + 1e-6, 1e20) (from kStudentTBeckmannLimitGamma = 1e20
// on the caller runs BeckmannLambdaF64 of math_f64-inl.h, as StudentTNdf does);
// any double a: +inf for a <= 0, where the true value exceeds DBL_MAX (a
// below ~6e-304 at gamma = 1.5+1e-6) and where 1/a overflows (a < 5.6e-309),
// 0 for a = +inf; never NaN unless a is NaN.
// Error: |err| <= 8e-15 max(1, Lambda), on every target. In (Y) (u < 1 and
// a < 4) it is ~(4 + w + expo) / 2 ulp of Lambda + 1/2, expo = (gamma -
// 3/2) log1p(u) <= 16 and w <= 16 the exponent and the argument of the
// e^w-like series (rounding of log1p, x0 and w, amplified), so that
// relative to Lambda it grows as Lambda falls below 1/2, to 1e-5 at a -> 4
// for gamma >= 1e6 (Lambda ~ 2e-10 there; the scalar twin switches at a =
// 1.5 and loses up to 2.3 digits). In (X) and (L) (u >= 1 or a >= 4) the
// error is relative: <= 2e-15 + 5e-16 expo, plus the quadrature's
// 5e-12 exp(-4 (a - 4)) in (L).
// Measured (tests/kernels/simd_std_f64_test.cc, 8323 40-digit values: 17 gamma
// from 1.5+1e-6 to 9.9e19 x a over [1e-8, 1e8] and 1e-300 .. 1e300, plus
// 1200 random (gamma, a)): max |err| / max(1, Lambda) 2.66e-15 on AVX3
// and AVX2, 2.61e-15 on SSE4, SSSE3 and SCALAR (gamma = 5.9e15, a = 3.43);
// (X), (L) within 0.65 of their relative bound (9e-14 at expo = 692, 2.5e-12
// at a = 4 in (L)). 4.1e-15 (AVX2 and SSE4) over 260k more random points
// with a in [0, 4], where (Y) is least accurate. Against StudentTNdf<double>::
// UnitLambda (itself within 5e-16 of the 40-digit values there): 2e-15.
// Cost per vector: 2 divisions (1/a, x0), hn::Log1p (~26 ops, 2 of them
// divisions) and hn::Exp (~30 ops), ~25 mul/compare/select/mask ops, and
// for each form some lane needs: (Y) n_Y + 6 FMA/mul, n_Y = 36 (gamma =
// 1.5+1e-6), 60 (gamma = 2), 104 (gamma ~ 17), 64 (gamma >= 1e3) (the
// counts above rounded up to 4: 4 interleaved Horner chains); (X) n_X + 5,
// n_X = 32..60; (L) 8 x
// (FMA, square root, mul, division, add) + 4, only for gamma > 17.
// Measured on an AMD EPYC (shared, +-15%), ns per value for a
// log-uniform in [1e-3, 1e3] (all forms mixed): AVX3 3.3 (gamma = 1.5) to
// 6.5 (gamma = 1e6), AVX2 6.8 to 13, SSE4 18 to 30; a in [0.1, 2]:
// AVX3 3.2-4.4, AVX2 6.5-9.3, SSE4 19-28.
template <class D, class V>
HWY_INLINE V StudentTLambdaF64(D d, const StudentTLambdaF64Consts& c, V a) {
  const V one = hn::Set(d, 1.0);
  const V a2 = hn::Mul(a, a);
  const V u = hn::Mul(a2, hn::Set(d, c.gm1_inv));
  const V x0 = hn::Div(one, hn::Add(one, u));  // 0 where u overflows
  const V ia = hn::Div(one, a);
  // log1p(u); where u may overflow (a > 2^500, u > 2^933) 2 log(a) -
  // log(gamma - 1) instead (log1p(1/u) < 2^-933 is dropped).
  V lg = hn::Log1p(d, u);
  const auto huge = hn::Gt(a, hn::Set(d, 0x1p500));
  if (!hn::AllFalse(d, huge)) {
    lg = hn::IfThenElse(huge, hn::MulAdd(hn::Set(d, 2.0), hn::Log(d, a), hn::Set(d, c.log_gm1_inv)),
                        lg);
  }
  const V e = hn::Exp(d, hn::Mul(hn::Set(d, -c.gm32), lg));  // (1 + u)^(3/2 - gamma)
  const V kt_ia_e = hn::Mul(hn::Mul(hn::Set(d, c.kt), ia), e);

  const auto use_x = hn::Ge(u, one);
  const auto use_y = hn::And(hn::Lt(u, one), hn::Lt(a, hn::Set(d, c.kSeriesMaxA)));
  const auto use_l = hn::Not(hn::Or(use_x, use_y));

  V lam_y = hn::Zero(d);
  if (!hn::AllFalse(d, use_y)) {
    const V w = hn::Mul(a2, x0);
    lam_y = hn::MulSub(kt_ia_e, StudentTF64Poly4(d, c.y_coef, c.y_blocks, w), hn::Set(d, 0.5));
  }
  V bracket = hn::Zero(d);  // of form (S): P_X(x0), or the same by quadrature
  if (!hn::AllFalse(d, use_x)) bracket = StudentTF64Poly4(d, c.x_coef, c.x_blocks, x0);
  if (!hn::AllFalse(d, use_l)) {
    const V ia2 = hn::Mul(ia, ia);
    V g = hn::Zero(d);
    for (int k = 0; k < c.kLaguerrePoints; ++k) {
      const V q = hn::MulAdd(hn::Set(d, c.lag_e[k]), ia2, one);
      g = hn::Add(g, hn::Div(hn::Set(d, c.lag_w[k]), hn::Mul(q, hn::Sqrt(q))));
    }
    bracket = hn::IfThenElse(use_l, hn::MulAdd(hn::Mul(g, hn::Set(d, c.c2)), ia2, hn::Set(d, c.c1)),
                             bracket);
  }
  // half_kt / a * bracket first, e last (where e is subnormal nothing else
  // rounds on its scale).
  const V lam_s = hn::Mul(hn::Mul(hn::Mul(hn::Set(d, c.half_kt), ia), bracket), e);
  const V lam = hn::IfThenElse(use_y, lam_y, lam_s);
  const V v = hn::IfThenZeroElse(hn::Eq(a, hn::Inf(d)), lam);
  return hn::IfThenElse(hn::Le(a, hn::Zero(d)), hn::Inf(d), v);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SIMD_STD_F64_INL_TOGGLE_
