// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The deterministic quadrature of the texel integral (texel_integrand.h)
// over the square of the GGX visible-normal sampler: lines u2 = const,
// each integrated in t up to its horizon crossings, refined along a ladder
// of node counts.

#ifndef BRDFBAKE_TESTS_REFERENCE_DISK_QUADRATURE_H_
#define BRDFBAKE_TESTS_REFERENCE_DISK_QUADRATURE_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <type_traits>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "quadrature/gauss_legendre.h"
#include "quadrature/solve_bracketed.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

// Deterministic quadrature. The square is mapped by u1 = sin^2(pi t / 2). For the GGX sampler
// sqrt(u1) is the radius rho of the visible-normal disk and the lift onto
// the hemisphere, sqrt(1 - rho^2), becomes cos(pi t / 2): smooth up to the
// rim, where it has a square-root singularity in rho.
// (Beckmann and STD used to be integrated over their own samplers' squares:
// Beckmann's inverse-CDF + erfinv and the STD's pseudo-VNIS have endpoint
// singularities and a non-periodic u2, on which the rule converged slowly
// and often stopped at the node cap; see GgxDiskLines.)
// For each outer node u2 the inner integrand is continuous but has a kink
// where wi crosses the horizon (G2 vanishes linearly there): its zeros in t
// are bracketed on a probe grid, refined by a bracketing secant iteration,
// and the rule is applied on each sub-interval where wi is above the horizon.

inline double U1(double t) {
  const double s = std::sin(1.5707963267948966 * t);
  return s * s;
}
inline double DU1(double t) {  // d u1 / dt = (pi / 2) sin(pi t)
  return 1.5707963267948966 * std::sin(3.141592653589793 * t);
}

// The width of the layer near the horizon where G2 falls to zero: Lambda(wi)
// grows like alpha / (2 wi.z), so G2 changes over wi.z of a few alpha. Each
// above-horizon interval that ends (or starts) on the horizon is split where
// wi.z equals this height, so both pieces are smooth at the scale of the rule.
// The same height serves Beckmann and STD: their Lambda_std(a) has the same
// a = cot(theta) / alpha scaling (Beckmann's falls off faster, the STD's
// like a^(2 - 2 gamma) for large a), and the rule converges to the default
// tolerance with it for both (checked against an independent half-vector
// integration for alpha 1e-3..1, mu 0..1, gamma 1.55..inf).
template <class Ndf>
double HorizonLayer(const Ndf& ndf) {
  return std::min(0.25, 8.0 * std::max(ndf.alpha_x(), ndf.alpha_y()));
}

// The exponent of the weight's power law at the rim of the GGX disk for a
// model sampled by the GGX visible normals: D_M / D_ggx ~ r^(2 RimPower) for
// large standard slopes r. Beckmann and GGX: 0 or below (bounded weight).
// STD: 2 - gamma, so for gamma < 2 the weight grows like nh.z^(2 gamma - 4)
// towards the lower rim, where nh.z ~ (1 - t)^2 (and like (1 - t)^(2 gamma
// - 4) at normal incidence): in t the integrand behaves like (1 - t)^(4 gamma
// - 7), singular for gamma < 7/4 and of low smoothness up to gamma = 2 (the
// slope tail of the STD is heavier than GGX's there; at gamma -> 3/2 its
// mean slope diverges). Measured max of the weight over the square (alpha
// 1e-3..1, mu 1e-7..1): 3.7e5 at gamma 1.55, 476 at gamma 1.8, against
// <= 2.61 for Beckmann and gamma >= 2.5. The horizon always cuts the rim off
// (m.z -> 0 puts wi at -wo.z), but at grazing or small alpha the cut comes
// within ~alpha mu of it, so the rule grades its mesh towards the rim for
// these models (IntegrateLine).
template <class Ndf>
double RimPower(const Ndf&) {
  return 0;
}
inline double RimPower(const StudentTNdf<double>& ndf) {
  return std::isinf(ndf.gamma()) ? 0.0 : 2 - ndf.gamma();
}

// Accuracy in t of the horizon crossings. The integrand is continuous there
// and vanishes linearly (or, at a tangential crossing, like a square root),
// so a split point off by d changes the integral by O(d^2) (O(d^1.5)): far
// below double precision for d = 1e-11.
inline constexpr double kCrossingTol = 1e-11;
// The layer split is only a choice of sub-intervals (the integrand is smooth
// across it): any point near the layer height serves.
inline constexpr double kLayerRelTol = 1e-3;

