// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Fresnel SIMD kernels, float lanes; the scalar twins (double reference) are
// FresnelDielectric and FresnelConductor in include/brdfbake/models/fresnel.h. Both
// take cos_i = cosine between the direction and the microfacet normal,
// clamped to [0, 1], and return the unpolarized reflectance
// F = (|r_parl|^2 + |r_perp|^2) / 2.
//
// Dielectric, real eta = n_t / n_i. With g = eta cos_t = sqrt(eta^2 - 1 + c^2)
// (Snell: eta^2 sin_t^2 = 1 - c^2) the amplitudes are
//   r_perp = (c - g) / (c + g)             = -(eta^2 - 1) / (c + g)^2,
//   r_parl = (eta^2 c - g) / (eta^2 c + g) =  (eta^2 - 1) W / (eta^2 c + g)^2,
//   W = (eta^2 + 1) c^2 - 1 = (eta^2 + 1)(c^2 - c_B^2), c_B Brewster's cosine,
// the right-hand forms multiplying through by the conjugate sums, so that
// neither difference cancels (eta near 1, where F ~ (eta - 1)^2 is tiny).
// g^2 <= 0 is total internal reflection (eta < 1 only): F = 1. One division
// and one square root per lane.
//
// Conductor, complex eta = n + i k, in real arithmetic: eta cos_t =
// sqrt(u), u = eta^2 - s^2, s^2 = 1 - c^2 = sin_i^2, so
//   Re u = c^2 + (n^2 - k^2 - 1), Im u = 2 n k, sqrt(u) = a + i b,
//   a^2, b^2 = (|u| +- Re u) / 2 (the larger one directly, the smaller one as
//   (n k)^2 / larger, from a b = n k: no cancellation),
//   |r_perp|^2 = ((c - a)^2 + b^2) / ((c + a)^2 + b^2),
//   |r_parl|^2 = |r_perp|^2 ((a c - s^2)^2 + b^2 c^2) / ((a c + s^2)^2 + b^2 c^2),
// which is the usual closed form (a^2 + b^2) c^2 -+ 2 a c s^2 + s^4 written
// as sums of squares. Two divisions and two square roots per lane.
//
// In both, c^2 + e (e = eta^2 - 1, or n^2 - k^2 - 1) is the quantity whose
// square root has an infinite slope at the critical angle; it is evaluated
// in CosSqPlus below to a few ulp relative to its own (small) value.
//
// Error against the double reference at the same float inputs, measured on
// every target by tests/kernels/simd_fresnel_test.cc over dense cos sweeps down to
// 1e-6 and eta in [1/3, 3], n in [0.05, 4], k in [0, 10]:
//   dielectric: |F - F_ref| <= 2e-6 F_ref (relative; measured 7.6e-7),
//               valid for eta in [0.01, 100]; eta = 1 gives exactly 0 (1 at
//               cos = 0, as the reference);
//   conductor:  |F - F_ref| <= 2e-6 F_ref + 1e-7 (measured: 1.9e-6 relative
//               where F > 1e-3, 4.4e-7 absolute; the absolute part covers n
//               near 1 with k near 0, where c - a cancels and F -> 0).

#if defined(BRDFBAKE_SRC_KERNELS_FRESNEL_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_FRESNEL_INL_H_
#undef BRDFBAKE_SRC_KERNELS_FRESNEL_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_FRESNEL_INL_H_
#endif

#include <cmath>

#include <hwy/highway.h>

#include "brdfbake/batch.h"
#include "kernels/common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// c^2 + e for a per-call constant e, accurate relative to the result even
// when it cancels (c near the critical cosine sqrt(-e)). For e < 0 it is
// (c - r)(c + r), r = sqrt(-e) carried as r_hi + r_lo: c - r_hi is exact
// near the root (Sterbenz), so the result has a few ulp of relative error
// on every target, with or without a fused multiply-add. For e >= 0 both
// terms are positive and MulAdd(c, c, e) is within 2 ulp.
template <class D>
struct CosSqPlus {
  hn::Vec<D> e, r_hi, r_lo;
  bool negative;
  CosSqPlus(D d, double e_) : negative(e_ < 0) {
    e = hn::Set(d, static_cast<float>(e_));
    const double r = negative ? std::sqrt(-e_) : 0.0;
    const float hi = static_cast<float>(r);
    r_hi = hn::Set(d, hi);
    r_lo = hn::Set(d, static_cast<float>(r - hi));
  }
  template <class V>
  HWY_INLINE V operator()(V c) const {
    if (!negative) return hn::MulAdd(c, c, e);
    return hn::Mul(hn::Sub(hn::Sub(c, r_hi), r_lo), hn::Add(c, r_hi));
  }
};

template <class D>
struct FresnelDielectricConsts {
  CosSqPlus<D> g2;  // eta^2 - 1 + c^2
  CosSqPlus<D> w;   // W / (eta^2 + 1) = c^2 - 1 / (eta^2 + 1)
  hn::Vec<D> eta2, eta2_plus_1, half_k2;
  bool unit;  // eta == 1: no interface, F = 0 except F(c = 0) = 1
  FresnelDielectricConsts(D d, float eta)
      : g2(d, (double(eta) - 1.0) * (double(eta) + 1.0)),
        w(d, -1.0 / (double(eta) * eta + 1.0)),
        unit(eta == 1.0f) {
    const double e2 = double(eta) * eta;
    eta2 = hn::Set(d, static_cast<float>(e2));
    eta2_plus_1 = hn::Set(d, static_cast<float>(e2 + 1.0));
    const double k = (double(eta) - 1.0) * (double(eta) + 1.0);
    half_k2 = hn::Set(d, static_cast<float>(0.5 * k * k));
  }
};

