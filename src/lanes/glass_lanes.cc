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

#include "kernels/math_f64-inl.h"
#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// ScalarGlassNodes in lanes, term by term:
//  - cos and sin of theta by CosF64ZeroToPi and SinF64HalfPi
//    (kernels/math_f64-inl.h, within 5e-16 relative; theta is in [0,
//    pi/2]), half the time of Highway's Cos and Sin;
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

  // k pieces' 15 nodes each (k at most kGlassPieceBatch).
  void operator()(const GlassRay& ray, const double* theta, double* v, int k = 1) const {
    HWY_ALIGN double in[16 * kGlassPieceBatch], out[16 * kGlassPieceBatch];
    for (int j = 0; j < k; ++j) NodesTo16(theta + 15 * j, in + 16 * j);
    Values16(ray, in, out, k);
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < 15; ++i) v[15 * j + i] = out[16 * j + i];
    }
  }

  // The sums of k pieces of the ray's segments (GlassSumsRule): each
  // piece's 16 nodes (Kronrod16) mapped by its segment's MappedSegment::Map
  // in lanes, and the sums of the values times the Jacobians, one
  // horizontal sum each.
  void Pieces(const GlassRay& ray, const MappedSegment* segments, const GlassPiece* spans, int k,
              GlassSums* sums) const {
    static const Kronrod16 rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double x[16 * kGlassPieceBatch], jac[16 * kGlassPieceBatch], out[16 * kGlassPieceBatch];
    const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), three = hn::Set(d, 3.0), six = hn::Set(d, 6.0);
    for (int j = 0; j < k; ++j) {
      const MappedSegment& g = segments[spans[j].segment];
      const V c = hn::Set(d, 0.5 * (spans[j].a + spans[j].b)), h = hn::Set(d, 0.5 * (spans[j].b - spans[j].a));
      const V a = hn::Set(d, g.a), width = hn::Set(d, g.b - g.a);
      for (size_t i = 0; i < 16; i += N) {
        const V t = hn::MulAdd(h, hn::Load(d, rule.x + i), c);
        V m = t, dm = one;
        if (g.singular_a && g.singular_b) {
          m = hn::Mul(hn::Mul(t, t), hn::NegMulAdd(two, t, three));
          dm = hn::Mul(hn::Mul(six, t), hn::Sub(one, t));
        } else if (g.singular_a) {
          m = hn::Mul(t, t);
          dm = hn::Mul(two, t);
        } else if (g.singular_b) {
          const V u = hn::Sub(one, t);
          m = hn::NegMulAdd(u, u, one);
          dm = hn::Mul(two, u);
        }
        hn::Store(hn::MulAdd(width, m, a), d, x + 16 * j + i);
        hn::Store(hn::Mul(width, dm), d, jac + 16 * j + i);
      }
    }
    Values16(ray, x, out, k);
    for (int j = 0; j < k; ++j) {
      V ks = hn::Zero(d), gs = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V f = hn::Mul(hn::Load(d, out + 16 * j + i), hn::Load(d, jac + 16 * j + i));
        ks = hn::MulAdd(hn::Load(d, rule.wk + i), f, ks);
        gs = hn::MulAdd(hn::Load(d, rule.wg + i), f, gs);
      }
      const double h = 0.5 * (spans[j].b - spans[j].a);
      sums[j] = {h * hn::GetLane(hn::SumOfLanes(d, ks)), h * hn::GetLane(hn::SumOfLanes(d, gs))};
    }
  }

  // The values at 16 k aligned angles theta in `in`, to `out`, in one
  // loop over their vectors (which overlap: each vector's chain of square
  // roots and divisions is long).
  void Values16(const GlassRay& ray, const double* in, double* out, int k) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const GlassFrame& f = *frame;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
    const V alpha = hn::Set(d, f.alpha), alpha2 = hn::Set(d, f.alpha * f.alpha);
    const V vx = hn::Set(d, f.vx), vz = hn::Set(d, f.vz);
    const V cp = hn::Set(d, ray.cp), sp = hn::Set(d, ray.sp);
    const V so = hn::Set(d, f.so), mu = hn::Set(d, f.mu);
    const V eta = hn::Set(d, f.eta), inv_eta = hn::Set(d, 1 / f.eta);
    const V inv_eta2 = hn::Set(d, 1 / (f.eta * f.eta));
    const V g1o = hn::Set(d, g1o_inv), one_lo = hn::Set(d, 1 + lambda_o);
    // G2 / G1(wo) = num / den at Lambda's numerator p and z = |w.z| > 0:
    // with q = z^2 + z sqrt(z^2 + p), Lambda = p / (2 q), so 1 / (1 +
    // Lambda) = 2 q / (2 q + p) (separable) and 1 / G1(wo) / (1 +
    // Lambda(wo) + Lambda) = 2 q g1o / (2 q (1 + Lambda(wo)) + p).
    auto g2_over_g1 = [&](V p, V z, V* num, V* den) {
      const V q2 = hn::Mul(hn::Set(d, 2.0), hn::MulAdd(z, hn::Sqrt(hn::MulAdd(z, z, p)), hn::Mul(z, z)));
      *num = separable ? q2 : hn::Mul(q2, g1o);
      *den = separable ? hn::Add(q2, p) : hn::MulAdd(q2, one_lo, p);
    };
    // All lanes true or all false: the part's terms, and the refraction's
    // weight (1 - F, or Schlick's complement 1 - (1 - c)^5).
    const bool schlick = part == DielectricPart::kTransmissionSchlick;
    const auto keep_r = hn::Ne(hn::Set(d, RefractionPart(part) ? 0.0 : 1.0), zero);
    const auto keep_t = hn::Ne(hn::Set(d, part == DielectricPart::kReflection ? 0.0 : 1.0), zero);
    const auto use_schlick = hn::Ne(hn::Set(d, schlick ? 1.0 : 0.0), zero);
    for (size_t i = 0; i < static_cast<size_t>(16 * k); i += N) {
      const V th = hn::Load(d, in + i);
      const V ct = CosF64ZeroToPi(d, th), st = SinF64HalfPi(d, th);
      // m = alpha (ct vx - st sp vz, st cp, .) and m.z = ct vz + st sp vx
      // (GlassFrame::M), unnormalized: l2 = |m|^2 (at least alpha^2 for
      // a unit normal of the stretched frame) and cm = wo.m = |m| c.
      const V ssp = hn::Mul(st, sp);
      const V mx = hn::Mul(alpha, hn::Sub(hn::Mul(ct, vx), hn::Mul(ssp, vz)));
      const V my = hn::Mul(alpha, hn::Mul(st, cp));
      const V mz = hn::Add(hn::Mul(ct, vz), hn::Mul(ssp, vx));
      const V l2 = hn::MulAdd(mx, mx, hn::MulAdd(my, my, hn::Mul(mz, mz)));
      const auto valid = hn::And(hn::Gt(l2, zero), hn::Ge(mz, zero));
      const V cm = hn::Max(hn::MulAdd(so, mx, hn::Mul(mu, mz)), zero);
      // |m|^2 sin^2(theta_t) = (|m|^2 - cm^2) / eta^2, and lct = |m|
      // cos_t; F's amplitudes are ratios of terms of degree 1 in |m|, so
      // they take cm and lct for c and cos_t.
      const V ls2 = hn::Mul(hn::Max(hn::NegMulAdd(cm, cm, l2), zero), inv_eta2);
      const auto tir = hn::Ge(ls2, l2);
      const V lct2 = hn::Sub(l2, ls2);
      const V lct = hn::Sqrt(hn::Max(lct2, zero));
      const V ec = hn::Mul(eta, cm), et = hn::Mul(eta, lct);
      const V pa = hn::Sub(ec, lct), pb = hn::Add(ec, lct);
      const V sa = hn::Sub(cm, et), sb = hn::Add(cm, et);
      const V pb2 = hn::Mul(pb, pb), sb2 = hn::Mul(sb, sb);
      const V f_den = hn::Mul(pb2, sb2);
      const auto f_ok = hn::And(hn::Not(tir), hn::Gt(f_den, zero));
      const V f_num = hn::MulAdd(hn::Mul(pa, pa), sb2, hn::Mul(hn::Mul(sa, sa), pb2));
      // F = fn / fd: f_num / (2 f_den), 1 (total internal reflection), or
      // not formed for the Schlick weight (eta may be inf there).
      const V fn = hn::IfThenElse(use_schlick, zero, hn::IfThenElse(f_ok, f_num, one));
      const V fd = hn::IfThenElse(hn::AndNot(use_schlick, f_ok), hn::Add(f_den, f_den), one);
      // The reflection |m|^2 r = 2 cm m - |m|^2 wo (wo = (so, 0, mu)):
      // Lambda is of degree 0 in its direction.
      const V two_c = hn::Add(cm, cm);
      const V rx = hn::MulSub(two_c, mx, hn::Mul(l2, so)), ry = hn::Mul(two_c, my);
      const V rz = hn::MulSub(two_c, mz, hn::Mul(l2, mu));
      const auto r_ok = hn::And(hn::And(hn::Gt(rz, zero), hn::Gt(fn, zero)), keep_r);
      const V rz_safe = hn::IfThenElse(r_ok, rz, one);
      const V pr = hn::Mul(alpha2, hn::MulAdd(rx, rx, hn::Mul(ry, ry)));
      V num_r, den_r;
      g2_over_g1(pr, rz_safe, &num_r, &den_r);
      // The refraction |m|^2 t = -|m|^2 wo / eta + (cm / eta - lct) m.
      const V k = hn::Sub(hn::Mul(cm, inv_eta), lct);
      const V l2e = hn::Mul(l2, inv_eta);
      const V tx = hn::MulSub(k, mx, hn::Mul(so, l2e)), ty = hn::Mul(k, my);
      const V tz = hn::MulSub(k, mz, hn::Mul(mu, l2e));
      const auto t_ok = hn::And(hn::And(hn::And(hn::Gt(lct2, zero), hn::Lt(fn, fd)), hn::Lt(tz, zero)), keep_t);
      const V tz_safe = hn::IfThenElse(t_ok, hn::Neg(tz), one);
      const V pt = hn::Mul(alpha2, hn::MulAdd(tx, tx, hn::Mul(ty, ty)));
      // The refraction's weight times fd: fd - fn = fd (1 - F), or
      // Schlick's complement 1 - (1 - c)^5, c = cm / |m| (fd = 1).
      V weight_t = hn::Sub(fd, fn);
      if (schlick) {
        const V omc = hn::Sub(one, hn::Min(hn::Div(cm, hn::Sqrt(hn::IfThenElse(valid, l2, one))), one));
        const V omc2s = hn::Mul(omc, omc);
        weight_t = hn::NegMulAdd(hn::Mul(omc2s, omc2s), omc, one);
      }
      V num_t, den_t;
      g2_over_g1(pt, tz_safe, &num_t, &den_t);
      // w = (fn num_r / den_r + weight_t num_t / den_t) / fd over one
      // division, each term 0 (over 1) where it does not count.
      const V xr = hn::IfThenElseZero(r_ok, hn::Mul(fn, num_r)), dr = hn::IfThenElse(r_ok, den_r, one);
      const V xt = hn::IfThenElseZero(t_ok, hn::Mul(weight_t, num_t)), dt = hn::IfThenElse(t_ok, den_t, one);
      const V den = hn::Mul(fd, hn::Mul(dr, dt));
      const V w = hn::Div(hn::MulAdd(xr, dt, hn::Mul(xt, dr)), den);
      hn::Store(hn::IfThenElseZero(valid, hn::Mul(hn::Mul(ct, st), w)), d, out + i);
    }
  }
};

