// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The one-dimensional rules of the slope-space models, Beckmann and the
// STD (rules/slope/azimuthal_slope.h, rules/beckmann, rules/std), with
// their nodes in double SIMD lanes: E with the azimuth in closed form or
// tabulated, and dfg with the azimuth integrated numerically.

#include <cstddef>
#include <limits>
#include <memory>

#include "lanes/slope_lanes.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/slope_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/math_f64-inl.h"
#include "lanes/beckmann_azimuth_f64-inl.h"
#include "lanes/lanes_common-inl.h"
#if BRDFBAKE_WITH_STD
#include "kernels/std_f64-inl.h"
#endif

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The azimuthal integrals of a slope-space model (azimuthal_slope.h,
// ScalarSlopeNodes) with each piece's 16 nodes in lanes: P22 from the
// model's lane function (BeckmannOverGgx's exponential, StudentTOverGgx's
// power, without their (1 + r2)^2 factor).
template <class P22, class LambdaF>
struct SimdSlopeNodes {
  static constexpr double kNegligibleR2 = P22::kNegligibleR2;
  P22 p22;
  LambdaF lambda;
  void operator()(const SlopeAzimuth& az, const AzimuthLadder::Piece* const* pieces, int n,
                  double* ke, double* ge, double* kb, double* gb) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const AzimuthLadder& rule = AzimuthLadder::Get(2);
    const V r2_0 = hn::Set(d, az.r2_0), r2_t = hn::Set(d, az.r2_t);
    const V v_min = hn::Set(d, az.v_min), two_b = hn::Set(d, az.two_b);
    const V one = hn::Set(d, 1.0), half = hn::Set(d, 0.5), zero = hn::Zero(d);
    for (int p = 0; p < n; ++p) {
      V se = zero, sge = zero, sb = zero, sgb = zero;
      for (size_t i = 0; i < 16; i += N) {
        const V t = hn::Mul(two_b, hn::LoadU(d, pieces[p]->s2 + i));
        const V v = hn::Add(v_min, t);
        const V f = hn::Mul(p22(d, hn::MulAdd(r2_t, t, r2_0)), hn::Mul(v, v));
        const V wk = hn::LoadU(d, rule.wk + i), wg = hn::LoadU(d, rule.wg + i);
        se = hn::MulAdd(wk, f, se);
        sge = hn::MulAdd(wg, f, sge);
        if (az.with_bias) {
          const V m = hn::Max(zero, hn::NegMulAdd(half, hn::Sqrt(v), one));
          const V m2 = hn::Mul(m, m);
          const V fb = hn::Mul(f, hn::Mul(hn::Mul(m2, m2), m));
          sb = hn::MulAdd(wk, fb, sb);
          sgb = hn::MulAdd(wg, fb, sgb);
        }
      }
      ke[p] = hn::GetLane(hn::SumOfLanes(d, se));
      ge[p] = hn::GetLane(hn::SumOfLanes(d, sge));
      kb[p] = hn::GetLane(hn::SumOfLanes(d, sb));
      gb[p] = hn::GetLane(hn::SumOfLanes(d, sgb));
    }
  }
};

// SlopeAzimuthalE::EvalPiece in lanes: the angles (AnglesAt), Lambda(wi),
// G2 and the azimuth's parameters of the 15 nodes of a theta_i piece
// together, then each node's azimuthal pieces (SimdSlopeNodes), the same
// operations as the scalar reference. The 16th lane repeats the first node.
template <class P22, class LambdaF>
struct SimdSlopeEval {
  SimdSlopeNodes<P22, LambdaF> nodes;
  AzimuthalFrame::FrameConsts fc;
  SlopeConsts sc;
  bool with_bias;

