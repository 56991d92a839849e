// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Ellipsoid NDF SIMD kernels (Walter et al., [Walter15]), generic over the
// lane type (float for the batch kernels; D, Lambda, G1, the BRDF and
// PdfVisible also in double lanes, tests/kernels/simd_ellipsoid_test.cc); the
// scalar twins (double reference) are EllipsoidNdf::D, ::Lambda, ::G1,
// ::PdfVisible, ::SampleVisible in include/brdfbake/models/ellipsoid.h and Brdf in
// brdf.h. A = S R, S = diag(ax, ay, 1), R = Rx Ry Rz (seed eq. 2-3); every
// matrix and derived constant is computed once per call in double.
//
//  - D(m) = |m|^4 / (pi ax ay ||An|| ||A^-T m||^4) (seed eq. 1, written
//    homogeneous of degree 0 in m as the GGX kernel does).
//  - Lambda (= 1/G1 - 1, ellipsoid.h) = P / (Q u.z), from one of two forms
//    per lane, whichever cancels less: 1 + Lambda = A_l(u, n) / u.z (eq. 29;
//    with A_l = xn / (2 ||An|| xd) from LuneParts, P = (A_l - u.z) xd,
//    Q = xd), or ellipsoid.h's rationalized form (accurate as
//    Lambda -> 0): with a = Au, h^ and rho as there, P = N ls and for
//    a.h^ > 0 N = rho^2 |a - h^ (a.h^)|^2 - (1 - rho^2)(a.h^)^2,
//    Q = rho |a| + a.h^, otherwise N = rho |a| - a.h^, Q = 1. P is clamped
//    at 0 (the min in eq. 6). G1 = Q u.z / (Q u.z + P): one square root,
//    one division.
//  - BRDF: with X = Q z, Y = P per direction (Lambda = Y / X),
//    G2 / (4 zi zo) = Q_i Q_o / (4 (Xi Xo + Yi Xo + Yo Xi)) height-
//    correlated, Q_i Q_o / (4 (Xi + Yi)(Xo + Yo)) separable; with D(h) at
//    the unnormalized half vector and Schlick F at wo.h, two square roots, one
//    reciprocal square root and one division per lane.
//  - PdfVisible (eq. 30, A_e(n) = 1) = D(m) (u.m) / A_l(u, n) with
//    A_l(u, n) = |a| (1 + w.k) / (2 ||An||) = (|a| + a.k) / (2 ||An||),
//    a = Au, w = a / |a|, k = An / ||An||; for a.k < 0 (thin lunes) |a| + a.k
//    = |k x a|^2 / (|a| - a.k), where k x a = (k x A) u is evaluated with a
//    precomputed matrix: no cancellation.
//  - SampleVisible ("Version 3", ellipsoid.h): in sphere space, basis
//    t1 = normalize(k x w), t2 = w x t1, crescent point and lift as for GGX
//    (CrescentPoint in ggx_sampling-inl.h, cancellation-free at the rim),
//    s and 1 - s each to full relative precision (the smaller one from
//    s (1 - s) = |k x w|^2 / 4), m = normalize(A^T p).
//    k x w is evaluated as (k x A) u / |Au| with the
//    matrix k x A precomputed and its third column set to exactly 0
//    (k x An = 0): the basis near w = k then has the same direction as the
//    double reference, and u = n gives the reference's fallback basis.
//
// Error against the double reference at the same float inputs (tests/
// simd_ellipsoid_test.cc, alpha 1e-4 .. 1, anisotropy 1000:1, tilts up to 80
// degrees, mu down to 1e-6), on every target. For a tilted, thin ellipsoid
// the float products A u and A^-T m themselves cancel, so the bounds scale
// with the componentwise condition number kappa(M, v) = | |M| |v| | / |M v|
// (1 for R = I) of the products involved:
//   D: 3e-6 kappa(A^-T, m) relative;
//   Lambda: 2e-6 kappa(A, u) relative to S = max(1, Lambda, |Au| /
//   (||An|| u.z)), the size of the terms of 1 + Lambda = A_l / u.z before
//   they cancel; S exceeds 1 + Lambda only near the cone where the min of
//   eq. 6 switches on, for thin lunes at grazing angles, where Au known to
//   an ulp leaves Lambda known to an ulp of S. G1: the same error times G1^2;
//   BRDF: 4e-6 kappa (1 + S_i / (1 + Lambda_i) + S_o / (1 + Lambda_o))
//   relative, kappa the largest of kappa(A^-T, wi + wo), kappa(A, wi),
//   kappa(A, wo);
//   PdfVisible: 4e-6 max(kappa(A^-T, m), kappa(A, u)) + 2e-7 / (u.m)
//   relative (the second term is the rounding of the dot product u.m);
//   SampleVisible: normals compared in sphere space p = normalize(A^-T m)
//   (the map to m stretches by up to 1/alpha): |p - p_ref| <= 2e-6 kappa,
//   kappa the largest of kappa(A^-T, m), kappa(A, u), kappa(k x A, u) and
//   the round trip | |A^-T| |A^T| |p| | / |p| of the last step
//   m = normalize(A^T p).
// (tests/kernels/simd_ellipsoid_test.cc asserts these and prints the observed
// maxima.) In double lanes D, Lambda, G1 and the BRDF are within 2e-14
// times the same factors, and PdfVisible within 2e-14 kappa + 1e-15 /
// (u.m), against the double reference at the same (unit, double) inputs;
// measured 2.0e-15, 9.3e-16, 8.6e-16, 8.6e-16 and 0.58 of the pdf's bound
// on every target (CheckEllipsoidF64); SampleVisible in double lanes within
// 2e-14 kappa in sphere space plus 4.4e-16 / lift, the reference's own
// cancellation of its lift at the rim of the disk (measured 0.43 of that
// bound, CheckEllipsoidF64).

