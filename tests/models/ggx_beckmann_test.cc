// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Physics of the GGX and Beckmann scalar references: normalization of D, the
// projected-area identity of G1, Lambda against its defining integral, and
// chi-square tests of the NDF and visible-normal samplers.

#include <cmath>
#include <cstdio>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

struct Alphas {
  double ax, ay;
};
const Alphas kAlphas[] = {{1.0, 1.0}, {0.5, 0.5}, {0.2, 0.2}, {0.8, 0.2}, {0.5, 0.05}};

template <class Ndf>
void CheckNormalization(const char* name) {
  for (const Alphas& a : kAlphas) {
    const Ndf ndf(a.ax, a.ay);
    const double integral = test::IntegrateHemisphereTheta(
        [&](const test::Dir& m) { return ndf.D(m) * m.z; }, 0.0, kPi<double> / 2, 1e-11);
    std::printf("%s ax=%g ay=%g  int D cos = %.12f\n", name, a.ax, a.ay, integral);
    EXPECT_NEAR(integral, 1.0, 1e-7) << name << " " << a.ax << " " << a.ay;
  }
}

TEST(GgxTest, DIsNormalized) { CheckNormalization<GgxNdf<double>>("ggx"); }
TEST(BeckmannTest, DIsNormalized) { CheckNormalization<BeckmannNdf<double>>("beckmann"); }

// Smith's projected-area identity: int G1(v) max(0, v.m) D(m) dm = v.z.
template <class Ndf>
void CheckProjectedArea(const char* name) {
  const double mus[] = {1.0, 0.7, 0.3, 0.1};
  const double phis[] = {0.0, 0.9, 2.2};
  for (const Alphas& a : kAlphas) {
    const Ndf ndf(a.ax, a.ay);
    for (double mu : mus) {
      for (double phi : phis) {
        const test::Dir v = FromMuPhi(mu, phi);
        const double g1 = ndf.G1(v);
        const double integral = test::IntegrateVisibleHemisphere(
            [&](const test::Dir& m) { return g1 * ndf.D(m); }, v, 1e-11);
        EXPECT_NEAR(integral, mu, 2e-7 * std::max(1.0, mu))
            << name << " ax=" << a.ax << " ay=" << a.ay << " mu=" << mu << " phi=" << phi;
      }
    }
  }
}

TEST(GgxTest, ProjectedAreaIdentity) { CheckProjectedArea<GgxNdf<double>>("ggx"); }
TEST(BeckmannTest, ProjectedAreaIdentity) { CheckProjectedArea<BeckmannNdf<double>>("beckmann"); }

// Lambda(a) = (1/a) int_a^inf (q - a) P2(q) dq ([Ribardiere17] eq. 17), P2 the 1D
// marginal of the unit-roughness slope density.
template <class Ndf>
void CheckLambdaIntegral(const char* name, double (*p2)(double)) {
  const Ndf ndf(1.0, 1.0);
  boost::math::quadrature::exp_sinh<double> integrator;
  double worst = 0;
  for (double a = 1e-3; a < 5; a *= 1.7) {
    const double integral =
        integrator.integrate([&](double t) { return t * p2(a + t); }, 0.0,
                             std::numeric_limits<double>::infinity(), 1e-14) /
        a;
    const double lambda = ndf.UnitLambda(a);
    const double rel = std::abs(lambda - integral) / integral;
    worst = std::max(worst, rel);
    EXPECT_LT(rel, 1e-10) << name << " a=" << a << " " << lambda << " vs " << integral;
  }
  std::printf("%s Lambda vs eq. 17 integral: max rel err %.3g\n", name, worst);
}

double GgxP2(double q) { return 0.5 / std::pow(1 + q * q, 1.5); }
double BeckmannP2(double q) { return std::exp(-q * q) / kSqrtPi<double>; }

TEST(GgxTest, LambdaMatchesIntegral) { CheckLambdaIntegral<GgxNdf<double>>("ggx", GgxP2); }
TEST(BeckmannTest, LambdaMatchesIntegral) {
  CheckLambdaIntegral<BeckmannNdf<double>>("beckmann", BeckmannP2);
}