// ScalarAverageLines in lanes with one division per node: with r =
// sqrt(z^2 + alpha^2 (1 - z^2)) of each cosine z (at least 0), G1 = 2 z /
// (z + r), so jac G2 = 4 za zb / (sqrt(2 - y^2) (ra zb + rb za))
// height-correlated (1 / G2 = 1 / ga + 1 / gb - 1) and 8 za zb / (sqrt(2 -
// y^2) (za + ra) (zb + rb)) separable; 0 where both cosines are 0 (the
// reference's G1 is 0 on the horizon); height-correlated, sqrt(2 - y^2)
// ra = sqrt((2 - y^2) ra^2), likewise rb. Each node differs from the
// reference by the rounding of these terms only. Pieces forms each
// piece's 16 nodes (Kronrod16: the 16th at the centre, of weight 0) and
// its K15 and G7 sums in lanes, one horizontal sum each: the sums differ
// from the reference's by their order of addition.
struct SimdAverageLines {
  using V = hn::Vec<DF64>;
  const AverageModel* model;

  // jac G2 at the nodes w, given the line's coefficients in lanes.
  struct Line {
    V a0, a1, b0, b1;
  };
  HWY_INLINE V Value(const Line& l, V w) const {
    const DF64 d;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    const V a2 = hn::Set(d, model->a2);
    auto square = [&](V z) { return hn::MulAdd(z, z, hn::Mul(a2, hn::Mul(hn::Sub(one, z), hn::Add(one, z)))); };
    const auto low = hn::Le(w, one);
    const V y = hn::IfThenElse(low, w, hn::Sub(two, w));
    const V x = hn::IfThenElse(low, hn::Mul(hn::Sub(one, y), hn::Add(one, y)),
                               hn::Mul(hn::Sub(y, one), hn::Add(y, one)));
    const V za = hn::Max(hn::MulAdd(l.a1, x, l.a0), zero), zb = hn::Max(hn::MulAdd(l.b1, x, l.b0), zero);
    const V jac2 = hn::NegMulAdd(y, y, two);  // (2 / jac)^2
    V den;
    if (model->separable) {
      den = hn::Mul(hn::Sqrt(jac2), hn::Mul(hn::Add(za, hn::Sqrt(square(za))), hn::Add(zb, hn::Sqrt(square(zb)))));
    } else {
      // sqrt(2 - y^2) (ra zb + rb za) with the Jacobian's root inside ra's
      // and rb's: two square roots, not three.
      den = hn::MulAdd(hn::Sqrt(hn::Mul(jac2, square(za))), zb, hn::Mul(hn::Sqrt(hn::Mul(jac2, square(zb))), za));
    }
    const auto ok = hn::Gt(den, zero);
    const V num = hn::Mul(hn::Set(d, model->separable ? 8.0 : 4.0), hn::Mul(za, zb));
    return hn::IfThenElseZero(ok, hn::Div(num, hn::IfThenElse(ok, den, one)));
  }
  static Line LineOf(const AverageLine& l) {
    const DF64 d;
    return {hn::Set(d, l.a0), hn::Set(d, l.a1), hn::Set(d, l.b0), hn::Set(d, l.b1)};
  }

