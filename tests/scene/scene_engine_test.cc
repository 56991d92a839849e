// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scenes beyond isotropic materials and brdfbake's own files: anisotropic
// GGX groups get the smaller of the 4D ggx-aniso tables and the isotropic
// tables at the collapsed roughness that meets the target, with a stated
// error that bounds random lookups of the 4D tables too; clearcoat layers
// reuse the isotropic tables; a scene bakes in an engine preset's layouts
// and containers (the engine's own file where the engine fixes it, byte for
// byte); command-line overrides are checked and recorded; a missed target
// says what would meet it.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/presets.h"
#include "brdfbake/scene.h"
#include "util/file_util.h"
#include "util/scene_util.h"
#include "util/lookup_util.h"

namespace brdfbake {
namespace {

using test::FindPlanned;
using test::Joined;
using test::Slurp;
using test::WriteText;

const std::string kExamples = std::string(BRDFBAKE_TEST_DATA) + "/../../examples";

Scene Toml(const std::string& dir, const std::string& text) {
  WriteText(dir + "/s.toml", text);
  return LoadScene(dir + "/s.toml");
}

// A GPU's lookup of a table over any number of axes: linear along each,
// clamp-to-edge, at the physical values `at` (Table::axes order).
double Lookup(const Table& t, const std::vector<double>& at) {
  const size_t n = t.axes.size();
  std::vector<int> i0(n), i1(n);
  std::vector<double> w(n);
  std::vector<int64_t> stride(n);
  int64_t st = 1;
  for (size_t a = 0; a < n; ++a) {
    const Axis& ax = t.axes[a];
    const double x = std::clamp(test::TextureCoordinate(ax, at[a]) * ax.size - 0.5, 0.0, double(ax.size - 1));
    i0[a] = std::min(int(std::floor(x)), std::max(0, ax.size - 2));
    i1[a] = std::min(i0[a] + 1, ax.size - 1);
    w[a] = x - i0[a];
    stride[a] = st;
    st *= ax.size;
  }
  double v = 0;
  for (int corner = 0; corner < (1 << n); ++corner) {
    double weight = 1;
    int64_t index = 0;
    for (size_t a = 0; a < n; ++a) {
      const bool hi = (corner >> a) & 1;
      weight *= hi ? w[a] : 1 - w[a];
      index += (hi ? i1[a] : i0[a]) * stride[a];
    }
    v += weight * t.channels[0].stored[size_t(index)];
  }
  return v;
}

// A strongly anisotropic material alone: the collapse is far off, so the
// 4D tables are planned for E and E_avg, and the isotropic dfg its base
// layer needs at the collapsed roughness; the bake writes them all.
TEST(SceneAnisoTest, AnisotropicOnlySceneBakesWhatItNeeds) {
  const std::string dir = test::Scratch("scene_aniso_only");
  const Scene s = Toml(dir,
                       "[engine]\nmax_lut_size = 16\nerror_target = 2e-2\npixel = \"float\"\n"
                       "[[material]]\nname = \"a\"\nmodel = \"ggx-aniso\"\nroughness = 0.5\nanisotropy = 0.8\n");
  const ScenePlan plan = PlanScene(s);
  const PlannedTable* dfg = FindPlanned(plan, "dfg_ggx.exr");
  const PlannedTable* e = FindPlanned(plan, "E_ggx-aniso.exr");
  const PlannedTable* avg = FindPlanned(plan, "E_avg_ggx-aniso.exr");
  ASSERT_NE(dfg, nullptr) << PlanText(s, plan);
  ASSERT_NE(e, nullptr) << PlanText(s, plan);
  ASSERT_NE(avg, nullptr) << PlanText(s, plan);
  EXPECT_EQ(plan.tables.size(), 3u);
  EXPECT_EQ(dfg->materials, (std::vector<std::string>{"a (collapsed)"}));
  EXPECT_GT(dfg->collapse_error, 2e-2);  // the base layer's dfg is off by the collapse, and says so
  EXPECT_TRUE(e->spec.Anisotropic());
  EXPECT_EQ(e->spec.roughness.size, 1);
  EXPECT_EQ(e->spec.anisotropy.size, 1);
  EXPECT_EQ(e->spec.anisotropy.min, 0.8);
  EXPECT_TRUE(e->meets_target) << e->total_error;
  EXPECT_EQ(e->materials, (std::vector<std::string>{"a"}));
  ASSERT_EQ(plan.decisions.size(), 1u);
  EXPECT_NE(plan.decisions[0].find("the 4D tables"), std::string::npos) << plan.decisions[0];
  EXPECT_NE(plan.decisions[0].find("collapsed roughness"), std::string::npos) << plan.decisions[0];
  std::filesystem::create_directories(dir + "/out");
  const std::vector<std::string> files = WriteScenePlan(s, plan, dir + "/out");
  const std::vector<std::string> possible = SceneOutputFiles(s, dir + "/out");
  for (const std::string& f : files) {
    EXPECT_TRUE(std::filesystem::exists(f)) << f;
    EXPECT_NE(std::find(possible.begin(), possible.end(), f), possible.end()) << f << " was not checked before";
  }
  const nlohmann::json m = nlohmann::json::parse(Slurp(dir + "/out/manifest.json"));
  EXPECT_EQ(m["tables"].size(), 3u);
  EXPECT_EQ(m["decisions"].size(), 1u);
}

// The same material under a size limit too small for the target: the 4D
// tables miss it (so do the isotropic ones, by the collapse alone), and
// the plan says which larger 4D table would meet it.
TEST(SceneAnisoTest, Missed4dTargetSaysWhatWouldMeetIt) {
  const std::string dir = test::Scratch("scene_aniso_hint");
  const Scene s = Toml(dir,
                       "[engine]\nmax_lut_size = 4\nerror_target = 2e-2\npixel = \"float\"\n"
                       "[[material]]\nname = \"a\"\nmodel = \"ggx-aniso\"\nroughness = 0.5\nanisotropy = 0.8\n");
  const ScenePlan plan = PlanScene(s);
  const PlannedTable* e = FindPlanned(plan, "E_ggx-aniso.exr");
  ASSERT_NE(e, nullptr) << PlanText(s, plan);
  EXPECT_FALSE(e->meets_target) << e->total_error;
  EXPECT_NE(e->hint.find("would meet it"), std::string::npos) << e->hint;
  EXPECT_NE(PlanText(s, plan).find("to meet the target: "), std::string::npos);
}

// A weak anisotropy: the isotropic tables at the collapsed roughness meet
// the target and are smaller than the 4D ones.
TEST(SceneAnisoTest, WeakAnisotropyIsLookedUpAtTheCollapsedRoughness) {
  const std::string dir = test::Scratch("scene_aniso_weak");
  const Scene s = Toml(dir,
                       "[engine]\nmax_lut_size = 16\nerror_target = 2e-2\ntables = [\"E\"]\n"
                       "[[material]]\nname = \"a\"\nmodel = \"ggx-aniso\"\nroughness = [0.4, 0.6]\nanisotropy = 0.02\n");
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 1u) << PlanText(s, plan);
  const PlannedTable& p = plan.tables[0];
  EXPECT_EQ(p.file, "E_ggx.exr");
  EXPECT_FALSE(p.spec.Anisotropic());
  EXPECT_EQ(p.materials, (std::vector<std::string>{"a (collapsed)"}));
  // The collapsed roughness (alpha_t alpha_b)^(1/4), a little above r.
  EXPECT_GT(p.spec.roughness.min, 0.4);
  EXPECT_LT(p.spec.roughness.max, 0.61);
  EXPECT_GT(p.collapse_error, 0.0);
  EXPECT_LE(p.total_error + p.collapse_error, 2e-2);
  ASSERT_EQ(plan.decisions.size(), 1u);
  EXPECT_NE(plan.decisions[0].find("the isotropic tables at the collapsed roughness"), std::string::npos)
      << plan.decisions[0];
}

// The stated error bounds random lookups of the 4D E table and the
// E_avg(r, s) table over a box of roughness and anisotropy.
TEST(SceneAnisoTest, PlannedErrorClaimsBoundOnAnisotropicTables) {
  const std::string dir = test::Scratch("scene_aniso_bound");
  const Scene s = Toml(dir,
                       "[engine]\nmax_lut_size = 16\nerror_target = 2e-2\npixel = \"float\"\ntables = [\"E\", \"E_avg\"]\n"
                       "[[material]]\nname = \"a\"\nmodel = \"ggx-aniso\"\nroughness = [0.3, 0.5]\nanisotropy = 0.5\n"
                       "[[material]]\nname = \"b\"\nmodel = \"ggx-aniso\"\nroughness = 0.4\nanisotropy = 0.9\n");
  const ScenePlan plan = PlanScene(s);
  const PlannedTable* e = FindPlanned(plan, "E_ggx-aniso.exr");
  const PlannedTable* avg = FindPlanned(plan, "E_avg_ggx-aniso.exr");
  ASSERT_NE(e, nullptr) << PlanText(s, plan);
  ASSERT_NE(avg, nullptr) << PlanText(s, plan);
  ASSERT_EQ(e->spec.roughness.min, 0.3);
  ASSERT_EQ(e->spec.anisotropy.max, 0.9);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto in = [&](const Axis& a) { return a.min + (a.max - a.min) * uni(rng); };
  double worst = 0;
  for (int i = 0; i < 600; ++i) {
    // mu log-uniform from 1e-4 half the time: the grazing layer.
    const double mu = i % 2 ? uni(rng) : std::exp(std::log(1e-4) * uni(rng));
    const double phi = in(e->spec.phi), r = in(e->spec.roughness), an = in(e->spec.anisotropy);
    const double exact = std::clamp(IntegrateAnisoTexel(e->spec, r, an, mu, phi).e, 0.0, 1.0);
    worst = std::max(worst, std::abs(Lookup(e->table, {mu, phi, r, an}) - exact));
  }
  std::printf("E %s: stated lookup error %.3g, random lookups %.3g\n", e->file.c_str(), e->total_error, worst);
  EXPECT_LE(worst, e->total_error);
  worst = 0;
  for (int i = 0; i < 8; ++i) {
    const double r = in(avg->spec.roughness), an = in(avg->spec.anisotropy);
    const double exact = std::clamp(IntegrateAnisoEavg(avg->spec, r, an).value, 0.0, 1.0);
    worst = std::max(worst, std::abs(Lookup(avg->table, {r, an}) - exact));
  }
  std::printf("E_avg %s: stated lookup error %.3g, random lookups %.3g\n", avg->file.c_str(), avg->total_error, worst);
  EXPECT_LE(worst, avg->total_error);
}

// An anisotropyTexture scales the strength: the box spans [0, strength].
TEST(SceneAnisoTest, AnisotropyTextureSpansTheStrength) {
  const std::string dir = test::Scratch("scene_aniso_texture");
  WriteText(dir + "/t.gltf",
            "{\"asset\": {\"version\": \"2.0\"}, \"textures\": [{\"source\": 0}], \"materials\": ["
            "{\"name\": \"a\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}, \"extensions\": "
            "{\"KHR_materials_anisotropy\": {\"anisotropyStrength\": 0.3, \"anisotropyTexture\": {\"index\": 0}}}}]}");
  const Scene s = LoadScene(dir + "/t.gltf");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].anisotropy, 0.3);
  EXPECT_EQ(s.materials[0].anisotropy_min, 0.0);
  WriteText(dir + "/bad.gltf",
            "{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"b\", \"extensions\": "
            "{\"KHR_materials_anisotropy\": {\"anisotropyStrength\": 0.3, \"anisotropyTexture\": 4}}}]}");
  EXPECT_THROW(LoadScene(dir + "/bad.gltf"), std::invalid_argument);
}

