// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scenes: the example TOML and glTF scenes load and plan exactly the tables
// their materials need (no model, gamma, roughness range or anisotropy they
// do not use), the planned resolution meets the error target under a GPU's
// bilinear lookup at random points, a scene bake writes those files and a
// manifest and nothing else, and malformed scenes (fixed cases and a seeded
// fuzz) get one-line errors naming the file, the material and the field.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/exr.h"
#include "brdfbake/scene.h"
#include "util/file_util.h"
#include "util/scene_util.h"
#include "util/lookup_util.h"

namespace brdfbake {
namespace {

using test::FindPlanned;
using test::Slurp;
using test::WriteText;

const std::string kExamples = std::string(BRDFBAKE_TEST_DATA) + "/../../examples";

std::string Scratch(const std::string& name) { return test::Scratch("scene_" + name); }

TEST(SceneTest, TomlExamplePlansExactlyWhatItsMaterialsNeed) {
  const Scene s = LoadScene(kExamples + "/scene.toml");
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.engine.max_lut_size, 64);
  EXPECT_EQ(s.engine.pixel, PixelType::kHalf);
  const ScenePlan plan = PlanScene(s);
  std::vector<std::string> files;
  for (const PlannedTable& p : plan.tables) files.push_back(p.file);
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"E_avg_ggx.exr", "E_avg_std_g3.exr", "E_ggx.exr", "E_std_g3.exr",
                                             "dfg_ggx.exr", "dfg_std_g3.exr"}));
  // ggx: the union of the materials' roughness, [0.3, 0.6], nothing more.
  const PlannedTable* e = FindPlanned(plan, "E_ggx.exr");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->spec.roughness.min, 0.3);
  EXPECT_EQ(e->spec.roughness.max, 0.6);
  EXPECT_EQ(e->materials, (std::vector<std::string>{"brushed_steel", "painted_metal"}));
  // std: one gamma, one roughness: a single roughness entry.
  const PlannedTable* d = FindPlanned(plan, "dfg_std_g3.exr");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->spec.model.gamma, 3.0);
  EXPECT_EQ(d->spec.roughness.size, 1);
  EXPECT_EQ(d->spec.roughness.min, 0.2);
  for (const PlannedTable& p : plan.tables) {
    EXPECT_TRUE(p.meets_target) << p.file << " " << p.total_error;
    EXPECT_LE(p.total_error, s.engine.error_target) << p.file;
    EXPECT_LE(p.spec.mu.size, 64);
  }
  EXPECT_TRUE(plan.notes.empty());
}

