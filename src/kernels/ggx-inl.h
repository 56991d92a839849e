// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// GGX SIMD kernels, float lanes; the scalar twins are in
// include/brdfbake/models/ggx.h and brdf.h (GgxNdf<T>::D, ::Lambda, Brdf).
//
// The BRDF is arranged to need two square roots and one division per
// evaluation (plus one approximate reciprocal square root refined by a
// Newton step, which runs on the FMA units):
//   s = wi + wo (unnormalized half vector), L = |s|^2,
//   Q = s.x^2/ax^2 + s.y^2/ay^2 + s.z^2, so D(h) = L^2 / (pi ax ay Q^2)
//     (D is homogeneous of degree 0 in h: no normalization needed);
//   R_w = sqrt(w.z^2 + ax^2 w.x^2 + ay^2 w.y^2), so 1 + Lambda(w) =
//     (w.z + R_w) / (2 w.z) and, height-correlated,
//     G2 / (4 wi.z wo.z) = 1 / (2 (wo.z R_i + wi.z R_o)), separable,
//     G1 G1 / (4 wi.z wo.z) = 1 / ((wi.z + R_i)(wo.z + R_o));
//   wo.h = (wo.s) rsqrt(L), F = F0 + (1 - F0)(1 - wo.h)^5.
// Error: within 2e-6 relative of the double reference evaluated at the same
// float inputs (tests/kernels/simd_ggx_test.cc measures it on every target).

#if defined(BRDFBAKE_SRC_KERNELS_GGX_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_GGX_INL_H_
#undef BRDFBAKE_SRC_KERNELS_GGX_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_GGX_INL_H_
#endif

#include <limits>

#include <hwy/highway.h>

#include "kernels/common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants of the GGX kernels, in the lanes' type (float or
// double: the kernels below are generic over the descriptor D).
template <class D>
struct GgxConsts {
  using T = hn::TFromD<D>;
  hn::Vec<D> ax2, ay2, inv_ax2, inv_ay2, inv_pi_axay, f0;
  GgxConsts(D d, T ax, T ay, T f0_) {
    ax = ax < T(1e-4) ? T(1e-4) : ax;
    ay = ay < T(1e-4) ? T(1e-4) : ay;
    ax2 = hn::Set(d, ax * ax);
    ay2 = hn::Set(d, ay * ay);
    inv_ax2 = hn::Set(d, T(1) / (ax * ax));
    inv_ay2 = hn::Set(d, T(1) / (ay * ay));
    inv_pi_axay = hn::Set(d, static_cast<T>(0.31830988618379067 / (double(ax) * ay)));
    f0 = hn::Set(d, f0_);
  }
  // Per-element widths and F0, one per lane (WidthLanes).
  GgxConsts(D d, hn::Vec<D> ax, hn::Vec<D> ay, hn::Vec<D> f0_) {
    const WidthLanes<D> w(d, ax, ay);
    ax2 = w.ax2;
    ay2 = w.ay2;
    inv_ax2 = w.inv_ax2;
    inv_ay2 = w.inv_ay2;
    inv_pi_axay = w.inv_pi_axay;
    f0 = f0_;
  }
};

template <class D, class V>
HWY_INLINE V GgxD(D d, const GgxConsts<D>& c, V mx, V my, V mz) {
  const V len2 = hn::MulAdd(mx, mx, hn::MulAdd(my, my, hn::Mul(mz, mz)));
  const V q = hn::MulAdd(hn::Mul(mx, mx), c.inv_ax2,
                         hn::MulAdd(hn::Mul(my, my), c.inv_ay2, hn::Mul(mz, mz)));
  const V d_val = hn::Div(hn::Mul(hn::Mul(len2, len2), c.inv_pi_axay), hn::Mul(q, q));
  return hn::IfThenElseZero(hn::Gt(mz, hn::Zero(d)), d_val);
}

// Lambda = P / (2 (w.z^2 + w.z sqrt(w.z^2 + P))), P = ax^2 w.x^2 + ay^2 w.y^2.
template <class D, class V>
HWY_INLINE V GgxLambda(D d, const GgxConsts<D>& c, V wx, V wy, V wz) {
  const V p = hn::MulAdd(hn::Mul(wx, wx), c.ax2, hn::Mul(hn::Mul(wy, wy), c.ay2));
  const V wz2 = hn::Mul(wz, wz);
  const V r = hn::Sqrt(hn::Add(wz2, p));
  using T = hn::TFromD<D>;
  const V lambda = hn::Div(p, hn::Mul(hn::Set(d, T(2)), hn::MulAdd(wz, r, wz2)));
  return hn::IfThenElse(hn::Gt(wz, hn::Zero(d)), lambda,
                        hn::Set(d, std::numeric_limits<T>::infinity()));
}

template <class D, class V, class Fr>
HWY_INLINE V GgxBrdf(D d, const GgxConsts<D>& c, bool separable, V ix, V iy, V iz, V ox, V oy,
                     V oz, const Fr& fresnel) {
  const V sx = hn::Add(ix, ox), sy = hn::Add(iy, oy), sz = hn::Add(iz, oz);
  const V len2 = hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(sz, sz)));
  const V q = hn::MulAdd(hn::Mul(sx, sx), c.inv_ax2,
                         hn::MulAdd(hn::Mul(sy, sy), c.inv_ay2, hn::Mul(sz, sz)));
  const V ri = hn::Sqrt(hn::MulAdd(iz, iz, hn::MulAdd(hn::Mul(ix, ix), c.ax2,
                                                      hn::Mul(hn::Mul(iy, iy), c.ay2))));
  const V ro = hn::Sqrt(hn::MulAdd(oz, oz, hn::MulAdd(hn::Mul(ox, ox), c.ax2,
                                                      hn::Mul(hn::Mul(oy, oy), c.ay2))));
  V vis_den;
  if (separable) {
    vis_den = hn::Mul(hn::Add(iz, ri), hn::Add(oz, ro));
  } else {
    vis_den = hn::Mul(hn::Set(d, hn::TFromD<D>(2)), hn::MulAdd(oz, ri, hn::Mul(iz, ro)));
  }
  const V num = hn::Mul(hn::Mul(len2, len2), c.inv_pi_axay);
  const V dv = hn::Div(num, hn::Mul(hn::Mul(q, q), vis_den));
  const V f = fresnel(d, CosAtHalf(d, ox, oy, oz, sx, sy, sz, len2));
  const auto valid = hn::And(hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d))),
                             hn::Gt(len2, hn::Set(d, hn::TFromD<D>(1e-30))));
  return hn::IfThenElseZero(valid, hn::Mul(f, dv));
}

// The Ggx kernels as the batch loops take them (kernels/batch_rows-inl.h,
// MicrofacetRows): D, Lambda and the BRDF over its constants (G1 = 1 / (1 +
// Lambda); the NDF density comes from ggx_sampling-inl.h).
template <class D>
struct GgxKernels {
  static constexpr bool kOwnG1 = false;
  static constexpr bool kPdfNdfFromD = false;
  const GgxConsts<D>& c;
  template <class V>
  HWY_INLINE V Ndf(D d, V x, V y, V z) const {
    return GgxD(d, c, x, y, z);
  }
  template <class V>
  HWY_INLINE V Lambda(D d, V x, V y, V z) const {
    return GgxLambda(d, c, x, y, z);
  }
  template <class V, class Fr>
  HWY_INLINE V Brdf(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz, const Fr& fr) const {
    return GgxBrdf(d, c, separable, ix, iy, iz, ox, oy, oz, fr);
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_GGX_INL_H_