// The integrand restricted to one line u2 = const of the quadrature's
// square, as a function of t: Z(t) = wi.z and Eval(t) = (w, w Fc). Every
// baked model uses the GGX disk (GgxDiskLines below, LineFamily after it).

// The GGX visible-normal sampler ([Heitz18], Listing 1) as the
// parameterisation of the square, for GGX itself and for the other
// slope-space models (Beckmann, STD) with the same alpha_x, alpha_y, with
// everything that depends only on wo precomputed per texel and cos / sin of
// the disk azimuth per line.
//
// For GGX the weight is G2 / G1(wo). For a model M sampled by the GGX
// visible normals, pdf(m) = G1_ggx(wo) (wo.m) D_ggx(m) / wo.z, and
//   f cos_i / pdf(wi) = D_M(m) G2_M(wi, wo, m) (wo.m) / (wo.z pdf(m))
//                     = [D_M(m) / D_ggx(m)] G2_M / G1_ggx(wo).
// Both D share the stretch (ax, ay), so D_M / D_ggx = P22_M(r^2) / P22_ggx(r^2)
// = pi (1 + r^2)^2 P22_M(r^2), where r^2 is the squared standard slope of
// the hemisphere-configuration normal nh, (nh.x^2 + nh.y^2) / nh.z^2.
// That ratio is bounded when M's slope tail is no heavier than GGX's:
// Beckmann exp(-r^2) (1 + r^2)^2 <= 4/e, STD gamma >= 2 (the ratio decays
// like r^(4 - 2 gamma)); with G2_M <= G1_M(wo) and G1_M / G1_ggx(wo) <=
// sqrt(pi) at grazing the weight stays below ~2.61 (measured max 2.608 over
// the square, alpha 1e-3..1, mu 1e-7..1). For STD gamma < 2 it grows like
// r^(4 - 2 gamma) towards the rim of the disk (nh.z -> 0): see RimPower.
//
// With wo at azimuth 0 (wo.y = 0) the basis is t1 = (0, 1, 0) (or (1, 0, 0)
// at normal incidence, where the integrand is rotationally symmetric), so the
// disk point (p1, p2) -> (-p1, p2), i.e. phi -> pi - phi, u2 -> 1/2 - u2,
// flips the sign of nh.y, m.y and wi.y and nothing else: every other
// quantity is computed from the same operands (the y products with wo.y = 0
// and with the zero components of t2 and vh are signed zeros; r^2 and
// Lambda use squares of y components), so the integrand is bit-for-bit
// symmetric and the outer rule evaluates half of its lines.
template <class Ndf>
struct GgxDiskLines {
  static constexpr bool kMirrorU2 = true;
  static constexpr bool kIsGgx = std::is_same_v<Ndf, GgxNdf<double>>;
  const Ndf* ndf;
  Vec3<double> wo, vh, t1, t2;
  double ax, ay, sh, lambda_wo, lambda_ggx_wo;
  bool separable;
  explicit GgxDiskLines(const Integrand<Ndf>& f)
      : ndf(&f.ndf), wo(f.wo), ax(f.ndf.alpha_x()), ay(f.ndf.alpha_y()),
        separable(f.masking == Masking::kSeparable) {
    vh = Normalize(Vec3<double>(ax * wo.x, ay * wo.y, wo.z));
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    t1 = lensq > 0 ? Vec3<double>(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : Vec3<double>(1, 0, 0);
    t2 = Cross(vh, t1);
    sh = 0.5 * (1 + vh.z);
    lambda_wo = f.ndf.Lambda(wo);
    lambda_ggx_wo = GgxLambda(wo);
  }
  // GGX Lambda with 1/a^2 = (ax^2 x^2 + ay^2 y^2) / z^2.
  double GgxLambda(const Vec3<double>& w) const {
    const double px = ax * w.x, py = ay * w.y;
    return GgxLambdaOfInvA2((px * px + py * py) / (w.z * w.z));
  }
  double Lambda(const Vec3<double>& w) const {
    if constexpr (kIsGgx) {
      return GgxLambda(w);
    } else {
      return ndf->Lambda(w);
    }
  }
  struct Line {
    const GgxDiskLines* fam;
    double c, s;  // cos, sin of the disk azimuth 2 pi u2
    // The hemisphere-configuration normal at disk radius sqrt(u1) = sin(pi t / 2).
    Vec3<double> Hemi(double t) const {
      const GgxDiskLines& F = *fam;
      const double r = std::sin(1.5707963267948966 * t);
      const double p1 = r * c;
      const double p2 = (1 - F.sh) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + F.sh * (r * s);
      const double lift = std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2));
      return F.t1 * p1 + F.t2 * p2 + F.vh * lift;
    }
    Vec3<double> Normal(const Vec3<double>& nh) const {
      const GgxDiskLines& F = *fam;
      return Normalize(Vec3<double>(F.ax * nh.x, F.ay * nh.y, std::max(0.0, nh.z)));
    }
    double Z(double t) const { return Reflect(fam->wo, Normal(Hemi(t))).z; }
    void Eval(double t, double* w, double* w_fc) const {
      const GgxDiskLines& F = *fam;
      const Vec3<double> nh = Hemi(t);
      const Vec3<double> m = Normal(nh);
      const double wo_m = Dot(F.wo, m);
      const Vec3<double> wi = m * (2 * wo_m) - F.wo;
      // wi.m = wo.m for a reflection.
      if (!(wi.z > 0) || !(wo_m > 0)) {
        *w = *w_fc = 0;
        return;
      }
      const double lambda_wi = F.Lambda(wi);
      double v;
      if constexpr (kIsGgx) {
        // G2 / G1(wo): G1(wi) (separable) or (1 + L(wo)) / (1 + L(wi) + L(wo)).
        v = F.separable ? 1 / (1 + lambda_wi)
                        : (1 + F.lambda_wo) / (1 + lambda_wi + F.lambda_wo);
      } else {
        // [D_M / D_ggx] G2_M / G1_ggx(wo). nh.z > 0 here (m.z = 0 would put
        // wi at -wo.z), so r2 is finite.
        const double r2 = (nh.x * nh.x + nh.y * nh.y) / (nh.z * nh.z);
        const double q = 1 + r2;
        const double ratio = kPi<double> * F.ndf->UnitP22(r2) * (q * q);
        const double g2 = F.separable ? 1 / ((1 + lambda_wi) * (1 + F.lambda_wo))
                                      : 1 / (1 + lambda_wi + F.lambda_wo);
        v = ratio * g2 * (1 + F.lambda_ggx_wo);
      }
      *w = v;
      *w_fc = v * SchlickWeight(wo_m);
    }
  };
  Line At(double u2) const {
    const double phi = 6.283185307179586 * u2;
    return {this, std::cos(phi), std::sin(phi)};
  }
};

