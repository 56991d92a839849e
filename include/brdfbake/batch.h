// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Batch evaluation with the SIMD kernels (Highway, dynamic dispatch over the
// x86 targets compiled in; targets.h picks one). One model descriptor, one
// quantity, one entry point per input shape: each call dispatches once, then
// runs one branch-free loop. Structure of arrays, float lanes, no Highway
// type here. Directions and normals are unit vectors in the shading frame
// (n = +z); outputs may not alias inputs. The kernels and their error bounds
// are in src/kernels/*-inl.h (bounds in kernel_bounds.h), the double scalar
// references in ggx.h, beckmann.h, std_ndf.h, ellipsoid.h and sel.h.

#ifndef BRDFBAKE_BATCH_H_
#define BRDFBAKE_BATCH_H_

#include <cstddef>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/fresnel.h"

namespace brdfbake {

// The Fresnel factor of the BRDF, evaluated at wo.h for one colour channel:
// Schlick with F0 (`f0`; F0 = 1 gives F = 1), a dielectric of relative
// index `eta`, or a conductor of complex index `eta` + i `k` (the twins of
// Fresnel::Schlick / Dielectric / Conductor in fresnel.h).
enum class BatchFresnel { kSchlick, kDielectric, kConductor };

// A model as the batch kernels take it. Every call checks it once, before
// any output is written, and throws std::invalid_argument naming the call
// and the field outside its domain (docs/kernels.md):
//   alpha_x, alpha_y  (0, 1e4]; below 1e-4 evaluated at 1e-4
//   gamma (std)       [1.5 + 1e-6, inf] (the mean slope diverges at 1.5; as
//                     a float, 1.5000011f is the smallest accepted), from
//                     1e10 on (and at inf) evaluated as Beckmann
//   theta_* (ellipsoid, sel)  [-pi/2, pi/2] radians: the ellipsoid's
//                     A = S Rx Ry Rz, the sel lobe's frame Q = Rx Ry Rz
//   f0 (Schlick)      [0, 1]
//   eta (dielectric)  [0.01, 100]; conductor eta in [0.01, 100], k in [0, 100]
// NaN is outside every domain. Directions and the sampler's u are not
// checked (per-element checks would cost a pass over the inputs): a
// non-finite one changes only its own element's outputs, to NaN or to the
// value below the horizon.
struct BatchModel {
  ModelKind kind = ModelKind::kGgx;  // ggx, beckmann, std, ellipsoid, sel, charlie, disney-diffuse
  float alpha_x = 0.25f, alpha_y = 0.25f;
  float gamma = 2.0f;
  float theta_x = 0, theta_y = 0, theta_z = 0;
  Masking masking = Masking::kHeightCorrelated;
  BatchFresnel fresnel = BatchFresnel::kSchlick;
  float f0 = 1.0f;             // Schlick F0; 1 means F = 1
  float eta = 1.5f, k = 0.0f;  // dielectric eta, or conductor eta + i k
  // charlie: its visibility (Lambda, G1 and G2 need conty-kulla). charlie
  // and disney-diffuse take alpha_x = alpha_y in (0, 1] and F = 1.
  SheenVisibility visibility = SheenVisibility::kContyKulla;
};

// The descriptor of a model's parameters (in float), with `masking` and
// channel 0 of `fresnel` (the kernels take one channel: a coloured Fresnel
// needs one call per channel).
BatchModel BatchModelOf(const ModelParams& model, Masking masking = Masking::kHeightCorrelated,
                        const Fresnel& fresnel = Fresnel::One());
// The model parameters of a descriptor, in double (the inverse of
// BatchModelOf for the model; masking and Fresnel are left out).
ModelParams ModelParamsOf(const BatchModel& model);

// What a batch call evaluates. The first five take one direction (or
// normal), the rest a pair.
enum class Quantity {
  kD,           // D(m), zero for m.z <= 0
  kLambda,      // Lambda(w), +inf for w.z <= 0
  kG1,          // G1(w), zero for w.z <= 0
  kPdfNdf,      // D(m) max(0, m.z): the density of Sampler::kNdf
  kK,           // the sel lobe K(w)
  kG2,          // G2(wi, wo) with the model's masking; zero unless both are above the horizon
  kBrdf,        // f(wi, wo) with the model's Fresnel at wo.h and its masking
  kPdfVisible,  // the density of Sampler::kVisible at (wo, m)
};

// How SampleBatch draws normals m from uniform (u1, u2) in [0, 1]^2.
enum class Sampler {
  kNdf,      // density D(m) m.z: phi = 2 pi u1, the radial CDF inverted at u2
  kVisible,  // visible normals of wo ([Heitz18] for ggx, exact CDF inversion for
             // beckmann, [Walter15] Version 3 for the ellipsoid, the pseudo-VNIS
             // of [Ribardiere17] Algorithm 1 for std); m = 0 for wo.z <= 0
};

const char* QuantityName(Quantity q);  // D, Lambda, G1, pdf_ndf, K, G2, brdf, pdf_visible
bool IsPairQuantity(Quantity q);       // G2, brdf, pdf_visible
bool BatchSupports(ModelKind kind, Quantity q);
bool BatchSupports(ModelKind kind, Sampler s);
// Whether the model's batch takes a Fresnel factor; a lobe without one
// (charlie, disney-diffuse, sel: F = 1) takes BatchFresnel::kSchlick with
// f0 = 1 only.
bool BatchTakesFresnel(ModelKind kind);

// n unit vectors as three arrays.
struct DirArrays {
  const float* x;
  const float* y;
  const float* z;
};
struct DirOutArrays {
  float* x;
  float* y;
  float* z;
};

// Per-element parameters, for a batch of mixed materials in one call: the
// arrays hold n values each, and a null array takes the BatchModel's value
// for every element. alpha_y null with alpha_x given means isotropic
// (alpha_y[j] = alpha_x[j]); f0 is Schlick's F0 (with BatchFresnel::kSchlick).
// Every element is checked against the domain above before any output is
// written; the error names the first element outside it. ggx and beckmann
// take them (BatchSupportsElements); the other models take one set of
// parameters per call.
struct BatchElements {
  const float* alpha_x = nullptr;
  const float* alpha_y = nullptr;
  const float* f0 = nullptr;
};
bool BatchSupportsElements(ModelKind kind);

// out[j] = q(w[j]) for a one-direction quantity, or q(a[j], b[j]) for a
// pair: (wi, wo) for G2 and brdf, (wo, m) for pdf_visible. A model that
// does not define q, a model left out of this build, or the wrong shape
// throws std::invalid_argument before any output is written.
void EvalBatch(const BatchModel& model, Quantity q, DirArrays w, float* out, size_t n);
void EvalBatch(const BatchModel& model, Quantity q, DirArrays a, DirArrays b, float* out, size_t n);
// m[j] drawn by sampler s from (u1[j], u2[j]); wo is read by kVisible only.
void SampleBatch(const BatchModel& model, Sampler s, DirArrays wo, const float* u1, const float* u2,
                 DirOutArrays m, size_t n);

// The same with per-element parameters.
void EvalBatch(const BatchModel& model, const BatchElements& elements, Quantity q, DirArrays w,
               float* out, size_t n);
void EvalBatch(const BatchModel& model, const BatchElements& elements, Quantity q, DirArrays a,
               DirArrays b, float* out, size_t n);
void SampleBatch(const BatchModel& model, const BatchElements& elements, Sampler s, DirArrays wo,
                 const float* u1, const float* u2, DirOutArrays m, size_t n);

// Light directions as a path tracer consumes them: wi[j] reflects wo[j]
// about a visible normal m drawn from (u1[j], u2[j]), with
//   pdf[j]    = pdf_visible(wo, m) / (4 wo.m), the density of wi in solid angle;
//   weight[j] = f(wi, wo) wi.z / pdf, the sample's estimate of the albedo
//               (F G2 / G1(wo) for ggx, beckmann and the ellipsoid),
//               0 where wi is on or below the horizon.
// For wo.z <= 0: wi = 0, weight = 0, pdf = 0; where the sampled normal's
// density underflows float (Beckmann's far tail, u at the ends of [0, 1]),
// pdf = 0 and weight = 0: no sample. Models with a visible-normal sampler
// (BatchSupports(kind, Sampler::kVisible)).
struct LightSampleArrays {
  float* x;
  float* y;
  float* z;
  float* weight;
  float* pdf;
};
void SampleLightBatch(const BatchModel& model, DirArrays wo, const float* u1, const float* u2,
                      LightSampleArrays wi, size_t n);
void SampleLightBatch(const BatchModel& model, const BatchElements& elements, DirArrays wo,
                      const float* u1, const float* u2, LightSampleArrays wi, size_t n);

// The rough dielectric BSDF of [Walter07] (models/dielectric.h,
// RoughDielectric: index 1 above the surface, eta below; wi and wo anywhere
// on the sphere) over GGX or Beckmann. Checked like BatchModel, before any
// output is written (std::invalid_argument naming the field):
//   ndf               ModelKind::kGgx or kBeckmann (kBeckmann needs the
//                     beckmann family in the build, glass needs glass)
//   alpha_x, alpha_y  (0, 1e4]; below 1e-4 evaluated at 1e-4
//   eta               [0.01, 100]; eta = 1 (no interface) gives f = 0
struct BatchDielectric {
  ModelKind ndf = ModelKind::kGgx;
  float alpha_x = 0.25f, alpha_y = 0.25f;
  float eta = 1.5f;
  Masking masking = Masking::kHeightCorrelated;
  DielectricTransport transport = DielectricTransport::kRadiance;
};
enum class DielectricQuantity {
  kBsdf,     // f(wi, wo): reflection on one side, refraction across
  kBsdfCos,  // f(wi, wo) |wi.n|, the integrand of the albedo E(wo)
};
// out[j] = q(wi[j], wo[j]) for n pairs, in float lanes (the error bounds
// are in src/kernels/dielectric-inl.h).
void DielectricBsdfBatch(const BatchDielectric& model, DielectricQuantity q, DirArrays wi,
                         DirArrays wo, float* out, size_t n);

// FresnelDielectric(eta, cos_i[j]) for n cosines (clamped to [0, 1]);
// eta = n_t / n_i in [0.01, 100].
void FresnelDielectricBatch(float eta, const float* cos_i, float* out, size_t n);
// FresnelConductor(eta_re, eta_im, cos_i[j]), complex eta = eta_re + i eta_im.
void FresnelConductorBatch(float eta_re, float eta_im, const float* cos_i, float* out, size_t n);

}  // namespace brdfbake

#endif  // BRDFBAKE_BATCH_H_