TEST(SceneTest, GltfExampleReadsMaterialsAndExtensions) {
  const Scene s = LoadScene(kExamples + "/scene.gltf");
  ASSERT_EQ(s.materials.size(), 5u);
  EXPECT_EQ(s.materials[0].name, "rubber");
  EXPECT_EQ(s.materials[0].roughness_min, 0.8);
  // A roughness texture: the range [0, factor].
  EXPECT_EQ(s.materials[2].roughness_min, 0.0);
  EXPECT_EQ(s.materials[2].roughness_max, 0.7);
  EXPECT_EQ(s.materials[3].model, ModelKind::kGgxAniso);
  EXPECT_EQ(s.materials[3].anisotropy, 0.6);
  // KHR_materials_sheen: a sheen layer at its own roughness.
  EXPECT_TRUE(s.materials[4].sheen);
  EXPECT_EQ(s.materials[4].sheen_roughness_min, 0.5);
  EXPECT_EQ(s.materials[4].sheen_roughness_max, 0.5);
  EXPECT_TRUE(s.materials[4].unsupported.empty());
  // The plan, at a reduced size so that it stays small: isotropic GGX
  // tables over [0, 0.9] for the four isotropic materials; the anisotropic
  // aluminium gets the tables the planner chose for it, and says why; the
  // velvet's sheen the charlie tables at its sheen roughness.
  Scene small = s;
  small.engine.max_lut_size = 16;
  small.engine.tables = {TableKind::kE, TableKind::kEavg};
  const ScenePlan plan = PlanScene(small);
  bool aluminium_served = false;
  int sheen_tables = 0;
  for (const PlannedTable& p : plan.tables) {
    if (p.spec.model.kind == ModelKind::kGgx) {
      EXPECT_EQ(p.spec.roughness.min, 0.0);
      EXPECT_EQ(p.spec.roughness.max, 0.9);
    }
    if (p.spec.model.kind == ModelKind::kCharlie) {
      ++sheen_tables;
      EXPECT_EQ(p.spec.roughness.min, 0.5);
      EXPECT_EQ(p.spec.roughness.max, 0.5);
      EXPECT_EQ(p.materials, std::vector<std::string>{"velvet (sheen)"});
    }
    for (const std::string& m : p.materials) aluminium_served |= m.rfind("brushed_aluminium", 0) == 0;
  }
  EXPECT_TRUE(aluminium_served);
  EXPECT_EQ(sheen_tables, 2);  // E and E_avg
  // The anisotropic aluminium, the sheen, and the opaque material with
  // KHR_materials_ior (served by dfg).
  ASSERT_EQ(plan.decisions.size(), 3u);
  std::string decisions;
  for (const std::string& d : plan.decisions) decisions += d + "\n";
  EXPECT_NE(decisions.find("(ior 1.5, opaque)"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("brushed_aluminium"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("collapsed roughness"), std::string::npos) << decisions;
  EXPECT_NE(decisions.find("the sheen layer of 'velvet'"), std::string::npos) << decisions;
  std::string notes;
  for (const std::string& n : plan.notes) notes += n + "\n";
  EXPECT_EQ(notes.find("brushed_aluminium"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("KHR_materials_sheen"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("gold"), std::string::npos) << "KHR_materials_ior is covered by dfg: " << notes;
}

// The planned lookup error bounds what a GPU's bilinear lookup of the table
// gives at random points (clamp-to-edge, texel centres).
TEST(SceneTest, PlannedErrorBoundsRandomLookups) {
  Scene s = LoadScene(kExamples + "/scene.toml");
  s.engine.tables = {TableKind::kE};
  s.engine.pixel = PixelType::kFloat;
  const ScenePlan plan = PlanScene(s);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const PlannedTable& p : plan.tables) {
    const Table& t = p.table;
    const Axis& am = t.spec.mu;
    const Axis& ar = t.spec.roughness;
    double worst = 0;
    for (int i = 0; i < 400; ++i) {
      const double mu = uni(rng), r = ar.min + (ar.max - ar.min) * uni(rng);
      // Texture coordinates by the axis maps (docs/format.md), inverted.
      auto at = [&](int x, int y) { return double(t.channels[0].stored[size_t(y) * t.width + x]); };
      const double lookup = test::TextureBilinear(at, am.size, ar.size, test::TextureCoordinate(am, mu),
                                                  test::TextureCoordinate(ar, r));
      BakeSpec es = t.spec;  // the table's model, masking and gamma
      const double exact = IntegrateTexel(es, ar.size == 1 ? ar.min : r, mu).e;
      worst = std::max(worst, std::abs(lookup - exact));
    }
    std::printf("%s: planned lookup error %.3g, random lookups %.3g\n", p.file.c_str(), p.total_error, worst);
    EXPECT_LE(worst, p.total_error) << p.file;
  }
}

// The stated error is a bound: random lookups over a table whose roughness
// range crosses the mirror cut (alpha = 1e-4, r = 0.01, where E jumps to 1)
// and whose mu axis reaches the grazing layer (NoV down to 1e-4), E and
// dfg, never exceed it.
TEST(SceneTest, PlannedErrorIsABoundAcrossTheMirrorCut) {
  const std::string dir = test::Scratch("scene_bound");
  test::WriteText(dir + "/s.toml",
                  "[engine]\nmax_lut_size = 32\npixel = \"float\"\nplacement = \"centers\"\n"
                  "error_target = 5e-3\ntables = [\"E\", \"dfg\"]\n"
                  "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.0, 0.25]\n");
  const ScenePlan plan = PlanScene(LoadScene(dir + "/s.toml"));
  ASSERT_EQ(plan.tables.size(), 2u);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const PlannedTable& p : plan.tables) {
    const Table& t = p.table;
    const Axis& am = t.spec.mu;
    const Axis& ar = t.spec.roughness;
    const size_t nvalue = t.spec.table == TableKind::kDfg ? 2 : 1;
    double worst = 0, worst_mu = 0, worst_r = 0;
    for (int i = 0; i < 3000; ++i) {
      // mu log-uniform from 1e-4 half the time; r near the cut a third.
      const double mu = i % 2 ? uni(rng) : std::exp(std::log(1e-4) * uni(rng));
      const double r = i % 3 == 0 ? 0.01 * (1 + 0.02 * (uni(rng) - 0.5)) : ar.min + (ar.max - ar.min) * uni(rng);
      BakeSpec es = t.spec;
      const TexelEstimate v = ClampToRange(IntegrateTexel(es, r, mu));
      const double exact[2] = {nvalue == 1 ? v.e : v.scale, v.bias};
      for (size_t c = 0; c < nvalue; ++c) {
        auto at = [&](int x, int y) { return double(t.channels[c].stored[size_t(y) * t.width + x]); };
        const double lookup = test::TextureBilinear(at, am.size, ar.size, test::TextureCoordinate(am, mu),
                                                    test::TextureCoordinate(ar, r));
        if (std::abs(lookup - exact[c]) > worst) {
          worst = std::abs(lookup - exact[c]);
          worst_mu = mu;
          worst_r = r;
        }
      }
    }
    std::printf("%s (%dx%d): stated lookup error %.3g, random lookups %.3g at mu %.3g r %.4g\n",
                p.file.c_str(), t.width, t.height, p.total_error, worst, worst_mu, worst_r);
    EXPECT_LE(worst, p.total_error) << p.file << " at mu " << worst_mu << " r " << worst_r;
  }
}

TEST(SceneTest, BakeWritesThePlanAndAManifest) {
  Scene s = LoadScene(kExamples + "/scene.toml");
  s.engine.error_target = 2e-2;  // small tables: this is about the files
  const ScenePlan plan = PlanScene(s);
  const std::string dir = Scratch("bake");
  const std::vector<std::string> files = WriteScenePlan(s, plan, dir);
  // The files are known before the plan, to be checked before its work.
  EXPECT_EQ(SceneOutputFiles(s, dir), files);
  std::vector<std::string> listed;
  for (const auto& e : std::filesystem::directory_iterator(dir)) listed.push_back(e.path().filename().string());
  std::sort(listed.begin(), listed.end());
  std::vector<std::string> expected;
  for (const std::string& f : files) expected.push_back(std::filesystem::path(f).filename().string());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(listed, expected);  // nothing else
  // 6 tables, each with its EXR, header, GLSL and HLSL, and the manifest.
  EXPECT_EQ(listed.size(), 6u * 4 + 1);
  const nlohmann::json m = nlohmann::json::parse(Slurp(dir + "/manifest.json"));
  ASSERT_EQ(m["tables"].size(), 6u);
  for (const auto& t : m["tables"]) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + t["file"].get<std::string>()));
    EXPECT_FALSE(t["why"].get<std::string>().empty());
    EXPECT_GE(t["seconds"].get<double>(), 0.0);
    EXPECT_GT(t["max_abs_error"].get<double>(), 0.0);
    EXPECT_LE(t["lookup_error"].get<double>(), 2e-2);
    EXPECT_EQ(t["also"].size(), 3u);
    const ExrContents c = ReadExr(dir + "/" + t["file"].get<std::string>());
    EXPECT_EQ(c.Attribute("brdfbake.table"), t["table"].get<std::string>());
  }
}

