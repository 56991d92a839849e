// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// More batch kernels (see batch.h for the conventions: structure of arrays,
// float lanes, no Highway type here, one dispatch per call): Fresnel
// reflectance, GGX sampling and its densities, and the ellipsoid NDF of
// seed 000. The kernels are in src/simd/fresnel-inl.h, ggx_sampling-inl.h
// and ellipsoid-inl.h, with their error bounds; the scalar references in
// fresnel.h, ggx.h and ellipsoid.h. Directions and normals are unit vectors
// in the shading frame (n = +z); outputs may not alias inputs.

#ifndef BRDFBAKE_BATCH_EXTRA_H_
#define BRDFBAKE_BATCH_EXTRA_H_

#include <cstddef>

#include "brdfbake/batch.h"
#include "brdfbake/brdf.h"

namespace brdfbake {

// FresnelDielectric(eta, cos_i[j]) for n cosines (clamped to [0, 1]);
// eta = n_t / n_i in [0.01, 100].
void FresnelDielectricBatch(float eta, const float* cos_i, float* out, size_t n);
// FresnelConductor(eta_re, eta_im, cos_i[j]), complex eta = eta_re + i eta_im.
void FresnelConductorBatch(float eta_re, float eta_im, const float* cos_i, float* out,
                           size_t n);

// GGX visible normals (seed 003 Listing 1) for n views wo and uniform pairs
// (u1, u2) in [0, 1]^2, written to m_x, m_y, m_z; views with wo.z <= 0 give
// m = (0, 0, 0). Uses alpha_x, alpha_y of p.
void GgxSampleVisibleBatch(const GgxBatchParams& p, const float* wo_x, const float* wo_y,
                           const float* wo_z, const float* u1, const float* u2, float* m_x,
                           float* m_y, float* m_z, size_t n);
// Density of GgxSampleVisibleBatch, G1(wo) max(0, wo.m) D(m) / wo.z.
void GgxPdfVisibleBatch(const GgxBatchParams& p, const float* wo_x, const float* wo_y,
                        const float* wo_z, const float* m_x, const float* m_y, const float* m_z,
                        float* out, size_t n);
// GGX normals with density D(m) m.z (slope_ndf.h SampleNdf: phi = 2 pi u1,
// radial CDF inverted at u2).
void GgxSampleNdfBatch(const GgxBatchParams& p, const float* u1, const float* u2, float* m_x,
                       float* m_y, float* m_z, size_t n);
// Density of GgxSampleNdfBatch, D(m) m.z.
void GgxPdfNdfBatch(const GgxBatchParams& p, const float* m_x, const float* m_y,
                    const float* m_z, float* out, size_t n);

// The ellipsoid NDF of ellipsoid.h: A = diag(alpha_x, alpha_y, 1)
// Rx(theta_x) Ry(theta_y) Rz(theta_z), angles in radians.
struct EllipsoidBatchParams {
  float alpha_x = 0.25f, alpha_y = 0.25f;  // clamped below at 1e-4
  float theta_x = 0, theta_y = 0, theta_z = 0;
  float f0 = 1.0f;  // Schlick F0 of EllipsoidBrdfBatch; 1 means F = 1
  Masking masking = Masking::kHeightCorrelated;
  BatchFresnel fresnel = BatchFresnel::kSchlick;  // see batch.h
  float eta = 1.5f, k = 0.0f;
};

// D(m) (zero for m.z <= 0).
void EllipsoidDBatch(const EllipsoidBatchParams& p, const float* m_x, const float* m_y,
                     const float* m_z, float* out, size_t n);
// Lambda(w) = 1 / G1(w) - 1 (+inf for w.z <= 0).
void EllipsoidLambdaBatch(const EllipsoidBatchParams& p, const float* w_x, const float* w_y,
                          const float* w_z, float* out, size_t n);
// G1(w) (zero for w.z <= 0).
void EllipsoidG1Batch(const EllipsoidBatchParams& p, const float* w_x, const float* w_y,
                      const float* w_z, float* out, size_t n);
// f(wi, wo) with the Fresnel of p (batch.h) at wo.h and p.masking; zero unless both are above
// the horizon.
// G2 of the reflection pairs (wi, wo) with p.masking (0 when either direction
// is on or below the horizon).
void EllipsoidG2Batch(const EllipsoidBatchParams& p, const float* wi_x, const float* wi_y,
                      const float* wi_z, const float* wo_x, const float* wo_y,
                      const float* wo_z, float* out, size_t n);
void EllipsoidBrdfBatch(const EllipsoidBatchParams& p, const float* wi_x, const float* wi_y,
                        const float* wi_z, const float* wo_x, const float* wo_y,
                        const float* wo_z, float* out, size_t n);
// Visible normals, seed 000 section 4 Version 3 (m = 0 for wo.z <= 0).
void EllipsoidSampleVisibleBatch(const EllipsoidBatchParams& p, const float* wo_x,
                                 const float* wo_y, const float* wo_z, const float* u1,
                                 const float* u2, float* m_x, float* m_y, float* m_z, size_t n);
// Density of EllipsoidSampleVisibleBatch (seed 000 eq. 30).
void EllipsoidPdfVisibleBatch(const EllipsoidBatchParams& p, const float* wo_x,
                              const float* wo_y, const float* wo_z, const float* m_x,
                              const float* m_y, const float* m_z, float* out, size_t n);

// The squared ellipsoidal lobe of sel.h: Q = Rx(theta_x) Ry(theta_y)
// Rz(theta_z), angles in radians, alphas clamped below at 1e-4.
struct SelBatchParams {
  float alpha_x = 0.25f, alpha_y = 0.25f;
  float theta_x = 0, theta_y = 0, theta_z = 0;
};
// K(w) (SelLobe::K) for n unit directions.
void SelKBatch(const SelBatchParams& p, const float* w_x, const float* w_y, const float* w_z,
               float* out, size_t n);

}  // namespace brdfbake

#endif  // BRDFBAKE_BATCH_EXTRA_H_
