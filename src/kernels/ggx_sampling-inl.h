// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// GGX sampling SIMD kernels, generic over the lane type (float for the
// batch kernels; double lanes tested by CheckGgxSamplingF64 in
// tests/kernels/simd_ggx_sampling_test.cc: SinCos2Pi within 4e-16 absolute, the
// unit-roughness normals of SampleVisible and SampleNdf within 1e-14,
// PdfVisible within 1e-14 + 1e-15 / (w.m) and PdfNdf within 1e-14
// relative; measured 1.1e-16, 0.48 of its bound, 7.8e-16, 0.19 of its
// bound and 2e-15); the scalar twins (double
// reference) are GgxNdf::SampleVisible ([Heitz18] Listing 1), SlopeNdf::
// SampleNdf, ::DVisible (= GgxNdf::PdfVisible) and ::PdfNdf in
// include/brdfbake/models/ggx.h and slope_ndf.h.
//
// SinCos2Pi: sin and cos of 2 pi u with the range reduction done on u, where
// it is exact: x = 4u, q = round(x), r = x - q in [-1/2, 1/2] (both exact in
// float), so 2 pi u = q pi/2 + r pi/2 with |r pi/2| <= pi/4; Taylor
// polynomials of degree 9 (sin) and 10 (cos) in r, truncation error below
// 2e-9, and the quadrant q mod 4 swaps the pair and sets the signs. Error
// <= 2.5e-7 absolute (tests/kernels/simd_ggx_sampling_test.cc asserts it on 2^20 + 1
// points of [0, 1] on every target; measured 8.7e-8). The reduction is
// exact for any float u, and sin(2 pi u) near u = 0, 1/2, 1 keeps its
// relative precision (r is exact there).
//
// SampleVisible follows [Heitz18] Listing 1 step by step, with the basis in
// closed form and one cancellation removed:
//  - vh = normalize(ax w.x, ay w.y, w.z) = (L cx, L cy, vz), (cx, cy) the
//    unit azimuth of vh (0, -1 at the pole, which gives Listing 1's
//    T1 = (1, 0, 0)); T1 = (-cy, cx, 0), T2 = vh x T1 = (-vz cx, -vz cy, L).
//  - the disk point p1 = r cos(phi), p2 = r sin(phi), r = sqrt(u1), is
//    sheared to p2' = (1 - s) c + s p2, s = (1 + vz) / 2, c = sqrt(1 - p1^2);
//  - the lift sqrt(1 - p1^2 - p2'^2) cancels at the rim of the disk (u1 -> 1)
//    in float. Since 1 - p1^2 - p2'^2 = (c - p2')(c + p2') with
//    c - p2' = s (c - p2) and c + p2' = 2 (1 - s) c + s (c + p2), where
//    c^2 = (1 - u1) + u1 sin^2(phi) (a sum of two non-negative terms) and
//    the smaller of c -+ p2 is (1 - u1) / (c + |p2|), the lift is computed
//    to a few ulp relative everywhere. 1 - s = L^2 / (4 s) keeps its
//    relative precision near normal view.
//  - m = normalize(ax nh.x, ay nh.y, max(0, nh.z)).
// Three square roots, four reciprocal square roots (estimate + one Newton
// step), one division. Lanes with w.z <= 0 return m = (0, 0, 0).
//
// Error: the map from (u1, u2) to m stretches by up to 1/alpha near the
// horizon of m, so the normals are compared in the unit-roughness
// configuration of [Heitz18] section 3.2, nh = normalize(m.x / ax, m.y / ay,
// m.z), where the map is well conditioned: |nh - nh_ref| <= 2e-6 (max
// component) against the double reference at the same float inputs. The
// same bound holds for SampleNdf (nh = normalize(-sqrt(u2) cos(2 pi u1),
// -sqrt(u2) sin(2 pi u1), sqrt(1 - u2)), no division). Measured maxima
// (20 times denser sweeps, all targets): 5.4e-7 (SampleVisible), 1.2e-7
// (SampleNdf). PdfNdf is within 2e-6 relative of the reference, PdfVisible
// within 2e-6 + 2e-7 / (w.m) relative (the second term is the rounding of
// the dot product w.m; measured 0.6 of that bound).

#if defined(BRDFBAKE_SRC_KERNELS_GGX_SAMPLING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_GGX_SAMPLING_INL_H_
#undef BRDFBAKE_SRC_KERNELS_GGX_SAMPLING_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_GGX_SAMPLING_INL_H_
#endif

#include <hwy/highway.h>

