// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The loop every batch kernel runs: whole vectors over the arrays, then the
// tail padded into one more vector.

#if defined(BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_
#undef BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_
#endif

#include <cstddef>
#include <cstring>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Runs `kernel(v...)` over n elements of `in_count` input arrays. The tail
// is copied into full vectors padded with a harmless value, so every target
// runs one branch-free vector loop and nothing is read or written past n.
// `kernel(d, const Vec* v)` maps kIn input vectors to one output vector.
template <int kIn, class Kernel>
HWY_INLINE void ForEachVector(const float* const* in, float pad, float* out, size_t n,
                              const Kernel& kernel) {
  using D = hn::ScalableTag<float>;
  const D d;
  const size_t N = hn::Lanes(d);
  size_t i = 0;
  for (; i + N <= n; i += N) {
    hn::Vec<D> v[kIn];
    for (int k = 0; k < kIn; ++k) v[k] = hn::LoadU(d, in[k] + i);
    hn::StoreU(kernel(d, v), d, out + i);
  }
  if (i < n) {
    HWY_ALIGN float buf[kIn][HWY_MAX_BYTES / sizeof(float)];
    HWY_ALIGN float res[HWY_MAX_BYTES / sizeof(float)];
    const size_t rem = n - i;
    hn::Vec<D> v[kIn];
    for (int k = 0; k < kIn; ++k) {
      for (size_t j = 0; j < N; ++j) buf[k][j] = j < rem ? in[k][i + j] : pad;
      v[k] = hn::Load(d, buf[k]);
    }
    hn::Store(kernel(d, v), d, res);
    std::memcpy(out + i, res, rem * sizeof(float));
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_
