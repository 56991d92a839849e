// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A family's part of the stability study (brdfbake/stability.h): at one
// sample, the double reference its float kernels are measured against and
// their stated bounds there. A family with one defines it in its
// dispatch file (src/kernels/batch_<family>.cc) and names it in its row
// (model_row.h); src/analysis/stability.cc draws the samples, runs the
// SIMD kernels and keeps the statistics.

#ifndef BRDFBAKE_SRC_KERNELS_STABILITY_PROBE_H_
#define BRDFBAKE_SRC_KERNELS_STABILITY_PROBE_H_

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

struct ModelParams;

// Indices of the quantities of StabilitySample's arrays.
enum StabilityQuantity { kStabilityD, kStabilityLambda, kStabilityG1, kStabilityBrdf };

struct StabilitySample {
  // The SIMD kernels of D(m), Lambda(a) and the BRDF (a, b), at the
  // float-rounded directions and parameters: the double reference there
  // (ref[kStabilityD], ref[kStabilityLambda], ref[kStabilityBrdf]), the
  // kernel's stated relative bound at this sample
  // (include/brdfbake/models/kernel_bounds.h), and whether its exponent is
  // past the float range (the batch flushes the factor: only finiteness
  // is checked).
  double ref[4] = {0, 0, 0, 0};
  double bound[4] = {0, 0, 0, 0};
  bool flush[4] = {false, false, false, false};
  // The float instantiation of the scalar reference at the drawn
  // parameters (float_value) and the double one (double_value), both at
  // the float-rounded directions: D, Lambda, G1 and the BRDF.
  double float_value[4] = {0, 0, 0, 0};
  double double_value[4] = {0, 0, 0, 0};
};

// A family's probe: `p` the drawn parameters (alpha_x, alpha_y, gamma and
// the angles; its kind is the row's), m, a and b the drawn directions
// (unrounded).
using StabilityProbeFn = void (*)(const ModelParams& p, const Vec3<double>& m, const Vec3<double>& a,
                                  const Vec3<double>& b, StabilitySample* out);

// The float-rounded copy of a direction, built from float values that went
// through memory: with GCC 12 at -O2 a Vec3<float> constructed from a
// Vec3<double> was seen to keep its double values (printed (double) of the
// float members had 52-bit mantissas), so the "float" path ran on unrounded
// inputs and the comparison measured the inputs' rounding instead of the
// arithmetic.
inline Vec3<float> RoundToFloat(const Vec3<double>& v) {
  volatile float c[3] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
  return Vec3<float>(c[0], c[1], c[2]);
}

// The float instantiation `nf` of the scalar reference and its double
// twin `nd` at the float-rounded m, a and b.
template <class NdfD, class NdfF>
void ProbeFloatReference(const NdfD& nd, const NdfF& nf, const Vec3<double>& m, const Vec3<double>& a,
                         const Vec3<double>& b, StabilitySample* out) {
  const Vec3<float> af = RoundToFloat(a), bf = RoundToFloat(b), mf = RoundToFloat(m);
  const Vec3<double> ad(af), bd(bf), md(mf);
  out->float_value[kStabilityD] = nf.D(mf);
  out->float_value[kStabilityLambda] = nf.Lambda(af);
  out->float_value[kStabilityG1] = nf.G1(af);
  out->float_value[kStabilityBrdf] = Brdf(nf, Fresnel::One(), af, bf, Masking::kHeightCorrelated);
  out->double_value[kStabilityD] = nd.D(md);
  out->double_value[kStabilityLambda] = nd.Lambda(ad);
  out->double_value[kStabilityG1] = nd.G1(ad);
  out->double_value[kStabilityBrdf] = Brdf(nd, Fresnel::One(), ad, bd, Masking::kHeightCorrelated);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_STABILITY_PROBE_H_