#include "kernels/ggx-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// sin(2 pi u) and cos(2 pi u); see the error statement at the top. In
// double lanes the same reduction (x = 4u and r = x - round(x), exact) and
// Taylor polynomials of degree 17 (sin) and 18 (cos), truncation below
// 1e-19: error a few ulp of 1 (CheckGgxSamplingF64).
template <class D, class V>
HWY_INLINE void SinCos2Pi(D d, V u, V* sin_out, V* cos_out) {
  using T = hn::TFromD<D>;
  const hn::RebindToSigned<D> di;
  const V x = hn::Mul(u, hn::Set(d, T(4)));
  V sin_r, cos_r;
  hn::Vec<decltype(di)> q;
  // Taylor coefficients of sin(pi/2 r) / r and cos(pi/2 r) in r^2:
  // (-1)^j (pi/2)^(2j+1) / (2j+1)! and (-1)^j (pi/2)^(2j) / (2j)!.
  if constexpr (sizeof(T) == 4) {
    q = hn::NearestInt(x);
    const V r = hn::Sub(x, hn::ConvertTo(d, q));
    const V r2 = hn::Mul(r, r);
    V ps = hn::Set(d, 1.6044118478735975e-4f);
    ps = hn::MulAdd(ps, r2, hn::Set(d, -4.6817541353186881e-3f));
    ps = hn::MulAdd(ps, r2, hn::Set(d, 7.9692626246167045e-2f));
    ps = hn::MulAdd(ps, r2, hn::Set(d, -6.4596409750624625e-1f));
    ps = hn::MulAdd(ps, r2, hn::Set(d, 1.5707963267948966f));
    sin_r = hn::Mul(ps, r);
    V pc = hn::Set(d, -2.5202042373060596e-5f);
    pc = hn::MulAdd(pc, r2, hn::Set(d, 9.1926027483942658e-4f));
    pc = hn::MulAdd(pc, r2, hn::Set(d, -2.0863480763352961e-2f));
    pc = hn::MulAdd(pc, r2, hn::Set(d, 2.5366950790104802e-1f));
    pc = hn::MulAdd(pc, r2, hn::Set(d, -1.2337005501361697f));
    cos_r = hn::MulAdd(pc, r2, hn::Set(d, 1.0f));
  } else {
    const V qf = hn::Round(x);
    q = hn::ConvertTo(di, qf);
    const V r = hn::Sub(x, qf);
    const V r2 = hn::Mul(r, r);
    static constexpr T kSin[9] = {
        6.0669357311061955e-12, -6.688035109811468e-10, 5.692172921967927e-08,
        -3.598843235212085e-06, 0.00016044118478735983, -0.004681754135318688,
        0.07969262624616705,    -0.6459640975062463,    1.5707963267948966};
    static constexpr T kCos[10] = {-5.294400200734623e-13,  6.565963114979473e-11,
                                   -6.386603083791852e-09,  4.710874778818172e-07,
                                   -2.5202042373060607e-05, 0.0009192602748394266,
                                   -0.02086348076335296,    0.25366950790104803,
                                   -1.2337005501361697,     1.0};
    V ps = hn::Set(d, kSin[0]);
    for (int j = 1; j < 9; ++j) ps = hn::MulAdd(ps, r2, hn::Set(d, kSin[j]));
    sin_r = hn::Mul(ps, r);
    V pc = hn::Set(d, kCos[0]);
    for (int j = 1; j < 10; ++j) pc = hn::MulAdd(pc, r2, hn::Set(d, kCos[j]));
    cos_r = pc;
  }
  // Quadrant q mod 4: odd q swaps sin and cos; sin is negated for q = 2, 3
  // (bit 1 of q), cos for q = 1, 2 (bit 1 of q + 1).
  constexpr int kToSign = static_cast<int>(sizeof(T) * 8) - 2;  // bit 1 to the sign bit
  const auto one_i = hn::Set(di, 1);
  const auto odd = hn::RebindMask(d, hn::Eq(hn::And(q, one_i), one_i));
  const V sign = hn::SignBit(d);
  const V sign_s = hn::And(hn::BitCast(d, hn::ShiftLeft<kToSign>(q)), sign);
  const V sign_c = hn::And(hn::BitCast(d, hn::ShiftLeft<kToSign>(hn::Add(q, one_i))), sign);
  *sin_out = hn::Xor(hn::IfThenElse(odd, cos_r, sin_r), sign_s);
  *cos_out = hn::Xor(hn::IfThenElse(odd, sin_r, cos_r), sign_c);
}

