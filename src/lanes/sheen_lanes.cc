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

// ScalarCharlieNodes with the 15 nodes in lanes (the 16th repeats the
// first): cos, pow, exp and log by Highway's (a few ulp in double),
// Lambda(NoL) by CharlieLogLambda of kernels/sheen-inl.h, Lambda(mu) once
// per texel.
struct SimdCharlieNodes {
  CharlieConsts<DF64> c;
  double mu;
  double lambda_mu;  // conty-kulla: Lambda(mu)

  void operator()(const CharlieArcTerms& t, const double* phi, double* g) const {
    Eval<false>(t, 0, phi, g);
  }
  void AtEnd(const CharlieArcTerms& t, double power, const double* z, double* g) const {
    Eval<true>(t, power, z, g);
  }

 private:
  // g = V NoL 4 y at NoL = 2 c y - mu, y = p + r cos(phi) (kEnd: NoL =
  // z^(1/power), times dphi/dz = NoL / (z power 2 c r sin(phi))).
  template <bool kEnd>
  void Eval(const CharlieArcTerms& t, double power, const double* x, double* g) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16], out[16];
    NodesTo16(x, in);
    const V p = hn::Set(d, t.p), r = hn::Set(d, t.r), two_c = hn::Set(d, t.two_c);
    const V muv = hn::Set(d, mu), one = hn::Set(d, 1.0), zero = hn::Zero(d);
    const V one_lambda_mu = hn::Set(d, 1 + lambda_mu);
    for (size_t i = 0; i < 16; i += N) {
      const V xv = hn::Load(d, in + i);
      V y, nol, jac = one;
      if constexpr (kEnd) {
        nol = hn::Exp(d, hn::Mul(hn::Set(d, 1 / power), hn::Log(d, xv)));
        y = hn::Div(hn::Add(nol, muv), two_c);
        const V cp = hn::Min(hn::Max(hn::Div(hn::Sub(y, p), r), hn::Set(d, -1.0)), one);
        const V sp = hn::Sqrt(hn::Mul(hn::Sub(one, cp), hn::Add(one, cp)));
        jac = hn::Div(nol, hn::Mul(hn::Mul(hn::Mul(xv, hn::Set(d, power)), hn::Mul(two_c, r)), sp));
      } else {
        y = hn::MulAdd(r, hn::Cos(d, xv), p);
        nol = hn::Sub(hn::Mul(two_c, y), muv);
      }
      const auto up = hn::Gt(nol, zero);
      const V nl = hn::Min(hn::IfThenElse(up, nol, one), one);
      V f;
      // (c.clamp: V <= 1, so g <= 4 NoL y.)
      if (c.neubelt) {
        // V NoL 4 y = NoL y / (NoL + mu - NoL mu).
        f = hn::Div(hn::Mul(nol, y), hn::Add(hn::NegMulAdd(nl, muv, nl), muv));
      } else {
        // V NoL 4 y = y G2 / mu, G2 = 1 / (1 + Lambda(mu) + Lambda(NoL)),
        // Lambda(mu) once per texel.
        const V lam = hn::Exp(d, CharlieLogLambda(d, c, nl));
        f = hn::Div(y, hn::Mul(muv, hn::Add(one_lambda_mu, lam)));
      }
      if (c.clamp) f = hn::Min(f, hn::Mul(hn::Mul(hn::Set(d, 4.0), nl), y));
      hn::Store(hn::IfThenElseZero(up, hn::Mul(f, jac)), d, out + i);
    }
    for (int i = 0; i < 15; ++i) g[i] = out[i];
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