  // 15 k nodes: k pieces' 15 each (k at most kGlassPieceBatch).
  void operator()(const AverageLine& l, const double* w_in, double* v, int k = 1) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16 * kGlassPieceBatch], out[16 * kGlassPieceBatch];
    for (int j = 0; j < k; ++j) NodesTo16(w_in + 15 * j, in + 16 * j);
    const Line line = LineOf(l);
    for (size_t i = 0; i < static_cast<size_t>(16 * k); i += N) hn::Store(Value(line, hn::Load(d, in + i)), d, out + i);
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < 15; ++i) v[15 * j + i] = out[16 * j + i];
    }
  }

  // The sums of the k pieces [a[j], b[j]] of w (k at most kMaxGraded).
  void Pieces(const AverageLine& l, const double* a, const double* b, int k, GlassSums* out) const {
    static const Kronrod16 rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const Line line = LineOf(l);
    for (int j = 0; j < k; ++j) {
      const double c = 0.5 * (a[j] + b[j]), h = 0.5 * (b[j] - a[j]);
      const V vc = hn::Set(d, c), vh = hn::Set(d, h);
      V ks = hn::Zero(d), gs = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V f = Value(line, hn::MulAdd(vh, hn::Load(d, rule.x + i), vc));
        ks = hn::MulAdd(hn::Load(d, rule.wk + i), f, ks);
        gs = hn::MulAdd(hn::Load(d, rule.wg + i), f, gs);
      }
      out[j] = {h * hn::GetLane(hn::SumOfLanes(d, ks)), h * hn::GetLane(hn::SumOfLanes(d, gs))};
    }
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

