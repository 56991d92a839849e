// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Physics of the STD (Student's t slopes, [Ribardiere17]) scalar reference:
// normalization of D, the projected-area identity of G1, Lambda against its
// defining integral ([Ribardiere17] eq. 17 with P2 of eq. 15), against the closed
// forms of section 4 and the rows of Table 1, the GGX (gamma = 2) and
// Beckmann (gamma -> inf) limits, the behaviour near gamma = 1.5, and
// chi-square tests of the NDF sampler and of the pseudo-VNIS of Algorithm 1.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <gtest/gtest.h>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Params {
  double ax, ay, gamma;
};

// n log-spaced points from lo to hi.
std::vector<double> LogGrid(double lo, double hi, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = lo * std::pow(hi / lo, i / double(n - 1));
  return v;
}

// ---------------------------------------------------------------------------
// D

// The unit-roughness slope density integrates to 1 over the slope plane:
// int_0^inf pi P22(s) ds = 1 (s = r^2).
TEST(StudentTTest, SlopeDensityIsNormalized) {
  boost::math::quadrature::exp_sinh<double> integrator;
  for (double gamma : {1.6, 2.0, 2.5, 7.5, 100.0}) {
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    // s = t^2 spreads the heavy tail (P22 ~ s^-gamma) over a wider range.
    const double integral = integrator.integrate(
        [&](double t) { return 2.0 * t * kPi<double> * ndf.UnitP22(t * t); }, 0.0, kInf, 1e-14);
    std::printf("gamma=%g  int pi P22 ds = %.15f\n", gamma, integral);
    EXPECT_NEAR(integral, 1.0, 1e-12) << gamma;
  }
}

TEST(StudentTTest, DIsNormalized) {
  const Params params[] = {{0.5, 0.5, 1.6}, {0.3, 0.3, 2.5}, {0.5, 0.5, 7.5},
                           {0.5, 0.1, 1.6}, {0.5, 0.1, 2.5}, {0.5, 0.1, 7.5},
                           {1.0, 1.0, 3.0}, {0.2, 0.6, 20.0}};
  for (const Params& p : params) {
    const StudentTNdf<double> ndf(p.ax, p.ay, p.gamma);
    const double integral = test::IntegrateHemisphereTheta(
        [&](const test::Dir& m) { return ndf.D(m) * m.z; }, 0.0, kPi<double> / 2, 1e-10);
    std::printf("std ax=%g ay=%g gamma=%g  int D cos = %.12f\n", p.ax, p.ay, p.gamma, integral);
    EXPECT_NEAR(integral, 1.0, 1e-6) << p.ax << " " << p.ay << " " << p.gamma;
  }
}

// ---------------------------------------------------------------------------
// Lambda: the projected-area identity (tests Lambda and D together)

// Integral over the upper hemisphere of f(m) max(0, v.m) dm, as
// test::IntegrateVisibleHemisphere (only the arc v.m > 0 of each circle of
// latitude is integrated), but in the variable t with mu = cos(theta) = t^6,
// dw = 6 t^5 dt dphi. The STD's D(m) behaves like mu^(2 gamma - 4) at the
// horizon (P22 ~ tan^(-2 gamma)), an integrable singularity for
// gamma < 2 that bisection in theta does not resolve; t^6 makes the
// integrand bounded for gamma >= 1.6 (exponent 12 gamma - 19 > 0).
double IntegrateVisibleHemisphereSingular(const std::function<double(const test::Dir&)>& f,
                                          const test::Dir& v, double tol = 1e-10) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  const double sin_v = std::sqrt(std::max(0.0, 1.0 - v.z * v.z));
  const double phi_v = sin_v > 0 ? std::atan2(v.y, v.x) : 0.0;
  auto inner = [&](double t) {
    const double t2 = t * t, t5 = t2 * t2 * t;
    const double mu = t5 * t, s = std::sqrt(std::max(0.0, (1 - mu) * (1 + mu)));
    auto g = [&](double phi) {
      const test::Dir m(s * std::cos(phi), s * std::sin(phi), mu);
      return f(m) * std::max(0.0, Dot(v, m));
    };
    // v.m = s sin_v cos(phi - phi_v) + mu v.z > 0.
    const double a = s * sin_v, b = mu * v.z;
    double arc;
    if (a <= std::abs(b)) {
      if (b <= 0) return 0.0;
      arc = GK::integrate(g, 0.0, 2.0 * kPi<double>, 15, tol);
    } else {
      const double half = std::acos(std::clamp(-b / a, -1.0, 1.0));
      arc = GK::integrate(g, phi_v - half, phi_v + half, 15, tol);
    }
    return 6.0 * t5 * arc;
  };
  return GK::integrate(inner, 0.0, 1.0, 15, tol);
}

