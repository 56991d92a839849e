// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann visible-normal sampling and its density, generic over the lane
// type (float for the batch kernels, double for the sampling integrators;
// see "Double lanes" below); the scalar
// twins (double reference) are BeckmannNdf::SampleVisible and ::PdfVisible in
// include/brdfbake/models/beckmann.h, which this kernel follows step by step: for
// the same (u1, u2) it returns the same normal.
//
// The method (Heitz and d'Eon 2014, the stretch of [Heitz18] section 3.2):
// in the unit-roughness configuration the view is (s, 0, c) after a rotation
// by its azimuth, c = cos(theta), s = sin(theta), mu = c / s = cot(theta). The
// visible slope x along the view azimuth has density (c - s x)^+ exp(-x^2),
// whose CDF up to normalization is
//   F(x) = c erfc(-x) / 2 + s exp(-x^2) / (2 sqrt(pi)),   x <= mu,
// and y given x is N(0, 1/2). x solves F(x) = u1 F(mu) on [-9, min(mu, 9)]
// (the scalar search interval), y = erf^-1(2 u2 - 1).
//
// Solving for x in float, without losing the tails:
//  - The equation is written as log F(x) = log(u1 F(mu)) for u1 <= 1/2 and
//    as log U(x) = log((1 - u1) F(mu)) for u1 > 1/2, U(x) = F(mu) - F(x) the
//    upper tail (1 - u1 is exact there). Both sides are log-concave in x
//    (a CDF and a survival function of the log-concave density), so Newton
//    on them is globally convergent; 4 steps from the initial guess below,
//    safeguarded by a bracket [lo, hi] that falls back to bisection when a
//    step leaves it, the same on every lane.
//  - F and V(x) = c - F(x) = c erfc(x) / 2 - s exp(-x^2) / (2 sqrt(pi)) are
//    built from E = exp(-x^2) and R = erfcx(|x|) (kernels/math-inl.h) so that
//    the smaller of the two is a sum of positive terms or one subtraction
//    at relative precision: F = E (c R + s/sqrt(pi)) / 2 for x <= 0,
//    V = E (c R - s/sqrt(pi)) / 2 for x > 0, and U = V(x) - V(mu).
//  - Near the top of the interval (r = mu - x small) V(x) - V(mu) cancels to
//    first order while U is of second order, U ~ s r^2 exp(-mu^2) / (2
//    sqrt(pi)), and the error of x would grow like 1e-7 / r (1.7e-4 in the
//    normal without the remedy). There U comes from its Taylor series in r:
//    with t = mu - z in U = s / sqrt(pi) int_x^mu (mu - t) exp(-t^2) dt,
//      U = s exp(-mu^2) / sqrt(pi) int_0^r z exp(2 mu z - z^2) dz
//        = s exp(-mu^2) / sqrt(pi) sum_n H_n(mu) r^(n+2) / (n! (n+2))
//    by the generating function of the Hermite polynomials H_n. It is used
//    where r max(mu, 2.5) < 1/4 (2 mu r < 1/2, r < 1/10) and mu is not
//    clamped; 7 terms leave 2.3e-7 relative there (mpmath, mu in [0, 9]),
//    which moves x by at most 1.2e-8 (U / U' ~ r / 2).
//  - Initial guess: the empirical fit of pbrt-v3's BeckmannSample11 (from
//    Mitsuba), erf(x0) = erf(mu) - (1 + erf(mu)) (1 - u1)^p(theta) with
//    p(theta) = 1 - 0.876 theta + 0.4265 theta^2 - 0.0594 theta^3, written as
//    x0 = erf^-1(2 v - 1), v = erfc(-mu) / 2 (-expm1(p log1p(-u1))), which
//    keeps its relative precision for small u1. Its error is up to 0.03
//    (1 + x^2); in double, over mu in [1e-4, 1e4] and u1 in [1e-12, 1 -
//    2^-24], 3 Newton steps leave 7e-6 (1 + x^2), 4 steps 1e-7 (1 + x^2).
//  - The ends u1 = 0 and u1 = 1 (target 0) return the ends of the interval,
//    -9 and min(mu, 9).
//
// Error, in the unit-roughness configuration where the map from (u1, u2) to
// the normal does not depend on alpha (nh = normalize(m.x / ax, m.y / ay,
// m.z), as for GGX in ggx_sampling-inl.h): |nh - nh_ref| <= 2e-6 (max
// component) against the double reference at the same float inputs, for
// any u1, u2 in [0, 1]: no range is excluded (tests/kernels/simd_beckmann_test.cc,
// alpha 1e-4 to 1 and 1000:1, mu down to 1e-4, 1 - u1 down to 2^-24 and u1
// down to 2^-40; measured max 9e-7 on AVX3, AVX2, SSE4, SSSE3 and SCALAR;
// 3 Newton steps would give 6e-6), u1 = 1 included (the reference solves on
// its upper tail as well, so it reaches the end min(mu, 9) exactly).
// wo.m >= -2e-7 (the rounding of m at the edge u1 = 1, where wo.m = 0).
// Views with w.z <= 0 give m = (0, 0, 0).
// PdfVisible: relative error 2e-6 + 3e-7 r2 + 2e-7 / (w.m), r2 the exponent
// of D at m (beckmann-inl.h) and the last term the rounding of w.m; 0 where
// exp(-r2) is below FLT_MIN and the batch call flushes it (measured 0.67 of
// the bound at most).
//
// Double lanes (the sampling integrators): the same steps with erfcx and
// exp(-x^2) in double (ErfcxF64, ExpNegSquareF64), 6 Newton steps, 15
// Taylor terms, erf^-1 refined by two Newton steps (ErfInvCentered), and
// the start deep in the upper tail from U's leading term. Error: the
// unit-roughness normal within 1e-14 of BeckmannNdf<double>::SampleVisible
// (max component), PdfVisible within 1e-13 + 2.2e-16 / (w.m) relative, for
// any u1, u2 in [0, 1] with 1 - u1 and u1 down to 2^-50 (CheckBeckmannSamplingF64,
// every target: measured 2.3e-15 and 0.64 of the pdf's bound).
//
// Cost per lane: 4 Newton steps of one exp, one log, two divisions and ~50
// FMA each, plus the guess (atan, log1p, expm1, one erf^-1) and erf^-1(2 u2 -
// 1). The steps form one dependency chain, so a vector takes about the same
// time on every target (latency-bound).

