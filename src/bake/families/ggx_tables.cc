// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ggx family's baker rows (family_row.h): ggx (E, dfg, E_avg and the
// GGX lobe's own tables, whose texels bake.cc dispatches by table kind),
// and ggx-aniso (E over mu, phi_o, roughness and the glTF anisotropy
// strength, and E_avg, by the slope-plane rule of aniso_ggx.h).

#include <algorithm>
#include <cmath>

#include "bake/family_row.h"
#include "bake/texel_for.h"
#include "brdfbake/models/ggx.h"
#include "lanes/aniso_lanes.h"
#include "rules/ggx_aniso/aniso_ggx.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {
namespace {

TexelEstimate GgxTexel(const BakeSpec& slice, const TexelAt& at, uint64_t seed) {
  if (at.alpha < kMinAlpha<double>) return MirrorTexel(at.mu);
  return TexelFor(GgxNdf<double>(at.alpha), at.mu, slice, seed);
}

void GgxModelJson(const BakeSpec& spec, nlohmann::json* out) {
  nlohmann::json& j = *out;
  j["alpha"] = "roughness^2";
  if (spec.table == TableKind::kF82Bias) {
    j["definition"] =
        "isotropic GGX reflection lobe (F = 1); its energy weighted by wo.h (1 - wo.h)^6, the "
        "F82 tint's shape ([Hoffman19]), taken over the visible normals ([Heitz18] eq. 3)";
  }
  if (spec.GenSchlick()) {
    j["definition"] = "isotropic GGX reflection lobe; s averages s_h(wo.h) over its visible normals "
                      "([Heitz18] eq. 3), reflections below the surface counting 0 ([Cycles]'s "
                      "generalized Schlick tables)";
    j[spec.table == TableKind::kGenSchlickS ? "exponent" : "ior"] =
        spec.table == TableKind::kGenSchlickS ? "the exponent axis (brdfbake.axes): s_h = (1 - wo.h)^exponent"
                                              : "the ior axis (brdfbake.axes): s_h = clamp((F(ior, wo.h) - "
                                                "F0) / (1 - F0), 0, 1)";
  }
}

void GgxIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    if (spec.table == TableKind::kF82Bias) {
      Describe(j,
               "the visible normals of wo in the stretched configuration of [Heitz18]: polar "
               "angles (theta, phi) about the view on the projected lune, each ray cut where the "
               "reflection reaches the horizon (src/rules/glass/gen_schlick.h)",
               "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
               "Gauss-Kronrod 15 on pieces graded towards the horizon and the lune's edge (double "
               "scalar code)",
               "3 x the sum over the phi pieces of |K15 - G7|, plus the rays' own sums carried "
               "through the Kronrod weights");
    } else if (spec.GenSchlick()) {
      Describe(j,
               "the visible normals of wo in the stretched configuration of [Heitz18]: polar "
               "angles (theta, phi) about the view on the projected lune, each ray cut where the "
               "reflection reaches the horizon (and, for an exponent above 40, at wo.h = 40 / "
               "exponent, beyond which (1 - wo.h)^exponent < e^-40; src/rules/glass/gen_schlick.h)",
               "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
               "Gauss-Kronrod 15 on pieces graded towards the curves and the lune's edge (double "
               "scalar code)",
               "3 x the sum over the phi pieces of |K15 - G7|, plus the rays' own sums carried "
               "through the Kronrod weights");
    } else {
      MicrofacetQuadratureJson(spec, false, j);
    }
  }
  if (spec.GenSchlick()) {
    (*j)["mirror"] = "alpha < 1e-4 is a mirror: s = s_h(mu)";
  } else if (spec.table == TableKind::kF82Bias) {
    (*j)["mirror"] = "alpha < 1e-4 is a mirror: b = mu (1 - mu)^6";
  } else {
    MirrorJson(j);
  }
}

// ggx-aniso: E at one texel by the slope-plane rule (aniso_ggx.h); below
// alpha_t = 1e-4 (hence alpha_b too) a mirror, as for ggx.
TexelEstimate AnisoTexel(const BakeSpec& spec, double r, double s, double mu, double phi) {
  const double alpha_t = AnisotropyAlphaT(r, s);
  if (alpha_t < kMinAlpha<double>) return MirrorTexel(mu);
  const double m = std::max(mu, kMuMin);
  const RuleResult a =
      spec.simd ? SimdAnisoGgxAlbedo(alpha_t, r * r, m, phi, spec.masking, spec.tolerance,
                                     spec.EffectiveSamples())
                : AnisoGgxAlbedo(alpha_t, r * r, m, phi, spec.masking, spec.tolerance,
                                 spec.EffectiveSamples());
  return AlbedoTexel(a);
}

