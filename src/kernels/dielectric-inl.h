// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric BSDF ([Walter07]) over GGX and Beckmann, generic
// over the lanes' type: the batch API runs it in float lanes
// (batch_glass.cc), tests/kernels/simd_dielectric_test.cc in double lanes
// too. The scalar twin is RoughDielectric<T, Ndf> in
// include/brdfbake/models/dielectric.h, whose comment gives the
// conventions (index 1 above, eta below; wi, wo anywhere on the sphere).
//
// With s the unnormalized half vector turned to +z, s = wi + wo for a
// reflection pair and s = eta_i wi + eta_o wo = eta w_below + w_above for a
// refraction pair (one rounding per component, ScaledSum: the tangential
// components cancel near the refraction peak, and all of s when eta is
// near 1 and wi near -wo), L = |s|^2 and P = D(s / |s|) / L^2 (D is homogeneous of
// degree 0 in its argument):
//   GGX:      P = 1 / (pi ax ay Q^2), Q = s.x^2/ax^2 + s.y^2/ay^2 + s.z^2;
//   Beckmann: P = exp(-r2) / (pi ax ay s.z^4), r2 = (s.x^2/ax^2 + s.y^2/ay^2) / s.z^2;
// and V = G2 / (|wi.n| |wo.n|) from Lambda at |w.n| (the forms of
// ggx-inl.h and beckmann-inl.h, no division by a cosine):
//   f_r = F V P L^2 / 4                        ([Walter07] eq. 20),
//   f_t = k^2 (1 - F) V P |wi.s| |wo.s|        ([Walter07] eq. 21: |wi.h||wo.h| /
//         (eta_i wi.h + eta_o wo.h)^2 = |wi.s||wo.s| / L^2),
// k = eta_o (radiance) or eta_i (importance). A pair counts where wi.s and
// wo.s have the signs of wi.z and wo.z. F is [Walter07] eq. 22,
//   F = (1/2) ((g - c) / (g + c))^2 (1 + ((c (g + c) - 1) / (c (g - c) + 1))^2),
//   g^2 = c^2 + e, e = eta_rel^2 - 1, g - c = e / (g + c),
// with c = |wo.s| / |s| from the side of wo (eta_rel = eta above, 1/eta
// below) for a reflection pair (the mean of |wi.s| and |wo.s|, as the
// reference), and c = |w_above.s| / |s| with eta_rel = eta for a refraction
// pair; g^2 = c^2 + e is formed as (c - r)(c + r), r = sqrt(-e) split in two
// parts, where e < 0, so that it keeps its relative precision next to the
// critical cosine r; g^2 <= 0 is total internal reflection, F = 1.
//
// Error against the double reference at the same float inputs (asserted
// on every target by tests/kernels/simd_dielectric_test.cc over random
// pairs on the sphere and the stiff corners, alpha 1e-4 at the peaks,
// grazing directions, eta = 1 +- 1e-4, eta < 1 at the critical angle; it
// prints the observed maxima, at most 0.75 of the bound):
//   relative 4e-6 + 2e-7 kappa (1 + q) + 4e-7 q (+ 4e-7 r2 for Beckmann),
//   q = |s| / |wi.s| + |s| / |wo.s|,
// kappa = c |dF/dc| / F for a reflection pair, c |dF/dc| / (1 - F) for a
// refraction pair: the rounding of the Fresnel cosine c (a few ulp, more
// next to the chi+ edges, where q grows) is amplified by the infinite
// slope of F at the critical angle, and exp by r2 (as in beckmann-inl.h).
// In double lanes the same with 2e-12 + 2e-9 times the epsilon terms.
// Where exp(-r2) underflows the lanes' type, f is 0.

#if defined(BRDFBAKE_SRC_KERNELS_DIELECTRIC_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_DIELECTRIC_INL_H_
#undef BRDFBAKE_SRC_KERNELS_DIELECTRIC_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_DIELECTRIC_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cmath>