// A clearcoat layer is GGX at its own roughness: it widens the isotropic
// GGX tables' range and adds no table of its own.
TEST(SceneAnisoTest, ClearcoatReusesTheIsotropicTables) {
  const std::string dir = test::Scratch("scene_clearcoat");
  WriteText(dir + "/cc.gltf",
            "{\"asset\": {\"version\": \"2.0\"}, \"materials\": ["
            "{\"name\": \"car_paint\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.6}, \"extensions\": "
            "{\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 1, \"clearcoatRoughnessFactor\": 0.1}}},"
            "{\"name\": \"off\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}, \"extensions\": "
            "{\"KHR_materials_clearcoat\": {\"clearcoatFactor\": 0, \"clearcoatRoughnessFactor\": 0.05}}}]}");
  Scene s = LoadScene(dir + "/cc.gltf");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].clearcoat, 1.0);
  EXPECT_EQ(s.materials[0].clearcoat_roughness_min, 0.1);
  EXPECT_EQ(s.materials[1].clearcoat, 0.0);
  s.engine.tables = {TableKind::kE};
  s.engine.max_lut_size = 16;
  s.engine.error_target = 5e-2;
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 1u) << PlanText(s, plan);
  EXPECT_EQ(plan.tables[0].file, "E_ggx.exr");
  EXPECT_EQ(plan.tables[0].spec.roughness.min, 0.1);
  EXPECT_EQ(plan.tables[0].spec.roughness.max, 0.6);
  EXPECT_EQ(plan.tables[0].materials, (std::vector<std::string>{"car_paint (clearcoat)", "car_paint", "off"}));
  ASSERT_EQ(plan.decisions.size(), 1u);
  EXPECT_NE(plan.decisions[0].find("IOR 1.5"), std::string::npos) << plan.decisions[0];
  EXPECT_NE(plan.decisions[0].find("reuses the isotropic GGX tables"), std::string::npos) << plan.decisions[0];
  EXPECT_TRUE(plan.notes.empty()) << Joined(plan.notes);
  // Its fields are checked like the others.
  WriteText(dir + "/bad.gltf",
            "{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"p\", \"extensions\": "
            "{\"KHR_materials_clearcoat\": {\"clearcoatRoughnessFactor\": 2}}}]}");
  try {
    LoadScene(dir + "/bad.gltf");
    ADD_FAILURE() << "accepted a clearcoat roughness of 2";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("material 'p': field 'KHR_materials_clearcoat.clearcoatRoughnessFactor'"),
              std::string::npos)
        << e.what();
  }
}

