// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Helpers shared by the per-target SIMD tests (tests/simd_*_test.cc):
// direction sets in structure-of-arrays float form and the relative error
// used against the double reference. Included before foreach_target.h, so it
// is compiled once; each test brings the names into its HWY_NAMESPACE.

#ifndef BRDFBAKE_TESTS_UTIL_SIMD_TEST_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_SIMD_TEST_UTIL_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/models/vec3.h"

namespace brdfbake {
namespace test {

// Unit directions as separate float arrays (the batch API's layout); At()
// returns the float-rounded direction in double, the reference's input.
struct Dirs {
  std::vector<float> x, y, z;
  void Push(const Vec3<double>& w) {
    x.push_back(static_cast<float>(w.x));
    y.push_back(static_cast<float>(w.y));
    z.push_back(static_cast<float>(w.z));
  }
  Vec3<double> At(size_t i) const { return {x[i], y[i], z[i]}; }
  size_t size() const { return x.size(); }
};

// n directions: mu uniform, log-uniform down to 1e-6 for one in seven, the
// pole for one in 97, and (when below_every > 0) below the horizon for one in
// below_every.
inline Dirs RandomDirs(size_t n, uint64_t seed, size_t below_every = 0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Dirs d;
  for (size_t i = 0; i < n; ++i) {
    double mu = i % 7 == 0 ? std::pow(10.0, -6 * uni(rng)) : uni(rng);
    if (i % 97 == 0) mu = 1.0;
    if (below_every > 0 && i % below_every == 0) mu = -uni(rng);
    d.Push(FromMuPhi(mu, 2 * 3.141592653589793 * uni(rng)));
  }
  return d;
}

// |got - ref| / max(|ref|, 1e-30); an infinite reference must be matched.
// Uniform floats in [0, 1) with the edges 0, 1 - 2^-24, 0.25, 0.5, 0.75 and
// values within 1e-6 of 1 mixed in.
inline std::vector<float> RandomUniforms(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const float edges[] = {0.0f, 1.0f - 0x1p-24f, 0.25f, 0.5f, 0.75f};
  std::vector<float> u(n);
  for (size_t i = 0; i < n; ++i) {
    u[i] = uni(rng);
    if (i % 53 == 0) u[i] = edges[(i / 53) % 5];
    if (i % 59 == 0) u[i] = 1.0f - 1e-6f * uni(rng);
  }
  return u;
}

inline double MaxAbsDiff(const Vec3<double>& a, const Vec3<double>& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

inline double RelErr(double got, double ref) {
  if (std::isinf(ref)) return std::isinf(got) ? 0.0 : 1.0;
  return std::abs(got - ref) / std::max(std::abs(ref), 1e-30);
}

// A batch call on n_in input arrays (8 unless given) writing n_out output
// arrays of n floats.
using BatchCall = std::function<void(const float* const*, float* const*, size_t)>;

// Counts 0..max_n at input misalignments 0..3 (each input array at least
// max_n + 4 long and len long for the reference call), outputs placed
// between sentinels at odd and even offsets: every call writes exactly its n
// outputs, each equal to that of one call over the whole arrays.
inline void CheckCountsAndSentinels(const float* const* in, size_t len, size_t max_n, int n_out,
                                    const BatchCall& call, int n_in = 8) {
  constexpr int kMaxIn = 16, kMaxOut = 5;
  ASSERT_LE(n_in, kMaxIn);
  ASSERT_LE(n_out, kMaxOut);
  std::vector<std::vector<float>> full(n_out, std::vector<float>(len));
  float* full_ptr[kMaxOut];
  for (int k = 0; k < n_out; ++k) full_ptr[k] = full[k].data();
  call(in, full_ptr, len);
  const float kSentinel = -12345.0f;
  for (size_t misalign = 0; misalign < 4; ++misalign) {
    for (size_t n = 0; n <= max_n; ++n) {
      const float* in_o[kMaxIn];
      for (int k = 0; k < n_in; ++k) in_o[k] = in[k] + misalign;
      std::vector<std::vector<float>> out(n_out, std::vector<float>(n + 8, kSentinel));
      float* dst[kMaxOut];
      for (int k = 0; k < n_out; ++k) dst[k] = out[k].data() + 1 + misalign % 2;
      call(in_o, dst, n);
      for (int k = 0; k < n_out; ++k) {
        for (size_t i = 0; i < n; ++i) {
          const float want = full[k][i + misalign];
          if (std::isnan(want)) {
            ASSERT_TRUE(std::isnan(dst[k][i])) << n << " " << i;
          } else {
            ASSERT_EQ(dst[k][i], want) << "output " << k << " n " << n << " " << i;
          }
        }
        for (float* s = out[k].data(); s < dst[k]; ++s) ASSERT_EQ(*s, kSentinel);
        for (float* s = dst[k] + n; s < out[k].data() + out[k].size(); ++s) {
          ASSERT_EQ(*s, kSentinel) << "output " << k << " n " << n;
        }
      }
    }
  }
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_SIMD_TEST_UTIL_H_
