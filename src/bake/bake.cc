// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/bake.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>

#include <Imath/half.h>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "base/error.h"
#include "base/pixel.h"
#include "bake/warp_coordinates.h"
#include "base/text.h"
#include "brdfbake/version.h"
#include "lanes/quadrature_simd.h"
#include "quadrature/adaptive_rule.h"
#include "quadrature/solve_bracketed.h"
#include "rules/ellipsoid/ellipsoid_albedo.h"
#include "rules/ellipsoid/ellipsoid_albedo_rule.h"
#include "rules/ggx/azimuthal.h"
#include "rules/ggx_aniso/aniso_ggx.h"
#include "rules/glass/gen_schlick.h"
#include "rules/glass/glass_albedo.h"
#include "rules/sel/sel_norm.h"
#include "rules/sheen/sheen_albedo.h"
#include "sampling/sampling_integrators.h"
#include "sampling/sampling_simd.h"

namespace brdfbake {
namespace {

}  // namespace


namespace {

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
  // E alone, from a closed-azimuth albedo rule.
  auto albedo = [](const RuleResult& r) {
    TexelEstimate v;
    v.e = r.value;
    v.err_e = r.error;
    return v;
  };
  if constexpr (std::is_same_v<Ndf, GgxNdf<double>>) {
    const double a = ndf.alpha_x();
    if (spec.table == TableKind::kDfg) {
      return texel(spec.simd ? SimdGgxAzimuthalDfg(a, m, spec.masking, tol, max_nodes)
                             : GgxAzimuthalDfg(a, m, spec.masking, tol, max_nodes));
    }
    return albedo(spec.simd ? SimdGgxAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes)
                            : GgxAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes));
  } else {
    const bool bias = spec.table == TableKind::kDfg;
    // Beckmann's E (and the STD's at gamma = inf, which is Beckmann) with
    // the azimuth in closed form (beckmann_azimuth.h).
    bool beckmann = std::is_same_v<Ndf, BeckmannNdf<double>>;
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) beckmann = std::isinf(ndf.gamma());
    if (beckmann && !bias) {
      const double a = ndf.alpha_x();
      return albedo(spec.simd ? SimdBeckmannAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes)
                              : BeckmannAzimuthalAlbedo(a, m, spec.masking, tol, max_nodes));
    }