#if defined(BRDFBAKE_SRC_KERNELS_ELLIPSOID_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_ELLIPSOID_INL_H_
#undef BRDFBAKE_SRC_KERNELS_ELLIPSOID_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_ELLIPSOID_INL_H_
#endif

#include <algorithm>
#include <cmath>

#include <hwy/highway.h>

#include "brdfbake/models/vec3.h"
#include "kernels/common-inl.h"
#include "kernels/ggx_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants, computed in double from the ellipsoid parameters and
// rounded once to the lane type.
template <class D>
struct EllipsoidConsts {
  using V = hn::Vec<D>;
  using T = hn::TFromD<D>;
  V a[3][3];      // A = S R
  V ait[3][3];    // A^-T = S^-1 R
  V kxa[3][2];    // columns 0, 1 of k x A (column 2 is 0)
  V k[3];         // An / ||An||
  V t1_pole[3];   // basis vector t1 when w = k
  V h[3];         // Lambda: h / ||h||
  V rho, rho2, one_minus_rho2, ls;
  V inv_2an;      // 1 / (2 ||An||)
  V d_scale;      // 1 / (pi ax ay ||An||)
  V pdf_scale;    // 2 ||An||
  V f0;

  EllipsoidConsts(D d, double alpha_x, double alpha_y, double theta_x, double theta_y,
                  double theta_z, double f0_) {
    const double ax = std::max(alpha_x, 1e-4), ay = std::max(alpha_y, 1e-4);
    const Mat3<double> r =
        Mat3<double>::RotX(theta_x) * Mat3<double>::RotY(theta_y) * Mat3<double>::RotZ(theta_z);
    const Mat3<double> am = Mat3<double>::Diagonal(ax, ay, 1.0) * r;
    const Mat3<double> aitm = Mat3<double>::Diagonal(1.0 / ax, 1.0 / ay, 1.0) * r;
    const Vec3<double> an(am.m[0][2], am.m[1][2], am.m[2][2]);
    const double an_len = Length(an);
    const Vec3<double> kd = an / an_len;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        a[i][j] = hn::Set(d, static_cast<T>(am.m[i][j]));
        ait[i][j] = hn::Set(d, static_cast<T>(aitm.m[i][j]));
      }
    }
    for (int j = 0; j < 2; ++j) {
      const Vec3<double> col(am.m[0][j], am.m[1][j], am.m[2][j]);
      const Vec3<double> kc = Cross(kd, col);
      for (int i = 0; i < 3; ++i) kxa[i][j] = hn::Set(d, static_cast<T>(kc[i]));
    }
    // ellipsoid.h's fallback basis for w = k.
    const Vec3<double> t1p = std::abs(kd.y) < 0.9
                                 ? Normalize(Cross(Vec3<double>(0, 1, 0), kd))
                                 : Normalize(Cross(kd, Vec3<double>(1, 0, 0)));
    const Vec3<double> g(aitm.m[0][2], aitm.m[1][2], aitm.m[2][2]);
    const Vec3<double> hv = g * (2 * an_len * an_len) - an;
    const double h_len = Length(hv);
    for (int i = 0; i < 3; ++i) {
      k[i] = hn::Set(d, static_cast<T>(kd[i]));
      t1_pole[i] = hn::Set(d, static_cast<T>(t1p[i]));
      h[i] = hn::Set(d, static_cast<T>(hv[i] / h_len));
    }
    const double rh = std::min(1.0, an_len / h_len);
    rho = hn::Set(d, static_cast<T>(rh));
    rho2 = hn::Set(d, static_cast<T>(rh * rh));
    one_minus_rho2 = hn::Set(d, static_cast<T>((1 - rh) * (1 + rh)));
    ls = hn::Set(d, static_cast<T>(h_len / (2 * an_len * an_len)));
    inv_2an = hn::Set(d, static_cast<T>(0.5 / an_len));
    const double ds = 0.31830988618379067 / (ax * ay * an_len);
    d_scale = hn::Set(d, static_cast<T>(ds));
    pdf_scale = hn::Set(d, static_cast<T>(2 * an_len));
    f0 = hn::Set(d, static_cast<T>(f0_));
  }
};