struct BadScene {
  const char* text;
  const char* expect;  // in the error, after the file name
};

// LoadScene(path) throws one line that starts with the path and contains
// the expected words.
void ExpectRejected(const std::string& path, const BadScene& c) {
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

TEST(SceneTest, MalformedScenesGetOneLineErrorsNamingTheField) {
  const std::string dir = Scratch("bad");
  const std::string good_material = "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n";
  const BadScene cases[] = {
      {"", "no [[material]]"},
      {"[engine]\nmax_lut_size = 64\n", "no [[material]]"},
      {"[[material]]\nmodel = \"ggx\"\nroughness = 0.5\n", "material '#1': field 'name': missing"},
      {"[[material]]\nname = \"m\"\nroughness = 0.5\n", "material 'm': field 'model': missing"},
      {"[[material]]\nname = \"m\"\nmodel = \"phong\"\nroughness = 0.5\n", "material 'm': field 'model': 'phong'"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\n", "material 'm': field 'roughness': missing"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = \"rough\"\n", "field 'roughness': expected a number"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 1.5\n", "field 'roughness': 1.5 is outside [0, 1]"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.6, 0.2]\n", "field 'roughness': the range"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = [0.1]\n", "field 'roughness': a range is two numbers"},
      {"[[material]]\nname = \"m\"\nmodel = \"std\"\nroughness = 0.5\n", "material 'm': field 'gamma': missing"},
      {"[[material]]\nname = \"m\"\nmodel = \"std\"\ngamma = 1.2\nroughness = 0.5\n",
       "field 'gamma': must be >= 1.500001 or inf (the STD's mean slope diverges at 1.5; got 1.2)"},
      {"[[material]]\nname = \"m\"\nmodel = \"std\"\ngamma = 1.5000001\nroughness = 0.5\n",
       "field 'gamma': must be >= 1.500001 or inf (the STD's mean slope diverges at 1.5; got 1.5000001)"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\ngamma = 3\nroughness = 0.5\n", "field 'gamma': only std"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\ncolour = 1\n", "field 'colour': unknown field"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\nmasking = \"none\"\n", "field 'masking'"},
      {"[engine]\npixel = \"double\"\n", "[engine]: field 'pixel'"},
      {"[engine]\nmax_lut_size = 1\n", "[engine]: field 'max_lut_size'"},
      {"[engine]\nmax_lut_size = 64.9\n", "[engine]: field 'max_lut_size': 64.9 is not an integer"},
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 1.0000000000000002\n",
       "field 'roughness': 1.0000000000000002 is outside [0, 1]"},
      {"[engine]\nerror_target = -1\n", "[engine]: field 'error_target'"},
      {"[engine]\ntables = [\"F\"]\n", "[engine]: field 'tables'"},
      {"[engine]\nshaders = \"glsl\"\n", "[engine]: field 'shaders'"},
      {"[engine]\nspeed = 3\n", "[engine]: field 'speed': unknown field"},
      {"[camera]\nfov = 3\n", "unknown section 'camera'"},
      {"material = 3\n", "'material' must be an array of tables"},
      {"[[material]\nname = \"m\"\n", ":1:"},  // TOML syntax: line and column
      {"[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.2\n",
       "another material has this name"},
  };
  int n = 0;
  for (const BadScene& c : cases) {
    const std::string path = dir + "/bad" + std::to_string(n++) + ".toml";
    WriteText(path, std::string(c.text) + (std::string(c.text).find("[[material]]") == std::string::npos &&
                                                   std::string(c.expect).find("no [[material]]") == std::string::npos &&
                                                   std::string(c.expect).find("array of tables") == std::string::npos
                                               ? good_material
                                               : ""));
    ExpectRejected(path, c);
  }
  // glTF.
  const BadScene gltf[] = {
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"a\", \"pbrMetallicRoughness\": "
       "{\"roughnessFactor\": 2}}]}",
       "material 'a': field 'pbrMetallicRoughness.roughnessFactor'"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"b\", \"extensions\": "
       "{\"KHR_materials_anisotropy\": {\"anisotropyStrength\": \"x\"}}}]}",
       "material 'b': field 'KHR_materials_anisotropy.anisotropyStrength'"},
      {"{\"asset\": {\"version\": \"2.0\"}}", "no materials"},
      {"{\"asset\": ", "not a valid glTF"},
      {"not json at all", "not a valid glTF"},
      // Types and versions are checked, not coerced.
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"c\", \"pbrMetallicRoughness\": "
       "{\"roughnessFactor\": \"high\"}}]}",
       "material 'c': field 'pbrMetallicRoughness.roughnessFactor': expected a number"},
      {"{\"asset\": {\"version\": \"1.0\"}, \"materials\": [{}]}", "asset.version is '1.0', not 2.x"},
      {"{\"materials\": [{}]}", "no 'asset' object"},
      {"{\"asset\": {\"version\": 2}, \"materials\": [{}]}", "no 'asset.version' string"},
      {"[1, 2]", "the top level is a array, not an object"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": {}}", "'materials' is a object, not an array"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [3]}", "materials[0]: a number, not an object"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": 7}]}", "materials[0]: field 'name'"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"d\", \"extensions\": []}]}",
       "material 'd': field 'extensions': expected an object"},
      {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"e\", \"pbrMetallicRoughness\": "
       "{\"metallicRoughnessTexture\": {\"index\": -1}}}]}",
       "material 'e': field 'pbrMetallicRoughness.metallicRoughnessTexture'"},
  };
  for (const BadScene& c : gltf) {
    const std::string path = dir + "/bad" + std::to_string(n++) + ".gltf";
    WriteText(path, c.text);
    ExpectRejected(path, c);
  }
  EXPECT_THROW(LoadScene(dir + "/missing.toml"), std::invalid_argument);
  WriteText(dir + "/scene.yaml", "a: 1");
  EXPECT_THROW(LoadScene(dir + "/scene.yaml"), std::invalid_argument);
}

