// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Sheen layers in scenes (glTF KHR_materials_sheen, TOML sheen_roughness):
// they get the charlie (conty-kulla) E and E_avg tables over their sheen
// roughness, through the same planner as the GGX tables, with a stated
// lookup error that bounds random lookups (E above 1 at grazing angles
// included); under an engine preset, the engine's sheen channel or
// brdfbake's own files; malformed sheen fields get one-line errors naming
// the field. In a build without the charlie family (BRDFBAKE_MODELS), a
// glTF sheen gets a one-line note and a TOML sheen a one-line error.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

std::string Scratch(const std::string& name) { return test::Scratch("scene_sheen_" + name); }

// A glTF file: a plain GGX material, a sheen material, one whose sheen
// roughness a texture modulates, and one whose sheen colour is 0 (no layer).
const char* const kSheenGltf =
    "{\"asset\": {\"version\": \"2.0\"}, \"textures\": [{\"source\": 0}], \"images\": [{\"uri\": \"r.png\"}],\n"
    " \"materials\": [\n"
    "  {\"name\": \"plain\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}},\n"
    "  {\"name\": \"velvet\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.9}, \"extensions\": "
    "{\"KHR_materials_sheen\": {\"sheenColorFactor\": [0.8, 0.2, 0.1], \"sheenRoughnessFactor\": 0.6}}},\n"
    "  {\"name\": \"satin\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}, \"extensions\": "
    "{\"KHR_materials_sheen\": {\"sheenColorFactor\": [0, 0, 0.5], \"sheenRoughnessFactor\": 0.45, "
    "\"sheenRoughnessTexture\": {\"index\": 0}}}},\n"
    "  {\"name\": \"dark\", \"pbrMetallicRoughness\": {\"roughnessFactor\": 0.5}, \"extensions\": "
    "{\"KHR_materials_sheen\": {\"sheenRoughnessFactor\": 0.3}}}\n"
    " ]}\n";

