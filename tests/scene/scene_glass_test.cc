// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Transmissive materials in scenes (glTF KHR_materials_transmission with
// KHR_materials_ior and KHR_materials_volume; TOML transmission, ior,
// volume): they get the ggx-glass E and E_avg over their roughness and
// ior range and no wider, the inverse tables (light leaving the medium)
// only for a volume, with a stated lookup error that bounds random
// lookups; an ior on an opaque material is served by dfg, and the plan
// says so; malformed fields get one-line errors naming the field.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/presets.h"
#include "brdfbake/scene.h"
#include "util/file_util.h"
#include "util/scene_util.h"
#include "util/lookup_util.h"

namespace brdfbake {
namespace {

using test::FindPlanned;
using test::Joined;
using test::WriteText;

std::string Scratch(const std::string& name) { return test::Scratch("scene_glass_" + name); }

// A glTF file: thin-walled glass (transmission, ior 1.33), a glass volume
// (ior 1.7), an opaque material with an ior, and one whose transmission
// factor is 0 (opaque).
const char* const kGlassGltf =
    "{\"asset\": {\"version\": \"2.0\"}, \"textures\": [{\"source\": 0}], \"images\": [{\"uri\": \"t.png\"}],\n"
    " \"materials\": [\n"
    "  {\"name\": \"pane\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.2}, \"extensions\": "
    "{\"KHR_materials_transmission\": {\"transmissionFactor\": 1.0}, \"KHR_materials_ior\": {\"ior\": 1.33}}},\n"
    "  {\"name\": \"bottle\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}, \"extensions\": "
    "{\"KHR_materials_ior\": {\"ior\": 1.7}, \"KHR_materials_transmission\": {\"transmissionFactor\": 0.8, "
    "\"transmissionTexture\": {\"index\": 0}}, \"KHR_materials_volume\": {\"thicknessFactor\": 0.01, "
    "\"attenuationColor\": [1, 0.9, 0.8], \"attenuationDistance\": 0.5}}},\n"
    "  {\"name\": \"gem\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.3}, \"extensions\": "
    "{\"KHR_materials_ior\": {\"ior\": 2.4}}},\n"
    "  {\"name\": \"frosted\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.6}, \"extensions\": "
    "{\"KHR_materials_transmission\": {}}}\n"
    " ]}\n";

TEST(SceneGlassTest, GltfTransmissionGetsTheGlassTablesOverItsIorRange) {
  const std::string dir = Scratch("gltf");
  WriteText(dir + "/g.gltf", kGlassGltf);
  Scene s = LoadScene(dir + "/g.gltf");
  ASSERT_EQ(s.materials.size(), 4u);
  if (!ModelBuilt(ModelKind::kGgxGlass)) {
    EXPECT_FALSE(s.materials[0].transmission);
    const ScenePlan plan = PlanScene(s);
    EXPECT_NE(Joined(plan.notes).find("BRDFBAKE_MODELS"), std::string::npos) << Joined(plan.notes);
    return;
  }
  EXPECT_TRUE(s.materials[0].transmission);
  EXPECT_FALSE(s.materials[0].volume);
  EXPECT_DOUBLE_EQ(s.materials[0].ior_min, 1.33);
  EXPECT_TRUE(s.materials[1].transmission);
  EXPECT_TRUE(s.materials[1].volume);
  EXPECT_DOUBLE_EQ(s.materials[1].ior_max, 1.7);
  EXPECT_FALSE(s.materials[2].transmission);
  EXPECT_DOUBLE_EQ(s.materials[2].ior_min, 2.4);
  EXPECT_FALSE(s.materials[3].transmission);  // transmissionFactor 0
  // A loose target: the smallest rungs meet it (the planner's ladder and
  // bound are checked below and in scene_test.cc).
  s.engine.max_lut_size = 8;
  s.engine.error_target = 0.08;
  s.engine.pixel = PixelType::kFloat;
  const ScenePlan plan = PlanScene(s);
  const std::string decisions = Joined(plan.decisions);
  // The glass tables over ior [1.33, 1.7] and roughness [0.2, 0.5] only.
  for (const char* f : {"E_ggx-glass.exr", "E_avg_ggx-glass.exr", "E_ggx-glass_inverse.exr",
                        "E_avg_ggx-glass_inverse.exr"}) {
    const PlannedTable* p = FindPlanned(plan, f);
    ASSERT_NE(p, nullptr) << f << "\n" << PlanText(s, plan);
    EXPECT_EQ(p->spec.model.kind, ModelKind::kGgxGlass);
    EXPECT_DOUBLE_EQ(p->spec.ior.min, 1.33) << f;
    EXPECT_DOUBLE_EQ(p->spec.ior.max, 1.7) << f;
    EXPECT_DOUBLE_EQ(p->spec.roughness.min, 0.2) << f;
    EXPECT_DOUBLE_EQ(p->spec.roughness.max, 0.5) << f;
    const bool inverse = std::string(f).find("inverse") != std::string::npos;
    EXPECT_EQ(p->spec.inverse, inverse) << f;
    // Only the volume leaves the medium.
    EXPECT_EQ(p->materials.size(), inverse ? 1u : 2u) << f;
  }
  EXPECT_NE(decisions.find("transmissive materials 'pane', 'bottle'"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("inverse tables"), std::string::npos) << decisions;
  // The opaque ior: F0 = (1.4 / 3.4)^2, served by dfg.
  EXPECT_NE(decisions.find("material 'gem' (ior 2.4, opaque)"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("dfg"), std::string::npos) << decisions;
  EXPECT_EQ(Joined(plan.notes).find("not bake yet"), std::string::npos) << Joined(plan.notes);
  for (const std::string& d : plan.decisions) EXPECT_EQ(d.find('\n'), std::string::npos) << d;

  // A thin-walled scene alone: no inverse tables.
  Scene thin = s;
  thin.materials.erase(thin.materials.begin() + 1);
  const ScenePlan thin_plan = PlanScene(thin);
  EXPECT_NE(FindPlanned(thin_plan, "E_ggx-glass.exr"), nullptr);
  EXPECT_EQ(FindPlanned(thin_plan, "E_ggx-glass_inverse.exr"), nullptr);
  const PlannedTable* one = FindPlanned(thin_plan, "E_ggx-glass.exr");
  ASSERT_NE(one, nullptr);
  EXPECT_EQ(one->spec.ior.size, 1);  // one ior: one slice
  EXPECT_DOUBLE_EQ(one->table.axes.back().Value(0), 1.33);

  // The bake writes them, with the manifest.
  std::filesystem::create_directories(dir + "/out");
  const std::vector<std::string> files = WriteScenePlan(s, plan, dir + "/out");
  for (const char* f : {"E_ggx-glass.exr", "E_avg_ggx-glass_inverse.exr", "manifest.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/" + f)) << f;
  }
  // Every written file is among those checked before the plan.
  const std::vector<std::string> possible = SceneOutputFiles(s, dir + "/out");
  for (const std::string& f : files) {
    EXPECT_NE(std::find(possible.begin(), possible.end(), f), possible.end()) << f;
  }
}

// Under a preset whose engine ships glass tables (cycles), the transmissive
// materials get those, at the engine's axes and size (16^3, ior to inf),
// written into the engine's header with its names; the plan measures their
// lookup error over the materials' range.
TEST(SceneGlassTest, EngineGlassTablesServeUnderCycles) {
  if (!ModelBuilt(ModelKind::kGgxGlass)) GTEST_SKIP() << "glass is not built (BRDFBAKE_MODELS)";
  const std::string dir = Scratch("cycles");
  WriteText(dir + "/g.gltf", kGlassGltf);
  Scene s = LoadScene(dir + "/g.gltf");
  ApplySceneOverrides(&s, {{"--preset", "cycles"}});
  s.engine.error_target = 0.08;
  const ScenePlan plan = PlanScene(s);
  const Preset& cycles = FindPreset("cycles");
  int glass = 0;
  for (const PlannedTable& p : plan.tables) {
    if (p.spec.model.kind != ModelKind::kGgxGlass) continue;
    ++glass;
    EXPECT_EQ(p.file, "ggx_tables.h");
    EXPECT_TRUE(p.size_fixed);
    EXPECT_EQ(p.spec.ior.size, 16);
    EXPECT_EQ(p.spec.ior.max, kInfinity);
    EXPECT_EQ(p.spec.roughness.size, 16);
    bool engine = false;
    for (const PresetTable& pt : cycles.tables) {
      engine |= pt.spec.model.kind == ModelKind::kGgxGlass && pt.spec.table == p.spec.table &&
                pt.spec.inverse == p.spec.inverse;
    }
    EXPECT_TRUE(engine) << TableName(p.spec.table) << (p.spec.inverse ? " inverse" : "");
  }
  EXPECT_EQ(glass, 4) << PlanText(s, plan);
  const std::string decisions = Joined(plan.decisions);
  EXPECT_NE(decisions.find("engine preset 'cycles' ships its own glass tables"), std::string::npos) << decisions;
  std::filesystem::create_directories(dir + "/out");
  WriteScenePlan(s, plan, dir + "/out");
  const std::string header = test::Slurp(dir + "/out/ggx_tables.h");
  for (const char* want : {"table_ggx_E[", "table_ggx_glass_E[4096]", "table_ggx_glass_Eavg[256]",
                           "table_ggx_glass_inv_E[4096]", "table_ggx_glass_inv_Eavg[256]"}) {
    EXPECT_NE(header.find(want), std::string::npos) << want;
  }
}

// Under EEVEE, whose one baked glass table is btdf_ggx (the refraction
// weighted by Schlick's complement, light entering the medium), the
// transmissive materials get that table in eevee_lut.cc and nothing the
// renderer does not read: no E_avg, no inverse table, no GGX table (its
// brdf_ggx is Blender's own).
TEST(SceneGlassTest, EngineGlassUnderEeveeIsItsBtdfTableAlone) {
  if (!ModelBuilt(ModelKind::kGgxGlass)) GTEST_SKIP() << "glass is not built (BRDFBAKE_MODELS)";
  const std::string dir = Scratch("eevee");
  WriteText(dir + "/g.gltf", kGlassGltf);
  Scene s = LoadScene(dir + "/g.gltf");
  ApplySceneOverrides(&s, {{"--preset", "eevee"}});
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 1u) << PlanText(s, plan);
  const PlannedTable& p = plan.tables[0];
  EXPECT_EQ(p.file, "eevee_lut.cc");
  EXPECT_EQ(p.spec.part, DielectricPart::kTransmissionSchlick);
  EXPECT_FALSE(p.spec.inverse);
  EXPECT_TRUE(p.size_fixed);
  EXPECT_EQ(p.spec.ior.max, kInfinity);
  EXPECT_EQ(p.materials, (std::vector<std::string>{"pane", "bottle"}));
  // Its lookup error over the materials' range is measured and stated.
  EXPECT_GT(p.interpolation_error, 0) << PlanText(s, plan);
  EXPECT_GE(p.total_error, p.interpolation_error);
  const std::string notes = Joined(plan.notes), decisions = Joined(plan.decisions);
  EXPECT_NE(decisions.find("btdf_ggx"), std::string::npos) << decisions;
  EXPECT_NE(notes.find("E_avg of the glass entering the medium: engine preset 'eevee' samples no such table"),
            std::string::npos) << notes;
  EXPECT_NE(notes.find("E of the glass leaving the medium (the volumes): engine preset 'eevee'"), std::string::npos)
      << notes;
  EXPECT_NE(PlanText(s, plan).find("part transmission-schlick"), std::string::npos);
  std::filesystem::create_directories(dir + "/out");
  const std::vector<std::string> files = WriteScenePlan(s, plan, dir + "/out");
  EXPECT_EQ(files.size(), 2u);  // eevee_lut.cc and the manifest
  const std::string source = test::Slurp(dir + "/out/eevee_lut.cc");
  EXPECT_NE(source.find("btdf_ggx[16][64][64][1]"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/E_avg_ggx-glass.exr"));

  // A scene without transmissive materials has nothing for EEVEE's table.
  Scene opaque = LoadScene(dir + "/g.gltf");
  opaque.materials.erase(opaque.materials.begin(), opaque.materials.begin() + 2);
  opaque.materials.pop_back();
  try {
    ApplySceneOverrides(&opaque, {{"--preset", "eevee"}});
    FAIL() << "an opaque scene was accepted under eevee";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("samples ggx-glass E, none of the scene's tables"), std::string::npos)
        << e.what();
  }
}

// Under openpbr the entering table's two-sided ior axis holds the
// volumes' side: no table of their own.
TEST(SceneGlassTest, EngineGlassUnderOpenPbrHoldsTheVolumesOnItsTwoSidedAxis) {
  if (!ModelBuilt(ModelKind::kGgxGlass)) GTEST_SKIP() << "glass is not built (BRDFBAKE_MODELS)";
  const std::string dir = Scratch("openpbr");
  WriteText(dir + "/g.gltf", kGlassGltf);
  Scene o = LoadScene(dir + "/g.gltf");
  ApplySceneOverrides(&o, {{"--preset", "openpbr"}});
  const ScenePlan op = PlanScene(o);
  for (const PlannedTable& t : op.tables) {
    EXPECT_FALSE(t.spec.Glass() && t.spec.inverse) << t.file;
    EXPECT_EQ(t.file, "openpbr_energy_arrays.h");
  }
  EXPECT_NE(Joined(op.notes).find("whose ior axis covers both sides"), std::string::npos) << Joined(op.notes);
}

// The stated error of a glass E bounds a GPU's lookup at random (mu,
// roughness, ior): bilinear in each ior slice, the two slices blended.
TEST(SceneGlassTest, PlannedGlassErrorBoundsRandomLookups) {
  if (!ModelBuilt(ModelKind::kGgxGlass)) GTEST_SKIP() << "glass is not in this build";
  const std::string dir = Scratch("bound");
  WriteText(dir + "/s.toml",
            "[engine]\nmax_lut_size = 8\npixel = \"float\"\nerror_target = 3e-2\ntables = [\"E\"]\n"
            "[[material]]\nname = \"glass\"\nmodel = \"ggx\"\nroughness = [0.3, 0.6]\n"
            "transmission = true\nvolume = true\nior = [1.3, 1.8]\n");
  const Scene s = LoadScene(dir + "/s.toml");
  const ScenePlan plan = PlanScene(s);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int checked = 0;
  for (const PlannedTable& p : plan.tables) {
    if (p.spec.model.kind != ModelKind::kGgxGlass) continue;
    ++checked;
    const Table& t = p.table;
    const Axis &am = t.spec.mu, &ar = t.spec.roughness, &ai = t.spec.ior;
    ASSERT_EQ(t.height, ar.size * ai.size);
    double worst = 0;
    for (int i = 0; i < 150; ++i) {
      const double mu = i % 2 ? uni(rng) : std::exp(std::log(1e-3) * uni(rng));
      const double r = ar.min + (ar.max - ar.min) * uni(rng);
      const double ior = ai.min + (ai.max - ai.min) * uni(rng);
      // The slice coordinate, clamped to the edge slices.
      const double w = std::clamp(test::TextureCoordinate(ai, ior) * ai.size - 0.5, 0.0, double(ai.size - 1));
      const int k0 = std::min(int(w), ai.size - 1), k1 = std::min(k0 + 1, ai.size - 1);
      auto slice = [&](int k) {
        auto at = [&](int x, int y) { return double(t.channels[0].stored[(size_t(k) * ar.size + y) * t.width + x]); };
        return test::TextureBilinear(at, am.size, ar.size, test::TextureCoordinate(am, mu),
                                     test::TextureCoordinate(ar, r));
      };
      const double lookup = (1 - (w - k0)) * slice(k0) + (w - k0) * slice(k1);
      BakeSpec es = t.spec;
      es.model.ior = t.spec.inverse ? 1 / ior : ior;
      const double exact = std::clamp(IntegrateTexel(es, r, mu).e, 0.0, 1.0);
      worst = std::max(worst, std::abs(lookup - exact));
    }
    std::printf("%s %dx%dx%d: planned lookup error %.3g, random lookups %.3g\n", p.file.c_str(), am.size, ar.size,
                ai.size, p.total_error, worst);
    EXPECT_LE(worst, p.total_error) << p.file;
  }
  EXPECT_EQ(checked, 2);
}

TEST(SceneGlassTest, MalformedGlassFieldsGetOneLine) {
  const std::string dir = Scratch("bad");
  auto gltf = [&](const std::string& ext) {
    WriteText(dir + "/b.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"m\", "
                               "\"extensions\": {" + ext + "}}]}");
    return dir + "/b.gltf";
  };
  auto expect_error = [](const std::string& path, const std::string& what) {
    try {
      LoadScene(path);
      ADD_FAILURE() << "no error for " << what;
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_NE(m.find("material 'm'"), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  };
  expect_error(gltf("\"KHR_materials_ior\": {\"ior\": 0.5}"), "KHR_materials_ior.ior");
  expect_error(gltf("\"KHR_materials_ior\": {\"ior\": \"glass\"}"), "KHR_materials_ior.ior");
  expect_error(gltf("\"KHR_materials_transmission\": {\"transmissionFactor\": 1.5}"),
               "KHR_materials_transmission.transmissionFactor");
  expect_error(gltf("\"KHR_materials_transmission\": {\"transmissionFactor\": true}"),
               "KHR_materials_transmission.transmissionFactor");
  expect_error(gltf("\"KHR_materials_transmission\": {\"transmissionTexture\": 3}"),
               "KHR_materials_transmission.transmissionTexture");
  expect_error(gltf("\"KHR_materials_volume\": {\"thicknessFactor\": -1}"), "KHR_materials_volume.thicknessFactor");
  expect_error(gltf("\"KHR_materials_volume\": {\"attenuationColor\": [1, 2]}"),
               "KHR_materials_volume.attenuationColor");
  expect_error(gltf("\"KHR_materials_volume\": {\"attenuationDistance\": 0}"),
               "KHR_materials_volume.attenuationDistance");
  auto toml = [&](const std::string& fields) {
    WriteText(dir + "/b.toml", "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.3\n" + fields);
    return dir + "/b.toml";
  };
  expect_error(toml("ior = 0.9\n"), "'ior'");
  expect_error(toml("ior = [1.8, 1.2]\n"), "'ior'");
  expect_error(toml("transmission = 1\n"), "'transmission'");
  expect_error(toml("volume = true\n"), "'volume'");
}

}  // namespace
}  // namespace brdfbake
