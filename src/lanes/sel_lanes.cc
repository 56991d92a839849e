// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sel lobe's integral (rules/sel/sel_norm_rule.h) with its inner
// rule's nodes in double SIMD lanes.

#include <cstddef>

#include "lanes/sel_lanes.h"
#include "rules/sel/sel_norm_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/sel_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// ScalarSelNodes (sel_norm_rule.h) with the 15 angles in lanes (the 16th
// repeats the first): cos and sin by Highway's Cos and Sin (3 ulp in
// double, against the C library's), the rest the same operations.
struct SimdSelNodes {
  void operator()(const SelPhiTerms& t, const double* phi, double* g) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double p[16], out[16];
    NodesTo16(phi, p);
    const V s2 = hn::Set(d, t.s2), c2 = hn::Set(d, t.c * t.c);
    const V ikx2 = hn::Set(d, t.ikx2), iky2 = hn::Set(d, t.iky2), one = hn::Set(d, 1.0);
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::Load(d, p + i);
      const V cp = hn::Cos(d, x), sp = hn::Sin(d, x);
      const V q = hn::Add(
          hn::Mul(s2, hn::Add(hn::Mul(hn::Mul(cp, cp), ikx2), hn::Mul(hn::Mul(sp, sp), iky2))), c2);
      hn::Store(hn::Div(one, hn::Sqrt(q)), d, out + i);
    }
    for (int i = 0; i < 15; ++i) g[i] = out[i];
  }
};

SelIntegral SelLobeTexel(double alpha_x, double alpha_y, double tol) {
  return SelLobeIntegralWith(alpha_x, alpha_y, tol, SimdSelNodes{});
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(SelLobeTexel);
SelIntegral SimdSelLobeIntegral(double alpha_x, double alpha_y, double tol) {
  return HWY_DYNAMIC_DISPATCH(SelLobeTexel)(alpha_x, alpha_y, tol);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
