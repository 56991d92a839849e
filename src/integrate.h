// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Per-texel integrators of the albedo E(mu) and the split-sum DFG terms of
// a microfacet BRDF with F = 1, generic over the distribution type.
//
// All integrators write the albedo as an integral over the unit square of
// the model's microfacet-normal sampler: with m = S(u1, u2) of density
// p(m) and wi = reflect(wo, m),
//   E = int f(wi, wo) cos(theta_i) dwi
//     = int_[0,1]^2 f cos_i 4 (wo.m) / p(m) du1 du2,
// whose integrand is G2 / G1(wo) in [0, 1] for exact visible-normal
// sampling (seed 003 eq. 19) and is zero where wi falls below the horizon.
// The DFG terms weight it with 1 - Fc and Fc, Fc = (1 - wo.m)^5.

#ifndef BRDFBAKE_SRC_INTEGRATE_H_
#define BRDFBAKE_SRC_INTEGRATE_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <type_traits>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/ggx.h"
#include "brdfbake/std_ndf.h"
#include "quadrature.h"

namespace brdfbake {

// The value of one texel: E and the two DFG terms, each with its estimated
// absolute error.
struct TexelValue {
  double e = 0, scale = 0, bias = 0;
  double err_e = 0, err_scale = 0, err_bias = 0;
};

// Sampler and integrand weight per distribution type.
template <class Ndf>
struct VisibleSampler {
  static Vec3<double> Sample(const Ndf& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SampleVisible(wo, u1, u2);
  }
  // f cos_i / pdf(wi) for F = 1; exact VNDF sampling makes it G2 / G1(wo).
  static double Weight(const Ndf& ndf, const Vec3<double>& wo, const Vec3<double>& m,
                       const Vec3<double>& wi, double g1_wo, Masking masking) {
    return G2(ndf, wi, wo, m, masking) / g1_wo;
  }
};

template <>
struct VisibleSampler<StdNdf<double>> {
  using Ndf = StdNdf<double>;
  static Vec3<double> Sample(const Ndf& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SamplePseudoVnis(wo, u1, u2);
  }
  static double Weight(const Ndf& ndf, const Vec3<double>& wo, const Vec3<double>& m,
                       const Vec3<double>& wi, double, Masking masking) {
    const double pdf = ndf.PdfPseudoVnis(wo, m);
    if (!(pdf > 0)) return 0.0;
    const double g2 = G2(ndf, wi, wo, m, masking);
    // f cos_i / (pdf / (4 wo.m)) = D G2 (wo.m) / (wo.z pdf).
    return ndf.D(m) * g2 * Dot(wo, m) / (wo.z * pdf);
  }
};

// Whether the sampler's u2 is an azimuth (periodic): then the outer rule is
// the trapezoidal rule in u2, which converges geometrically for smooth
// periodic integrands; otherwise Gauss-Legendre after u2 = 3 s^2 - 2 s^3.
template <class Ndf>
struct PeriodicU2 : std::false_type {};
template <>
struct PeriodicU2<GgxNdf<double>> : std::true_type {};

// Accumulates (w, w Fc) for a sample of the unit square; returns wi.z so
// callers can locate the horizon.
template <class Ndf>
struct Integrand {
  const Ndf& ndf;
  Vec3<double> wo;
  Masking masking;
  double g1_wo;

  Integrand(const Ndf& n, const Vec3<double>& w, Masking mk)
      : ndf(n), wo(w), masking(mk), g1_wo(n.G1(w)) {}

