// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen ([EstevezKulla17], models/sheen.h) and the Disney
// diffuse lobe ([Burley12], models/disney_diffuse.h): the closed forms the
// code relies on, checked numerically, the NDF sampler's chi-square test
// and the model registry's handling of both.

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "brdfbake/model.h"
#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/sheen.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

using boost::math::quadrature::gauss_kronrod;

// The projected area of the Charlie NDF is one: integral D(m) cos dm = 1.
TEST(SheenTest, CharlieProjectedAreaIsOne) {
  for (double alpha : {1e-3, 0.01, 0.1, 0.3, 0.5, 0.8, 1.0}) {
    const CharlieSheen<double> s(alpha, SheenVisibility::kNeubelt);
    const double area = gauss_kronrod<double, 61>::integrate(
        [&](double th) { return s.DCos(std::cos(th)) * std::cos(th) * std::sin(th) * kTwoPi<double>; },
        0.0, kPi<double> / 2, 15, 1e-14);
    EXPECT_NEAR(area, 1.0, 1e-10) << "alpha " << alpha;
  }
}

// D as written in [EstevezKulla17] eq. 2, (2 + 1/alpha) sin^(1/alpha) / (2 pi).
TEST(SheenTest, CharlieDIsThePapersForm) {
  for (double alpha : {0.01, 0.25, 1.0}) {
    const CharlieSheen<double> s(alpha, SheenVisibility::kContyKulla);
    for (double th : {0.1, 0.7, 1.2, 1.5}) {
      const double paper = (2 + 1 / alpha) * std::pow(std::sin(th), 1 / alpha) / kTwoPi<double>;
      // The power amplifies the rounding of its base: 4 ulp of the exponent.
      const double tol = 1e-15 * (4 + 4 * std::abs(std::log(paper))) * paper;
      EXPECT_NEAR(s.DCos(std::cos(th)), paper, tol) << alpha << " " << th;
    }
    EXPECT_EQ(s.DCos(1.0), 0.0);
  }
}

// The two branches of the fitted Lambda meet at cos = 1/2 with the same
// value and slope; L is the paper's interpolation between its two fits.
TEST(SheenTest, ContyKullaLambdaIsContinuous) {
  for (double alpha : {1e-6, 0.1, 0.5, 1.0}) {
    const CharlieSheen<double> s(alpha, SheenVisibility::kContyKulla);
    const double h = 1e-7;
    const double lo = s.LambdaCos(0.5 - h), mid = s.LambdaCos(0.5), hi = s.LambdaCos(0.5 + h);
    EXPECT_NEAR(lo, mid, 1e-5 * mid);
    EXPECT_NEAR(hi, mid, 1e-5 * mid);
    EXPECT_NEAR((mid - lo) / h, (hi - mid) / h, 1e-3 * std::abs((mid - lo) / h));
    EXPECT_GT(s.LambdaCos(1e-3), s.LambdaCos(0.2));  // grows towards grazing
    EXPECT_LT(s.LambdaCos(1.0), 1e-6);
  }
  // At alpha = 1 the weight (1 - alpha)^2 is 0: the second fit alone.
  EXPECT_NEAR(CharlieL(1.0, 0.25), 21.5473 / (1 + 3.82987 * std::pow(0.25, 0.19823)) - 1.97760 * 0.25 - 4.32054, 1e-12);
  EXPECT_NEAR(CharlieL(0.0, 0.25), 25.3245 / (1 + 3.32435 * std::pow(0.25, 0.16801)) - 1.27393 * 0.25 - 4.85967, 1e-12);
}

// The visibility terms as the header states them; the conty-kulla one
// exceeds 1 where both cosines are small.
TEST(SheenTest, VisibilityTerms) {
  const CharlieSheen<double> n(0.3, SheenVisibility::kNeubelt), ck(0.3, SheenVisibility::kContyKulla);
  for (double l : {0.01, 0.3, 1.0}) {
    for (double v : {0.05, 0.5, 1.0}) {
      EXPECT_DOUBLE_EQ(n.Visibility(l, v), 1 / (4 * (l + v - l * v)));
      EXPECT_NEAR(ck.Visibility(l, v), 1 / ((1 + ck.LambdaCos(l) + ck.LambdaCos(v)) * 4 * l * v), 1e-15);
    }
  }
  EXPECT_GT(ck.Visibility(0.01, 0.01), 1.0);
  EXPECT_EQ(n.Visibility(0.0, 0.5), 0.0);
}