// Smith: int G1(v) max(0, v.m) D(m) dm = v.z.
TEST(StudentTTest, ProjectedAreaIdentity) {
  const Params params[] = {{0.5, 0.5, 1.6}, {0.4, 0.4, 3.3}, {0.5, 0.1, 7.5},
                           {0.6, 0.3, 2.5}, {0.3, 0.3, 1000.0}, {0.1, 0.5, 1.6}};
  const double mus[] = {1.0, 0.6, 0.1};
  const double phis[] = {0.0, 0.9, 2.2};
  double worst = 0;
  for (const Params& p : params) {
    const StudentTNdf<double> ndf(p.ax, p.ay, p.gamma);
    for (double mu : mus) {
      for (double phi : phis) {
        if (mu == 1.0 && phi != 0.0) continue;
        const test::Dir v = FromMuPhi(mu, phi);
        const double g1 = ndf.G1(v);
        const double integral = IntegrateVisibleHemisphereSingular(
            [&](const test::Dir& m) { return g1 * ndf.D(m); }, v, 1e-10);
        worst = std::max(worst, std::abs(integral - mu) / mu);
        EXPECT_NEAR(integral, mu, 1e-6 * mu) << "ax=" << p.ax << " ay=" << p.ay
                                             << " gamma=" << p.gamma << " mu=" << mu
                                             << " phi=" << phi;
      }
    }
  }
  std::printf("projected-area identity: max rel err %.3g\n", worst);
}

// ---------------------------------------------------------------------------
// Lambda against its definition, [Ribardiere17] eq. 17 with P2 from eq. 15
// (sigma = 1): Lambda(a) = (1/a) int_a^inf (q - a) P2(q) dq,
//   P2(q) = (gamma-1)^gamma Gamma(gamma-1/2) / (sqrt(pi) Gamma(gamma)
//           (gamma - 1 + q^2)^(gamma-1/2)),
// evaluated in logarithms (no overflow of (gamma-1)^gamma) with std::lgamma,
// i.e. independently of the library's hypergeometric machinery.
double LogP2(double gamma, double q) {
  return gamma * std::log(gamma - 1) + std::lgamma(gamma - 0.5) - std::lgamma(gamma) -
         0.5 * std::log(kPi<double>) - (gamma - 0.5) * std::log(gamma - 1 + q * q);
}

// The integral is written relative to P2(a) (so that nothing underflows
// before the end) and split at the scale of the decay; tanh-sinh on [0, w]
// and exp-sinh on [w, inf) handle both the Gaussian-like (large gamma) and
// the algebraic (gamma -> 1.5, q^-(2 gamma - 1)) tails.
double LambdaByQuadrature(double gamma, double a) {
  const double log_p2a = LogP2(gamma, a);
  auto f = [&](double t) { return t * std::exp(LogP2(gamma, a + t) - log_p2a); };
  // Decay length of P2 beyond a.
  const double w = std::min((gamma - 1 + a * a) / ((2 * gamma - 1) * a),
                            std::sqrt((gamma - 1 + a * a) / (2 * gamma - 1)));
  boost::math::quadrature::tanh_sinh<double> ts;
  boost::math::quadrature::exp_sinh<double> es;
  const double near = ts.integrate(f, 0.0, w, 1e-15);
  const double far = es.integrate([&](double t) { return f(w + t); }, 0.0, kInf, 1e-15);
  return std::exp(log_p2a) * (near + far) / a;
}

