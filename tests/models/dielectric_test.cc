// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric BSDF ([Walter07], models/dielectric.h) over GGX and
// Beckmann: the closed forms it relies on, reciprocity, the furnace test
// against an independent visible-normal integral, the smooth-interface
// limit, the sampler's chi-square test and the normalization of its pdf.

#include "brdfbake/models/dielectric.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

using boost::math::quadrature::gauss_kronrod;
using test::Dir;
using Ggx = RoughDielectric<double, GgxNdf<double>>;
using Beck = RoughDielectric<double, BeckmannNdf<double>>;

const double kEtas[] = {1.5, 1 / 1.5, 1.33, 1 / 1.33, 2.4, 1 / 2.4, 1.05, 1 / 1.05};

Dir RandomSphere(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  return FromMuPhi(2 * uni(rng) - 1, kTwoPi<double> * uni(rng));
}

// Walter eq. 22, F = (g - c)^2 / (2 (g + c)^2) (1 + ((c (g + c) - 1) /
// (c (g - c) + 1))^2), g^2 = eta^2 - 1 + c^2 (1 for g^2 < 0), is the
// reflectance of fresnel.h (the kernels evaluate this form).
TEST(DielectricTest, FresnelIsWalterEq22) {
  for (double eta : kEtas) {
    for (double c = 0; c <= 1.0; c += 1.0 / 512) {
      const double g2 = eta * eta - 1 + c * c;
      double walter = 1;
      if (g2 > 0) {
        const double g = std::sqrt(g2);
        const double a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
        walter = 0.5 * a * a * (1 + b * b);
      }
      EXPECT_NEAR(FresnelDielectric(eta, c), walter, 1e-13) << eta << " " << c;
    }
  }
}

// Reciprocity: reflection f(wi, wo) = f(wo, wi); refraction f_t(wi, wo) /
// eta_o^2 = f_t(wo, wi) / eta_i^2 with eta_o the index of wo's side and
// eta_i that of wi's (1 above, eta below); the adjoint transport is the
// radiance BSDF with its arguments swapped.
template <class Model>
void CheckReciprocity(const Model& rad, const Model& imp, std::mt19937_64& rng, int* checked,
                      double* worst) {
  for (int k = 0; k < 4000; ++k) {
    const Dir wi = RandomSphere(rng), wo = RandomSphere(rng);
    const double f = rad.Bsdf(wi, wo), b = rad.Bsdf(wo, wi);
    ASSERT_TRUE(std::isfinite(f) && f >= 0) << f;
    const double ei = rad.IndexOf(wi), eo = rad.IndexOf(wo);
    const double lhs = f / (eo * eo), rhs = b / (ei * ei);
    if (std::max(lhs, rhs) > 1e-280)
      *worst = std::max(*worst, std::abs(lhs - rhs) / std::max(lhs, rhs));
    ASSERT_NEAR(lhs, rhs, 1e-13 * std::max(lhs, rhs) + 1e-300)
        << "eta " << rad.eta() << " wi.z " << wi.z << " wo.z " << wo.z;
    ASSERT_NEAR(imp.Bsdf(wi, wo), b, 1e-13 * b + 1e-300);
    if (f > 0) ++*checked;
  }
}

TEST(DielectricTest, Reciprocity) {
  std::mt19937_64 rng(7);
  int checked = 0;
  double worst = 0;
  for (double eta : kEtas) {
    for (double alpha : {0.05, 0.3, 1.0}) {
      for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        CheckReciprocity(Ggx(GgxNdf<double>(alpha), eta, mk, DielectricTransport::kRadiance),
                         Ggx(GgxNdf<double>(alpha), eta, mk, DielectricTransport::kImportance), rng,
                         &checked, &worst);
        CheckReciprocity(
            Beck(BeckmannNdf<double>(alpha), eta, mk, DielectricTransport::kRadiance),
            Beck(BeckmannNdf<double>(alpha), eta, mk, DielectricTransport::kImportance), rng,
            &checked, &worst);
      }
    }
  }
  EXPECT_GT(checked, 100000);  // most pairs are not degenerate
  std::printf("reciprocity: %d pairs, max relative difference %.3g\n", checked, worst);
}

