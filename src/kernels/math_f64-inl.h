// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Double-lane special functions for the integration core, the f64 twins of
// src/kernels/math-inl.h: exp(-x^2) without the rounding of x^2, erfcx,
// exp without a range guard, cos on [0, pi], and
// Beckmann's unit-roughness Smith Lambda (the scalar reference is
// BeckmannNdf<double>::UnitLambda in include/brdfbake/models/beckmann.h). Each states
// its range and the error measured against 50-digit values
// (Boost.Multiprecision) by tests/kernels/simd_math_f64_test.cc on every target.
// Highway 1.0.3 ops only (hn::Exp is 1 ulp for f64 there; no Erf).

#if defined(BRDFBAKE_SRC_KERNELS_MATH_F64_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_MATH_F64_INL_H_
#undef BRDFBAKE_SRC_KERNELS_MATH_F64_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_MATH_F64_INL_H_
#endif

#include <cstddef>
#include <cstdint>

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// exp(-x^2) for finite |x| < 1.3e154 (x^2 finite), no range guard: x^2 =
// p + q exactly, p = fl(x * x), by Dekker's product with x split by masking:
// xh keeps the top 26 significand bits, xl = x - xh (at most 27 bits) is
// exact, xh^2 and 2 xh xl are exact and so is (xh^2 - p) + 2 xh xl; only
// xl^2 rounds, which leaves q = x^2 - p with a relative error of 2^-53. Then
// exp(-x^2) = exp(-p) (1 - q) to double precision (|q| <= ulp(p)/2 <=
// 6e-14, so the dropped q^2/2 is below 2e-27). Without q the rounding of x^2
// alone costs up to x^2/2 ulp (360 ulp at x = 27). Every product is exact,
// so no fused multiply-add is needed and SSE4 gets the accuracy of AVX2.
template <class D, class V>
HWY_INLINE V ExpNegSquareF64Unguarded(D d, V x) {
  const hn::RebindToUnsigned<D> du;
  const V xh = hn::And(x, hn::BitCast(d, hn::Set(du, uint64_t{0xFFFFFFFFF8000000u})));
  const V xl = hn::Sub(x, xh);
  const V p = hn::Mul(x, x);
  const V q = hn::MulAdd(xl, xl, hn::MulAdd(hn::Add(xh, xh), xl, hn::MulSub(xh, xh, p)));
  const V e = hn::Exp(d, hn::Neg(p));
  return hn::NegMulAdd(e, q, e);
}

// exp(-x^2) for any double x (NaN propagates; 0 for |x| > 27.3, where the
// true value is below half the smallest subnormal).
// Error: |err| <= 3.3e-16 exp(-x^2) + 4.9e-324 (one subnormal ulp, the
// results are subnormal for |x| > 26.6). Measured max relative error where
// normal 2.2e-16 in the test on every target (2.45e-16 on SSE4 over 1e6
// points), 1 subnormal ulp below.
// Cost: 9 add/mul/FMA/logic ops + hn::Exp (~35 ops: 11-term Estrin,
// two-part reduction, exponent reconstruction) + 3 for the guard.
template <class D, class V>
HWY_INLINE V ExpNegSquareF64(D d, V x) {
  // Beyond 28, x^2 may overflow and q would be NaN; the value is 0 there.
  return hn::IfThenZeroElse(hn::Gt(hn::Abs(x), hn::Set(d, 28.0)), ExpNegSquareF64Unguarded(d, x));
}