#if BRDFBAKE_WITH_STD
    // The STD's E at finite gamma with the azimuth from tabulated moments
    // (std_azimuth.h).
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) {
      if (!bias) {
        return albedo(spec.simd ? SimdStdAzimuthalAlbedo(ndf, m, spec.masking, tol, max_nodes)
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

// E of the sheen and diffuse lobes: the quadrature (rules/sheen/
// sheen_albedo.h, in lanes or by the double reference), or a sampling
// integrator over their own samplers (sampling_integrators.h, in double
// scalar code), the engine setting's error measured against the
// quadrature.
TexelEstimate SheenQuadrature(const BakeSpec& spec, double alpha, double mu);

TexelEstimate SheenTexel(const BakeSpec& spec, double alpha, double mu, uint64_t texel_seed) {
  if (spec.integrator == IntegratorKind::kQuadrature) return SheenQuadrature(spec, alpha, mu);
  const Vec3<double> wo = SamplingView(mu);
  const int n = spec.EffectiveSamples();
  auto run = [&](const auto& sum) {
    if (spec.integrator != IntegratorKind::kEngine) {
      return QmcTexelWith(n, texel_seed, spec.integrator == IntegratorKind::kMc, sum);
    }
    TexelEstimate v;
    v.e = EngineRuleWith(n, sum).e;
    v.err_e = std::numeric_limits<double>::infinity();
    if (spec.estimate_error) {
      BakeSpec ref = spec;
      ref.integrator = IntegratorKind::kQuadrature;
      ref.tolerance = 1e-10;
      ref.samples = 0;
      const TexelEstimate q = SheenQuadrature(ref, alpha, mu);
      v.err_e = std::abs(v.e - q.e) + q.err_e;
    }
    return v;
  };
  TexelEstimate v = spec.model.kind == ModelKind::kDisneyDiffuse
                        ? run(DisneySum(DisneyDiffuse<double>(std::sqrt(alpha)), wo))
                        : run(CharlieSum(CharlieSheen<double>(alpha, spec.model.visibility), wo));
  v.scale = v.bias = v.err_scale = v.err_bias = 0;
  return v;
}

TexelEstimate SheenQuadrature(const BakeSpec& spec, double alpha, double mu) {
  RuleResult r;
  if (spec.model.kind == ModelKind::kDisneyDiffuse) {
    const double rough = std::sqrt(alpha);
    r = spec.simd ? SimdDisneyAlbedo(rough, mu) : DisneyAlbedo(rough, mu);
  } else {
    const SheenVisibility v = spec.model.visibility;
    const int n = spec.EffectiveSamples();
    r = spec.simd ? SimdCharlieAlbedo(alpha, v, mu, spec.tolerance, n)
                  : CharlieAlbedo(CharlieSheen<double>(alpha, v), mu, spec.tolerance, n);
  }
  TexelEstimate t;
  t.e = r.value;
  t.err_e = r.error;
  return t;
}

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
  v.e = r.value;
  v.err_e = r.error;
  return v;
}

// gen_schlick_s / gen_schlick_ior_s: the factor s at one texel by the
// visible-normal rule of rules/glass/gen_schlick.h; below alpha 1e-4 the
// mirror, whose one half vector is the normal: s = s_h(mu).
TexelEstimate GenSchlickTexel(const BakeSpec& spec, double alpha, double mu, const GenSchlickShape& shape) {
  TexelEstimate v;
  const double m = std::max(mu, kMuMin);
  if (alpha < kMinAlpha<double>) {
    v.e = GenSchlickWeight(shape, m);
    return v;
  }
  const RuleResult r = GenSchlickFactor(alpha, shape, m, spec.tolerance, spec.EffectiveSamples());
  v.e = r.value;
  v.err_e = r.error;
  return v;
}

// f82_bias: the F82-tint term at one texel by the visible-normal rule of
// rules/glass/gen_schlick.h; below alpha 1e-4 the mirror, b(mu).
TexelEstimate F82Texel(const BakeSpec& spec, double alpha, double mu) {
  TexelEstimate v;
  const double m = std::max(mu, kMuMin);
  if (alpha < kMinAlpha<double>) {
    v.e = F82TintWeight(m);
    return v;
  }
  const RuleResult r = F82TintBias(alpha, spec.masking, m, spec.tolerance, spec.EffectiveSamples());
  v.e = r.value;
  v.err_e = r.error;
  return v;
}

// The shape of s_h in slice k of a gen_schlick table: the exponent axis'
// value or the dielectric shape at the ior axis' value, each clamped.
GenSchlickShape GenSchlickSlice(const BakeSpec& spec, int k) {
  if (spec.table == TableKind::kGenSchlickS) {
    const Axis& a = spec.exponent;
    return {std::clamp(a.Value(k), a.clamp_min, a.clamp_max), 1.0};
  }
  return {-1.0, std::min(spec.ior.Value(k), spec.ior.clamp_max)};
}

TexelEstimate Texel(const BakeSpec& spec, double alpha, double mu, uint64_t texel_seed) {
  const ModelKind m = spec.model.kind;
  if (m == ModelKind::kGgxGlass) return GlassTexel(spec, alpha, mu);
  if (m == ModelKind::kCharlie || m == ModelKind::kDisneyDiffuse) return SheenTexel(spec, alpha, mu, texel_seed);
  if (alpha < kMinAlpha<double>) return MirrorTexel(mu);
  if (m == ModelKind::kGgx) return TexelFor(GgxNdf<double>(alpha), mu, spec, texel_seed);
#if BRDFBAKE_WITH_BECKMANN
  if (m == ModelKind::kBeckmann) return TexelFor(BeckmannNdf<double>(alpha), mu, spec, texel_seed);
#endif
#if BRDFBAKE_WITH_STD
  if (m == ModelKind::kStudentT)
    return TexelFor(StudentTNdf<double>(alpha, alpha, spec.model.gamma), mu, spec, texel_seed);
#endif
  return TexelFor(GgxNdf<double>(alpha), mu, spec, texel_seed);  // ValidateBakeSpec admits no other
}

// A texel of spec's table in slice z at (alpha, mu), `slice` the spec Bake
// made for that slice (gamma or eta set): the one dispatch over the table
// kinds, Bake's and IntegrateTexel's.
TexelEstimate TableTexel(const BakeSpec& spec, const BakeSpec& slice, int z, double alpha, double mu,
                         uint64_t texel_seed) {
  if (spec.GenSchlick()) return GenSchlickTexel(spec, alpha, mu, GenSchlickSlice(spec, z));
  if (spec.table == TableKind::kF82Bias) return F82Texel(spec, alpha, mu);
  return Texel(slice, alpha, mu, texel_seed);
}

std::string ModelJson(const BakeSpec& spec) {
  nlohmann::json j;
  j["name"] = spec.model.name();
  if (spec.table == TableKind::kSelNorm) {
    j["definition"] = "squared ellipsoidal lobe K(w; Q, alpha_x, alpha_y) of [TokuyoshiHarada]; its "
                      "integral does not depend on Q";
    j["closed_form"] = "alpha_x = alpha_y = alpha: N = 4 pi alpha^2; as both go to 0, "
                       "N / (4 pi alpha_x alpha_y) -> 1";
    return j.dump();
  }
  if (spec.model.kind == ModelKind::kEllipsoid) {
    const ModelParams& p = spec.model;
    j["alpha_x"] = p.alpha_x;
    j["alpha_y"] = p.alpha_y;
    j["theta_x"] = p.theta_x;
    j["theta_y"] = p.theta_y;
    j["theta_z"] = p.theta_z;
    j["definition"] = "Walter et al. ellipsoid NDF ([Walter15]), A = S R, S = diag(alpha_x, "
                      "alpha_y, 1), R = Rx(theta_x) Ry(theta_y) Rz(theta_z), angles in radians; "
                      "G1 of eq. 6 (clamped at 1)";
    j["phi_o"] = "azimuth of wo from the x axis, radians; no symmetry: E(phi_o) != E(-phi_o) "
                 "once the ellipsoid is tilted";
    return j.dump();
  }
  if (spec.Anisotropic()) {
    j["alpha_t"] = "mix(roughness^2, 1, anisotropy^2), along the tangent (x)";
    j["alpha_b"] = "roughness^2, along the bitangent (y)";
    j["definition"] = "glTF KHR_materials_anisotropy (anisotropy = its strength)";
    j["phi_o"] = "azimuth of wo from the tangent, radians; E is even in phi_o and symmetric "
                 "about pi/2, so [0, pi/2] covers every azimuth";
    return j.dump();
  }
  if (spec.model.kind == ModelKind::kDisneyDiffuse) {
    j["roughness"] = "r itself: F_D90 = 1/2 + 2 r (L.H)^2";
    j["definition"] = "Disney diffuse of [Burley12], base colour 1: f = (1/pi) (1 + (F_D90 - 1) "
                      "(1 - NoL)^5) (1 + (F_D90 - 1) (1 - NoV)^5)";
    return j.dump();
  }
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
    return j.dump();
  }
  if (spec.Glass()) {
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
    return j.dump();
  }
  if (spec.model.kind == ModelKind::kCharlie) {
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
    return j.dump();
  }
  if (spec.model.kind == ModelKind::kStudentT && spec.HasGammaAxis()) {
    j["gamma"] = "the gamma axis (brdfbake.axes); its last value inf is beckmann";
  } else if (spec.model.kind == ModelKind::kStudentT) {
    if (std::isinf(spec.model.gamma)) j["gamma"] = "inf"; else j["gamma"] = spec.model.gamma;
    if (std::isfinite(spec.model.gamma) && spec.model.gamma >= kStudentTBeckmannLimitGamma) {
      j["evaluated_as"] = "beckmann (the limit gamma -> inf; gamma >= 1e20 agrees with it to double precision)";
    }
  }
  return j.dump();
}

std::string IntegratorJson(const BakeSpec& spec) {
  nlohmann::json j;
  const int n = spec.EffectiveSamples();
  j["method"] = IntegratorName(spec.integrator);
  // Beckmann's E (and the STD's at gamma = inf) has its azimuth in closed form.
  const bool beckmann_e = spec.table != TableKind::kDfg &&
                          (spec.model.kind == ModelKind::kBeckmann ||
                           (spec.model.kind == ModelKind::kStudentT && !spec.HasGammaAxis() &&
                            spec.model.gamma >= kStudentTBeckmannLimitGamma));
  auto describe = [&](const char* domain, const char* rule, const char* error_estimate) {
    j["domain"] = domain;
    j["rule"] = rule;
    j["error_estimate"] = error_estimate;
  };
  switch (spec.integrator) {
    case IntegratorKind::kQuadrature:
      j["tolerance"] = spec.tolerance;
      j["max_pieces"] = n;
      if (spec.table == TableKind::kSelNorm) {
        describe("N = 4 pi alpha_x alpha_y G, G = (2/pi) int_0^{pi/2} int_0^1 g dx dphi over the "
                 "half vector of the stretched direction and the lobe axis in GGX slope "
                 "coordinates (x = 1 - u), g = 1 / |v' / k| (src/rules/sel/sel_norm.h)",
                 "Gauss-Kronrod 15 in x graded towards 0 and in phi graded towards the peak of g, "
                 "worst pieces bisected; the tolerance applies to G",
                 "sum of |K15 - G7| of both rules");
        break;
      }
      if (spec.table == TableKind::kF82Bias) {
        describe(
            "the visible normals of wo in the stretched configuration of [Heitz18]: polar "
            "angles (theta, phi) about the view on the projected lune, each ray cut where the "
            "reflection reaches the horizon (src/rules/glass/gen_schlick.h)",
            "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
            "Gauss-Kronrod 15 on pieces graded towards the horizon and the lune's edge (double "
            "scalar code)",
            "3 x the sum over the phi pieces of |K15 - G7|, plus the rays' own sums carried "
            "through the Kronrod weights");
        break;
      }
      if (spec.GenSchlick()) {
        describe("the visible normals of wo in the stretched configuration of [Heitz18]: polar "
                 "angles (theta, phi) about the view on the projected lune, each ray cut where the "
                 "reflection reaches the horizon (and, for an exponent above 40, at wo.h = 40 / "
                 "exponent, beyond which (1 - wo.h)^exponent < e^-40; src/rules/glass/gen_schlick.h)",
                 "Gauss-Kronrod 15 over phi on pieces bisected worst first; along each ray "
                 "Gauss-Kronrod 15 on pieces graded towards the curves and the lune's edge (double "
                 "scalar code)",
                 "3 x the sum over the phi pieces of |K15 - G7|, plus the rays' own sums carried "
                 "through the Kronrod weights");
        break;
      }
      if (spec.Glass()) {
        describe("the visible normals of wo in the stretched configuration of [Heitz18]: polar "
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
        break;
      }
      if (spec.model.kind == ModelKind::kEllipsoid || spec.Anisotropic()) {
        describe(spec.Anisotropic()
                     ? "the slope plane of the half vector, in the stretched polar coordinates "
                       "(psi, u = rho^2 / (1 + rho^2)) in which the GGX slope density is uniform; "
                       "wi above the horizon is a disk in slopes, reached along each ray in "
                       "closed form (src/rules/ggx_aniso/aniso_ggx.h)"
                     : "the slope plane of the half vector: the ellipsoid's slope density is a "
                       "sheared and shifted GGX, uniform in polar coordinates (psi, u) around its "
                       "peak; wi above the horizon is a disk in slopes, crossed by each ray in a "
                       "segment found in closed form (src/rules/ellipsoid/ellipsoid_albedo.h)",
                 spec.Anisotropic()
                     ? "Gauss-Kronrod 15 over psi on pieces bisected worst first; along each ray "
                       "Gauss-Kronrod 15 in sqrt(u) on pieces graded by 4 towards the disk's "
                       "edge down to its masking layer (nodes in double SIMD lanes)"
                     : "Gauss-Kronrod 15 over psi on pieces bisected worst first; along each ray "
                       "Gauss-Kronrod 15 in sqrt(u), mapped towards the horizon crossings, cut "
                       "at the kinks of G1's clamp and bisected worst first to a fifth of the "
                       "tolerance (rays set up and nodes in double SIMD lanes, or the double "
                       "scalar reference with --target scalar)",
                 "sum over the psi pieces of |K15 - G7|, plus the rays' own sums of |K15 - G7| "
                 "carried through the Kronrod weights");
        break;
      }
      if (spec.model.kind == ModelKind::kCharlie) {
        describe("the half vector: E = int D(theta_h) sin(theta_h) J dtheta_h over [0, theta_max], "
                 "J = 2 int V NoL 4 (wo.h) dphi_h over the arc of the light's azimuth where NoL > 0, "
                 "found in closed form (both visibilities depend on the cosines only; "
                 "src/rules/sheen/sheen_albedo.h)",
                 "Gauss-Kronrod 15 in s, theta_h = theta_max (1 - s^2), on pieces graded towards "
                 "s = 0 and cut where J changes form; each node's J by Gauss-Kronrod 15 in phi_h, "
                 "the arc's end in log1p(NoL / eps) (neubelt) or NoL^p (with a Lambda); the worst "
                 "pieces bisected (nodes in double SIMD lanes)",
                 "sum over the s pieces of |K15 - G7|, plus the arcs' sums of |K15 - G7| carried "
                 "through the Kronrod weights and a bound on the nodes counted as 0");
        break;
      }
      if (spec.model.kind == ModelKind::kDisneyDiffuse) {
        describe("mu_i in [0, 1], the azimuth of wi in closed form: the azimuthal mean of f is a "
                 "polynomial of degree 8 in mu_i (src/rules/sheen/sheen_albedo.h)",
                 spec.table == TableKind::kEavg
                     ? "8 x 8-point Gauss-Legendre over (mu_i, mu), exact for the polynomial"
                     : "8-point Gauss-Legendre in mu_i, exact for the polynomial",
                 "difference from the 6-point rule (also exact: rounding only) plus 1e-15 E");
        break;
      }
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
        break;
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
        break;
      }
      j["domain"] = "theta_i in [0, pi/2], mesh graded geometrically (ratio 3) from the "
                    "specular peak and the horizon; Lambda(wi) once per theta_i; the azimuth "
                    "of D (and of D Fc for dfg) by Gauss-Kronrod 15 on pieces graded "
                    "geometrically from the lobe's half width (ratio 2; from tolerance 1e-7 "
                    "up, 2e-7 for dfg, ratio 3 for std up to gamma 4 and 2.5 beyond)";
      if (spec.model.kind == ModelKind::kStudentT && spec.HasGammaAxis() &&
          spec.table != TableKind::kDfg) {
        j["gamma_inf"] = "the last slice (beckmann) with the azimuth of wi in closed form "
                         "(three moments of Kummer's function), relative error 2e-15";
      }
      j["rule"] = "Gauss-Kronrod 15 per piece in theta_i, pieces bisected worst first until "
                  "the error estimates meet the tolerance";
      j["error_estimate"] = "sum over the pieces of |K15 - G7|, plus that of the azimuthal "
                            "rule carried through the Kronrod weights";
      break;
    case IntegratorKind::kQmc:
      j["samples"] = 8 * std::max(1, n / 8);
      j["sequence"] = "Hammersley, 8 Cranley-Patterson rotations";
      j["sampling"] = "visible normals";
      j["error_estimate"] = "4 x standard error over the 8 replicas";
      j["seed"] = spec.seed;
      break;
    case IntegratorKind::kMc:
      j["samples"] = 8 * std::max(1, n / 8);
      j["sampling"] = "visible normals, pseudo-random (SplitMix64 per texel)";
      j["error_estimate"] = "4 x standard error over 8 batches";
      j["seed"] = spec.seed;
      break;
    case IntegratorKind::kEngine:
      j["samples"] = n;
      j["sequence"] = "Hammersley (unrandomized)";
      j["sampling"] = "NDF importance sampling of the half vector";
      j["error_estimate"] = "difference from the converged quadrature (tolerance 1e-10) plus its error";
      break;
  }
  if (spec.integrator != IntegratorKind::kQuadrature && spec.model.kind == ModelKind::kCharlie) {
    j["sampling"] = std::string("the Charlie NDF's half vector (pdf D(h) h.z / (4 wo.h)), ") +
                    (spec.integrator == IntegratorKind::kEngine ? "as the Khronos renderer's generator"
                                                                  : "double scalar code");
  } else if (spec.integrator != IntegratorKind::kQuadrature && spec.model.kind == ModelKind::kDisneyDiffuse) {
    j["sampling"] = "the cosine (pdf wi.z / pi), as HDRP's generator; double scalar code";
  }
  if (spec.table == TableKind::kEavg && spec.model.kind == ModelKind::kEllipsoid) {
    j["E_avg"] = "(1/pi) int E(wo) cos(theta_o) dwo = int_0^1 4 s^3 A(s) ds, s = sqrt(mu), by "
                 "adaptive Gauss-Kronrod 15 in s cut where G1(wo)'s clamp edge has extreme mu, A(s) "
                 "the average of E over phi_o in [0, 2 pi) by adaptive Gauss-Kronrod 15 on the arcs "
                 "between the clamp edge's crossings; error: the rules' |K15 - G7| plus the "
                 "propagated errors of E";
  } else if (spec.table == TableKind::kEavg && spec.Anisotropic()) {
    j["E_avg"] = "(1/pi) int E(wo) cos(theta_o) dwo = 2 int_0^1 A(mu) mu dmu by adaptive "
                 "Gauss-Kronrod 15 in sqrt(mu) as for the other models, A(mu) the average of "
                 "E(mu, phi_o) over phi_o in [0, pi/2] by adaptive Gauss-Kronrod 15; error: the "
                 "rules' |K15 - G7| plus the propagated errors of E";
  } else if (spec.table == TableKind::kEavg && spec.model.kind == ModelKind::kDisneyDiffuse) {
    j["E_avg"] = "2 int_0^1 E(mu) mu dmu by the 8 x 8-point Gauss-Legendre rule above (exact)";
  } else if (spec.table == TableKind::kEavg) {
    if (spec.integrator == IntegratorKind::kQuadrature) {
      j["E_avg"] = "2 int_0^1 E(mu) mu dmu, adaptive Gauss-Kronrod 15 in sqrt(mu) from the "
                   "pieces [0, 1/4], [1/4, 1], the worst bisected until the error estimate "
                   "meets the tolerance; E at each node from the integrator above; error: "
                   "sum of |K15 - G7| plus the propagated E error";
      if (spec.Glass() && (spec.inverse || spec.ior.warp == Warp::kTwoSided)) {
        j["E_avg"] = j["E_avg"].get<std::string>() + "; each slice" +
                     (spec.inverse ? "" : " with eta < 1") +
                     " also cut at the critical cosine sqrt(1 - eta^2) (s = its "
                     "square root), the pieces on either side mapped quadratically towards it";
      }
    } else {
      j["E_avg"] = "2 int_0^1 E(mu) mu dmu, 32-node Gauss-Legendre in sqrt(mu), "
                   "E at each node from the integrator above; error: difference from "
                   "the 16-node rule plus the propagated E error";
    }
  }
  j["grazing"] = "mu = 0 evaluated at mu = 1e-7";
  if (spec.model.kind == ModelKind::kCharlie) {
    j["smallest_alpha"] = "alpha < 1e-6 is evaluated at 1e-6";
  } else if (spec.Glass()) {
    j["smooth"] = spec.part == DielectricPart::kBoth ? "alpha < 1e-4 is the smooth interface: E = 1"
                  : spec.part == DielectricPart::kReflection
                      ? "alpha < 1e-4 is the smooth interface: E = F(eta, mu)"
                  : spec.part == DielectricPart::kTransmission
                      ? "alpha < 1e-4 is the smooth interface: E = 1 - F(eta, mu)"
                      : "alpha < 1e-4 is the smooth interface: E = 1 - (1 - mu)^5";
  } else if (spec.GenSchlick()) {
    j["mirror"] = "alpha < 1e-4 is a mirror: s = s_h(mu)";
  } else if (spec.table == TableKind::kF82Bias) {
    j["mirror"] = "alpha < 1e-4 is a mirror: b = mu (1 - mu)^6";
  } else if (spec.model.kind != ModelKind::kDisneyDiffuse) {
    j["mirror"] = "alpha < 1e-4 is a mirror: E = 1";
  }
  return j.dump();
}

}  // namespace

