// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sheen and Disney diffuse albedo rules (rules/sheen/sheen_albedo_rule.h)
// with their nodes in double SIMD lanes, through the kernels of
// kernels/sheen-inl.h that the float batch API runs too.

#include <algorithm>
#include <cstddef>

#include "lanes/quadrature_simd.h"
#include "rules/sheen/sheen_albedo_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/sheen_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/sheen-inl.h"
#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// ScalarCharlieNodes with a piece's 15 nodes in lanes (the 16th at the
// piece's centre, of weight 0) and its Kronrod and Gauss sums in lanes:
// cos, exp, expm1 and log by Highway's (a few ulp in double), Lambda(NoL)
// by CharlieLogLambda of kernels/sheen-inl.h, Lambda(mu) once per texel.
// In z = NoL^power, z is the x^p of Lambda's L(x) = a / (1 + b x^p) + d x
// + e (CharlieLPower is the fit's p), and every NoL there is below 1/2
// (Lambda's lower branch), so L takes z itself.
struct SimdCharlieNodes {
  using V = hn::Vec<DF64>;
  CharlieConsts<DF64> c;
  double mu;
  double lambda_mu;  // conty-kulla: Lambda(mu)

  // ScalarCharlieNodes::Outer in lanes: Highway's Sin, Cos, Acos and
  // Log1p, D by CharlieDCos2.
  void Outer(const CharlieOuterSetup& o, const double* sv, CharlieOuterNodes* out) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16];
    NodesTo16(sv, in);
    const V one = hn::Set(d, 1.0), minus_one = hn::Set(d, -1.0), zero = hn::Zero(d);
    const V mu = hn::Set(d, o.mu), s_mu = hn::Set(d, o.s_mu), theta_max = hn::Set(d, o.theta_max);
    const V inv_eps = hn::Set(d, 1 / o.eps);
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::Load(d, in + i);
      const V th = hn::Mul(theta_max, hn::NegMulAdd(x, x, one));
      const V cv = hn::Cos(d, th), sv_th = hn::Sin(d, th);
      const V w = hn::Mul(hn::Mul(CharlieDCos2(d, c, hn::Mul(cv, cv)), sv_th),
                          hn::Mul(hn::Set(d, 2 * o.theta_max), x));
      const V p = hn::Mul(mu, cv), r = hn::Mul(s_mu, sv_th), two_c = hn::Add(cv, cv);
      const auto r_pos = hn::Gt(r, zero);
      const V rs = hn::IfThenElse(r_pos, r, one);
      // cos(phi) where NoL = nol; -1 (phi = pi) where r = 0.
      auto cos_at = [&](V nol) {
        const V v = hn::Div(hn::Sub(hn::Div(hn::Add(nol, mu), two_c), p), rs);
        return hn::IfThenElse(r_pos, hn::Min(hn::Max(v, minus_one), one), minus_one);
      };
      const V cm = hn::IfThenElse(r_pos, hn::Div(hn::Sub(hn::Div(mu, two_c), p), rs), minus_one);
      const V phi_max = hn::IfThenElse(
          hn::Lt(cm, one), hn::Acos(d, hn::Min(hn::Max(cm, minus_one), one)), zero);
      const V nol0 = hn::Sub(hn::Mul(two_c, hn::Add(p, r)), mu);
      V split = hn::Mul(hn::Set(d, 0.5), nol0);
      if (o.lambda) {
        split = hn::IfThenElse(hn::Ge(nol0, hn::Set(d, 0.8)), hn::Set(d, 0.5),
                               hn::Mul(hn::Set(d, 0.35), nol0));
      }
      hn::StoreU(cv, d, out->c + i);
      hn::StoreU(sv_th, d, out->s + i);
      hn::StoreU(w, d, out->w + i);
      hn::StoreU(phi_max, d, out->phi_max + i);
      hn::StoreU(hn::Acos(d, cos_at(hn::Set(d, 0.5))), d, out->phi_half + i);
      hn::StoreU(hn::Acos(d, cos_at(split)), d, out->phi_split + i);
      hn::StoreU(hn::Log1p(d, hn::Mul(split, inv_eps)), d, out->tau_hi + i);
    }
  }

  GkPiece Piece(CharlieArcVar var, const CharlieArcTerms& t, double arg, double a, double b) const {
    switch (var) {
      case CharlieArcVar::kZ: return Sums<CharlieArcVar::kZ>(t, arg, a, b);
      case CharlieArcVar::kLog: return Sums<CharlieArcVar::kLog>(t, arg, a, b);
      default: return Sums<CharlieArcVar::kPhi>(t, arg, a, b);
    }
  }

 private:
  template <CharlieArcVar kVar>
  GkPiece Sums(const CharlieArcTerms& t, double arg, double a, double b) const {
    static const Kronrod16 rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const double mid = 0.5 * (a + b), h = 0.5 * (b - a);
    const Terms terms(d, t, mu, lambda_mu);
    V ks = hn::Zero(d), gs = hn::Zero(d);
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::MulAdd(hn::Set(d, h), hn::Load(d, rule.x + i), hn::Set(d, mid));
      const V g = Node<kVar>(d, terms, arg, x);
      ks = hn::MulAdd(hn::Load(d, rule.wk + i), g, ks);
      gs = hn::MulAdd(hn::Load(d, rule.wg + i), g, gs);
    }
    const double k = hn::GetLane(hn::SumOfLanes(d, ks)), gauss = hn::GetLane(hn::SumOfLanes(d, gs));
    const double s = 2 * h;
    GkPiece p;
    p.a = a;
    p.b = b;
    p.value = k * s;
    p.err = std::abs(k - gauss) * s;
    return p;
  }

  // One arc's constants in lanes.
  struct Terms {
    V p, r, two_c, mu, one_lambda_mu, half_over_c, nol0, nol_pi;
    Terms(DF64 d, const CharlieArcTerms& t, double m, double lambda_mu)
        : p(hn::Set(d, t.p)),
          r(hn::Set(d, t.r)),
          two_c(hn::Set(d, t.two_c)),
          mu(hn::Set(d, m)),
          one_lambda_mu(hn::Set(d, 1 + lambda_mu)),
          half_over_c(hn::Set(d, 1 / t.two_c)),
          nol0(hn::Set(d, t.two_c * (t.p + t.r) - m)),
          nol_pi(hn::Set(d, t.two_c * (t.p - t.r) - m)) {}
  };

  // g = V NoL 4 y at NoL = 2 c y - mu, as num / den, times the Jacobian
  // jac_num / jac_den of the node's variable: y = p + r cos(phi) (kPhi);
  // NoL = z^(1/power), dphi/dz = NoL / (z power 2 c r sin(phi)) (kZ);
  // NoL = eps expm1(tau), dphi/dtau = (NoL + eps) / (2 c r sin(phi))
  // (kLog). There 2 c r sin(phi) = sqrt((nol0 - NoL) (NoL - nol_pi))
  // (ArcSine). One division per node where V is not capped.
  template <CharlieArcVar kVar>
  HWY_INLINE V Node(DF64 d, const Terms& t, double arg, V x) const {
    const V one = hn::Set(d, 1.0), zero = hn::Zero(d);
    V y, nol, jac_num = one, jac_den = one;
    if constexpr (kVar == CharlieArcVar::kPhi) {
      y = hn::MulAdd(t.r, hn::Cos(d, x), t.p);
      nol = hn::Sub(hn::Mul(t.two_c, y), t.mu);
    } else {
      if constexpr (kVar == CharlieArcVar::kZ) {
        nol = hn::Exp(d, hn::Mul(hn::Set(d, 1 / arg), hn::Log(d, x)));
      } else {
        nol = hn::Mul(hn::Set(d, arg), hn::Expm1(d, x));
      }
      y = hn::Mul(hn::Add(nol, t.mu), t.half_over_c);
      jac_den = hn::Sqrt(hn::Max(hn::Mul(hn::Sub(t.nol0, nol), hn::Sub(nol, t.nol_pi)), zero));
      if constexpr (kVar == CharlieArcVar::kZ) {
        jac_num = nol;
        jac_den = hn::Mul(jac_den, hn::Mul(x, hn::Set(d, arg)));
      } else {
        jac_num = hn::Add(nol, hn::Set(d, arg));
      }
    }
    const auto up = hn::Gt(nol, zero);
    const V nl = hn::Min(hn::IfThenElse(up, nol, one), one);
    V num, den;
    if (c.neubelt) {
      // V NoL 4 y = NoL y / (NoL + mu - NoL mu).
      num = hn::Mul(nol, y);
      den = hn::Add(hn::NegMulAdd(nl, t.mu, nl), t.mu);
    } else {
      // V NoL 4 y = y G2 / mu, G2 = 1 / (1 + Lambda(mu) + Lambda(NoL)).
      V log_lambda;
      if constexpr (kVar == CharlieArcVar::kZ) {
        log_lambda = hn::Add(hn::MulAdd(c.dd, nl, c.e), hn::Div(c.a, hn::MulAdd(c.b, x, one)));
      } else {
        log_lambda = CharlieLogLambda(d, c, nl);
      }
      num = y;
      den = hn::Mul(t.mu, hn::Add(t.one_lambda_mu, hn::Exp(d, log_lambda)));
    }
    V g;
    if (c.clamp) {
      // V <= 1, so g <= 4 NoL y.
      g = hn::Min(hn::Div(num, den), hn::Mul(hn::Mul(hn::Set(d, 4.0), nl), y));
      if constexpr (kVar != CharlieArcVar::kPhi) g = hn::Div(hn::Mul(g, jac_num), jac_den);
    } else {
      g = hn::Div(hn::Mul(num, jac_num), hn::Mul(den, jac_den));
    }
    return hn::IfThenElseZero(up, g);
  }
};