  void operator()(const double* theta, AzimuthalValues* out) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double th[16], w[16], cav[16], r2_0[16], r2_t[16], v_min[16], two_b[16];
    HWY_ALIGN double start[16], norm[16];
    NodesTo16(theta, th);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
    const V alpha = hn::Set(d, sc.alpha), a2 = hn::Set(d, sc.alpha * sc.alpha);
    const V lambda_o = hn::Set(d, sc.lambda_o), scale = hn::Set(d, fc.scale);
    const V s_o = hn::Set(d, fc.s_o);
    for (size_t i = 0; i < 16; i += N) {
      V sa, ca, st, ct, s_i, mu_i;
      FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
      // a = cot(theta_i) / alpha: 0 (Lambda = inf) on the horizon.
      const V a = hn::IfThenElseZero(hn::Gt(mu_i, zero), hn::Div(mu_i, hn::Mul(alpha, s_i)));
      const V lambda_i = nodes.lambda(d, a);
      const V g2 = sc.separable
                       ? hn::Div(one, hn::Mul(hn::Add(one, lambda_i), hn::Add(one, lambda_o)))
                       : hn::Div(one, hn::Add(hn::Add(one, lambda_i), lambda_o));
      hn::Store(hn::Mul(hn::Mul(scale, g2), s_i), d, w + i);
      hn::Store(ca, d, cav + i);
      const V cc = hn::Mul(ca, ct);
      const V tb = hn::Mul(hn::Mul(four, s_i), s_o);
      hn::Store(hn::Div(hn::Mul(st, st), hn::Mul(hn::Mul(a2, ct), ct)), d, r2_0 + i);
      hn::Store(hn::Div(one, hn::Mul(hn::Mul(hn::Mul(four, a2), cc), cc)), d, r2_t + i);
      hn::Store(hn::Mul(hn::Mul(four, ca), ca), d, v_min + i);
      hn::Store(tb, d, two_b + i);
      // The ladder's start: the lobe's half width (and 2 cos A for Fc).
      const V b = hn::Mul(hn::Set(d, 0.5), tb);
      const V bs = hn::IfThenElse(hn::Gt(b, zero), b, one);
      V st_v = hn::IfThenElse(hn::Gt(b, zero),
                              hn::Mul(hn::Mul(alpha, cc), hn::Sqrt(hn::Div(hn::Set(d, 8.0), bs))),
                              hn::Inf(d));
      if (with_bias) st_v = hn::Min(st_v, hn::Mul(hn::Set(d, 2.0), ca));
      hn::Store(st_v, d, start + i);
      const V cc2 = hn::Mul(cc, cc);
      hn::Store(hn::Div(hn::Set(d, 2.0), hn::Mul(hn::Mul(hn::Mul(a2, hn::Set(d, 16.0)), cc2), cc2)),
                d, norm + i);
    }
    const AzimuthLadder& ladder = AzimuthLadder::Get(sc.ladder_ratio);
    for (int k = 0; k < 15; ++k) {
      AzimuthalValues& v = out[k];
      v = AzimuthalValues();
      if (!(w[k] > 0) || !(cav[k] > 0)) continue;
      SlopeAzimuth az;
      az.r2_0 = r2_0[k];
      az.r2_t = r2_t[k];
      az.v_min = v_min[k];
      az.two_b = two_b[k];
      az.with_bias = with_bias;
      v = SlopeAzimuthOnLadder(ladder, az, start[k], w[k] * norm[k], nodes);
    }
  }
};

// The slope-space rule with SimdSlopeEval's nodes.
template <class Ndf, class P22, class LambdaF>
AzimuthalDfgResult SimdSlopeTexel(const Ndf& ndf, double mu, Masking masking, bool with_bias,
                                  double tol, int max_pieces,
                                  const SimdSlopeNodes<P22, LambdaF>& nodes) {
  const SlopeAzimuthalE<Ndf> f(ndf, mu, masking, tol, with_bias);
  const SimdSlopeEval<P22, LambdaF> eval{nodes, f.frame_consts(), f.slope_consts(), with_bias};
  return AdaptiveAzimuthalRule(
      AzimuthalMesh(f.theta_o(), f.lambda_o(), f.alpha(), f.horizon_widen(), f.normal_scale()),
      eval, tol, max_pieces);
}

#if BRDFBAKE_WITH_BECKMANN
// Lambda (kernels/math_f64-inl.h) and P22 = exp(-r2) / pi (0 beyond r2 = 706,
// below the smallest normal double).
struct BeckmannLambda {
  template <class V>
  HWY_INLINE V operator()(DF64 d, V a) const {
    return BeckmannLambdaF64(d, a);
  }
};
struct BeckmannP22 {
  static constexpr double kNegligibleR2 = kBeckmannNegligibleR2;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V r2) const {
    const V e = hn::Exp(d, hn::Neg(hn::Min(r2, hn::Set(d, 706.0))));
    return hn::IfThenElseZero(hn::Lt(r2, hn::Set(d, 706.0)),
                              hn::Mul(e, hn::Set(d, 0.3183098861837907)));
  }
};

