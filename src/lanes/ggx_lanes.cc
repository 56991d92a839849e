// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX one-dimensional rule (rules/ggx/azimuthal.h) with its theta_i
// nodes in double SIMD lanes: E and the split-sum dfg of isotropic GGX.

#include <cstddef>

#include "lanes/ggx_lanes.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/ggx_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// GgxAzimuthalE at the 15 nodes of one theta_i piece in lanes: its
// operator() (E's integrand, Albedo) and EvalDfg (operator()), with
// everything but the remainder's azimuthal nodes in lanes: the angles
// (AnglesAt), Phi, G2 and the closed-form moments, the same operations as
// the scalar reference, then the remainder node by node
// (SimdRemainderNodes). The 16th lane repeats the first node.
struct SimdGgxNodes {
  AzimuthalFrame::FrameConsts fc;
  GgxAzimuthalE::DfgConsts gc;

  // Per node: E's integrand, and for dfg the weight w norm of the bias, the
  // closed part, and the remainder's a = sqrt(kappa), vmin, 2 B and start
  // 2 cos A.
  struct Terms {
    HWY_ALIGN double e[16], wn[16], closed[16], sk[16], vmin[16], two_bb[16], start[16];
  };

  void Albedo(const double* theta, double* out) const {
    Terms terms;
    Front<false>(theta, &terms);
    for (int i = 0; i < 15; ++i) out[i] = terms.e[i];
  }

  void operator()(const double* theta, AzimuthalValues* out) const {
    Terms terms;
    Front<true>(theta, &terms);
    const double *e = terms.e, *wn = terms.wn, *closed = terms.closed, *sk = terms.sk,
                 *vmin = terms.vmin, *two_bb = terms.two_bb, *start = terms.start;
    const AzimuthLadder& ladder = AzimuthLadder::Get(3);
    const SimdRemainderNodes nodes;
    for (int i = 0; i < 15; ++i) {
      AzimuthalValues& v = out[i];
      v = AzimuthalValues();
      v.e = e[i];
      if (!(wn[i] > 0)) continue;
      const OddRemainder rem(sk[i], vmin[i], two_bb[i]);
      const AzimuthLadder::Piece* used[AzimuthLadder::kMaxPieces];
      const int pieces = ladder.Select(start[i], used);
      double rem_k, rem_err;
      nodes(rem, used, pieces, &rem_k, &rem_err);
      v.bias = wn[i] * (closed[i] - 2 * rem_k);
      v.bias_error = wn[i] * 2 * rem_err;
    }
  }

