// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The documented error bounds of the float SIMD kernels against the double
// reference evaluated at the same float inputs, as functions of the input
// where the bound depends on it. The derivations are beside the kernels
// (src/kernels/*-inl.h); the per-target tests (tests/kernels/simd_*_test.cc) and
// `brdfbake stability` both assert these functions, so there is one
// statement of each bound.

#ifndef BRDFBAKE_MODELS_KERNEL_BOUNDS_H_
#define BRDFBAKE_MODELS_KERNEL_BOUNDS_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/models/vec3.h"

namespace brdfbake {
namespace bounds {

// GGX (src/kernels/ggx-inl.h): relative, for D, 1 + Lambda and the BRDF.
inline constexpr double kGgxRel = 2e-6;

// Beckmann and STD (src/kernels/beckmann-inl.h, std-inl.h). The exponent E of
// the exponential factor (Beckmann: r2, the squared standard slope; STD:
// gamma log1p(r2 / (gamma - 1))) is rounded like any float expression of
// the inputs, and exp multiplies that relative error by E.
inline constexpr double kBeckmannExpSlope = 3e-7;
inline constexpr double kStudentTExpSlope = 4.5e-7;
// The Beckmann BRDF forms its exponent from s = wi + wo (sums, squares and a
// division more): one more ulp per unit of exponent (a sample at r2 = 65.5
// in the lobe had 2.18e-5, above 3e-7 r2).
inline constexpr double kBeckmannBrdfExpSlope = 3.6e-7;
constexpr double SlopeD(double exponent, double slope) { return 1e-6 + slope * exponent; }
constexpr double SlopeBrdf(double exponent, double slope) { return 2e-6 + slope * exponent; }
// Lambda: absolute error <= 1e-6 max(1, Lambda) + 3e-7 a^2 Lambda at
// a = cot(theta) / alpha (the a^2 term is the amplification of a's rounding).
inline double SlopeLambdaAbs(double a, double lambda) {
  return 1e-6 * std::max(1.0, lambda) + 3e-7 * a * a * lambda;
}
// The batch calls flush subnormals to zero: where exp(-E) is below FLT_MIN
// (E > 87.3) D and the BRDF may be 0 (with slack for the rounding of E).
inline constexpr double kFlushExponent = 87.0;

// Ellipsoid (src/kernels/ellipsoid-inl.h): the float products A u and A^-T m
// cancel for tilted, thin ellipsoids, so the bounds scale with the
// componentwise condition number of the product.
inline constexpr double kEllipsoidDRel = 3e-6;       // times Kappa(A^-T, m)
inline constexpr double kEllipsoidLambdaRel = 2e-6;  // times Kappa(A, u), of EllipsoidLambdaScale
inline constexpr double kEllipsoidBrdfRel = 4e-6;    // see EllipsoidBrdfCondition

// A^-T = S^-1 R of the ellipsoid as the SIMD kernels build it (alphas
// clamped at 1e-4, R = Rx Ry Rz, radians), the matrix whose products with
// m the D bound is conditioned by.
inline Mat3<double> EllipsoidKernelInvT(double ax, double ay, double tx, double ty, double tz) {
  return Mat3<double>::Diagonal(1.0 / std::max(ax, 1e-4), 1.0 / std::max(ay, 1e-4), 1.0) *
         (Mat3<double>::RotX(tx) * Mat3<double>::RotY(ty) * Mat3<double>::RotZ(tz));
}

// Componentwise condition number of M v: | |M| |v| | / |M v| >= 1; 1 for a
// diagonal M, growing as the rows of M cancel against v.
inline double Kappa(const Mat3<double>& m, const Vec3<double>& v) {
  double num = 0;
  for (int i = 0; i < 3; ++i) {
    const double s = std::abs(m.m[i][0] * v.x) + std::abs(m.m[i][1] * v.y) +
                     std::abs(m.m[i][2] * v.z);
    num += s * s;
  }
  const Vec3<double> mv = m * v;
  return std::max(1.0, std::sqrt(num / std::max(Dot(mv, mv), 1e-300)));
}

// Skeel condition number of the round trip p -> q = A^T p -> A^-T q:
// | |A^-T| |A^T| |p| | / |p| >= 1, which bounds how much the componentwise
// rounding of q (the sampler's last step) moves the sphere-space normal.
// It is 1 for diagonal A and grows to ~1/alpha for tilted, thin ellipsoids.
inline double KappaRoundTrip(const Mat3<double>& a, const Mat3<double>& ait,
                             const Vec3<double>& p) {
  double tv[3], r2 = 0;  // tv = |A^T| |p|
  for (int j = 0; j < 3; ++j) {
    tv[j] = std::abs(a.m[0][j] * p.x) + std::abs(a.m[1][j] * p.y) + std::abs(a.m[2][j] * p.z);
  }
  for (int i = 0; i < 3; ++i) {
    const double r = std::abs(ait.m[i][0]) * tv[0] + std::abs(ait.m[i][1]) * tv[1] +
                     std::abs(ait.m[i][2]) * tv[2];
    r2 += r * r;
  }
  return std::max(1.0, std::sqrt(r2 / std::max(Dot(p, p), 1e-300)));
}

// The size of the two terms of 1 + Lambda = A_l(u, n) / u.z before they
// cancel: |Au| / (||An|| u.z) >= A_l / u.z. Near the cone where the min of
// eq. 6 switches on (Lambda -> 0) the float product Au is only known to
// ~1 ulp of |Au|, so Lambda is only known to ~1 ulp of this scale; it
// exceeds 1 + Lambda by orders of magnitude only for thin lunes (tilted
// ellipsoids seen at grazing angles from the side opposite the tilt).
inline double EllipsoidLambdaScale(const Mat3<double>& a, const Vec3<double>& u, double lambda) {
  const Vec3<double> an(a.m[0][2], a.m[1][2], a.m[2][2]);
  return std::max({1.0, lambda, Length(a * u) / (Length(an) * u.z)});
}

// The factor of kEllipsoidBrdfRel for the BRDF at (wi, wo): the largest
// condition number of the products involved times the relative error that
// the Lambda errors put into G2.
inline double EllipsoidBrdfCondition(const Mat3<double>& a, const Mat3<double>& ait,
                                     const Vec3<double>& wi, const Vec3<double>& wo,
                                     double lambda_i, double lambda_o) {
  const double kappa = std::max({Kappa(ait, wi + wo), Kappa(a, wi), Kappa(a, wo)});
  const double g_cond = 1 + EllipsoidLambdaScale(a, wi, lambda_i) / (1 + lambda_i) +
                        EllipsoidLambdaScale(a, wo, lambda_o) / (1 + lambda_o);
  return kappa * g_cond;
}

}  // namespace bounds
}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_KERNEL_BOUNDS_H_