// Nesting deep enough to exhaust a recursive parser's stack is refused
// before parsing, in the materials' extras as anywhere else.
TEST(SceneTest, DeeplyNestedGltfIsRefused) {
  const std::string dir = Scratch("deep");
  for (int depth : {600, 20000, 200000}) {
    const std::string path = dir + "/deep" + std::to_string(depth) + ".gltf";
    WriteText(path, "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{\"extras\":" +
                        std::string(depth, '[') + std::string(depth, ']') + "}]}");
    ExpectRejected(path, {"deep", "nested deeper than 512 levels"});
  }
  // Brackets inside strings do not count; 100 levels load.
  const std::string path = dir + "/fine.gltf";
  WriteText(path, "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{\"name\":\"[[[\\\"[[\",\"extras\":" +
                      std::string(100, '[') + std::string(100, ']') + "}]}");
  const Scene s = LoadScene(path);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "[[[\"[[");
}

// A glTF scene is read for its materials alone: buffer and image URIs
// (absolute, traversing, percent-encoded, missing, huge, a FIFO, a data
// URI) are never opened, so they can neither fail the load nor reveal
// anything about other files. (The FIFO, which blocks whoever opens it,
// is in tests/cli/reliability_test.cc, under a timeout.)
TEST(SceneTest, GltfUrisAreNeverOpened) {
  const std::string dir = Scratch("uris");
  const std::string huge = dir + "/huge.bin";
  {
    std::ofstream f(huge);
  }
  std::filesystem::resize_file(huge, uintmax_t(3) << 30);  // sparse, 3 GiB
  const std::string uris[] = {"/etc/shadow", "../../../../../../etc/passwd", "%2fetc%2fpasswd",
                              "missing.bin", huge, "data:application/octet-stream;base64,AAAA"};
  std::string buffers, images;
  for (const std::string& u : uris) {
    buffers += std::string(buffers.empty() ? "" : ",") + "{\"uri\":\"" + u + "\",\"byteLength\":16}";
    images += std::string(images.empty() ? "" : ",") + "{\"uri\":\"" + u + "\"}";
  }
  const std::string path = dir + "/scene.gltf";
  WriteText(path, "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[" + buffers + "],\"images\":[" + images +
                      "],\"materials\":[{\"name\":\"m\",\"pbrMetallicRoughness\":{\"roughnessFactor\":0.4}}]}");
  const Scene s = LoadScene(path);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].roughness_max, 0.4);
  std::filesystem::remove(huge);
}

