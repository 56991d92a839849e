// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The squared ellipsoidal lobe (SEL) of Tokuyoshi and Harada ([TokuyoshiHarada]) and
// its isotropic case, the squared spheroidal lobe (SSL).
//
// SSL ([TokuyoshiHarada] section 1): for the angle theta between a direction and the
// lobe axis,
//   pi alpha^2 D_GGX(cos(theta/2), alpha)
//     = 4 alpha^4 / ((1 - cos theta) + alpha^2 (1 + cos theta))^2,
// and sqrt of it, as a polar plot around the axis, is a spheroid with centre
// (0, 0, (1 - alpha^2) / 2) and semi-axes (alpha, alpha, (1 + alpha^2) / 2).
//
// SEL ([TokuyoshiHarada] section 2): the semi-axes become (alpha_x, alpha_y,
// (1 + amax^2) / 2), amax = max(alpha_x, alpha_y), the centre
// c = (0, 0, (1 - amax^2) / 2), and K(w) is the squared distance t^2 from the
// origin to that ellipsoid along v = Q w (v: the direction in lobe space):
//   K = 4 amax^4 / ((U - v_z) + amax^2 (U + v_z))^2,
//   U = sqrt(amax^2 v_x^2 / alpha_x^2 + amax^2 v_y^2 / alpha_y^2 + v_z^2).
// Both U - v_z and U + v_z are positive; the smaller of the two is evaluated
// as (U^2 - v_z^2) / (the larger) so K keeps full relative precision near the
// lobe axis and opposite it. K(axis) = 1, K(-axis) = amax^4, and
// 0 < K <= 1 whenever amax <= 1 ([TokuyoshiHarada]'s range of roughness; up to the
// rounding of w: within ~1e-8 rad of the axis a w that is unit only to
// rounding can give 1 + ulp). For amax > 1 the lobe exceeds 1 behind
// (K(-axis) = amax^4); alphas are not clamped from above.
//
// Typos in [TokuyoshiHarada], checked numerically (tests/models/sel_test.cc):
//  - the diagonal scaling of the line, p' = (t w - c) diag(1/ax, 1/ay, .),
//    prints z / (1 + amax^2) in the last entry; it is 2 / (1 + amax^2), as
//    the d of its eq. (1) shows.
//  - the first line of the solution for t must be read as
//    2 ((1 + amax^2) U + z (1 - amax^2)) / ((1 + amax^2)^2 ||d||^2): the
//    square root covers U^2 only.
//  - "K = I^2" means K = t^2; "K(w; E, ax, a)" means K(w; E, ax, ay), and
//    "Eq. (2) is generalized" refers to the formula for K, not to eq. (2).
//  - v = Q w (column vectors) although the scaling step is written with row
//    vectors.

#ifndef BRDFBAKE_MODELS_SEL_H_
#define BRDFBAKE_MODELS_SEL_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// Squared spheroidal lobe pi alpha^2 D_GGX(cos(theta/2), alpha), written out
// ([TokuyoshiHarada] section 1); alpha is clamped to kMinAlpha.
template <typename T>
T SquaredSpheroidalLobe(T alpha, T cos_theta) {
  const T a = ClampAlpha(alpha);
  const T a2 = a * a;
  const T den = (T(1) - cos_theta) + a2 * (T(1) + cos_theta);
  const T ratio = T(2) * a2 / den;
  return ratio * ratio;
}

template <typename T>
class SelLobe {
 public:
  // q is orthogonal and maps world directions into lobe space, v = Q w; the
  // lobe axis in world space is therefore Q^T z (the third row of Q), the
  // alpha_x and alpha_y axes are the first and second rows. Alphas are
  // clamped to kMinAlpha.
  SelLobe(T alpha_x, T alpha_y, const Mat3<T>& q)
      : ax_(ClampAlpha(alpha_x)), ay_(ClampAlpha(alpha_y)), q_(q) {
    const T amax = std::max(ax_, ay_);
    amax2_ = amax * amax;
    kx_ = amax / ax_;
    ky_ = amax / ay_;
  }

  // Q = Rx(theta_x) Ry(theta_y) Rz(theta_z) (the Mat3::RotX/RotY/RotZ
  // matrices, radians), so v = Rx Ry Rz w: w is turned about z first, then y,
  // then x. The lobe axis in world space is Rz^T Ry^T Rx^T z.
  static SelLobe FromAngles(T alpha_x, T alpha_y, T theta_x, T theta_y, T theta_z) {
    return SelLobe(alpha_x, alpha_y,
                   Mat3<T>::RotX(theta_x) * Mat3<T>::RotY(theta_y) *
                       Mat3<T>::RotZ(theta_z));
  }

  T alpha_x() const { return ax_; }
  T alpha_y() const { return ay_; }
  const Mat3<T>& q() const { return q_; }
  // Unit lobe axis in world space, Q^T z.
  Vec3<T> Axis() const { return {q_.m[2][0], q_.m[2][1], q_.m[2][2]}; }

  // K(w; Q, alpha_x, alpha_y), [TokuyoshiHarada]'s final U form, for a unit w.
  T K(const Vec3<T>& w) const {
    const Vec3<T> v = q_ * w;
    const T sx = kx_ * v.x, sy = ky_ * v.y;
    const T r2 = sx * sx + sy * sy;  // U^2 - v_z^2
    const T u = std::sqrt(r2 + v.z * v.z);
    T u_minus, u_plus;
    if (v.z >= T(0)) {
      u_plus = u + v.z;
      u_minus = r2 / u_plus;
    } else {
      u_minus = u - v.z;
      u_plus = r2 / u_minus;
    }
    const T ratio = T(2) * amax2_ / (u_minus + amax2_ * u_plus);
    return ratio * ratio;
  }

 private:
  T ax_, ay_;
  Mat3<T> q_;
  T amax2_;    // max(alpha_x, alpha_y)^2
  T kx_, ky_;  // amax / alpha_x, amax / alpha_y
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_SEL_H_