// The capped variants are min(V, 1) of their uncapped twins; the
// enterprise-pbr Lambda is [EnterprisePbr]'s refined fit, continuous at
// 1/2 and growing towards grazing like the paper's.
TEST(SheenTest, VisibilityVariants) {
  for (double alpha : {1e-4, 0.05, 0.3, 1.0}) {
    const CharlieSheen<double> n(alpha, SheenVisibility::kNeubelt), ck(alpha, SheenVisibility::kContyKulla);
    const CharlieSheen<double> nc(alpha, SheenVisibility::kNeubeltClamped);
    const CharlieSheen<double> ckc(alpha, SheenVisibility::kContyKullaClamped);
    const CharlieSheen<double> ent(alpha, SheenVisibility::kEnterprisePbr);
    for (double l : {1e-4, 0.01, 0.3, 0.6, 1.0}) {
      for (double v : {1e-3, 0.05, 0.5, 1.0}) {
        EXPECT_EQ(nc.Visibility(l, v), std::min(1.0, n.Visibility(l, v)));
        EXPECT_EQ(ckc.Visibility(l, v), std::min(1.0, ck.Visibility(l, v)));
        EXPECT_NEAR(ent.Visibility(l, v), 1 / ((1 + ent.LambdaCos(l) + ent.LambdaCos(v)) * 4 * l * v),
                    1e-15 * ent.Visibility(l, v));
      }
    }
    EXPECT_EQ(ckc.Visibility(0.01, 0.01), 1.0);  // capped: V(0.01, 0.01) > 1 uncapped
    const double h = 1e-7;
    const double lo = ent.LambdaCos(0.5 - h), mid = ent.LambdaCos(0.5), hi = ent.LambdaCos(0.5 + h);
    EXPECT_NEAR(lo, mid, 1e-5 * mid);
    EXPECT_NEAR(hi, mid, 1e-5 * mid);
    EXPECT_GT(ent.LambdaCos(1e-3), ent.LambdaCos(0.2));
  }
  // The weight w(alpha) = -1.59612 / (1 + 0.20375 alpha^-0.55825) + 1.32805
  // of the second row: about 0 at alpha = 0 ... at alpha = 1, 1.32805 -
  // 1.59612 / 1.20375.
  const double w1 = -1.59612 / (1 + 0.20375) + 1.32805;
  const CharlieLFit<double> f1(1.0, SheenVisibility::kEnterprisePbr);
  EXPECT_NEAR(f1.a, 11.9095 + w1 * (13.7000 - 11.9095), 1e-12);
  EXPECT_NEAR(f1.p, 0.33467 + w1 * (0.28670 - 0.33467), 1e-12);
  const CharlieLFit<double> f0(1e-12, SheenVisibility::kEnterprisePbr);
  EXPECT_NEAR(f0.e, -1.76591 + (-1.59612 / (1 + 0.20375 * std::pow(1e-12, -0.55825)) + 1.32805) * (-1.22466 + 1.76591),
              1e-12);
  for (SheenVisibility v : kSheenVisibilities) EXPECT_EQ(ParseSheenVisibility(SheenVisibilityName(v)), v);
}

// SampleNdf draws normals with density D(m) m.z.
TEST(SheenTest, SampleNdfChiSquare) {
  const double alphas[] = {0.05, 0.3, 1.0};
  const double alpha_level = test::ChiSquareAlpha(3);
  for (double a : alphas) {
    const CharlieSheen<double> s(a, SheenVisibility::kNeubelt);
    const auto r = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* m) {
          *m = s.SampleNdf(u1, u2);
          return true;
        },
        [&](const test::Dir& m) { return s.PdfNdf(m); }, 40, 40, 1000000, 77);
    std::printf("charlie alpha %.2f: p = %.4f chi2 = %.1f dof = %d pdf mass = %.6f\n", a, r.p_value,
                r.chi2, r.dof, r.pdf_mass);
    EXPECT_GT(r.p_value, alpha_level) << a;
    EXPECT_NEAR(r.pdf_mass, 1.0, 2e-3) << a;
  }
}