  double HorizonZ(double u1, double u2) const {
    const Vec3<double> m = VisibleSampler<Ndf>::Sample(ndf, wo, u1, u2);
    return Reflect(wo, m).z;
  }
  // Returns false when wi is below the horizon (zero contribution).
  bool Eval(double u1, double u2, double* w, double* w_fc) const {
    const Vec3<double> m = VisibleSampler<Ndf>::Sample(ndf, wo, u1, u2);
    const Vec3<double> wi = Reflect(wo, m);
    if (!(wi.z > 0)) {
      *w = *w_fc = 0;
      return false;
    }
    const double v = VisibleSampler<Ndf>::Weight(ndf, wo, m, wi, g1_wo, masking);
    const double fc = SchlickWeight(Dot(wo, m));
    *w = v;
    *w_fc = v * fc;
    return true;
  }
};

// Deterministic quadrature. The square is mapped by u1 = sin^2(pi t / 2) and
// u2 = 3 s^2 - 2 s^3. For the GGX sampler sqrt(u1) is the radius rho of the
// visible-normal disk and the lift onto the hemisphere, sqrt(1 - rho^2),
// becomes cos(pi t / 2): smooth up to the rim, where it has a square-root
// singularity in rho. Both maps also flatten the endpoints of samplers whose
// inverse CDF is singular there (Beckmann's slopes).
// For each outer node s the inner integrand is continuous but has a kink
// where wi crosses the horizon (G2 vanishes linearly there): its zeros in t
// are bracketed on a probe grid, refined by bisection, and the rule is
// applied on each sub-interval where wi is above the horizon.
struct QuadratureResult {
  double e = 0, fc = 0;
};

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
template <class Ndf>
double HorizonLayer(const Ndf& ndf) {
  return std::min(0.25, 8.0 * std::max(ndf.alpha_x(), ndf.alpha_y()));
}

template <class Ndf>
QuadratureResult QuadratureRule(const Integrand<Ndf>& f, const GaussLegendre& outer,
                                const GaussLegendre& inner, int probes) {
  QuadratureResult r;
  const double layer = HorizonLayer(f.ndf);
  std::vector<double> cuts;
  // Solves HorizonZ(t) = level for t in [lo, hi], where the two ends are on
  // either side of the level.
  auto solve = [&](double lo, double hi, double u2, double level) {
    const bool lo_above = f.HorizonZ(U1(lo), u2) > level;
    for (int it = 0; it < 52 && hi - lo > 1e-15; ++it) {
      const double mid = 0.5 * (lo + hi);
      if ((f.HorizonZ(U1(mid), u2) > level) == lo_above) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
  };
  auto integrate = [&](double a, double b, double u2, double* acc, double* acc_fc) {
    for (size_t i = 0; i < inner.x.size(); ++i) {
      const double t = a + (b - a) * inner.x[i];
      double w, wfc;
      f.Eval(U1(t), u2, &w, &wfc);
      const double jac = inner.w[i] * (b - a) * DU1(t);
      *acc += jac * w;
      *acc_fc += jac * wfc;
    }
  };
  const bool periodic = PeriodicU2<Ndf>::value;
  const size_t n_outer = outer.x.size();
  for (size_t j = 0; j < n_outer; ++j) {
    double u2, du2;
    if (periodic) {
      u2 = (j + 0.5) / n_outer;
      du2 = 1.0 / n_outer;
    } else {
      const double s = outer.x[j];
      u2 = s * s * (3 - 2 * s);
      du2 = 6 * s * (1 - s) * outer.w[j];
    }
    // Bracket the horizon crossings along t on a probe grid.
    cuts.clear();
    cuts.push_back(0.0);
    double t_prev = 0.0;
    double z_prev = f.HorizonZ(0.0, u2);
    const bool first_above = z_prev > 0;
    for (int k = 1; k <= probes; ++k) {
      const double t = static_cast<double>(k) / probes;
      const double z = f.HorizonZ(U1(t), u2);
      if ((z > 0) != (z_prev > 0)) cuts.push_back(solve(t_prev, t, u2, 0.0));
      t_prev = t;
      z_prev = z;
    }
    cuts.push_back(1.0);
    // Sub-intervals alternate above/below the horizon, starting with
    // first_above; split each above-horizon one at the layer height next to
    // every end that lies on the horizon.
    double acc = 0, acc_fc = 0;
    bool above = first_above;
    for (size_t c = 0; c + 1 < cuts.size(); ++c, above = !above) {
      if (!above) continue;
      double a = cuts[c], b = cuts[c + 1];
      const bool a_on = c > 0, b_on = c + 2 < cuts.size();
      const double mid = 0.5 * (a + b);
      const bool mid_high = f.HorizonZ(U1(mid), u2) > layer;
      if (a_on && mid_high) {
        const double ca = solve(a, mid, u2, layer);
        integrate(a, ca, u2, &acc, &acc_fc);
        a = ca;
      }
      if (b_on && mid_high) {
        const double cb = solve(mid, b, u2, layer);
        integrate(cb, b, u2, &acc, &acc_fc);
        b = cb;
      }
      integrate(a, b, u2, &acc, &acc_fc);
    }
    r.e += du2 * acc;
    r.fc += du2 * acc_fc;
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

inline TexelValue FromTwo(const QuadratureResult& fine, const QuadratureResult& coarse) {
  TexelValue v;
  v.e = fine.e;
  v.bias = fine.fc;
  v.scale = fine.e - fine.fc;
  v.err_e = std::abs(fine.e - coarse.e);
  v.err_bias = std::abs(fine.fc - coarse.fc);
  v.err_scale = std::abs((fine.e - fine.fc) - (coarse.e - coarse.fc));
  // Floor at a few ulps of the stored magnitude.
  v.err_e = std::max(v.err_e, 4e-16);
  v.err_bias = std::max(v.err_bias, 4e-16);
  v.err_scale = std::max(v.err_scale, 4e-16);
  return v;
}

// The grazing limit mu -> 0 is evaluated at mu = kMuMin (SPEC: mu = 0 is the
// grazing limit; E is continuous there).
inline constexpr double kMuMin = 1e-7;

// Mirror (alpha below the clamp): h = n, E = 1, Fc = (1 - mu)^5.
inline TexelValue MirrorTexel(double mu) {
  TexelValue v;
  v.e = 1;
  v.bias = SchlickWeight(mu);
  v.scale = 1 - v.bias;
  return v;
}

// Quadrature refined along a ladder of node counts until two successive
// rules agree to `tol` (or `max_nodes` is reached); the value is the finer
// rule and its error estimate the difference between the last two, which
// bounds the finer rule's error when convergence is geometric.
template <class Ndf>
TexelValue QuadratureTexel(const Ndf& ndf, double mu, Masking masking, int max_nodes,
                           double tol) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  const Integrand<Ndf> f(ndf, wo, masking);
  const int probes = 24;
  static const int kLadder[] = {12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512,
                                768, 1024, 1536, 2048, 3072, 4096};
  QuadratureResult prev = QuadratureRule(f, CachedRule(kLadder[0]), CachedRule(kLadder[0]), probes);
  TexelValue v;
  for (int k = 1; k < int(std::size(kLadder)); ++k) {
    const int n = std::min(kLadder[k], std::max(max_nodes, kLadder[1]));
    const QuadratureResult cur = QuadratureRule(f, CachedRule(n), CachedRule(n), probes);
    v = FromTwo(cur, prev);
    if (std::max(v.err_e, std::max(v.err_scale, v.err_bias)) <= tol || n >= max_nodes) break;
    prev = cur;
  }
  return v;
}

// Randomized QMC: `replicas` Cranley-Patterson rotations of an
// n-point Hammersley set; the estimate is their mean and the error 4 times
// the standard error of the mean.
template <class Ndf>
TexelValue QmcTexel(const Ndf& ndf, double mu, Masking masking, int samples, uint64_t seed,
                    bool plain_mc) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  const Integrand<Ndf> f(ndf, wo, masking);
  const int replicas = 8;
  const int n = std::max(1, samples / replicas);
  Rng rng(seed);
  double sum_e = 0, sum_e2 = 0, sum_b = 0, sum_b2 = 0, sum_s = 0, sum_s2 = 0;
  for (int r = 0; r < replicas; ++r) {
    const double shift1 = rng.Uniform(), shift2 = rng.Uniform();
    double acc = 0, acc_fc = 0;
    for (int i = 0; i < n; ++i) {
      double u1, u2;
      if (plain_mc) {
        u1 = rng.Uniform();
        u2 = rng.Uniform();
      } else {
        u1 = (i + 0.5) / n + shift1;
        u2 = RadicalInverse2(static_cast<uint32_t>(i)) + shift2;
        u1 -= std::floor(u1);
        u2 -= std::floor(u2);
      }
      double w, wfc;
      f.Eval(u1, u2, &w, &wfc);
      acc += w;
      acc_fc += wfc;
    }
    const double e = acc / n, b = acc_fc / n, s = e - b;
    sum_e += e; sum_e2 += e * e;
    sum_b += b; sum_b2 += b * b;
    sum_s += s; sum_s2 += s * s;
  }
  auto err = [&](double sum, double sum2) {
    const double mean = sum / replicas;
    const double var = std::max(0.0, (sum2 - replicas * mean * mean) / (replicas - 1));
    return 4.0 * std::sqrt(var / replicas);
  };
  TexelValue v;
  v.e = sum_e / replicas;
  v.bias = sum_b / replicas;
  v.scale = sum_s / replicas;
  v.err_e = err(sum_e, sum_e2);
  v.err_bias = err(sum_b, sum_b2);
  v.err_scale = err(sum_s, sum_s2);
  return v;
}

// The engine setting: an N-point Hammersley set (no randomization) driving
// NDF sampling of the half vector, pdf(wi) = D(h) h.z / (4 wo.h), so the
// weight is G2 (wo.h) / (wo.z h.z).
template <class Ndf>
QuadratureResult EngineRule(const Ndf& ndf, double mu, Masking masking, int samples) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  QuadratureResult r;
  for (int i = 0; i < samples; ++i) {
    const double u1 = static_cast<double>(i) / samples;
    const double u2 = RadicalInverse2(static_cast<uint32_t>(i));
    const Vec3<double> h = ndf.SampleNdf(u1, u2);
    const Vec3<double> wi = Reflect(wo, h);
    const double wo_h = Dot(wo, h);
    if (!(wi.z > 0) || !(wo_h > 0) || !(h.z > 0)) continue;
    const double w = G2(ndf, wi, wo, h, masking) * wo_h / (wo.z * h.z);
    r.e += w;
    r.fc += w * SchlickWeight(wo_h);
  }
  r.e /= samples;
  r.fc /= samples;
  return r;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_INTEGRATE_H_