// Beckmann's unit-roughness Smith Lambda, a = cot(theta) / alpha:
//   Lambda(a) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 = ierfc(a) / (2 a)
//             = exp(-a^2) h(a) / (2 sqrt(pi) a),
//   h(a) = 1 - sqrt(pi) a erfcx(a)  (A&S 7.2.1; h -> 1/(2 a^2) at infinity),
// with nothing that cancels: h is fitted directly. w(a) = 1 + sqrt(pi) a +
// 2 a^2 matches h's value, slope and decay at both ends, so that
//   F(a) = h(a) w(a) / (2 sqrt(pi))  stays within [0.282, 0.335]
// (a flat target keeps the polynomial's evaluation error near 1 ulp;
// fitting h (1 + a/c)^2 instead converges a little faster, but that target
// falls to 0.04 at the far end, where a trial lost 1.9e-15 to the rounding
// of the coefficients and of Horner's steps). F is a polynomial P of degree 23
// in
//   x = (c - k a) / (c + a),  c = 4, k = 165/128,
// which maps a in [0, a_max] onto [1, -1], a_max = 2c / (k - 1) = 27.68
// (Lambda rounds to 0 beyond a = 27.1), and takes out the algebraic decay in
// a (as s = (2 - x)/(2 + x) does in math-inl.h): P converges geometrically.
// Then
//   Lambda = exp(-a^2) P(x) (c + a) / den,  den = a (c + a) w(a),
//   1 / (c + a) = a w(a) / den:
// a single division. With c = 4, den = 4 a exactly for subnormal a, and
// 1 / den overflows only where Lambda does (a < 1.4e-309; x is clamped to 1
// so that the polynomial stays finite there).
//
// P was fitted with mpmath 1.3 (50 digits), Chebyshev interpolation:
//   from mpmath import mp, mpf, sqrt, pi, erfc, exp, chebyfit
//   mp.dps = 50
//   c, k = 4, mpf(165) / 128
//   h = lambda a: 1 - sqrt(pi) * a * erfc(a) * exp(a * a)
//   F = lambda a: h(a) * (1 + sqrt(pi) * a + 2 * a * a) / (2 * sqrt(pi))
//   a_of_x = lambda x: c * (1 - x) / (k + x)
//   poly, err = chebyfit(lambda x: F(a_of_x(x)), [-1, 1], 24, error=True)
// Fit error 1.9e-17 absolute (6.7e-17 relative to F), below half an ulp;
// coefficients rounded to double (%.17g), highest degree first.
//
// Range: any double a: +inf for a <= 0 (on or below the horizon) and for
// 0 < a < 1.57e-309 (the true value exceeds DBL_MAX), 0 for a > 27.5 and
// a = +inf, NaN for NaN.
// Error: |err| <= 1.5e-15 Lambda + 4.9e-324 (one subnormal ulp; Lambda is
// subnormal for a > 26.5), hence |err| <= 2e-15 max(1, Lambda), on every
// target. Measured (tests/kernels/simd_math_f64_test.cc, 24k points, the same on
// AVX3, AVX2, SSE4, SSSE3 and SCALAR): 7.3e-16 relative where normal
// (8.5e-16 over 400k points), 7.3e-16 max(1, Lambda), 1 subnormal ulp.
// Cost per vector: 1 division, 37 add/mul/FMA/min (24 in the polynomial,
// as two interleaved Horner chains in x^2 for half the latency), 9 for
// exp(-a^2) besides hn::Exp (~35 ops), 4 compares and selects: about 85
// ops, no branches. Measured 1.6 ns per value on AVX3 (8 lanes), 3.2 ns on
// AVX2, 9.5 ns on SSE4; about 3 times hn::Exp alone.
// P(x) of F in the fit's variable x (see above), x in [-1, 1]: two
// interleaved Horner chains in x^2 (BeckmannLambdaF64, ErfcxF64).
template <class D, class V>
HWY_INLINE V BeckmannFPolyF64(D d, V x) {
  static constexpr double kP[24] = {
      2.3088759449293881e-10,  -1.1523855837075012e-09, -3.3732790536941273e-09,
      1.5884261771572756e-08,  3.6860915155739234e-08,  -1.3547786578784028e-07,
      -4.1825639643590009e-07, 8.30222957210712e-07,    4.8161618048257746e-06,
      -1.7816783820065462e-07, -4.6422840727152118e-05, -0.00011036672903095425,
      0.00014600237473497987,  0.0016819814082406552,   0.0057925054537865932,
      0.012456268222644201,    0.017841724983471554,    0.013987034954056862,
      -0.0056862937325805642,  -0.03617527776421077,    -0.055476632716579398,
      -0.035353592316747465,   0.03310033065640583,     0.32993256688735229};
  // P(x) = E(x^2) + x O(x^2); kP[0] is the x^23 coefficient (odd).
  const V y = hn::Mul(x, x);
  V odd = hn::Set(d, kP[0]);
  V even = hn::Set(d, kP[1]);
  for (size_t i = 2; i < 24; i += 2) {
    odd = hn::MulAdd(odd, y, hn::Set(d, kP[i]));
    even = hn::MulAdd(even, y, hn::Set(d, kP[i + 1]));
  }
  return hn::MulAdd(odd, x, even);
}

