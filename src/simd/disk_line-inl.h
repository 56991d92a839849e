// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The integrand of the baker's two-dimensional quadrature (src/integrate.h,
// GgxDiskLines) in double-precision lanes: quadrature nodes along one line
// u2 = const of the GGX visible-normal disk, several per vector. The scalar
// twin is GgxDiskLines<Ndf>::Line::Eval and ::Z; both compute the same
// expressions in the same order, except that sin comes from Highway's Sin
// (3 ulp) instead of the C library's, so they agree to a few ulps of each
// term (tests/quadrature_simd_test.cc compares whole texels).
//
// The model enters through two functions (the traits below):
//   Ratio(r2): [D_M / D_ggx] at the squared standard slope r2 of the
//     hemisphere-configuration normal (not used for GGX itself);
//   Lambda(w): the model's Smith Lambda of a direction above the horizon
//     (lanes below the horizon are masked out by the caller).

#if defined(BRDFBAKE_SIMD_DISK_LINE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SIMD_DISK_LINE_INL_H_
#undef BRDFBAKE_SIMD_DISK_LINE_INL_H_
#else
#define BRDFBAKE_SIMD_DISK_LINE_INL_H_
#endif

#include <cmath>
#include <cstddef>

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The per-texel and per-line constants of GgxDiskLines, broadcast.
template <class D>
struct DiskLineConsts {
  using V = hn::Vec<D>;
  V c, s;               // cos, sin of the disk azimuth 2 pi u2
  V sh, one_minus_sh;   // (1 + vh.z) / 2 and its complement
  V t1x, t1y, t1z, t2x, t2y, t2z, vhx, vhy, vhz;
  V wox, woy, woz;
  V ax, ay;
  V lambda_wo, one_plus_lambda_ggx_wo;
  template <class Lines>
  DiskLineConsts(D d, const Lines& f, double cos_phi, double sin_phi)
      : c(hn::Set(d, cos_phi)), s(hn::Set(d, sin_phi)), sh(hn::Set(d, f.sh)),
        one_minus_sh(hn::Set(d, 1 - f.sh)),
        t1x(hn::Set(d, f.t1.x)), t1y(hn::Set(d, f.t1.y)), t1z(hn::Set(d, f.t1.z)),
        t2x(hn::Set(d, f.t2.x)), t2y(hn::Set(d, f.t2.y)), t2z(hn::Set(d, f.t2.z)),
        vhx(hn::Set(d, f.vh.x)), vhy(hn::Set(d, f.vh.y)), vhz(hn::Set(d, f.vh.z)),
        wox(hn::Set(d, f.wo.x)), woy(hn::Set(d, f.wo.y)), woz(hn::Set(d, f.wo.z)),
        ax(hn::Set(d, f.ax)), ay(hn::Set(d, f.ay)), lambda_wo(hn::Set(d, f.lambda_wo)),
        one_plus_lambda_ggx_wo(hn::Set(d, 1 + f.lambda_ggx_wo)) {}
};

// The hemisphere-configuration normal nh at t (disk radius sin(pi t / 2)),
// the microfacet normal m, wo.m and wi = reflect(wo, m).
template <class D>
struct DiskPoint {
  hn::Vec<D> nhx, nhy, nhz, wo_m, wix, wiy, wiz;
};

template <class D, class V = hn::Vec<D>>
HWY_INLINE DiskPoint<D> DiskPointAt(D d, const DiskLineConsts<D>& k, V t) {
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const V r = hn::Sin(d, hn::Mul(hn::Set(d, 1.5707963267948966), t));
  const V p1 = hn::Mul(r, k.c);
  const V one_minus_p1sq = hn::Sub(one, hn::Mul(p1, p1));
  const V p2 = hn::Add(hn::Mul(k.one_minus_sh, hn::Sqrt(hn::Max(zero, one_minus_p1sq))),
                       hn::Mul(k.sh, hn::Mul(r, k.s)));
  const V lift = hn::Sqrt(hn::Max(zero, hn::Sub(one_minus_p1sq, hn::Mul(p2, p2))));
  DiskPoint<D> q;
  q.nhx = hn::Add(hn::Add(hn::Mul(k.t1x, p1), hn::Mul(k.t2x, p2)), hn::Mul(k.vhx, lift));
  q.nhy = hn::Add(hn::Add(hn::Mul(k.t1y, p1), hn::Mul(k.t2y, p2)), hn::Mul(k.vhy, lift));
  q.nhz = hn::Add(hn::Add(hn::Mul(k.t1z, p1), hn::Mul(k.t2z, p2)), hn::Mul(k.vhz, lift));
  // m = normalize(ax nh.x, ay nh.y, max(0, nh.z)).
  const V mx0 = hn::Mul(k.ax, q.nhx), my0 = hn::Mul(k.ay, q.nhy), mz0 = hn::Max(zero, q.nhz);
  const V len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(mx0, mx0), hn::Mul(my0, my0)), hn::Mul(mz0, mz0)));
  const V mx = hn::Div(mx0, len), my = hn::Div(my0, len), mz = hn::Div(mz0, len);
  q.wo_m = hn::Add(hn::Add(hn::Mul(k.wox, mx), hn::Mul(k.woy, my)), hn::Mul(k.woz, mz));
  const V two_wo_m = hn::Mul(hn::Set(d, 2.0), q.wo_m);
  q.wix = hn::Sub(hn::Mul(mx, two_wo_m), k.wox);
  q.wiy = hn::Sub(hn::Mul(my, two_wo_m), k.woy);
  q.wiz = hn::Sub(hn::Mul(mz, two_wo_m), k.woz);
  return q;
}

