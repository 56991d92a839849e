// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann's azimuthal moments M_0, M_1, M_2 (src/rules/beckmann/beckmann_azimuth.h, the
// double scalar reference BeckmannAzimuthMoments) in double lanes. Each lane
// sums the same terms as the scalar reference: Horner's rule runs from the
// highest top term among the lanes, with the coefficients above a lane's own
// top masked to zero (its sums stay 0 until its top term), so the lanes
// differ from the scalar only by fused multiply-adds and hn::Exp (1 ulp).
// tests/rules/beckmann_azimuth_test.cc bounds the difference on every target.
// Cost: up to 109 (x < 40) and 38 (x >= 40) Horner steps of three
// independent chains; a vector whose lanes all lie on one side skips the
// other side's sums.

// Plain includes (normal include guard).
#ifndef BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_PLAIN_
#define BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_PLAIN_
#include "rules/beckmann/beckmann_azimuth.h"
#endif

// The SIMD part (per-target include guard).
#if defined(BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_
#undef BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_
#else
#define BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// M_0, M_1, M_2 at x >= 0 (no NaN; +inf gives 0).
template <class D, class V>
HWY_INLINE void BeckmannAzimuthMomentsF64(D d, V x, V* m0, V* m1, V* m2) {
  using T = BeckmannMomentTables;
  const T& t = T::Get();
  const V zero = hn::Zero(d), from = hn::Set(d, T::kAsymptoticFrom);
  const auto small = hn::Lt(x, from);
  V r0 = zero, r1 = zero, r2 = zero;
  if (!hn::AllFalse(d, small)) {
    // The series at x < 40 (other lanes at x = 0).
    const V xs = hn::IfThenElseZero(small, x);
    const V top =
        hn::Floor(hn::Add(hn::Add(xs, hn::Mul(hn::Set(d, 9.0), hn::Sqrt(xs))), hn::Set(d, 12.0)));
    const int top_max = static_cast<int>(hn::GetLane(hn::MaxOfLanes(d, top)));
    V s0 = zero, s1 = zero, s2 = zero;
    for (int n = top_max; n >= 0; --n) {
      const auto in = hn::Le(hn::Set(d, static_cast<double>(n)), top);
      s0 = hn::MulAdd(s0, xs, hn::IfThenElseZero(in, hn::Set(d, t.series[0][n])));
      s1 = hn::MulAdd(s1, xs, hn::IfThenElseZero(in, hn::Set(d, t.series[1][n])));
      s2 = hn::MulAdd(s2, xs, hn::IfThenElseZero(in, hn::Set(d, t.series[2][n])));
    }
    const V e = hn::Exp(d, hn::Neg(xs));
    r0 = hn::Mul(e, s0);
    r1 = hn::Mul(e, s1);
    r2 = hn::Mul(e, s2);
  }
  if (!hn::AllTrue(d, small)) {
    // The asymptotic expansion at x >= 40 (other lanes at x = 40).
    const V xl = hn::IfThenElse(small, from, x);
    const V y = hn::Div(hn::Set(d, 1.0), xl), r = hn::Sqrt(y);
    // AsymptoticCount: 38, less 13 from 50, 9 from 80, 6 from 200, 3 from
    // 1000 and 3 from 1e5.
    V count = hn::Set(d, 38.0);
    const double steps[5][2] = {{50, 13}, {80, 9}, {200, 6}, {1000, 3}, {1e5, 3}};
    for (const auto& s : steps) {
      count = hn::Sub(count, hn::IfThenElseZero(hn::Ge(xl, hn::Set(d, s[0])), hn::Set(d, s[1])));
    }
    const int top_max = static_cast<int>(hn::GetLane(hn::MaxOfLanes(d, count))) - 1;
    V s0 = zero, s1 = zero, s2 = zero;
    for (int n = top_max; n >= 0; --n) {
      const auto in = hn::Lt(hn::Set(d, static_cast<double>(n)), count);
      s0 = hn::MulAdd(s0, y, hn::IfThenElseZero(in, hn::Set(d, t.asymptotic[0][n])));
      s1 = hn::MulAdd(s1, y, hn::IfThenElseZero(in, hn::Set(d, t.asymptotic[1][n])));
      s2 = hn::MulAdd(s2, y, hn::IfThenElseZero(in, hn::Set(d, t.asymptotic[2][n])));
    }
    const V ry = hn::Mul(r, y);
    r0 = hn::IfThenElse(small, r0, hn::Mul(r, s0));
    r1 = hn::IfThenElse(small, r1, hn::Mul(ry, s1));
    r2 = hn::IfThenElse(small, r2, hn::Mul(hn::Mul(ry, y), s2));
  }
  *m0 = r0;
  *m1 = r1;
  *m2 = r2;
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_LANES_BECKMANN_AZIMUTH_F64_INL_H_
