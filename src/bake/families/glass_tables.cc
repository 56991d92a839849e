// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The glass family's baker row (family_row.h): ggx-glass, the rough
// dielectric's E over mu x roughness x ior and its E_avg, by the
// visible-normal rule of glass_albedo.h.

#include <algorithm>
#include <cmath>
#include <vector>

#include "bake/family_row.h"
#include "brdfbake/models/dielectric.h"
#include "lanes/glass_lanes.h"
#include "quadrature/adaptive_rule.h"
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

// ggx-glass with eta < 1 (the view inside the denser medium): E_avg as
// AdaptiveEavg, with one more cut at the critical cosine mu_c = sqrt(1 -
// eta^2), s_c = sqrt(mu_c). There the Fresnel factor of the facets about
// the normal reaches 1 with an infinite slope ([Walter07] eq. 22), so
// E(mu) has a square-root edge, smoothed over about alpha. The pieces on
// either side are mapped s = s_c -+ (s_c - a) (1 - t)^2 towards it (the
// square root becomes linear in t), as the rule maps its rays at the
// critical curve (glass_albedo.h); bisection is in t.
EavgEstimate GlassEavg(const BakeSpec& spec, double alpha) {
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
      const TexelEstimate v = GlassTexel(spec, alpha, sv * sv);
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

// E_avg at one texel: the rough interface by the rule over h and wo of
// glass_average.h, the smooth one (below alpha 1e-4) over mu, where E is
// closed-form (SmoothGlassAlbedo).
EavgEstimate GlassTexelEavg(const BakeSpec& spec, double alpha) {
  if (alpha >= kMinAlpha<double>) {
    const int n = spec.EffectiveSamples();
    const RuleResult r =
        spec.simd ? SimdGlassAlbedoAverage(alpha, spec.model.ior, spec.masking, spec.tolerance, n, spec.part)
                  : GlassAlbedoAverage(alpha, spec.model.ior, spec.masking, spec.tolerance, n, spec.part);
    return {r.value, r.error};
  }
  if (spec.model.ior < 1 && spec.part != DielectricPart::kBoth) return GlassEavg(spec, alpha);
  return AdaptiveEavg([&](double mu) { return GlassTexel(spec, alpha, mu); }, spec.tolerance);
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
          "15 at each level on pieces "
          "bisected worst first, graded towards the horizons down to alpha in the cosine" +
              std::string(spec.simd ? " (each psi piece's nodes in double SIMD lanes)" : " (double scalar code)") +
              "; error: "
          "the sum of |K15 - G7| with the inner levels' carried through the Kronrod weights. "
          "Below alpha 1e-4: 2 int_0^1 E(mu) mu dmu of the smooth interface. (domain, rule and "
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
    1.0};

}  // namespace

extern const BakerFamily kBakerFamily_glass = {&kGgxGlassRow, 1};

}  // namespace brdfbake
