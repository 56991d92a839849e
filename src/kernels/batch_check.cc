// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The domain check of per-element parameter arrays (batch.h,
// BatchElements) in whole vectors: a pass over n floats costs a small part
// of the kernels it guards. Compiled once per Highway target.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_check.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <bool kOpenLow>
bool AllWithinT(const float* a, size_t n, float lo, float hi) {
  const hn::ScalableTag<float> d;
  const size_t N = hn::Lanes(d);
  const auto vlo = hn::Set(d, lo), vhi = hn::Set(d, hi);
  auto ok = hn::Eq(vlo, vlo);
  size_t i = 0;
  for (; i + N <= n; i += N) {
    const auto v = hn::LoadU(d, a + i);
    const auto above = kOpenLow ? hn::Gt(v, vlo) : hn::Ge(v, vlo);
    ok = hn::And(ok, hn::And(above, hn::Le(v, vhi)));  // false for NaN
  }
  bool all = hn::AllTrue(d, ok);
  for (; i < n; ++i) all &= (kOpenLow ? a[i] > lo : a[i] >= lo) && a[i] <= hi;
  return all;
}

bool AllWithin(const float* a, size_t n, float lo, float hi, bool open_low) {
  return open_low ? AllWithinT<true>(a, n, lo, hi) : AllWithinT<false>(a, n, lo, hi);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(AllWithin);

bool AllWithinBatch(const float* a, size_t n, float lo, float hi, bool open_low) {
  return HWY_DYNAMIC_DISPATCH(AllWithin)(a, n, lo, hi, open_low);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