RuleResult CharlieTexel(double alpha, SheenVisibility visibility, double mu, double tol,
                        int max_pieces) {
  const CharlieSheen<double> sheen(alpha, visibility);
  const double m = std::clamp(mu, 1e-7, 1.0);
  const SimdCharlieNodes nodes{CharlieConsts<DF64>(DF64(), alpha, visibility), m,
                               SheenHasLambda(visibility) ? sheen.LambdaCos(m) : 0.0};
  return CharlieAlbedoWith(sheen, mu, tol, max_pieces, nodes);
}

// ScalarDisneyNodes with the n <= 16 cosines in lanes.
struct SimdDisneyNodes {
  double r;
  void operator()(const double* x, double mu, int n, double* m) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16] = {}, out[16];
    for (int i = 0; i < n; ++i) in[i] = x[i];
    const DisneyConsts<DF64> c(d, r);
    const V muv = hn::Set(d, mu);
    for (size_t i = 0; i < size_t(n); i += N) {
      hn::Store(DisneyAzimuthMean(d, c, hn::Load(d, in + i), muv), d, out + i);
    }
    for (int i = 0; i < n; ++i) m[i] = out[i];
  }
};

RuleResult DisneyTexel(double r, double mu) { return DisneyAlbedoWith(mu, SimdDisneyNodes{r}); }
RuleResult DisneyEavgTexel(double r) { return DisneyEavgWith(SimdDisneyNodes{r}); }

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(CharlieTexel);
RuleResult SimdCharlieAlbedo(double alpha, SheenVisibility visibility, double mu, double tol,
                             int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(CharlieTexel)(alpha, visibility, mu, tol, max_pieces);
}

HWY_EXPORT(DisneyTexel);
RuleResult SimdDisneyAlbedo(double r, double mu) { return HWY_DYNAMIC_DISPATCH(DisneyTexel)(r, mu); }

HWY_EXPORT(DisneyEavgTexel);
RuleResult SimdDisneyEavg(double r) { return HWY_DYNAMIC_DISPATCH(DisneyEavgTexel)(r); }

}  // namespace brdfbake
#endif  // HWY_ONCE
