// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The baker: tables against independent high-precision integration, the
// exact value 1 - ln 2, Blender Cycles' shipped GGX table, honest error
// claims for every integrator, dfg.scale + dfg.bias = E, E_avg consistent
// with E, bit-identical output at any thread count, and the file format.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/exr.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "reference/reference_albedo.h"
#include "util/test_util.h"


namespace brdfbake {
namespace {

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "/brdfbake_" + name;
}

const Table& DefaultGgxTable() {
  static const Table t = [] {
    BakeSpec spec;  // E, ggx, 32x32, edges, quadrature
    return Bake(spec);
  }();
  return t;
}

TEST(BakeTest, DefaultGgxTableHasOneMinusLn2AtAlphaOneMuOne) {
  const Table& t = DefaultGgxTable();
  ASSERT_EQ(t.width, 32);
  ASSERT_EQ(t.height, 32);
  const double e = t.channels[0].values[31 * 32 + 31];
  std::printf("E(mu=1, r=1) = %.12f, 1 - ln 2 = %.12f, claimed max error %.3g\n", e,
              1 - std::log(2.0), t.max_abs_error);
  EXPECT_NEAR(e, 1 - std::log(2.0), 1e-9);
  EXPECT_LE(t.max_abs_error, 1e-6);
}

TEST(BakeTest, DefaultGgxTableAgreesWithIndependentIntegration) {
  const Table& t = DefaultGgxTable();
  double worst = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = (y % 2); x < 32; x += 2) {
      const double r = t.spec.roughness.Value(y), mu = t.spec.mu.Value(x);
      const double value = t.channels[0].values[y * 32 + x];
      const double ref = r == 0 ? 1.0 : ReferenceE(r * r, mu);
      // The reference's own uncertainty: ten times the change from a looser
      // tolerance (it matters only at the grazing edge mu = 0).
      const double ref_loose = r == 0 ? 1.0 : ReferenceE(r * r, mu, Masking::kHeightCorrelated, 1e-8);
      const double ref_err = 10 * std::abs(ref - ref_loose);
      const double err = std::abs(value - ref);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-6) << "r=" << r << " mu=" << mu;
      EXPECT_LE(err, t.max_abs_error + ref_err) << "r=" << r << " mu=" << mu;
    }
  }
  std::printf("max |table - reference| over the sampled texels: %.3g (claimed %.3g)\n", worst,
              t.max_abs_error);
}

// Blender Cycles' table_ggx_E (32x32, height-correlated GGX, alpha = r^2,
// r = x/31 and mu = y/31 clamped below at 1e-4, 2^23 Sobol samples, printed
// with six decimals): a few of its rows.
TEST(BakeTest, AgreesWithCyclesTable) {
  struct Row {
    int y;
    double values[8];
  };
  const int xs[8] = {1, 2, 4, 8, 12, 16, 24, 31};
  const Row rows[] = {
      {0, {0.980405, 0.994967, 0.998725, 0.999634, 0.999738, 0.999693, 0.999429, 0.999079}},
      {1, {0.999451, 0.990086, 0.911203, 0.917411, 0.947567, 0.952096, 0.927272, 0.888202}},
      {2, {0.999866, 0.997676, 0.962386, 0.888687, 0.911810, 0.918982, 0.881006, 0.819138}},
      {31, {0.999999, 0.999983, 0.999716, 0.995072, 0.971982, 0.903873, 0.592102, 0.306853}},
  };
  BakeSpec spec;
  double worst = 0;
  for (const Row& row : rows) {
    const double mu = std::max(row.y / 31.0, 1e-4);
    for (int i = 0; i < 8; ++i) {
      const double r = xs[i] / 31.0;
      const TexelEstimate v = IntegrateTexel(spec, r, mu);
      const double diff = std::abs(v.e - row.values[i]);
      worst = std::max(worst, diff);
      // Cycles' values carry Monte Carlo noise and 5e-7 of print rounding.
      EXPECT_LT(diff, 3e-6) << "r=" << r << " mu=" << mu << " ours " << v.e;
    }
  }
  std::printf("max |ours - Cycles| = %.3g\n", worst);
}