TEST(SceneSheenTest, GltfSheenGetsTheCharlieTables) {
  const std::string dir = Scratch("gltf");
  WriteText(dir + "/s.gltf", kSheenGltf);
  Scene s = LoadScene(dir + "/s.gltf");
  ASSERT_EQ(s.materials.size(), 4u);
  s.engine.error_target = 5e-3;
  s.engine.max_lut_size = 32;
  if (!ModelBuilt(ModelKind::kCharlie)) {
    // No charlie family: one note per sheen material, naming the build
    // option; the GGX tables as ever.
    EXPECT_FALSE(s.materials[1].sheen);
    const ScenePlan plan = PlanScene(s);
    const std::string notes = Joined(plan.notes);
    EXPECT_NE(notes.find("material 'velvet' (KHR_materials_sheen)"), std::string::npos) << notes;
    EXPECT_NE(notes.find("BRDFBAKE_MODELS"), std::string::npos) << notes;
    for (const std::string& n : plan.notes) EXPECT_EQ(n.find('\n'), std::string::npos) << n;
    for (const PlannedTable& p : plan.tables) EXPECT_NE(p.spec.model.kind, ModelKind::kCharlie) << p.file;
    return;
  }
  EXPECT_FALSE(s.materials[0].sheen);
  ASSERT_TRUE(s.materials[1].sheen);
  EXPECT_EQ(s.materials[1].sheen_roughness_min, 0.6);
  EXPECT_EQ(s.materials[1].sheen_roughness_max, 0.6);
  // A sheen roughness texture: [0, factor].
  ASSERT_TRUE(s.materials[2].sheen);
  EXPECT_EQ(s.materials[2].sheen_roughness_min, 0.0);
  EXPECT_EQ(s.materials[2].sheen_roughness_max, 0.45);
  // sheenColorFactor 0 (the default): no sheen layer.
  EXPECT_FALSE(s.materials[3].sheen);
  for (const SceneMaterial& m : s.materials) EXPECT_TRUE(m.unsupported.empty()) << m.name;

  const ScenePlan plan = PlanScene(s);
  std::vector<std::string> files;
  for (const PlannedTable& p : plan.tables) files.push_back(p.file);
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"E_avg_charlie.exr", "E_avg_ggx.exr", "E_charlie.exr", "E_ggx.exr",
                                             "dfg_ggx.exr"}));
  for (const char* f : {"E_charlie.exr", "E_avg_charlie.exr"}) {
    const PlannedTable* p = FindPlanned(plan, f);
    ASSERT_NE(p, nullptr) << f;
    EXPECT_EQ(p->spec.model.kind, ModelKind::kCharlie);
    EXPECT_EQ(p->spec.model.visibility, SheenVisibility::kContyKulla);
    // The union of the sheen ranges, nothing more (not the base roughness).
    EXPECT_EQ(p->spec.roughness.min, 0.0);
    EXPECT_EQ(p->spec.roughness.max, 0.6);
    EXPECT_EQ(p->materials, (std::vector<std::string>{"velvet (sheen)", "satin (sheen)"}));
    EXPECT_NE(p->why.find("sheen"), std::string::npos) << p->why;
    EXPECT_LE(p->spec.mu.size, 32);
    // Down to sheen roughness 0 the Charlie E's grazing peak (E = 148 at
    // r = 0, NoV = 1e-4) is beyond any table: a missed target says so.
    if (!p->meets_target) {
      EXPECT_FALSE(p->hint.empty()) << f;
    }
  }
  EXPECT_EQ(FindPlanned(plan, "E_charlie.exr")->spec.mu.clamp_min, 1e-4);
  EXPECT_EQ(FindPlanned(plan, "E_charlie.exr")->table.axes[0].clamp_min, 1e-4);
  // The base layers' GGX tables are the base roughness' alone.
  EXPECT_EQ(FindPlanned(plan, "E_ggx.exr")->spec.roughness.min, 0.5);
  EXPECT_EQ(FindPlanned(plan, "E_ggx.exr")->spec.roughness.max, 0.9);
  const std::string decisions = Joined(plan.decisions);
  EXPECT_NE(decisions.find("the sheen layers of 'velvet', 'satin'"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("conty-kulla"), std::string::npos) << decisions;
  EXPECT_EQ(decisions.find("'dark'"), std::string::npos) << decisions;
  EXPECT_TRUE(plan.notes.empty()) << Joined(plan.notes);
  const std::string text = PlanText(s, plan);
  EXPECT_NE(text.find("E_charlie.exr (E"), std::string::npos) << text;

  // A sheen roughness away from 0 meets a target of 2e-2 (the E's
  // rise towards NoV = 1e-4, about 0.08 per decade of NoV, takes more
  // entries than GGX's grazing layer).
  Scene soft = s;
  soft.materials = {s.materials[1]};
  soft.materials[0].sheen_roughness_min = soft.materials[0].sheen_roughness_max = 0.8;
  soft.engine.error_target = 2e-2;
  soft.engine.max_lut_size = 64;
  for (const PlannedTable& p : PlanScene(soft).tables) {
    EXPECT_TRUE(p.meets_target) << p.file << " " << p.total_error;
    EXPECT_LE(p.total_error, 2e-2) << p.file;
  }

  // Only the kinds the engine samples: E alone gives the sheen's E alone;
  // dfg alone none, with a note.
  s.engine.max_lut_size = 8;
  s.engine.tables = {TableKind::kE};
  const ScenePlan e_only = PlanScene(s);
  EXPECT_NE(FindPlanned(e_only, "E_charlie.exr"), nullptr);
  EXPECT_EQ(FindPlanned(e_only, "E_avg_charlie.exr"), nullptr);
  s.engine.tables = {TableKind::kDfg};
  const ScenePlan dfg_only = PlanScene(s);
  for (const PlannedTable& p : dfg_only.tables) EXPECT_NE(p.spec.model.kind, ModelKind::kCharlie) << p.file;
  EXPECT_NE(Joined(dfg_only.notes).find("samples no E or E_avg"), std::string::npos) << Joined(dfg_only.notes);
}