TEST(GgxTest, IsotropicClosedForms) {
  // Isotropic GGX: D = alpha^2 / (pi (cos^2 (alpha^2 - 1) + 1)^2),
  // Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2.
  for (double alpha : {0.01, 0.3, 1.0, 2.0}) {
    const GgxNdf<double> ndf(alpha);
    for (double mu = 0.05; mu <= 1.0; mu += 0.05) {
      const test::Dir w = FromMuPhi(mu, 0.7);
      const double c2 = mu * mu;
      const double q = c2 * (alpha * alpha - 1) + 1;
      EXPECT_NEAR(ndf.D(w), alpha * alpha / (kPi<double> * q * q),
                  1e-12 * ndf.D(w));
      const double tan2 = (1 - c2) / c2;
      const double lambda = 0.5 * (std::sqrt(1 + alpha * alpha * tan2) - 1);
      EXPECT_NEAR(ndf.Lambda(w), lambda, 1e-12 * std::max(1.0, lambda));
    }
  }
}

TEST(GgxTest, AnisotropySwapsAxes) {
  const GgxNdf<double> a(0.7, 0.1), b(0.1, 0.7);
  const BeckmannNdf<double> c(0.7, 0.1), d(0.1, 0.7);
  for (double mu = 0.1; mu < 1; mu += 0.2) {
    for (double phi = 0; phi < 6; phi += 0.5) {
      const test::Dir w = FromMuPhi(mu, phi);
      const test::Dir s(w.y, w.x, w.z);
      EXPECT_NEAR(a.D(w), b.D(s), 1e-12 * a.D(w));
      EXPECT_NEAR(a.Lambda(w), b.Lambda(s), 1e-12 * (1 + a.Lambda(w)));
      EXPECT_NEAR(c.D(w), d.D(s), 1e-12 * c.D(w));
      EXPECT_NEAR(c.Lambda(w), d.Lambda(s), 1e-12 * (1 + c.Lambda(w)));
    }
  }
}

TEST(GgxTest, FloatMatchesDouble) {
  const GgxNdf<float> f(0.3f, 0.6f);
  const GgxNdf<double> d(0.3, 0.6);
  const BeckmannNdf<float> fb(0.3f, 0.6f);
  const BeckmannNdf<double> db(0.3, 0.6);
  for (double mu = 0.05; mu <= 1.0; mu += 0.05) {
    const test::Dir w = FromMuPhi(mu, 0.4);
    const Vec3<float> wf(w);
    EXPECT_NEAR(f.D(wf), d.D(w), 2e-5 * d.D(w));
    EXPECT_NEAR(f.Lambda(wf), d.Lambda(w), 2e-5 * (1e-3 + d.Lambda(w)));
    EXPECT_NEAR(fb.D(wf), db.D(w), 2e-5 * db.D(w) + 1e-30);  // float underflow below ~1e-38
    EXPECT_NEAR(fb.Lambda(wf), db.Lambda(w), 1e-4 * (1e-3 + db.Lambda(w)));
  }
}

// ---------------------------------------------------------------------------
// Chi-square tests of the samplers.

struct SamplerCase {
  double ax, ay, mu_v, phi_v;
};
const SamplerCase kCases[] = {{0.5, 0.5, 1.0, 0.0},   {0.5, 0.5, 0.5, 0.3},
                              {0.8, 0.2, 0.3, 1.1},   {0.3, 0.6, 0.05, 2.0},
                              {1.0, 1.0, 0.02, 0.0},  {0.15, 0.15, 0.7, 0.0}};
constexpr int kNumChi2 = 2 * 2 * 6;

template <class Ndf>
void CheckSamplers(const char* name) {
  uint64_t seed = 11;
  for (const SamplerCase& c : kCases) {
    const Ndf ndf(c.ax, c.ay);
    const test::Dir v = FromMuPhi(c.mu_v, c.phi_v);
    auto ndf_result = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* m) {
          *m = ndf.SampleNdf(u1, u2);
          return true;
        },
        [&](const test::Dir& m) { return ndf.PdfNdf(m); }, 40, 80, 1000000, seed++);
    auto vndf_result = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* m) {
          *m = ndf.SampleVisible(v, u1, u2);
          return true;
        },
        [&](const test::Dir& m) { return ndf.PdfVisible(v, m); }, 40, 80, 1000000, seed++);
    std::printf("%s ax=%g ay=%g mu_v=%g: NDF p=%.3g (mass %.6f), VNDF p=%.3g (mass %.6f)\n",
                name, c.ax, c.ay, c.mu_v, ndf_result.p_value, ndf_result.pdf_mass,
                vndf_result.p_value, vndf_result.pdf_mass);
    EXPECT_GT(ndf_result.p_value, test::ChiSquareAlpha(kNumChi2)) << name << " NDF " << c.ax;
    EXPECT_GT(vndf_result.p_value, test::ChiSquareAlpha(kNumChi2)) << name << " VNDF " << c.ax;
  }
}