TEST(BakeTest, DfgSumsToE) {
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = spec.roughness.size = 8;
  const Table dfg = Bake(spec);
  spec.table = TableKind::kE;
  const Table e = Bake(spec);
  ASSERT_EQ(dfg.channels.size(), 2u);
  EXPECT_EQ(dfg.channels[0].name, "dfg.0_scale");
  EXPECT_EQ(dfg.channels[0].meaning, Meaning::kDfgScale);
  EXPECT_EQ(dfg.channels[1].name, "dfg.1_bias");
  EXPECT_EQ(dfg.channels[1].meaning, Meaning::kDfgBias);
  for (size_t i = 0; i < e.channels[0].values.size(); ++i) {
    const double sum = dfg.channels[0].values[i] + dfg.channels[1].values[i];
    // E comes from the one-dimensional rule (azimuth in closed form), dfg
    // from the rule over the visible-normal disk: they agree within the
    // two claims.
    EXPECT_NEAR(sum, e.channels[0].values[i], e.integration_error + dfg.integration_error);
    EXPECT_GE(dfg.channels[1].values[i], 0.0);
  }
}

// The mirror texel at mu = 0, r = 0 is evaluated at mu = 1e-7 like every
// grazing texel, as the header says: (1 - (1 - 1e-7)^5, (1 - 1e-7)^5), not
// the limit (0, 1); and it agrees with the texel integrated alone.
TEST(BakeTest, MirrorTexelAtGrazingIsEvaluatedAtMuMin) {
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = spec.roughness.size = 4;  // edges: the first texel is mu = 0, r = 0
  const Table t = Bake(spec);
  const double fc = std::pow(1 - 1e-7, 5);
  EXPECT_NEAR(t.channels[0].values[0], 1 - fc, 1e-15);  // 5e-7, against 0 before
  EXPECT_NEAR(t.channels[1].values[0], fc, 1e-15);
  const TexelEstimate alone = IntegrateTexel(spec, 0.0, 0.0);
  EXPECT_EQ(t.channels[0].values[0], alone.scale);
  EXPECT_EQ(t.channels[1].values[0], alone.bias);
  EXPECT_NE(t.channels[0].values[0], 0.0);
}

// Every integrator's claimed maximum error bounds its true error against a
// converged quadrature.
TEST(BakeTest, ErrorClaimsBoundTheTrueError) {
  BakeSpec ref_spec;
  ref_spec.mu.size = ref_spec.roughness.size = 6;
  ref_spec.tolerance = 1e-11;
  const Table ref = Bake(ref_spec);
  struct Case {
    IntegratorKind kind;
    int samples;
  };
  for (const Case& c : {Case{IntegratorKind::kQuadrature, 24}, Case{IntegratorKind::kQuadrature, 0},
                        Case{IntegratorKind::kQmc, 256}, Case{IntegratorKind::kQmc, 4096},
                        Case{IntegratorKind::kMc, 512}, Case{IntegratorKind::kEngine, 1024},
                        Case{IntegratorKind::kEngine, 64}}) {
    BakeSpec spec = ref_spec;
    spec.tolerance = 1e-8;
    spec.integrator = c.kind;
    spec.samples = c.samples;
    const Table t = Bake(spec);
    double worst = 0;
    for (size_t i = 0; i < t.channels[0].values.size(); ++i) {
      worst = std::max(worst, std::abs(t.channels[0].values[i] - ref.channels[0].values[i]));
    }
    std::printf("%-10s samples %5d: true max error %.3g, claimed %.3g\n",
                IntegratorName(c.kind), c.samples, worst, t.max_abs_error);
    EXPECT_LE(worst, t.max_abs_error) << IntegratorName(c.kind) << " " << c.samples;
  }
}

TEST(BakeTest, EavgIsConsistentWithE) {
  BakeSpec spec;
  spec.table = TableKind::kEavg;
  spec.roughness.size = 5;
  const Table avg = Bake(spec);
  ASSERT_EQ(avg.width, 5);
  ASSERT_EQ(avg.height, 1);
  // Against 2 int E mu dmu from a fine E table (Simpson's rule over 257
  // edges-placed mu values; E is smooth away from mu = 0 and mu E -> 0).
  spec.table = TableKind::kE;
  spec.mu.size = 257;
  const Table e = Bake(spec);
  for (int y = 0; y < 5; ++y) {
    double acc = 0;
    for (int x = 0; x < 257; ++x) {
      const double w = (x == 0 || x == 256) ? 1 : (x % 2 ? 4 : 2);
      acc += w * e.channels[0].values[y * 257 + x] * spec.mu.Value(x);
    }
    const double simpson = 2 * acc / (3 * 256);
    EXPECT_NEAR(avg.channels[0].values[y], simpson, 2e-6) << "r=" << spec.roughness.Value(y);
  }
  // Cycles' table_ggx_Eavg at r = 1 (2^26 samples): 0.409137.
  EXPECT_NEAR(avg.channels[0].values[4], 0.409137, 3e-6);
  EXPECT_NEAR(avg.channels[0].values[0], 1.0, 1e-12);  // mirror
}