// The half vectors: a reflection pair reflects about h, a refraction pair
// obeys Snell's law at h (eta_i sin_i = eta_o sin_o, tangential parts
// opposite), with wi.h and wo.h of the signs of wi.n and wo.n wherever f >
// 0; and the refraction formula is [Walter07] eq. 21 written with the
// angles of the pair.
TEST(DielectricTest, HalfVectorsObeyReflectionAndSnell) {
  std::mt19937_64 rng(3);
  for (double eta : kEtas) {
    const Ggx m(GgxNdf<double>(0.5), eta);
    for (int k = 0; k < 20000; ++k) {
      const Dir wi = RandomSphere(rng), wo = RandomSphere(rng);
      Dir h;
      if (!m.HalfVector(wi, wo, &h) || !(m.Bsdf(wi, wo) > 0)) continue;
      ASSERT_GT(h.z, 0);
      ASSERT_GT(Dot(wi, h) * wi.z, 0);
      ASSERT_GT(Dot(wo, h) * wo.z, 0);
      if ((wi.z > 0) == (wo.z > 0)) {
        const Dir r = Reflect(wo, h);
        ASSERT_NEAR(Length(r - wi), 0, 1e-12);
        continue;
      }
      const double ei = m.IndexOf(wi), eo = m.IndexOf(wo);
      const Dir ti = wi - h * Dot(wi, h), to = wo - h * Dot(wo, h);
      ASSERT_NEAR(Length(ti * ei + to * eo), 0, 1e-12);
      ASSERT_LT(Dot(wi, h) * Dot(wo, h), 0);
      // Eq. 21 from the angles: eta_o^2 (1 - F) D G |i.h||o.h| / (|i.n||o.n| (eta_i i.h + eta_o
      // o.h)^2).
      const double ci = Dot(wi, h), co = Dot(wo, h);
      const double g = 1 / (1 + m.Lambda(wi) + m.Lambda(wo));
      // F from wo's side equals F from wi's side (from the dense side near
      // the critical angle fresnel.h's form keeps fewer digits).
      const double f_o = FresnelDielectric(ei / eo, std::abs(co));
      const double f_i = FresnelDielectric(eo / ei, std::abs(ci));
      ASSERT_NEAR(f_o, f_i, 1e-7 * (1 - std::min(f_o, f_i)) + 1e-14);
      const double f = wi.z > 0 ? f_i : f_o;
      const double want = eo * eo * (1 - f) * m.ndf().D(h) * g * std::abs(ci * co) /
                          (std::abs(wi.z * wo.z) * std::pow(ei * ci + eo * co, 2));
      ASSERT_NEAR(m.Bsdf(wi, wo), want, 1e-10 * want);
    }
  }
}

// The exact height-correlated masking of a refraction pair: the integral
// over the heights, B(1 + a, 1 + b), at most the reflection form 1 / (1 +
// a + b) and equal to it when a or b is 0.
TEST(DielectricTest, HeightCorrelatedBetaIsTheHeightIntegral) {
  for (double a : {0.0, 0.01, 0.3, 1.0, 4.0, 30.0}) {
    for (double b : {0.0, 0.2, 1.0, 7.0}) {
      // tanh-sinh: the integrand's derivatives are singular at the ends.
      const double q = boost::math::quadrature::tanh_sinh<double>().integrate(
          [&](double u) { return std::pow(u, a) * std::pow(1 - u, b); }, 0.0, 1.0, 1e-14);
      EXPECT_NEAR(HeightCorrelatedBeta(a, b), q, 1e-12 * q) << a << " " << b;
      EXPECT_LE(HeightCorrelatedBeta(a, b), 1 / (1 + a + b) * (1 + 1e-12));
      if (a == 0 || b == 0) {
        EXPECT_NEAR(HeightCorrelatedBeta(a, b), 1 / (1 + a + b), 1e-13);
      }
    }
  }
}

