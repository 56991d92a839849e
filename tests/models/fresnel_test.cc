// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/models/fresnel.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/model.h"

namespace brdfbake {
namespace {

TEST(FresnelTest, SchlickEndpoints) {
  EXPECT_DOUBLE_EQ(FresnelSchlick(0.04, 1.0), 0.04);
  EXPECT_DOUBLE_EQ(FresnelSchlick(0.04, 0.0), 1.0);
  EXPECT_NEAR(FresnelSchlick(0.04, 0.5), 0.04 + 0.96 / 32, 1e-15);
  EXPECT_DOUBLE_EQ(SchlickWeight(-0.5), 1.0);  // clamped
}

TEST(FresnelTest, DielectricNormalIncidenceAndGrazing) {
  for (double eta : {1.33, 1.5, 2.4}) {
    const double r0 = (eta - 1) / (eta + 1);
    EXPECT_NEAR(FresnelDielectric(eta, 1.0), r0 * r0, 1e-15);
    EXPECT_NEAR(FresnelDielectric(eta, 0.0), 1.0, 1e-15);
    // Monotone decreasing in the cosine.
    double prev = 1.0;
    for (double c = 0.01; c <= 1.0; c += 0.01) {
      const double f = FresnelDielectric(eta, c);
      EXPECT_LE(f, prev + 1e-15);
      prev = f;
    }
  }
  // Total internal reflection from the dense side.
  EXPECT_DOUBLE_EQ(FresnelDielectric(1.0 / 1.5, 0.3), 1.0);
}

TEST(FresnelTest, DielectricBrewsterAngle) {
  // At Brewster's angle tan(theta_B) = eta the parallel reflectance vanishes,
  // so F = r_perp^2 / 2 with r_perp = (c - eta c_t) / (c + eta c_t).
  const double eta = 1.5;
  const double theta_b = std::atan(eta);
  const double c = std::cos(theta_b);
  const double c_t = std::sqrt(1 - (1 - c * c) / (eta * eta));
  const double r_perp = (c - eta * c_t) / (c + eta * c_t);
  EXPECT_NEAR(FresnelDielectric(eta, c), 0.5 * r_perp * r_perp, 1e-15);
}

TEST(FresnelTest, ConductorMatchesKnownValues) {
  // Normal incidence: ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
  for (double n : {0.2, 1.1, 2.9}) {
    for (double k : {0.0, 0.5, 3.9}) {
      const double expected = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
      EXPECT_NEAR(FresnelConductor(n, k, 1.0), expected, 1e-14);
      EXPECT_NEAR(FresnelConductor(n, k, 0.0), 1.0, 1e-12);
    }
  }
  // Grazing incidence is total reflection even for eta = 1 (0/0 in the
  // general expression).
  EXPECT_EQ(FresnelConductor(1.0, 0.0, 0.0), 1.0);
  // k = 0 is a dielectric.
  for (double c = 0.05; c <= 1.0; c += 0.05) {
    EXPECT_NEAR(FresnelConductor(1.5, 0.0, c), FresnelDielectric(1.5, c), 1e-14);
  }
}

TEST(FresnelTest, ModelDispatchAndGrey) {
  const Fresnel one = Fresnel::One();
  EXPECT_TRUE(one.IsGrey());
  EXPECT_EQ(one.Eval(0.3, 0), 1.0);
  const Fresnel s = Fresnel::Schlick({0.9, 0.6, 0.3});
  EXPECT_FALSE(s.IsGrey());
  EXPECT_DOUBLE_EQ(s.Eval(1.0, 2), 0.3);
  const Fresnel c = Fresnel::Conductor({0.2, 0.9, 1.1}, {3.9, 2.4, 2.1});
  EXPECT_NEAR(c.Eval(0.6, 1), FresnelConductor(0.9, 2.4, 0.6), 1e-15);
  EXPECT_EQ(Fresnel::Dielectric(1.5).Name(), "dielectric");
}

// Over the whole domain (eta and n in [0.01, 100], k in [0, 100], every
// cosine, float and double) the reflectances are finite and in [0, 1]; the
// parameters outside it are refused in one line naming the parameter.
TEST(FresnelTest, FiniteOverTheDomainAndRefusedOutside) {
  std::vector<double> indices, cosines = {0.0, 1e-300, 1e-30, 1e-7, 1e-3, 0.1, 0.5, 0.9, 1 - 1e-7, 1.0};
  for (double e = -2; e <= 2.0001; e += 0.125) indices.push_back(std::pow(10.0, e));
  for (double eta : indices) {
    for (double c : cosines) {
      const double fd = FresnelDielectric(eta, c);
      const float ff = FresnelDielectric(float(eta), float(c));
      ASSERT_TRUE(fd >= 0 && fd <= 1) << eta << " " << c << " " << fd;
      ASSERT_TRUE(ff >= 0 && ff <= 1) << eta << " " << c << " " << ff;
      for (double k : {0.0, 1e-3, 0.5, 3.0, 30.0, 100.0}) {
        const double fc = FresnelConductor(eta, k, c);
        const float fcf = FresnelConductor(float(eta), float(k), float(c));
        ASSERT_TRUE(fc >= 0 && fc <= 1 + 1e-12) << eta << " " << k << " " << c << " " << fc;
        ASSERT_TRUE(fcf >= 0 && fcf <= 1 + 1e-6f) << eta << " " << k << " " << c << " " << fcf;
      }
    }
  }
  const double nan = std::nan("");
  const std::vector<std::pair<Fresnel, std::string>> bad = {
      {Fresnel::Dielectric(1e-300), "eta"},
      {Fresnel::Dielectric(0), "eta"},
      {Fresnel::Dielectric(1e3), "eta"},
      {Fresnel::Dielectric(nan), "eta"},
      {Fresnel::Conductor({1e-300, 1, 1}, {0, 0, 0}), "n[0]"},
      {Fresnel::Conductor({1, 1, 1}, {0, -1, 0}), "k[1]"},
      {Fresnel::Conductor({1, 1, nan}, {0, 0, 0}), "n[2]"},
      {Fresnel::Schlick({0.04, 1.5, 0.04}), "f0[1]"},
  };
  for (const auto& [f, field] : bad) {
    try {
      ValidateFresnel(f);
      ADD_FAILURE() << "accepted " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(ValidateFresnel(Fresnel::Conductor({0.01, 100, 1}, {0, 100, 3})));
  EXPECT_NO_THROW(ValidateFresnel(Fresnel::Dielectric(0.01)));
}

}  // namespace
}  // namespace brdfbake
