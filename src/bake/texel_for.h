// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// One texel of a microfacet NDF's E or dfg table (ggx, beckmann, std:
// src/bake/families/), by the quadrature or a sampling integrator, for the
// NDF at the texel's alpha.

#ifndef BRDFBAKE_SRC_BAKE_TEXEL_FOR_H_
#define BRDFBAKE_SRC_BAKE_TEXEL_FOR_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "bake/family_row.h"
#include "brdfbake/bake.h"
#include "brdfbake/config.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "lanes/ggx_lanes.h"
#include "lanes/slope_lanes.h"
#include "rules/beckmann/beckmann_azimuth.h"
#include "rules/ggx/azimuthal.h"
#include "rules/slope/azimuthal_slope.h"
#include "rules/std/std_azimuth.h"
#include "sampling/sampling_integrators.h"
#include "sampling/ggx_sampling_simd.h"
#include "sampling/slope_sampling_simd.h"

namespace brdfbake {

// The deterministic quadrature: the one-dimensional rules over theta_i of
// azimuthal.h (GGX: E with the azimuth in closed form; dfg with the
// Schlick-weighted azimuth) and azimuthal_slope.h (Beckmann, STD: the
// azimuth numerically). Only E is filled for E and E_avg tables. `spec.simd`
// picks the rules with their azimuthal nodes in double SIMD lanes.
template <class Ndf>
TexelEstimate QuadratureFor(const Ndf& ndf, double mu, const BakeSpec& spec, int max_nodes,
                         double tol) {
  const double m = std::max(mu, kMuMin);
  auto texel = [](const AzimuthalDfgResult& r) {
    TexelEstimate v;
    v.e = r.e;
    v.bias = r.bias;
    v.scale = r.e - r.bias;
    v.err_e = r.err_e;
    v.err_bias = r.err_bias;
    v.err_scale = r.err_scale;
    return v;
  };
  if constexpr (std::is_same_v<Ndf, GgxNdf<double>>) {
    const double a = ndf.alpha_x();
    if (spec.table == TableKind::kDfg) {
      return texel(spec.simd ? SimdGgxAzimuthalDfg(a, m, spec.masking, tol, max_nodes)
                             : GgxAzimuthalDfg(a, m, spec.masking, tol, max_nodes));
    }
    return AlbedoTexel(spec.simd ? SimdGgxAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes)
                                 : GgxAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes));
  } else {
    const bool bias = spec.table == TableKind::kDfg;
    // Beckmann's E (and the STD's at gamma = inf, which is Beckmann) with
    // the azimuth in closed form (beckmann_azimuth.h).
    bool beckmann = std::is_same_v<Ndf, BeckmannNdf<double>>;
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) beckmann = std::isinf(ndf.gamma());
    if (beckmann && !bias) {
      const double a = ndf.alpha_x();
      return AlbedoTexel(spec.simd ? SimdBeckmannAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes)
                                   : BeckmannAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes));
    }
#if BRDFBAKE_WITH_STD
    // The STD's E at finite gamma with the azimuth from tabulated moments
    // (std_azimuth.h).
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) {
      if (!bias) {
        return AlbedoTexel(spec.simd ? SimdStdAzimuthalAlbedo(ndf, m, spec.masking, tol, max_nodes)
                                     : StdAzimuthalAlbedo(ndf, m, spec.masking, tol, max_nodes));
      }
    }
#endif
    return texel(spec.simd ? SimdSlopeAzimuthalDfg(ndf, m, spec.masking, bias, tol, max_nodes)
                           : SlopeAzimuthalDfg(ndf, m, spec.masking, bias, tol, max_nodes));
  }
}

