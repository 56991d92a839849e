// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// For the per-target tests of the double-lane kernels: a vector function
// applied to every element of an array on the target being compiled.

#if defined(BRDFBAKE_TESTS_KERNELS_SIMD_MAP_F64_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_TESTS_KERNELS_SIMD_MAP_F64_INL_H_
#undef BRDFBAKE_TESTS_KERNELS_SIMD_MAP_F64_INL_H_
#else
#define BRDFBAKE_TESTS_KERNELS_SIMD_MAP_F64_INL_H_
#endif

#include <cstddef>
#include <vector>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {

// fn(d, v) over x, the tail padded with 1.0 into one more vector.
template <class Fn>
std::vector<double> MapF64(const std::vector<double>& x, const Fn& fn) {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::ScalableTag<double> d;
  const size_t N = hn::Lanes(d);
  std::vector<double> in(x), out((x.size() + N - 1) / N * N);
  in.resize(out.size(), 1.0);
  for (size_t i = 0; i < in.size(); i += N) hn::StoreU(fn(d, hn::LoadU(d, &in[i])), d, &out[i]);
  out.resize(x.size());
  return out;
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_TESTS_KERNELS_SIMD_MAP_F64_INL_H_