TEST(StudentTTest, LambdaMatchesEq17Integral) {
  const double gammas[] = {1.6, 2, 2.5, 3, 3.5, 4, 7.5, 20, 100};
  const std::vector<double> as = LogGrid(1e-3, 1e3, 31);
  const double kTol = 1e-11;  // relative; measured max 2.3e-13 (gamma = 100)
  for (double gamma : gammas) {
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    double worst = 0;
    int n = 0;
    for (double a : as) {
      const double ref = LambdaByQuadrature(gamma, a);
      if (!(ref > 1e-280)) continue;  // underflow of the reference
      const double lambda = ndf.UnitLambda(a);
      const double rel = std::abs(lambda - ref) / ref;
      worst = std::max(worst, rel);
      ++n;
      EXPECT_LT(rel, kTol) << "gamma=" << gamma << " a=" << a << " " << lambda << " vs "
                           << ref;
    }
    std::printf("gamma=%-5g Lambda vs eq. 17 quadrature: %d points, max rel err %.3g\n", gamma,
                n, worst);
  }
}

// ---------------------------------------------------------------------------
// Closed forms ([Ribardiere17] section 4) and Table 1

TEST(StudentTTest, HasClosedForm) {
  for (double g : {2.0, 2.5, 3.0, 3.5, 4.0, 7.5, 20.0, 100.0, 100.5}) {
    EXPECT_TRUE(StudentTHasClosedForm(g)) << g;
  }
  for (double g : {1.5, 1.6, 2.25, 3.3, 1e9, kInf, std::nan("")}) {
    EXPECT_FALSE(StudentTHasClosedForm(g)) << g;
  }
  EXPECT_TRUE(std::isnan(StudentTLambdaClosedForm(3.3, 1.0)));
}

TEST(StudentTTest, LambdaMatchesClosedForms) {
  const double gammas[] = {2, 2.5, 3, 3.5, 4, 7.5, 20, 100};
  const std::vector<double> as = LogGrid(1e-3, 1e3, 61);
  for (double gamma : gammas) {
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    double worst_abs = 0, worst_rel = 0;
    for (double a : as) {
      const double lambda = ndf.UnitLambda(a);
      const double closed = StudentTLambdaClosedForm(gamma, a);
      // The closed forms end in a subtraction (of 1/2 or so): their
      // absolute error is ~1e-16 (1 + Lambda), so relative accuracy is only
      // expected where Lambda is not small.
      const double err = std::abs(closed - lambda);
      worst_abs = std::max(worst_abs, err / (1 + lambda));
      EXPECT_LT(err, 1e-14 * (1 + lambda)) << "gamma=" << gamma << " a=" << a;
      if (lambda > 1e-3) {
        worst_rel = std::max(worst_rel, err / lambda);
        EXPECT_LT(err, 1e-11 * lambda) << "gamma=" << gamma << " a=" << a;
      }
    }
    std::printf("gamma=%-5g closed form vs UnitLambda: max |diff|/(1+L) %.3g, rel (L>1e-3) %.3g\n",
                gamma, worst_abs, worst_rel);
  }
}

