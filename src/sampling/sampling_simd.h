// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators of sampling_integrators.h (randomized QMC, MC,
// the engine setting) with their samples in double SIMD lanes: the same
// point sets, drawn in the same order, and per point the model's sampler
// and weight in lanes (kernels/ggx_sampling-inl.h, beckmann_sampling-inl.h,
// the double Lambda kernels, and the NDF samplers and the STD's D in
// sampling_simd.cc); each replica's sum is accumulated in lanes. Agrees
// with the scalar reference within 8e-15 per texel on every target
// (tests/sampling/sampling_simd_test.cc). Dispatched once per
// texel to the best Highway target (or the one ForceTarget chose).

#ifndef BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_H_
#define BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_H_

#include <cstdint>

#include "brdfbake/estimate.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

// QmcTexel (QMC, or MC with plain_mc) with the model's visible-normal
// sampler in lanes.
TexelEstimate SimdQmcTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);
#if BRDFBAKE_WITH_BECKMANN
TexelEstimate SimdQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);
#endif
#if BRDFBAKE_WITH_STD
// With the pseudo visible-normal sampler of [Ribardiere17] Algorithm 1.
TexelEstimate SimdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);
#endif

// EngineRule with NDF sampling of the half vector in lanes.
QuadratureResult SimdEngineRule(const GgxNdf<double>& ndf, double mu, Masking masking, int samples);
#if BRDFBAKE_WITH_BECKMANN
QuadratureResult SimdEngineRule(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                                int samples);
#endif
#if BRDFBAKE_WITH_STD
QuadratureResult SimdEngineRule(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                int samples);
#endif

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_H_