// The stated error of the sheen tables bounds a GPU's bilinear lookup at
// random points: mu log-uniform down to 1e-4 half the time (where the
// Charlie E exceeds 1 at low sheen roughness), the sheen roughness over
// the materials' range, in half pixels (E above 1: the rounding is part
// of the bound).
TEST(SceneSheenTest, PlannedSheenErrorBoundsRandomLookups) {
  if (!ModelBuilt(ModelKind::kCharlie)) GTEST_SKIP() << "charlie is not in this build";
  const std::string dir = Scratch("bound");
  for (const char* pixel : {"half"}) {
    WriteText(dir + "/s.toml", std::string("[engine]\nmax_lut_size = 32\npixel = \"") + pixel +
                                   "\"\nerror_target = 5e-3\ntables = [\"E\", \"E_avg\"]\n"
                                   "[[material]]\nname = \"cloth\"\nmodel = \"ggx\"\nroughness = 0.5\n"
                                   "sheen_roughness = [0.1, 0.7]\n");
    const Scene s = LoadScene(dir + "/s.toml");
    const ScenePlan plan = PlanScene(s);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    int checked = 0;
    for (const PlannedTable& p : plan.tables) {
      if (p.spec.model.kind != ModelKind::kCharlie) continue;
      ++checked;
      const Table& t = p.table;
      const Axis& am = t.spec.mu;
      const Axis& ar = t.spec.roughness;
      const double e_max = StoredEMax(t.spec);
      double worst = 0, worst_mu = 0, worst_r = 0, largest = 0;
      const bool eavg = t.spec.table == TableKind::kEavg;
      for (int i = 0; i < (eavg ? 60 : 1500); ++i) {
        const double mu = i % 2 ? uni(rng) : std::exp(std::log(1e-4) * uni(rng));
        const double r = ar.min + (ar.max - ar.min) * uni(rng);
        double lookup, exact;
        if (eavg) {
          auto at = [&](int x, int) { return double(t.channels[0].stored[size_t(x)]); };
          lookup = test::TextureBilinear(at, ar.size, 1, test::TextureCoordinate(ar, r), 0.5);
          exact = std::clamp(IntegrateEavg(t.spec, r).value, 0.0, e_max);
        } else {
          auto at = [&](int x, int y) { return double(t.channels[0].stored[size_t(y) * t.width + x]); };
          lookup = test::TextureBilinear(at, am.size, ar.size, test::TextureCoordinate(am, mu),
                                         test::TextureCoordinate(ar, r));
          // The table's NoV clamp (1e-4, below which the sheen's E keeps
          // growing): a lookup at NoV below it means E there.
          exact = ClampToRange(IntegrateTexel(t.spec, r, std::max(mu, am.clamp_min)), e_max).e;
        }
        largest = std::max(largest, exact);
        if (std::abs(lookup - exact) > worst) {
          worst = std::abs(lookup - exact);
          worst_mu = mu;
          worst_r = r;
        }
      }
      std::printf("%s, %s (%dx%d): stated lookup error %.3g, random lookups %.3g at mu %.3g r %.3g; largest E %.3g\n",
                  p.file.c_str(), pixel, t.width, t.height, p.total_error, worst, worst_mu, worst_r, largest);
      EXPECT_LE(worst, p.total_error) << p.file << " " << pixel << " at mu " << worst_mu << " r " << worst_r;
      if (!p.meets_target) {
        EXPECT_FALSE(p.hint.empty()) << p.file;
      }
    }
    EXPECT_EQ(checked, 2) << PlanText(s, plan);
  }
}

struct BadSheen {
  const char* text;
  const char* expect;
};

void ExpectRejected(const std::string& path, const BadSheen& c) {
  try {
    LoadScene(path);
    ADD_FAILURE() << "accepted: " << c.text;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find(c.expect), std::string::npos) << "'" << c.expect << "' not in: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(SceneSheenTest, TomlSheenRoughnessIsValidatedStrictly) {
  const std::string dir = Scratch("toml");
  const std::string head = "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n";
  if (!ModelBuilt(ModelKind::kCharlie)) {
    WriteText(dir + "/s.toml", head + "sheen_roughness = 0.5\n");
    ExpectRejected(dir + "/s.toml", {"", "material 'm': field 'sheen_roughness': a sheen layer needs the charlie "
                                         "model, which is not in this build (BRDFBAKE_MODELS)"});
    return;
  }
  WriteText(dir + "/s.toml", head + "sheen_roughness = [0.25, 0.5]\n");
  const Scene s = LoadScene(dir + "/s.toml");
  ASSERT_TRUE(s.materials[0].sheen);
  EXPECT_EQ(s.materials[0].sheen_roughness_min, 0.25);
  EXPECT_EQ(s.materials[0].sheen_roughness_max, 0.5);
  WriteText(dir + "/s.toml", head);
  EXPECT_FALSE(LoadScene(dir + "/s.toml").materials[0].sheen);
  const BadSheen cases[] = {
      {"sheen_roughness = 1.5\n", "material 'm': field 'sheen_roughness': 1.5 is outside [0, 1]"},
      {"sheen_roughness = -0.1\n", "field 'sheen_roughness': -0.1 is outside [0, 1]"},
      {"sheen_roughness = \"soft\"\n", "field 'sheen_roughness': expected a number"},
      {"sheen_roughness = [0.6, 0.2]\n", "field 'sheen_roughness': the range must satisfy"},
      {"sheen_roughness = [0.1, 0.2, 0.3]\n", "field 'sheen_roughness': a range is two numbers"},
      {"sheen_roughness = true\n", "field 'sheen_roughness': expected a number"},
      {"sheen_colour = 1\n", "field 'sheen_colour': unknown field"},
  };
  int n = 0;
  for (const BadSheen& c : cases) {
    const std::string path = dir + "/bad" + std::to_string(n++) + ".toml";
    WriteText(path, head + c.text);
    ExpectRejected(path, c);
  }
}