namespace {

// E_avg = 2 int E(mu) mu dmu = 4 int_0^1 E(s^2) s^3 ds by adaptive
// Gauss-Kronrod 15 in s from the pieces [0, 1/4], [1/4, 1]: the worst piece
// is bisected until the sum of |K15 - G7| plus the propagated error of E
// meets the tolerance (or bisection stops helping: the rule's part below a
// tenth of it, or 64 pieces). E near grazing has a boundary layer, and for
// the heavy-tailed STD a non-smooth one, which a fixed rule resolved only to
// ~1e-5. `e_at(mu)` gives E and its error. `grade_levels` > 0 cuts [1/4, 1]
// geometrically (ratio 4) towards s = 1 from the start (StdEavgGrading).
template <class EAt>
EavgEstimate AdaptiveEavg(const EAt& e_at, double tolerance, int grade_levels = 0) {
  using Piece = GkPiece;
  auto piece = [&](double a, double b) {
    return KronrodPiece(a, b, 1.0, [&](double sv, double* err) {
      const TexelEstimate v = e_at(sv * sv);
      const double jac = 4 * sv * sv * sv;
      *err = jac * v.err_e;
      return jac * v.e;
    });
  };
  std::vector<Piece> pieces = {piece(0.0, 0.25)};
  double a = 0.25;
  for (int k = 1; k <= grade_levels; ++k) {
    const double b = 1 - 0.75 * std::pow(4.0, -k);
    pieces.push_back(piece(a, b));
    a = b;
  }
  pieces.push_back(piece(a, 1.0));
  auto sums = [&](double* rule, double* prop) {
    *rule = *prop = 0;
    for (const Piece& p : pieces) {
      *rule += p.err;
      *prop += p.prop;
    }
  };
  double rule_err, prop_err;
  sums(&rule_err, &prop_err);
  while (rule_err + prop_err > tolerance && rule_err > 0.1 * tolerance && pieces.size() < 64) {
    BisectWorst(&pieces, piece);
    sums(&rule_err, &prop_err);
  }
  double value = 0;
  for (const Piece& p : pieces) value += p.value;
  return {value, rule_err + prop_err + 4e-16 * value};
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
  TexelEstimate v;
  v.e = a.value;
  v.err_e = a.error;
  return v;
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

// ggx-aniso: E is even in phi_o and symmetric about pi/2, so [0, pi/2]
// covers every azimuth.
EavgEstimate AnisoEavg(const BakeSpec& spec, double r, double s) {
  return HemisphericalEavg(
      [&](double mu, double phi) { return AnisoTexel(spec, r, s, mu, phi); }, kHalfPi,
      spec.tolerance);
}

// For an E table over (mu, phi_o) (ellipsoid) or (mu, phi_o, r, s)
// (ggx-aniso, phi_o fastest of the rows): each texel's first texel of the
// same view and material. Where mu = 1 wo is the normal whatever phi_o;
// phi_o values within 1e-12 modulo 2 pi are one azimuth.
std::vector<int64_t> SameViewTexels(const BakeSpec& spec, const Axis& ax_mu, int width,
                                    int64_t total) {
  const int n_phi = spec.phi.size;
  std::vector<int> phi_first(n_phi);
  for (int y = 0; y < n_phi; ++y) {
    phi_first[y] = y;
    // (Quadratic in the phi_o count: skipped for very long axes.)
    for (int z = 0; z < y && n_phi <= 4096; ++z) {
      if (std::abs(std::remainder(spec.phi.Value(y) - spec.phi.Value(z), kTwoPi<double>)) <= 1e-12) {
        phi_first[y] = z;
        break;
      }
    }
  }
  std::vector<int64_t> same(static_cast<size_t>(total));
  for (int64_t idx = 0; idx < total; ++idx) {
    const int x = static_cast<int>(idx % width);
    const int64_t y = idx / width;
    const int yp = static_cast<int>(y % n_phi);
    const int64_t rest = y / n_phi;
    const int first = ax_mu.Value(x) >= 1 ? 0 : phi_first[yp];
    same[idx] = (rest * n_phi + first) * width + x;
  }
  return same;
}

// ellipsoid: E at (mu, phi_o) by the slope-plane rule (ellipsoid_albedo.h)
// for the material in spec.model.
// `tolerance` (default: the spec's) for E_avg's weighted nodes.
TexelEstimate EllipsoidTexel(const BakeSpec& spec, double mu, double phi, double tolerance = 0) {
  const ModelParams& m = spec.model;
  const double mu_c = std::max(mu, kMuMin);
  const double tol = tolerance > 0 ? tolerance : spec.tolerance;
  const RuleResult a =
      spec.simd ? SimdEllipsoidAlbedo(m.alpha_x, m.alpha_y, m.theta_x, m.theta_y, m.theta_z, mu_c,
                                      phi, spec.masking, tol, spec.EffectiveSamples())
                : EllipsoidAlbedo(m.alpha_x, m.alpha_y, m.theta_x, m.theta_y, m.theta_z, mu_c,
                                  phi, spec.masking, tol, spec.EffectiveSamples());
  TexelEstimate v;
  v.e = a.value;
  v.err_e = a.error;
  return v;
}

// E_avg = (1 / pi) int E cos dwo = int_0^1 4 s^3 A(s) ds, s = sqrt(mu), A
// the average of E over phi_o in [0, 2 pi) (a rotated ellipsoid has no
// azimuthal symmetry). E has a kink where G1(wo)'s clamp turns on, along
// the clamp's edge (ClampEdge, a closed curve of wo); elsewhere it is
// smooth. So:
// - A(s) is adaptive Gauss-Kronrod 15 over the arcs of phi_o between the
//   edge's crossings of cos(theta_o) = s^2 (one piece per quarter turn to
//   start with, the worst bisected until their |K15 - G7| sum is below a
//   third of the tolerance), its 15 or 30 values of E in parallel;
// - over s, SegmentRule with cuts at 1/4 (E's grazing layer) and at the
//   square roots of the edge's extremes of cos(theta_o), where an arc of
//   clamped views appears and A goes like |s - s*|^(3/2).
// The error: the rules' |K15 - G7| plus the propagated errors of E.
EavgEstimate EllipsoidEavg(const BakeSpec& spec) {
  const ModelParams& m = spec.model;
  const EllipsoidNdf<double> ndf(m.alpha_x, m.alpha_y, m.theta_x, m.theta_y, m.theta_z);
  const bool clamped = ndf.lambda_rho() < 1;
  const ClampEdge edge(ndf);
  // (theta, cos(theta_o)) along the edge, on kEdgeProbes points and its
  // refined extremes, in theta order.
  constexpr int kEdgeProbes = 64;
  std::vector<std::pair<double, double>> edge_points;
  std::vector<double> s_cuts;
  if (clamped) {
    auto mu_at = [&](double th) { return edge.At(th).z; };
    std::vector<double> probe(kEdgeProbes);
    for (int k = 0; k < kEdgeProbes; ++k) {
      probe[k] = mu_at(kTwoPi<double> * k / kEdgeProbes);
      edge_points.push_back({kTwoPi<double> * k / kEdgeProbes, probe[k]});
    }
    for (const EdgeExtreme& e : ExtremesOnEdge(mu_at, probe, [](double v, double) { return v; })) {
      // The edge passes through the normal (N of seed eq. 6 vanishes at
      // u = n), so one extreme is mu = 1, which golden-section search
      // returns as 1 or just below: either way a cut at s = 1, where the
      // arc of clamped views appears. (Dropping a value that rounded to 1
      // cost the s rule 4x the nodes: E_avg of the bench material took
      // 2.0 s instead of 0.7 s, and erred by 5.9e-10 instead of 1.6e-11.)
      if (e.value > 0) s_cuts.push_back(std::sqrt(std::min(e.value, 1.0)));
      // (t is within a probe step of [0, 2 pi).)
      const double t =
          e.theta < 0 ? e.theta + kTwoPi<double> : e.theta >= kTwoPi<double> ? e.theta - kTwoPi<double> : e.theta;
      edge_points.push_back({t, e.value});
    }
    std::sort(edge_points.begin(), edge_points.end());
  }
  // The phi_o in [0, 2 pi) where the edge crosses cos(theta_o) = mu0, ascending.
  auto crossings = [&](double mu0) {
    std::vector<double> phis;
    const size_t n = edge_points.size();
    for (size_t k = 0; k < n; ++k) {
      const size_t k1 = (k + 1) % n;
      const double a = edge_points[k].first, b = edge_points[k1].first + (k1 == 0 ? kTwoPi<double> : 0.0);
      const double da = edge_points[k].second - mu0, db = edge_points[k1].second - mu0;
      if (da == 0 || db == 0 || (da > 0) == (db > 0)) continue;
      const double t = SolveBracketed([&](double th) { return edge.At(th).z - mu0; }, a, b, da, db,
                                      1e-13);
      const Vec3<double> w = edge.At(t);
      const double phi = std::atan2(w.y, w.x);
      phis.push_back(phi < 0 ? phi + kTwoPi<double> : phi);
    }
    std::sort(phis.begin(), phis.end());
    return phis;
  };
  const double tol = spec.tolerance;
  const KronrodRule& r = Kronrod15();
  // A(s) times 2 pi (SegmentRule divides by 2 pi) and 4 s^3.
  auto weighted_average = [&](double s, double* err) {
    const double mu0 = s * s;
    // E enters with the weight 4 s^3: its tolerance is tol / max(4 s^3,
    // 1/32) (up to 32 tol near grazing, where E costs most), which bounds
    // its part of the propagated error by the same tol as a uniform one
    // would (20% to 30% faster, measured).
    const double tol_e = tol / std::max(4 * s * s * s, 1.0 / 32);
    std::vector<double> cuts = crossings(mu0);
    std::vector<std::pair<double, double>> arcs;
    if (cuts.empty()) {
      arcs.push_back({0.0, kTwoPi<double>});
    } else {
      for (size_t i = 0; i < cuts.size(); ++i) {
        arcs.push_back({cuts[i], i + 1 < cuts.size() ? cuts[i + 1] : cuts[0] + kTwoPi<double>});
      }
    }
    std::vector<GkPiece> pieces;
    // Pieces [a, b] of phi_o, their 15 values of E computed in parallel.
    auto evaluate = [&](const std::vector<std::pair<double, double>>& ab) {
      std::vector<TexelEstimate> e(15 * ab.size());
      tbb::parallel_for(size_t(0), e.size(), [&](size_t k) {
        const double c = 0.5 * (ab[k / 15].first + ab[k / 15].second);
        const double h = 0.5 * (ab[k / 15].second - ab[k / 15].first);
        e[k] = EllipsoidTexel(spec, mu0, c + h * r.x[k % 15], tol_e);
      });
      for (size_t j = 0; j < ab.size(); ++j) {
        double k = 0, g = 0, prop = 0;
        for (int i = 0; i < 15; ++i) {
          k += r.wk[i] * e[15 * j + i].e;
          g += r.wg[i] * e[15 * j + i].e;
          prop += r.wk[i] * e[15 * j + i].err_e;
        }
        const double h = 0.5 * (ab[j].second - ab[j].first);
        pieces.push_back(GkPiece{ab[j].first, ab[j].second, k * h, std::abs(k - g) * h, prop * h});
      }
    };
    std::vector<std::pair<double, double>> first;
    for (const auto& [a, b] : arcs) {
      const int n = std::max(1, static_cast<int>(std::ceil((b - a) / (kTwoPi<double> / 4) - 1e-9)));
      for (int i = 0; i < n; ++i) first.push_back({a + (b - a) * i / n, a + (b - a) * (i + 1) / n});
    }
    evaluate(first);
    auto rule_error = [&] {
      double e = 0;
      for (const GkPiece& p : pieces) e += p.err;
      return e / kTwoPi<double>;
    };
    while (rule_error() > tol / 3 && pieces.size() < 64) {
      size_t worst = 0;
      for (size_t i = 1; i < pieces.size(); ++i) {
        if (pieces[i].err > pieces[worst].err) worst = i;
      }
      const GkPiece p = pieces[worst];
      pieces.erase(pieces.begin() + worst);
      const double mid = 0.5 * (p.a + p.b);
      evaluate({{p.a, mid}, {mid, p.b}});
    }
    double value = 0, e = 0;
    for (const GkPiece& p : pieces) {
      value += p.value;
      e += p.err + p.prop;
    }
    const double w = 4 * s * s * s;  // times 2 pi / (2 pi)
    *err = w * e;
    return w * value;
  };
  std::vector<double> points = {0.0, 0.25, 1.0};
  for (double c : s_cuts) points.push_back(c);
  std::sort(points.begin(), points.end());
  std::vector<PsiSegment> segments;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    if (!(points[i + 1] > points[i])) continue;
    PsiSegment g{points[i], points[i + 1]};
    auto is_cut = [&](double x) {
      return std::find(s_cuts.begin(), s_cuts.end(), x) != s_cuts.end();
    };
    g.singular_a = is_cut(g.a);
    g.singular_b = is_cut(g.b);
    segments.push_back(g);
  }
  auto averages = [&](const double* s, int n, double* value, double* err) {
    for (int i = 0; i < n; ++i) {
      err[i] = 0;
      value[i] = weighted_average(s[i], &err[i]);
    }
  };
  const RuleResult res = SegmentRule(averages, segments, tol, 64);
  return {res.value, res.error};
}

}  // namespace