// F = (k^2 / 2) ((eta^2 c + g)^4 + W^2 (c + g)^4) / ((c + g)^4 (eta^2 c + g)^4),
// k = eta^2 - 1. For float eta != 1, (c + g)(eta^2 c + g) >= |k| >= 1.1e-7,
// so the denominator stays a normal float.
template <class D, class V>
HWY_INLINE V FresnelDielectric(D d, const FresnelDielectricConsts<D>& k, V cos_i) {
  const V one = hn::Set(d, 1.0f);
  const V c = hn::Min(hn::Max(cos_i, hn::Zero(d)), one);
  if (k.unit) return hn::IfThenElse(hn::Gt(c, hn::Zero(d)), hn::Zero(d), one);
  const V g2 = k.g2(c);
  const V g = hn::Sqrt(hn::Max(g2, hn::Zero(d)));
  const V x = hn::Add(c, g);                 // c + g
  const V y = hn::MulAdd(k.eta2, c, g);      // eta^2 c + g
  // W vanishes at Brewster's cosine and, for eta < 1, nearly so at the
  // critical one (W = -eta^4 there): factored through CosSqPlus.
  const V w = hn::Mul(k.eta2_plus_1, k.w(c));
  const V x2 = hn::Mul(x, x), y2 = hn::Mul(y, y);
  const V wx2 = hn::Mul(w, x2);
  const V xy2 = hn::Mul(x2, y2);
  const V num = hn::Mul(k.half_k2, hn::MulAdd(y2, y2, hn::Mul(wx2, wx2)));
  const V f = hn::Div(num, hn::Mul(xy2, xy2));
  return hn::IfThenElse(hn::Gt(g2, hn::Zero(d)), hn::Min(f, one), one);
}

template <class D>
struct FresnelConductorConsts {
  CosSqPlus<D> re_u;  // Re u = c^2 + n^2 - k^2 - 1
  hn::Vec<D> two_nk, nk2;
  FresnelConductorConsts(D d, float n, float k)
      : re_u(d, (double(n) - 1.0) * (double(n) + 1.0) - double(k) * k) {
    const double nk = double(n) * k;
    two_nk = hn::Set(d, static_cast<float>(2 * nk));
    nk2 = hn::Set(d, static_cast<float>(nk * nk));
  }
};

template <class D, class V>
HWY_INLINE V FresnelConductor(D d, const FresnelConductorConsts<D>& k, V cos_i) {
  const V one = hn::Set(d, 1.0f);
  const V c = hn::Min(hn::Max(cos_i, hn::Zero(d)), one);
  const V re = k.re_u(c);
  const V abs_u = hn::Sqrt(hn::MulAdd(re, re, hn::Mul(k.two_nk, k.two_nk)));
  // The larger of a^2, b^2 directly, the smaller from a^2 b^2 = (n k)^2.
  const V big = hn::Max(hn::Mul(hn::Set(d, 0.5f), hn::Add(abs_u, hn::Abs(re))),
                        hn::Set(d, 1e-30f));
  const V small = hn::Div(k.nk2, big);
  const auto re_pos = hn::Ge(re, hn::Zero(d));
  const V a2 = hn::IfThenElse(re_pos, big, small);
  const V b2 = hn::IfThenElse(re_pos, small, big);
  const V a = hn::Sqrt(a2);
  const V s2 = hn::Mul(hn::Sub(one, c), hn::Add(one, c));
  const V cma = hn::Sub(c, a), cpa = hn::Add(c, a);
  const V n1 = hn::MulAdd(cma, cma, b2);
  const V d1 = hn::MulAdd(cpa, cpa, b2);
  const V b2c2 = hn::Mul(b2, hn::Mul(c, c));
  const V acms = hn::MulSub(a, c, s2), acps = hn::MulAdd(a, c, s2);
  const V n2 = hn::MulAdd(acms, acms, b2c2);
  const V d2 = hn::MulAdd(acps, acps, b2c2);
  // F = (|r_perp|^2 + |r_parl|^2) / 2 = n1 (d2 + n2) / (2 d1 d2).
  const V f = hn::Div(hn::Mul(n1, hn::Add(d2, n2)), hn::Mul(hn::Set(d, 2.0f), hn::Mul(d1, d2)));
  return hn::Min(f, one);
}

// The two as functors F(d, cos) for the BRDF kernels (see SchlickFresnel in
// kernels/ggx-inl.h).
template <class D>
struct DielectricFresnel {
  FresnelDielectricConsts<D> k;
  template <class V>
  HWY_INLINE V operator()(D d, V cos_i) const {
    return FresnelDielectric(d, k, cos_i);
  }
};
template <class D>
struct ConductorFresnel {
  FresnelConductorConsts<D> k;
  template <class V>
  HWY_INLINE V operator()(D d, V cos_i) const {
    return FresnelConductor(d, k, cos_i);
  }
};

// Calls f(fresnel) with the functor that the batch parameters select: one
// branch per call, none per lane.
template <class D, class Params, class F>
HWY_INLINE void WithFresnel(D d, const Params& p, const F& f) {
  switch (p.fresnel) {
    case BatchFresnel::kDielectric:
      f(DielectricFresnel<D>{FresnelDielectricConsts<D>(d, p.eta)});
      return;
    case BatchFresnel::kConductor:
      f(ConductorFresnel<D>{FresnelConductorConsts<D>(d, p.eta, p.k)});
      return;
    case BatchFresnel::kSchlick:
      break;
  }
  f(SchlickFresnel<D>{hn::Set(d, p.f0)});
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_FRESNEL_INL_H_