 private:
  template <bool kDfg>
  void Front(const double* theta, Terms* terms) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double th[16];
    NodesTo16(theta, th);
    double *e = terms->e, *wn = terms->wn, *closed = terms->closed, *sk = terms->sk,
           *vmin = terms->vmin, *two_bb = terms->two_bb, *start = terms->start;
    const V half = hn::Set(d, 0.5), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0),
            four = hn::Set(d, 4.0), zero = hn::Zero(d), two_pi = hn::Set(d, kTwoPi<double>);
    const V a2 = hn::Set(d, gc.a2), b = hn::Set(d, gc.b);
    const V lambda_o1 = hn::Set(d, 1 + gc.lambda_o), scale = hn::Set(d, fc.scale);
    const V s_o = hn::Set(d, fc.s_o), norm = hn::Set(d, gc.a2 / 3.141592653589793);
    for (size_t i = 0; i < 16; i += N) {
      V sa, ca, st, ct, s_i, mu_i;
      FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
      // PhiAt.
      const V x = hn::MulAdd(hn::Mul(a2, ct), ct, hn::Mul(st, st));
      const V y = hn::MulAdd(hn::Mul(a2, ca), ca, hn::Mul(sa, sa));
      const V xy = hn::Mul(x, y);
      const V ca2 = hn::Mul(ca, ca), ct2 = hn::Mul(ct, ct);
      const V q = hn::Div(hn::Mul(hn::Mul(b, ca), ct), hn::Sqrt(xy));
      const V inner = hn::Div(hn::Mul(b, hn::MulAdd(ca2, x, hn::Mul(ct2, y))), hn::Mul(two, xy));
      const V phi = hn::Mul(hn::Mul(two, a2), hn::MulAdd(q, hn::Add(two, inner), one));
      // G2.
      const V a2s2 = hn::Mul(hn::Mul(a2, s_i), s_i);
      const V n =
          hn::Mul(hn::Mul(two, mu_i), hn::Add(mu_i, hn::Sqrt(hn::MulAdd(mu_i, mu_i, a2s2))));
      const V g2 = gc.separable ? hn::Div(n, hn::Mul(hn::Add(n, a2s2), lambda_o1))
                                : hn::Div(n, hn::MulAdd(n, lambda_o1, a2s2));
      if constexpr (!kDfg) {
        // operator(): scale G2 Phi sin(theta_i), in that order.
        hn::Store(hn::Mul(hn::Mul(hn::Mul(scale, g2), phi), s_i), d, e + i);
        continue;
      }
      const V w = hn::Mul(hn::Mul(scale, g2), s_i);
      hn::Store(hn::Mul(w, phi), d, e + i);
      // The closed-form moments.
      const V r = hn::Mul(hn::Mul(hn::Mul(four, ca), ct), hn::Sqrt(xy));
      const auto valid = hn::And(hn::Gt(r, zero), hn::Gt(w, zero));
      const V rs = hn::IfThenElse(valid, r, one);
      const V cmb = hn::Mul(hn::Mul(four, ca2), x), cpb = hn::Mul(hn::Mul(four, ct2), y);
      const V c = hn::Mul(half, hn::Add(cmb, cpb));
      const V bb = hn::Mul(hn::Mul(two, s_i), s_o);
      const V i_m2 = hn::Div(hn::Mul(two_pi, c), hn::Mul(hn::Mul(rs, rs), rs));
      const V i_m1 = hn::Div(two_pi, rs);
      const V i_1 = hn::Mul(two_pi, c);
      const V i_2 = hn::Mul(two_pi, hn::MulAdd(hn::Mul(half, bb), bb, hn::Mul(c, c)));
      const V kappa = hn::Mul(hn::Mul(hn::Mul(b, four), ca2), ct2);
      const V skv = hn::Sqrt(kappa);
      const V f = hn::NegMulAdd(half, skv, one), f2 = hn::Mul(f, f), f4 = hn::Mul(f2, f2);
      const V g_k = hn::Mul(hn::Mul(hn::Mul(kappa, kappa), f4), f);
      const V gp_k =
          hn::Mul(hn::Mul(kappa, f4), hn::NegMulAdd(hn::Set(d, 1.25), skv, hn::Mul(two, f)));
      const V c2 = hn::MulAdd(kappa, hn::MulAdd(kappa, hn::Set(d, 1.875), hn::Set(d, 7.5)), one);
      const V c3 = hn::MulAdd(hn::Set(d, 1.25), kappa, hn::Set(d, 2.5));
      V cl = hn::Mul(g_k, i_m2);
      cl = hn::MulAdd(gp_k, i_m1, cl);
      cl = hn::MulAdd(c2, two_pi, cl);
      cl = hn::MulAdd(c3, i_1, cl);
      cl = hn::MulAdd(hn::Set(d, 0.3125), i_2, cl);
      hn::Store(hn::IfThenElseZero(valid, hn::Mul(w, norm)), d, wn + i);
      hn::Store(cl, d, closed + i);
      hn::Store(skv, d, sk + i);
      hn::Store(hn::Mul(four, ca2), d, vmin + i);
      hn::Store(hn::Mul(two, bb), d, two_bb + i);
      hn::Store(hn::Mul(two, ca), d, start + i);
    }
  }
};

RuleResult GgxAlbedoTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  return GgxAzimuthalAlbedoWith(
      alpha, mu, masking, tol, max_pieces,
      [](const GgxAzimuthalE& f, const double* theta, double* out) {
        SimdGgxNodes{f.frame_consts(), f.dfg_consts()}.Albedo(theta, out);
      });
}

AzimuthalDfgResult GgxDfgTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  const GgxAzimuthalE f(alpha, mu, masking);
  const SimdGgxNodes nodes{f.frame_consts(), f.dfg_consts()};
  return AdaptiveAzimuthalRule(AzimuthalMesh(f.theta_o(), f.lambda_o(), alpha), nodes, tol,
                               max_pieces);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GgxAlbedoTexel);
RuleResult SimdGgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(GgxAlbedoTexel)(alpha, mu, masking, tol, max_pieces);
}

HWY_EXPORT(GgxDfgTexel);
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(GgxDfgTexel)(alpha, mu, masking, tol, max_pieces);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
