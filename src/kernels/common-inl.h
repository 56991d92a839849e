// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// SIMD helpers every model's kernels share (float or double lanes): the refined
// reciprocal square root, wo.h from the unnormalized half vector, Schlick's
// Fresnel functor, the compile-time masking switch and Smith G1 / G2 from
// a Lambda kernel.

#if defined(BRDFBAKE_SRC_KERNELS_COMMON_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_COMMON_INL_H_
#undef BRDFBAKE_SRC_KERNELS_COMMON_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_COMMON_INL_H_
#endif

#include <type_traits>

#include <hwy/highway.h>

#include "brdfbake/models/brdf.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// 1 / sqrt(x). Float lanes: the hardware estimate and one Newton step
// (2 ulp); the portable fallbacks (SCALAR, EMU128) only have a coarse
// estimate, so they use the exact square root instead. Double lanes: the
// exact square root and a division (an estimate would need three Newton
// steps).
template <class D, class V>
HWY_INLINE V RsqrtNewton(D d, V x) {
  using T = hn::TFromD<D>;
  if constexpr (sizeof(T) == 8) {
    return hn::Div(hn::Set(d, T(1)), hn::Sqrt(x));
  } else {
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
    return hn::Div(hn::Set(d, 1.0f), hn::Sqrt(x));
#else
    const V y = hn::ApproximateReciprocalSqrt(x);
    const V half_x = hn::Mul(x, hn::Set(d, 0.5f));
    return hn::Mul(y, hn::NegMulAdd(hn::Mul(half_x, y), y, hn::Set(d, 1.5f)));
#endif
  }
}

// wo.h with h = s / |s|, len2 = |s|^2, clamped to [0, 1] (shared by every
// model's BRDF kernel).
template <class D, class V>
HWY_INLINE V CosAtHalf(D d, V ox, V oy, V oz, V sx, V sy, V sz, V len2) {
  const V wo_s = hn::MulAdd(ox, sx, hn::MulAdd(oy, sy, hn::Mul(oz, sz)));
  using T = hn::TFromD<D>;
  const V safe_len2 = hn::Max(len2, hn::Set(d, T(1e-30)));
  return hn::Min(hn::Mul(wo_s, RsqrtNewton(d, safe_len2)), hn::Set(d, T(1)));
}

// Schlick's Fresnel F0 + (1 - F0)(1 - c)^5 of a cosine: the default
// Fresnel of the BRDF kernels, which take any functor F(d, cos) (the
// dielectric and conductor ones are in kernels/fresnel-inl.h).
template <class D>
struct SchlickFresnel {
  hn::Vec<D> f0;
  template <class V>
  HWY_INLINE V operator()(D d, V cos_d) const {
    using T = hn::TFromD<D>;
    const V m = hn::Max(hn::Sub(hn::Set(d, T(1)), cos_d), hn::Zero(d));
    const V m2 = hn::Mul(m, m);
    return hn::MulAdd(hn::Sub(hn::Set(d, T(1)), f0), hn::Mul(hn::Mul(m2, m2), m), f0);
  }
};

// The width terms of the GGX and Beckmann constants from per-element
// widths, one per lane: alpha clamped below at 1e-4, alpha^2, 1 / alpha^2
// and 1 / (pi ax ay), with two divisions per vector (1 / ax, 1 / ay); they
// round in the lanes' type, a little apart from the per-call constants.
template <class D>
struct WidthLanes {
  hn::Vec<D> ax, ay, ax2, ay2, inv_ax2, inv_ay2, inv_pi_axay;
  WidthLanes(D d, hn::Vec<D> ax_, hn::Vec<D> ay_) {
    using T = hn::TFromD<D>;
    const hn::Vec<D> one = hn::Set(d, T(1)), lo = hn::Set(d, T(1e-4));
    ax = hn::Max(ax_, lo);
    ay = hn::Max(ay_, lo);
    ax2 = hn::Mul(ax, ax);
    ay2 = hn::Mul(ay, ay);
    const hn::Vec<D> inv_ax = hn::Div(one, ax), inv_ay = hn::Div(one, ay);
    inv_ax2 = hn::Mul(inv_ax, inv_ax);
    inv_ay2 = hn::Mul(inv_ay, inv_ay);
    inv_pi_axay = hn::Mul(hn::Set(d, T(0.31830988618379067)), hn::Mul(inv_ax, inv_ay));
  }
};

// Calls f(separable) with separable a std::true_type or std::false_type, so
// that a kernel's `if (separable)` is resolved at compile time and the loop
// around it has no branch (GCC does not unswitch these loops by itself once
// the Fresnel functor is a template argument: 15% of the GGX BRDF on AVX3).
template <class F>
HWY_INLINE void WithMasking(Masking masking, const F& f) {
  if (masking == Masking::kSeparable) {
    f(std::true_type());
  } else {
    f(std::false_type());
  }
}

// Smith masking from a Lambda kernel `lambda(w_x, w_y, w_z)` (+inf on and
// below the horizon): G1 = 1 / (1 + Lambda), and for a reflection pair G2 =
// 1 / (1 + Lambda_i + Lambda_o) (height-correlated) or G1(wi) G1(wo)
// (separable); wi.h = wo.h = |wi + wo| / 2 >= 0 for every pair, and wi = -wo
// puts both on the horizon, where Lambda = +inf makes G2 = 0.
template <class D, class V, class L>
HWY_INLINE V G1FromLambda(D d, const L& lambda, V wx, V wy, V wz) {
  using T = hn::TFromD<D>;
  return hn::Div(hn::Set(d, T(1)), hn::Add(hn::Set(d, T(1)), lambda(wx, wy, wz)));
}
template <class D, class V, class L>
HWY_INLINE V G2FromLambda(D d, bool separable, const L& lambda, V ix, V iy, V iz, V ox, V oy,
                          V oz) {
  const V one = hn::Set(d, hn::TFromD<D>(1));
  const V li = lambda(ix, iy, iz), lo = lambda(ox, oy, oz);
  if (separable) return hn::Div(one, hn::Mul(hn::Add(one, li), hn::Add(one, lo)));
  return hn::Div(one, hn::Add(one, hn::Add(li, lo)));
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_COMMON_INL_H_