AzimuthalDfgResult BeckmannAzimuthalTexel(const BeckmannNdf<double>& ndf, double mu,
                                          Masking masking, bool with_bias, double tol,
                                          int max_pieces) {
  return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
                        SimdSlopeNodes<BeckmannP22, BeckmannLambda>{});
}
#endif

#if BRDFBAKE_WITH_STD
// Lambda (kernels/std_f64-inl.h) and P22 = exp(-gamma log1p(r2 / (gamma - 1))) / pi
// ([Ribardiere17] eq. 13).
struct StudentTLambda {
  StudentTLambdaF64Consts c;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V a) const {
    return StudentTLambdaF64(d, c, a);
  }
};
struct StudentTP22 {
  static constexpr double kNegligibleR2 = std::numeric_limits<double>::infinity();
  double gamma, inv_gamma_minus_1;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V r2) const {
    const V ex = hn::Mul(hn::Set(d, gamma), hn::Log1p(d, hn::Mul(r2, hn::Set(d, inv_gamma_minus_1))));
    const V e = hn::Exp(d, hn::Neg(hn::Min(ex, hn::Set(d, 706.0))));
    return hn::IfThenElseZero(hn::Lt(ex, hn::Set(d, 706.0)),
                              hn::Mul(e, hn::Set(d, 0.3183098861837907)));
  }
};

AzimuthalDfgResult StudentTAzimuthalTexel(const StudentTNdf<double>& ndf, double mu,
                                          Masking masking, bool with_bias, double tol,
                                          int max_pieces) {
  const double g = ndf.gamma();
  if (std::isinf(g)) {
    return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
                          SimdSlopeNodes<BeckmannP22, BeckmannLambda>{});
  }
  return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
                        SimdSlopeNodes<StudentTP22, StudentTLambda>{
                            {g, 1 / (g - 1)}, StudentTLambda{StudentTLambdaF64Consts(g)}});
}
#endif

// MomentAzimuthalE's integrand at the 15 nodes of one theta_i piece in
// lanes (the 16th repeats the first): the angles, Lambda(wi), G2 and the
// terms, then the model's moments and c(r2_0) from `model.Lambda(d, a)`
// (a = cot(theta_i) / alpha, 0 on the horizon) and `model.Moments(d, t,
// m, &c)`; the same operations as the scalar reference.
struct MomentTermsF64 {
  hn::Vec<DF64> a2, cc, two_b, v_min, r2_0;
};
template <class Model>
void SimdMomentNodes(const AzimuthalFrame::FrameConsts& fc, const MomentAzimuthalE::Consts& mc,
                     const Model& model, const double* theta, double* out) {
  using V = hn::Vec<DF64>;
  const DF64 d;
  const size_t N = hn::Lanes(d);
  HWY_ALIGN double th[16], e[16];
  NodesTo16(theta, th);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0),
          four = hn::Set(d, 4.0);
  const V alpha = hn::Set(d, mc.alpha), a2 = hn::Set(d, mc.alpha * mc.alpha);
  const V lambda_o = hn::Set(d, mc.lambda_o), scale = hn::Set(d, fc.scale);
  const V s_o = hn::Set(d, fc.s_o);
  const V norm_c = hn::Set(d, 3.141592653589793 * (mc.alpha * mc.alpha) * 16);
  for (size_t i = 0; i < 16; i += N) {
    V sa, ca, st, ct, s_i, mu_i;
    FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
    const V a = hn::IfThenElseZero(hn::Gt(mu_i, zero), hn::Div(mu_i, hn::Mul(alpha, s_i)));
    const V lambda_i = model.Lambda(d, a);
    const V g2 = mc.separable ? hn::Div(one, hn::Mul(hn::Add(one, lambda_i), hn::Add(one, lambda_o)))
                           : hn::Div(one, hn::Add(hn::Add(one, lambda_i), lambda_o));
    const V w = hn::Mul(hn::Mul(scale, g2), s_i);
    const auto valid = hn::And(hn::Gt(w, zero), hn::Gt(ca, zero));
    MomentTermsF64 t;
    t.a2 = a2;
    t.cc = hn::IfThenElse(valid, hn::Mul(ca, ct), one);
    t.two_b = hn::Mul(hn::Mul(four, s_i), s_o);
    t.v_min = hn::Mul(hn::Mul(four, ca), ca);
    t.r2_0 = hn::Div(hn::Mul(st, st), hn::Mul(hn::Mul(a2, ct), ct));
    V m[3], c;
    model.Moments(d, t, m, &c);
    const V sum = hn::MulAdd(
        hn::Mul(t.two_b, t.two_b), m[2],
        hn::Mul(hn::MulAdd(t.v_min, m[0], hn::Mul(hn::Mul(two, t.two_b), m[1])), t.v_min));
    const V cc2 = hn::Mul(t.cc, t.cc);
    const V norm = hn::Div(two, hn::Mul(hn::Mul(norm_c, cc2), cc2));
    const V v = hn::Mul(w, hn::Mul(hn::Mul(norm, c), sum));
    hn::Store(hn::IfThenElseZero(valid, v), d, e + i);
  }
  for (int i = 0; i < 15; ++i) out[i] = e[i];
}

