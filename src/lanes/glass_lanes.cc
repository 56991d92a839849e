// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The glass albedo rule (rules/glass/glass_albedo_rule.h) with each ray
// piece's nodes in double SIMD lanes: the same rays, cuts, pieces and
// nodes as the scalar reference ScalarGlassNodes, the 15 values of a
// piece computed together (the 16th lane repeats the first node and is
// dropped). Likewise the E_avg rule (rules/glass/glass_average_rule.h)
// with each psi piece's nodes in lanes (ScalarAverageLines).

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"
#include "lanes/glass_lanes.h"
#include "rules/glass/glass_albedo.h"
#include "rules/glass/glass_albedo_rule.h"
#include "rules/glass/glass_average_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/glass_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// ScalarGlassNodes in lanes, term by term:
//  - cos and sin of theta by Highway's Cos and Sin (within 3 ulp on
//    Highway 1.0.3; theta is in [0, pi/2]);
//  - the microfacet h = m / |m| and its Fresnel cosine c = wo.h clamped to
//    [0, 1];
//  - F by the same amplitudes as FresnelDielectric (models/fresnel.h,
//    [Walter07] eq. 22 in its cos_t form), 1 where sin^2(theta_t) >= 1
//    (total internal reflection, eta < 1);
//  - the reflection r = 2 c h - wo and the refraction t = -wo / eta +
//    (c / eta - cos_t) h ([Walter07] eq. 40), each counted where it lies on
//    its side of the surface;
//  - Lambda of r and of t (turned to z > 0) in the GGX form without a
//    division by the cosine, P / (2 (z^2 + z sqrt(z^2 + P))), P = alpha^2
//    (x^2 + y^2) (ggx-inl.h's GgxLambda; the reference forms 1/a^2 =
//    P / z^2 first), and G2 / G1(wo) of the bsdf's masking.
// The divisions by eta become products by 1 / eta. Every node differs
// from the reference by the rounding of these terms only: a few ulp of
// the largest term, more next to the critical angle, where F has an
// infinite slope in c (tests/lanes/glass_lanes_test.cc bounds the
// albedos of both paths against each other on every target). `part`
// drops the refraction or the reflection term, as the reference does;
// kTransmissionSchlick weights the refraction by 1 - (1 - c)^5 and forms
// no F (its eta may be inf: 1 / eta = 0, t = -h).
struct SimdGlassNodes {
  using V = hn::Vec<DF64>;
  const GlassFrame* frame;
  bool separable;
  double g1o_inv;  // 1 + Lambda(wo) (height-correlated); unused when separable
  double lambda_o;
  DielectricPart part = DielectricPart::kBoth;

