// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The one description of a table (table_spec.h): ShapeOf's axes, image
// size and channels are those the bake produces, for every table kind and
// model family built; TableAxes points at the same axes; and the library's
// messages name parameters, which the command line spells as flags.

#include "brdfbake/table_spec.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/error.h"

namespace brdfbake {
namespace {

BakeSpec Small(TableKind table, ModelKind model) {
  BakeSpec s;
  s.table = table;
  s.model.kind = model;
  if (model == ModelKind::kEllipsoid) s.phi.max = 2 * 3.141592653589793;
  // A model of another build has no axes here (its family's row says them).
  if (ModelBuilt(model)) {
    for (Axis* a : TableAxes(&s)) a->size = 3;
  }
  s.tolerance = 1e-4;
  return s;
}

std::vector<BakeSpec> Specs() {
  std::vector<BakeSpec> specs;
  for (TableKind t : {TableKind::kE, TableKind::kEavg, TableKind::kDfg}) {
    for (ModelKind m : {ModelKind::kGgx, ModelKind::kBeckmann}) specs.push_back(Small(t, m));
  }
  BakeSpec dfg = Small(TableKind::kDfg, ModelKind::kGgx);
  dfg.complement = dfg.error_channel = true;
  specs.push_back(dfg);
  BakeSpec e1 = Small(TableKind::kE, ModelKind::kGgx);
  e1.complement = e1.error_channel = true;
  specs.push_back(e1);
  if (ModelBuilt(ModelKind::kStudentT)) {
    BakeSpec g = Small(TableKind::kE, ModelKind::kStudentT);
    g.gamma.size = 2;
    specs.push_back(g);
    g.table = TableKind::kEavg;
    specs.push_back(g);
  }
  specs.push_back(Small(TableKind::kE, ModelKind::kGgxAniso));
  specs.push_back(Small(TableKind::kEavg, ModelKind::kGgxAniso));
  if (ModelBuilt(ModelKind::kEllipsoid)) {
    specs.push_back(Small(TableKind::kE, ModelKind::kEllipsoid));
    specs.push_back(Small(TableKind::kEavg, ModelKind::kEllipsoid));
  }
  if (ModelBuilt(ModelKind::kSel)) {
    BakeSpec sel = Small(TableKind::kSelNorm, ModelKind::kSel);
    sel.error_channel = true;
    specs.push_back(sel);
  }
  BakeSpec f82 = Small(TableKind::kF82Bias, ModelKind::kGgx);
  f82.error_channel = true;
  specs.push_back(f82);
  if (ModelBuilt(ModelKind::kCharlie)) specs.push_back(Small(TableKind::kEavg, ModelKind::kCharlie));
  if (ModelBuilt(ModelKind::kGgxGlass)) {
    specs.push_back(Small(TableKind::kE, ModelKind::kGgxGlass));
    specs.push_back(Small(TableKind::kEavg, ModelKind::kGgxGlass));
    specs.push_back(Small(TableKind::kGenSchlickS, ModelKind::kGgx));
    specs.push_back(Small(TableKind::kGenSchlickIorS, ModelKind::kGgx));
  }
  return specs;
}

TEST(TableSpecTest, ShapeIsWhatTheBakeMakes) {
  for (const BakeSpec& s : Specs()) {
    const std::string what = std::string(TableName(s.table)) + " " + s.model.name();
    const TableShape shape = ShapeOf(s);
    const Table t = Bake(s);
    ASSERT_EQ(shape.axes.size(), t.axes.size()) << what;
    for (size_t i = 0; i < t.axes.size(); ++i) EXPECT_EQ(shape.axes[i].name, t.axes[i].name) << what;
    EXPECT_EQ(shape.width, t.width) << what;
    EXPECT_EQ(shape.height, t.height) << what;
    EXPECT_EQ(shape.Texels(), int64_t(t.channels[0].values.size())) << what;
    ASSERT_EQ(shape.channels.size(), t.channels.size()) << what;
    for (size_t c = 0; c < t.channels.size(); ++c) {
      EXPECT_EQ(shape.channels[c].name, t.channels[c].name) << what;
      EXPECT_EQ(shape.channels[c].meaning, t.channels[c].meaning) << what;
    }
    EXPECT_EQ(shape.value_channels + (s.error_channel ? 1 : 0), int(shape.channels.size())) << what;
    EXPECT_EQ(BakeOutputValues(s), shape.Texels() * int64_t(shape.channels.size())) << what;
    // TableAxes points at the same axes, in the same order.
    BakeSpec copy = s;
    const std::vector<Axis*> axes = TableAxes(&copy);
    ASSERT_EQ(axes.size(), shape.axes.size()) << what;
    for (size_t i = 0; i < axes.size(); ++i) EXPECT_EQ(axes[i]->name, shape.axes[i].name) << what;
    EXPECT_EQ(DefaultSizes(s).size(), axes.size()) << what;
    EXPECT_FALSE(SizeForm(s).empty()) << what;
  }
}

// The layouts docs/format.md states, written out here.
TEST(TableSpecTest, KnownShapes) {
  struct Case {
    BakeSpec spec;
    std::vector<std::string> axes;
    int64_t width, height;
  };
  std::vector<Case> cases = {
      {Small(TableKind::kE, ModelKind::kGgx), {"mu", "roughness"}, 3, 3},
      {Small(TableKind::kEavg, ModelKind::kGgx), {"roughness"}, 3, 1},
      {Small(TableKind::kE, ModelKind::kGgxAniso), {"mu", "phi_o", "roughness", "anisotropy"}, 3, 27},
      {Small(TableKind::kEavg, ModelKind::kGgxAniso), {"roughness", "anisotropy"}, 3, 3},
      {Small(TableKind::kE, ModelKind::kEllipsoid), {"mu", "phi_o"}, 3, 3},
      {Small(TableKind::kEavg, ModelKind::kEllipsoid), {}, 1, 1},
      {Small(TableKind::kSelNorm, ModelKind::kSel), {"alpha_x", "alpha_y"}, 3, 3},
      {Small(TableKind::kE, ModelKind::kGgxGlass), {"mu", "roughness", "ior"}, 3, 9},
      {Small(TableKind::kEavg, ModelKind::kGgxGlass), {"roughness", "ior"}, 3, 3},
      {Small(TableKind::kGenSchlickS, ModelKind::kGgx), {"mu", "roughness", "exponent"}, 3, 9},
      {Small(TableKind::kGenSchlickIorS, ModelKind::kGgx), {"mu", "roughness", "ior"}, 3, 9},
  };
  BakeSpec g = Small(TableKind::kEavg, ModelKind::kStudentT);
  g.gamma.size = 4;
  cases.push_back({g, {"roughness", "gamma"}, 3, 4});
  for (const Case& c : cases) {
    if (!ModelBuilt(c.spec.model.kind)) {
      // Its family's row gives its axes: without it, its shape is refused.
      EXPECT_THROW(ShapeOf(c.spec), std::invalid_argument) << c.spec.model.name();
      continue;
    }
    const TableShape shape = ShapeOf(c.spec);
    std::vector<std::string> names;
    for (const Axis& a : shape.axes) names.push_back(a.name);
    const std::string what = std::string(TableName(c.spec.table)) + " " + c.spec.model.name();
    EXPECT_EQ(names, c.axes) << what;
    EXPECT_EQ(shape.width, c.width) << what;
    EXPECT_EQ(shape.height, c.height) << what;
  }
}

TEST(TableSpecTest, ChannelNamesSortInTheirOrder) {
  BakeSpec s = Small(TableKind::kDfg, ModelKind::kGgx);
  s.complement = s.error_channel = true;
  const TableShape shape = ShapeOf(s);
  std::vector<std::string> names;
  for (const ChannelSpec& c : shape.channels) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"dfg.0_scale", "dfg.1_bias", "dfg.2_1-E", "dfg.3_error"}));
  EXPECT_STREQ(MeaningName(shape.channels[2].meaning), "1-E");
  EXPECT_TRUE(ParameterAxis(s.gamma));
  EXPECT_FALSE(ParameterAxis(s.mu));
}