// The integral of g(wi) over the sphere, for wo above the surface at
// azimuth 0 and g even in the azimuth, by nested adaptive Gauss-Kronrod
// quadrature over both hemispheres in (theta, phi), cut where the BSDF and
// the sampler's density have a peak, a jump or a kink: theta at the
// reflection and refraction directions, where the refraction half vector
// lies in the plane (s.z = 0: eta cos(theta) = wo.z, h flips there) and
// where the reflection's does (below, cos(theta) = wo.z); phi at the lobes
// (pi) and where the cones wi.wo = -eta and wi.wo = -1/eta (wi.s = 0,
// wo.s = 0: the chi+ edges) cross.
template <class G>
double SphereIntegral(const G& g, const Dir& wo, double eta, double tol) {
  using GK = gauss_kronrod<double, 61>;
  const double so = std::sqrt(std::max(0.0, 1 - wo.z * wo.z));
  auto hemi = [&](double sign, std::vector<double> cuts) {
    cuts.push_back(0);
    cuts.push_back(kPi<double> / 2);
    std::sort(cuts.begin(), cuts.end());
    auto inner = [&](double theta) {
      const double c = std::cos(theta), s = std::sin(theta);
      auto gp = [&](double phi) { return g(Dir(s * std::cos(phi), s * std::sin(phi), sign * c)); };
      std::vector<double> phis = {0.0, kPi<double>};
      for (double k : {-eta, -1 / eta}) {
        // sin_o s cos(phi) + wo.z sign c = k
        const double cp = (k - wo.z * sign * c) / (so * s);
        if (so * s > 0 && std::abs(cp) < 1) phis.push_back(std::acos(cp));
      }
      std::sort(phis.begin(), phis.end());
      double acc = 0;
      for (size_t k = 0; k + 1 < phis.size(); ++k) {
        acc += GK::integrate(gp, phis[k], phis[k + 1], 8, tol * 1e-2);
      }
      return 2 * s * acc;  // even in phi
    };
    double acc = 0;
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
      if (cuts[k + 1] > cuts[k]) acc += GK::integrate(inner, cuts[k], cuts[k + 1], 8, tol);
    }
    return acc;
  };
  std::vector<double> below = {std::acos(wo.z)};
  if (so / eta < 1) below.push_back(std::asin(so / eta));
  if (wo.z / eta < 1) below.push_back(std::acos(wo.z / eta));
  return hemi(1.0, {std::acos(wo.z)}) + hemi(-1.0, below);
}

// The energy albedo E(wo) = integral over the sphere of f*(wi, wo) |wi.n|
// dwi (the importance transport), for wo above at azimuth 0.
template <class Model>
double DirectAlbedo(const Model& m, const Dir& wo, double tol) {
  return SphereIntegral([&](const Dir& wi) { return m.BsdfCos(wi, wo); }, wo, m.eta(), tol);
}

// The same albedo as an integral over the visible normals of wo, mapped to
// the unit square by the NDF's exact visible-normal sampler (density D_wo,
// so du1 du2 = D_wo(m) dm): each normal reflects with F and refracts with
// 1 - F, and a path counts with G2 / G1(wo) when it ends on its own side
// ([Walter07] eq. 14, 17 cancel the Jacobians). Written from the
// microfacet picture, not from Bsdf or Pdf.
template <class Ndf>
struct BranchWeight {
  const Ndf& ndf;
  double eta;
  Masking mk;
  Dir wo;
  // F G2 / G1(wo) for the reflection about m plus (1 - F) G2 / G1(wo) for
  // the refraction through it, each where it ends on its own side.
  double operator()(const Dir& m) const {
    const double g1o = ndf.G1(wo);
    auto g2 = [&](const Dir& wi) {
      const Dir up(wi.x, wi.y, std::abs(wi.z));
      if (mk == Masking::kSeparable) return ndf.G1(up) * g1o;
      return 1 / (1 + ndf.Lambda(up) + ndf.Lambda(wo));
    };
    const double c = std::min(1.0, Dot(wo, m));
    const double f = FresnelDielectric(eta, c);
    double e = 0;
    const Dir r = Reflect(wo, m);
    if (r.z > 0) e += f * g2(r) / g1o;
    const double ct2 = 1 - (1 - c * c) / (eta * eta);
    if (ct2 > 0) {
      const Dir t = wo * (-1 / eta) + m * (c / eta - std::sqrt(ct2));
      if (t.z < 0) e += (1 - f) * g2(t) / g1o;
    }
    return e;
  }
};

template <class Ndf>
double VisibleNormalAlbedo(const Ndf& ndf, double eta, Masking mk, const Dir& wo, double tol) {
  using GK = gauss_kronrod<double, 31>;
  const BranchWeight<Ndf> e{ndf, eta, mk, wo};
  auto inner = [&](double u1) {
    return GK::integrate([&](double u2) { return e(ndf.SampleVisible(wo, u1, u2)); }, 0.0, 1.0,
                         8, tol * 1e-2);
  };
  return GK::integrate(inner, 0.0, 1.0, 8, tol);
}