TEST(SceneSheenTest, GltfSheenFieldsAreValidatedStrictly) {
  const std::string dir = Scratch("gltf_bad");
  auto with = [](const std::string& sheen) {
    return "{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"v\", \"extensions\": "
           "{\"KHR_materials_sheen\": " + sheen + "}}]}";
  };
  const BadSheen cases[] = {
      {"{\"sheenColorFactor\": [1, 2, 0]}",
       "material 'v': field 'KHR_materials_sheen.sheenColorFactor[1]': 2 is outside [0, 1]"},
      {"{\"sheenColorFactor\": 1}", "field 'KHR_materials_sheen.sheenColorFactor': expected an array of three numbers"},
      {"{\"sheenColorFactor\": [1, 1]}", "field 'KHR_materials_sheen.sheenColorFactor': expected an array"},
      {"{\"sheenColorFactor\": [1, \"x\", 1]}", "field 'KHR_materials_sheen.sheenColorFactor[1]': expected a number"},
      {"{\"sheenColorFactor\": [1, 1, 1], \"sheenRoughnessFactor\": 1.5}",
       "field 'KHR_materials_sheen.sheenRoughnessFactor': 1.5 is outside [0, 1]"},
      {"{\"sheenRoughnessFactor\": \"soft\"}", "field 'KHR_materials_sheen.sheenRoughnessFactor': expected a number"},
      {"{\"sheenColorFactor\": [1, 1, 1], \"sheenRoughnessTexture\": {\"index\": -1}}",
       "field 'KHR_materials_sheen.sheenRoughnessTexture': expected an object"},
      {"{\"sheenColorTexture\": 3}", "field 'KHR_materials_sheen.sheenColorTexture': expected an object"},
      {"[]", "field 'extensions.KHR_materials_sheen': expected an object"},
  };
  int n = 0;
  for (const BadSheen& c : cases) {
    const std::string path = dir + "/bad" + std::to_string(n++) + ".gltf";
    WriteText(path, with(c.text));
    ExpectRejected(path, c);
  }
}