template <class V>
HWY_INLINE V Dot3(V ax, V ay, V az, V bx, V by, V bz) {
  return hn::MulAdd(ax, bx, hn::MulAdd(ay, by, hn::Mul(az, bz)));
}

// Row i of M times (x, y, z).
template <class V>
HWY_INLINE V Row(const V (&m)[3][3], int i, V x, V y, V z) {
  return Dot3(m[i][0], m[i][1], m[i][2], x, y, z);
}

// ||A^-T m||^4 / |m|^4 as the pair (Q^2, len2^2) so callers fuse divisions.
template <class D, class V>
HWY_INLINE void EllipsoidDParts(const EllipsoidConsts<D>& c, V mx, V my, V mz, V* num, V* den) {
  const V qx = Row(c.ait, 0, mx, my, mz), qy = Row(c.ait, 1, mx, my, mz),
          qz = Row(c.ait, 2, mx, my, mz);
  const V q = Dot3(qx, qy, qz, qx, qy, qz);
  const V len2 = Dot3(mx, my, mz, mx, my, mz);
  *num = hn::Mul(hn::Mul(len2, len2), c.d_scale);
  *den = hn::Mul(q, q);
}

template <class D, class V>
HWY_INLINE V EllipsoidD(D d, const EllipsoidConsts<D>& c, V mx, V my, V mz) {
  V num, den;
  EllipsoidDParts(c, mx, my, mz, &num, &den);
  return hn::IfThenElseZero(hn::Gt(mz, hn::Zero(d)), hn::Div(num, den));
}

// (k x A) u = k x a: the matrix k x A is precomputed with its u.z column
// exactly 0, so the result is accurate (and exactly 0 at u = n) however
// close a comes to k.
template <class D, class V>
HWY_INLINE void KCrossA(const EllipsoidConsts<D>& c, V ux, V uy, V* kx, V* ky, V* kz) {
  *kx = hn::MulAdd(c.kxa[0][0], ux, hn::Mul(c.kxa[0][1], uy));
  *ky = hn::MulAdd(c.kxa[1][0], ux, hn::Mul(c.kxa[1][1], uy));
  *kz = hn::MulAdd(c.kxa[2][0], ux, hn::Mul(c.kxa[2][1], uy));
}

// |a| + a.k = |a| (1 + w.k) = 2 ||An|| A_l(u, n) as xn / xd without
// cancellation: directly where a.k >= 0, else |k x a|^2 / (|a| - a.k)
// (thin lunes, w near -k).
template <class D, class V>
HWY_INLINE void LuneParts(D d, const EllipsoidConsts<D>& c, V ux, V uy, V ax, V ay, V az,
                          V a_len, V* xn, V* xd) {
  V kx, ky, kz;
  KCrossA(c, ux, uy, &kx, &ky, &kz);
  const V ak = Dot3(ax, ay, az, c.k[0], c.k[1], c.k[2]);
  const auto pos = hn::Ge(ak, hn::Zero(d));
  *xn = hn::IfThenElse(pos, hn::Add(a_len, ak), Dot3(kx, ky, kz, kx, ky, kz));
  *xd = hn::IfThenElse(pos, hn::Set(d, hn::TFromD<D>(1)), hn::Sub(a_len, ak));
}