// BeckmannAzimuthalE::operator() in lanes: Lambda by BeckmannLambdaF64,
// the closed-form moments by BeckmannAzimuthMomentsF64.
struct SimdBeckmannModel {
  hn::Vec<DF64> Lambda(DF64 d, hn::Vec<DF64> a) const { return BeckmannLambdaF64(d, a); }
  void Moments(DF64 d, const MomentTermsF64& t, hn::Vec<DF64>* m, hn::Vec<DF64>* c) const {
    using V = hn::Vec<DF64>;
    const V four = hn::Set(d, 4.0), max_r2 = hn::Set(d, 706.0);
    const V x = hn::Div(t.two_b, hn::Mul(hn::Mul(hn::Mul(four, t.a2), t.cc), t.cc));
    BeckmannAzimuthMomentsF64(d, x, &m[0], &m[1], &m[2]);
    // exp(-r2_0): 0 from 706 on (below the smallest normal double).
    *c = hn::IfThenElseZero(hn::Lt(t.r2_0, max_r2), hn::Exp(d, hn::Neg(hn::Min(t.r2_0, max_r2))));
  }
};

RuleResult BeckmannAlbedoTexel(double alpha, double mu, Masking masking, double tol,
                                    int max_pieces) {
  return BeckmannAzimuthalAlbedoWith(
      alpha, mu, masking, tol, max_pieces,
      [](const BeckmannAzimuthalE& f, const double* theta, double* out) {
        SimdMomentNodes(f.frame_consts(), f.consts(), SimdBeckmannModel{}, theta, out);
      });
}

#if BRDFBAKE_WITH_STD
// StdAzimuthalE::operator() in lanes: Lambda by StudentTLambdaF64, y and
// the tabulated moments (Clenshaw's recurrence on each lane's own piece of
// the table), the same operations as the scalar reference.
struct SimdStdModel {
  double gamma;
  const StdAzimuthMoments* moments;
  const StudentTLambdaF64Consts* lc;