void GlassAverageSums(double alpha, Masking masking, const double* coefficients, double a, double b, double* kron,
                      double* gauss) {
  const AverageModel m = AverageModelOf(alpha, 1.5, masking, DielectricPart::kBoth);
  const AverageLine line{coefficients[0], coefficients[1], coefficients[2], coefficients[3]};
  GlassSums sums;
  SimdAverageLines{&m}.Pieces(line, &a, &b, 1, &sums);
  *kron = sums.kron;
  *gauss = sums.gauss;
}

// A view's rough dielectric, its rule's frame and the lanes nodes of its
// albedo, as the bake forms them.
struct SimdGlassView {
  RoughDielectric<double, GgxNdf<double>> bsdf;
  GlassFrame frame;
  double lambda_o;
  SimdGlassNodes nodes;
  SimdGlassView(double alpha, double eta, Masking masking, double mu, DielectricPart part)
      : bsdf(GgxNdf<double>(alpha), eta, masking, DielectricTransport::kImportance),
        frame(bsdf.ndf().alpha_x(), GlassRuleEta(bsdf.eta(), eta, part), mu),
        lambda_o(bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu})),
        nodes{&frame, bsdf.masking() == Masking::kSeparable, 1 + lambda_o, lambda_o, part} {}
  SimdGlassView(const SimdGlassView&) = delete;
  SimdGlassView& operator=(const SimdGlassView&) = delete;
};