TEST(GgxTest, SamplersChiSquare) { CheckSamplers<GgxNdf<double>>("ggx"); }
// The visible-slope solver of BeckmannNdf::SampleVisible at the ends of u1
// and for steep views, against 50-digit values of the CDF: with alpha = 1,
// the view at azimuth 0 and u2 = 1/2 (y = 0) the sampled normal is
// normalize(-x, 0, 1), so x = -m.x / m.z, and x must satisfy
// n(x) = u1 n(mu) (lower half) or U(x) = n(mu) - n(x) = (1 - u1) n(mu)
// (upper half) to near double precision; u1 = 1 gives x = mu exactly.
// (Below u1 ~ 1e-36 the root lies under the search interval [-9, mu].)
TEST(BeckmannTest, VisibleSlopeSolverAtTheEnds) {
  using Big = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>>;
  const BeckmannNdf<double> b(1.0);
  double worst = 0;
  for (double mu : {0.05, 0.5, 2.0, 4.4, 8.0}) {
    const double theta = std::atan(1 / mu);
    const Vec3<double> w(std::sin(theta), 0, std::cos(theta));
    const Big c = w.z, sn = w.x, mub = Big(w.z) / Big(w.x);
    const Big sqrt_pi = sqrt(boost::math::constants::pi<Big>());
    auto n = [&](const Big& x) { return (c * erfc(-x) + sn * exp(-x * x) / sqrt_pi) / 2; };
    const Big total = n(mub);
    for (double u : {1e-30, 1e-12, 0.3, 0.5, 0.9, 1 - 1e-9, 1 - 1e-15}) {
      const Vec3<double> m = b.SampleVisible(w, u, 0.5);
      const double x = -m.x / m.z;
      const Big got = u <= 0.5 ? n(Big(x)) : total - n(Big(x));
      const Big want = u <= 0.5 ? Big(u) * total : (1 - Big(u)) * total;
      // The CDF's relative change per ulp of x (its log-derivative times x's ulp).
      const Big dens = (c - Big(x) * sn) * exp(-Big(x) * Big(x)) / sqrt_pi;
      const double slack = static_cast<double>(abs(dens / got)) * 8e-16 * (1 + std::abs(x));
      const double err = static_cast<double>(abs(got / want - 1));
      worst = std::max(worst, err / (1e-12 + slack));
      EXPECT_LE(err, 1e-12 + slack) << "mu " << mu << " u " << u << " x " << x;
    }
    const Vec3<double> top = b.SampleVisible(w, 1.0, 0.5);
    EXPECT_NEAR(-top.x / top.z, std::min(static_cast<double>(mub), 9.0), 1e-12 * (1 + mu));
  }
  std::printf("Beckmann visible-slope solver: max error / bound %.3g\n", worst);
}

TEST(BeckmannTest, SamplersChiSquare) { CheckSamplers<BeckmannNdf<double>>("beckmann"); }

// The visible-normal density integrates to one for every view.
TEST(GgxTest, VisibleNormalsIntegrateToOne) {
  for (const SamplerCase& c : kCases) {
    const GgxNdf<double> g(c.ax, c.ay);
    const BeckmannNdf<double> b(c.ax, c.ay);
    const test::Dir v = FromMuPhi(c.mu_v, c.phi_v);
    const double ig = test::IntegrateVisibleHemisphere(
        [&](const test::Dir& m) { return g.PdfVisible(v, m) / Dot(v, m); }, v, 1e-11);
    const double ib = test::IntegrateVisibleHemisphere(
        [&](const test::Dir& m) { return b.PdfVisible(v, m) / Dot(v, m); }, v, 1e-11);
    EXPECT_NEAR(ig, 1.0, 1e-6);
    EXPECT_NEAR(ib, 1.0, 1e-6);
  }
}

TEST(GgxTest, TinyAlphaStaysFinite) {
  const GgxNdf<double> g(1e-4);
  const BeckmannNdf<double> b(1e-4);
  const test::Dir v = FromMuPhi(1e-3, 0.2);
  for (double u : {0.0, 1e-9, 0.5, 1.0 - 1e-9}) {
    const test::Dir m1 = g.SampleVisible(v, u, 0.3), m2 = b.SampleVisible(v, u, 0.3);
    const test::Dir m3 = g.SampleNdf(u, 0.3), m4 = b.SampleNdf(0.3, u);
    for (const test::Dir& m : {m1, m2, m3, m4}) {
      EXPECT_TRUE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z));
      EXPECT_NEAR(Length(m), 1.0, 1e-12);
    }
  }
  EXPECT_TRUE(std::isfinite(g.D(test::Dir(0, 0, 1))));
  EXPECT_TRUE(std::isfinite(b.Lambda(v)));
}

}  // namespace
}  // namespace brdfbake