// For the STD below gamma 2 E(mu) is not smooth at normal incidence, and the
// adaptive E_avg rule bisected [1/4, 1] towards s = 1 again and again (8 to
// 10 times at gamma 1.501, each bisection 30 new E). Starting from the
// grading it converged to evaluates half as many E or fewer: measured over
// 64 roughnesses, Kronrod pieces (15 E each) evaluated per E_avg 18.0 -> 7.5
// at gamma 1.501 (4 levels), 14.2 -> 6.2 at 1.6 (3), 9.1 -> 4.8 at 1.8 (2);
// from gamma 2 on no grading is best (2.3 at 2 and 2.4 at 3, against 3.1
// with one level).
// ggx-glass with eta < 1 (the view inside the denser medium): E_avg as
// AdaptiveEavg, with one more cut at the critical cosine mu_c = sqrt(1 -
// eta^2), s_c = sqrt(mu_c). There the Fresnel factor of the facets about
// the normal reaches 1 with an infinite slope ([Walter07] eq. 22), so
// E(mu) has a square-root edge, smoothed over about alpha. The pieces on
// either side are mapped s = s_c -+ (s_c - a) (1 - t)^2 towards it (the
// square root becomes linear in t), as the rule maps its rays at the
// critical curve (glass_albedo.h); bisection is in t.
static EavgEstimate GlassEavg(const BakeSpec& spec, double alpha) {
  const double eta = spec.model.ior;
  const double sc = std::sqrt(std::sqrt((1 - eta) * (1 + eta)));
  struct Segment {
    double a, b;
    bool edge_a, edge_b;  // the critical cosine at that end
  };
  std::vector<Segment> segs;
  const double cuts[] = {0.0, 0.25, 1.0};
  for (int k = 0; k < 2; ++k) {
    const double a = cuts[k], b = cuts[k + 1];
    if (sc > a && sc < b) {
      segs.push_back({a, sc, false, true});
      segs.push_back({sc, b, true, false});
    } else {
      segs.push_back({a, b, false, false});
    }
  }
  struct Piece : GkPiece {
    int seg = 0;
  };
  auto piece = [&](int k, double t0, double t1) {
    const Segment& g = segs[size_t(k)];
    Piece p;
    static_cast<GkPiece&>(p) = KronrodPiece(t0, t1, 1.0, [&](double t, double* err) {
      double sv, ds;
      if (g.edge_b) {
        sv = g.b - (g.b - g.a) * (1 - t) * (1 - t), ds = 2 * (g.b - g.a) * (1 - t);
      } else if (g.edge_a) {
        sv = g.a + (g.b - g.a) * t * t, ds = 2 * (g.b - g.a) * t;
      } else {
        sv = g.a + (g.b - g.a) * t, ds = g.b - g.a;
      }
      const TexelEstimate v = Texel(spec, alpha, sv * sv, 0);
      const double jac = 4 * sv * sv * sv * ds;
      *err = jac * v.err_e;
      return jac * v.e;
    });
    p.seg = k;
    return p;
  };
  std::vector<Piece> pieces;
  for (int k = 0; k < int(segs.size()); ++k) pieces.push_back(piece(k, 0.0, 1.0));
  auto sums = [&](double* rule, double* prop) {
    *rule = *prop = 0;
    for (const Piece& p : pieces) {
      *rule += p.err;
      *prop += p.prop;
    }
  };
  double rule_err, prop_err;
  sums(&rule_err, &prop_err);
  const double tolerance = spec.tolerance;
  while (rule_err + prop_err > tolerance && rule_err > 0.1 * tolerance && pieces.size() < 64) {
    size_t worst = 0;
    for (size_t i = 1; i < pieces.size(); ++i) {
      if (pieces[i].err > pieces[worst].err) worst = i;
    }
    const Piece p = pieces[worst];
    const double m = 0.5 * (p.a + p.b);
    pieces[worst] = piece(p.seg, p.a, m);
    pieces.push_back(piece(p.seg, m, p.b));
    sums(&rule_err, &prop_err);
  }
  double value = 0;
  for (const Piece& p : pieces) value += p.value;
  return {value, rule_err + prop_err + 4e-16 * value};
}