#include "brdfbake/models/dielectric.h"
#include "kernels/beckmann-inl.h"
#include "kernels/common-inl.h"
#include "kernels/ggx-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants of the interface, eta clamped as ClampDielectricEta
// and every constant formed in double (long double for the split root).
template <class D>
struct DielectricConsts {
  using T = hn::TFromD<D>;
  hn::Vec<D> eta, eta2;
  hn::Vec<D> e_above, e_below;       // eta_rel^2 - 1 seen from above (eta) and below (1/eta)
  hn::Vec<D> r_hi, r_lo;             // sqrt(-e) of the negative one
  hn::Vec<D> eta_hi, eta_lo, split;  // eta = eta_hi + eta_lo, half-width parts (ScaledSum)
  bool unit;                         // eta = 1: no interface, f = 0
  bool radiance;
  DielectricConsts(D d, double eta_in, DielectricTransport transport) {
    const double et = ClampDielectricEta(eta_in);
    unit = et == 1.0;
    radiance = transport == DielectricTransport::kRadiance;
    eta = hn::Set(d, static_cast<T>(et));
    eta2 = hn::Set(d, static_cast<T>(et * et));
    const double ea = (et - 1.0) * (et + 1.0);  // exact for a float eta
    const double eb = (1.0 - et) * (1.0 + et) / (et * et);
    e_above = hn::Set(d, static_cast<T>(ea));
    e_below = hn::Set(d, static_cast<T>(eb));
    // Veltkamp's split of eta in the lanes' type: eta_hi has half the
    // significand, so eta_hi times the half-width part of a lane is exact.
    const T sp = static_cast<T>(sizeof(T) == 4 ? 4097.0 : 134217729.0);  // 2^12 + 1, 2^27 + 1
    const T et_t = static_cast<T>(et), c = sp * et_t;
    const T hi = c - (c - et_t);
    eta_hi = hn::Set(d, hi);
    eta_lo = hn::Set(d, et_t - hi);
    split = hn::Set(d, sp);
    const long double eta_l = et;
    const long double neg = et > 1.0 ? (1.0L - eta_l) * (1.0L + eta_l) / (eta_l * eta_l)
                                     : (eta_l - 1.0L) * (eta_l + 1.0L);
    const long double r = std::sqrt(-neg);
    const T r_h = static_cast<T>(r);
    r_hi = hn::Set(d, r_h);
    r_lo = hn::Set(d, static_cast<T>(r - static_cast<long double>(r_h)));
  }
};

// eta b + a with one rounding: near a refraction peak eta b and a cancel
// in the tangential components, which must keep their digits relative to
// their (small) sum. A fused multiply-add does it; without one (SSSE3,
// SSE4, the portable targets) eta b is formed exactly as a sum of four
// exact products (Dekker's product with Veltkamp's split), and p + a is
// exact where it cancels (Sterbenz).
template <class D, class V>
HWY_INLINE V ScaledSum(D d, const DielectricConsts<D>& k, V b, V a) {
#if HWY_NATIVE_FMA
  (void)d;
  return hn::MulAdd(k.eta, b, a);
#else
  (void)d;
  const V p = hn::Mul(k.eta, b);
  const V c = hn::Mul(k.split, b);
  const V hi = hn::Sub(c, hn::Sub(c, b));
  const V lo = hn::Sub(b, hi);
  const V err = hn::Add(hn::Add(hn::Sub(hn::Mul(k.eta_hi, hi), p),
                                hn::Add(hn::Mul(k.eta_hi, lo), hn::Mul(k.eta_lo, hi))),
                        hn::Mul(k.eta_lo, lo));
  return hn::Add(hn::Add(p, a), err);
#endif
}

// F at cosine c in [0, 1] with e = eta_rel^2 - 1 per lane (e_above or
// e_below); `neg` marks the lanes whose e is the negative one.
template <class D, class V, class M>
HWY_INLINE V InterfaceFresnel(D d, const DielectricConsts<D>& k, V c, V e, M neg) {
  using T = hn::TFromD<D>;
  const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
  const V g2_pos = hn::MulAdd(c, c, e);
  const V g2_neg = hn::Mul(hn::Sub(hn::Sub(c, k.r_hi), k.r_lo), hn::Add(c, k.r_hi));
  const V g2 = hn::IfThenElse(neg, g2_neg, g2_pos);
  const auto tir = hn::Le(g2, hn::Zero(d));
  const V g = hn::Sqrt(hn::Max(g2, hn::Zero(d)));
  const V gpc = hn::Max(hn::Add(g, c), hn::Set(d, T(1e-30)));
  const V gmc = hn::Div(e, gpc);  // g - c
  const V a = hn::Div(gmc, gpc);
  const V b = hn::Div(hn::MulSub(c, gpc, one), hn::MulAdd(c, gmc, one));
  const V f = hn::Mul(hn::Mul(half, hn::Mul(a, a)), hn::MulAdd(b, b, one));
  return hn::IfThenElse(tir, one, hn::Min(f, one));
}

