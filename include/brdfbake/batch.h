// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Batch evaluation with SIMD kernels (Highway, dynamic dispatch over the x86
// targets compiled in). Structure of arrays, float lanes; no Highway type in
// this interface. Each batch function dispatches once per call.

#ifndef BRDFBAKE_BATCH_H_
#define BRDFBAKE_BATCH_H_

#include <cstddef>
#include <string>
#include <vector>

#include "brdfbake/brdf.h"

namespace brdfbake {

// The Fresnel factor of every BRDF batch kernel, evaluated at wo.h for one
// colour channel: Schlick with F0 (`f0`; F0 = 1 gives F = 1), a dielectric
// of relative index `eta`, or a conductor of complex index `eta` + i `k`
// (the twins of Fresnel::Schlick / Dielectric / Conductor in fresnel.h).
enum class BatchFresnel { kSchlick, kDielectric, kConductor };

struct GgxBatchParams {
  float alpha_x = 0.25f, alpha_y = 0.25f;  // clamped below at 1e-4
  float f0 = 1.0f;                         // Schlick F0; 1 means F = 1
  Masking masking = Masking::kHeightCorrelated;
  BatchFresnel fresnel = BatchFresnel::kSchlick;
  float eta = 1.5f, k = 0.0f;  // dielectric eta, or conductor eta + i k
};

// f(wi, wo) of anisotropic GGX with the Fresnel of `p`, for n pairs of unit
// directions given as separate x, y, z arrays. Zero when either direction is
// on or below the horizon.
void GgxBrdfBatch(const GgxBatchParams& p, const float* wi_x, const float* wi_y,
                  const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                  float* out, size_t n);
// D(m) for n unit normals (zero for m.z <= 0).
void GgxDBatch(const GgxBatchParams& p, const float* m_x, const float* m_y, const float* m_z,
               float* out, size_t n);
// Lambda(w) for n unit directions (+inf for w.z <= 0).
void GgxLambdaBatch(const GgxBatchParams& p, const float* w_x, const float* w_y,
                    const float* w_z, float* out, size_t n);
// Smith G1(w) = 1 / (1 + Lambda(w)) (0 on and below the horizon), and G2 of
// the reflection pairs (wi, wo) with p.masking (0 when either direction is on
// or below the horizon).
void GgxG1Batch(const GgxBatchParams& p, const float* w_x, const float* w_y, const float* w_z,
                float* out, size_t n);
void GgxG2Batch(const GgxBatchParams& p, const float* wi_x, const float* wi_y,
                const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                float* out, size_t n);

// The Highway target the batch functions dispatch to right now (e.g. AVX3).
std::string BatchTarget();
// Restricts dynamic dispatch to the named target (AVX3, AVX2, SSE4, ...,
// or "best" to undo). Throws std::invalid_argument naming the target if it
// was not compiled in or this CPU lacks it.
void ForceTarget(const std::string& name);
// Every target that is compiled in and runs on this CPU, best first.
std::vector<std::string> AvailableTargets();

}  // namespace brdfbake

#endif  // BRDFBAKE_BATCH_H_