// Lambda(u) = P / (Q u.z), from whichever of two exact forms is better
// conditioned at u: with X = A_l(u, n) = (|a| + a.k) / (2 ||An||) (eq. 26
// and 29: 1 + Lambda = X / u.z; |a| + a.k from LuneParts as xn / xd),
// (P, Q) = ((X - u.z) xd, xd), good for large
// Lambda; or the rationalized (N ls, Dn) of ellipsoid.h, exact as
// Lambda -> 0 for R = I but cancelling for tilted ellipsoids. The lane takes
// the form with the smaller cancellation factor. P is clamped at 0.
template <class D, class V>
HWY_INLINE void EllipsoidLambdaParts(D d, const EllipsoidConsts<D>& c, V ux, V uy, V uz, V* p,
                                     V* q) {
  const V ax = Row(c.a, 0, ux, uy, uz), ay = Row(c.a, 1, ux, uy, uz), az = Row(c.a, 2, ux, uy, uz);
  const V a2 = Dot3(ax, ay, az, ax, ay, az);
  const V a_len = hn::Sqrt(a2);
  V xn, xd;
  LuneParts(d, c, ux, uy, ax, ay, az, a_len, &xn, &xd);
  const V x = hn::Mul(xn, c.inv_2an);  // A_l(u, n) xd
  const V ah = Dot3(ax, ay, az, c.h[0], c.h[1], c.h[2]);
  const V px = hn::NegMulAdd(c.h[0], ah, ax), py = hn::NegMulAdd(c.h[1], ah, ay),
          pz = hn::NegMulAdd(c.h[2], ah, az);
  const V perp2 = Dot3(px, py, pz, px, py, pz);
  const V num_pos = hn::MulSub(c.rho2, perp2, hn::Mul(c.one_minus_rho2, hn::Mul(ah, ah)));
  const V rho_a = hn::Mul(c.rho, a_len);
  const auto pos = hn::Gt(ah, hn::Zero(d));
  const V n = hn::Mul(hn::IfThenElse(pos, num_pos, hn::Sub(rho_a, ah)), c.ls);
  const V dn = hn::IfThenElse(pos, hn::Add(rho_a, ah), hn::Set(d, hn::TFromD<D>(1)));
  // Condition numbers: X / (X - u.z) for the first form, (sum of the
  // magnitudes of N's two terms) / |N| for the second; take the smaller.
  const V terms = hn::IfThenElse(
      pos, hn::MulAdd(c.rho2, perp2, hn::Mul(c.one_minus_rho2, hn::Mul(ah, ah))), hn::Abs(n));
  const V x_minus = hn::NegMulAdd(uz, xd, x);  // (A_l - u.z) xd
  const auto use_x = hn::Le(hn::Mul(x, hn::Abs(n)), hn::Mul(x_minus, hn::Mul(terms, c.ls)));
  *p = hn::Max(hn::IfThenElse(use_x, x_minus, n), hn::Zero(d));
  *q = hn::IfThenElse(use_x, xd, dn);
}

template <class D, class V>
HWY_INLINE V EllipsoidLambda(D d, const EllipsoidConsts<D>& c, V ux, V uy, V uz) {
  V n, dn;
  EllipsoidLambdaParts(d, c, ux, uy, uz, &n, &dn);
  const auto up = hn::Gt(uz, hn::Zero(d));
  const V lambda = hn::Div(n, hn::Mul(dn, hn::IfThenElse(up, uz, hn::Set(d, hn::TFromD<D>(1)))));
  return hn::IfThenElse(up, lambda, hn::Inf(d));
}

template <class D, class V>
HWY_INLINE V EllipsoidG1(D d, const EllipsoidConsts<D>& c, V ux, V uy, V uz) {
  V n, dn;
  EllipsoidLambdaParts(d, c, ux, uy, uz, &n, &dn);
  const V x = hn::Mul(dn, uz);
  const V g1 = hn::Div(x, hn::Add(n, x));
  return hn::IfThenElseZero(hn::Gt(uz, hn::Zero(d)), g1);
}

