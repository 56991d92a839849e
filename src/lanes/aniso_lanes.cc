// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ggx-aniso slope-plane rule (rules/ggx_aniso/aniso_ggx_rule.h) with
// each ray piece's nodes in double SIMD lanes.

#include <cstddef>

#include "lanes/aniso_lanes.h"
#include "rules/ggx_aniso/aniso_ggx_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/aniso_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One piece of a ggx-aniso ray (aniso_ggx_rule.h, ScalarAnisoNodes) with
// its 16 nodes (15 and one of weight 0) in lanes: AnisoRay::Eval, the same
// operations in the same order.
struct SimdAnisoNodes {
  void operator()(const AnisoFrame& f, const AnisoRay& ray, double v_b, double c, double h,
                  double* k, double* g) const {
    using V = hn::Vec<DF64>;
    static const Kronrod16 rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    const V vb = hn::Set(d, v_b), two_vb = hn::Set(d, 2 * v_b);
    const V cv = hn::Set(d, c), hv = hn::Set(d, h);
    const V u_b = hn::Set(d, ray.u_b), omub = hn::Set(d, ray.one_minus_ub);
    const V ex = hn::Set(d, ray.ex), ey = hn::Set(d, ray.ey), ce = hn::Set(d, ray.ce);
    const V rho_b = hn::Set(d, ray.rho_b), isc = hn::Set(d, ray.inv_s_plus_ce);
    const V wz_ee = hn::Set(d, f.wz * ray.ee), two_wz = hn::Set(d, 2 * f.wz);
    const V wx = hn::Set(d, f.wx), wy = hn::Set(d, f.wy);
    const V fax = hn::Set(d, f.ax), fay = hn::Set(d, f.ay);
    const V zw = hn::Set(d, f.z_weight), gs = hn::Set(d, f.g_scale);
    V ks = zero, gsum = zero;
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::MulAdd(hv, hn::Load(d, rule.x + i), cv);
      const V w = hn::Mul(x, hn::Sub(two_vb, x));
      const V jac = hn::Mul(two, hn::Sub(vb, x));
      const V u = hn::Max(zero, hn::Sub(u_b, w));
      const V omu = hn::Add(omub, w);
      const V rho = hn::Sqrt(hn::Div(u, omu));
      const V p = hn::Mul(rho, ex), q = hn::Mul(rho, ey);
      const V n2 = hn::MulAdd(q, q, hn::MulAdd(p, p, one));
      const V lin = hn::MulAdd(rho, ce, one);
      const V m = hn::Mul(hn::Mul(omub, omu), hn::Add(rho_b, rho));
      const V z = hn::Mul(hn::Mul(wz_ee, w), hn::Add(rho, isc));
      const V kk = hn::Mul(two_wz, lin);
      const V X = hn::Neg(hn::Mul(hn::MulAdd(kk, p, hn::Mul(wx, n2)), m));
      const V Y = hn::Neg(hn::Mul(hn::MulAdd(kk, q, hn::Mul(wy, n2)), m));
      const V ax = hn::Mul(fax, X), ay = hn::Mul(fay, Y);
      const V root = hn::Sqrt(hn::MulAdd(z, z, hn::MulAdd(ax, ax, hn::Mul(ay, ay))));
      const V val = hn::Mul(hn::Div(hn::Mul(hn::Mul(two, z), lin), hn::MulAdd(zw, z, root)), gs);
      const auto valid = hn::And(hn::Gt(z, zero), hn::Gt(lin, zero));
      const V v = hn::Mul(hn::IfThenElseZero(valid, val), jac);
      ks = hn::MulAdd(hn::Load(d, rule.wk + i), v, ks);
      gsum = hn::MulAdd(hn::Load(d, rule.wg + i), v, gsum);
    }
    *k = hn::GetLane(hn::SumOfLanes(d, ks));
    *g = hn::GetLane(hn::SumOfLanes(d, gsum));
  }
};


RuleResult AnisoAlbedoTexel(double alpha_x, double alpha_y, double mu, double phi,
                                 Masking masking, double tol, int max_pieces) {
  return AnisoGgxAlbedoWith(alpha_x, alpha_y, mu, phi, masking, tol, max_pieces,
                            SimdAnisoNodes{});
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(AnisoAlbedoTexel);
RuleResult SimdAnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                                   Masking masking, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(AnisoAlbedoTexel)(alpha_x, alpha_y, mu, phi, masking, tol,
                                                max_pieces);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
