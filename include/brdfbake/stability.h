// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// `brdfbake stability`: region by region over the documented domain, the
// largest error of each float kernel (the float instantiation of the scalar
// reference, and the SIMD kernels where they exist) against the double
// reference, and the count of non-finite outputs.

#ifndef BRDFBAKE_STABILITY_H_
#define BRDFBAKE_STABILITY_H_

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace brdfbake {

struct StabilityRow {
  std::string region, model, quantity, kernel;
  int64_t samples = 0, non_finite = 0;
  double max_rel_error = 0;
  // The largest ratio of a sample's error to that sample's stated bound:
  // <= 1 means every sample is within its bound. The SIMD kernels' bounds
  // are those of include/brdfbake/models/kernel_bounds.h (which depend on the
  // input: the exponent of Beckmann / STD, the condition of the ellipsoid's
  // matrix products); the float instantiation of the scalar reference is
  // bounded by 1e-4 relative (see src/analysis/stability.cc).
  double max_error_over_bound = 0;
  bool Within() const { return non_finite == 0 && max_error_over_bound <= 1; }
};

// Error metric: |float - double| / max(|double|, 1e-30) for D, G1 and the
// BRDF; for Lambda the relative error of 1 + Lambda (what G1 and G2 use).
// The double reference is evaluated at the float-rounded inputs. Where the
// SIMD batch calls flush a subnormal exponential factor to zero (exponent
// above 87) a zero output counts as exact.
std::vector<StabilityRow> RunStability(int samples_per_region, uint64_t seed);
void WriteStabilityCsv(const std::vector<StabilityRow>& rows, std::ostream& out);

}  // namespace brdfbake

#endif  // BRDFBAKE_STABILITY_H_
