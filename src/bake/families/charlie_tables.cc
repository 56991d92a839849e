// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The charlie family's baker row (family_row.h): the Charlie sheen's E and
// E_avg by the half-vector rule of sheen_albedo.h, or a sampling
// integrator over its NDF's sampler.

#include <string>

#include "bake/families/lobe_texel.h"
#include "bake/family_row.h"
#include "brdfbake/models/sheen.h"
#include "lanes/sheen_lanes.h"
#include "rules/sheen/sheen_albedo.h"
#include "sampling/sampling_integrators.h"

namespace brdfbake {
namespace {

TexelEstimate CharlieQuadrature(const BakeSpec& spec, double alpha, double mu) {
  const SheenVisibility v = spec.model.visibility;
  const int n = spec.EffectiveSamples();
  const RuleResult r = spec.simd ? SimdCharlieAlbedo(alpha, v, mu, spec.tolerance, n)
                                 : CharlieAlbedo(CharlieSheen<double>(alpha, v), mu, spec.tolerance, n);
  return AlbedoTexel(r);
}

TexelEstimate CharlieTexel(const BakeSpec& spec, const TexelAt& at, uint64_t seed) {
  if (spec.integrator == IntegratorKind::kQuadrature) return CharlieQuadrature(spec, at.alpha, at.mu);
  return SampledLobeTexel(
      spec, CharlieSum(CharlieSheen<double>(at.alpha, spec.model.visibility), SamplingView(at.mu)),
      [&](const BakeSpec& ref) { return CharlieQuadrature(ref, at.alpha, at.mu); }, seed);
}

void CharlieModelJson(const BakeSpec& spec, nlohmann::json* out) {
  nlohmann::json& j = *out;
  j["alpha"] = "roughness^2";
  j["visibility"] = SheenVisibilityName(spec.model.visibility);
  const SheenVisibility v = spec.model.visibility;
  const bool clamp = SheenClampsVisibility(v);
  std::string def = "Charlie sheen of [EstevezKulla17], f = D(h) V, D = (2 + 1/alpha) "
                    "sin(theta_h)^(1/alpha) / (2 pi), F = 1, V = ";
  if (!SheenHasLambda(v)) {
    def += clamp ? "min(1, 1 / (4 (NoL + NoV - NoL NoV))) ([Neubelt13], capped as "
                   "[KhronosSampleRenderer]'s V_Ashikhmin)"
                 : "1 / (4 (NoL + NoV - NoL NoV)) ([Neubelt13])";
  } else {
    def += std::string(clamp ? "min(1, G2 / (4 NoL NoV))" : "G2 / (4 NoL NoV)") +
           ", G2 = 1 / (1 + Lambda(NoV) + Lambda(NoL)) with " +
           (v == SheenVisibility::kEnterprisePbr ? "[EnterprisePbr]'s refined Lambda fit"
                                                 : "the paper's fitted Lambda") +
           (clamp ? " (capped as [KhronosSampleRenderer]'s V_Sheen)" : "");
  }
  j["definition"] = def;
}

void CharlieIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    Describe(j,
             "the half vector: E = int D(theta_h) sin(theta_h) J dtheta_h over [0, theta_max], "
             "J = 2 int V NoL 4 (wo.h) dphi_h over the arc of the light's azimuth where NoL > 0, "
             "found in closed form (both visibilities depend on the cosines only; "
             "src/rules/sheen/sheen_albedo.h)",
             "Gauss-Kronrod 15 in s, theta_h = theta_max (1 - s^2), on pieces graded towards "
             "s = 0 and cut where J changes form; each node's J by Gauss-Kronrod 15 in phi_h, "
             "the arc's end in log1p(NoL / eps) (neubelt) or NoL^p (with a Lambda); the worst "
             "pieces bisected (nodes in double SIMD lanes)",
             "sum over the s pieces of |K15 - G7|, plus the arcs' sums of |K15 - G7| carried "
             "through the Kronrod weights and a bound on the nodes counted as 0");
  } else {
    (*j)["sampling"] = std::string("the Charlie NDF's half vector (pdf D(h) h.z / (4 wo.h)), ") +
                       (spec.integrator == IntegratorKind::kEngine ? "as the Khronos renderer's generator"
                                                                     : "double scalar code");
  }
  (*j)["smallest_alpha"] = "alpha < 1e-6 is evaluated at 1e-6";
}

const BakerRow kCharlieRow = {
    ModelKind::kCharlie,
    Bit(TableKind::kE) | Bit(TableKind::kEavg),
    false,
    "E and E_avg (no dfg: it has no Fresnel factor; the engines' sheen and diffuse channels are its E)",
    CharlieTexel,
    nullptr,
    nullptr,
    nullptr,
    CharlieModelJson,
    CharlieIntegratorJson,
    kInfinity,
    nullptr,
    false};  // its shadowing is its own

}  // namespace

extern const BakerFamily kBakerFamily_charlie = {&kCharlieRow, 1};

}  // namespace brdfbake
