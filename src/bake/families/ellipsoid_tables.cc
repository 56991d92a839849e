// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ellipsoid family's baker row (family_row.h): E over mu and phi_o and
// its E_avg (one value) by the slope-plane rule of ellipsoid_albedo.h.

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "bake/family_row.h"
#include "brdfbake/models/ellipsoid.h"
#include "lanes/ellipsoid_lanes.h"
#include "quadrature/adaptive_rule.h"
#include "quadrature/kronrod.h"
#include "quadrature/solve_bracketed.h"
#include "rules/ellipsoid/ellipsoid_albedo.h"
#include "rules/ellipsoid/ellipsoid_albedo_rule.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {
namespace {

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
  return AlbedoTexel(a);
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


void EllipsoidModelJson(const BakeSpec& spec, nlohmann::json* out) {
  nlohmann::json& j = *out;
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
}

void EllipsoidIntegratorJson(const BakeSpec& spec, nlohmann::json* j) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    Describe(j,
             "the slope plane of the half vector: the ellipsoid's slope density is a "
             "sheared and shifted GGX, uniform in polar coordinates (psi, u) around its "
             "peak; wi above the horizon is a disk in slopes, crossed by each ray in a "
             "segment found in closed form (src/rules/ellipsoid/ellipsoid_albedo.h)",
             "Gauss-Kronrod 15 over psi on pieces bisected worst first; along each ray "
             "Gauss-Kronrod 15 in sqrt(u), mapped towards the horizon crossings, cut "
             "at the kinks of G1's clamp and bisected worst first to a fifth of the "
             "tolerance (rays set up and nodes in double SIMD lanes, or the double "
             "scalar reference with --target scalar)",
             "sum over the psi pieces of |K15 - G7|, plus the rays' own sums of |K15 - G7| "
             "carried through the Kronrod weights");
  }
  if (spec.table == TableKind::kEavg) {
    (*j)["E_avg"] = "(1/pi) int E(wo) cos(theta_o) dwo = int_0^1 4 s^3 A(s) ds, s = sqrt(mu), by "
                    "adaptive Gauss-Kronrod 15 in s cut where G1(wo)'s clamp edge has extreme mu, A(s) "
                    "the average of E over phi_o in [0, 2 pi) by adaptive Gauss-Kronrod 15 on the arcs "
                    "between the clamp edge's crossings; error: the rules' |K15 - G7| plus the "
                    "propagated errors of E";
  }
  MirrorJson(j);
}

const BakerRow kEllipsoidRow = {
    ModelKind::kEllipsoid,
    Bit(TableKind::kE) | Bit(TableKind::kEavg),
    true,
    "E (over mu and phi_o) and E_avg (no dfg)",
    [](const BakeSpec& slice, const TexelAt& at, uint64_t) { return EllipsoidTexel(slice, at.mu, at.phi); },
    [](const BakeSpec& slice, const TexelAt&) { return EllipsoidEavg(slice); },
    nullptr,
    nullptr,
    EllipsoidModelJson,
    EllipsoidIntegratorJson,
    1.0,
    nullptr,
    true,
    // One material: E over the view (no azimuthal symmetry), E_avg one value.
    [](const BakeSpec& spec) {
      if (spec.table == TableKind::kEavg) return OwnAxes{{}, {}, "no size (the ellipsoid's E_avg is one value)"};
      return OwnAxes{{&BakeSpec::mu, &BakeSpec::phi}, {32, 16}, "WxH (mu x phi_o, e.g. 64x64)", kTwoPi<double>};
    }};

}  // namespace

extern const BakerFamily kBakerFamily_ellipsoid = {&kEllipsoidRow, 1};

}  // namespace brdfbake