template <class D, class V>
HWY_INLINE V BeckmannLambdaF64(D d, V a) {
  const V c = hn::Set(d, 4.0);
  const V c_a = hn::Add(c, a);
  const V w = hn::MulAdd(hn::MulAdd(hn::Set(d, 2.0), a, hn::Set(d, 1.7724538509055160)), a,
                         hn::Set(d, 1.0));
  const V aw = hn::Mul(a, w);
  const V inv = hn::Div(hn::Set(d, 1.0), hn::Mul(aw, c_a));
  const V r = hn::Mul(aw, inv);  // 1 / (c + a)
  const V x = hn::Min(hn::Mul(hn::NegMulAdd(hn::Set(d, 165.0 / 128.0), a, c), r), hn::Set(d, 1.0));
  const V p = BeckmannFPolyF64(d, x);
  // The exponential multiplies last: where it is subnormal, nothing else
  // rounds on its scale.
  const V lambda = hn::Mul(ExpNegSquareF64Unguarded(d, a), hn::Mul(hn::Mul(p, c_a), inv));
  const V v = hn::IfThenZeroElse(hn::Gt(a, hn::Set(d, 27.5)), lambda);
  return hn::IfThenElse(hn::Le(a, hn::Zero(d)), hn::Inf(d), v);
}

// erfcx(a) = exp(a^2) erfc(a) for a >= 0 (the visible-slope CDF of
// Beckmann's sampler in double lanes, kernels/beckmann_sampling-inl.h):
//  - a < 1/2: exp(a^2) (1 - erf(a)), erf by its Maclaurin series
//    (2 / sqrt(pi)) sum_n (-1)^n a^(2n+1) / (n! (2n+1)), n <= 12 (the first
//    term left out is below 2e-18 of erf at a = 1/2); 1 - erf >= 0.479
//    there, so the subtraction keeps its relative precision.
//  - a >= 1/2: from F = P(x) of BeckmannLambdaF64's fit (h = 2 sqrt(pi) F / w,
//    h = 1 - sqrt(pi) a erfcx(a), w = 1 + sqrt(pi) a + 2 a^2):
//      erfcx(a) = (w - 2 sqrt(pi) P) / (sqrt(pi) a w),
//    where h <= 0.46, so the numerator loses at most a factor 2.2 of P's
//    precision; up to a = 27, inside the fit's range;
//  - a >= 27: the asymptotic series (below).
// Range: any a >= 0 (+inf gives 0); NaN for NaN. Error: |err| <= 1e-15
// erfcx(a) on every target (tests/kernels/simd_math_f64_test.cc, CheckErfcxF64,
// 40k points against 50-digit values: measured 4.4e-16, the same on AVX3,
// AVX2, SSE4, SSSE3 and SCALAR). Cost: one hn::Exp, four divisions and
// ~50 FMA (all three forms are computed and selected per lane).
template <class D, class V>
HWY_INLINE V ErfcxF64(D d, V a) {
  // Series: (2 / sqrt(pi)) (-1)^n / (n! (2n + 1)), highest n first.
  static constexpr double kErf[13] = {
      9.4227590646504113e-11,  -1.2290555301717928e-09, 1.4807192815879218e-08,
      -1.6365844691234924e-07, 1.6462114365889248e-06,  -1.492565035840625e-05,
      0.00012055332981789664,  -0.00085483270234508533, 0.0052239776254421879,
      -0.026866170645131252,   0.11283791670955126,     -0.37612638903183754,
      1.1283791670955126};
  const V one = hn::Set(d, 1.0), sqrt_pi = hn::Set(d, 1.7724538509055160);
  const V y = hn::Mul(a, a);
  V erf_poly = hn::Set(d, kErf[0]);
  for (int i = 1; i < 13; ++i) erf_poly = hn::MulAdd(erf_poly, y, hn::Set(d, kErf[i]));
  const V small = hn::Mul(hn::Exp(d, y), hn::NegMulAdd(erf_poly, a, one));
  const V c = hn::Set(d, 4.0);
  const V x = hn::Min(
      hn::Div(hn::NegMulAdd(hn::Set(d, 165.0 / 128.0), a, c), hn::Add(c, a)), one);
  const V w = hn::MulAdd(hn::MulAdd(hn::Set(d, 2.0), a, sqrt_pi), a, one);
  const V num = hn::NegMulAdd(hn::Set(d, 3.5449077018110322), BeckmannFPolyF64(d, x), w);
  const V large = hn::Div(num, hn::Mul(hn::Mul(sqrt_pi, a), w));
  // Beyond the fit (a > 27.7): the asymptotic series (A&S 7.1.23) in t =
  // 1 / (2 a^2), sum_n (-1)^n (2n - 1)!! t^n for n <= 8, whose first term
  // left out is below 2e-21 from a = 27 on.
  const V t = hn::Div(hn::Set(d, 0.5), y);
  V asym = hn::Set(d, 2027025.0);
  for (double k : {-135135.0, 10395.0, -945.0, 105.0, -15.0, 3.0, -1.0, 1.0}) {
    asym = hn::MulAdd(asym, t, hn::Set(d, k));
  }
  const V far = hn::Div(asym, hn::Mul(sqrt_pi, a));
  return hn::IfThenElse(hn::Lt(a, hn::Set(d, 0.5)), small,
                        hn::IfThenElse(hn::Lt(a, hn::Set(d, 27.0)), large, far));
}