template <class Ndf>
struct LineFamily : GgxDiskLines<Ndf> {
  using GgxDiskLines<Ndf>::GgxDiskLines;
};

// One inner integral: the rule on [0, 1] in t along `line`, split at the
// horizon crossings and at the layer height next to them.
//
// With `grade_rim` every interval is further cut at t = 1 - 2^-k (k >= 1), a
// mesh graded geometrically towards the rim t = 1 of the disk, where the
// weight of a model with a heavier slope tail than GGX (STD gamma < 2) is
// singular (see RimPower); each piece then lies at a distance from t = 1 at
// least its own width, so the rule converges geometrically on every piece
// at a rate independent of how close the horizon cut comes to the rim.
template <class LineT>
void IntegrateLine(const LineT& line, const GaussLegendre& inner, int probes, double layer,
                   bool grade_rim, std::vector<double>* cuts_buf, double* acc, double* acc_fc) {
  std::vector<double>& cuts = *cuts_buf;
  auto integrate_piece = [&](double a, double b) {
    for (size_t i = 0; i < inner.x.size(); ++i) {
      const double t = a + (b - a) * inner.x[i];
      double w, wfc;
      line.Eval(t, &w, &wfc);
      const double jac = inner.w[i] * (b - a) * DU1(t);
      *acc += jac * w;
      *acc_fc += jac * wfc;
    }
  };
  auto integrate = [&](double a, double b) {
    if (!grade_rim) {
      integrate_piece(a, b);
      return;
    }
    // 1 - 2^-k is exact in double; 48 levels reach 1 - t ~ 4e-15, below
    // which the disk point no longer changes in double.
    double step = 0.5;
    for (int k = 1; k <= 48 && a < b; ++k, step *= 0.5) {
      const double g = 1 - step;
      if (g <= a) continue;
      const double e = std::min(g, b);
      integrate_piece(a, e);
      a = e;
    }
    if (a < b) integrate_piece(a, b);
  };
  auto z_at = [&](double t) { return line.Z(t); };
  // Bracket the horizon crossings along t on a probe grid.
  cuts.clear();
  cuts.push_back(0.0);
  double t_prev = 0.0;
  double z_prev = line.Z(0.0);
  const bool first_above = z_prev > 0;
  for (int k = 1; k <= probes; ++k) {
    const double t = static_cast<double>(k) / probes;
    const double z = line.Z(t);
    if ((z > 0) != (z_prev > 0)) {
      cuts.push_back(SolveBracketed(z_at, t_prev, t, z_prev, z, kCrossingTol));
    }
    t_prev = t;
    z_prev = z;
  }
  cuts.push_back(1.0);
  // Sub-intervals alternate above/below the horizon, starting with
  // first_above; split each above-horizon one at the layer height next to
  // every end that lies on the horizon.
  bool above = first_above;
  for (size_t c = 0; c + 1 < cuts.size(); ++c, above = !above) {
    if (!above) continue;
    double a = cuts[c], b = cuts[c + 1];
    const bool a_on = c > 0, b_on = c + 2 < cuts.size();
    if (!a_on && !b_on) {
      integrate(a, b);
      continue;
    }
    const double mid = 0.5 * (a + b);
    const double z_mid = line.Z(mid);
    if (z_mid > layer) {
      auto g = [&](double t) { return line.Z(t) - layer; };
      const double tol = kLayerRelTol * (b - a);
      if (a_on) {
        const double ca = SolveBracketed(g, a, mid, -layer, z_mid - layer, tol);
        integrate(a, ca);
        a = ca;
      }
      if (b_on) {
        const double cb = SolveBracketed(g, mid, b, z_mid - layer, -layer, tol);
        integrate(cb, b);
        b = cb;
      }
    }
    integrate(a, b);
  }
}

