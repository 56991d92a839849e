// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// ForEachVector (foreach-inl.h) for kernels with several outputs, e.g. the
// samplers that return the x, y, z arrays of a normal: whole vectors, then
// the tail padded into one more vector, nothing read or written past n.

#if defined(BRDFBAKE_SRC_KERNELS_FOREACH_OUT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_FOREACH_OUT_INL_H_
#undef BRDFBAKE_SRC_KERNELS_FOREACH_OUT_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_FOREACH_OUT_INL_H_
#endif

#include <cstddef>
#include <cstring>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// `kernel(d, const Vec* in, Vec* out)` maps kIn input vectors to kOut
// output vectors; `pad` fills the inputs of the unused tail lanes.
template <int kIn, int kOut, class Kernel>
HWY_INLINE void ForEachVectorOut(const float* const* in, float pad, float* const* out, size_t n,
                                 const Kernel& kernel) {
  using D = hn::ScalableTag<float>;
  const D d;
  const size_t N = hn::Lanes(d);
  size_t i = 0;
  for (; i + N <= n; i += N) {
    hn::Vec<D> v[kIn], r[kOut];
    for (int k = 0; k < kIn; ++k) v[k] = hn::LoadU(d, in[k] + i);
    kernel(d, v, r);
    for (int k = 0; k < kOut; ++k) hn::StoreU(r[k], d, out[k] + i);
  }
  if (i < n) {
    HWY_ALIGN float buf[kIn][HWY_MAX_BYTES / sizeof(float)];
    HWY_ALIGN float res[HWY_MAX_BYTES / sizeof(float)];
    const size_t rem = n - i;
    hn::Vec<D> v[kIn], r[kOut];
    for (int k = 0; k < kIn; ++k) {
      for (size_t j = 0; j < N; ++j) buf[k][j] = j < rem ? in[k][i + j] : pad;
      v[k] = hn::Load(d, buf[k]);
    }
    kernel(d, v, r);
    for (int k = 0; k < kOut; ++k) {
      hn::Store(r[k], d, res);
      std::memcpy(out[k] + i, res, rem * sizeof(float));
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_FOREACH_OUT_INL_H_