// Table 1 of [Ribardiere17], isotropic Lambda rows with mu = cot(theta), s = sigma.
// Rows gamma = 2, 5/2, 3, 4, inf as printed; the printed gamma = 7/2 row is
// wrong, the corrected row is tested and the printed one shown to differ.
double Table1Row(double gamma, double mu, double s) {
  const double pi = kPi<double>;
  if (gamma == 2) return 0.5 * (std::sqrt(mu * mu + s * s) / mu - 1);
  if (gamma == 2.5)
    return std::atan(std::sqrt(2.0 / 3) * mu / s) / pi - 0.5 + std::sqrt(1.5) * s / (pi * mu);
  if (gamma == 3) {
    const double m2 = mu * mu, s2 = s * s;
    return 0.5 * ((m2 * m2 + 3 * m2 * s2 + 2 * s2 * s2) / (mu * std::pow(m2 + 2 * s2, 1.5)) - 1);
  }
  if (gamma == 3.5) {  // corrected
    const double m2 = mu * mu, s2 = s * s, d = 2 * m2 + 5 * s2;
    return std::atan(std::sqrt(0.4) * mu / s) / pi - 0.5 +
           std::sqrt(10.0) * s * (6 * m2 * m2 + 25 * m2 * s2 + 25 * s2 * s2) /
               (3 * pi * mu * d * d);
  }
  if (gamma == 4) {
    const double m2 = mu * mu, s2 = s * s;
    return 0.5 * ((8 * m2 * m2 * m2 + 60 * m2 * m2 * s2 + 135 * m2 * s2 * s2 + 81 * s2 * s2 * s2) /
                      (8 * mu * std::pow(m2 + 3 * s2, 2.5)) -
                  1);
  }
  // gamma = inf (Beckmann)
  return 0.5 * (s * std::exp(-mu * mu / (s * s)) / (mu * std::sqrt(pi)) + std::erf(mu / s) - 1);
}

double Table1PrintedRow35(double mu, double s) {
  const double pi = kPi<double>, m2 = mu * mu, s2 = s * s;
  return std::atan(std::sqrt(0.4) * mu / s) / (3 * pi) - 1 +
         5 * std::sqrt(2.5) * (-6 * m2 * m2 + 17 * m2 * s2 + 8 * s2 * s2) /
             (6 * pi * mu * s * (2 * m2 + 5 * s2));
}

TEST(StudentTTest, Table1Rows) {
  const double s = 0.6;  // the rows depend on mu / s only
  for (double gamma : {2.0, 2.5, 3.0, 3.5, 4.0, kInf}) {
    const StudentTNdf<double> ndf(s, s, gamma);
    double worst = 0;
    for (double mu : LogGrid(1e-2, 2.0, 15)) {
      const test::Dir w = Normalize(test::Dir(1.0, 0.0, mu));  // cot(theta) = mu
      const double lambda = ndf.Lambda(w);
      const double row = Table1Row(gamma, mu, s);
      worst = std::max(worst, std::abs(row - lambda) / lambda);
      // The rows end in "- 1/2" or "- 1": absolute rounding ~1e-16 on top.
      EXPECT_NEAR(row, lambda, 1e-12 * lambda + 1e-15) << "gamma=" << gamma << " mu=" << mu;
    }
    std::printf("Table 1 row gamma=%g: max rel diff %.3g (mu/sigma in [1/60, 10/3])\n", gamma,
                worst);
  }
  const StudentTNdf<double> ndf(s, s, 3.5);
  for (double mu : {0.1, 1.0, 3.0}) {
    const double lambda = ndf.UnitLambda(mu / s);
    const double printed = Table1PrintedRow35(mu, s);
    std::printf("Table 1 gamma=7/2 as printed at mu=%g: %.6g (true %.6g)\n", mu, printed, lambda);
    EXPECT_GT(std::abs(printed - lambda), 0.5 * lambda);
  }
}

// ---------------------------------------------------------------------------
// Limits: gamma = 2 is GGX, gamma -> inf is Beckmann, gamma -> 1.5

std::vector<test::Dir> RandomDirections(int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<test::Dir> dirs;
  for (int i = 0; i < n; ++i) {
    const double mu = 1e-3 + (1 - 1e-3) * uni(rng);
    dirs.push_back(FromMuPhi(mu, 2 * kPi<double> * uni(rng)));
  }
  return dirs;
}