static int StdEavgGrading(const BakeSpec& spec) {
  if (spec.model.kind != ModelKind::kStudentT) return 0;
  const double g = spec.model.gamma;
  return g < 1.6 ? 4 : g < 1.75 ? 3 : g < 2 ? 2 : 0;
}

EavgEstimate IntegrateBiasAvg(const BakeSpec& spec, double roughness) {
  BakeSpec s = spec;
  s.table = TableKind::kDfg;
  ValidateBakeSpec(s);  // a model with a dfg table
  if (s.integrator != IntegratorKind::kQuadrature) Bad("the dfg bias average is integrated by the quadrature");
  const double alpha = AlphaFromRoughness(roughness);
  return AdaptiveEavg(
      [&](double mu) {
        const TexelEstimate v = Texel(s, alpha, mu, 0);
        TexelEstimate b;
        b.e = v.bias;
        b.err_e = v.err_bias;
        return b;
      },
      s.tolerance, StdEavgGrading(s));
}

EavgEstimate IntegrateEavg(const BakeSpec& spec, double roughness, uint64_t index) {
  const double alpha = AlphaFromRoughness(roughness);
  if (spec.model.kind == ModelKind::kDisneyDiffuse && spec.integrator == IntegratorKind::kQuadrature) {
    const RuleResult r = spec.simd ? SimdDisneyEavg(roughness) : DisneyEavg(roughness);
    return {r.value, r.error};
  }
  if (spec.integrator == IntegratorKind::kQuadrature) {
    if (spec.Glass() && spec.model.ior < 1 && (alpha >= kMinAlpha<double> || spec.part != DielectricPart::kBoth)) {
      return GlassEavg(spec, alpha);
    }
    return AdaptiveEavg([&](double mu) { return Texel(spec, alpha, mu, 0); }, spec.tolerance,
                        StdEavgGrading(spec));
  }
  // The sampling integrators: a fixed rule, 32-node Gauss-Legendre in s
  // with the 16-node rule for the error estimate (each E carries its own
  // random error; bisecting on noise would not converge).
  static const GaussLegendre fine(32), coarse(16);
  auto rule = [&](const GaussLegendre& gl, uint64_t salt, double* err) {
    double acc = 0, acc_err = 0;
    for (size_t k = 0; k < gl.x.size(); ++k) {
      const double sv = gl.x[k];
      const TexelEstimate v =
          Texel(spec, alpha, sv * sv, Mix64(spec.seed ^ Mix64((index << 20) + k + salt)));
      const double wk = 4 * gl.w[k] * sv * sv * sv;
      acc += wk * v.e;
      acc_err += wk * v.err_e;
    }
    *err = acc_err;
    return acc;
  };
  double err_f, err_c;
  const double f = rule(fine, 0, &err_f);
  const double c = rule(coarse, 1 << 10, &err_c);
  return {f, std::abs(f - c) + err_f};
}