#if defined(BRDFBAKE_SRC_KERNELS_BECKMANN_SAMPLING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_BECKMANN_SAMPLING_INL_H_
#undef BRDFBAKE_SRC_KERNELS_BECKMANN_SAMPLING_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_BECKMANN_SAMPLING_INL_H_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/beckmann-inl.h"
#include "kernels/common-inl.h"
#include "kernels/math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// erf^-1(2u - 1) for u in [0, 1], with the tail mass q = min(u, 1 - u)
// clamped below at 2^-53 (|result| <= 5.86), as the scalar reference's clamp
// of 2u - 1 to +-(1 - 2^-52) does in double. With w = -log(4 q (1 - q)) =
// -log(1 - (2u - 1)^2) (accurate in both tails: q and 1 - q are exact or at
// relative precision),
//   erf^-1(2u - 1) = (2u - 1) P(w),
// P fitted here (mpmath chebyfit, 40 digits) on w in [0, 5] in the variable
// w - 2.5 (degree 9, fit error 6e-9 relative) and on [5, 35.36] in
// sqrt(w) - 4 (degree 12, 3e-8), the split and the variables of Giles,
// "Approximating the erfinv function" (GPU Computing Gems, 2011).
// Error: 3e-7 relative for any u in [0, 1] (tests/kernels/simd_beckmann_test.cc,
// SimdBeckmannTest.CheckErfInv: measured max 2.1e-7 with FMA (AVX2,
// AVX3), 2.7e-7 without (SSE4, SSSE3, SCALAR)).
template <bool kRefine = true, class D, class V>
HWY_INLINE V ErfInvCentered(D d, V u) {
  using T = hn::TFromD<D>;
  static constexpr float kCentral[10] = {
      -8.931926310e-09f, 2.333596782e-08f,  4.681313612e-07f,  -3.463985195e-06f,
      -4.972419902e-06f, 2.183493925e-04f,  -1.252726419e-03f, -4.177392926e-03f,
      2.466402799e-01f,  1.501409411e+00f};
  static constexpr float kTail[13] = {
      -4.602292165e-07f, 1.621187948e-06f, 2.140182687e-06f,  -1.575197530e-05f,
      2.306117131e-05f,  -2.063626016e-05f, 4.839427129e-05f, -1.284933533e-04f,
      3.260869416e-04f,  -8.647334762e-04f, 1.258546021e-03f, 1.009492755e+00f,
      3.839783907e+00f};
  const V one = hn::Set(d, T(1));
  const V q = hn::Max(hn::Min(u, hn::Sub(one, u)), hn::Set(d, T(0x1p-53)));
  const V w = hn::Neg(hn::Log(d, hn::Mul(hn::Mul(hn::Set(d, T(4)), q), hn::Sub(one, q))));
  const V p_central = HornerHighFirst(d, kCentral, hn::Sub(w, hn::Set(d, T(2.5))));
  const V p_tail = HornerHighFirst(d, kTail, hn::Sub(hn::Sqrt(w), hn::Set(d, T(4))));
  const V p = hn::IfThenElse(hn::Lt(w, hn::Set(d, T(5))), p_central, p_tail);
  const V abs_x = hn::NegMulAdd(hn::Set(d, T(2)), q, one);  // |2u - 1| = 1 - 2q
  V y = hn::Mul(p, abs_x);
  if constexpr (sizeof(T) == 8 && kRefine) {
    // Double lanes: the fit above (3e-7) refined by Newton on erfc(y) = 2q
    // (exact), y >= 0: y += (sqrt(pi) / 2) (erfcx(y) - 2q / exp(-y^2)),
    // with ErfcxF64 and ExpNegSquareF64 (kernels/math_f64-inl.h; exp(-y^2) >=
    // 1e-15 for y <= 5.86). Two steps square the error twice (3e-7 ->
    // 1e-13 -> below rounding); the result is within 1e-15 |y| + 4e-16 of
    // erf^-1 (CheckBeckmannSamplingF64; the absolute part is erfc's
    // rounding near y = 0).
    const V two_q = hn::Add(q, q);
    for (int step = 0; step < 2; ++step) {
      const V corr = hn::Sub(ErfcxF64(d, y), hn::Div(two_q, ExpNegSquareF64(d, y)));
      y = hn::Max(hn::MulAdd(hn::Set(d, T(0.88622692545275801)), corr, y), hn::Zero(d));
    }
  }
  return hn::CopySign(y, hn::Sub(u, hn::Set(d, T(0.5))));
}