TEST(StudentTTest, Gamma2IsGgx) {
  for (const auto& [ax, ay] : {std::pair{0.4, 0.15}, std::pair{0.05, 0.9}, std::pair{1.0, 1.0}}) {
    const StudentTNdf<double> std_ndf(ax, ay, 2.0);
    const GgxNdf<double> ggx(ax, ay);
    double worst_d = 0, worst_l = 0, worst_s = 0;
    for (const test::Dir& w : RandomDirections(2000, 3)) {
      const double d = std_ndf.D(w), dg = ggx.D(w);
      const double l = std_ndf.Lambda(w), lg = ggx.Lambda(w);
      worst_d = std::max(worst_d, std::abs(d - dg) / dg);
      worst_l = std::max(worst_l, std::abs(l - lg) / lg);
      EXPECT_NEAR(d, dg, 1e-12 * dg);
      EXPECT_NEAR(l, lg, 1e-12 * lg);
    }
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
      const double u1 = uni(rng), u2 = uni(rng);
      const test::Dir a = std_ndf.SampleNdf(u1, u2), b = ggx.SampleNdf(u1, u2);
      worst_s = std::max(worst_s, Length(a - b));
      EXPECT_LT(Length(a - b), 1e-12);
    }
    std::printf("gamma=2 vs GGX ax=%g ay=%g: D %.3g, Lambda %.3g, SampleNdf %.3g\n", ax, ay,
                worst_d, worst_l, worst_s);
  }
}

TEST(StudentTTest, GammaInfinityIsBeckmannExactly) {
  const StudentTNdf<double> std_ndf(0.3, 0.7, kInf);
  const BeckmannNdf<double> beckmann(0.3, 0.7);
  for (const test::Dir& w : RandomDirections(500, 4)) {
    EXPECT_EQ(std_ndf.D(w), beckmann.D(w));
    EXPECT_EQ(std_ndf.Lambda(w), beckmann.Lambda(w));
  }
  for (double u : {0.0, 1e-12, 0.3, 0.999, 1.0}) {
    EXPECT_EQ(std_ndf.UnitSampleR2(u), beckmann.UnitSampleR2(u));
    const test::Dir a = std_ndf.SampleNdf(0.37, u), b = beckmann.SampleNdf(0.37, u);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.z, b.z);
  }
}

// For large gamma, log(P22_std / P22_beck) = r^2 - gamma log1p(r^2/(gamma-1))
// = (r^4/2 - r^2) / gamma + O(gamma^-2): D differs from Beckmann by
// O((r^2 + r^4/2) / gamma). Lambda's relative difference is O((1 + a^4) /
// gamma) (the tail is the first to feel the heavier Student law).
TEST(StudentTTest, LargeGammaApproachesBeckmann) {
  const double ax = 0.3, ay = 0.5;
  const BeckmannNdf<double> beckmann(ax, ay);
  double worst_d = 0, worst_l = 0;
  for (double gamma : {1e5, 1e6}) {
    const StudentTNdf<double> std_ndf(ax, ay, gamma);
    for (const test::Dir& w : RandomDirections(2000, 6)) {
      const double sx = w.x / (ax * w.z), sy = w.y / (ay * w.z), r2 = sx * sx + sy * sy;
      if (r2 > 30) continue;
      const double db = beckmann.D(w), ds = std_ndf.D(w);
      const double bound = 1.05 * (r2 + 0.5 * r2 * r2) / (gamma - 1) + 1e-14;
      EXPECT_LE(std::abs(ds / db - 1), bound) << "gamma=" << gamma << " r2=" << r2;
      if (gamma == 1e6) worst_d = std::max(worst_d, std::abs(ds / db - 1));
    }
  }
  // Lambda: gamma (Lambda_std / Lambda_beck - 1) = c(a) + O(1/gamma), with
  // c(a) <= 1.3 (1 + a^4) (measured) and c(0) = 3/8: for a -> 0, Lambda ->
  // K / ((2 gamma - 3) m) = (1 + 3/(8 gamma) + O(gamma^-2)) / (2 a sqrt(pi)).
  const StudentTNdf<double> s5(1, 1, 1e5), s6(1, 1, 1e6);
  for (double a : LogGrid(1e-3, 20.0, 40)) {
    const double lb = beckmann.UnitLambda(a);
    const double d5 = s5.UnitLambda(a) / lb - 1, d6 = s6.UnitLambda(a) / lb - 1;
    EXPECT_LE(std::abs(d6), 1.5 * (1 + a * a * a * a) / 1e6) << "a=" << a;
    EXPECT_GT(d6, 0.0) << "a=" << a;  // the Student tail is heavier
    worst_l = std::max(worst_l, std::abs(d6));
    if (a <= 5) {
      EXPECT_NEAR(d5 / d6, 10.0, 0.05) << "a=" << a;  // O(1/gamma)
    }
  }
  // The 3/8 (c(1e-3) = 0.3757) holds on both sides of gamma = 1e8, where
  // K switches from Boost's tgamma_delta_ratio to its asymptotic series.
  for (double gamma : {1e6, 1e9, 1e12}) {
    const double c0 =
        gamma * (StudentTNdf<double>(1, 1, gamma).UnitLambda(1e-3) / beckmann.UnitLambda(1e-3) - 1);
    EXPECT_NEAR(c0, 0.375, 2e-3) << "gamma=" << gamma;
  }
  std::printf("gamma=1e6 vs Beckmann: D max rel diff %.3g (r^2 <= 30), Lambda max rel diff %.3g"
              " (a <= 20)\n",
              worst_d, worst_l);
}