// The NDF's part of the kernel: P = D(s / |s|) / |s|^4 (and the lanes where
// it is representable) and V = G2 / (|wi.n| |wo.n|) at |w.n|.
template <class D>
struct GgxDielectricNdf {
  const GgxConsts<D>& c;
  template <class V>
  HWY_INLINE V P(D d, V sx, V sy, V sz, hn::Mask<D>* ok) const {
    const V q = hn::MulAdd(hn::Mul(sx, sx), c.inv_ax2,
                           hn::MulAdd(hn::Mul(sy, sy), c.inv_ay2, hn::Mul(sz, sz)));
    *ok = hn::Gt(sz, hn::Zero(d));
    return hn::Div(c.inv_pi_axay, hn::Mul(q, q));
  }
  template <class V>
  HWY_INLINE V Vis(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz) const {
    using T = hn::TFromD<D>;
    const V ri = hn::Sqrt(
        hn::MulAdd(iz, iz, hn::MulAdd(hn::Mul(ix, ix), c.ax2, hn::Mul(hn::Mul(iy, iy), c.ay2))));
    const V ro = hn::Sqrt(
        hn::MulAdd(oz, oz, hn::MulAdd(hn::Mul(ox, ox), c.ax2, hn::Mul(hn::Mul(oy, oy), c.ay2))));
    if (separable) {
      return hn::Div(hn::Set(d, T(4)), hn::Mul(hn::Add(iz, ri), hn::Add(oz, ro)));
    }
    return hn::Div(hn::Set(d, T(2)), hn::MulAdd(oz, ri, hn::Mul(iz, ro)));
  }
};

template <class D>
struct BeckmannDielectricNdf {
  const BeckmannConsts<D>& c;
  template <class V>
  HWY_INLINE V P(D d, V sx, V sy, V sz, hn::Mask<D>* ok) const {
    using T = hn::TFromD<D>;
    const V iz2 = hn::Div(hn::Set(d, T(1)), hn::Mul(sz, sz));
    const V q = hn::MulAdd(hn::Mul(sx, sx), c.inv_ax2, hn::Mul(hn::Mul(sy, sy), c.inv_ay2));
    const V r2 = hn::Mul(q, iz2);
    *ok = hn::And(hn::Gt(sz, hn::Zero(d)), hn::Lt(r2, hn::Set(d, BeckmannMaxR2<T>())));
    // The exponential multiplies last (see BeckmannD).
    return hn::Mul(hn::Mul(hn::Mul(c.inv_pi_axay, iz2), iz2), hn::Exp(d, hn::Neg(r2)));
  }
  template <class V>
  HWY_INLINE V Vis(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz) const {
    V ni, mi, no, mo;
    BeckmannLambdaParts(d, c, ix, iy, iz, &ni, &mi);
    BeckmannLambdaParts(d, c, ox, oy, oz, &no, &mo);
    const V mm = hn::Mul(mi, mo);
    const V g_den = separable ? hn::Mul(hn::Add(mi, ni), hn::Add(mo, no))
                              : hn::MulAdd(ni, mo, hn::MulAdd(no, mi, mm));
    return hn::Div(mm, hn::Mul(g_den, hn::Mul(iz, oz)));
  }
};

