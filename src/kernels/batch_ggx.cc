// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX batch kernels (src/kernels/ggx-inl.h, ggx_sampling-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_ggx.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/ggx-inl.h"
#include "kernels/ggx_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void GgxEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  if (q == Quantity::kPdfNdf || q == Quantity::kPdfVisible) {
    const GgxSamplingConsts<DF> s(DF(), p.alpha_x, p.alpha_y);
    if (q == Quantity::kPdfNdf) {
      return DirRows([&](auto d, auto x, auto y, auto z) { return GgxPdfNdf(d, s, x, y, z); }, in,
                     out, n);
    }
    return PairRows([&](auto d, auto ox, auto oy, auto oz, auto mx, auto my,
                        auto mz) { return GgxPdfVisible(d, s, ox, oy, oz, mx, my, mz); },
                    in, out, n);
  }
  const GgxConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  MicrofacetRows(GgxKernels<DF>{c}, p, q, in, out, n);
}

void GgxSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
               size_t n) {
  const GgxSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y);
  if (s == Sampler::kVisible) {
    return VisibleRows([&](auto d, auto ox, auto oy, auto oz, auto u1, auto u2, auto* mx, auto* my,
                           auto* mz) { GgxSampleVisible(d, c, ox, oy, oz, u1, u2, mx, my, mz); },
                       in, out, n);
  }
  NdfSampleRows([&](auto d, auto u1, auto u2, auto* mx, auto* my,
                    auto* mz) { GgxSampleNdf(d, c, u1, u2, mx, my, mz); },
                in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Ggx)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Ggx)

}  // namespace brdfbake
#endif  // HWY_ONCE