// The same for Beckmann over the slopes (x, y) of m = normalize(-x, -y,
// 1), with wo at azimuth 0: D_wo(m) dm = G1(wo) / wo.z P22(x, y) (wo.z -
// x wo.x)^+ dx dy, P22 = exp(-(x^2 + y^2) / alpha^2) / (pi alpha^2); the
// factor (.)^+ ends at x = wo.z / wo.x (no Newton solve per node).
inline double BeckmannSlopeAlbedo(double alpha, double eta, Masking mk, const Dir& wo,
                                  double tol) {
  using GK = gauss_kronrod<double, 31>;
  const BeckmannNdf<double> ndf(alpha);
  const BranchWeight<BeckmannNdf<double>> e{ndf, eta, mk, wo};
  const double g1o = ndf.G1(wo), lim = 7 * alpha;
  const double x_hi = wo.x > 0 ? std::min(lim, wo.z / wo.x) : lim;
  auto inner = [&](double x) {
    auto g = [&](double y) {
      const double p22 = std::exp(-(x * x + y * y) / (alpha * alpha)) / (kPi<double> * alpha * alpha);
      return p22 * (wo.z - x * wo.x) * e(Normalize(Dir(-x, -y, 1)));
    };
    return 2 * GK::integrate(g, 0.0, lim, 8, tol * 1e-2);  // even in y
  };
  return g1o / wo.z * GK::integrate(inner, -lim, x_hi, 8, tol);
}

// The two agree to the rules' accuracy (observed 5.4e-7: the visible-normal
// integrand has square-root kinks where the microfacet cosine crosses the
// critical angle, which the square's rule does not align with).
struct FurnaceCase {
  double eta, alpha, mu;
};

template <class Ndf>
void CheckFurnace(const char* name, const FurnaceCase* cases, int n_cases) {
  double worst = 0;
  for (int k = 0; k < n_cases; ++k) {
    const FurnaceCase& c = cases[k];
    for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      const RoughDielectric<double, Ndf> m(Ndf(c.alpha), c.eta, mk,
                                           DielectricTransport::kImportance);
      const Dir wo = FromMuPhi(c.mu, 0.0);
      const double direct = DirectAlbedo(m, wo, 1e-8);
      const double vn = std::is_same_v<Ndf, BeckmannNdf<double>>
                            ? BeckmannSlopeAlbedo(c.alpha, c.eta, mk, wo, 1e-9)
                            : VisibleNormalAlbedo(Ndf(c.alpha), c.eta, mk, wo, 1e-8);
      worst = std::max(worst, std::abs(direct - vn));
      std::printf("%s eta %.4g alpha %g mu %g %s: E = %.9f (visible normals %.9f)\n", name, c.eta,
                  c.alpha, c.mu, MaskingName(mk), direct, vn);
      EXPECT_NEAR(direct, vn, 1e-6) << name << " eta " << c.eta << " alpha " << c.alpha << " mu "
                                    << c.mu << " " << MaskingName(mk);
      // Energy is lost, never gained: 1 - E is what single scattering misses.
      EXPECT_LE(direct, 1 + 1e-7);
      EXPECT_LE(vn, 1 + 1e-7);
      EXPECT_GT(vn, 0.3);
    }
  }
  std::printf("%s: furnace, direct vs visible-normal integral: max |diff| %.3g\n", name, worst);
}

TEST(DielectricTest, GgxFurnaceAgreesWithVisibleNormalIntegral) {
  const FurnaceCase cases[] = {{1.5, 0.1, 0.9},     {1.5, 0.5, 0.3}, {1 / 1.5, 0.1, 0.3},
                               {1 / 1.5, 0.5, 0.9}, {2.4, 0.3, 0.6}, {1 / 1.33, 0.9, 0.15}};
  CheckFurnace<GgxNdf<double>>("ggx", cases, 6);
}
TEST(DielectricTest, BeckmannFurnaceAgreesWithVisibleNormalIntegral) {
  const FurnaceCase cases[] = {{1.33, 0.2, 0.8}, {1.33, 0.6, 0.2}, {1 / 1.33, 0.3, 0.5},
                               {1 / 2.4, 0.6, 0.9}};
  CheckFurnace<BeckmannNdf<double>>("beckmann", cases, 4);
}