// Binary glTF: the JSON chunk is read, the BIN chunk never; a truncated or
// foreign container is refused in one line.
TEST(SceneTest, GlbReadsTheJsonChunk) {
  const std::string dir = Scratch("glb");
  const auto le32 = [](uint32_t v) {
    std::string b(4, '\0');
    for (int k = 0; k < 4; ++k) b[k] = char((v >> (8 * k)) & 0xff);
    return b;
  };
  std::string json = "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{\"name\":\"g\"}]}";
  while (json.size() % 4) json += ' ';
  const std::string bin(64, '\x7f');
  const std::string glb = "glTF" + le32(2) + le32(uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
                          le32(uint32_t(json.size())) + "JSON" + json + le32(uint32_t(bin.size())) +
                          std::string("BIN\0", 4) + bin;
  const std::string path = dir + "/scene.glb";
  WriteText(path, glb);
  const Scene s = LoadScene(path);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "g");
  const BadScene bad[] = {{"glTF", "shorter than a GLB header"},
                          {"glTX", "no GLB magic"},
                          {"version", "GLB version 1, not 2"},
                          {"cut", "the GLB lengths exceed the file"},
                          {"type", "the first GLB chunk is not JSON"}};
  for (const BadScene& c : bad) {
    std::string b = glb;
    const std::string what = c.text;
    if (what == "glTF") b = b.substr(0, 10);
    if (what == "glTX") b[3] = 'X';
    if (what == "version") b.replace(4, 4, le32(1));
    if (what == "cut") b = b.substr(0, 40);
    if (what == "type") b.replace(16, 4, std::string("BIN\0", 4));
    const std::string p = dir + "/bad_" + what + ".glb";
    WriteText(p, b);
    ExpectRejected(p, c);
  }
}