// The quadrature's E_avg meets its tolerance and its claim bounds the error
// against the same integral converged to 1e-10, for every model, including
// the heavy-tailed STD (gamma 1.6), where E's boundary layer at grazing is
// not smooth (a fixed 32-node rule was 1.7e-6 off there, within its own
// claim of 1.3e-5).
TEST(BakeTest, EavgMeetsItsToleranceAndClaim) {
  struct Case {
    const char* model;
    double gamma;
  };
  for (const Case& c : {Case{"ggx", 2}, Case{"beckmann", 2}, Case{"std", 1.6}, Case{"std", 3}}) {
    BakeSpec spec;
    spec.table = TableKind::kEavg;
    spec.model.kind = ParseModelKind(c.model);
    spec.model.gamma = c.gamma;
    BakeSpec ref_spec = spec;
    ref_spec.tolerance = 1e-10;
    for (double r : {0.05, 0.5, 1.0}) {
      const EavgEstimate got = IntegrateEavg(spec, r);
      const EavgEstimate ref = IntegrateEavg(ref_spec, r);
      EXPECT_LE(got.error, 1.1e-7) << c.model << " " << c.gamma << " r " << r;
      EXPECT_LE(std::abs(got.value - ref.value), got.error + ref.error)
          << c.model << " " << c.gamma << " r " << r;
    }
  }
}

// Quadrature and QMC; std over a gamma axis; ggx-aniso's 4D table; an
// ellipsoid material's E and E_avg; sel_norm.
TEST(BakeTest, BitIdenticalAtAnyThreadCount) {
  std::vector<BakeSpec> specs;
  for (IntegratorKind kind : {IntegratorKind::kQuadrature, IntegratorKind::kQmc}) {
    BakeSpec spec;
    spec.integrator = kind;
    spec.samples = kind == IntegratorKind::kQmc ? 512 : 64;
    spec.mu.size = spec.roughness.size = 12;
    specs.push_back(spec);
  }
  BakeSpec gamma;
  gamma.model.kind = ModelKind::kStudentT;
  gamma.mu.size = gamma.roughness.size = 6;
  gamma.gamma.size = 5;
  specs.push_back(gamma);
  BakeSpec aniso;
  aniso.model.kind = ModelKind::kGgxAniso;
  aniso.mu.size = aniso.roughness.size = 4;
  aniso.phi.size = aniso.anisotropy.size = 3;
  specs.push_back(aniso);
  BakeSpec ellipsoid;
  ellipsoid.model.kind = ModelKind::kEllipsoid;
  ellipsoid.model.alpha_x = 0.3;
  ellipsoid.model.alpha_y = 0.6;
  ellipsoid.model.theta_x = 0.4;
  ellipsoid.mu.size = 4;
  ellipsoid.phi.size = 5;
  ellipsoid.phi.max = 6.283185307179586;
  specs.push_back(ellipsoid);
  ellipsoid.table = TableKind::kEavg;  // its E values in parallel
  specs.push_back(ellipsoid);
  BakeSpec sel;
  sel.table = TableKind::kSelNorm;
  sel.model.kind = ModelKind::kSel;
  sel.alpha_x.size = sel.alpha_y.size = 5;
  specs.push_back(sel);
  for (BakeSpec spec : specs) {
    spec.threads = 1;
    const Table a = Bake(spec);
    spec.threads = 2;
    const Table b = Bake(spec);
    ASSERT_EQ(a.channels[0].values, b.channels[0].values);
    EXPECT_EQ(a.max_abs_error, b.max_abs_error);
    const std::string pa = TempPath("t1.exr"), pb = TempPath("t2.exr");
    WriteExr(a, pa);
    WriteExr(b, pb);
    std::ifstream fa(pa, std::ios::binary), fb(pb, std::ios::binary);
    const std::string da((std::istreambuf_iterator<char>(fa)), std::istreambuf_iterator<char>());
    const std::string db((std::istreambuf_iterator<char>(fb)), std::istreambuf_iterator<char>());
    EXPECT_FALSE(da.empty());
    EXPECT_EQ(da, db);
  }
}