// The Disney lobe: its azimuthal mean in closed form against the numerical
// mean over phi, and the product form at a few points.
TEST(SheenTest, DisneyAzimuthMeanIsExact) {
  for (double r : {0.0, 0.3, 1.0}) {
    const DisneyDiffuse<double> f(r);
    for (double nl : {0.0, 0.2, 0.9}) {
      for (double nv : {0.05, 0.5, 1.0}) {
        const double sl = std::sqrt(1 - nl * nl), sv = std::sqrt(1 - nv * nv);
        const double mean = gauss_kronrod<double, 31>::integrate(
                                [&](double phi) { return f.PiF(nl, nv, nl * nv + sl * sv * std::cos(phi)); },
                                0.0, kPi<double>, 10, 1e-15) / kPi<double>;
        EXPECT_NEAR(f.AzimuthMean(nl, nv), mean, 1e-14) << r << " " << nl << " " << nv;
      }
    }
    // F_D90 = 1/2 + 2 r (L.H)^2 = 1/2 + r (1 + L.V).
    const Vec3<double> wi = Normalize(Vec3<double>{0.3, 0.2, 0.8}), wo = Normalize(Vec3<double>{-0.5, 0.1, 0.4});
    const Vec3<double> h = Normalize(wi + wo);
    const double fd90 = 0.5 + 2 * r * Dot(wi, h) * Dot(wi, h);
    const double paper = (1 + (fd90 - 1) * std::pow(1 - wi.z, 5)) * (1 + (fd90 - 1) * std::pow(1 - wo.z, 5)) / kPi<double>;
    EXPECT_NEAR(f.Brdf(wi, wo), paper, 1e-15);
  }
}

TEST(SheenTest, Registry) {
  ModelParams p;
  p.kind = ParseModelKind("charlie");
  p.alpha_x = p.alpha_y = 0.25;
  p.visibility = SheenVisibility::kNeubelt;
  const auto m = MakeModel(p);
  const Vec3<double> wi = Normalize(Vec3<double>{0.3, 0.2, 0.8}), wo = Normalize(Vec3<double>{-0.5, 0.1, 0.4});
  EXPECT_DOUBLE_EQ(m->Brdf(wi, wo, Fresnel::One(), Masking::kHeightCorrelated, 0),
                   CharlieSheen<double>(0.25, SheenVisibility::kNeubelt).Brdf(wi, wo));
  EXPECT_THROW(m->Lambda(wi), std::invalid_argument);  // neubelt has no masking
  EXPECT_THROW(m->Brdf(wi, wo, Fresnel::Schlick({0.04, 0.04, 0.04}), Masking::kHeightCorrelated, 0),
               std::invalid_argument);
  EXPECT_NE(p.ToJson().find("\"visibility\":\"neubelt\""), std::string::npos);
  p.alpha_x = 1.5;
  EXPECT_THROW(ValidateModelParams(p), std::invalid_argument);
  p.alpha_x = 0.25;
  p.alpha_y = 0.3;
  EXPECT_THROW(ValidateModelParams(p), std::invalid_argument);

  ModelParams d;
  d.kind = ParseModelKind("disney-diffuse");
  d.alpha_x = d.alpha_y = 0;  // r = 0 is an ordinary lobe
  EXPECT_NO_THROW(ValidateModelParams(d));
  const auto md = MakeModel(d);
  EXPECT_FALSE(md->IsMicrofacet());
  EXPECT_THROW(md->D(wi), std::invalid_argument);
  EXPECT_DOUBLE_EQ(md->Brdf(wi, wo, Fresnel::One(), Masking::kHeightCorrelated, 0),
                   DisneyDiffuse<double>(0).Brdf(wi, wo));
  EXPECT_THROW(ParseSheenVisibility("ashikhmin"), std::invalid_argument);
  try {
    ParseSheenVisibility("ashikhmin");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'neubelt'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace brdfbake