// Seeded random GLB containers: the header's version and lengths, the
// chunk's type and the file's length drawn from edge values (0, 1, the
// true lengths +- 1 and 4, 2^31 - 1, 2^32 - 1) and at random. Every load
// either succeeds or throws one line naming the file; nothing past the
// file is read and no length is trusted.
TEST(SceneTest, FuzzedGlbContainersNeverCrash) {
  const std::string dir = Scratch("glb_fuzz");
  const auto le32 = [](uint32_t v) {
    std::string b(4, '\0');
    for (int k = 0; k < 4; ++k) b[k] = char((v >> (8 * k)) & 0xff);
    return b;
  };
  std::string json = "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{\"name\":\"g\"}]}";
  while (json.size() % 4) json += ' ';
  std::mt19937_64 rng(4242);
  const auto edge = [&](uint32_t truth) {
    const uint32_t values[] = {0u, 1u, truth - 4, truth - 1, truth, truth, truth + 1, truth + 4,
                               0x7fffffffu, 0xffffffffu, uint32_t(rng())};
    return values[rng() % (sizeof(values) / sizeof(values[0]))];
  };
  int ok = 0, rejected = 0;
  for (int run = 0; run < 400; ++run) {
    const uint32_t len = uint32_t(json.size()), total = 20 + len + 8 + 16;
    std::string body = json;
    if (rng() % 4 == 0) {
      for (char& c : body) c = rng() % 8 == 0 ? char(rng()) : c;
    }
    const std::string types[] = {"JSON", std::string("BIN\0", 4), "json", std::string(4, '\0')};
    std::string glb = "glTF" + le32(rng() % 6 == 0 ? uint32_t(rng() % 4) : 2u) + le32(edge(total)) +
                      le32(edge(len)) + (rng() % 6 == 0 ? types[rng() % 4] : types[0]) + body +
                      le32(edge(16)) + std::string("BIN\0", 4) + std::string(16, '\x7f');
    if (rng() % 4 == 0) glb.resize(rng() % (glb.size() + 1));
    const std::string path = dir + "/g" + std::to_string(run) + ".glb";
    test::WriteText(path, glb);
    try {
      const Scene s = LoadScene(path);
      ASSERT_FALSE(s.materials.empty()) << path;
      ++ok;
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      ASSERT_EQ(msg.rfind(path, 0), 0u) << msg;
      ASSERT_EQ(msg.find('\n'), std::string::npos) << msg;
      ++rejected;
    }
  }
  std::printf("400 random GLB containers: %d loaded, %d rejected with a one-line error\n", ok, rejected);
  EXPECT_GT(ok, 10);
  EXPECT_GT(rejected, 200);
}

