// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Disney diffuse batch kernel (src/kernels/sheen-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include <cmath>

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_disney.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/sheen-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void DisneyEval(const BatchModel& p, Quantity, const float* const* in, float* out, size_t n) {
  const DisneyConsts<DF> c(DF(), std::sqrt(double(p.alpha_x)));
  PairRows(
      [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
        return DisneyBrdf(d, c, ix, iy, iz, ox, oy, oz);
      },
      in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Disney)

}  // namespace brdfbake
#endif  // HWY_ONCE