TEST(StudentTTest, LambdaMonotoneFinitePositive) {
  const std::vector<double> as = LogGrid(1e-4, 1e4, 2001);
  for (double gamma : {1.0, 1.5, 1.5000001, 1.5001, 1.6, 2.0, 2.5, 3.3, 7.5, 20.0, 100.0,
                       1e4, 1e6, 1e12, kInf}) {
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    double prev = kInf;
    for (double a : as) {
      const double l = ndf.UnitLambda(a);
      ASSERT_TRUE(std::isfinite(l)) << "gamma=" << gamma << " a=" << a;
      ASSERT_GE(l, 0.0) << "gamma=" << gamma << " a=" << a;
      if (gamma < 10) {
        ASSERT_GT(l, 0.0) << "gamma=" << gamma << " a=" << a;
      }
      if (prev > 0) {
        ASSERT_LT(l, prev) << "gamma=" << gamma << " a=" << a;
      }
      prev = l;
    }
  }
  // gamma is clamped at 1.5 + 1e-6; Lambda grows as gamma -> 1.5 (the mean
  // slope diverges like 1 / (2 gamma - 3)) but stays finite.
  EXPECT_EQ(StudentTNdf<double>(0.5, 0.5, 1.2).gamma(), kMinStudentTGamma<double>);
  for (double a : {1e-3, 0.1, 1.0, 10.0, 1e3}) {
    double prev = 0;
    for (double gamma : {1.6, 1.55, 1.51, 1.501, 1.5001, 1.50001, 1.5}) {
      const double l = StudentTNdf<double>(1.0, 1.0, gamma).UnitLambda(a);
      EXPECT_TRUE(std::isfinite(l));
      EXPECT_GT(l, prev) << "a=" << a << " gamma=" << gamma;
      prev = l;
    }
    std::printf("a=%-6g Lambda at gamma=1.5+1e-6: %.6g\n", a, prev);
  }
  // And the full directional API stays finite at grazing angles.
  const StudentTNdf<double> ndf(1e-4, 1.0, 1.5);
  for (double mu : {1e-6, 1e-3, 0.5, 1.0}) {
    const test::Dir w = FromMuPhi(mu, 0.3);
    EXPECT_TRUE(std::isfinite(ndf.Lambda(w)));
    EXPECT_TRUE(std::isfinite(ndf.D(w)));
  }
}

// ---------------------------------------------------------------------------
// Sampling

TEST(StudentTTest, SampleR2InvertsRadialCdf) {
  for (double gamma : {1.5001, 1.6, 2.0, 3.3, 20.0, 1e6}) {
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    for (double u : {1e-15, 1e-9, 1e-3, 0.3, 0.9, 0.999999}) {
      const double r2 = ndf.UnitSampleR2(u);
      // CDF(r^2) = 1 - (1 + r^2/(gamma-1))^(1-gamma) ([Ribardiere17] eq. 41-42).
      const double cdf = -std::expm1((1 - gamma) * std::log1p(r2 / (gamma - 1)));
      EXPECT_NEAR(cdf, u, 1e-13 * u) << "gamma=" << gamma << " u=" << u;
    }
  }
}