// A smooth interface loses nothing: as alpha -> 0 the albedo tends to 1
// for every view, on both sides, beyond the critical angle (total internal
// reflection, eta < 1) too; the loss shrinks in proportion to alpha.
TEST(DielectricTest, SmoothLimitAgreesWithOne) {
  double worst = 0;
  for (double eta : kEtas) {
    for (double mu : {0.99, 0.7, 0.4, 0.15}) {
      const Dir wo = FromMuPhi(mu, 0.0);
      double prev = 1;
      for (double alpha : {1e-2, 1e-3, 1e-4}) {
        const double e =
            VisibleNormalAlbedo(GgxNdf<double>(alpha), eta, Masking::kHeightCorrelated, wo, 1e-10);
        const double loss = 1 - e;
        EXPECT_GE(loss, -1e-9) << eta << " " << mu << " " << alpha;
        EXPECT_LE(loss, 2 * alpha / mu) << eta << " " << mu << " " << alpha;
        EXPECT_LE(loss, prev + 1e-9);
        prev = loss;
      }
      EXPECT_NEAR(prev, 0, 1e-6) << eta << " " << mu;
      worst = std::max(worst, prev);
    }
  }
  std::printf("smooth limit: 1 - E at alpha 1e-4 at most %.3g\n", worst);
  // The direct integral of the BSDF itself at a small width.
  for (double eta : {1.5, 1 / 1.5}) {
    const Ggx m(GgxNdf<double>(0.02), eta, Masking::kHeightCorrelated,
                DielectricTransport::kImportance);
    const double e = DirectAlbedo(m, FromMuPhi(0.8, 0.0), 1e-9);
    EXPECT_NEAR(e, 1, 0.01) << eta;
    EXPECT_LE(e, 1 + 1e-6);
  }
}

// The radiance BSDF of a nearly smooth interface carries (1 - F) (eta_o /
// eta_i)^2 of the radiance across: integral of f |wi.n| dwi over the other
// side.
TEST(DielectricTest, RadianceScalesByTheSquaredIndexRatio) {
  for (double eta : {1.5, 1.33}) {
    const Dir wo = FromMuPhi(0.9, 0.0);
    const Ggx rad(GgxNdf<double>(0.01), eta, Masking::kHeightCorrelated,
                  DielectricTransport::kRadiance);
    const Ggx imp(GgxNdf<double>(0.01), eta, Masking::kHeightCorrelated,
                  DielectricTransport::kImportance);
    const double t_rad = DirectAlbedo(rad, wo, 1e-9) - DirectAlbedo(imp, wo, 1e-9);
    // E_rad - E_imp = (1 / eta^2 - 1) T with T the transmitted energy.
    const double t = 1 - FresnelDielectric(eta, 0.9);
    EXPECT_NEAR(t_rad, (1 / (eta * eta) - 1) * t, 0.01 * t) << eta;
  }
}