void ReleaseBakeCaches() { ClearStdAzimuthMoments(); }


Table Bake(const BakeSpec& spec, const ProgressFn& progress) {
  ValidateBakeSpec(spec);
  const auto start = std::chrono::steady_clock::now();
  Table t;
  t.spec = spec;
  t.model_json = ModelJson(spec);
  t.integrator_json = IntegratorJson(spec);
  const Axis& ax_mu = spec.mu;
  const Axis& ax_r = spec.roughness;
  const bool eavg = spec.table == TableKind::kEavg;
  const bool sel = spec.table == TableKind::kSelNorm;
  const bool ellipsoid = spec.model.kind == ModelKind::kEllipsoid;
  const bool aniso = spec.Anisotropic();
  TableShape shape = ShapeOf(spec);
  t.axes = std::move(shape.axes);
  t.width = int(shape.width);
  t.height = int(shape.height);
  // One spec per slice of a parameter axis, so every slice is baked
  // exactly as a table at that parameter would be: gamma (model.gamma set
  // from the axis), ggx-glass's ior (eta = ior, or 1 / ior inside);
  // gen_schlick's slices are set up per texel (GenSchlickSlice).
  std::vector<BakeSpec> slice_specs(1, spec);
  if (!t.axes.empty() && ParameterAxis(t.axes.back())) slice_specs.assign(size_t(t.axes.back().size), spec);
  if (spec.HasGammaAxis()) {
    for (int k = 0; k < spec.gamma.size; ++k) slice_specs[k].model.gamma = spec.gamma.Value(k);
  }
  if (spec.Glass()) {
    for (int k = 0; k < spec.ior.size; ++k) {
      const double ior = std::min(spec.ior.Value(k), spec.ior.clamp_max);
      slice_specs[k].model.ior = spec.inverse ? 1 / ior : ior;
    }
  }
  const int64_t total = shape.Texels();
  std::vector<double> error;
  // Every output buffer is allocated before the bake: a memory failure
  // comes first, not after the work.
  try {
    for (ChannelSpec& c : shape.channels) {
      t.channels.push_back({std::move(c.name), c.meaning, std::move(c.definition), {}, {}, {}});
    }
    for (Channel& c : t.channels) {
      c.values.resize(size_t(total));
      c.stored.resize(size_t(total));
      if (spec.half) c.half_bits.resize(size_t(total));
    }
    error.resize(size_t(total));
  } catch (const std::bad_alloc&) {
    char msg[160];
    std::snprintf(msg, sizeof(msg), "cannot allocate %.1f MiB for the %dx%d %s table (out of memory)",
                  double(BakeOutputBytes(spec)) / (1 << 20), t.width, t.height,
                  TableName(spec.table));
    throw std::runtime_error(msg);
  }

  std::unique_ptr<tbb::global_control> limit;
  if (spec.threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  spec.threads);
  }
