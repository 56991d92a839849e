// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen ([EstevezKulla17]) and the Disney diffuse ([Burley12])
// kernels, generic over the lanes' type: the batch API runs them in float
// lanes (batch_charlie.cc, batch_disney.cc), the baker's rules in double
// lanes (lanes/sheen_lanes.cc). The scalar twins are CharlieSheen<T> in
// include/brdfbake/models/sheen.h and DisneyDiffuse<T> in
// models/disney_diffuse.h, whose comments give the formulas:
//
//   D = k exp(q log(s^2)) = k exp(q log1p(-c^2)), k = (2 + 1/alpha) / (2 pi),
//     q = 1 / (2 alpha), c = cos(theta_m), s = sin(theta_m); 0 at c >= 1;
//   Lambda(c) = exp(L(c)) (c < 1/2), exp(2 L(1/2) - L(1 - c)) (c >= 1/2),
//     L(x) = a / (1 + b exp(p log x)) + d x + e;
//   V = 1 / (4 (NoL + NoV - NoL NoV)) (neubelt) or G2 / (4 NoL NoV),
//     G2 = 1 / (1 + Lambda(NoV) + Lambda(NoL)) (conty-kulla, enterprise-pbr,
//     each with its fit of L), min(V, 1) for the clamped variants;
//   Disney: pi f = (1 + g (1 - NoL)^5) (1 + g (1 - NoV)^5),
//     g = (r - 1/2) + r L.V.
//
// Error against the double reference at the same float inputs (the bounds
// of kernel_bounds.h, asserted on every target by
// tests/kernels/simd_sheen_test.cc):
//   D:      relative 2e-6 + 3e-7 |q log(s^2)| + 1.2e-7 q (the exponent's
//           rounding, amplified by exp as for Beckmann's, and the rounding
//           of s^2 = sin(theta_m)^2, amplified by the power q: a narrow
//           lobe is ill-conditioned in float);
//   Lambda: relative 2e-6 + 3e-7 (|L| + 20) (the same for exp(L));
//   G1, G2: absolute 4e-6;
//   BRDF:   relative 4e-6 + 3e-7 |q log(s^2)| + 2e-7 q, plus (conty-kulla)
//           3e-7 (|L_i| + |L_o| + 20) for charlie; relative 2e-6 for disney.
// The baker's double lanes (lanes/sheen_lanes.cc) use the Lambda kernel;
// CharlieDCos2 is D in double lanes at cos^2, the form of the reference's
// DCos2, checked to 1e-13 on every target.
// Where the float exponential underflows (q log1p(-c^2) < -87.3), D and the
// BRDF are 0 after the batch functions' subnormal flush.

#if defined(BRDFBAKE_SRC_KERNELS_SHEEN_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_SHEEN_INL_H_
#undef BRDFBAKE_SRC_KERNELS_SHEEN_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_SHEEN_INL_H_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "brdfbake/models/constants.h"
#include "brdfbake/models/sheen.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants of the Charlie kernels, the width clamped as in
// ClampSheenAlpha and every constant formed in double.
template <class D>
struct CharlieConsts {
  using T = hn::TFromD<D>;
  hn::Vec<D> k, q, a, b, p, dd, e, two_l_half;
  bool neubelt;  // V has no Lambda
  bool clamp;    // V capped at 1
  CharlieConsts(D d, double alpha, SheenVisibility visibility) {
    const double al = ClampSheenAlpha(alpha);
    const CharlieLFit<double> fit(al, visibility);
    k = hn::Set(d, static_cast<T>((2 + 1 / al) / kTwoPi<double>));
    q = hn::Set(d, static_cast<T>(0.5 / al));
    a = hn::Set(d, static_cast<T>(fit.a));
    b = hn::Set(d, static_cast<T>(fit.b));
    p = hn::Set(d, static_cast<T>(fit.p));
    dd = hn::Set(d, static_cast<T>(fit.d));
    e = hn::Set(d, static_cast<T>(fit.e));
    two_l_half = hn::Set(d, static_cast<T>(2 * fit(0.5)));
    neubelt = !SheenHasLambda(visibility);
    clamp = SheenClampsVisibility(visibility);
  }
};

// D at c^2 = cos(theta_m)^2 in [0, 1]: k (1 - c^2)^q, 0 at c^2 >= 1.
template <class D, class V>
HWY_INLINE V CharlieDCos2(D d, const CharlieConsts<D>& c, V cos2) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1));
  const auto below = hn::Lt(cos2, one);
  const V x = hn::IfThenElse(below, hn::Neg(cos2), hn::Zero(d));
  const V v = hn::Mul(c.k, hn::Exp(d, hn::Mul(c.q, hn::Log1p(d, x))));
  return hn::IfThenElseZero(below, v);
}