// exp(x) for x in [-700, 700], no range guard (outside, the exponent
// wraps): hn::Exp's reduction and polynomial (x = k ln 2 + r, ln 2 in two
// parts, |r| <= ln(2)/2, e^r - 1 - r by its 11-term Estrin polynomial)
// without its conversions to and from int32 and its two-step scaling: k
// is rounded by adding 1.5 2^52, whose low mantissa bits then hold k, and
// 2^k is applied by adding k << 52 to the bits of e^r in [0.7, 1.5] (the
// result stays normal: |k| <= 1010). Error: |err| <= 3e-16 exp(x) on every
// target (tests/kernels/simd_math_f64_test.cc, CheckExpF64Unguarded, 60k
// points against 50-digit values: measured 2.2e-16 on AVX3, AVX2, SSE4,
// SSSE3 and SCALAR, as hn::Exp). Cost: 20 add/mul/FMA/integer ops, about
// 0.6x hn::Exp's time in double lanes on AVX3.
template <class D, class V>
HWY_INLINE V ExpF64Unguarded(D d, V x) {
  const hn::RebindToSigned<D> di;
  const V shift = hn::Set(d, 6755399441055744.0);  // 1.5 2^52
  const V kf = hn::MulAdd(x, hn::Set(d, 1.442695040888963407359924681), shift);
  const V k = hn::Sub(kf, shift);
  V r = hn::MulAdd(k, hn::Set(d, -0.6931471805596629565116018), x);
  r = hn::MulAdd(k, hn::Set(d, -0.28235290563031577122588448175e-12), r);
  // hn::Exp's coefficients (Highway 1.0.3, contrib/math/math-inl.h, ExpPoly).
  const V r2 = hn::Mul(r, r), r4 = hn::Mul(r2, r2), r8 = hn::Mul(r4, r4);
  const V p01 = hn::MulAdd(hn::Set(d, 0.166666666666666851703837), r, hn::Set(d, 0.5));
  const V p23 = hn::MulAdd(hn::Set(d, 0.00833333333331652721664984), r, hn::Set(d, 0.0416666666666665047591422));
  const V p45 = hn::MulAdd(hn::Set(d, 0.000198412698960509205564975), r, hn::Set(d, 0.00138888888889774492207962));
  const V p67 = hn::MulAdd(hn::Set(d, 2.75572362911928827629423e-6), r, hn::Set(d, 2.4801587159235472998791e-5));
  const V p89 = hn::MulAdd(hn::Set(d, 2.51112930892876518610661e-8), r, hn::Set(d, 2.75573911234900471893338e-7));
  const V p03 = hn::MulAdd(p23, r2, p01), p47 = hn::MulAdd(p67, r2, p45);
  const V p810 = hn::MulAdd(hn::Set(d, 2.08860621107283687536341e-9), r2, p89);
  const V p = hn::MulAdd(p810, r8, hn::MulAdd(p47, r4, p03));
  const V y = hn::Add(hn::MulAdd(p, r2, r), hn::Set(d, 1.0));
  return hn::BitCast(d, hn::Add(hn::BitCast(di, y), hn::ShiftLeft<52>(hn::BitCast(di, kf))));
}

