// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The squared ellipsoidal lobe K(w) ([TokuyoshiHarada]) in float lanes; the scalar
// twin is SelLobe<T>::K in include/brdfbake/models/sel.h, whose comment derives the
// form used here: v = Q w, U = sqrt(kx^2 v_x^2 + ky^2 v_y^2 + v_z^2),
// K = (2 amax^2 / ((U - v_z) + amax^2 (U + v_z)))^2, with the smaller of
// U -+ v_z taken as (U^2 - v_z^2) / (the larger): one square root and two
// divisions per lane, no branch (a select on the sign of v_z).
// Error against the double reference at the same float inputs
// (tests/kernels/simd_sel_test.cc, CheckSelK, every target): relative 2e-6 plus
// the change of the exact K when v moves by the float rounding of the
// rotation Q w (3 ulp of |Q| |w| per component): near the lobe axis of a
// thin, rotated lobe the tangential part of v is tiny and that rounding is
// a large part of it (for Q = I it is exact and the bound is 2e-6).

#if defined(BRDFBAKE_SRC_KERNELS_SEL_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_SEL_INL_H_
#undef BRDFBAKE_SRC_KERNELS_SEL_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_SEL_INL_H_
#endif

#include <algorithm>

#include <hwy/highway.h>

#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D>
struct SelConsts {
  hn::Vec<D> q[3][3], kx, ky, two_amax2, amax2;
  // Q = Rx(theta_x) Ry(theta_y) Rz(theta_z) and the alphas as in
  // SelLobe::FromAngles (clamped at kMinAlpha), computed in double.
  SelConsts(D d, float alpha_x, float alpha_y, float theta_x, float theta_y, float theta_z) {
    const double ax = ClampAlpha(double(alpha_x)), ay = ClampAlpha(double(alpha_y));
    const double amax = std::max(ax, ay);
    const Mat3<double> m = Mat3<double>::RotX(theta_x) * Mat3<double>::RotY(theta_y) *
                           Mat3<double>::RotZ(theta_z);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) q[i][j] = hn::Set(d, static_cast<float>(m.m[i][j]));
    }
    kx = hn::Set(d, static_cast<float>(amax / ax));
    ky = hn::Set(d, static_cast<float>(amax / ay));
    amax2 = hn::Set(d, static_cast<float>(amax * amax));
    two_amax2 = hn::Set(d, static_cast<float>(2 * amax * amax));
  }
};

template <class D, class V>
HWY_INLINE V SelK(D d, const SelConsts<D>& c, V wx, V wy, V wz) {
  const V vx = hn::MulAdd(c.q[0][0], wx, hn::MulAdd(c.q[0][1], wy, hn::Mul(c.q[0][2], wz)));
  const V vy = hn::MulAdd(c.q[1][0], wx, hn::MulAdd(c.q[1][1], wy, hn::Mul(c.q[1][2], wz)));
  const V vz = hn::MulAdd(c.q[2][0], wx, hn::MulAdd(c.q[2][1], wy, hn::Mul(c.q[2][2], wz)));
  const V sx = hn::Mul(c.kx, vx), sy = hn::Mul(c.ky, vy);
  const V r2 = hn::MulAdd(sx, sx, hn::Mul(sy, sy));  // U^2 - v_z^2
  const V u = hn::Sqrt(hn::MulAdd(vz, vz, r2));
  // The larger of U -+ v_z directly, the smaller as r2 / larger.
  const V big = hn::Max(hn::Add(u, hn::Abs(vz)), hn::Set(d, 1e-30f));
  const V small = hn::Div(r2, big);
  const auto up = hn::Ge(vz, hn::Zero(d));
  const V u_plus = hn::IfThenElse(up, big, small);
  const V u_minus = hn::IfThenElse(up, small, big);
  const V ratio = hn::Div(c.two_amax2, hn::MulAdd(c.amax2, u_plus, u_minus));
  return hn::Mul(ratio, ratio);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_SEL_INL_H_
