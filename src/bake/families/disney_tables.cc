// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The disney family's baker row (family_row.h): the Disney diffuse lobe's
// E and E_avg, by Gauss-Legendre rules exact for its azimuthal mean (a
// polynomial, sheen_albedo.h), or a sampling integrator over the cosine.

#include <cmath>

#include "bake/families/lobe_texel.h"
#include "bake/family_row.h"
#include "brdfbake/models/disney_diffuse.h"
#include "lanes/sheen_lanes.h"
#include "rules/sheen/sheen_albedo.h"
#include "sampling/sampling_integrators.h"

namespace brdfbake {
namespace {

TexelEstimate DisneyQuadrature(const BakeSpec& spec, double alpha, double mu) {
  const double rough = std::sqrt(alpha);
  const RuleResult r = spec.simd ? SimdDisneyAlbedo(rough, mu) : DisneyAlbedo(rough, mu);
  return AlbedoTexel(r);
}

TexelEstimate DisneyTexel(const BakeSpec& spec, const TexelAt& at, uint64_t seed) {
  if (spec.integrator == IntegratorKind::kQuadrature) return DisneyQuadrature(spec, at.alpha, at.mu);
  return SampledLobeTexel(
      spec, DisneySum(DisneyDiffuse<double>(std::sqrt(at.alpha)), SamplingView(at.mu)),
      [&](const BakeSpec& ref) { return DisneyQuadrature(ref, at.alpha, at.mu); }, seed);
}

void DisneyIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    Describe(j,
             "mu_i in [0, 1], the azimuth of wi in closed form: the azimuthal mean of f is a "
             "polynomial of degree 8 in mu_i (src/rules/sheen/sheen_albedo.h)",
             spec.table == TableKind::kEavg ? "8 x 8-point Gauss-Legendre over (mu_i, mu), exact for the polynomial"
                                            : "8-point Gauss-Legendre in mu_i, exact for the polynomial",
             "difference from the 6-point rule (also exact: rounding only) plus 1e-15 E");
    // E_avg's own exact rule; the sampling integrators' is the generic one.
    if (spec.table == TableKind::kEavg) {
      (*j)["E_avg"] = "2 int_0^1 E(mu) mu dmu by the 8 x 8-point Gauss-Legendre rule above (exact)";
    }
  } else {
    (*j)["sampling"] = "the cosine (pdf wi.z / pi), as HDRP's generator; double scalar code";
  }
}

const BakerRow kDisneyRow = {
    ModelKind::kDisneyDiffuse,
    Bit(TableKind::kE) | Bit(TableKind::kEavg),
    false,
    "E and E_avg (no dfg: it has no Fresnel factor; the engines' sheen and diffuse channels are its E)",
    DisneyTexel,
    [](const BakeSpec& slice, const TexelAt& at) {
      const RuleResult r = slice.simd ? SimdDisneyEavg(at.roughness) : DisneyEavg(at.roughness);
      return EavgEstimate{r.value, r.error};
    },
    nullptr,
    nullptr,
    [](const BakeSpec&, nlohmann::json* j) {
      (*j)["roughness"] = "r itself: F_D90 = 1/2 + 2 r (L.H)^2";
      (*j)["definition"] = "Disney diffuse of [Burley12], base colour 1: f = (1/pi) (1 + (F_D90 - 1) "
                           "(1 - NoL)^5) (1 + (F_D90 - 1) (1 - NoV)^5)";
    },
    DisneyIntegratorJson,
    kInfinity,
    nullptr,
    false};  // no shadowing

}  // namespace

extern const BakerFamily kBakerFamily_disney = {&kDisneyRow, 1};

}  // namespace brdfbake