// One row per kind (table_spec.cc): the help lists every kind in order,
// notes shared by neighbours once, and each name parses back to its kind.
TEST(TableSpecTest, KindsHelpListsEveryKind) {
  EXPECT_EQ(TableKindsHelp(),
            "E | E_avg | dfg | sel_norm (with {model} sel) | gen_schlick_s, gen_schlick_ior_s (the generalized "
            "Schlick factor s of GGX over mu x roughness x exponent or ior) | f82_bias (GGX's F82-tint term, wo.h "
            "(1 - wo.h)^6 weighting its energy, over mu x roughness)");
  EXPECT_EQ(SpellParameters("sel_norm (with {model} sel)", [](const std::string& p) { return "--" + p; }),
            "sel_norm (with --model sel)");
  for (TableKind k : {TableKind::kE, TableKind::kEavg, TableKind::kDfg, TableKind::kSelNorm, TableKind::kGenSchlickS,
                      TableKind::kGenSchlickIorS, TableKind::kF82Bias}) {
    EXPECT_EQ(ParseTable(TableName(k)), k);
    EXPECT_NE(TableKindsHelp().find(TableName(k)), std::string::npos);
  }
}

TEST(TableSpecTest, IntegratorsAllowed) {
  EXPECT_EQ(TableIntegrators(Small(TableKind::kDfg, ModelKind::kGgx)).size(), 4u);
  for (BakeSpec s : {Small(TableKind::kE, ModelKind::kGgxGlass), Small(TableKind::kE, ModelKind::kGgxAniso),
                     Small(TableKind::kGenSchlickS, ModelKind::kGgx), Small(TableKind::kSelNorm, ModelKind::kSel),
                     Small(TableKind::kF82Bias, ModelKind::kGgx)}) {
    // A model of another build has no row here (and the build's refusal
    // comes first).
    if (!ModelBuilt(s.model.kind)) continue;
    EXPECT_EQ(TableIntegrators(s), std::vector<IntegratorKind>{IntegratorKind::kQuadrature});
    s.integrator = IntegratorKind::kQmc;
    try {
      ValidateBakeSpec(s);
      ADD_FAILURE() << TableName(s.table) << " " << s.model.name() << " accepted qmc";
    } catch (const ParameterError& e) {
      EXPECT_NE(std::string(e.what()).find("integrator: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("quadrature only (got qmc)"), std::string::npos) << e.what();
    }
  }
}

// The library names the parameter; the command line spells it as a flag.
TEST(TableSpecTest, MessagesNameParameters) {
  BakeSpec s;
  s.table = TableKind::kDfg;
  s.model.kind = ModelKind::kGgxAniso;
  try {
    ValidateBakeSpec(s);
    FAIL() << "ggx-aniso dfg accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "table: ggx-aniso bakes E and E_avg (no dfg)");
    EXPECT_EQ(e.Render([](const std::string& n) { return "--" + n; }), "--table: ggx-aniso bakes E and E_avg (no dfg)");
  }
  try {
    ParseTable("albedo");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("table: unknown table 'albedo'", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean 'E'"), std::string::npos) << e.what();
  }
  // Only the parameters' marks are rendered; other braces stay.
  const ParameterError mixed("{mu_o} in {0, 1}: {not a parameter}");
  EXPECT_EQ(std::string(mixed.what()), "mu_o in {0, 1}: {not a parameter}");
  EXPECT_EQ(mixed.Render([](const std::string& n) { return "<" + n + ">"; }), "<mu_o> in {0, 1}: {not a parameter}");
  EXPECT_EQ(ErrorText(mixed), "{mu_o} in {0, 1}: {not a parameter}");
  EXPECT_EQ(ErrorText(std::runtime_error("{table}")), "{table}");
}

}  // namespace
}  // namespace brdfbake