// The sampler against its density, over the whole sphere, on both sides
// of the interface, past the critical angle; the density integrates to 1
// and the weights average to the albedo. A view below the surface is
// checked through the symmetry f(wi, wo; eta) = f(flip wi, flip wo; 1 /
// eta) (z mirrored; f_t depends only on the ratio of the indices).
// Widths up to 0.5: where a branch's normal reaches the horizon the GGX
// density jumps, which the 6 x 6 points per cell of the expected counts do
// not resolve at larger widths.
template <class Ndf>
void CheckSampler(const char* name) {
  struct Case {
    double alpha, eta, mu;
  };
  const Case cases[] = {{0.3, 1.5, 0.7},
                        {0.5, 1 / 1.5, 0.8},
                        {0.4, 1 / 1.5, 0.5},  // beyond the critical angle
                        {0.4, 1.33, -0.6},    // from below
                        {0.2, 2.4, 0.2}};
  const int n_tests = 2 * 5;
  uint64_t seed = 5;
  for (const Case& c : cases) {
    const RoughDielectric<double, Ndf> m(Ndf(c.alpha), c.eta, Masking::kHeightCorrelated,
                                         DielectricTransport::kImportance);
    const Dir wo = FromMuPhi(c.mu, 0.0);
    std::mt19937_64 rng(seed * 977);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    double wsum = 0;
    const int n = 1000000;
    const auto r = test::ChiSquareDirections(
        [&](double u1, double u2, Dir* wi) {
          const DielectricSample<double> s = m.Sample(wo, u1, u2, uni(rng));
          if (!(s.pdf > 0)) return false;
          EXPECT_NEAR(s.pdf, m.Pdf(s.wi, wo), 1e-9 * s.pdf);
          wsum += s.weight;
          *wi = s.wi;
          return true;
        },
        [&](const Dir& wi) { return m.Pdf(wi, wo); }, 60, 60, n, seed++, -1.0);
    // The mirrored view above, of index 1 / eta below.
    const bool up = wo.z > 0;
    const RoughDielectric<double, Ndf> mm(Ndf(c.alpha), up ? c.eta : 1 / c.eta,
                                          Masking::kHeightCorrelated,
                                          DielectricTransport::kImportance);
    const Dir wu(wo.x, wo.y, std::abs(wo.z));
    const double mass = SphereIntegral([&](const Dir& wi) { return mm.Pdf(wi, wu); }, wu, mm.eta(), 1e-8);
    const double e = DirectAlbedo(mm, wu, 1e-8);
    const double mean = wsum / n;
    std::printf("%s alpha %g eta %.4g mu %g: p = %.3g, pdf mass %.9f, E %.6f, mean weight %.6f\n",
                name, c.alpha, c.eta, c.mu, r.p_value, mass, e, mean);
    EXPECT_GT(r.p_value, test::ChiSquareAlpha(n_tests)) << name;
    EXPECT_NEAR(mass, 1.0, 1e-6) << name;
    EXPECT_NEAR(mean, e, 5e-3) << name;
    if (up) continue;
    // The symmetry itself, pointwise.
    for (int k = 0; k < 1000; ++k) {
      const Dir wi = FromMuPhi(2 * uni(rng) - 1, kTwoPi<double> * uni(rng));
      const Dir wf(wi.x, wi.y, -wi.z);
      EXPECT_NEAR(m.Bsdf(wi, wo), mm.Bsdf(wf, wu), 1e-12 * m.Bsdf(wi, wo));
    }
  }
}

TEST(DielectricTest, GgxSamplerChiSquare) { CheckSampler<GgxNdf<double>>("ggx"); }
TEST(DielectricTest, BeckmannSamplerChiSquare) { CheckSampler<BeckmannNdf<double>>("beckmann"); }

// Finite and non-negative everywhere, the stiff corners included: tiny
// widths, grazing directions, eta near 1 and near the critical angle.
TEST(DielectricTest, FiniteEverywhere) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (double eta : {1.0, 1.0001, 1 / 1.0001, 1.5, 1 / 1.5, 0.01, 100.0}) {
    for (double alpha : {1e-4, 1e-2, 0.5, 1.0, 10.0}) {
      for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        const Ggx g(GgxNdf<double>(alpha), eta, mk);
        const Beck b(BeckmannNdf<double>(alpha), eta, mk);
        for (int k = 0; k < 2000; ++k) {
          Dir wi = RandomSphere(rng), wo = RandomSphere(rng);
          if (k % 5 == 0) wi = FromMuPhi(std::copysign(std::pow(10.0, -7 * uni(rng)), wi.z), 1.0);
          if (k % 7 == 0) wo = FromMuPhi(std::copysign(std::pow(10.0, -7 * uni(rng)), wo.z), 2.0);
          for (double v : {g.Bsdf(wi, wo), b.Bsdf(wi, wo), g.Pdf(wi, wo), b.Pdf(wi, wo)}) {
            ASSERT_TRUE(std::isfinite(v) && v >= 0) << eta << " " << alpha << " " << v;
          }
          const DielectricSample<double> s = g.Sample(wo, uni(rng), uni(rng), uni(rng));
          ASSERT_TRUE(std::isfinite(s.pdf) && std::isfinite(s.weight))
              << eta << " " << alpha << " wo " << wo.x << " " << wo.y << " " << wo.z << " pdf "
              << s.pdf << " w " << s.weight << " wi " << s.wi.x << " " << s.wi.y << " " << s.wi.z;
          const DielectricSample<double> t = b.Sample(wo, uni(rng), uni(rng), uni(rng));
          ASSERT_TRUE(std::isfinite(t.pdf) && std::isfinite(t.weight)) << eta << " " << alpha;
        }
      }
    }
  }
}

}  // namespace
}  // namespace brdfbake
