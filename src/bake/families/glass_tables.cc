// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The glass family's baker row (family_row.h): ggx-glass, the rough
// dielectric's E over mu x roughness x ior and its E_avg, by the
// visible-normal rule of glass_albedo.h.

#include <algorithm>
#include <cmath>

#include "bake/family_row.h"
#include "brdfbake/models/dielectric.h"
#include "lanes/glass_lanes.h"
#include "rules/glass/glass_albedo.h"
#include "rules/glass/glass_average.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {
namespace {

// ggx-glass: E of reflection plus refraction by the visible-normal rule
// of rules/glass/glass_albedo.h at eta = spec.model.ior; below alpha 1e-4
// the smooth interface, whose E is exactly 1 (its reflection F(eta, mu),
// its refraction 1 - F).
TexelEstimate GlassTexel(const BakeSpec& spec, double alpha, double mu) {
  TexelEstimate v;
  if (alpha < kMinAlpha<double>) {
    v.e = SmoothGlassAlbedo(spec.model.ior, mu, spec.part).value;
    return v;
  }
  const double m = std::max(mu, kMuMin);
  const int n = spec.EffectiveSamples();
  const RuleResult r = spec.simd ? SimdGlassAlbedo(alpha, spec.model.ior, spec.masking, m, spec.tolerance, n, spec.part)
                                 : GlassAlbedo(alpha, spec.model.ior, spec.masking, m, spec.tolerance, n, spec.part);
  return AlbedoTexel(r);
}

// E_avg at one texel by the rule over h and wo of glass_average.h; below
// alpha 1e-4 the smooth interface's (alpha 0 there: the hemispherical
// average of F, 1 - F or Schlick's complement).
EavgEstimate GlassTexelEavg(const BakeSpec& spec, double alpha) {
  const double a = alpha >= kMinAlpha<double> ? alpha : 0.0;
  const int n = spec.EffectiveSamples();
  const RuleResult r = spec.simd ? SimdGlassAlbedoAverage(a, spec.model.ior, spec.masking, spec.tolerance, n, spec.part)
                                 : GlassAlbedoAverage(a, spec.model.ior, spec.masking, spec.tolerance, n, spec.part);
  return {r.value, r.error};
}

void GlassModelJson(const BakeSpec& spec, nlohmann::json* out) {
  nlohmann::json& j = *out;
  j["alpha"] = "roughness^2";
  j["definition"] = "rough dielectric over isotropic GGX ([Walter07]): reflection weighted by the "
                    "exact unpolarized dielectric Fresnel F(eta, wo.h), refraction by 1 - F with "
                    "the half-vector Jacobian; importance transport (no 1/eta^2 radiance factor), "
                    "so a smooth interface has E = 1";
  j["eta"] = spec.inverse ? "1 / ior: the view inside the medium, light leaving it (total "
                            "internal reflection beyond the critical angle)"
                          : "ior: the view outside, light entering the medium";
  j["ior"] = "the ior axis (brdfbake.axes)";
  if (spec.ior.warp == Warp::kTwoSided) {
    j["eta"] =
        "ior: the view outside the medium for ior >= 1, inside it for ior < 1 (total internal "
        "reflection beyond the critical angle)";
  }
  if (spec.part != DielectricPart::kBoth) {
    j["part"] = spec.part == DielectricPart::kReflection
                    ? "reflection: the reflection lobe alone, weighted by F (the energy the interface reflects)"
                : spec.part == DielectricPart::kTransmission
                    ? "transmission: the refraction lobe alone, weighted by 1 - F"
                    : "transmission-schlick: the refraction lobe alone without F, weighted by 1 - (1 - "
                      "|wo.h|)^5 (EEVEE's btdf_ggx); eta up to inf, where the refraction is -h";
  }
}

void GlassIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    Describe(j,
             "the visible normals of wo in the stretched configuration of [Heitz18]: polar "
             "angles (theta, phi) about the view on the projected lune, each ray cut where the "
             "reflection or the refraction reaches the horizon and at the critical angle (roots "
             "of quadratic forms in closed form), the rays cut where the sequence of those "
             "curves changes (src/rules/glass/glass_albedo.h)",
             spec.simd ? "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
                         "Gauss-Kronrod 15 on pieces graded towards the curves and the lune's "
                         "edge, mapped smoothly at the critical angle's square-root edge (each "
                         "piece's nodes in double SIMD lanes)"
                       : "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
                         "Gauss-Kronrod 15 on pieces graded towards the curves and the lune's "
                         "edge, mapped smoothly at the critical angle's square-root edge (double "
                         "scalar code)",
             "3 x the sum over the phi pieces of |K15 - G7|, plus the rays' own sums carried "
             "through the Kronrod weights");
    if (spec.table == TableKind::kEavg) {
      (*j)["E_avg"] =
          "(1/pi) int over wo above, int over h of D(h) (wo.h) [F G2(wo, r) + (1 - F) G2(wo, t)] dh "
          "dwo, taken about h: theta_h by GGX's radial CDF u = q^2 (2 - q^2), c = wo.h (F is F(c); "
          "cut at sin(theta_h) and, for eta < 1, at the critical cosine and where the refraction's "
          "horizon reaches psi = 0), the azimuth psi of wo about h between the horizons, which are "
          "closed-form, in w = sqrt(1 -+ cos(psi)) (src/rules/glass/glass_average.h); Gauss-Kronrod "
          "15 at each level on pieces bisected worst first, graded towards the horizons down to "
          "alpha in the cosine" +
          std::string(spec.simd ? " (each psi piece's nodes in double SIMD lanes)" : " (double scalar code)") +
          "; error: the sum of |K15 - G7| with the inner levels' carried through the Kronrod "
          "weights. Below alpha 1e-4, the smooth interface: 2 int_0^1 c w(c) dc, w = 1, F, 1 - F "
          "or 1 - (1 - c)^5 by the part, cut at the critical cosine. (domain, rule and "
          "error_estimate describe the rule for E, which E_avg does not use.)";
    }
  }
  (*j)["smooth"] = spec.part == DielectricPart::kBoth ? "alpha < 1e-4 is the smooth interface: E = 1"
                   : spec.part == DielectricPart::kReflection
                       ? "alpha < 1e-4 is the smooth interface: E = F(eta, mu)"
                   : spec.part == DielectricPart::kTransmission
                       ? "alpha < 1e-4 is the smooth interface: E = 1 - F(eta, mu)"
                       : "alpha < 1e-4 is the smooth interface: E = 1 - (1 - mu)^5";
}