// Per-call constants of the GGX samplers and pdfs.
template <class D>
struct GgxSamplingConsts {
  using T = hn::TFromD<D>;
  GgxConsts<D> ggx;
  hn::Vec<D> ax, ay;
  GgxSamplingConsts(D d, T ax_, T ay_) : ggx(d, ax_, ay_, T(1)) {
    ax = hn::Set(d, ax_ < T(1e-4) ? T(1e-4) : ax_);
    ay = hn::Set(d, ay_ < T(1e-4) ? T(1e-4) : ay_);
  }
  // Per-element widths, one per lane.
  GgxSamplingConsts(D d, hn::Vec<D> ax_, hn::Vec<D> ay_) : ggx(d, ax_, ay_, hn::Set(d, T(1))) {
    ax = hn::Max(ax_, hn::Set(d, T(1e-4)));
    ay = hn::Max(ay_, hn::Set(d, T(1e-4)));
  }
};

// The crescent step shared by GGX and the ellipsoid ([Heitz18] section 4.2,
// [Walter15] section 4 Version 3): for a view whose lune has compression
// s = (1 + cos) / 2 (oms = 1 - s, passed separately so that it keeps its
// relative precision near normal view), returns the in-plane point
// (p1, p2') and the lift z = sqrt(1 - p1^2 - p2'^2) along the view,
// cancellation-free (see the derivation at the top).
template <class D, class V>
HWY_INLINE void CrescentPoint(D d, V s, V oms, V u1, V u2, V* p1, V* p2s, V* lift) {
  const V one = hn::Set(d, hn::TFromD<D>(1));
  V sn, cs;
  SinCos2Pi(d, u2, &sn, &cs);
  const V uc = hn::Min(hn::Max(u1, hn::Zero(d)), one);
  const V one_minus_u1 = hn::Sub(one, uc);
  const V r = hn::Sqrt(uc);
  *p1 = hn::Mul(r, cs);
  const V p2 = hn::Mul(r, sn);
  const V c = hn::Sqrt(hn::MulAdd(hn::Mul(uc, sn), sn, one_minus_u1));  // sqrt(1 - p1^2)
  *p2s = hn::MulAdd(oms, c, hn::Mul(s, p2));
  // c + |p2| directly, c - |p2| = (1 - u1) / (c + |p2|).
  const V sum = hn::Add(c, hn::Abs(p2));
  const V diff = hn::Div(one_minus_u1, hn::Max(sum, hn::Set(d, hn::TFromD<D>(1e-30f))));
  const auto p2_pos = hn::Gt(p2, hn::Zero(d));
  const V c_minus_p2 = hn::IfThenElse(p2_pos, diff, sum);
  const V c_plus_p2 = hn::IfThenElse(p2_pos, sum, diff);
  // 1 - p1^2 - p2'^2 = (c - p2')(c + p2') = s (c - p2) (2 oms c + s (c + p2)).
  const V z2 =
      hn::Mul(hn::Mul(s, c_minus_p2), hn::MulAdd(hn::Add(oms, oms), c, hn::Mul(s, c_plus_p2)));
  *lift = hn::Sqrt(hn::Max(z2, hn::Zero(d)));
}

// [Heitz18] Listing 1: a visible normal of GGX for the view w, from (u1, u2).
template <class D, class V>
HWY_INLINE void GgxSampleVisible(D d, const GgxSamplingConsts<D>& c, V wx, V wy, V wz, V u1, V u2,
                                 V* mx, V* my, V* mz) {
  const V zero = hn::Zero(d), one = hn::Set(d, hn::TFromD<D>(1)),
          half = hn::Set(d, hn::TFromD<D>(0.5));
  // Section 3.2: to the hemisphere configuration; vh = (L cx, L cy, vz).
  const V gx = hn::Mul(c.ax, wx), gy = hn::Mul(c.ay, wy);
  const V g2 = hn::MulAdd(gx, gx, hn::Mul(gy, gy));
  const auto off_pole = hn::Gt(g2, hn::Set(d, hn::TFromD<D>(1e-36f)));
  const V inv_g = RsqrtNewton(d, hn::IfThenElse(off_pole, g2, one));
  const V cx = hn::IfThenElseZero(off_pole, hn::Mul(gx, inv_g));
  const V cy = hn::IfThenElse(off_pole, hn::Mul(gy, inv_g), hn::Set(d, hn::TFromD<D>(-1)));
  const V inv_len = RsqrtNewton(d, hn::MulAdd(wz, wz, hn::IfThenElse(off_pole, g2, zero)));
  const V l = hn::IfThenElseZero(off_pole, hn::Mul(hn::Mul(g2, inv_g), inv_len));
  const V vz = hn::Mul(wz, inv_len);
  // Section 4.2: point on the projected area, s = (1 + vz) / 2 and
  // 1 - s = (1 - vz) / 2 = L^2 / (4 s), without the cancellation of 1 - vz.
  const V s = hn::MulAdd(half, vz, half);
  const V rs = RsqrtNewton(d, s);
  const V oms = hn::Mul(hn::Mul(hn::Mul(l, l), hn::Mul(rs, rs)), hn::Set(d, hn::TFromD<D>(0.25)));
  V p1, p2, lift;
  CrescentPoint(d, s, oms, u1, u2, &p1, &p2, &lift);
  // Section 4.3: nh = T1 p1 + T2 p2 + vh lift, then back to the ellipsoid.
  const V t = hn::MulSub(l, lift, hn::Mul(vz, p2));  // L lift - vz p2
  const V nx = hn::MulSub(cx, t, hn::Mul(cy, p1));
  const V ny = hn::MulAdd(cy, t, hn::Mul(cx, p1));
  const V nz = hn::Max(hn::MulAdd(l, p2, hn::Mul(vz, lift)), zero);
  const V sx = hn::Mul(c.ax, nx), sy = hn::Mul(c.ay, ny);
  const V inv_m = RsqrtNewton(d, hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(nz, nz))));
  const auto valid = hn::Gt(wz, zero);
  *mx = hn::IfThenElseZero(valid, hn::Mul(sx, inv_m));
  *my = hn::IfThenElseZero(valid, hn::Mul(sy, inv_m));
  *mz = hn::IfThenElseZero(valid, hn::Mul(nz, inv_m));
}