template <class Ndf>
TexelEstimate TexelFor(const Ndf& ndf, double mu, const BakeSpec& spec, uint64_t texel_seed) {
  const int n = spec.EffectiveSamples();
  switch (spec.integrator) {
    case IntegratorKind::kQuadrature:
      return QuadratureFor(ndf, mu, spec, n, spec.tolerance);
    case IntegratorKind::kQmc:
    case IntegratorKind::kMc: {
      const bool plain_mc = spec.integrator == IntegratorKind::kMc;
      if (spec.simd) return SimdQmcTexel(ndf, mu, spec.masking, n, texel_seed, plain_mc);
      return QmcTexel(ndf, mu, spec.masking, n, texel_seed, plain_mc);
    }
    case IntegratorKind::kEngine: {
      const QuadratureResult r = spec.simd ? SimdEngineRule(ndf, mu, spec.masking, n)
                                           : EngineRule(ndf, mu, spec.masking, n);
      if (!spec.estimate_error) {
        TexelEstimate v;
        v.e = r.e;
        v.bias = r.fc;
        v.scale = r.e - r.fc;
        v.err_e = v.err_bias = v.err_scale = std::numeric_limits<double>::infinity();
        return v;
      }
      const TexelEstimate ref = QuadratureFor(ndf, mu, spec, 512, 1e-10);
      TexelEstimate v;
      v.e = r.e;
      v.bias = r.fc;
      v.scale = r.e - r.fc;
      // Measured against the converged quadrature (plus its own error).
      v.err_e = std::abs(v.e - ref.e) + ref.err_e;
      v.err_bias = std::abs(v.bias - ref.bias) + ref.err_bias;
      v.err_scale = std::abs(v.scale - ref.scale) + ref.err_scale;
      return v;
    }
  }
  return {};
}
// brdfbake.integrator's quadrature entries for TexelFor's rules: GGX's E
// (or Beckmann's, and the STD's at gamma = inf, when `beckmann_e`) with the
// azimuth in closed form, GGX's dfg, and the slope rule with a numerical
// azimuth (Beckmann's dfg, the STD).
inline void MicrofacetQuadratureJson(const BakeSpec& spec, bool beckmann_e, nlohmann::json* out) {
  nlohmann::json& j = *out;
  if ((spec.model.kind == ModelKind::kGgx && spec.table != TableKind::kDfg) || beckmann_e) {
    j["domain"] = beckmann_e
                      ? "theta_i in [0, pi/2], the azimuth of wi integrated in closed form "
                        "(isotropic Beckmann: three moments of Kummer's function, by its "
                        "series below x = 40 and its asymptotic expansion above, relative "
                        "error 2e-15); mesh graded geometrically (ratio 3) from the specular "
                        "peak (scale 2 alpha) and the horizon"
                      : "theta_i in [0, pi/2], the azimuth of wi integrated in closed form "
                        "(isotropic GGX); mesh graded geometrically (ratio 3) from the "
                        "specular peak (scale 2 alpha) and the horizon";
    j["rule"] = "Gauss-Kronrod 15 per piece, pieces bisected worst first until the "
                "summed error estimate meets the tolerance";
    j["error_estimate"] = "sum over the pieces of |K15 - G7|";
    return;
  }
  if (spec.model.kind == ModelKind::kGgx) {
    j["domain"] = "theta_i in [0, pi/2], mesh graded geometrically (ratio 3) from the "
                  "specular peak and the horizon; the azimuth of wi integrated in closed "
                  "form for E and for the even powers of wo.h in the Schlick weight, the "
                  "odd powers less their Taylor terms at the pole of D by Gauss-Kronrod 15 "
                  "over the azimuth on pieces graded from the branch point of wo.h "
                  "(isotropic GGX)";
    j["rule"] = "Gauss-Kronrod 15 per piece in theta_i, pieces bisected worst first until "
                "the error estimates of E, dfg.scale and dfg.bias meet the tolerance";
    j["error_estimate"] = "sum over the pieces of |K15 - G7|, plus that of the azimuthal "
                          "rule carried through the Kronrod weights";
    return;
  }
  j["domain"] = "theta_i in [0, pi/2], mesh graded geometrically (ratio 3) from the "
                "specular peak and the horizon; Lambda(wi) once per theta_i; the azimuth "
                "of D (and of D Fc for dfg) by Gauss-Kronrod 15 on pieces graded "
                "geometrically from the lobe's half width (ratio 2; from tolerance 1e-7 "
                "up, 2e-7 for dfg, ratio 3 for std up to gamma 4 and 2.5 beyond)";
  if (spec.model.kind == ModelKind::kStudentT && spec.HasGammaAxis() && spec.table != TableKind::kDfg) {
    j["gamma_inf"] = "the last slice (beckmann) with the azimuth of wi in closed form "
                     "(three moments of Kummer's function), relative error 2e-15";
  }
  j["rule"] = "Gauss-Kronrod 15 per piece in theta_i, pieces bisected worst first until "
              "the error estimates meet the tolerance";
  j["error_estimate"] = "sum over the pieces of |K15 - G7|, plus that of the azimuthal "
                        "rule carried through the Kronrod weights";
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BAKE_TEXEL_FOR_H_
