// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The squared ellipsoidal lobe's batch kernel (src/kernels/sel-inl.h, seed
// 002) behind batch.h, compiled once per Highway target by
// foreach_target.h.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_sel.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/sel-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void SelEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const SelConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z);
  DirRows([&](auto d, auto x, auto y, auto z) { return SelK(d, c, x, y, z); }, in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Sel)

}  // namespace brdfbake
#endif  // HWY_ONCE