const int kChiSquareTests = 15;

void ExpectChiSquare(const char* what, const test::ChiSquareResult& r) {
  std::printf("%s: chi2=%.1f dof=%d p=%.3g pdf mass=%.6f\n", what, r.chi2, r.dof, r.p_value,
              r.pdf_mass);
  EXPECT_GT(r.p_value, test::ChiSquareAlpha(kChiSquareTests)) << what;
}

TEST(StudentTTest, NdfSamplingChiSquare) {
  const Params params[] = {{0.5, 0.5, 1.6}, {0.5, 0.5, 3.0}, {0.5, 0.5, 10.0},
                           {0.6, 0.2, 1.6}, {0.6, 0.2, 3.0}, {0.6, 0.2, 10.0}};
  for (const Params& p : params) {
    const StudentTNdf<double> ndf(p.ax, p.ay, p.gamma);
    const auto r = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* d) {
          *d = ndf.SampleNdf(u1, u2);
          return true;
        },
        [&](const test::Dir& m) { return ndf.PdfNdf(m); });
    char what[128];
    std::snprintf(what, sizeof(what), "NDF sampling ax=%g ay=%g gamma=%g", p.ax, p.ay, p.gamma);
    ExpectChiSquare(what, r);
  }
}

TEST(StudentTTest, PseudoVnisBranches) {
  // Algorithm 1 with sigma = sqrt(ax ay).
  EXPECT_EQ(StudentTNdf<double>(0.005, 0.005, 3.0).PseudoVnisBranch(), 0);   // sigma <= 0.01
  EXPECT_EQ(StudentTNdf<double>(0.005, 0.005, 50.0).PseudoVnisBranch(), 0);  // sigma first
  EXPECT_EQ(StudentTNdf<double>(0.5, 0.5, 3.0).PseudoVnisBranch(), 1);     // GGX
  EXPECT_EQ(StudentTNdf<double>(0.5, 0.5, 4.99).PseudoVnisBranch(), 1);    // upper = 5
  EXPECT_EQ(StudentTNdf<double>(0.05, 0.05, 2.4).PseudoVnisBranch(), 1);   // upper = 2.5
  EXPECT_EQ(StudentTNdf<double>(0.05, 0.05, 2.6).PseudoVnisBranch(), 0);   // gap
  EXPECT_EQ(StudentTNdf<double>(0.15, 0.15, 6.0).PseudoVnisBranch(), 0);   // gap
  EXPECT_EQ(StudentTNdf<double>(0.35, 0.35, 6.0).PseudoVnisBranch(), 2);   // lower = 5
  EXPECT_EQ(StudentTNdf<double>(0.25, 0.25, 7.0).PseudoVnisBranch(), 0);   // lower = 7.5
  EXPECT_EQ(StudentTNdf<double>(0.25, 0.25, 8.0).PseudoVnisBranch(), 2);
  EXPECT_EQ(StudentTNdf<double>(0.05, 0.05, 10.5).PseudoVnisBranch(), 2);  // gamma > 10
  EXPECT_EQ(StudentTNdf<double>(0.3, 0.3, kInf).PseudoVnisBranch(), 2);
  // Anisotropic: sigma = sqrt(0.8 * 0.05) = 0.2 -> GGX upper bound 4.
  EXPECT_EQ(StudentTNdf<double>(0.8, 0.05, 3.9).PseudoVnisBranch(), 1);
  EXPECT_EQ(StudentTNdf<double>(0.8, 0.05, 4.1).PseudoVnisBranch(), 0);
}

