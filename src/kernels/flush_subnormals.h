// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Flushes subnormals to zero (MXCSR FTZ and DAZ) for the duration of one
// batch call, and restores the caller's mode on return. The exponential
// factors of the Beckmann and STD kernels (D, Lambda, the samplers' CDFs)
// pass through the subnormal range in many lanes of an ordinary row
// (exp(-a^2) is subnormal for a > 9.3, i.e. mu > 0.92 at alpha = 0.25), and
// x86 handles subnormal operands and results in microcode: with mu uniform
// in (0, 1) and alpha = 0.25 the flush takes the Beckmann BRDF from 11.1 to
// 4.0 ns per element on AVX3 and from 13.7 to 6.5 on AVX2 (GGX: 0.9 and
// 1.3). With it, every result whose exponential factor is below FLT_MIN
// (exponent above 87.3), and every result below FLT_MIN, is 0.

#ifndef BRDFBAKE_SRC_KERNELS_FLUSH_SUBNORMALS_H_
#define BRDFBAKE_SRC_KERNELS_FLUSH_SUBNORMALS_H_

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

namespace brdfbake {

class FlushSubnormals {
 public:
#if defined(__x86_64__) || defined(__i386__)
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
  ~FlushSubnormals() { _mm_setcsr(saved_); }
  FlushSubnormals(const FlushSubnormals&) = delete;
  FlushSubnormals& operator=(const FlushSubnormals&) = delete;

 private:
  unsigned saved_;
#endif
};

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_FLUSH_SUBNORMALS_H_
