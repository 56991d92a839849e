// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators of sampling_integrators.h (randomized QMC, MC,
// the engine setting) with their samples in double SIMD lanes: the same
// point sets, drawn in the same order, and per point the model's sampler
// and weight in lanes; each replica's sum is accumulated in lanes
// (sampling_simd-inl.h). This file: the samplers of
// Beckmann (kernels/beckmann_sampling-inl.h) and the STD (its NDF sampler
// and D in lanes, and its pseudo visible-normal sampler of
// [Ribardiere17] Algorithm 1). Agrees with the scalar reference within 8e-15 per
// texel on every target (tests/sampling/sampling_simd_test.cc).
// Dispatched once per texel to the best Highway target (or the one
// ForceTarget chose). A family's table row finds its overloads by the
// NDF's type (TexelFor, bake/texel_for.h).

#ifndef BRDFBAKE_SRC_SAMPLING_SLOPE_SAMPLING_SIMD_H_
#define BRDFBAKE_SRC_SAMPLING_SLOPE_SAMPLING_SIMD_H_

#include <cstdint>

#include "brdfbake/config.h"
#include "brdfbake/estimate.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/std_ndf.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

#if BRDFBAKE_WITH_BECKMANN
// QmcTexel (QMC, or MC with plain_mc) with Beckmann's visible-normal
// sampler in lanes, and EngineRule with its NDF sampler.
TexelEstimate SimdQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);
QuadratureResult SimdEngineRule(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                                int samples);
#endif
#if BRDFBAKE_WITH_STD
// The same for the STD, with the pseudo visible-normal sampler of
// [Ribardiere17] Algorithm 1.
TexelEstimate SimdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);
QuadratureResult SimdEngineRule(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                int samples);
#endif

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_SLOPE_SAMPLING_SIMD_H_