// Material names with terminal controls (ESC, BEL, a newline), a C1
// control (U+0085) and a bidirectional override (U+202E) are printed by
// the plan as escapes, never raw.
TEST(SceneTest, PlanPrintsControlCharactersAsEscapes) {
  const std::string dir = Scratch("controls");
  const std::string path = dir + "/names.toml";
  WriteText(path,
            "[[material]]\nname = \"a\\u001b[31mred\\u0007\"\nmodel = \"ggx\"\nroughness = 0.5\n"
            "[[material]]\nname = \"b\\nc\\u0085d\\u202ee\"\nmodel = \"ggx\"\nroughness = 0.3\n");
  const Scene scene = LoadScene(path);
  ASSERT_EQ(scene.materials.size(), 2u);
  const std::string text = PlanText(scene, PlanScene(scene));
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    ASSERT_TRUE(c == '\n' || (c >= 0x20 && c != 0x7f)) << "raw control " << int(c) << " in\n" << text;
  }
  EXPECT_EQ(text.find("\xc2\x85"), std::string::npos) << text;
  EXPECT_EQ(text.find("\xe2\x80\xae"), std::string::npos) << text;
  EXPECT_NE(text.find("a\\x1b[31mred\\x07"), std::string::npos) << text;
  EXPECT_NE(text.find("b\\nc\\u{0085}d\\u{202e}e"), std::string::npos) << text;
}

// Seeded mutations of the example scenes: every load either succeeds with
// valid materials or throws one line naming the file.
TEST(SceneTest, FuzzedScenesNeverCrash) {
  const std::string dir = Scratch("fuzz");
  const std::string toml = Slurp(kExamples + "/scene.toml");
  const std::string gltf = Slurp(kExamples + "/scene.gltf");
  std::mt19937_64 rng(2026);
  const std::vector<std::string> tokens = {"\"\"", "-1", "1e400", "nan", "[", "]", "{", "}", "=", "\"x\"",
                                           "true", "[0.5, 0.1]", "\n", "\"inf\"", "0x10", ",", ":", "null",
                                           // Type confusion and bytes parsers trip on.
                                           "NaN", "Infinity", "-0.0", "1e-400", "18446744073709551616",
                                           "{\"a\":1,\"a\":2}", "a.b.c", "\xff\xfe", "\"\\u0000\"",
                                           "\"roughness\" = \"0.5\"", "{\"index\":-1}"};
  int ok = 0, rejected = 0;
  for (int run = 0; run < 300; ++run) {
    const bool is_toml = run % 3 != 0;
    std::string text = is_toml ? toml : gltf;
    const int edits = 1 + int(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text.erase(at, 1 + rng() % 12); break;
        case 1: text.insert(at, tokens[rng() % tokens.size()]); break;
        default: text = text.substr(0, at); break;
      }
      if (text.empty()) text = "x";
    }
    const std::string path = dir + "/f" + std::to_string(run) + (is_toml ? ".toml" : ".gltf");
    WriteText(path, text);
    try {
      const Scene s = LoadScene(path);
      ASSERT_FALSE(s.materials.empty());
      for (const SceneMaterial& m : s.materials) {
        ASSERT_TRUE(m.roughness_min >= 0 && m.roughness_min <= m.roughness_max && m.roughness_max <= 1) << path;
        ASSERT_TRUE(m.sheen_roughness_min >= 0 && m.sheen_roughness_min <= m.sheen_roughness_max &&
                    m.sheen_roughness_max <= 1)
            << path;
        ASSERT_FALSE(m.name.empty());
      }
      ++ok;
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      ASSERT_EQ(msg.rfind(path, 0), 0u) << msg;
      ASSERT_EQ(msg.find('\n'), std::string::npos) << msg;
      ++rejected;
    }
  }
  std::printf("300 mutated scenes: %d loaded, %d rejected with a one-line error\n", ok, rejected);
  EXPECT_GT(ok, 10);
  EXPECT_GT(rejected, 100);
}

}  // namespace
}  // namespace brdfbake
