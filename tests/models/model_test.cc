// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The run-time model registry and `eval`: validation of parameters with
// one-line messages, identities between models through the type-erased
// interface, and the CSV contract.

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "brdfbake/bake.h"
#include "brdfbake/eval.h"
#include "brdfbake/model.h"

namespace brdfbake {
namespace {

std::string ErrorOf(const ModelParams& p) {
  try {
    ValidateModelParams(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ModelTest, RejectsBadParametersWithOneLineMessages) {
  ModelParams p;
  EXPECT_EQ(ErrorOf(p), "");
  p.alpha_x = -0.1;
  EXPECT_NE(ErrorOf(p).find("alpha_x"), std::string::npos);
  p.alpha_x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(ErrorOf(p).find("alpha_x"), std::string::npos);
  p.alpha_x = 0.3;
  p.alpha_y = 0;
  EXPECT_NE(ErrorOf(p).find("alpha_y"), std::string::npos);
  p.alpha_y = 0.3;
  try {
    ParseModelKind("phong");
    ADD_FAILURE() << "no error for an unknown model";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown model 'phong'"), std::string::npos);
  }
  // Every registered kind's name parses back to it (BRDFBAKE_MODEL_KINDS).
  int kinds = 0;
#define BRDFBAKE_TEST_KIND(family, kind, name)                                  \
  EXPECT_EQ(ParseModelKind(name), ModelKind::k##kind) << name;                  \
  EXPECT_STREQ(ModelName(ModelKind::k##kind), name);                            \
  ++kinds;
  BRDFBAKE_MODEL_KINDS(BRDFBAKE_TEST_KIND)
#undef BRDFBAKE_TEST_KIND
  EXPECT_GE(kinds, 9);
  p.kind = ModelKind::kStudentT;
  p.gamma = 1.5;
  EXPECT_NE(ErrorOf(p).find("gamma"), std::string::npos);
  p.gamma = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(ErrorOf(p).find("gamma"), std::string::npos);
  p.gamma = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ErrorOf(p), "");
  p.kind = ModelKind::kEllipsoid;
  p.theta_y = 2.0;
  EXPECT_NE(ErrorOf(p).find("theta_y"), std::string::npos);
  for (const ModelParams& bad : {p}) {
    const std::string msg = ErrorOf(bad);
    EXPECT_EQ(msg.find('\n'), std::string::npos);
  }
}

TEST(ModelTest, StudentTGammaTwoIsGgxAndInfinityIsBeckmann) {
  ModelParams g;
  g.kind = ModelKind::kGgx;
  g.alpha_x = 0.3;
  g.alpha_y = 0.7;
  ModelParams s = g;
  s.kind = ModelKind::kStudentT;
  s.gamma = 2;
  ModelParams b = g;
  b.kind = ModelKind::kBeckmann;
  ModelParams si = s;
  si.gamma = std::numeric_limits<double>::infinity();
  const auto mg = MakeModel(g), ms = MakeModel(s), mb = MakeModel(b), msi = MakeModel(si);
  for (double mu = 0.05; mu <= 1; mu += 0.1) {
    const Vec3<double> w = FromMuPhi(mu, 0.8);
    EXPECT_NEAR(ms->D(w), mg->D(w), 1e-12 * mg->D(w));
    EXPECT_NEAR(ms->Lambda(w), mg->Lambda(w), 1e-10 * (1 + mg->Lambda(w)));
    EXPECT_NEAR(msi->D(w), mb->D(w), 1e-12 * mb->D(w));
    EXPECT_NEAR(msi->Lambda(w), mb->Lambda(w), 1e-12 * (1 + mb->Lambda(w)));
  }
}

TEST(ModelTest, SelHasOnlyK) {
  ModelParams p;
  p.kind = ModelKind::kSel;
  const auto m = MakeModel(p);
  EXPECT_FALSE(m->IsMicrofacet());
  EXPECT_NEAR(m->K(Vec3<double>(0, 0, 1)), 1.0, 1e-12);
  EXPECT_THROW(m->D(Vec3<double>(0, 0, 1)), std::invalid_argument);
  ModelParams q;
  EXPECT_THROW(MakeModel(q)->K(Vec3<double>(0, 0, 1)), std::invalid_argument);
}

TEST(EvalTest, CsvHasHeaderAndRows) {
  EvalRequest req;
  req.quantities = {"D", "Lambda", "G1", "G2", "brdf", "pdf"};
  req.count = 5;
  req.mu_o = 0.5;
  std::ostringstream out;
  EvalCsv(req, out);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "mu,theta_deg,D,Lambda,G1,G2,brdf,pdf");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    int commas = 0;
    for (char c : line) commas += c == ',';
    EXPECT_EQ(commas, 7) << line;
    EXPECT_EQ(line.find("nan"), std::string::npos) << line;
  }
  EXPECT_EQ(rows, 5);
}

TEST(EvalTest, ColouredFresnelGivesThreeChannels) {
  EvalRequest req;
  req.quantities = {"brdf"};
  req.fresnel = Fresnel::Schlick({0.9, 0.6, 0.3});
  req.count = 3;
  req.from = 0.2;
  req.mu_o = 0.9;
  std::ostringstream out;
  EvalCsv(req, out);
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "mu,theta_deg,brdf_r,brdf_g,brdf_b");
}

TEST(EvalTest, ThetaSweepMatchesMu) {
  EvalRequest req;
  req.sweep = "theta";
  req.from = 0;
  req.to = 60;
  req.count = 2;
  req.quantities = {"G1"};
  std::ostringstream out;
  EvalCsv(req, out);
  EXPECT_NE(out.str().find("\n0.50000000000000011,60,"), std::string::npos) << out.str();
}

// eval's gen_schlick_s and gen_schlick_ior_s are the bake's tables at one
// exponent or ior: the value of every texel of a one-slice table, and its
// error; f82_bias is the table's texel; a bad exponent or ior is refused
// naming it.
TEST(EvalTest, GenSchlickIsTheBakedSlice) {
  for (const char* q : {"gen_schlick_s", "gen_schlick_ior_s"}) {
    const bool exponent = std::string(q) == "gen_schlick_s";
    BakeSpec spec;
    spec.table = exponent ? TableKind::kGenSchlickS : TableKind::kGenSchlickIorS;
    spec.mu.size = 4;
    spec.roughness.size = 3;
    Axis& slice = exponent ? spec.exponent : spec.ior;
    slice.size = 1;
    slice.placement = Placement::kCenters;
    slice.min = slice.max = exponent ? 3.5 : 1.8;
    spec.error_channel = true;
    const Table t = Bake(spec);
    ASSERT_EQ(t.width, 4);
    ASSERT_EQ(t.height, 3);
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 4; ++i) {
        EvalRequest req;
        req.quantities = {q};
        req.sweep = "none";
        req.mu_o = t.axes[0].Value(i);
        const double r = t.axes[1].Value(j);
        req.model.alpha_x = req.model.alpha_y = r * r;
        req.exponent = 3.5;
        req.model.ior = 1.8;
        std::ostringstream out;
        EvalCsv(req, out);
        const std::string csv = out.str();
        EXPECT_EQ(csv.substr(0, csv.find('\n')), std::string("mu,roughness,") + q + "," + q + "_error");
        std::istringstream row(csv.substr(csv.find('\n') + 1));
        double mu = 0, rough = 0, value = 0, error = 0;
        char c;
        row >> mu >> c >> rough >> c >> value >> c >> error;
        const size_t at = size_t(j) * 4 + size_t(i);
        // The same rule at the same point: equal but for the float
        // rounding of the stored value (eval takes alpha back as r^2 from
        // sqrt(alpha), a last-bit change).
        const double stored = t.channels[0].values[at];
        EXPECT_NEAR(value, stored, 1e-7 * std::abs(stored) + 1e-30) << q << " at (" << i << ", " << j << ")";
        EXPECT_GE(error, 0);
        EXPECT_LE(error, spec.tolerance) << q;
      }
    }
  }
  // f82_bias: the table's texel, either masking.
  for (Masking masking : {Masking::kSeparable, Masking::kHeightCorrelated}) {
    BakeSpec f82;
    f82.table = TableKind::kF82Bias;
    f82.masking = masking;
    const TexelEstimate want = IntegrateTexel(f82, 0.5, 0.25);
    EvalRequest req;
    req.quantities = {"f82_bias"};
    req.sweep = "none";
    req.masking = masking;
    req.mu_o = 0.25;
    req.model.alpha_x = req.model.alpha_y = 0.25;  // roughness 0.5
    std::ostringstream out;
    EvalCsv(req, out);
    EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "mu,roughness,f82_bias,f82_bias_error");
    std::istringstream row(out.str().substr(out.str().find('\n') + 1));
    double mu = 0, rough = 0, value = 0, error = 0;
    char c;
    row >> mu >> c >> rough >> c >> value >> c >> error;
    EXPECT_EQ(value, want.e) << MaskingName(masking);
    EXPECT_EQ(error, want.err_e);
  }
  EvalRequest bad;
  bad.quantities = {"gen_schlick_s"};
  bad.exponent = -1;
  try {
    ValidateEvalRequest(bad);
    ADD_FAILURE() << "exponent -1 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exponent must be >= 0 or inf"), std::string::npos) << e.what();
  }
  bad.quantities = {"gen_schlick_ior_s"};
  bad.model.ior = 0.5;
  EXPECT_THROW(ValidateEvalRequest(bad), std::invalid_argument);
  bad.model.ior = 1.5;
  bad.model.kind = ModelKind::kBeckmann;
  EXPECT_THROW(ValidateEvalRequest(bad), std::invalid_argument);
}

TEST(EvalTest, RejectsBadRequests) {
  EvalRequest req;
  req.quantities = {"Q"};
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
  req.quantities = {"K"};
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
  req.quantities = {"D"};
  req.count = 0;
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
  req.count = 3;
  req.from = 2;
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
  req.from = 0;
  req.mu_o = -0.1;
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
  req.mu_o = 1;
  req.sweep = "phi";
  EXPECT_THROW(ValidateEvalRequest(req), std::invalid_argument);
}

}  // namespace
}  // namespace brdfbake