// Every model's dfg and E tables bit-identical at 1 and 2 threads with the
// SIMD rules, and within 1e-13 (per value, before storage) of the same
// tables from the double scalar reference (`--target scalar`); with every
// integrator (the sampling ones on the same points in lanes and in the
// reference).
TEST(BakeTest, SimdTablesAgreeWithTheScalarReference) {
  for (IntegratorKind integrator : {IntegratorKind::kQuadrature, IntegratorKind::kQmc,
                                    IntegratorKind::kMc, IntegratorKind::kEngine}) {
    for (const char* model : {"ggx", "beckmann", "std"}) {
      for (TableKind table : {TableKind::kDfg, TableKind::kE, TableKind::kEavg}) {
        BakeSpec spec;
        spec.table = table;
        spec.integrator = integrator;
        spec.model.kind = ParseModelKind(model);
        spec.model.gamma = 1.8;
        const bool sampling = integrator != IntegratorKind::kQuadrature;
        spec.samples = sampling ? 128 : 0;
        spec.mu.size = spec.roughness.size = sampling ? 5 : 9;
        spec.threads = 1;
        const Table one = Bake(spec);
        spec.threads = 2;
        const Table two = Bake(spec);
        spec.simd = false;
        const Table ref = Bake(spec);
        for (size_t c = 0; c < ref.channels.size(); ++c) {
          ASSERT_EQ(one.channels[c].values, two.channels[c].values) << model;
          for (size_t i = 0; i < ref.channels[c].values.size(); ++i) {
            EXPECT_NEAR(two.channels[c].values[i], ref.channels[c].values[i], 1e-13)
                << model << " " << TableName(table) << " channel " << c << " texel " << i
                << " integrator " << IntegratorName(integrator);
          }
        }
      }
    }
  }
}

TEST(BakeTest, ExrCarriesEveryAttribute) {
  BakeSpec spec;
  spec.mu.size = 16;
  spec.roughness.size = 8;
  spec.mu.placement = spec.roughness.placement = Placement::kCenters;
  spec.roughness.warp = Warp::kSquare;
  spec.error_channel = true;
  spec.complement = true;
  const Table t = Bake(spec);
  const std::string path = TempPath("attrs.exr");
  WriteExr(t, path);
  const ExrContents c = ReadExr(path);
  EXPECT_EQ(c.width, 16);
  EXPECT_EQ(c.height, 8);
  EXPECT_FALSE(c.half);
  EXPECT_EQ(c.Attribute("brdfbake.version"), "0.1.0");
  EXPECT_EQ(c.Attribute("brdfbake.table"), "E");
  EXPECT_EQ(c.Attribute("brdfbake.masking"), "height-correlated");
  EXPECT_EQ(c.Attribute("brdfbake.fresnel"), "one");
  const auto model = nlohmann::json::parse(c.Attribute("brdfbake.model"));
  EXPECT_EQ(model["name"], "ggx");
  const auto axes = nlohmann::json::parse(c.Attribute("brdfbake.axes"));
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[0]["name"], "mu");
  EXPECT_EQ(axes[0]["size"], 16);
  EXPECT_EQ(axes[0]["placement"], "centers");
  EXPECT_EQ(axes[1]["name"], "roughness");
  EXPECT_EQ(axes[1]["warp"], "square");
  EXPECT_EQ(axes[1]["min"], 0.0);
  EXPECT_EQ(axes[1]["max"], 1.0);
  const auto channels = nlohmann::json::parse(c.Attribute("brdfbake.channels"));
  EXPECT_EQ(channels["1-E"], "1-E");
  EXPECT_EQ(channels["error"], "error");
  const auto integrator = nlohmann::json::parse(c.Attribute("brdfbake.integrator"));
  EXPECT_EQ(integrator["method"], "quadrature");
  const double claimed = std::stod(c.Attribute("brdfbake.max_abs_error"));
  EXPECT_GT(claimed, 0);
  EXPECT_LE(t.max_abs_error, claimed * 1.001);
  // Pixel values: row 0 is the first roughness (centers, square warp).
  const std::vector<float>* one_minus_e = c.ChannelData("1-E");
  ASSERT_NE(one_minus_e, nullptr);
  for (int i = 0; i < 16 * 8; ++i) {
    EXPECT_EQ((*one_minus_e)[i], static_cast<float>(t.channels[0].values[i]));
  }
  const TexelEstimate v = IntegrateTexel(spec, spec.roughness.Value(3), spec.mu.Value(5));
  EXPECT_NEAR((*one_minus_e)[3 * 16 + 5], 1 - v.e, 1e-7);
}

