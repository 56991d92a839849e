// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen's batch kernels (src/kernels/sheen-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_charlie.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/ggx_sampling-inl.h"
#include "kernels/sheen-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void CharlieEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const CharlieConsts<DF> c(DF(), p.alpha_x, p.visibility);
  switch (q) {
    case Quantity::kD:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieD(d, c, z); }, in, out, n);
    case Quantity::kPdfNdf:
      return DirRows(
          [&](auto d, auto, auto, auto z) {
            return hn::Mul(CharlieD(d, c, z), hn::Min(hn::Max(z, hn::Zero(d)), hn::Set(d, 1.0f)));
          },
          in, out, n);
    case Quantity::kLambda:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieLambda(d, c, z); }, in, out,
                     n);
    case Quantity::kG1:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieG1(d, c, z); }, in, out, n);
    case Quantity::kG2:
      return PairRows(
          [&](auto d, auto, auto, auto iz, auto, auto, auto oz) { return CharlieG2(d, c, iz, oz); },
          in, out, n);
    case Quantity::kBrdf:
      return PairRows(
          [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
            return CharlieBrdf(d, c, ix, iy, iz, ox, oy, oz);
          },
          in, out, n);
    default:
      return;  // batch.cc admits no other quantity
  }
}

// Normals with density D(m) m.z (CharlieSheen<T>::SampleNdf): phi = 2 pi u1,
// sin(theta_m) = u2^(alpha / (2 alpha + 1)).
void CharlieSample(const BatchModel& p, Sampler, const float* const* in, float* const* out,
                   size_t n) {
  const double alpha = ClampSheenAlpha(double(p.alpha_x));
  const float expo = static_cast<float>(alpha / (2 * alpha + 1));
  NdfSampleRows<0>(
      p,
      [&](auto d, const auto*, auto u1, auto u2, auto* mx, auto* my, auto* mz) {
        const auto one = hn::Set(d, 1.0f);
        const auto uc = hn::Min(hn::Max(u2, hn::Zero(d)), one);
        const auto pos = hn::Gt(uc, hn::Zero(d));
        const auto s = hn::IfThenElseZero(
            pos, hn::Exp(d, hn::Mul(hn::Set(d, expo), hn::Log(d, hn::IfThenElse(pos, uc, one)))));
        const auto z = hn::Sqrt(hn::Max(hn::Mul(hn::Sub(one, s), hn::Add(one, s)), hn::Zero(d)));
        using V = hn::Vec<decltype(d)>;
        V sn = hn::Zero(d), cs = hn::Zero(d);
        SinCos2Pi(d, u1, &sn, &cs);
        *mx = hn::Mul(s, cs);
        *my = hn::Mul(s, sn);
        *mz = z;
      },
      in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Charlie)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Charlie)

}  // namespace brdfbake
#endif  // HWY_ONCE