template <class D, class V, class Fr>
HWY_INLINE V EllipsoidBrdf(D d, const EllipsoidConsts<D>& c, bool separable, V ix, V iy, V iz, V ox, V oy,
                           V oz, const Fr& fresnel) {
  const V sx = hn::Add(ix, ox), sy = hn::Add(iy, oy), sz = hn::Add(iz, oz);
  V d_num, d_den;
  EllipsoidDParts(c, sx, sy, sz, &d_num, &d_den);
  V ni, dni, no, dno;
  EllipsoidLambdaParts(d, c, ix, iy, iz, &ni, &dni);
  EllipsoidLambdaParts(d, c, ox, oy, oz, &no, &dno);
  const V xi = hn::Mul(dni, iz), xo = hn::Mul(dno, oz);
  const V yi = ni, yo = no;
  V g_den;
  if (separable) {
    g_den = hn::Mul(hn::Add(xi, yi), hn::Add(xo, yo));
  } else {
    g_den = hn::MulAdd(xi, xo, hn::MulAdd(yi, xo, hn::Mul(yo, xi)));
  }
  const V num = hn::Mul(d_num, hn::Mul(dni, dno));
  const V dv = hn::Div(num, hn::Mul(hn::Mul(hn::Set(d, hn::TFromD<D>(4)), d_den), g_den));
  const V len2 = Dot3(sx, sy, sz, sx, sy, sz);
  const V f = fresnel(d, CosAtHalf(d, ox, oy, oz, sx, sy, sz, len2));
  const auto valid = hn::And(hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d))),
                             hn::Gt(len2, hn::Set(d, hn::TFromD<D>(1e-30f))));
  return hn::IfThenElseZero(valid, hn::Mul(f, dv));
}

// Seed eq. 30: D(m) (u.m) / A_l(u, n); zero unless u.z, m.z, u.m > 0.
template <class D, class V>
HWY_INLINE V EllipsoidPdfVisible(D d, const EllipsoidConsts<D>& c, V ux, V uy, V uz, V mx, V my,
                                 V mz) {
  const V zero = hn::Zero(d);
  const V ax = Row(c.a, 0, ux, uy, uz), ay = Row(c.a, 1, ux, uy, uz), az = Row(c.a, 2, ux, uy, uz);
  const V a_len = hn::Sqrt(Dot3(ax, ay, az, ax, ay, az));
  V xn, xd;
  LuneParts(d, c, ux, uy, ax, ay, az, a_len, &xn, &xd);
  V d_num, d_den;
  EllipsoidDParts(c, mx, my, mz, &d_num, &d_den);
  const V um = Dot3(ux, uy, uz, mx, my, mz);
  // 1 / A_l = 2 ||An|| xd / xn.
  const V num = hn::Mul(hn::Mul(d_num, um), hn::Mul(c.pdf_scale, xd));
  const V den = hn::Mul(d_den, xn);
  using T = hn::TFromD<D>;
  const V tiny = hn::Set(d, sizeof(T) == 4 ? T(1e-38f) : T(1e-300));  // keeps 0 / 0 off
  const V pdf = hn::Div(num, hn::Max(den, tiny));
  const auto valid = hn::And(hn::And(hn::Gt(uz, zero), hn::Gt(mz, zero)), hn::Gt(um, zero));
  return hn::IfThenElseZero(valid, pdf);
}