// sin(t) for t in [-pi/2, pi/2], no range reduction: t + t u Q(u), u =
// t^2, Q the Taylor series of (sin(t) - t) / t^3 to t^21 (the first term
// left out, t^23 / 23!, is below 1.3e-18 at |t| = pi/2), by Estrin's
// scheme. Error: within 5e-16 |sin(t)| + 1e-32 on every target
// (CheckSinF64HalfPi, 65k points against 50-digit values, t uniform over
// [-pi/2, pi/2] and near 0: measured 2.9e-16 on every target). Cost: 15
// add/mul/FMA ops.
template <class D, class V>
HWY_INLINE V SinF64HalfPi(D d, V t) {
  const V u = hn::Mul(t, t), u2 = hn::Mul(u, u), u4 = hn::Mul(u2, u2), u8 = hn::Mul(u4, u4);
  // (-1)^(k+1) / (2k + 3)!, k = 0..9.
  const V q01 = hn::MulAdd(hn::Set(d, 1.0 / 120), u, hn::Set(d, -1.0 / 6));
  const V q23 = hn::MulAdd(hn::Set(d, 1.0 / 362880), u, hn::Set(d, -1.0 / 5040));
  const V q45 = hn::MulAdd(hn::Set(d, 1.0 / 6227020800.0), u, hn::Set(d, -1.0 / 39916800));
  const V q67 = hn::MulAdd(hn::Set(d, 1.0 / 355687428096000.0), u, hn::Set(d, -1.0 / 1307674368000.0));
  const V q89 = hn::MulAdd(hn::Set(d, 1.0 / 51090942171709440000.0), u, hn::Set(d, -1.0 / 121645100408832000.0));
  const V q03 = hn::MulAdd(q23, u2, q01), q47 = hn::MulAdd(q67, u2, q45);
  const V q = hn::MulAdd(q89, u8, hn::MulAdd(q47, u4, q03));
  return hn::MulAdd(hn::Mul(t, u), q, t);
}

// cos(x) for x in [0, pi], no range reduction: cos(x) = sin(t), t = pi/2 -
// x in [-pi/2, pi/2], pi/2 in two parts (pi/2 - x is exact for x >= pi/4,
// and below, where cos is near 1, its rounding costs at most 1.2e-16 sin(x)),
// and sin(t) by SinF64HalfPi. Error: |err| <= 5e-16 (absolute) and
// 5e-16 |cos(x)| + 1e-32 on every target (CheckCosF64ZeroToPi, 65k points
// against 50-digit values, x uniform over [0, pi], near 0, pi/2 and pi:
// measured 3.0e-16 on AVX3 and AVX2, 4.4e-16 without fused multiply-adds
// on SSE4, SSSE3 and SCALAR, near cos = +-1). Cost: 16 add/mul/FMA ops,
// about half of hn::Cos's time in double lanes on AVX3.
template <class D, class V>
HWY_INLINE V CosF64ZeroToPi(D d, V x) {
  return SinF64HalfPi(d, hn::Add(hn::Sub(hn::Set(d, 1.5707963267948966), x), hn::Set(d, 6.123233995736766e-17)));
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_MATH_F64_INL_H_