// The scalar search interval of the visible slope is [-kBeckmannSlopeMax,
// min(mu, kBeckmannSlopeMax)]; Newton steps of the kernel.
constexpr float kBeckmannSlopeMax = 9.0f;
// Per lane type (the header's error statement is for float; double: see
// BeckmannSampleVisible): Newton steps (float 4: 1e-7 (1 + x^2); double 6,
// two more quadratic steps), terms of the Taylor series of U near the top
// (float 7: 2.3e-7 relative; double 15: 1e-18, mpmath over mu in [0, 9] at
// the switch r max(mu, 2.5) = 1/4).
template <class T>
constexpr int BeckmannNewtonSteps() {
  return sizeof(T) == 8 ? 6 : 4;
}
template <class T>
constexpr int BeckmannTaylorTerms() {
  return sizeof(T) == 8 ? 15 : 7;
}

// exp(-x^2) and erfcx(x) (x >= 0) in the lanes' precision.
template <class D, class V>
HWY_INLINE V ExpNegSquareOf(D d, V x) {
  if constexpr (sizeof(hn::TFromD<D>) == 8) {
    return ExpNegSquareF64(d, x);
  } else {
    return ExpNegSquare(d, x);
  }
}
template <class D, class V>
HWY_INLINE V ErfcxOf(D d, V x) {
  if constexpr (sizeof(hn::TFromD<D>) == 8) {
    return ErfcxF64(d, x);
  } else {
    return Erfcx(d, x);
  }
}

