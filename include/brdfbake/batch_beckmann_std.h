// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Batch evaluation of the Beckmann and STD (Student's t slopes) models with
// SIMD kernels (Highway, dynamic dispatch, see batch.h). Structure of arrays,
// float lanes; no Highway type in this interface. Each batch function
// dispatches once per call and runs with subnormals flushed to zero (the
// caller's floating-point mode is restored on return): results below FLT_MIN,
// or whose exponential factor exp(-r2) or exp(-a^2) is, are 0. The error
// bounds of the kernels are documented in src/simd/beckmann-inl.h and
// src/simd/std-inl.h.

#ifndef BRDFBAKE_BATCH_BECKMANN_STD_H_
#define BRDFBAKE_BATCH_BECKMANN_STD_H_

#include <cstddef>

#include "brdfbake/batch.h"
#include "brdfbake/brdf.h"

namespace brdfbake {

struct BeckmannBatchParams {
  float alpha_x = 0.25f, alpha_y = 0.25f;  // clamped below at 1e-4
  float f0 = 1.0f;                         // Schlick F0; 1 means F = 1
  Masking masking = Masking::kHeightCorrelated;
  BatchFresnel fresnel = BatchFresnel::kSchlick;  // see batch.h
  float eta = 1.5f, k = 0.0f;
};

struct StudentTBatchParams {
  float alpha_x = 0.25f, alpha_y = 0.25f;  // the seed's sigma_x, sigma_y; clamped below at 1e-4
  float gamma = 2.0f;  // clamped below at 1.5 + 1e-6; +inf (and >= 1e10) is Beckmann
  float f0 = 1.0f;     // Schlick F0; 1 means F = 1
  Masking masking = Masking::kHeightCorrelated;
  BatchFresnel fresnel = BatchFresnel::kSchlick;  // see batch.h
  float eta = 1.5f, k = 0.0f;
};

// f(wi, wo) with the Fresnel of p (batch.h) for n pairs of unit directions given as
// separate x, y, z arrays. Zero when either direction is on or below the
// horizon.
void BeckmannBrdfBatch(const BeckmannBatchParams& p, const float* wi_x, const float* wi_y,
                       const float* wi_z, const float* wo_x, const float* wo_y,
                       const float* wo_z, float* out, size_t n);
// D(m) for n unit normals (zero for m.z <= 0).
void BeckmannDBatch(const BeckmannBatchParams& p, const float* m_x, const float* m_y,
                    const float* m_z, float* out, size_t n);
// Lambda(w) for n unit directions (+inf for w.z <= 0).
void BeckmannLambdaBatch(const BeckmannBatchParams& p, const float* w_x, const float* w_y,
                         const float* w_z, float* out, size_t n);
// NDF sampling: for each (u1[i], u2[i]) in [0, 1)^2 the normal m that
// BeckmannNdf::SampleNdf(u1, u2) returns (density D(m) m.z).
void BeckmannSampleNdfBatch(const BeckmannBatchParams& p, const float* u1, const float* u2,
                            float* m_x, float* m_y, float* m_z, size_t n);

// Smith G1(w) = 1 / (1 + Lambda(w)) (0 on and below the horizon); G2 of the
// reflection pairs (wi, wo) with p.masking (0 when either direction is on or
// below the horizon); the density D(m) m.z of BeckmannSampleNdfBatch.
void BeckmannG1Batch(const BeckmannBatchParams& p, const float* w_x, const float* w_y,
                     const float* w_z, float* out, size_t n);
void BeckmannG2Batch(const BeckmannBatchParams& p, const float* wi_x, const float* wi_y,
                     const float* wi_z, const float* wo_x, const float* wo_y,
                     const float* wo_z, float* out, size_t n);
void BeckmannPdfNdfBatch(const BeckmannBatchParams& p, const float* m_x, const float* m_y,
                         const float* m_z, float* out, size_t n);

// The same seven for STD.
void StudentTBrdfBatch(const StudentTBatchParams& p, const float* wi_x, const float* wi_y,
                  const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                  float* out, size_t n);
void StudentTDBatch(const StudentTBatchParams& p, const float* m_x, const float* m_y,
                    const float* m_z, float* out, size_t n);
void StudentTLambdaBatch(const StudentTBatchParams& p, const float* w_x, const float* w_y,
                    const float* w_z, float* out, size_t n);
void StudentTSampleNdfBatch(const StudentTBatchParams& p, const float* u1, const float* u2,
                            float* m_x, float* m_y, float* m_z, size_t n);

void StudentTG1Batch(const StudentTBatchParams& p, const float* w_x, const float* w_y,
                     const float* w_z, float* out, size_t n);
void StudentTG2Batch(const StudentTBatchParams& p, const float* wi_x, const float* wi_y,
                const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                float* out, size_t n);
void StudentTPdfNdfBatch(const StudentTBatchParams& p, const float* m_x, const float* m_y,
                    const float* m_z, float* out, size_t n);

}  // namespace brdfbake

#endif  // BRDFBAKE_BATCH_BECKMANN_STD_H_
