// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Batch visible-normal sampling of Beckmann (exact, by inversion of the
// visible-slope CDF) and of STD (the pseudo-VNIS of seed 004 Algorithm 1),
// with their densities, by SIMD kernels (Highway, dynamic dispatch, one
// dispatch per call; see batch.h). Structure of arrays, float lanes, no
// Highway type here. Each call runs with subnormals flushed to zero, as the
// calls of batch_beckmann_std.h do. For the same (u1, u2) the samplers return
// the normal of the scalar BeckmannNdf::SampleVisible and
// StudentTNdf::SamplePseudoVnis; the kernels and their error bounds are in
// src/simd/beckmann_sampling-inl.h and std_sampling-inl.h. Directions and
// normals are unit vectors in the shading frame (n = +z); views with
// wo.z <= 0 give m = (0, 0, 0); outputs may not alias inputs.

#ifndef BRDFBAKE_BATCH_SAMPLING_H_
#define BRDFBAKE_BATCH_SAMPLING_H_

#include <cstddef>

#include "brdfbake/batch_beckmann_std.h"

namespace brdfbake {

// Beckmann visible normals for n views wo and uniform pairs (u1, u2) in
// [0, 1]^2, written to m_x, m_y, m_z. Uses alpha_x, alpha_y of p.
void BeckmannSampleVisibleBatch(const BeckmannBatchParams& p, const float* wo_x,
                                const float* wo_y, const float* wo_z, const float* u1,
                                const float* u2, float* m_x, float* m_y, float* m_z, size_t n);
// Density of BeckmannSampleVisibleBatch, G1(wo) max(0, wo.m) D(m) / wo.z.
void BeckmannPdfVisibleBatch(const BeckmannBatchParams& p, const float* wo_x, const float* wo_y,
                             const float* wo_z, const float* m_x, const float* m_y,
                             const float* m_z, float* out, size_t n);

// STD pseudo-VNIS: the proposal of StudentTNdf::PseudoVnisBranch() for
// (alpha_x, alpha_y, gamma) of p (NDF sampling, GGX or Beckmann visible
// normals), for n views and uniform pairs.
void StudentTSamplePseudoVnisBatch(const StudentTBatchParams& p, const float* wo_x,
                                   const float* wo_y, const float* wo_z, const float* u1,
                                   const float* u2, float* m_x, float* m_y, float* m_z, size_t n);
// Density of StudentTSamplePseudoVnisBatch (the proposal's, see std_ndf.h).
void StudentTPdfPseudoVnisBatch(const StudentTBatchParams& p, const float* wo_x, const float* wo_y,
                           const float* wo_z, const float* m_x, const float* m_y,
                           const float* m_z, float* out, size_t n);

}  // namespace brdfbake

#endif  // BRDFBAKE_BATCH_SAMPLING_H_
