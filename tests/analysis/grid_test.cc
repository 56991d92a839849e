// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Grid evaluation: the SIMD path against the double scalar reference at
// every pixel, thread-count independence, and the geometry of each grid.

#include "brdfbake/grid.h"

#include <cmath>

#include <gtest/gtest.h>

#include "brdfbake/batch.h"
#include "brdfbake/models/ggx.h"

namespace brdfbake {
namespace {

TEST(GridTest, SimdSliceMatchesScalarModel) {
 // Each Fresnel kind: grey on the SIMD path, coloured (channel 0 the same)
 // on the scalar one.
 struct FresnelPair {
  Fresnel grey, coloured;
 };
 const FresnelPair fresnels[] = {
     {Fresnel::Schlick({0.04, 0.04, 0.04}), Fresnel::Schlick({0.04, 0.5, 0.5})},
     {Fresnel::Conductor({0.2, 0.2, 0.2}, {3, 3, 3}), Fresnel::Conductor({0.2, 1, 1}, {3, 2, 2})}};
 for (const FresnelPair& fp : fresnels) {
 for (const char* model : {"ggx", "beckmann", "std", "ellipsoid"}) {
  GridRequest req;
  req.model.kind = ParseModelKind(model);
  req.model.gamma = 3.0;
  req.model.theta_x = 0.3;
  req.model.alpha_x = 0.2;
  req.model.alpha_y = 0.45;
  req.fresnel = fp.grey;
  req.width = 64;
  req.height = 48;
  const Grid simd = EvalGrid(req);
  EXPECT_EQ(simd.path.rfind("simd:", 0), 0u);
  // Same request through the scalar path: a coloured Fresnel forces it, and
  // channel 0 of it equals the grey one.
  GridRequest scalar_req = req;
  scalar_req.fresnel = fp.coloured;
  const Grid scalar = EvalGrid(scalar_req);
  EXPECT_EQ(scalar.path, "scalar");
  double worst = 0;
  for (size_t i = 0; i < simd.values.size(); ++i) {
    const double ref = scalar.values[i];
    const double err = std::abs(simd.values[i] - ref) / std::max(std::abs(ref), 1e-30);
    worst = std::max(worst, err);
    // Float kernel bounds (plus the float rounding of the reference); D's
    // exponent grows the Beckmann/std bound in the far tail, where values
    // are tiny: compare those absolutely.
    ASSERT_LT(std::min(err, std::abs(simd.values[i] - ref)), 5e-5) << model << " " << i;
  }
  std::printf("slice %s: SIMD (%s) vs scalar max relative difference %.3g\n", model,
              simd.path.c_str(), worst);
 }
 }
}

TEST(GridTest, BitIdenticalAtAnyThreadCount) {
  for (GridKind kind : {GridKind::kSlice, GridKind::kHemisphere, GridKind::kG1}) {
    GridRequest req;
    req.kind = kind;
    req.width = 37;
    req.height = 29;
    req.threads = 1;
    const Grid a = EvalGrid(req);
    req.threads = 2;
    const Grid b = EvalGrid(req);
    EXPECT_EQ(a.values, b.values) << GridKindName(kind);
  }
}

TEST(GridTest, GeometryOfEachGrid) {
  GridRequest req;
  req.kind = GridKind::kHemisphere;
  req.width = req.height = 32;
  const Grid h = EvalGrid(req);
  EXPECT_EQ(h.values[0], 0.0f);               // corner: outside the disk
  EXPECT_GT(h.values[16 * 32 + 16], 0.0f);    // centre
  req.kind = GridKind::kG1;
  const Grid g = EvalGrid(req);
  for (int y = 0; y < 32; ++y) {
    for (int x = 1; x < 32; ++x) {
      EXPECT_GE(g.values[y * 32 + x], g.values[y * 32 + x - 1] - 1e-7f);  // G1 grows with mu
      EXPECT_LE(g.values[y * 32 + x], 1.0f);
    }
  }
  // G1 at mu = 0.5 (x = 15.5 is not a centre, so check a direct value).
  const GgxNdf<double> ndf(std::pow((3 + 0.5) / 32, 2));
  EXPECT_NEAR(g.values[3 * 32 + 20], ndf.G1(FromMuPhi((20 + 0.5) / 32, 0.0)), 2e-6);
}

TEST(GridTest, RejectsBadRequests) {
  GridRequest req;
  req.width = 0;
  EXPECT_THROW(EvalGrid(req), std::invalid_argument);
  req.width = 8;
  req.model.kind = ModelKind::kSel;
  EXPECT_THROW(EvalGrid(req), std::invalid_argument);
  EXPECT_THROW(ParseGridKind("cube"), std::invalid_argument);
}

}  // namespace
}  // namespace brdfbake