// --preset bevy: the scene's dfg tables (its only table) in Bevy's layout
// and container, one per material group, the manifest recording the
// overrides.
TEST(ScenePresetTest, PresetSceneWritesTheEnginesFiles) {
  const std::string dir = test::Scratch("scene_preset_bevy");
  Scene s = LoadScene(kExamples + "/scene.toml");
  ApplySceneOverrides(&s, {{"--preset", "bevy"}, {"--max-size", "16"}, {"--error-target", "5e-2"}});
  EXPECT_EQ(s.engine.preset, "bevy");
  EXPECT_EQ(s.engine.max_lut_size, 16);
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 2u) << PlanText(s, plan);
  EXPECT_EQ(plan.tables[0].file, "dfg.ktx2");
  EXPECT_EQ(plan.tables[1].file, "dfg_std_g3.ktx2");
  for (const PlannedTable& p : plan.tables) {
    EXPECT_EQ(p.spec.roughness.min, 0.0);  // the engine's axes
    EXPECT_EQ(p.spec.roughness.max, 1.0);
    EXPECT_FALSE(p.size_fixed);            // Bevy reads the size from the KTX2 file
    EXPECT_LE(p.spec.mu.size, 16);
    EXPECT_EQ(p.layout.pixel, PixelType::kHalf);
  }
  EXPECT_NE(Joined(plan.notes).find("E tables: engine preset 'bevy' samples none"), std::string::npos);
  const std::vector<std::string> files = WriteScenePlan(s, plan, dir);
  EXPECT_EQ(SceneOutputFiles(s, dir), files);
  for (const std::string& f : files) EXPECT_TRUE(std::filesystem::exists(f)) << f;
  EXPECT_TRUE(std::filesystem::exists(dir + "/dfg.glsl"));  // the scene's shaders, named as the preset names them
  const nlohmann::json m = nlohmann::json::parse(Slurp(dir + "/manifest.json"));
  EXPECT_EQ(m["engine"]["preset"], "bevy");
  EXPECT_EQ(m["overrides"]["--preset"], "bevy");
  EXPECT_EQ(m["overrides"]["--max-size"], "16");
  EXPECT_EQ(m["overrides"]["--error-target"], "5e-2");
  EXPECT_EQ(m["tables"][0]["file"], "dfg.ktx2");
  const std::string text = PlanText(s, plan);
  EXPECT_NE(text.find("overrides: --preset bevy --max-size 16 --error-target 5e-2"), std::string::npos) << text;
}

