// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The loop every batch kernel runs: whole vectors over the arrays, then the
// remainder as one more whole vector.

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

// Runs `kernel(d, const Vec* in, Vec* out)`, which maps kIn input vectors
// to kOut output vectors, over n elements. An input array may be null: its
// lanes are then fill[k] (a per-call value broadcast to every element).
//
// The remainder after the whole vectors is one more whole vector: with
// n >= Lanes, the last Lanes elements again (the kernels are elementwise and
// the outputs do not alias the inputs, so the overlap stores the same
// values); with fewer, a copy padded with fill[k]. Every target runs one
// branch-free vector loop, and nothing is read or written outside [0, n).
template <int kIn, int kOut, class Kernel>
HWY_INLINE void ForEachVectorOut(const float* const* in, const float* fill, float* const* out,
                                 size_t n, const Kernel& kernel) {
  using D = hn::ScalableTag<float>;
  const D d;
  const size_t N = hn::Lanes(d);
  hn::Vec<D> broadcast[kIn];
  for (int k = 0; k < kIn; ++k) broadcast[k] = hn::Set(d, fill[k]);
  const auto step = [&](size_t i) HWY_ATTR {
    hn::Vec<D> v[kIn], r[kOut];
    for (int k = 0; k < kIn; ++k) v[k] = in[k] ? hn::LoadU(d, in[k] + i) : broadcast[k];
    kernel(d, v, r);
    for (int k = 0; k < kOut; ++k) hn::StoreU(r[k], d, out[k] + i);
  };
  size_t i = 0;
  for (; i + N <= n; i += N) step(i);
  if (i == n) return;
  if (n >= N) return step(n - N);
  HWY_ALIGN float buf[kIn][HWY_MAX_BYTES / sizeof(float)];
  HWY_ALIGN float res[HWY_MAX_BYTES / sizeof(float)];
  hn::Vec<D> v[kIn], r[kOut];
  for (int k = 0; k < kIn; ++k) {
    for (size_t j = 0; j < N; ++j) buf[k][j] = in[k] && j < n ? in[k][j] : fill[k];
    v[k] = hn::Load(d, buf[k]);
  }
  kernel(d, v, r);
  for (int k = 0; k < kOut; ++k) {
    hn::Store(r[k], d, res);
    std::memcpy(out[k], res, n * sizeof(float));
  }
}

// The same with every input array given and `pad` in the padded lanes.
template <int kIn, int kOut, class Kernel>
HWY_INLINE void ForEachVectorOut(const float* const* in, float pad, float* const* out, size_t n,
                                 const Kernel& kernel) {
  float fill[kIn];
  for (int k = 0; k < kIn; ++k) fill[k] = pad;
  ForEachVectorOut<kIn, kOut>(in, fill, out, n, kernel);
}

// One output array: `kernel(d, const Vec* in)` returns its vector.
template <int kIn, class Kernel>
HWY_INLINE void ForEachVector(const float* const* in, float pad, float* out, size_t n,
                              const Kernel& kernel) {
  float* outs[1] = {out};
  ForEachVectorOut<kIn, 1>(in, pad, outs, n,
                           [&](auto d, const auto* v, auto* r) HWY_ATTR { r[0] = kernel(d, v); });
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_FOREACH_INL_H_