// [Walter15] section 4, Version 3 (see the top); m = (0, 0, 0) for u.z <= 0.
template <class D, class V>
HWY_INLINE void EllipsoidSampleVisible(D d, const EllipsoidConsts<D>& c, V ux, V uy, V uz, V u1,
                                       V u2, V* mx, V* my, V* mz) {
  using T = hn::TFromD<D>;
  // Floors of |Au|^2 and of |k x w|^2 (the pole) in the lanes' range.
  constexpr T kTinyLen2 = sizeof(T) == 8 ? T(1e-300) : T(1e-30f);
  constexpr T kPoleKw2 = sizeof(T) == 8 ? T(1e-300) : T(1e-36f);
  const V zero = hn::Zero(d), one = hn::Set(d, T(1));
  const V ax = Row(c.a, 0, ux, uy, uz), ay = Row(c.a, 1, ux, uy, uz), az = Row(c.a, 2, ux, uy, uz);
  const V ra = RsqrtNewton(d, hn::Max(Dot3(ax, ay, az, ax, ay, az), hn::Set(d, kTinyLen2)));
  const V wx = hn::Mul(ax, ra), wy = hn::Mul(ay, ra), wz = hn::Mul(az, ra);
  // t1 = normalize(k x w) = normalize((k x A) u).
  V kx, ky, kz;
  KCrossA(c, ux, uy, &kx, &ky, &kz);
  const V kw2 = Dot3(kx, ky, kz, kx, ky, kz);
  const auto off_pole = hn::Gt(kw2, hn::Set(d, kPoleKw2));
  const V inv_kw = RsqrtNewton(d, hn::IfThenElse(off_pole, kw2, one));
  const V t1x = hn::IfThenElse(off_pole, hn::Mul(kx, inv_kw), c.t1_pole[0]);
  const V t1y = hn::IfThenElse(off_pole, hn::Mul(ky, inv_kw), c.t1_pole[1]);
  const V t1z = hn::IfThenElse(off_pole, hn::Mul(kz, inv_kw), c.t1_pole[2]);
  // t2 = w x t1.
  const V t2x = hn::MulSub(wy, t1z, hn::Mul(wz, t1y));
  const V t2y = hn::MulSub(wz, t1x, hn::Mul(wx, t1z));
  const V t2z = hn::MulSub(wx, t1y, hn::Mul(wy, t1x));
  // s = (1 + w.k) / 2 and 1 - s = (1 - w.k) / 2: the larger one directly,
  // the smaller one from s (1 - s) = |k x w|^2 / 4 = |k x a|^2 / (4 |a|^2),
  // so that both keep their relative precision (thin lunes, w near -k, and
  // views near the cut normal, w near k).
  const V wk = Dot3(wx, wy, wz, c.k[0], c.k[1], c.k[2]);
  const V big = hn::Min(hn::MulAdd(hn::Set(d, T(0.5)), hn::Abs(wk), hn::Set(d, T(0.5))), one);
  const V rb = RsqrtNewton(d, big);
  const V small = hn::Min(hn::Mul(hn::Mul(hn::Mul(kw2, hn::Mul(ra, ra)), hn::Mul(rb, rb)),
                                  hn::Set(d, T(0.25))),
                          big);
  const auto wk_pos = hn::Ge(wk, zero);
  const V s = hn::IfThenElse(wk_pos, big, small);
  const V oms = hn::IfThenElse(wk_pos, small, big);
  V p1, p2, lift;
  CrescentPoint(d, s, oms, u1, u2, &p1, &p2, &lift);
  const V px = hn::MulAdd(t1x, p1, hn::MulAdd(t2x, p2, hn::Mul(wx, lift)));
  const V py = hn::MulAdd(t1y, p1, hn::MulAdd(t2y, p2, hn::Mul(wy, lift)));
  const V pz = hn::MulAdd(t1z, p1, hn::MulAdd(t2z, p2, hn::Mul(wz, lift)));
  // m = normalize(A^T p); column j of A is row j of A^T.
  const V qx = Dot3(c.a[0][0], c.a[1][0], c.a[2][0], px, py, pz);
  const V qy = Dot3(c.a[0][1], c.a[1][1], c.a[2][1], px, py, pz);
  const V qz = hn::Max(Dot3(c.a[0][2], c.a[1][2], c.a[2][2], px, py, pz), zero);
  const V inv_q = RsqrtNewton(d, hn::Max(Dot3(qx, qy, qz, qx, qy, qz), hn::Set(d, kTinyLen2)));
  const auto valid = hn::Gt(uz, zero);
  *mx = hn::IfThenElseZero(valid, hn::Mul(qx, inv_q));
  *my = hn::IfThenElseZero(valid, hn::Mul(qy, inv_q));
  *mz = hn::IfThenElseZero(valid, hn::Mul(qz, inv_q));
}

// The Ellipsoid kernels as the batch loops take them (kernels/batch_rows-inl.h,
// MicrofacetRows): D, Lambda and the BRDF over its constants (its own G1; no
// NDF density).
template <class D>
struct EllipsoidKernels {
  static constexpr bool kOwnG1 = true;
  static constexpr bool kPdfNdfFromD = false;
  const EllipsoidConsts<D>& c;
  template <class V>
  HWY_INLINE V Ndf(D d, V x, V y, V z) const {
    return EllipsoidD(d, c, x, y, z);
  }
  template <class V>
  HWY_INLINE V Lambda(D d, V x, V y, V z) const {
    return EllipsoidLambda(d, c, x, y, z);
  }
  template <class V>
  HWY_INLINE V G1(D d, V x, V y, V z) const {
    return EllipsoidG1(d, c, x, y, z);
  }
  template <class V, class Fr>
  HWY_INLINE V Brdf(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz, const Fr& fr) const {
    return EllipsoidBrdf(d, c, separable, ix, iy, iz, ox, oy, oz, fr);
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_ELLIPSOID_INL_H_