// Where the engine fixes the size (Filament's dfg.inc), a GGX scene's file
// is the engine's own, byte for byte the one `bake --preset` writes: one
// orchestration for both.
TEST(ScenePresetTest, FixedSizeEngineFileIsTheEnginesOwn) {
  const std::string dir = test::Scratch("scene_preset_filament");
  Scene s = Toml(dir, "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.2, 0.7]\n");
  ApplySceneOverrides(&s, {{"--preset", "filament"}, {"--error-target", "1"}});
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 1u);
  EXPECT_TRUE(plan.tables[0].size_fixed);
  EXPECT_EQ(plan.tables[0].spec.mu.size, 128);
  EXPECT_NE(PlanText(s, plan).find("size fixed by engine preset 'filament'"), std::string::npos);
  std::filesystem::create_directories(dir + "/scene");
  WriteScenePlan(s, plan, dir + "/scene");
  const Preset& filament = FindPreset("filament");
  PresetRun run;
  run.dir = dir + "/preset";
  std::filesystem::create_directories(run.dir);
  const Table t = Bake(filament.tables[0].spec);
  WritePresetFiles(filament, run, {t}, {ArrangePresetTable(filament.tables[0], t)});
  const std::string a = Slurp(dir + "/scene/dfg.inc"), b = Slurp(dir + "/preset/dfg.inc");
  EXPECT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the scene's dfg.inc differs from the preset's";
}