// wi.z at t: the function whose sign changes are the horizon crossings.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V DiskZ(D d, const DiskLineConsts<D>& k, V t) {
  return DiskPointAt(d, k, t).wiz;
}

// (w, w Fc) at t: for GGX G2 / G1(wo); for a model sampled through the GGX
// disk [D_M / D_ggx] G2_M / G1_ggx(wo); zero where wi or wo.m is not above
// the horizon (GgxDiskLines::Line::Eval).
template <bool kIsGgx, class D, class Model, class Separable, class V = hn::Vec<D>>
HWY_INLINE void DiskEval(D d, const DiskLineConsts<D>& k, const Model& model, Separable separable,
                         V t, V* w, V* w_fc) {
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const DiskPoint<D> q = DiskPointAt(d, k, t);
  const auto valid = hn::And(hn::Gt(q.wiz, zero), hn::Gt(q.wo_m, zero));
  const V lambda_wi = model.Lambda(d, q.wix, q.wiy, q.wiz);
  V v;
  if constexpr (kIsGgx) {
    v = separable ? hn::Div(one, hn::Add(one, lambda_wi))
                  : hn::Div(hn::Add(one, k.lambda_wo), hn::Add(hn::Add(one, lambda_wi), k.lambda_wo));
  } else {
    const V r2 = hn::Div(hn::Add(hn::Mul(q.nhx, q.nhx), hn::Mul(q.nhy, q.nhy)),
                         hn::Mul(q.nhz, q.nhz));
    const V g2 = separable
                     ? hn::Div(one, hn::Mul(hn::Add(one, lambda_wi), hn::Add(one, k.lambda_wo)))
                     : hn::Div(one, hn::Add(hn::Add(one, lambda_wi), k.lambda_wo));
    v = hn::Mul(hn::Mul(model.Ratio(d, r2), g2), k.one_plus_lambda_ggx_wo);
  }
  v = hn::IfThenElseZero(valid, v);
  const V m = hn::Min(hn::Max(hn::Sub(one, q.wo_m), zero), one);
  const V m2 = hn::Mul(m, m);
  *w = v;
  *w_fc = hn::Mul(v, hn::Mul(hn::Mul(m2, m2), m));
}

// Lambda of the isotropic or anisotropic GGX as GgxDiskLines::GgxLambda:
// 1/a^2 = (ax^2 x^2 + ay^2 y^2) / z^2, Lambda = (1/a^2) / (2 (1 + sqrt(1 + 1/a^2))).
template <class D>
struct GgxDiskModel {
  hn::Vec<D> ax, ay;
  template <class V>
  HWY_INLINE V Lambda(D d, V x, V y, V z) const {
    const V px = hn::Mul(ax, x), py = hn::Mul(ay, y);
    const V inv_a2 = hn::Div(hn::Add(hn::Mul(px, px), hn::Mul(py, py)), hn::Mul(z, z));
    const V one = hn::Set(d, 1.0);
    return hn::Div(inv_a2, hn::Mul(hn::Set(d, 2.0), hn::Add(one, hn::Sqrt(hn::Add(one, inv_a2)))));
  }
};

// D_Beckmann / D_ggx = pi P22(r2) (1 + r2)^2 with P22 = exp(-r2) / pi.
template <class D, class V>
HWY_INLINE V BeckmannOverGgx(D d, V r2) {
  const V q = hn::Add(hn::Set(d, 1.0), r2);
  // Beyond r2 = 706 exp(-r2) is below the smallest normal double (and
  // Highway's Exp range): the ratio is 0 to double precision.
  const V e = hn::Exp(d, hn::Neg(hn::Min(r2, hn::Set(d, 706.0))));
  return hn::IfThenElseZero(hn::Lt(r2, hn::Set(d, 706.0)), hn::Mul(e, hn::Mul(q, q)));
}

// D_std / D_ggx = pi P22(r2) (1 + r2)^2 with P22 = exp(-gamma log1p(r2 / (gamma - 1))) / pi
// (seed 004 eq. 13 with sigma = 1).
template <class D, class V>
HWY_INLINE V StudentTOverGgx(D d, V r2, V gamma, V inv_gamma_minus_1) {
  const V q = hn::Add(hn::Set(d, 1.0), r2);
  const V ex = hn::Mul(gamma, hn::Log1p(d, hn::Mul(r2, inv_gamma_minus_1)));
  const V e = hn::Exp(d, hn::Neg(hn::Min(ex, hn::Set(d, 745.0))));
  // Infinite r2 (nh.z = 0, masked by the caller) gives exp(-inf) * inf.
  return hn::IfThenElseZero(hn::Lt(ex, hn::Set(d, 745.0)), hn::Mul(e, hn::Mul(q, q)));
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SIMD_DISK_LINE_INL_H_