// NDF sampling (density D(m) m.z): slope r (ax cos phi, ay sin phi) with
// r^2 = u2 / (1 - u2), phi = 2 pi u1 (slope_ndf.h), m = normalize(-slope, 1)
// multiplied through by sqrt(1 - u2): no division, and u2 = 1 gives the
// horizon normal instead of an infinite slope.
template <class D, class V>
HWY_INLINE void GgxSampleNdf(D d, const GgxSamplingConsts<D>& c, V u1, V u2, V* mx, V* my, V* mz) {
  const V one = hn::Set(d, hn::TFromD<D>(1));
  const V uc = hn::Min(hn::Max(u2, hn::Zero(d)), one);
  V sn, cs;
  SinCos2Pi(d, u1, &sn, &cs);
  const V r = hn::Sqrt(uc);
  const V z = hn::Sqrt(hn::Sub(one, uc));
  const V sx = hn::Neg(hn::Mul(hn::Mul(c.ax, r), cs));
  const V sy = hn::Neg(hn::Mul(hn::Mul(c.ay, r), sn));
  const V inv_m = RsqrtNewton(d, hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(z, z))));
  *mx = hn::Mul(sx, inv_m);
  *my = hn::Mul(sy, inv_m);
  *mz = hn::Mul(z, inv_m);
}

// Visible-normal density G1(w) max(0, w.m) D(m) / w.z ([Heitz18] eq. 3)
// with G1(w) = 2 w.z / (w.z + R), R = sqrt(w.z^2 + ax^2 w.x^2 + ay^2 w.y^2):
// = 2 (w.m) |m|^4 / (pi ax ay Q^2 (w.z + R)), Q as in GgxD. One square root,
// one division; zero unless w.z, m.z and w.m are positive.
template <class D, class V>
HWY_INLINE V GgxPdfVisible(D d, const GgxSamplingConsts<D>& c, V wx, V wy, V wz, V mx, V my, V mz) {
  const GgxConsts<D>& g = c.ggx;
  const V zero = hn::Zero(d);
  const V len2 = hn::MulAdd(mx, mx, hn::MulAdd(my, my, hn::Mul(mz, mz)));
  const V q = hn::MulAdd(hn::Mul(mx, mx), g.inv_ax2,
                         hn::MulAdd(hn::Mul(my, my), g.inv_ay2, hn::Mul(mz, mz)));
  const V r = hn::Sqrt(
      hn::MulAdd(wz, wz, hn::MulAdd(hn::Mul(wx, wx), g.ax2, hn::Mul(hn::Mul(wy, wy), g.ay2))));
  const V wm = hn::MulAdd(wx, mx, hn::MulAdd(wy, my, hn::Mul(wz, mz)));
  const V num = hn::Mul(hn::Mul(hn::Add(wm, wm), hn::Mul(len2, len2)), g.inv_pi_axay);
  const V pdf = hn::Div(num, hn::Mul(hn::Mul(q, q), hn::Add(wz, r)));
  const auto valid = hn::And(hn::And(hn::Gt(wz, zero), hn::Gt(mz, zero)), hn::Gt(wm, zero));
  return hn::IfThenElseZero(valid, pdf);
}

// NDF-sampling density D(m) m.z (zero for m.z <= 0).
template <class D, class V>
HWY_INLINE V GgxPdfNdf(D d, const GgxSamplingConsts<D>& c, V mx, V my, V mz) {
  return hn::Mul(GgxD(d, c.ggx, mx, my, mz), mz);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_GGX_SAMPLING_INL_H_