// D at s2 = sin(theta_m)^2 in [0, 1]: k exp(q log(s2)), 0 at s2 <= 0.
template <class D, class V>
HWY_INLINE V CharlieDSin2(D d, const CharlieConsts<D>& c, V s2) {
  using T = hn::TFromD<D>;
  const auto pos = hn::Gt(s2, hn::Zero(d));
  const V x = hn::Min(hn::IfThenElse(pos, s2, hn::Set(d, T(1))), hn::Set(d, T(1)));
  return hn::IfThenElseZero(pos, hn::Mul(c.k, hn::Exp(d, hn::Mul(c.q, hn::Log(d, x)))));
}

// D(m) from m.z: sin^2 = (1 - m.z)(1 + m.z), exact in the lanes' type near
// m.z = 1, where 1 - m.z^2 would lose the digits the power q amplifies.
template <class D, class V>
HWY_INLINE V CharlieD(D d, const CharlieConsts<D>& c, V mz) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1));
  const V s2 = hn::Mul(hn::Sub(one, mz), hn::Add(one, mz));
  return hn::IfThenElseZero(hn::Gt(mz, hn::Zero(d)), CharlieDSin2(d, c, s2));
}

// L(x) for x in [0, 1] (x^p = exp(p log x), 0 at x = 0).
template <class D, class V>
HWY_INLINE V CharlieLOf(D d, const CharlieConsts<D>& c, V x) {
  using T = hn::TFromD<D>;
  const auto pos = hn::Gt(x, hn::Zero(d));
  const V xs = hn::IfThenElse(pos, x, hn::Set(d, T(1)));
  const V xp = hn::IfThenElseZero(pos, hn::Exp(d, hn::Mul(c.p, hn::Log(d, xs))));
  const V den = hn::MulAdd(c.b, xp, hn::Set(d, T(1)));
  return hn::Add(hn::MulAdd(c.dd, x, c.e), hn::Div(c.a, den));
}

// The exponent of Lambda at a cosine w in (0, 1]: L(w) below 1/2,
// 2 L(1/2) - L(1 - w) from 1/2 on.
template <class D, class V>
HWY_INLINE V CharlieLogLambda(D d, const CharlieConsts<D>& c, V w) {
  using T = hn::TFromD<D>;
  const V half = hn::Set(d, T(0.5));
  const auto low = hn::Lt(w, half);
  const V x = hn::IfThenElse(low, w, hn::Sub(hn::Set(d, T(1)), w));
  const V l = CharlieLOf(d, c, x);
  return hn::IfThenElse(low, l, hn::Sub(c.two_l_half, l));
}

// Lambda(w.z): +inf at w.z <= 0.
template <class D, class V>
HWY_INLINE V CharlieLambda(D d, const CharlieConsts<D>& c, V wz) {
  using T = hn::TFromD<D>;
  const auto up = hn::Gt(wz, hn::Zero(d));
  const V w = hn::Min(hn::IfThenElse(up, wz, hn::Set(d, T(0.5))), hn::Set(d, T(1)));
  return hn::IfThenElse(up, hn::Exp(d, CharlieLogLambda(d, c, w)), hn::Inf(d));
}

template <class D, class V>
HWY_INLINE V CharlieG1(D d, const CharlieConsts<D>& c, V wz) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1));
  const auto up = hn::Gt(wz, hn::Zero(d));
  const V w = hn::Min(hn::IfThenElse(up, wz, hn::Set(d, T(0.5))), one);
  const V lam = hn::Exp(d, CharlieLogLambda(d, c, w));
  return hn::IfThenElseZero(up, hn::Div(one, hn::Add(one, lam)));
}

// The visibility V(NoL, NoV) for cosines in (0, 1].
template <class D, class V>
HWY_INLINE V CharlieVisibility(D d, const CharlieConsts<D>& c, V nol, V nov) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1)), four = hn::Set(d, T(4));
  V v;
  if (c.neubelt) {
    v = hn::Div(one, hn::Mul(four, hn::NegMulAdd(nol, nov, hn::Add(nol, nov))));
  } else {
    const V lam = hn::Add(hn::Exp(d, CharlieLogLambda(d, c, nol)),
                          hn::Exp(d, CharlieLogLambda(d, c, nov)));
    v = hn::Div(one, hn::Mul(hn::Mul(hn::Mul(four, nol), nov), hn::Add(one, lam)));
  }
  return c.clamp ? hn::Min(v, one) : v;
}

