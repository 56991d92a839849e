// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Beckmann batch kernels (src/kernels/beckmann-inl.h,
// beckmann_sampling-inl.h) behind batch.h, compiled once per Highway target
// by foreach_target.h.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_beckmann.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/beckmann-inl.h"
#include "kernels/beckmann_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void BeckmannEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  if (MicrofacetRows(BeckmannKernels<DF>{c}, p, q, in, out, n)) return;
  if (q != Quantity::kPdfVisible) return;
  PairRows([&](auto d, auto ox, auto oy, auto oz, auto mx, auto my,
               auto mz) { return BeckmannPdfVisible(d, c, ox, oy, oz, mx, my, mz); },
           in, out, n);
}

void BeckmannSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                    size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  if (s == Sampler::kVisible) {
    return VisibleRows(
        [&](auto d, auto ox, auto oy, auto oz, auto u1, auto u2, auto* mx, auto* my, auto* mz) {
          BeckmannSampleVisible(d, c, ox, oy, oz, u1, u2, mx, my, mz);
        },
        in, out, n);
  }
  NdfSampleRows([&](auto d, auto u1, auto u2, auto* mx, auto* my,
                    auto* mz) { BeckmannSampleNdf(d, c, u1, u2, mx, my, mz); },
                in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Beckmann)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Beckmann)

}  // namespace brdfbake
#endif  // HWY_ONCE
