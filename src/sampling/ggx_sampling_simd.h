// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators of sampling_integrators.h (randomized QMC, MC,
// the engine setting) with their samples in double SIMD lanes: the same
// point sets, drawn in the same order, and per point the model's sampler
// and weight in lanes; each replica's sum is accumulated in lanes
// (sampling_simd-inl.h). This file: GGX's samplers
// (kernels/ggx_sampling-inl.h). Agrees with the scalar reference within 8e-15 per
// texel on every target (tests/sampling/sampling_simd_test.cc).
// Dispatched once per texel to the best Highway target (or the one
// ForceTarget chose). A family's table row finds its overloads by the
// NDF's type (TexelFor, bake/texel_for.h).

#ifndef BRDFBAKE_SRC_SAMPLING_GGX_SAMPLING_SIMD_H_
#define BRDFBAKE_SRC_SAMPLING_GGX_SAMPLING_SIMD_H_

#include <cstdint>

#include "brdfbake/estimate.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

// QmcTexel (QMC, or MC with plain_mc) with GGX's visible-normal sampler in
// lanes.
TexelEstimate SimdQmcTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc);

// EngineRule with NDF sampling of the half vector in lanes.
QuadratureResult SimdEngineRule(const GgxNdf<double>& ndf, double mu, Masking masking, int samples);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_GGX_SAMPLING_SIMD_H_