// Under an engine preset: Filament's dfg carries the sheen in its cloth
// channel (no table of its own, and the plan says so); Bevy has no sheen
// table, so the charlie tables go out as brdfbake's own EXR files beside
// its dfg.ktx2, known before the plan like every other file.
TEST(SceneSheenTest, EnginePresetsServeTheSheenOrGetBrdfbakesFiles) {
  if (!ModelBuilt(ModelKind::kCharlie)) GTEST_SKIP() << "charlie is not in this build";
  const std::string dir = Scratch("preset");
  WriteText(dir + "/s.gltf", kSheenGltf);
  Scene filament = LoadScene(dir + "/s.gltf");
  ApplySceneOverrides(&filament, {{"--preset", "filament"}});
  const ScenePlan fp = PlanScene(filament);
  for (const PlannedTable& p : fp.tables) EXPECT_NE(p.spec.model.kind, ModelKind::kCharlie) << p.file;
  const std::string fd = Joined(fp.decisions);
  EXPECT_NE(fd.find("engine preset 'filament' serves the sheen from a channel of its own table"), std::string::npos)
      << fd;
  EXPECT_NE(fd.find("cloth channel (B)"), std::string::npos) << fd;
  EXPECT_NE(fd.find("in dfg.inc (128x128) the channel's bilinear lookup error over the sheen roughness is"),
            std::string::npos)
      << fd;

  // Godot, at sizes of the scene's choice: the stated error of its cloth
  // channel bounds random lookups of that channel (the Charlie E, neubelt,
  // over the planned dfg's axes) at the sheen roughness.
  Scene godot = LoadScene(dir + "/s.gltf");
  ApplySceneOverrides(&godot, {{"--preset", "godot"}, {"--max-size", "16"}});
  const ScenePlan gp = PlanScene(godot);
  const std::string gd = Joined(gp.decisions);
  const std::string says = "the channel's bilinear lookup error over the sheen roughness is ";
  const size_t at = gd.find(says);
  ASSERT_NE(at, std::string::npos) << gd;
  const double stated = std::stod(gd.substr(at + says.size()));
  const PlannedTable* dfg = FindPlanned(gp, "dfg_lut.exr");
  ASSERT_NE(dfg, nullptr) << PlanText(godot, gp);
  BakeSpec cloth;
  cloth.table = TableKind::kE;
  cloth.model.kind = ModelKind::kCharlie;
  cloth.model.visibility = SheenVisibility::kNeubelt;
  cloth.mu = dfg->table.spec.mu;
  cloth.roughness = dfg->table.spec.roughness;
  const Table ct = Bake(cloth);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 600; ++i) {
    const double mu = i % 2 ? uni(rng) : std::exp(std::log(1e-4) * uni(rng)), r = 0.6 * uni(rng);
    auto texel = [&](int x, int y) { return double(ct.channels[0].stored[size_t(y) * ct.width + x]); };
    const double lookup = test::TextureBilinear(texel, cloth.mu.size, cloth.roughness.size,
                                                test::TextureCoordinate(cloth.mu, mu),
                                                test::TextureCoordinate(cloth.roughness, r));
    worst = std::max(worst, std::abs(lookup - ClampToRange(IntegrateTexel(cloth, r, mu), kInfinity).e));
  }
  std::printf("godot's cloth channel (%dx%d): stated lookup error %.3g, random lookups %.3g\n", ct.width, ct.height,
              stated, worst);
  EXPECT_LE(worst, stated * (1 + 1e-3));  // the decision prints 4 digits

  Scene bevy = LoadScene(dir + "/s.gltf");
  ApplySceneOverrides(&bevy, {{"--preset", "bevy"}, {"--error-target", "1e-2"}, {"--max-size", "16"}});
  const ScenePlan bp = PlanScene(bevy);
  const PlannedTable* e = FindPlanned(bp, "E_charlie.exr");
  ASSERT_NE(e, nullptr) << PlanText(bevy, bp);
  EXPECT_NE(FindPlanned(bp, "E_avg_charlie.exr"), nullptr) << PlanText(bevy, bp);
  EXPECT_NE(FindPlanned(bp, "dfg.ktx2"), nullptr) << PlanText(bevy, bp);
  EXPECT_EQ(e->spec.roughness.min, 0.0);
  EXPECT_EQ(e->spec.roughness.max, 0.6);
  EXPECT_FALSE(e->spec.half);  // brdfbake's own file under a preset: float, as the 4D tables
  EXPECT_NE(e->why.find("no sheen table: brdfbake's own"), std::string::npos) << e->why;
  const std::string bd = Joined(bp.decisions);
  EXPECT_NE(bd.find("engine preset 'bevy' has no sheen table"), std::string::npos) << bd;
  const std::string out = Scratch("preset_out");
  const std::vector<std::string> files = WriteScenePlan(bevy, bp, out);
  EXPECT_EQ(SceneOutputFiles(bevy, out), files);
  std::vector<std::string> listed;
  for (const auto& f : std::filesystem::directory_iterator(out)) listed.push_back(f.path().filename().string());
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(listed, (std::vector<std::string>{"E_avg_charlie.exr", "E_charlie.exr", "dfg.ktx2", "manifest.json"}));
  const nlohmann::json m = nlohmann::json::parse(Slurp(out + "/manifest.json"));
  bool listed_sheen = false;
  for (const auto& t : m["tables"]) {
    if (t["file"] == "E_charlie.exr") {
      listed_sheen = true;
      EXPECT_EQ(t["model"]["name"], "charlie");
      EXPECT_EQ(t["model"]["visibility"], "conty-kulla");
    }
  }
  EXPECT_TRUE(listed_sheen) << m.dump(2);
}

}  // namespace
}  // namespace brdfbake