#if BRDFBAKE_WITH_STD
  // The STD's azimuthal moment tables, built here with every thread (a
  // texel that built one would hold the others waiting on its lock).
  if (spec.model.kind == ModelKind::kStudentT &&
      (spec.integrator == IntegratorKind::kQuadrature || spec.integrator == IntegratorKind::kEngine) &&
      spec.table != TableKind::kDfg) {
    for (const BakeSpec& s : slice_specs) {
      const double g = StudentTNdf<double>(1.0, 1.0, s.model.gamma).gamma();
      if (std::isfinite(g)) StdAzimuthMomentsFor(g);
    }
  }
#endif
  std::atomic<int64_t> done{0};
  std::vector<double>& v0 = t.channels[0].values;
  const double e_max = StoredEMax(spec);
  if (sel) {
    tbb::parallel_for(int64_t(0), total, [&](int64_t i) {
      const int x = static_cast<int>(i % t.width), y = static_cast<int>(i / t.width);
      const double ax = spec.alpha_x.Value(x), ay = spec.alpha_y.Value(y);
      const SelIntegral n = spec.simd ? SimdSelLobeIntegral(ax, ay, spec.tolerance)
                                      : SelLobeIntegral(ax, ay, spec.tolerance);
      v0[i] = n.n;
      t.channels[1].values[i] = n.ratio;
      error[i] = std::max(n.n_error, n.ratio_error);
      if (progress) progress(++done, total);
    });
  } else if (eavg) {
    tbb::parallel_for(int64_t(0), total, [&](int64_t i) {
      const int x = static_cast<int>(i % t.width), z = static_cast<int>(i / t.width);
      const double r = std::max(ax_r.Value(x), ax_r.clamp_min);
      const EavgEstimate e = ellipsoid ? EllipsoidEavg(spec)
                             : aniso   ? AnisoEavg(spec, r, spec.anisotropy.Value(z))
                                       : IntegrateEavg(slice_specs[z], r, uint64_t(i));
      const double value = std::clamp(e.value, 0.0, e_max);
      v0[i] = spec.complement ? 1.0 - value : value;
      error[i] = e.error;
      if (progress) progress(++done, total);
    });
  } else {
    // Texels whose views coincide are computed once: where mu = 1 every
    // phi_o is the same view, and phi_o values equal modulo 2 pi (0 and
    // 2 pi on an edges axis) are too. same_as[idx] is the first texel of
    // idx's view.
    const bool views = (ellipsoid || aniso) && spec.table == TableKind::kE;
    const std::vector<int64_t> same_as =
        views ? SameViewTexels(spec, ax_mu, t.width, total) : std::vector<int64_t>();
    tbb::parallel_for(int64_t(0), total, [&](int64_t idx) {
      if (!same_as.empty() && same_as[idx] != idx) return;
      const int x = static_cast<int>(idx % t.width), y = static_cast<int>(idx / t.width);
      const double mu = std::max(ax_mu.Value(x), ax_mu.clamp_min);
      TexelEstimate v;
      if (ellipsoid) {
        v = EllipsoidTexel(spec, mu, spec.phi.Value(y));
      } else if (aniso) {
        // Rows: phi_o fastest, then roughness, then anisotropy.
        const int yp = y % spec.phi.size, rest = y / spec.phi.size;
        const double r = std::max(ax_r.Value(rest % ax_r.size), ax_r.clamp_min);
        v = AnisoTexel(spec, r, spec.anisotropy.Value(rest / ax_r.size), mu, spec.phi.Value(yp));
      } else {
        const int ry = y % ax_r.size, z = y / ax_r.size;
        const double r = std::max(ax_r.Value(ry), ax_r.clamp_min);
        v = TableTexel(spec, slice_specs[z], z, r * r, mu, Mix64(spec.seed ^ Mix64(uint64_t(idx))));
      }
      if (spec.table != TableKind::kDfg) {
        // E, or a table of one quantity of its own (gen_schlick's s,
        // f82_bias) in v.e.
        const double e = std::clamp(v.e, 0.0, e_max);  // ClampToRange's E
        v0[idx] = spec.complement ? 1.0 - e : e;
        error[idx] = v.err_e;
      } else {
        const TexelEstimate c = ClampToRange({v.e, v.scale, v.bias, v.err_e, v.err_scale, v.err_bias});
        v0[idx] = c.scale;
        t.channels[1].values[idx] = c.bias;
        error[idx] = std::max(c.err_scale, c.err_bias);
        if (spec.complement) {
          t.channels[2].values[idx] = 1.0 - c.e;
          error[idx] = std::max(error[idx], c.err_e);
        }
      }
      if (progress) progress(++done, total);
    });
    for (int64_t idx = 0; idx < total && !same_as.empty(); ++idx) {
      if (same_as[idx] == idx) continue;
      v0[idx] = v0[same_as[idx]];
      error[idx] = error[same_as[idx]];
      if (progress) progress(++done, total);
    }
  }
  for (double e : error) t.integration_error = std::max(t.integration_error, e);
  if (spec.error_channel) t.channels.back().values = error;

  // Rounding to the pixel type, with dfg's scale + bias <= 1 kept in the
  // stored precision; the claim adds each texel's rounding to its error.
  const size_t nv = size_t(shape.value_channels);
  const PixelType pixel = spec.half ? PixelType::kHalf : PixelType::kFloat;
  double claim = 0;
  for (int64_t i = 0; i < total; ++i) {
    double worst = 0;
    double stored[3];
    for (size_t c = 0; c < nv; ++c) stored[c] = RoundToPixel(t.channels[c].values[i], pixel);
    if (spec.table == TableKind::kDfg) {
      RoundScaleBias(t.channels[0].values[i], t.channels[1].values[i], pixel, &stored[0], &stored[1]);
    }
    for (size_t c = 0; c < nv; ++c) {
      t.channels[c].stored[i] = float(stored[c]);
      worst = std::max(worst, std::abs(stored[c] - t.channels[c].values[i]));
    }
    claim = std::max(claim, error[i] + worst);
  }
  if (spec.error_channel) {
    Channel& ce = t.channels.back();
    for (int64_t i = 0; i < total; ++i) ce.stored[i] = float(RoundToPixel(ce.values[i], pixel));
  }
  if (spec.half) {
    for (Channel& c : t.channels) {
      for (int64_t i = 0; i < total; ++i) c.half_bits[i] = Imath::half(c.stored[i]).bits();
    }
  }
  t.max_abs_error = claim;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