// F(x) and V(x) = c - F(x) of the header, from E = exp(-x^2) and
// R = erfcx(|x|) (also returned: erfc(|x|) = E R).
template <class D, class V>
HWY_INLINE void BeckmannSlopeCdf(D d, V c, V s_pi, V x, V* f, V* v, V* e, V* r) {
  *e = ExpNegSquareOf(d, x);
  *r = ErfcxOf(d, hn::Abs(x));
  const auto neg = hn::Le(x, hn::Zero(d));
  // x <= 0: F = E (c R + s/sqrt(pi)) / 2;  x > 0: V = E (c R - s/sqrt(pi)) / 2.
  const V small = hn::Mul(hn::Mul(*e, hn::Set(d, hn::TFromD<D>(0.5))),
                          hn::MulAdd(c, *r, hn::IfThenElse(neg, s_pi, hn::Neg(s_pi))));
  const V large = hn::Sub(c, small);
  *f = hn::IfThenElse(neg, small, large);
  *v = hn::IfThenElse(neg, large, small);
}

// BeckmannNdf::SampleVisible (see the header): the visible normal of
// Beckmann for the view w and (u1, u2); m = 0 for w.z <= 0.
template <class D, class V>
HWY_INLINE void BeckmannSampleVisible(D d, const BeckmannConsts<D>& k, V wx, V wy, V wz, V u1,
                                      V u2, V* mx, V* my, V* mz) {
  using T = hn::TFromD<D>;
  constexpr int kNewtonSteps = BeckmannNewtonSteps<T>();
  constexpr int kTaylorTerms = BeckmannTaylorTerms<T>();
  // Floors and clamps in the lanes' range: the smallest normal's order
  // (float 1e-38, double 1e-300) and the largest u1 below 1
  // (SlopeSampleMaxU, beckmann-inl.h).
  constexpr T kTiny = sizeof(T) == 8 ? T(1e-300) : T(1.2e-38f);
  constexpr T kTargetFloor = sizeof(T) == 8 ? T(1e-300) : T(1e-37f);
  constexpr T kBelowOne = SlopeSampleMaxU<T>();
  const V zero = hn::Zero(d), one = hn::Set(d, T(1.0)), half = hn::Set(d, T(0.5));
  const V inv_sqrt_pi = hn::Set(d, T(0.56418958354775628));
  const V slope_max = hn::Set(d, T(kBeckmannSlopeMax));
  // Stretch: the view (gx, gy, w.z), its azimuth (cos_phi, sin_phi) ((1, 0)
  // at the pole, as in the scalar code) and c, s of the unit-roughness view.
  const V gx = hn::Mul(k.ax, wx), gy = hn::Mul(k.ay, wy);
  const V g2 = hn::MulAdd(gx, gx, hn::Mul(gy, gy));
  const auto off_pole = hn::Gt(g2, hn::Set(d, kTiny));
  const V inv_g = RsqrtNewton(d, hn::IfThenElse(off_pole, g2, one));
  const V cos_phi = hn::IfThenElse(off_pole, hn::Mul(gx, inv_g), one);
  const V sin_phi = hn::IfThenElseZero(off_pole, hn::Mul(gy, inv_g));
  const V g = hn::IfThenElseZero(off_pole, hn::Mul(g2, inv_g));
  const V inv_len = RsqrtNewton(d, hn::MulAdd(wz, wz, hn::Mul(g, g)));
  const V c = hn::Mul(wz, inv_len), s = hn::Mul(g, inv_len);
  const V s_pi = hn::Mul(s, inv_sqrt_pi);
  const V mu_raw = hn::Div(c, s);  // +inf at the pole
  const V mu = hn::Min(mu_raw, slope_max);

  // The target of each form: u1 F(mu) (lower) or (1 - u1) F(mu) (upper).
  V f_mu, v_mu, e_mu, r_mu;
  BeckmannSlopeCdf(d, c, s_pi, mu, &f_mu, &v_mu, &e_mu, &r_mu);
  const auto upper = hn::Gt(u1, half);
  const V sign = hn::IfThenElse(upper, hn::Set(d, T(-1.0)), one);
  const V tail = hn::IfThenElse(upper, hn::Sub(one, u1), u1);
  const V target = hn::Max(hn::Mul(tail, f_mu), hn::Set(d, kTargetFloor));
  const V log_target = hn::Log(d, target);

  // Taylor coefficients of U in r = mu - x: b_n = s E(mu) / sqrt(pi) h_n /
  // (n + 2), h_n = H_n(mu) / n! from h_(n+1) = (2 mu h_n - 2 h_(n-1)) / (n + 1).
  // Used where r max(mu, 2.5) < 1/4 and mu is not clamped.
  V b[kTaylorTerms];
  {
    const V scale = hn::Mul(s_pi, e_mu), two_mu = hn::Add(mu, mu);
    V h_prev = one, h = two_mu;
    b[0] = hn::Mul(scale, half);
    for (int n = 1; n < kTaylorTerms; ++n) {
      b[n] = hn::Mul(scale, hn::Mul(h, hn::Set(d, T(1) / static_cast<T>(n + 2))));
      const V h_next = hn::Mul(hn::MulSub(two_mu, h, hn::Add(h_prev, h_prev)),
                               hn::Set(d, T(1) / static_cast<T>(n + 1)));
      h_prev = h;
      h = h_next;
    }
  }
  const V taylor_scale = hn::IfThenElse(hn::Lt(mu_raw, slope_max),
                                        hn::Max(mu, hn::Set(d, T(2.5))), hn::Set(d, T(1e30)));

  // Initial guess x0 = erf^-1(2 v - 1), v = erfc(-mu)/2 (-expm1(p log1p(-u1))).
  const V theta = hn::Atan(d, hn::Div(s, c));
  const V p = hn::MulAdd(
      theta,
      hn::MulAdd(theta, hn::MulAdd(theta, hn::Set(d, T(-0.0594)), hn::Set(d, T(0.4265))),
                 hn::Set(d, T(-0.876))),
      one);
  const V log_1mu = hn::Log1p(d, hn::Neg(hn::Min(u1, hn::Set(d, kBelowOne))));
  const V cdf_mu = hn::NegMulAdd(hn::Mul(e_mu, r_mu), half, one);  // erfc(-mu) / 2
  const V v0 = hn::Mul(cdf_mu, hn::Neg(hn::Expm1(d, hn::Mul(p, log_1mu))));
  V lo = hn::Neg(slope_max), hi = mu;
  V x = hn::Min(hn::Max(ErfInvCentered</*kRefine=*/false>(d, v0), lo), hi);
  // Deep in the upper tail the fit puts x0 at the top itself (U(x0) = 0),
  // where Newton on log U cannot start; there U ~ b_0 r^2 gives the start
  // r0 = sqrt(target / b_0), exact as r -> 0, used where it falls in the
  // series' range. (Float lanes never get that deep: 1 - u1 >= 2^-24 there
  // keeps x0 below the top; double lanes reach 1 - u1 = 2^-53.)
  const V r_top = hn::Sqrt(hn::Div(target, b[0]));
  const auto start_top =
      hn::And(upper, hn::Lt(hn::Mul(r_top, taylor_scale), hn::Set(d, T(0.25))));
  x = hn::IfThenElse(start_top, hn::Max(hn::Sub(mu, r_top), lo), x);

  // Safeguarded Newton on log F (sign = 1) or log U (sign = -1).
  for (int step = 0; step < kNewtonSteps; ++step) {
    V f, v, e, r;
    BeckmannSlopeCdf(d, c, s_pi, x, &f, &v, &e, &r);
    const V dist = hn::Sub(mu, x);
    V series = b[kTaylorTerms - 1];
    for (int n = kTaylorTerms - 2; n >= 0; --n) series = hn::MulAdd(series, dist, b[n]);
    const auto near_top = hn::Lt(hn::Mul(dist, taylor_scale), hn::Set(d, T(0.25)));
    const V u_tail = hn::IfThenElse(near_top, hn::Mul(hn::Mul(dist, dist), series),
                                    hn::Sub(v, v_mu));
    const V val = hn::IfThenElse(upper, u_tail, f);
    // x is above the root where sign (val - target) > 0.
    const auto above = hn::Gt(hn::Mul(sign, hn::Sub(val, target)), zero);
    hi = hn::IfThenElse(above, x, hi);
    lo = hn::IfThenElse(above, lo, x);
    // F'(x) = (c - s x) E / sqrt(pi); the step is sign (log val - log target) val / F'.
    const V dens = hn::Mul(hn::Mul(hn::NegMulAdd(s, x, c), e), inv_sqrt_pi);
    const auto val_ok = hn::Gt(val, zero);
    const V log_val = hn::Log(d, hn::IfThenElse(val_ok, val, one));
    const V next = hn::NegMulAdd(
        sign, hn::Div(hn::Mul(hn::Sub(log_val, log_target), val), dens), x);
    const auto inside = hn::And(val_ok, hn::And(hn::Ge(next, lo), hn::Le(next, hi)));
    x = hn::IfThenElse(inside, next, hn::Mul(half, hn::Add(lo, hi)));
  }
  // The ends u1 = 0 and 1 (target 0) map to the ends of the interval.
  x = hn::IfThenElse(hn::Eq(tail, zero), hn::IfThenElse(upper, mu, hn::Neg(slope_max)), x);

  // y = erf^-1(2 u2 - 1); rotate back to the view azimuth, unstretch, and
  // m = normalize(-slope, 1).
  const V y = ErfInvCentered(d, u2);
  const V sx = hn::Mul(k.ax, hn::MulSub(cos_phi, x, hn::Mul(sin_phi, y)));
  const V sy = hn::Mul(k.ay, hn::MulAdd(sin_phi, x, hn::Mul(cos_phi, y)));
  const V inv_m = RsqrtNewton(d, hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, one)));
  const auto valid = hn::Gt(wz, zero);
  *mx = hn::IfThenElseZero(valid, hn::Neg(hn::Mul(sx, inv_m)));
  *my = hn::IfThenElseZero(valid, hn::Neg(hn::Mul(sy, inv_m)));
  *mz = hn::IfThenElseZero(valid, inv_m);
}

// BeckmannNdf::PdfVisible = DVisible: G1(w) max(0, w.m) D(m) / w.z with
// Lambda = N / M (beckmann-inl.h), G1 = M / (M + N). Zero unless w.z and w.m
// are positive (D is zero for m.z <= 0).
template <class D, class V>
HWY_INLINE V BeckmannPdfVisible(D d, const BeckmannConsts<D>& k, V wx, V wy, V wz, V mx, V my,
                                V mz) {
  const V zero = hn::Zero(d);
  V num, den;
  BeckmannLambdaParts(d, k, wx, wy, wz, &num, &den);
  const V wm = hn::MulAdd(wx, mx, hn::MulAdd(wy, my, hn::Mul(wz, mz)));
  const V pdf = hn::Mul(hn::Div(hn::Mul(den, wm), hn::Mul(hn::Add(den, num), wz)),
                        BeckmannD(d, k, mx, my, mz));
  return hn::IfThenElseZero(hn::And(hn::Gt(wz, zero), hn::Gt(wm, zero)), pdf);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_BECKMANN_SAMPLING_INL_H_