// G2(wi, wo) of the visibilities with a Lambda.
template <class D, class V>
HWY_INLINE V CharlieG2(D d, const CharlieConsts<D>& c, V iz, V oz) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
  const auto up = hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d)));
  const V ci = hn::Min(hn::IfThenElse(up, iz, half), one);
  const V co = hn::Min(hn::IfThenElse(up, oz, half), one);
  const V lam = hn::Add(hn::Exp(d, CharlieLogLambda(d, c, ci)),
                        hn::Exp(d, CharlieLogLambda(d, c, co)));
  return hn::IfThenElseZero(up, hn::Div(one, hn::Add(one, lam)));
}

// f(wi, wo) = D(h) V with F = 1; 0 unless both directions are above the
// horizon. cos^2 of the half vector is (wi.z + wo.z)^2 / |wi + wo|^2.
template <class D, class V>
HWY_INLINE V CharlieBrdf(D d, const CharlieConsts<D>& c, V ix, V iy, V iz, V ox, V oy, V oz) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
  const V sx = hn::Add(ix, ox), sy = hn::Add(iy, oy), sz = hn::Add(iz, oz);
  const V len2 = hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(sz, sz)));
  const auto up = hn::And(hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d))),
                          hn::Gt(len2, hn::Zero(d)));
  const V len2s = hn::IfThenElse(up, len2, one);
  // sin^2 of the half vector: (s.x^2 + s.y^2) / |s|^2, no cancellation.
  const V sin2 = hn::Div(hn::MulAdd(sx, sx, hn::Mul(sy, sy)), len2s);
  const V ci = hn::Min(hn::IfThenElse(up, iz, half), one);
  const V co = hn::Min(hn::IfThenElse(up, oz, half), one);
  const V f = hn::Mul(CharlieDSin2(d, c, sin2), CharlieVisibility(d, c, ci, co));
  return hn::IfThenElseZero(up, f);
}

// The Disney diffuse BRDF at roughness r (base colour 1).
template <class D>
struct DisneyConsts {
  using T = hn::TFromD<D>;
  hn::Vec<D> r, c, inv_pi;
  DisneyConsts(D d, double roughness) {
    const double rr = roughness < 0 ? 0 : roughness > 1 ? 1 : roughness;
    r = hn::Set(d, static_cast<T>(rr));
    c = hn::Set(d, static_cast<T>(rr - 0.5));
    inv_pi = hn::Set(d, static_cast<T>(kInvPi<double>));
  }
};

template <class D, class V>
HWY_INLINE V Pow5(D, V x) {
  const V x2 = hn::Mul(x, x);
  return hn::Mul(hn::Mul(x2, x2), x);
}

template <class D, class V>
HWY_INLINE V DisneyBrdf(D d, const DisneyConsts<D>& c, V ix, V iy, V iz, V ox, V oy, V oz) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1));
  const auto up = hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d)));
  const V lov = hn::MulAdd(ix, ox, hn::MulAdd(iy, oy, hn::Mul(iz, oz)));
  const V g = hn::MulAdd(c.r, lov, c.c);
  const V pl = Pow5(d, hn::Sub(one, hn::Min(iz, one)));
  const V pv = Pow5(d, hn::Sub(one, hn::Min(oz, one)));
  const V f = hn::Mul(hn::Mul(hn::MulAdd(g, pl, one), hn::MulAdd(g, pv, one)), c.inv_pi);
  return hn::IfThenElseZero(up, f);
}

// The azimuthal mean of pi f at cosines nol, nov
// (DisneyDiffuse<T>::AzimuthMean).
template <class D, class V>
HWY_INLINE V DisneyAzimuthMean(D d, const DisneyConsts<D>& c, V nol, V nov) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5)), two = hn::Set(d, T(2));
  const V x = hn::Mul(nol, nov);
  const V s2 = hn::Mul(hn::Mul(hn::Sub(one, nol), hn::Add(one, nol)),
                       hn::Mul(hn::Sub(one, nov), hn::Add(one, nov)));
  const V g1 = hn::MulAdd(c.r, x, c.c);
  const V cr = hn::Mul(c.c, c.r);
  const V g2 = hn::Add(hn::MulAdd(c.c, c.c, hn::Mul(hn::Mul(two, cr), x)),
                       hn::Mul(hn::Mul(c.r, c.r), hn::MulAdd(x, x, hn::Mul(half, s2))));
  const V p = Pow5(d, hn::Sub(one, nol)), q = Pow5(d, hn::Sub(one, nov));
  return hn::Add(hn::MulAdd(g1, hn::Add(p, q), one), hn::Mul(hn::Mul(g2, p), q));
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_SHEEN_INL_H_