// E_avg = (1 / pi) int E(wo) cos(theta_o) dwo = 2 int_0^1 A(mu) mu dmu
// (AdaptiveEavg) with A(mu) the average of e_at(mu, phi_o) over
// [0, phi_max]. A is adaptive Gauss-Kronrod 15, the worst piece bisected
// until its |K15 - G7| sum is below a third of the tolerance: at grazing an
// anisotropic E changes over phi_o within about alpha_b / alpha_t of the
// narrow axis, where the effective width turns from alpha_t to alpha_b.
template <class EAt>
EavgEstimate HemisphericalEavg(const EAt& e_at, double phi_max, double tolerance) {
  auto average_over_phi = [&](double mu) {
    using Piece = GkPiece;
    auto piece = [&](double a, double b) {
      // The average over [0, phi_max].
      return KronrodPiece(a, b, 1 / phi_max, [&](double phi, double* err) {
        const TexelEstimate v = e_at(mu, phi);
        *err = v.err_e;
        return v.e;
      });
    };
    std::vector<Piece> pieces = {piece(0.0, phi_max)};
    auto rule_error = [&] {
      double e = 0;
      for (const Piece& p : pieces) e += p.err;
      return e;
    };
    while (rule_error() > tolerance / 3 && pieces.size() < 32) BisectWorst(&pieces, piece);
    TexelEstimate v;
    for (const Piece& p : pieces) {
      v.e += p.value;
      v.err_e += p.err + p.prop;
    }
    return v;
  };
  return AdaptiveEavg(average_over_phi, tolerance);
}

// E is even in phi_o and symmetric about pi/2, so [0, pi/2] covers every
// azimuth.
EavgEstimate AnisoEavg(const BakeSpec& spec, const TexelAt& at) {
  return HemisphericalEavg(
      [&](double mu, double phi) { return AnisoTexel(spec, at.roughness, at.anisotropy, mu, phi); }, kHalfPi,
      spec.tolerance);
}

void AnisoModelJson(const BakeSpec&, nlohmann::json* out) {
  nlohmann::json& j = *out;
  j["alpha_t"] = "mix(roughness^2, 1, anisotropy^2), along the tangent (x)";
  j["alpha_b"] = "roughness^2, along the bitangent (y)";
  j["definition"] = "glTF KHR_materials_anisotropy (anisotropy = its strength)";
  j["phi_o"] = "azimuth of wo from the tangent, radians; E is even in phi_o and symmetric "
               "about pi/2, so [0, pi/2] covers every azimuth";
}

void AnisoIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    Describe(j,
             "the slope plane of the half vector, in the stretched polar coordinates "
             "(psi, u = rho^2 / (1 + rho^2)) in which the GGX slope density is uniform; "
             "wi above the horizon is a disk in slopes, reached along each ray in "
             "closed form (src/rules/ggx_aniso/aniso_ggx.h)",
             "Gauss-Kronrod 15 over psi on pieces bisected worst first; along each ray "
             "Gauss-Kronrod 15 in sqrt(u) on pieces graded by 4 towards the disk's "
             "edge down to its masking layer (nodes in double SIMD lanes)",
             "sum over the psi pieces of |K15 - G7|, plus the rays' own sums of |K15 - G7| "
             "carried through the Kronrod weights");
  }
  if (spec.table == TableKind::kEavg) {
    (*j)["E_avg"] = "(1/pi) int E(wo) cos(theta_o) dwo = 2 int_0^1 A(mu) mu dmu by adaptive "
                    "Gauss-Kronrod 15 in sqrt(mu) as for the other models, A(mu) the average of "
                    "E(mu, phi_o) over phi_o in [0, pi/2] by adaptive Gauss-Kronrod 15; error: the "
                    "rules' |K15 - G7| plus the propagated errors of E";
  }
  MirrorJson(j);
}

const BakerRow kGgxRows[] = {
    {ModelKind::kGgx,
     Bit(TableKind::kE) | Bit(TableKind::kEavg) | Bit(TableKind::kDfg) | Bit(TableKind::kGenSchlickS) |
         Bit(TableKind::kGenSchlickIorS) | Bit(TableKind::kF82Bias),
     false, "E, E_avg and dfg", GgxTexel, nullptr, nullptr, nullptr, GgxModelJson, GgxIntegratorJson, 1.0},
    {ModelKind::kGgxAniso, Bit(TableKind::kE) | Bit(TableKind::kEavg), true, "E and E_avg (no dfg)",
     [](const BakeSpec& slice, const TexelAt& at, uint64_t) {
       return AnisoTexel(slice, at.roughness, at.anisotropy, at.mu, at.phi);
     },
     AnisoEavg, nullptr, nullptr, AnisoModelJson, AnisoIntegratorJson, 1.0, nullptr, true,
     [](const BakeSpec& spec) {
       if (spec.table == TableKind::kEavg) {
         return OwnAxes{{&BakeSpec::roughness, &BakeSpec::anisotropy}, {32, 16},
                        "RxS (roughness x anisotropy, e.g. 32x16)"};
       }
       return OwnAxes{{&BakeSpec::mu, &BakeSpec::phi, &BakeSpec::roughness, &BakeSpec::anisotropy},
                      {32, 16, 32, 16},
                      "WxPxRxS (mu x phi_o x roughness x anisotropy, e.g. 32x16x32x16)"};
     },
     // Its widths come from the roughness and anisotropy axes.
     [](ModelParams* p) { p->kind = ModelKind::kGgx; }},
};

}  // namespace

extern const BakerFamily kBakerFamily_ggx = {kGgxRows, 2};

TexelEstimate IntegrateAnisoTexel(const BakeSpec& spec, double roughness, double anisotropy, double mu,
                                  double phi_o) {
  ValidateBakeSpec(spec);
  return AnisoTexel(spec, roughness, anisotropy, mu, phi_o);
}

EavgEstimate IntegrateAnisoEavg(const BakeSpec& spec, double roughness, double anisotropy) {
  ValidateBakeSpec(spec);
  TexelAt at;
  at.roughness = roughness;
  at.anisotropy = anisotropy;
  return AnisoEavg(spec, at);
}

}  // namespace brdfbake
