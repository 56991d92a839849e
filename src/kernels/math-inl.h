// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Float-lane special functions that Highway 1.0.3's hwy/contrib/math lacks:
// exp(-x^2) without the rounding of x^2, the scaled complementary error
// function erfcx, erfc, and the scaled first repeated integral of erfc that
// Beckmann's Smith Lambda is made of. Each function states its range and the
// error measured against the double references by
// tests/kernels/simd_beckmann_test.cc (SimdBeckmannTest.CheckMath, every target).
//
// The polynomials were fitted here (mpmath chebyfit, 30 digits) in the
// variable s = (2 - x) / (2 + x), which maps [0, +inf) onto (-1, 1]:
// t = 2 / (2 + x) = (1 + s) / 2 takes out the 1/x decay of both functions,
// and what is left is smooth on the closed interval (its expansion at
// x = inf is in powers of 1/x^2 = (t / (2 (1 - t)))^2). The fit error is
// 2.8e-8 relative for erfcx (degree 10) and 5.2e-8 for h (degree 12), below
// float rounding.

#if defined(BRDFBAKE_SRC_KERNELS_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_MATH_INL_H_
#undef BRDFBAKE_SRC_KERNELS_MATH_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_MATH_INL_H_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Horner evaluation of c[0] s^(K-1) + ... + c[K-1] (highest degree first).
template <size_t K, class D, class V>
HWY_INLINE V HornerHighFirst(D d, const float (&c)[K], V s) {
  V acc = hn::Set(d, c[0]);
  for (size_t k = 1; k < K; ++k) acc = hn::MulAdd(acc, s, hn::Set(d, c[k]));
  return acc;
}

// exp(-x^2) for any float x. x^2 = p + q exactly, p = fl(x * x), by Dekker's
// product: x is split (Veltkamp, by masking the low 12 mantissa bits) into a
// 12-bit head xh and a tail xl = x - xh, and q = ((xh^2 - p) + 2 xh xl) + xl^2
// with every operation exact. Then exp(-x^2) = exp(-p) (1 - q) to float
// precision (|q| <= ulp(p)/2, so the dropped q^2/2 is below 1e-10). Without
// this the rounding of x^2 alone costs up to x^2/2 ulp (40 ulp at x = 9). No
// fused multiply-add is needed, so SSE4 gets the same accuracy as AVX2.
// Error: 1.5e-7 relative where the result is a normal float (|x| <= 9.3);
// 3 * 2^-149 absolute below (subnormal), 0 beyond |x| = 10.2 (Highway's Exp
// flushes below exp(-104)).
template <class D, class V>
HWY_INLINE V ExpNegSquare(D d, V x) {
  const hn::RebindToUnsigned<D> du;
  const V xh = hn::And(x, hn::BitCast(d, hn::Set(du, 0xFFFFF000u)));
  const V xl = hn::Sub(x, xh);
  const V p = hn::Mul(x, x);
  const V q = hn::MulAdd(xl, xl,
                         hn::MulAdd(hn::Add(xh, xh), xl, hn::MulSub(xh, xh, p)));
  const V e = hn::Exp(d, hn::Neg(p));
  return hn::NegMulAdd(e, q, e);
}

// erfcx(x) = exp(x^2) erfc(x) for x >= 0 (x = +inf gives 0):
//   erfcx(x) = 2 P(s) / (2 + x),  s = (2 - x) / (2 + x),
// P of degree 10 fitted to erfcx(x) (1 + x/2) (P(-1) = 1 / (2 sqrt(pi)) is
// the 1 / (x sqrt(pi)) tail). One division.
// Error: 3e-7 relative on [0, +inf) (measured max 2.7e-7 in the test).
template <class D, class V>
HWY_INLINE V Erfcx(D d, V x) {
  static constexpr float kP[11] = {
      4.428841467e-05f, -3.676436164e-05f, -3.047190864e-04f, 4.310400216e-04f,
      1.533847044e-03f, -3.243733068e-03f, -1.075331088e-02f, 1.822174911e-02f,
      1.397359458e-01f, 3.435803125e-01f,  5.107913526e-01f};
  const V two = hn::Set(d, 2.0f);
  const V x_fin = hn::Min(x, hn::Set(d, 1e30f));  // keeps s finite for x = inf
  const V r = hn::Div(hn::Set(d, 1.0f), hn::Add(two, x_fin));
  const V s = hn::Mul(hn::Sub(two, x_fin), r);
  const V p = HornerHighFirst(d, kP, s);
  return hn::IfThenZeroElse(hn::IsInf(x), hn::Mul(hn::Mul(two, p), r));
}

// erfc(x) for any float x: exp(-x^2) erfcx(|x|), reflected as 2 - erfc(-x)
// for x < 0. Range: all floats (NaN propagates); 0 beyond x = 10.05 (the
// true value is below the smallest float).
// Error: 3.5e-7 relative where erfc(x) >= FLT_MIN (x <= 9.19; measured
// max 3.1e-7 in the test),
// 3 * 2^-149 absolute beyond.
template <class D, class V>
HWY_INLINE V Erfc(D d, V x) {
  const V ax = hn::Abs(x);
  const V pos = hn::Mul(ExpNegSquare(d, ax), Erfcx(d, ax));
  return hn::IfThenElse(hn::Lt(x, hn::Zero(d)), hn::Sub(hn::Set(d, 2.0f), pos), pos);
}

// h(a) = 1 - sqrt(pi) a erfcx(a) = sqrt(pi) exp(a^2) ierfc(a) for a >= 0,
// ierfc(a) = integral_a^inf erfc(t) dt = exp(-a^2)/sqrt(pi) - a erfc(a) (the
// first repeated integral of erfc, Abramowitz and Stegun 7.2.1). h falls from
// 1 at a = 0 to 1/(2 a^2) - 3/(4 a^4) + ... at infinity; the difference
// 1 - sqrt(pi) a erfcx(a) cancels (2 a^2 digits lost), so h is fitted
// directly:
//   h(a) = Q(s) / (1 + 2 a^2),  s = (2 - a) / (2 + a),
// Q of degree 12 fitted to h(a) (1 + 2 a^2) (Q -> 1 at both ends). No
// cancellation anywhere. Returns (numerator Q, denominator 1 + 2 a^2) so
// that callers can merge the division into their own.
// Error of Q / (1 + 2 a^2): 3e-7 relative for 0 <= a <= 1.3e19, where the
// denominator overflows (measured max 2.6e-7 in the test); a = +inf gives
// Q = 1, denominator inf.
template <class D, class V>
HWY_INLINE void IerfcScaled(D d, V a, V* num, V* den) {
  static constexpr float kQ[13] = {
      4.673399887e-04f,  -7.229179343e-04f, -2.674473510e-03f, 5.943229473e-03f,
      9.096929935e-03f,  -3.062389554e-02f, -4.017963603e-02f, 1.281166500e-01f,
      3.563587880e-01f,  2.585917372e-01f,  -1.748820183e-01f, -3.613048244e-01f,
      8.518131003e-01f};
  const V two = hn::Set(d, 2.0f);
  const V a_fin = hn::Min(a, hn::Set(d, 1e30f));
  const V s = hn::Div(hn::Sub(two, a_fin), hn::Add(two, a_fin));
  *num = HornerHighFirst(d, kQ, s);
  *den = hn::MulAdd(hn::Mul(two, a), a, hn::Set(d, 1.0f));
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_MATH_INL_H_