RuleResult GlassTexel(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                      DielectricPart part) {
  const SimdGlassView view(alpha, eta, masking, mu, part);
  return GlassAlbedoWith(view.frame, tol, max_pieces, view.nodes);
}

void GlassPieceSums(double alpha, double eta, Masking masking, double mu, double phi, double a, double b,
                    bool singular_a, bool singular_b, double ta, double tb, double* kron, double* gauss) {
  const SimdGlassView view(alpha, eta, masking, mu, DielectricPart::kBoth);
  const MappedSegment segment{a, b, singular_a, singular_b};
  GlassPiece span{};
  span.a = ta;
  span.b = tb;
  span.segment = 0;
  GlassSums sums;
  view.nodes.Pieces(GlassRay{std::cos(phi), std::sin(phi)}, &segment, &span, 1, &sums);
  *kron = sums.kron;
  *gauss = sums.gauss;
}

void GlassNodes(double alpha, double eta, Masking masking, double mu, double phi, const double* theta, double* v,
                DielectricPart part) {
  const SimdGlassView view(alpha, eta, masking, mu, part);
  view.nodes(GlassRay{std::cos(phi), std::sin(phi)}, theta, v);
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

HWY_EXPORT(GlassPieceSums);
void SimdGlassPieceSums(double alpha, double eta, Masking masking, double mu, double phi, double a, double b,
                        bool singular_a, bool singular_b, double ta, double tb, double* kron, double* gauss) {
  HWY_DYNAMIC_DISPATCH(GlassPieceSums)(alpha, eta, masking, mu, phi, a, b, singular_a, singular_b, ta, tb, kron,
                                       gauss);
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

HWY_EXPORT(GlassAverageSums);
void SimdGlassAverageLineSums(double alpha, Masking masking, const double* coefficients, double a, double b,
                              double* kron, double* gauss) {
  HWY_DYNAMIC_DISPATCH(GlassAverageSums)(alpha, masking, coefficients, a, b, kron, gauss);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