void ExpectOverrideRejected(Scene s, const SceneOverrides& o, const std::string& expect) {
  try {
    ApplySceneOverrides(&s, o);
    SceneOutputFiles(s, ".");
    ADD_FAILURE() << "accepted " << o.front().first << " " << o.front().second;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

TEST(ScenePresetTest, OverridesAndEnginesAreChecked) {
  const std::string dir = test::Scratch("scene_overrides");
  const Scene s = LoadScene(kExamples + "/scene.toml");  // header = true
  ExpectOverrideRejected(s, {{"--preset", "bevy"}, {"--pixel", "float"}}, "--pixel: fixed by the engine preset 'bevy'");
  ExpectOverrideRejected(s, {{"--pixel", "unorm16"}}, "only the dds format holds unorm16");
  ExpectOverrideRejected(s, {{"--max-size", "1"}}, "--max-size: '1' is not an integer in [2, 8192]");
  ExpectOverrideRejected(s, {{"--error-target", "0"}}, "--error-target: '0' is outside");
  ExpectOverrideRejected(s, {{"--max-size", "16x"}}, "--max-size: '16x' is not an integer");
  ExpectOverrideRejected(s, {{"--error-target", "nan"}}, "--error-target: 'nan' is outside");
  ExpectOverrideRejected(s, {{"--preset", "ue4"}}, "did you mean 'unreal'");
  ExpectOverrideRejected(s, {{"--format", "header"}}, "header = true");
  ExpectOverrideRejected(s, {{"--format", "gif"}}, "gif");
  ExpectOverrideRejected(s, {{"--format", "png"}}, "png");
  ExpectOverrideRejected(s, {{"--shader", "glsl,glsl"}}, "given twice");
  ExpectOverrideRejected(s, {{"--preset", "bevy"}, {"--format", "js"}}, "bevy loads its dfg table as");
  Scene dfg_only = Toml(dir, "[engine]\ntables = [\"dfg\"]\n[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n");
  ExpectOverrideRejected(dfg_only, {{"--preset", "cycles"}}, "samples E, E_avg, ggx-glass E, ggx-glass E_avg, gen_schlick_ior_s, gen_schlick_s, "
                         "none of the scene's tables");
  // Without a preset: another container and pixel type for every table.
  Scene dds = s;
  dds.engine.header = false;
  ApplySceneOverrides(&dds, {{"--format", "DDS"}, {"--pixel", "unorm16"}, {"--shader", "wgsl"}});
  EXPECT_EQ(dds.engine.format, "dds");
  EXPECT_TRUE(dds.engine.unorm16);
  const std::vector<std::string> files = SceneOutputFiles(dds, "d");
  EXPECT_NE(std::find(files.begin(), files.end(), "d/E_ggx.dds"), files.end());
  // The plan names the files as written, the anisotropic tables' too.
  Scene aniso = Toml(dir, "[engine]\nmax_lut_size = 8\nerror_target = 0.05\ntables = [\"E\"]\n"
                          "[[material]]\nname = \"a\"\nmodel = \"ggx-aniso\"\nroughness = 0.5\nanisotropy = 0.9\n");
  ApplySceneOverrides(&aniso, {{"--format", "ktx2"}});
  const ScenePlan aniso_plan = PlanScene(aniso);
  ASSERT_EQ(aniso_plan.tables.size(), 1u) << PlanText(aniso, aniso_plan);
  EXPECT_TRUE(aniso_plan.tables[0].spec.Anisotropic()) << PlanText(aniso, aniso_plan);
  EXPECT_EQ(aniso_plan.tables[0].file, "E_ggx-aniso.ktx2");
  EXPECT_NE(std::find(files.begin(), files.end(), "d/E_ggx.wgsl"), files.end());
  // The engine in a TOML scene: `engine = "bevy"`, or `preset` in [engine]
  // (where the fields its layout fixes are refused).
  const std::string mat = "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n";
  EXPECT_EQ(Toml(dir, "engine = \"bevy\"\n" + mat).engine.preset, "bevy");
  EXPECT_EQ(Toml(dir, "[engine]\npreset = \"godot\"\nerror_target = 1e-2\n" + mat).engine.preset, "godot");
  for (const auto& [text, expect] : std::vector<std::pair<std::string, std::string>>{
           {"engine = \"bevvy\"\n", "field 'engine': unknown preset 'bevvy'"},
           {"[engine]\npreset = \"bevy\"\npixel = \"float\"\n", "field 'pixel': fixed by the engine preset 'bevy'"},
           {"[engine]\npreset = 3\n", "field 'preset': expected a string"},
           {"[engine]\npreset = \"bevy\"\ntables = [\"E\"]\n", "field 'tables': engine preset 'bevy' samples dfg only"}}) {
    try {
      Toml(dir, text + mat);
      ADD_FAILURE() << "accepted " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  }
}

// A target missed within the size limit: the plan says which size and
// warp would meet it, or that the roughness range crosses the mirror cut,
// which no size resolves, and what would from the cut on.
TEST(ScenePlanTest, MissedTargetSaysWhatWouldMeetIt) {
  const std::string dir = test::Scratch("scene_hint");
  const Scene s = Toml(dir,
                       "[engine]\nmax_lut_size = 16\nerror_target = 5e-3\npixel = \"float\"\ntables = [\"E\"]\n"
                       "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.3, 0.6]\n");
  const ScenePlan plan = PlanScene(s);
  ASSERT_EQ(plan.tables.size(), 1u);
  EXPECT_FALSE(plan.tables[0].meets_target);
  EXPECT_NE(plan.tables[0].hint.find("would meet it"), std::string::npos) << plan.tables[0].hint;
  EXPECT_NE(PlanText(s, plan).find("to meet the target: "), std::string::npos);
  const Scene cut = Toml(dir,
                         "[engine]\nmax_lut_size = 8\nerror_target = 1e-2\npixel = \"float\"\ntables = [\"E\"]\n"
                         "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.0, 0.5]\n");
  const ScenePlan cut_plan = PlanScene(cut);
  ASSERT_EQ(cut_plan.tables.size(), 1u);
  EXPECT_FALSE(cut_plan.tables[0].meets_target);
  EXPECT_NE(cut_plan.tables[0].hint.find("crosses the mirror cut"), std::string::npos) << cut_plan.tables[0].hint;
}

}  // namespace
}  // namespace brdfbake