// f(wi, wo), times |wi.n| if `cos_weighted`, for wi and wo anywhere on the
// sphere; 0 on the horizon and where the pair is not a reflection or
// refraction pair.
template <class D, class V, class Ndf>
HWY_INLINE V DielectricBsdf(D d, const DielectricConsts<D>& k, const Ndf& ndf, bool separable,
                            bool cos_weighted, V ix, V iy, V iz, V ox, V oy, V oz) {
  using T = hn::TFromD<D>;
  const V zero = hn::Zero(d), one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
  if (k.unit) return zero;
  const auto i_up = hn::Gt(iz, zero), o_up = hn::Gt(oz, zero);
  const auto i_dn = hn::Lt(iz, zero), o_dn = hn::Lt(oz, zero);
  const auto same = hn::Or(hn::And(i_up, o_up), hn::And(i_dn, o_dn));
  // s: wi + wo, or eta w_below + w_above.
  const V bx = hn::IfThenElse(i_up, ox, ix), ax = hn::IfThenElse(i_up, ix, ox);
  const V by = hn::IfThenElse(i_up, oy, iy), ay = hn::IfThenElse(i_up, iy, oy);
  const V bz = hn::IfThenElse(i_up, oz, iz), az = hn::IfThenElse(i_up, iz, oz);
  const V tx = ScaledSum(d, k, bx, ax), ty = ScaledSum(d, k, by, ay), tz = ScaledSum(d, k, bz, az);
  V sx = hn::IfThenElse(same, hn::Add(ix, ox), tx);
  V sy = hn::IfThenElse(same, hn::Add(iy, oy), ty);
  V sz = hn::IfThenElse(same, hn::Add(iz, oz), tz);
  const auto flip = hn::Lt(sz, zero);
  sx = hn::IfThenElse(flip, hn::Neg(sx), sx);
  sy = hn::IfThenElse(flip, hn::Neg(sy), sy);
  sz = hn::Abs(sz);
  const V len2 = hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(sz, sz)));
  const V wi_s = hn::MulAdd(ix, sx, hn::MulAdd(iy, sy, hn::Mul(iz, sz)));
  const V wo_s = hn::MulAdd(ox, sx, hn::MulAdd(oy, sy, hn::Mul(oz, sz)));
  // chi+ of [Walter07]'s G1: w.s of the sign of w.n, for both.
  const auto chi_i = hn::Or(hn::And(i_up, hn::Gt(wi_s, zero)), hn::And(i_dn, hn::Lt(wi_s, zero)));
  const auto chi_o = hn::Or(hn::And(o_up, hn::Gt(wo_s, zero)), hn::And(o_dn, hn::Lt(wo_s, zero)));
  hn::Mask<D> p_ok;
  const V p = ndf.P(d, sx, sy, sz, &p_ok);
  const V aiz = hn::Abs(iz), aoz = hn::Abs(oz);
  const V vis = ndf.Vis(d, separable, ix, iy, aiz, ox, oy, aoz);
  // The Fresnel cosine and relative index (see the header comment).
  const V inv_len = RsqrtNewton(d, hn::Max(len2, hn::Set(d, T(1e-30))));
  const V awi = hn::Abs(wi_s), awo = hn::Abs(wo_s);
  const V c_num =
      hn::IfThenElse(same, hn::Mul(half, hn::Add(awi, awo)), hn::IfThenElse(i_up, awi, awo));
  const V c = hn::Min(hn::Mul(c_num, inv_len), one);
  const auto from_above = hn::Or(hn::Not(same), o_up);
  const V e = hn::IfThenElse(from_above, k.e_above, k.e_below);
  const auto neg = hn::Lt(e, zero);
  const V f = InterfaceFresnel(d, k, c, e, neg);
  const V fr =
      hn::Mul(hn::Mul(hn::Mul(f, vis), hn::Mul(p, hn::Mul(len2, len2))), hn::Set(d, T(0.25)));
  // k^2 of the transport: eta^2 where its side is below.
  const auto k_below = k.radiance ? o_dn : i_dn;
  const V kk = hn::IfThenElse(k_below, k.eta2, one);
  const V ft = hn::Mul(hn::Mul(kk, hn::Sub(one, f)), hn::Mul(hn::Mul(vis, p), hn::Mul(awi, awo)));
  V val = hn::IfThenElse(same, fr, ft);
  if (cos_weighted) val = hn::Mul(val, aiz);
  const auto valid =
      hn::And(hn::And(hn::And(chi_i, chi_o), p_ok), hn::Gt(len2, hn::Set(d, T(1e-30))));
  return hn::IfThenElseZero(valid, val);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_DIELECTRIC_INL_H_
