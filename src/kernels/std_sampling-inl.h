// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// STD pseudo visible-normal importance sampling ([Ribardiere17] section 7.2,
// Algorithm 1) and its density, float lanes; the scalar twins (double
// reference) are StudentTNdf::SamplePseudoVnis and ::PdfPseudoVnis in
// include/brdfbake/models/std_ndf.h.
//
// Algorithm 1 picks one proposal per material, from sigma = sqrt(alpha_x
// alpha_y) and gamma alone: NDF sampling of the STD itself ([Ribardiere17]
// section 6, eq. 11-12 and 42), the GGX visible normals ([Heitz18]) or the
// Beckmann visible normals, the last two with the STD's alpha_x, alpha_y.
// The choice is a per-call constant, so it is made once per call by the
// scalar StudentTNdf::PseudoVnisBranch (one definition of the thresholds, with
// [Ribardiere17]'s comparisons as std_ndf.h documents them), and every lane runs
// the same existing kernel:
//   branch 0: StudentTSampleNdf (std-inl.h; BeckmannSampleNdf for gamma >= 1e10),
//             density D(m) m.z (StudentTD or BeckmannD);
//   branch 1: GgxSampleVisible and GgxPdfVisible (ggx_sampling-inl.h);
//   branch 2: BeckmannSampleVisible and BeckmannPdfVisible
//             (beckmann_sampling-inl.h).
// The density is the proposal's, not the STD's visible-normal density: the
// Monte Carlo weight is f cos(theta_i) / pdf (std_ndf.h corrects eq. 43).
//
// Error: that of the kernel of the branch (stated in its file), against the
// double reference at the same float inputs: normals within 2e-6 (max
// component) in the unit-roughness configuration for branches 1 and 2, and
// within 2e-6 absolute for branch 0; densities within 2e-6 + 4.5e-7 E
// (branch 0: StudentTD's exponent E; branch 2: 3e-7 r2 instead) plus 2e-7 / (w.m)
// for the visible-normal densities, relative, and 0 where the batch call
// flushes exp(-E) below FLT_MIN. Measured (tests/kernels/simd_std_test.cc,
// gamma from 1.5 to 1e6, 2e10 and +inf, sigma from 1e-4 to 1 and 1000:1, all
// three branches, every target): normals 4.8e-7 (NDF), 3.2e-7 (GGX), 6.4e-7
// (Beckmann); densities at most 0.62 of their bound.
// u in [0, 1]^2, except that the NDF branch takes u2 = 1 as 1 - 2^-24 (as
// SampleBatch with Sampler::kNdf does; the reference takes it as 1 - 2^-53).

#if defined(BRDFBAKE_SRC_KERNELS_STD_SAMPLING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_STD_SAMPLING_INL_H_
#undef BRDFBAKE_SRC_KERNELS_STD_SAMPLING_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_STD_SAMPLING_INL_H_
#endif

#include <hwy/highway.h>

#include "brdfbake/models/std_ndf.h"
#include "kernels/beckmann-inl.h"
#include "kernels/beckmann_sampling-inl.h"
#include "kernels/ggx_sampling-inl.h"
#include "kernels/std-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-call constants: the STD's (with its Beckmann constants, which the
// Beckmann branch and gamma >= 1e10 use), GGX's, and the branch.
template <class D>
struct StudentTSamplingConsts {
  StudentTConsts<D> std;
  GgxSamplingConsts<D> ggx;
  int branch;  // StudentTNdf::PseudoVnisBranch(): 0 NDF, 1 GGX VNDF, 2 Beckmann VNDF
  StudentTSamplingConsts(D d, float ax, float ay, float gamma)
      : std(d, ax, ay, 1.0f, gamma),
        ggx(d, ax, ay),
        branch(StudentTNdf<double>(ax, ay, gamma).PseudoVnisBranch()) {}
};

template <class D, class V>
HWY_INLINE void StudentTSamplePseudoVnis(D d, const StudentTSamplingConsts<D>& c, V wx, V wy, V wz,
                                         V u1, V u2, V* mx, V* my, V* mz) {
  switch (c.branch) {
    case 1:
      GgxSampleVisible(d, c.ggx, wx, wy, wz, u1, u2, mx, my, mz);
      return;
    case 2:
      BeckmannSampleVisible(d, c.std.b, wx, wy, wz, u1, u2, mx, my, mz);
      return;
    default:
      if (c.std.beckmann) {
        BeckmannSampleNdf(d, c.std.b, u1, u2, mx, my, mz);
      } else {
        StudentTSampleNdf(d, c.std, u1, u2, mx, my, mz);
      }
  }
}

template <class D, class V>
HWY_INLINE V StudentTPdfPseudoVnis(D d, const StudentTSamplingConsts<D>& c, V wx, V wy, V wz, V mx,
                                   V my, V mz) {
  switch (c.branch) {
    case 1:
      return GgxPdfVisible(d, c.ggx, wx, wy, wz, mx, my, mz);
    case 2:
      return BeckmannPdfVisible(d, c.std.b, wx, wy, wz, mx, my, mz);
    default: {
      const V dm =
          c.std.beckmann ? BeckmannD(d, c.std.b, mx, my, mz) : StudentTD(d, c.std, mx, my, mz);
      return hn::Mul(dm, hn::Max(mz, hn::Zero(d)));
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_STD_SAMPLING_INL_H_