TEST(BakeTest, HalfPixelsAndNoPartialFiles) {
  BakeSpec spec;
  spec.mu.size = spec.roughness.size = 4;
  spec.half = true;
  const Table t = Bake(spec);
  const std::string path = TempPath("half.exr");
  WriteExr(t, path);
  const ExrContents c = ReadExr(path);
  EXPECT_TRUE(c.half);
  double rounding = 0;
  for (size_t i = 0; i < 16; ++i) {
    EXPECT_NEAR(c.channels[0].second[i], t.channels[0].values[i], 1e-3);
    rounding = std::max(rounding, std::abs(c.channels[0].second[i] - t.channels[0].values[i]));
  }
  EXPECT_GT(rounding, 1e-4);
  // The half rounding of every texel is part of the claim.
  EXPECT_GE(t.max_abs_error, rounding);
  EXPECT_LE(t.max_abs_error, rounding + t.integration_error);
  EXPECT_THROW(WriteExr(t, "/nonexistent-dir/x.exr"), std::runtime_error);
}

TEST(BakeTest, OtherModelsBakeFinite) {
  for (const char* model : {"beckmann", "std"}) {
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      BakeSpec spec;
      spec.model.kind = ParseModelKind(model);
      spec.model.gamma = 3.5;
      spec.masking = masking;
      spec.mu.size = spec.roughness.size = 6;
      spec.tolerance = 1e-7;
      const Table t = Bake(spec);
      for (double v : t.channels[0].values) {
        EXPECT_TRUE(std::isfinite(v));
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0 + 1e-9);
      }
      std::printf("%s %s: max claimed error %.3g\n", model, MaskingName(masking),
                  t.max_abs_error);
    }
  }
  // std at gamma = 2 bakes the GGX table.
  BakeSpec g;
  g.mu.size = g.roughness.size = 5;
  BakeSpec s = g;
  s.model.kind = ModelKind::kStudentT;
  s.model.gamma = 2;
  const Table tg = Bake(g), ts = Bake(s);
  for (size_t i = 0; i < tg.channels[0].values.size(); ++i) {
    EXPECT_NEAR(tg.channels[0].values[i], ts.channels[0].values[i], 2e-6);
  }
}

// The sampling integrators of the sheen and diffuse lobes (their own
// samplers: the Charlie NDF, the cosine) agree with the quadrature within
// their claims (4 standard errors; the engine setting's error is measured
// against the quadrature), and bake whole tables, E_avg included.
TEST(BakeTest, SheenSamplingIntegratorsAgreeWithTheQuadrature) {
  if (!ModelBuilt(ModelKind::kCharlie) || !ModelBuilt(ModelKind::kDisneyDiffuse)) GTEST_SKIP();
  struct Case {
    ModelKind model;
    SheenVisibility visibility;
  };
  double worst = 0;
  for (const Case& c : {Case{ModelKind::kCharlie, SheenVisibility::kNeubelt},
                        Case{ModelKind::kCharlie, SheenVisibility::kContyKullaClamped},
                        Case{ModelKind::kCharlie, SheenVisibility::kEnterprisePbr},
                        Case{ModelKind::kDisneyDiffuse, SheenVisibility::kContyKulla}}) {
    for (double r : {0.3, 0.7, 1.0}) {
      for (double mu : {0.1, 0.5, 0.95}) {
        BakeSpec q;
        q.model.kind = c.model;
        q.model.visibility = c.visibility;
        const TexelEstimate exact = IntegrateTexel(q, r, mu);
        for (IntegratorKind kind : {IntegratorKind::kQmc, IntegratorKind::kMc, IntegratorKind::kEngine}) {
          BakeSpec s = q;
          s.integrator = kind;
          s.samples = 8192;
          const TexelEstimate v = IntegrateTexel(s, r, mu, 17);
          ASSERT_TRUE(std::isfinite(v.e) && std::isfinite(v.err_e)) << IntegratorName(kind);
          const double d = std::abs(v.e - exact.e);
          worst = std::max(worst, d / (v.err_e + exact.err_e));
          EXPECT_LE(d, v.err_e + exact.err_e) << ModelName(c.model) << " " << SheenVisibilityName(c.visibility)
                                              << " " << IntegratorName(kind) << " r " << r << " mu " << mu;
          // The claims are useful: QMC to about 1%, plain MC 20%, the
          // engine setting (Hammersley with the lobe's sampler) 5%.
          const double useful = kind == IntegratorKind::kQmc ? 0.02 : kind == IntegratorKind::kMc ? 0.2 : 0.05;
          EXPECT_LT(v.err_e, useful * std::max(0.1, exact.e)) << IntegratorName(kind) << " r " << r << " mu " << mu;
        }
      }
    }
  }
  std::printf("sheen sampling integrators: max |estimate - quadrature| / claim %.3g\n", worst);
  for (ModelKind m : {ModelKind::kCharlie, ModelKind::kDisneyDiffuse}) {
    for (TableKind t : {TableKind::kE, TableKind::kEavg}) {
      BakeSpec s;
      s.model.kind = m;
      s.table = t;
      s.integrator = IntegratorKind::kQmc;
      s.samples = 1024;
      s.mu.size = s.roughness.size = 4;
      const Table tab = Bake(s);
      for (double v : tab.channels[0].values) EXPECT_TRUE(std::isfinite(v) && v >= 0);
      EXPECT_GT(tab.max_abs_error, 0);
      EXPECT_NE(tab.integrator_json.find("sampling"), std::string::npos);
      // E_avg by the sampling integrators is the 32-node rule over their E,
      // whatever the lobe's own quadrature does.
      if (t == TableKind::kEavg) {
        const auto j = nlohmann::json::parse(tab.integrator_json);
        EXPECT_NE(j["E_avg"].get<std::string>().find("32-node Gauss-Legendre"), std::string::npos)
            << ModelName(m);
      }
    }
  }
}

