// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// One texel of a lobe's E by a sampling integrator over the lobe's own
// sampler (charlie, disney-diffuse: sampling_integrators.h, double scalar
// code), the engine setting's error measured against the quadrature.

#ifndef BRDFBAKE_SRC_BAKE_FAMILIES_LOBE_TEXEL_H_
#define BRDFBAKE_SRC_BAKE_FAMILIES_LOBE_TEXEL_H_

#include <cmath>
#include <cstdint>
#include <limits>

#include "brdfbake/bake.h"
#include "sampling/sampling_integrators.h"

namespace brdfbake {

// `sum` is the lobe's sampled sum, `quadrature(spec)` its E by the
// quadrature at the texel under `spec`.
template <class Sum, class Quadrature>
TexelEstimate SampledLobeTexel(const BakeSpec& spec, const Sum& sum, const Quadrature& quadrature,
                               uint64_t texel_seed) {
  const int n = spec.EffectiveSamples();
  TexelEstimate v;
  if (spec.integrator != IntegratorKind::kEngine) {
    v = QmcTexelWith(n, texel_seed, spec.integrator == IntegratorKind::kMc, sum);
  } else {
    v.e = EngineRuleWith(n, sum).e;
    v.err_e = std::numeric_limits<double>::infinity();
    if (spec.estimate_error) {
      BakeSpec ref = spec;
      ref.integrator = IntegratorKind::kQuadrature;
      ref.tolerance = 1e-10;
      ref.samples = 0;
      const TexelEstimate q = quadrature(ref);
      v.err_e = std::abs(v.e - q.e) + q.err_e;
    }
  }
  v.scale = v.bias = v.err_scale = v.err_bias = 0;
  return v;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BAKE_FAMILIES_LOBE_TEXEL_H_