TEST(StudentTTest, PseudoVnisChiSquare) {
  struct Case {
    Params p;
    double mu, phi;
    int branch;
  };
  const Case cases[] = {
      {{0.5, 0.5, 3.0}, 0.05, 0.4, 1},   {{0.5, 0.5, 3.0}, 1.0, 0.0, 1},
      {{0.6, 0.3, 2.5}, 0.05, 2.0, 1},   {{0.35, 0.35, 6.0}, 0.05, 0.4, 2},
      {{0.35, 0.35, 6.0}, 1.0, 0.0, 2},  {{0.5, 0.2, 20.0}, 0.05, 0.7, 2},
      {{0.15, 0.15, 6.0}, 0.05, 0.4, 0}, {{0.4, 0.1, 7.0}, 0.9, 0.0, 0},
      {{0.3, 0.3, 1.6}, 0.5, 0.2, 1}};
  static_assert(6 + sizeof(cases) / sizeof(cases[0]) == kChiSquareTests);
  for (const Case& c : cases) {
    const StudentTNdf<double> ndf(c.p.ax, c.p.ay, c.p.gamma);
    ASSERT_EQ(ndf.PseudoVnisBranch(), c.branch);
    const test::Dir w = FromMuPhi(c.mu, c.phi);
    const auto r = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* d) {
          *d = ndf.SamplePseudoVnis(w, u1, u2);
          return true;
        },
        [&](const test::Dir& m) { return ndf.PdfPseudoVnis(w, m); });
    char what[160];
    std::snprintf(what, sizeof(what),
                  "pseudo-VNIS branch %d ax=%g ay=%g gamma=%g mu_v=%g", c.branch, c.p.ax,
                  c.p.ay, c.p.gamma, c.mu);
    ExpectChiSquare(what, r);
    // The pdf integrates to 1 over the hemisphere (it is a density of m).
    EXPECT_NEAR(r.pdf_mass, 1.0, 2e-3) << what;
  }
}

// ---------------------------------------------------------------------------
// float

TEST(StudentTTest, FloatMatchesDouble) {
  double worst_l = 0, worst_d = 0;
  for (float gamma : {1.6f, 2.0f, 3.3f, 7.5f, 100.0f, 1e6f}) {
    const StudentTNdf<float> nf(0.4f, 0.25f, gamma);
    const StudentTNdf<double> nd(0.4, 0.25, static_cast<double>(gamma));
    for (double a : LogGrid(1e-3, 1e2, 60)) {
      const float af = static_cast<float>(a);
      const double ld = nd.UnitLambda(af);
      if (!(ld > 1e-30)) continue;
      const double rel = std::abs(nf.UnitLambda(af) - ld) / ld;
      worst_l = std::max(worst_l, rel);
      EXPECT_LT(rel, 1e-5) << "gamma=" << gamma << " a=" << a;
    }
    for (const test::Dir& w : RandomDirections(300, 8)) {
      const Vec3<float> wf(w);
      const Vec3<double> wd(wf);
      const double dd = nd.D(wd);
      if (!(dd > 1e-30)) continue;
      // D = exp(-E) / (...) with E = gamma log1p(r^2/(gamma-1)): float
      // rounding of r^2 and of E costs ~E ulps of float.
      const double sx = wd.x / (0.4 * wd.z), sy = wd.y / (0.25 * wd.z);
      const double e = gamma * std::log1p((sx * sx + sy * sy) / (gamma - 1));
      const double rel = std::abs(nf.D(wf) - dd) / dd;
      worst_d = std::max(worst_d, rel / (1 + e));
      EXPECT_LT(rel, 1e-6 * (1 + e)) << "gamma=" << gamma << " E=" << e;
    }
    const Vec3<float> m = nf.SampleNdf(0.3f, 0.6f);
    const Vec3<double> md = nd.SampleNdf(0.3, 0.6);
    EXPECT_LT(Length(Vec3<double>(m) - md), 1e-5);
    EXPECT_GE(nf.PseudoVnisBranch(), 0);
  }
  EXPECT_NEAR(StudentTLambdaClosedForm(3.0f, 0.7f), StudentTLambdaClosedForm(3.0, double(0.7f)),
              1e-6);
  std::printf("float vs double: Lambda max rel %.3g, D max rel/(1+E) %.3g\n", worst_l,
              worst_d);
}

}  // namespace
}  // namespace brdfbake