// E's definition by the parts it counts (BakeSpec::part).
const char* GlassEDefinition(const BakeSpec& spec) {
  switch (spec.part) {
    case DielectricPart::kReflection:
      return "directional albedo E(mu) = integral over the upper hemisphere of f_R cos(theta_i) dwi of "
             "the rough dielectric's reflection lobe, Fresnel included: the energy it reflects";
    case DielectricPart::kTransmission:
      return "directional albedo E(mu) = integral over the lower hemisphere of f_T |cos(theta_i)| dwi of "
             "the rough dielectric's refraction lobe, Fresnel included: the energy it refracts";
    case DielectricPart::kTransmissionSchlick:
      return "T(mu) = integral over the lower hemisphere of (1 - (1 - |wo.h|)^5) f_T |cos(theta_i)| dwi, f_T the "
             "rough dielectric's refraction lobe without its Fresnel factor: the refraction weighted by the "
             "complement of Schlick's weight (EEVEE's btdf_ggx; the renderer multiplies it by 1 - F0)";
    case DielectricPart::kBoth: break;
  }
  return "directional albedo E(mu) = integral over the sphere of (f_R + f_T) |cos(theta_i)| dwi of "
         "the rough dielectric, Fresnel included: reflection plus refraction";
}

const BakerRow kGgxGlassRow = {
    ModelKind::kGgxGlass,
    Bit(TableKind::kE) | Bit(TableKind::kEavg),
    true,
    "E and E_avg (reflection plus refraction; no dfg)",
    [](const BakeSpec& slice, const TexelAt& at, uint64_t) { return GlassTexel(slice, at.alpha, at.mu); },
    [](const BakeSpec& slice, const TexelAt& at) { return GlassTexelEavg(slice, at.alpha); },
    nullptr,
    nullptr,
    GlassModelJson,
    GlassIntegratorJson,
    1.0,
    nullptr,
    true,
    // Slices over the ior of the medium below the view.
    [](const BakeSpec& spec) {
      if (spec.table == TableKind::kEavg) {
        return OwnAxes{{&BakeSpec::roughness, &BakeSpec::ior}, {32, 32}, "NxD (roughness x ior, e.g. 32x16)"};
      }
      return OwnAxes{{&BakeSpec::mu, &BakeSpec::roughness, &BakeSpec::ior}, {32, 32, 32},
                     "WxHxD (mu x roughness x ior, e.g. 32x32x16)"};
    },
    // Its widths come from the roughness axis.
    [](ModelParams* p) { p->alpha_x = p->alpha_y = 1.0; },
    GlassEDefinition};

}  // namespace

extern const BakerFamily kBakerFamily_glass = {&kGgxGlassRow, 1};

}  // namespace brdfbake