  void operator()(const GlassRay& ray, const double* theta, double* v) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const GlassFrame& f = *frame;
    HWY_ALIGN double in[16], out[16];
    NodesTo16(theta, in);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
    const V alpha = hn::Set(d, f.alpha), alpha2 = hn::Set(d, f.alpha * f.alpha);
    const V vx = hn::Set(d, f.vx), vz = hn::Set(d, f.vz);
    const V cp = hn::Set(d, ray.cp), sp = hn::Set(d, ray.sp);
    const V so = hn::Set(d, f.so), mu = hn::Set(d, f.mu);
    const V eta = hn::Set(d, f.eta), inv_eta = hn::Set(d, 1 / f.eta);
    const V inv_eta2 = hn::Set(d, 1 / (f.eta * f.eta));
    const V g1o = hn::Set(d, g1o_inv), one_lo = hn::Set(d, 1 + lambda_o);
    // G2 / G1(wo) at Lambda's numerator p and z = |w.z| > 0.
    auto g2_over_g1 = [&](V p, V z) {
      const V z2 = hn::Mul(z, z);
      const V lambda = hn::Div(p, hn::Mul(hn::Set(d, 2.0), hn::MulAdd(z, hn::Sqrt(hn::Add(z2, p)), z2)));
      return separable ? hn::Div(one, hn::Add(one, lambda)) : hn::Div(g1o, hn::Add(one_lo, lambda));
    };
    // All lanes true or all false: the part's terms, and the refraction's
    // weight (1 - F, or Schlick's complement 1 - (1 - c)^5).
    const bool schlick = part == DielectricPart::kTransmissionSchlick;
    const auto keep_r = hn::Ne(hn::Set(d, RefractionPart(part) ? 0.0 : 1.0), zero);
    const auto keep_t = hn::Ne(hn::Set(d, part == DielectricPart::kReflection ? 0.0 : 1.0), zero);
    const auto use_schlick = hn::Ne(hn::Set(d, schlick ? 1.0 : 0.0), zero);
    for (size_t i = 0; i < 16; i += N) {
      const V th = hn::Load(d, in + i);
      const V ct = hn::Cos(d, th), st = hn::Sin(d, th);
      // m = alpha (ct vx - st sp vz, st cp, .) and m.z = ct vz + st sp vx
      // (GlassFrame::M).
      const V ssp = hn::Mul(st, sp);
      const V mx = hn::Mul(alpha, hn::Sub(hn::Mul(ct, vx), hn::Mul(ssp, vz)));
      const V my = hn::Mul(alpha, hn::Mul(st, cp));
      const V mz = hn::Add(hn::Mul(ct, vz), hn::Mul(ssp, vx));
      const V len = hn::Sqrt(hn::MulAdd(mx, mx, hn::MulAdd(my, my, hn::Mul(mz, mz))));
      const auto valid = hn::And(hn::Gt(len, zero), hn::Ge(mz, zero));
      const V inv_len = hn::Div(one, hn::IfThenElse(valid, len, one));
      const V hx = hn::Mul(mx, inv_len), hy = hn::Mul(my, inv_len), hz = hn::Mul(mz, inv_len);
      const V c = hn::Min(hn::Max(hn::MulAdd(so, hx, hn::Mul(mu, hz)), zero), one);
      // Fresnel: sin^2(theta_t) = (1 - c^2) / eta^2.
      const V omc2 = hn::Mul(hn::Sub(one, c), hn::Add(one, c));
      const V sin2_t = hn::Mul(omc2, inv_eta2);
      const auto tir = hn::Ge(sin2_t, one);
      const V cos_t = hn::Sqrt(hn::Max(hn::Sub(one, sin2_t), zero));
      const V ec = hn::Mul(eta, c), et = hn::Mul(eta, cos_t);
      const V r_parl = hn::Div(hn::Sub(ec, cos_t), hn::Add(ec, cos_t));
      const V r_perp = hn::Div(hn::Sub(c, et), hn::Add(c, et));
      // F is not formed for the Schlick weight (eta may be inf there).
      const V fr = hn::IfThenElse(use_schlick, zero,
                                  hn::IfThenElse(tir, one, hn::Mul(half, hn::MulAdd(r_parl, r_parl, hn::Mul(r_perp, r_perp)))));
      // Reflection r = 2 c h - wo (wo = (so, 0, mu)).
      const V two_c = hn::Add(c, c);
      const V rx = hn::MulSub(two_c, hx, so), ry = hn::Mul(two_c, hy), rz = hn::MulSub(two_c, hz, mu);
      const auto r_ok = hn::And(hn::And(hn::Gt(rz, zero), hn::Gt(fr, zero)), keep_r);
      const V rz_safe = hn::IfThenElse(r_ok, rz, one);
      const V pr = hn::Mul(alpha2, hn::MulAdd(rx, rx, hn::Mul(ry, ry)));
      V w = hn::IfThenElseZero(r_ok, hn::Mul(fr, g2_over_g1(pr, rz_safe)));
      // Refraction t = -wo / eta + (c / eta - cos_t) h, cos_t^2 = 1 - (1 -
      // c^2) / eta^2.
      const V ct2 = hn::Sub(one, hn::Mul(omc2, inv_eta2));
      const V k = hn::Sub(hn::Mul(c, inv_eta), hn::Sqrt(hn::Max(ct2, zero)));
      const V tx = hn::MulSub(k, hx, hn::Mul(so, inv_eta)), ty = hn::Mul(k, hy);
      const V tz = hn::MulSub(k, hz, hn::Mul(mu, inv_eta));
      const auto t_ok = hn::And(hn::And(hn::And(hn::Gt(ct2, zero), hn::Lt(fr, one)), hn::Lt(tz, zero)), keep_t);
      const V tz_safe = hn::IfThenElse(t_ok, hn::Neg(tz), one);
      const V pt = hn::Mul(alpha2, hn::MulAdd(tx, tx, hn::Mul(ty, ty)));
      const V omc = hn::Sub(one, c), omc2s = hn::Mul(omc, omc);
      const V s5 = hn::Mul(hn::Mul(omc2s, omc2s), omc);
      const V weight_t = hn::IfThenElse(use_schlick, hn::Sub(one, s5), hn::Sub(one, fr));
      w = hn::Add(w, hn::IfThenElseZero(t_ok, hn::Mul(weight_t, g2_over_g1(pt, tz_safe))));
      hn::Store(hn::IfThenElseZero(valid, hn::Mul(hn::Mul(ct, st), w)), d, out + i);
    }
    for (int i = 0; i < 15; ++i) v[i] = out[i];
  }
};