// Tables at the edges of the domain (std with gamma near 1.5, moderate and
// huge; beckmann; both masking variants) agree with the independent
// half-vector integration to 1e-5 at every texel, including the alpha = 0
// (mirror) row and the mu = 0 (grazing limit) column.
TEST(BakeTest, ExtremeTablesAgreeWithIndependentIntegration) {
  struct Case {
    const char* model;
    double gamma;
    Masking masking;
  };
  const Case cases[] = {{"std", 1.55, Masking::kHeightCorrelated},
                        {"std", 3.5, Masking::kSeparable},
                        {"std", 1e6, Masking::kHeightCorrelated},
                        {"beckmann", 2, Masking::kSeparable}};
  for (const Case& c : cases) {
    BakeSpec spec;
    spec.model.kind = ParseModelKind(c.model);
    spec.model.gamma = c.gamma;
    spec.masking = c.masking;
    spec.mu.size = 5;
    spec.roughness.size = 5;
    const Table t = Bake(spec);
    double worst = 0;
    for (int y = 0; y < 5; ++y) {
      for (int x = 0; x < 5; ++x) {
        const double r = spec.roughness.Value(y), mu = spec.mu.Value(x);
        const double value = t.channels[0].values[y * 5 + x];
        ASSERT_TRUE(std::isfinite(value));
        double ref = 1.0;  // mirror row
        if (r > 0) {
          const double alpha = r * r;
          ref =
              std::string(c.model) == "std"
                  ? ReferenceEFor(StudentTNdf<double>(alpha, alpha, c.gamma), mu, c.masking, 1e-10)
                  : ReferenceEFor(BeckmannNdf<double>(alpha), mu, c.masking, 1e-10);
        }
        worst = std::max(worst, std::abs(value - ref));
        EXPECT_NEAR(value, ref, 1e-5) << c.model << " gamma=" << c.gamma << " r=" << r
                                      << " mu=" << mu;
      }
    }
    std::printf("%s gamma=%g %s: max |table - reference| %.3g (claimed %.3g)\n", c.model,
                c.gamma, MaskingName(c.masking), worst, t.max_abs_error);
  }
}

TEST(BakeTest, RejectsBadSpecs) {
  BakeSpec spec;
  spec.model.kind = ModelKind::kSel;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.model.kind = ModelKind::kGgx;
  spec.mu.size = 0;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.mu.size = 1;  // edges need 2
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.mu.size = 8;
  spec.table = TableKind::kDfg;
  spec.complement = true;  // dfg adds a 1-E channel
  EXPECT_NO_THROW(ValidateBakeSpec(spec));
  spec.mu.min = 0.5;
  spec.mu.max = 0.25;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.mu.max = 1.5;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.mu.max = 1.0;
  spec.threads = kMaxThreads + 1;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  EXPECT_THROW(ParseTable("F"), std::invalid_argument);
  EXPECT_THROW(ParseIntegrator("euler"), std::invalid_argument);
}

}  // namespace
}  // namespace brdfbake