template <class Ndf>
QuadratureResult QuadratureRule(const LineFamily<Ndf>& family, double layer, bool grade_rim,
                                int n_outer, const GaussLegendre& inner, int probes) {
  // u2 is the azimuth of the GGX disk: periodic, so the outer rule is the
  // trapezoidal rule, which converges geometrically for smooth periodic
  // integrands.
  QuadratureResult r;
  std::vector<double> cuts;
  if (grade_rim) {
    // The inner integral I(u2) of a model whose weight is singular at the
    // rim (RimPower > 0) is itself singular, algebraically, at u2 = 0 and
    // 1/2 (phi = 0, pi: the plane of incidence, where the lower rim, on
    // which nh.z -> 0, meets the upper rim, on which wo.m -> 0). There
    // the trapezoidal rule in u2 converges only like n^-2.4 (measured, STD
    // gamma 1.6 at grazing). Each half period [h/2, (h+1)/2] is mapped by
    // Sidi's sin^4 transformation u2 = h/2 + psi(s)/2, psi'(s) = (8/3)
    // sin^4(pi s), which vanishes to fourth order at both singular points,
    // and the trapezoidal rule at the midpoints s = (j + 1/2)/k, k = n/2 per
    // half, is applied; the mirror u2 -> 1/2 - u2 maps s -> 1 - s within
    // each half, so node j pairs with k - 1 - j.
    const int k = std::max(1, n_outer / 2);
    for (int h = 0; h < 2; ++h) {
      for (int j = 0; j < k; ++j) {
        const int jm = k - 1 - j;
        if (jm < j) continue;
        const double count = jm > j ? 2 : 1;
        const double sv = (j + 0.5) / k;
        const double a = 6.283185307179586 * sv;
        // psi(s) = s - (8/3) [sin(2 pi s) / (4 pi) - sin(4 pi s) / (32 pi)],
        // psi'(s) = (3 - 4 cos(2 pi s) + cos(4 pi s)) / 3.
        const double psi = sv - (8.0 / 3.0) * (std::sin(a) / 12.566370614359172 -
                                               std::sin(2 * a) / 100.53096491487338);
        const double dpsi = (3 - 4 * std::cos(a) + std::cos(2 * a)) / 3;
        double acc = 0, acc_fc = 0;
        IntegrateLine(family.At(0.5 * h + 0.5 * psi), inner, probes, layer, grade_rim, &cuts,
                      &acc, &acc_fc);
        const double wgt = count * dpsi * 0.5 / k;
        r.e += wgt * acc;
        r.fc += wgt * acc_fc;
      }
    }
  } else {
    // Trapezoidal rule at the midpoints u2 = (j + 1/2) / n. With the mirror
    // symmetry and n even, node j pairs with (n/2 - 1 - j) mod n: each pair
    // is evaluated once and counted twice (a node that is its own mirror,
    // u2 = 1/4 or 3/4 when n = 2 mod 4, once).
    const bool mirror = LineFamily<Ndf>::kMirrorU2 && n_outer % 2 == 0;
    for (int j = 0; j < n_outer; ++j) {
      double count = 1;
      if (mirror) {
        const int jm = ((n_outer / 2 - 1 - j) % n_outer + n_outer) % n_outer;
        if (jm < j) continue;
        if (jm > j) count = 2;
      }
      double acc = 0, acc_fc = 0;
      IntegrateLine(family.At((j + 0.5) / n_outer), inner, probes, layer, grade_rim, &cuts, &acc,
                    &acc_fc);
      r.e += count * acc;
      r.fc += count * acc_fc;
    }
    r.e /= n_outer;
    r.fc /= n_outer;
  }
  return r;
}

