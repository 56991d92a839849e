// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The model families of this build (CMake BRDFBAKE_MODELS): exactly the
// configured ones are registered and work end to end (model, grid, bake);
// the others are rejected everywhere with a one-line error that says they
// are not in this build.

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/bake.h"
#include "brdfbake/grid.h"
#include "brdfbake/model.h"
#include "brdfbake/scene.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

std::vector<std::string> Configured() {
  std::vector<std::string> out;
  std::stringstream ss(BRDFBAKE_MODELS_LIST);
  for (std::string m; std::getline(ss, m, ',');) out.push_back(m);
  return out;
}

bool IsConfigured(const std::string& m) {
  for (const std::string& c : Configured()) {
    if (c == m) return true;
  }
  return false;
}

TEST(BuildTest, OnlyTheConfiguredFamiliesAreRegistered) {
  std::vector<std::string> registered;
  for (const ModelInfo& m : Models()) registered.push_back(ModelName(m.kind));
  std::vector<std::string> expected;
  for (const char* m : {"ggx", "beckmann", "std", "ellipsoid", "sel", "charlie", "disney"}) {
    if (IsConfigured(m)) expected.push_back(std::string(m) == "disney" ? "disney-diffuse" : m);
  }
  EXPECT_EQ(registered, expected);
}

TEST(BuildTest, BuiltFamiliesWorkAndOthersAreRejected) {
  const std::string dir = test::Scratch("build_test");
  for (const char* name : {"ggx", "beckmann", "std", "ellipsoid", "sel", "charlie", "disney-diffuse"}) {
    ModelParams p;
    p.kind = ParseModelKind(name);
    p.gamma = 3;
    const bool lobe = p.kind == ModelKind::kCharlie || p.kind == ModelKind::kDisneyDiffuse;
    const bool built = IsConfigured(std::string(name) == "disney-diffuse" ? "disney" : name);
    EXPECT_EQ(ModelBuilt(p.kind), built) << name;
    if (!built) {
      try {
        ValidateModelParams(p);
        ADD_FAILURE() << name << " accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("not in this build"), std::string::npos) << e.what();
      }
      EXPECT_THROW(MakeModel(p), std::invalid_argument);
      BakeSpec spec;
      spec.model = p;
      EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument) << name;
      const std::string scene = dir + "/" + name + ".toml";
      test::WriteText(scene, std::string("[[material]]\nname = \"m\"\nmodel = \"") + name +
                                 "\"\nroughness = 0.5\n" + (std::string(name) == "std" ? "gamma = 3\n" : ""));
      if (std::string(name) != "ellipsoid" && std::string(name) != "sel") {
        EXPECT_THROW(LoadScene(scene), std::invalid_argument) << name;
      }
      continue;
    }
    const auto model = MakeModel(p);
    EXPECT_EQ(model->params().kind, p.kind);
    if (std::string(name) == "sel") continue;
    if (lobe) {
      BakeSpec spec;
      spec.model = p;
      spec.mu.size = spec.roughness.size = 3;
      const Table t = Bake(spec);
      for (double v : t.channels[0].values) EXPECT_TRUE(std::isfinite(v) && v >= 0) << name;
      continue;
    }
    GridRequest g;
    g.model = p;
    g.width = g.height = 8;
    for (float v : EvalGrid(g).values) EXPECT_TRUE(std::isfinite(v)) << name;
    if (std::string(name) == "ellipsoid") continue;
    BakeSpec spec;
    spec.model = p;
    spec.mu.size = spec.roughness.size = 3;
    const Table t = Bake(spec);
    for (double v : t.channels[0].values) EXPECT_TRUE(v >= 0 && v <= 1) << name;
  }
}

}  // namespace
}  // namespace brdfbake