  hn::Vec<DF64> Lambda(DF64 d, hn::Vec<DF64> a) const { return StudentTLambdaF64(d, *lc, a); }
  void Moments(DF64 d, const MomentTermsF64& t, hn::Vec<DF64>* n, hn::Vec<DF64>* c) const {
    using T = StdAzimuthMoments;
    using V = hn::Vec<DF64>;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
    const V gamma_v = hn::Set(d, gamma), gm1 = hn::Set(d, gamma - 1);
    const V min_exp = hn::Set(d, -706.0);
    const double* coef = moments->coef();
    const double* p = moments->p();
    const V l0 = hn::Log1p(d, hn::Div(t.r2_0, gm1));
    const V y =
        hn::Mul(hn::Div(t.two_b, hn::Mul(hn::Mul(hn::Mul(hn::Mul(four, t.a2), t.cc), t.cc), gm1)),
                hn::Exp(d, hn::Neg(l0)));
    // StdAzimuthMoments::At.
    const V z = hn::Mul(gamma_v, y);
    const V tt = hn::Min(hn::Log1p(d, z), hn::Set(d, T::kMaxT));
    const V piece_f =
        hn::Min(hn::Floor(hn::Mul(tt, hn::Set(d, 1 / T::kWidth))), hn::Set(d, T::kPieces - 1.0));
    const V x = hn::Sub(hn::NegMulAdd(piece_f, hn::Set(d, T::kWidth), tt), one);
    const int degree = moments->degree();
    const V inv = hn::Div(one, hn::Add(one, z)), r = hn::Sqrt(inv);
    const V half_powers[3] = {r, hn::Mul(r, inv), hn::Mul(hn::Mul(r, inv), inv)};
    const V x2 = hn::Add(x, x);
    // Clenshaw's recurrence, the three chains interleaved, once per
    // distinct table piece among the lanes (the nodes of a theta_i piece
    // mostly share one or two) with its coefficients broadcast, each lane
    // taking the sums of its own piece: the same operations per lane as
    // the scalar reference.
    HWY_ALIGN double piece_of[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(piece_f, d, piece_of);
    for (int k = 0; k < 3; ++k) n[k] = zero;
    auto todo = hn::Eq(piece_f, piece_f);
    while (!hn::AllFalse(d, todo)) {
      const double pc = piece_of[hn::FindFirstTrue(d, todo)];
      const auto mine = hn::And(todo, hn::Eq(piece_f, hn::Set(d, pc)));
      todo = hn::AndNot(mine, todo);
      const double* cf = coef + static_cast<size_t>(pc) * (degree + 1) * 3;
      V b1[3] = {zero, zero, zero}, b2[3] = {zero, zero, zero};
      for (int j = degree; j >= 1; --j) {
        for (int k = 0; k < 3; ++k) {
          const V b0 = hn::MulAdd(x2, b1[k], hn::Sub(hn::Set(d, cf[j * 3 + k]), b2[k]));
          b2[k] = b1[k];
          b1[k] = b0;
        }
      }
      for (int k = 0; k < 3; ++k) {
        n[k] = hn::IfThenElse(mine, hn::MulAdd(x, b1[k], hn::Sub(hn::Set(d, cf[k]), b2[k])), n[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      const V decay = p[k] < k + 0.5 ? hn::Exp(d, hn::Mul(hn::Set(d, -p[k]), tt)) : half_powers[k];
      n[k] = hn::Mul(n[k], decay);
    }
    const V arg = hn::Neg(hn::Mul(gamma_v, l0));
    *c = hn::IfThenElseZero(hn::Gt(arg, min_exp), hn::Exp(d, hn::Max(arg, min_exp)));
  }
};

RuleResult StdAlbedoTexel(const StudentTNdf<double>& ndf, double mu, Masking masking,
                               double tol, int max_pieces) {
  // Lambda's constants (series coefficients, Gamma ratios: a few us), kept
  // per thread for the last gamma.
  thread_local double lc_gamma = std::numeric_limits<double>::quiet_NaN();
  thread_local std::unique_ptr<StudentTLambdaF64Consts> lc_cached;
  if (!(lc_gamma == ndf.gamma())) {
    lc_cached = std::make_unique<StudentTLambdaF64Consts>(ndf.gamma());
    lc_gamma = ndf.gamma();
  }
  const StudentTLambdaF64Consts& lc = *lc_cached;
  return StdAzimuthalAlbedoWith(
      ndf, mu, masking, tol, max_pieces,
      [&](const StdAzimuthalE& f, const double* theta, double* out) {
        SimdMomentNodes(f.frame_consts(), f.consts(), SimdStdModel{f.gamma(), &f.moments(), &lc},
                        theta, out);
      });
}
#endif

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(BeckmannAlbedoTexel);
RuleResult SimdBeckmannAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                            int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(BeckmannAlbedoTexel)(alpha, mu, masking, tol, max_pieces);
}

#if BRDFBAKE_WITH_STD
HWY_EXPORT(StdAlbedoTexel);
RuleResult SimdStdAzimuthalAlbedo(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                       double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(StdAlbedoTexel)(ndf, mu, masking, tol, max_pieces);
}
#endif

#if BRDFBAKE_WITH_BECKMANN
HWY_EXPORT(BeckmannAzimuthalTexel);
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const BeckmannNdf<double>& ndf, double mu,
                                         Masking masking, bool with_bias, double tol,
                                         int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(BeckmannAzimuthalTexel)(ndf, mu, masking, with_bias, tol,
                                                      max_pieces);
}
#endif

#if BRDFBAKE_WITH_STD
HWY_EXPORT(StudentTAzimuthalTexel);
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(StudentTAzimuthalTexel)(ndf, mu, masking, with_bias, tol,
                                                      max_pieces);
}
#endif

}  // namespace brdfbake
#endif  // HWY_ONCE