// Rules for each node count, built once.
inline const GaussLegendre& CachedRule(int n) {
  static thread_local std::vector<std::unique_ptr<GaussLegendre>> cache;
  if (static_cast<int>(cache.size()) <= n) cache.resize(n + 1);
  if (!cache[n]) cache[n] = std::make_unique<GaussLegendre>(n);
  return *cache[n];
}

// Quadrature refined along a ladder of node counts, doubling, until two
// successive rules agree to `tol` (or `max_nodes` is reached); the value is
// the finer rule and its error estimate the difference between the last two.
// That bounds the finer rule's error whenever one doubling at least halves
// the error, i.e. for any convergence faster than O(1/n): geometric in the
// smooth regime, and also the algebraic pre-asymptotic convergence where the
// outer integrand is not smooth (a line grazing the horizon curve) or the
// rule does not yet resolve the lobe at small alpha. Closer steps (x4/3,
// x3/2) need O(n^-2.4) for the same guarantee and under-claimed there.
template <class Ndf>
TexelEstimate QuadratureTexel(const Ndf& ndf, double mu, Masking masking, int max_nodes,
                           double tol) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  const Integrand<Ndf> f(ndf, wo, masking);
  const LineFamily<Ndf> family(f);
  const double layer = HorizonLayer(ndf);
  const bool grade_rim = RimPower(ndf) > 0;
  // For the models sampled through the GGX disk, whose weight varies over
  // the whole disk (D_M / D_ggx), 12 and 24 nodes can agree by accident
  // (measured: STD gamma 2.5, alpha 0.01, mu = 1 agreed to 3e-11 with a true
  // error of 1.2e-10), so convergence is only accepted from the 48-node rule
  // on. GGX keeps its ladder (its weight G2 / G1 is flat except near the
  // horizon, where the layer split resolves it).
  const int min_k = std::is_same_v<Ndf, GgxNdf<double>> ? 1 : 2;
  const int probes = 24;
  static const int kLadder[] = {12, 24, 48, 96, 192, 384, 768, 1536, 3072, 4096};
  QuadratureResult prev =
      QuadratureRule(family, layer, grade_rim, kLadder[0], CachedRule(kLadder[0]), probes);
  TexelEstimate v, v_prev;
  for (int k = 1; k < int(std::size(kLadder)); ++k) {
    const int n = std::min(kLadder[k], std::max(max_nodes, kLadder[1]));
    const QuadratureResult cur =
        QuadratureRule(family, layer, grade_rim, n, CachedRule(n), probes);
    v = FromTwo(cur, prev);
    const bool converged =
        k >= min_k && std::max(v.err_e, std::max(v.err_scale, v.err_bias)) <= tol;
    if (!converged && n >= max_nodes && k >= 2) {
      // Stopped by the node cap short of the tolerance: the rule may not
      // yet be in its asymptotic regime, so the claim is the sum of the last
      // two differences. If the error shrinks by a factor rho per doubling,
      // the error of the finer rule is rho / (1 - rho) times the last
      // difference and the claim (1 + 1 / rho) times it: a bound for any
      // rho <= 1 / sqrt(2), i.e. convergence faster than O(n^-1/2), where
      // the last difference alone needs rho <= 1/2 (O(1/n)).
      v.err_e += v_prev.err_e;
      v.err_scale += v_prev.err_scale;
      v.err_bias += v_prev.err_bias;
    }
    if (converged || n >= max_nodes) break;
    prev = cur;
    v_prev = v;
  }
  return v;
}


}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_DISK_QUADRATURE_H_
