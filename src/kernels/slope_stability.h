// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The stability probe (stability_probe.h) of the slope-space NDFs that
// share the STD's kernels: Beckmann (gamma = inf) and the STD.

#ifndef BRDFBAKE_SRC_KERNELS_SLOPE_STABILITY_H_
#define BRDFBAKE_SRC_KERNELS_SLOPE_STABILITY_H_

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfbake/model.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/models/std_ndf.h"
#include "kernels/stability_probe.h"

namespace brdfbake {

// The SIMD kernels' reference and bounds at one sample, for Beckmann
// (`beckmann`) or the STD at p.gamma (float-rounded, as the kernel takes
// it). Their bounds grow with the exponent E of the exponential factor
// (kernel_bounds.h): E = r2 for Beckmann, gamma log1p(r2 / (gamma - 1))
// for the STD, r2 the squared unit-roughness slope.
inline void ProbeSlopeKernels(bool beckmann, const ModelParams& p, const Vec3<double>& m_in,
                              const Vec3<double>& a_in, const Vec3<double>& b_in, StabilitySample* out) {
  const Vec3<double> m(RoundToFloat(m_in)), a(RoundToFloat(a_in)), b(RoundToFloat(b_in));
  const float ax = static_cast<float>(p.alpha_x), ay = static_cast<float>(p.alpha_y);
  const double gamma = beckmann ? std::numeric_limits<double>::infinity()
                                : static_cast<double>(static_cast<float>(p.gamma));
  const double slope = beckmann ? bounds::kBeckmannExpSlope : bounds::kStudentTExpSlope;
  const double brdf_slope = beckmann ? bounds::kBeckmannBrdfExpSlope : bounds::kStudentTExpSlope;
  const StudentTNdf<double> nd(ax, ay, gamma);  // gamma = inf is Beckmann
  auto exponent = [&](const Vec3<double>& n) {
    const double sx = n.x / ax, sy = n.y / ay;
    const double r2 = (sx * sx + sy * sy) / (n.z * n.z);
    return beckmann ? r2 : gamma * std::log1p(r2 / (gamma - 1));
  };
  Vec3<double> h(0, 0, 1);
  HalfVector(a, b, &h);
  const double e_m = exponent(m), e_h = exponent(h);
  const double lref = nd.Lambda(a);
  // a = cot(theta) / alpha of a, the argument of the STD's Lambda.
  const double px = ax * a.x, py = ay * a.y;
  const double arg = a.z / std::sqrt(std::max(px * px + py * py, 1e-300));
  out->ref[kStabilityD] = nd.D(m);
  out->ref[kStabilityLambda] = lref;
  out->ref[kStabilityBrdf] = Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated);
  out->bound[kStabilityD] = bounds::SlopeD(e_m, slope);
  out->bound[kStabilityLambda] = std::isinf(lref) ? 1.0 : bounds::SlopeLambdaAbs(arg, lref) / (1 + lref);
  out->bound[kStabilityBrdf] = bounds::SlopeBrdf(e_h, brdf_slope);
  out->flush[kStabilityD] = e_m > bounds::kFlushExponent;
  out->flush[kStabilityBrdf] = e_h > bounds::kFlushExponent;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_SLOPE_STABILITY_H_