// ScalarAverageLines in lanes: w to cos(psi) and dpsi/dw (CosOfW), the
// two cosines, G1 = 2 z / (z + sqrt(z^2 + alpha^2 (1 - z^2))) of each (z
// at least 0: G1 is 0 there, as the reference's branch gives), and G2 of
// the masking. Each node differs from the reference by the rounding of
// these terms (fused multiply-adds) only.
struct SimdAverageLines {
  using V = hn::Vec<DF64>;
  const AverageModel* model;
  void operator()(const AverageLine& l, const double* w_in, double* v) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16], out[16];
    NodesTo16(w_in, in);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    const V a2 = hn::Set(d, model->a2);
    const V a0 = hn::Set(d, l.a0), a1 = hn::Set(d, l.a1), b0 = hn::Set(d, l.b0), b1 = hn::Set(d, l.b1);
    auto g1 = [&](V z) {
      z = hn::Max(z, zero);
      const V r = hn::Sqrt(hn::MulAdd(z, z, hn::Mul(a2, hn::Mul(hn::Sub(one, z), hn::Add(one, z)))));
      return hn::Div(hn::Mul(two, z), hn::Add(z, r));
    };
    for (size_t i = 0; i < 16; i += N) {
      const V w = hn::Load(d, in + i);
      const auto low = hn::Le(w, one);
      const V y = hn::IfThenElse(low, w, hn::Sub(two, w));
      const V x = hn::IfThenElse(low, hn::Mul(hn::Sub(one, y), hn::Add(one, y)),
                                 hn::Mul(hn::Sub(y, one), hn::Add(y, one)));
      const V jac = hn::Div(two, hn::Sqrt(hn::NegMulAdd(y, y, two)));
      const V ga = g1(hn::MulAdd(a1, x, a0)), gb = g1(hn::MulAdd(b1, x, b0));
      const V prod = hn::Mul(ga, gb);
      V g2;
      if (model->separable) {
        g2 = prod;
      } else {
        const V den = hn::Sub(hn::Add(ga, gb), prod);
        const auto ok = hn::Gt(den, zero);
        g2 = hn::IfThenElseZero(ok, hn::Div(prod, hn::IfThenElse(ok, den, one)));
      }
      hn::Store(hn::Mul(jac, g2), d, out + i);
    }
    for (int i = 0; i < 15; ++i) v[i] = out[i];
  }
};

RuleResult GlassAverage(double alpha, double eta, Masking masking, double tol, int max_pieces, DielectricPart part) {
  const AverageModel m = AverageModelOf(alpha, eta, masking, part);
  return GlassAlbedoAverageWith(m, tol, max_pieces, SimdAverageLines{&m});
}

void GlassAverageLine(double alpha, Masking masking, const double* coefficients, const double* w, double* v) {
  const AverageModel m = AverageModelOf(alpha, 1.5, masking, DielectricPart::kBoth);
  const AverageLine line{coefficients[0], coefficients[1], coefficients[2], coefficients[3]};
  SimdAverageLines{&m}(line, w, v);
}

RuleResult GlassTexel(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                      DielectricPart part) {
  const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(alpha), eta, masking,
                                                     DielectricTransport::kImportance);
  const GlassFrame frame(bsdf.ndf().alpha_x(), GlassRuleEta(bsdf.eta(), eta, part), mu);
  const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
  const SimdGlassNodes nodes{&frame, bsdf.masking() == Masking::kSeparable, 1 + lambda_o, lambda_o, part};
  return GlassAlbedoWith(frame, tol, max_pieces, nodes);
}

void GlassNodes(double alpha, double eta, Masking masking, double mu, double phi, const double* theta, double* v,
                DielectricPart part) {
  const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(alpha), eta, masking,
                                                     DielectricTransport::kImportance);
  const GlassFrame frame(bsdf.ndf().alpha_x(), GlassRuleEta(bsdf.eta(), eta, part), mu);
  const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
  const SimdGlassNodes nodes{&frame, bsdf.masking() == Masking::kSeparable, 1 + lambda_o, lambda_o, part};
  nodes(GlassRay{std::cos(phi), std::sin(phi)}, theta, v);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GlassTexel);
RuleResult SimdGlassAlbedo(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                           DielectricPart part) {
  if (alpha == 0) return SmoothGlassAlbedo(eta, mu, part);
  return HWY_DYNAMIC_DISPATCH(GlassTexel)(alpha, eta, masking, mu, tol, max_pieces, part);
}

HWY_EXPORT(GlassNodes);
void SimdGlassNodeValues(double alpha, double eta, Masking masking, double mu, double phi, const double* theta,
                         double* v, DielectricPart part) {
  HWY_DYNAMIC_DISPATCH(GlassNodes)(alpha, eta, masking, mu, phi, theta, v, part);
}

HWY_EXPORT(GlassAverage);
RuleResult SimdGlassAlbedoAverage(double alpha, double eta, Masking masking, double tol, int max_pieces,
                                  DielectricPart part) {
  return HWY_DYNAMIC_DISPATCH(GlassAverage)(alpha, eta, masking, tol, max_pieces, part);
}

HWY_EXPORT(GlassAverageLine);
void SimdGlassAverageLineValues(double alpha, Masking masking, const double* coefficients, const double* w,
                                double* v) {
  HWY_DYNAMIC_DISPATCH(GlassAverageLine)(alpha, masking, coefficients, w, v);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