double StoredEMax(const BakeSpec& spec) {
  const ModelKind m = spec.model.kind;
  return m == ModelKind::kCharlie || m == ModelKind::kDisneyDiffuse ? kInfinity : 1.0;
}

TexelEstimate ClampToRange(const TexelEstimate& v, double e_max) {
  TexelEstimate c = v;
  // E: the true value lies in [0, e_max], so the clamp only moves towards it.
  c.e = std::clamp(v.e, 0.0, e_max);
  // scale, bias >= 0 likewise; scale + bias <= 1 is kept by moving both
  // down by half the excess, and the move is added to their errors.
  double s = std::max(v.scale, 0.0), b = std::max(v.bias, 0.0);
  const double excess = s + b - 1.0;
  if (excess > 0) {
    s -= excess / 2;
    b -= excess / 2;
    if (s < 0) { b += s; s = 0; }
    if (b < 0) { s += b; b = 0; }
    c.err_scale += excess;
    c.err_bias += excess;
  }
  c.scale = s;
  c.bias = b;
  return c;
}

TexelEstimate IntegrateAnisoTexel(const BakeSpec& spec, double roughness, double anisotropy,
                                  double mu, double phi_o) {
  ValidateBakeSpec(spec);
  const TexelEstimate v = AnisoTexel(spec, roughness, anisotropy, mu, phi_o);
  return {v.e, v.scale, v.bias, v.err_e, v.err_scale, v.err_bias};
}

EavgEstimate IntegrateAnisoEavg(const BakeSpec& spec, double roughness, double anisotropy) {
  ValidateBakeSpec(spec);
  return AnisoEavg(spec, roughness, anisotropy);
}

TexelEstimate IntegrateTexel(const BakeSpec& spec, double roughness, double mu,
                             uint64_t texel_seed) {
  ValidateBakeSpec(spec);
  if (spec.GenSchlick()) {
    // Its value depends on the slice: one exponent or ior, a size-1 axis.
    const Axis& slice = spec.table == TableKind::kGenSchlickS ? spec.exponent : spec.ior;
    if (slice.size != 1) {
      Bad("{size}: one texel of " + std::string(TableName(spec.table)) + " is at one " + slice.name + " (got " +
          std::to_string(slice.size) + " slices)");
    }
  }
  return TableTexel(spec, spec, 0, AlphaFromRoughness(roughness), mu, Mix64(spec.seed ^ texel_seed));
}

}  // namespace brdfbake
