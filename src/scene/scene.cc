// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scene files (TOML and glTF 2.0), plans and scene bakes (scene.h). The
// TOML schema is documented in examples/README.md.

#include "brdfbake/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <vector>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <toml++/toml.h>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/exr.h"
#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/output_file.h"
#include "brdfbake/version.h"

namespace brdfbake {
namespace {

std::string Num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.4g", v);
  return buf;
}

// Typed fields of a TOML table, each error naming the file, the place and
// the field.
struct Fields {
  const toml::table& t;
  std::string where;  // "scene.toml: material 'steel'"

  [[noreturn]] void Fail(const std::string& field, const std::string& what) const {
    Bad(where + ": field '" + field + "': " + what);
  }
  void OnlyKnown(const std::vector<std::string>& known) const {
    for (const auto& kv : t) {
      const std::string key(kv.first.str());
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        Fail(Excerpt(key), "unknown field (expected one of " + list + ")");
      }
    }
  }
  bool Has(const std::string& f) const { return t.contains(f); }
  std::string String(const std::string& f, const std::string& fallback, bool required = false) const {
    const toml::node* n = t.get(f);
    if (!n) {
      if (required) Fail(f, "missing (a string is required)");
      return fallback;
    }
    if (!n->is_string()) Fail(f, "expected a string");
    return std::string(**n->as_string());
  }
  double Number(const std::string& f, double fallback, double lo, double hi, bool required = false) const {
    const toml::node* n = t.get(f);
    if (!n) {
      if (required) Fail(f, "missing (a number is required)");
      return fallback;
    }
    double v;
    if (n->is_floating_point()) {
      v = **n->as_floating_point();
    } else if (n->is_integer()) {
      v = double(**n->as_integer());
    } else {
      Fail(f, "expected a number");
    }
    if (!(v >= lo && v <= hi)) Fail(f, ExactText(v) + " is outside [" + Num(lo) + ", " + Num(hi) + "]");
    return v == 0 ? 0.0 : v;  // -0 as 0
  }
  bool Bool(const std::string& f, bool fallback) const {
    const toml::node* n = t.get(f);
    if (!n) return fallback;
    if (!n->is_boolean()) Fail(f, "expected true or false");
    return **n->as_boolean();
  }
  std::vector<std::string> Strings(const std::string& f, const std::vector<std::string>& fallback) const {
    const toml::node* n = t.get(f);
    if (!n) return fallback;
    if (!n->is_array()) Fail(f, "expected an array of strings");
    std::vector<std::string> out;
    for (const toml::node& e : *n->as_array()) {
      if (!e.is_string()) Fail(f, "expected an array of strings");
      out.emplace_back(**e.as_string());
    }
    return out;
  }
};

Masking MaskingOf(const Fields& f) {
  const std::string m = f.String("masking", "height-correlated");
  if (m == "height-correlated") return Masking::kHeightCorrelated;
  if (m == "separable") return Masking::kSeparable;
  f.Fail("masking", "'" + Excerpt(m) + "' is not height-correlated or separable");
}

std::string ReadBytes(const std::string& path, size_t limit = std::string::npos);

// toml++ bounds the nesting of values (arrays, inline tables) at 256 levels,
// but not of dotted keys: a table header [a.a.a...] of 100,000 parts
// overflows its recursion. A scene needs two levels; a key of more than
// kMaxTomlKeyParts parts is refused before parsing. The dots are counted
// outside strings and comments, in runs that [ ] { } = , and line ends
// close (so a value's decimal point counts alone).
constexpr int kMaxTomlKeyParts = 64;

void CheckTomlKeyDepth(const std::string& path, const std::string& text) {
  int dots = 0, line = 1;
  const size_t n = text.size();
  for (size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      // A string: basic ("...", escapes) or literal ('...'), single-line
      // or multi-line (three quotes).
      const bool basic = c == '"';
      const bool multi = text.compare(i, 3, std::string(3, c)) == 0;
      i += multi ? 3 : 1;
      for (; i < n; ++i) {
        if (text[i] == '\n') {
          ++line;
          if (!multi) break;  // unterminated: the parser reports it
        } else if (basic && text[i] == '\\') {
          if (i + 1 < n && text[i + 1] == '\n') ++line;
          ++i;
        } else if (text[i] == c && (!multi || text.compare(i, 3, std::string(3, c)) == 0)) {
          if (multi) i += 2;
          break;
        }
      }
    } else if (c == '#') {
      while (i + 1 < n && text[i + 1] != '\n') ++i;
    } else if (c == '.') {
      if (++dots >= kMaxTomlKeyParts) {
        Bad(path + ":" + std::to_string(line) + ": a key of more than " +
            std::to_string(kMaxTomlKeyParts) + " dotted parts (a scene needs two)");
      }
    } else if (c == '\n' || c == '[' || c == ']' || c == '{' || c == '}' || c == '=' || c == ',') {
      if (c == '\n') ++line;
      dots = 0;
    }
  }
}

Scene LoadToml(const std::string& path) {
  const std::string text = ReadBytes(path);
  CheckTomlKeyDepth(path, text);
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << path << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    Bad(os.str());
  }
  Scene s;
  s.path = path;
  for (const auto& kv : root) {
    const std::string key(kv.first.str());
    if (key != "engine" && key != "material") {
      Bad(path + ": unknown section '" + Excerpt(key) + "' (expected [engine] and [[material]])");
    }
  }
  if (const toml::node* e = root.get("engine")) {
    if (!e->is_table()) Bad(path + ": 'engine' must be a table ([engine])");
    const Fields f{*e->as_table(), path + ": [engine]"};
    f.OnlyKnown({"max_lut_size", "pixel", "placement", "error_target", "complement", "tables", "header", "shaders"});
    const double lut = f.Number("max_lut_size", 64, 2, 8192);
    if (lut != std::floor(lut)) f.Fail("max_lut_size", ExactText(lut) + " is not an integer");
    s.engine.max_lut_size = int(lut);
    const std::string pixel = f.String("pixel", "half");
    if (pixel != "half" && pixel != "float") f.Fail("pixel", "'" + Excerpt(pixel) + "' is not half or float");
    s.engine.pixel = pixel == "half" ? PixelType::kHalf : PixelType::kFloat;
    const std::string pl = f.String("placement", "centers");
    if (pl != "centers" && pl != "edges") f.Fail("placement", "'" + Excerpt(pl) + "' is not centers or edges");
    s.engine.placement = pl == "centers" ? Placement::kCenters : Placement::kEdges;
    s.engine.error_target = f.Number("error_target", 2e-3, 1e-7, 1.0);
    s.engine.complement = f.Bool("complement", false);
    s.engine.header = f.Bool("header", false);
    s.engine.tables.clear();
    for (const std::string& t : f.Strings("tables", {"dfg", "E", "E_avg"})) {
      if (t == "E") s.engine.tables.push_back(TableKind::kE);
      else if (t == "E_avg") s.engine.tables.push_back(TableKind::kEavg);
      else if (t == "dfg") s.engine.tables.push_back(TableKind::kDfg);
      else f.Fail("tables", "'" + Excerpt(t) + "' is not E, E_avg or dfg");
    }
    for (const std::string& l : f.Strings("shaders", {})) {
      if (l != "glsl" && l != "hlsl" && l != "wgsl") {
        f.Fail("shaders", "'" + Excerpt(l) + "' is not glsl, hlsl or wgsl");
      }
      s.engine.shaders.push_back(ParseShaderLanguage(l));
    }
  }
  const toml::node* mats = root.get("material");
  if (!mats) Bad(path + ": no [[material]] entries");
  if (!mats->is_array_of_tables()) Bad(path + ": 'material' must be an array of tables ([[material]])");
  int index = 0;
  std::set<std::string> names;  // each name once (a set: 100k materials load in well under a second)
  for (const toml::node& m : *mats->as_array()) {
    ++index;
    const toml::table& mt = *m.as_table();
    std::string name = "#" + std::to_string(index);
    if (const toml::node* n = mt.get("name"); n && n->is_string()) name = std::string(**n->as_string());
    const Fields f{mt, path + ": material '" + Excerpt(name) + "'"};
    f.OnlyKnown({"name", "model", "roughness", "gamma", "anisotropy", "masking"});
    SceneMaterial mat;
    mat.name = f.String("name", "", true);
    if (mat.name.empty()) f.Fail("name", "must not be empty");
    if (!names.insert(mat.name).second) f.Fail("name", "another material has this name");
    mat.source = "toml";
    const std::string model = f.String("model", "", true);
    if (model != "ggx" && model != "beckmann" && model != "std" && model != "ggx-aniso") {
      f.Fail("model", "'" + Excerpt(model) + "' is not ggx, beckmann, std or ggx-aniso");
    }
    mat.model = ParseModelKind(model);
    if (!ModelBuilt(mat.model)) f.Fail("model", "'" + model + "' is not in this build (BRDFBAKE_MODELS)");
    const toml::node* r = mt.get("roughness");
    if (!r) f.Fail("roughness", "missing (a number in [0, 1] or a range [min, max])");
    if (r->is_array()) {
      const toml::array& a = *r->as_array();
      if (a.size() != 2 || !a[0].is_number() || !a[1].is_number()) {
        f.Fail("roughness", "a range is two numbers [min, max]");
      }
      mat.roughness_min = a[0].value<double>().value() + 0.0;  // -0 as 0
      mat.roughness_max = a[1].value<double>().value() + 0.0;
      if (!(mat.roughness_min >= 0 && mat.roughness_min <= mat.roughness_max && mat.roughness_max <= 1)) {
        f.Fail("roughness", "the range must satisfy 0 <= min <= max <= 1");
      }
    } else {
      mat.roughness_min = mat.roughness_max = f.Number("roughness", 0.5, 0, 1, true);
    }
    if (mat.model == ModelKind::kStudentT) {
      const toml::node* g = mt.get("gamma");
      if (!g) f.Fail("gamma", "missing (std needs gamma in [1.500001, inf], or \"inf\")");
      if (g->is_string() && **g->as_string() == "inf") {
        mat.gamma = std::numeric_limits<double>::infinity();
      } else if (g->is_floating_point()) {
        mat.gamma = **g->as_floating_point();  // TOML's inf too
      } else if (g->is_integer()) {
        mat.gamma = double(**g->as_integer());
      } else {
        f.Fail("gamma", "expected a number or \"inf\"");
      }
      if (!StudentTGammaAllowed(mat.gamma)) f.Fail("gamma", StudentTGammaDomain(mat.gamma));
    } else if (f.Has("gamma")) {
      f.Fail("gamma", "only std has gamma");
    }
    if (mat.model == ModelKind::kGgxAniso) {
      mat.anisotropy = f.Number("anisotropy", 0, 0, 1, true);
    } else if (f.Has("anisotropy")) {
      f.Fail("anisotropy", "only ggx-aniso has an anisotropy");
    }
    mat.masking = MaskingOf(f);
    s.materials.push_back(mat);
  }
  if (s.materials.empty()) Bad(path + ": no [[material]] entries");
  return s;
}

// glTF 2.0 is read for its materials alone: the JSON of a .gltf file, or
// the JSON chunk of a .glb container. The scene file is the one file
// opened: buffers, images and every other URI are never read, so a scene
// from anywhere cannot make the tool read, block on or reveal another file.

constexpr int kMaxJsonDepth = 512;  // far beyond any real glTF file

[[noreturn]] void NotGltf(const std::string& path, const std::string& why) {
  Bad(path + ": not a valid glTF 2.0 file: " + why);
}

// The bytes of `path`, or of its first `limit` bytes.
std::string ReadBytes(const std::string& path, size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) Bad(path + ": cannot be read");
  std::string bytes;
  if (limit == std::string::npos) {
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } else {
    bytes.resize(limit);
    in.read(bytes.data(), static_cast<std::streamsize>(limit));
    bytes.resize(static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) Bad(path + ": read error");
  return bytes;
}

uint32_t Le32(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 |
         uint32_t(uint8_t(b[at + 2])) << 16 | uint32_t(uint8_t(b[at + 3])) << 24;
}

// The JSON chunk of a .glb file (glTF 2.0 section 4.4: a 12-byte header,
// then chunks of length, type and data; the first chunk is the JSON).
std::string GlbJson(const std::string& path) {
  const std::string head = ReadBytes(path, 20);
  if (head.size() < 20) NotGltf(path, "shorter than a GLB header");
  if (Le32(head, 0) != 0x46546C67u) NotGltf(path, "no GLB magic 'glTF'");
  if (Le32(head, 4) != 2) NotGltf(path, "GLB version " + std::to_string(Le32(head, 4)) + ", not 2");
  const uint32_t length = Le32(head, 8), chunk = Le32(head, 12);
  if (Le32(head, 16) != 0x4E4F534Au) NotGltf(path, "the first GLB chunk is not JSON");
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || length > size || uint64_t(chunk) + 20 > length) {
    NotGltf(path, "the GLB lengths exceed the file");
  }
  const std::string bytes = ReadBytes(path, 20 + size_t(chunk));
  if (bytes.size() != 20 + size_t(chunk)) NotGltf(path, "the JSON chunk is cut short");
  return bytes.substr(20);
}

// Refuses JSON nested deeper than kMaxJsonDepth before it is parsed.
void CheckJsonDepth(const std::string& path, const std::string& text) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        NotGltf(path, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// The JSON type of v, for messages.
std::string JsonType(const nlohmann::json& v) { return v.type_name(); }

// A SAX pass that stops at the first key an object has twice. A JSON
// parser keeps one of the two (nlohmann-json the last, others the first),
// so which value a scene means is not defined; it is refused instead.
struct DuplicateKeys {
  using json = nlohmann::json;
  std::vector<std::set<std::string>> objects;  // the keys of each open object
  std::string duplicate;

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t) { return true; }
  bool number_float(json::number_float_t, const json::string_t&) { return true; }
  bool string(json::string_t&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool start_object(size_t) {
    objects.emplace_back();
    return true;
  }
  bool key(json::string_t& k) {
    if (objects.back().insert(k).second) return true;
    duplicate = k;
    return false;
  }
  bool end_object() {
    objects.pop_back();
    return true;
  }
  bool start_array(size_t) { return true; }
  bool end_array() { return true; }
  bool parse_error(size_t, const std::string&, const nlohmann::detail::exception&) { return false; }
};

Scene LoadGltf(const std::string& path) {
  const bool binary = Lowercase(std::filesystem::path(path).extension().string()) == ".glb";
  const std::string text = binary ? GlbJson(path) : ReadBytes(path);
  CheckJsonDepth(path, text);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    NotGltf(path, std::string("invalid JSON: ") + e.what());
  }
  DuplicateKeys keys;
  nlohmann::json::sax_parse(text, &keys);
  if (!keys.duplicate.empty()) {
    NotGltf(path, "the key '" + Excerpt(keys.duplicate) + "' appears twice in one object");
  }
  if (!doc.is_object()) NotGltf(path, "the top level is a " + JsonType(doc) + ", not an object");
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) NotGltf(path, "no 'asset' object");
  const auto version = asset->find("version");
  if (version == asset->end() || !version->is_string()) NotGltf(path, "no 'asset.version' string");
  const std::string v = version->get<std::string>();
  if (v.rfind("2.", 0) != 0) NotGltf(path, "asset.version is '" + Excerpt(v) + "', not 2.x");
  const auto materials = doc.find("materials");
  if (materials == doc.end()) Bad(path + ": the glTF file has no materials");
  if (!materials->is_array()) NotGltf(path, "'materials' is a " + JsonType(*materials) + ", not an array");

  Scene s;
  s.path = path;
  for (size_t i = 0; i < materials->size(); ++i) {
    const nlohmann::json& m = (*materials)[i];
    const std::string at = path + ": materials[" + std::to_string(i) + "]";
    if (!m.is_object()) Bad(at + ": a " + JsonType(m) + ", not an object");
    SceneMaterial mat;
    const auto name = m.find("name");
    if (name != m.end() && !name->is_string()) Bad(at + ": field 'name': expected a string");
    mat.name = name != m.end() && !name->get<std::string>().empty() ? name->get<std::string>()
                                                                       : "material " + std::to_string(i);
    mat.source = "glTF material " + std::to_string(i);
    const std::string where = path + ": material '" + Excerpt(mat.name) + "'";
    // A number field of an object, `fallback` when absent.
    const auto number = [&](const nlohmann::json& obj, const char* key, const std::string& field,
                            double fallback) {
      const auto it = obj.find(key);
      if (it == obj.end()) return fallback;
      if (!it->is_number()) Bad(where + ": field '" + field + "': expected a number, got a " + JsonType(*it));
      return it->get<double>();
    };
    double factor = 1.0;
    bool textured = false;
    const auto pbr = m.find("pbrMetallicRoughness");
    if (pbr != m.end()) {
      if (!pbr->is_object()) Bad(where + ": field 'pbrMetallicRoughness': expected an object");
      factor = number(*pbr, "roughnessFactor", "pbrMetallicRoughness.roughnessFactor", 1.0);
      const auto tex = pbr->find("metallicRoughnessTexture");
      if (tex != pbr->end()) {
        const auto index = tex->is_object() ? tex->find("index") : tex->end();
        if (!tex->is_object() || index == tex->end() || !index->is_number_unsigned()) {
          Bad(where + ": field 'pbrMetallicRoughness.metallicRoughnessTexture': expected an object "
                      "with an integer 'index' >= 0");
        }
        // The texture is never read, but the index must name one.
        const auto textures = doc.find("textures");
        const uint64_t count = textures != doc.end() && textures->is_array() ? textures->size() : 0;
        if (index->get<uint64_t>() >= count) {
          Bad(where + ": field 'pbrMetallicRoughness.metallicRoughnessTexture.index': " +
              std::to_string(index->get<uint64_t>()) + " names no texture (the file has " +
              std::to_string(count) + ")");
        }
        textured = true;
      }
    }
    factor += 0.0;  // -0 as 0
    if (!(factor >= 0 && factor <= 1)) {
      Bad(where + ": field 'pbrMetallicRoughness.roughnessFactor': " + ExactText(factor) + " is outside [0, 1]");
    }
    // A metallic-roughness texture multiplies the factor: any roughness in [0, factor].
    mat.roughness_min = textured ? 0.0 : factor;
    mat.roughness_max = factor;
    const auto extensions = m.find("extensions");
    if (extensions != m.end() && !extensions->is_object()) {
      Bad(where + ": field 'extensions': expected an object");
    }
    const nlohmann::json none = nlohmann::json::object();
    for (const auto& item : (extensions != m.end() ? *extensions : none).items()) {
      const std::string& name_ext = item.key();
      const nlohmann::json& ext = item.value();
      if (!ext.is_object()) {
        Bad(where + ": field 'extensions." + Excerpt(name_ext) + "': expected an object");
      }
      if (name_ext == "KHR_materials_anisotropy") {
        const double strength = number(ext, "anisotropyStrength", "KHR_materials_anisotropy.anisotropyStrength", 0.0);
        if (!(strength >= 0 && strength <= 1)) {
          Bad(where + ": field 'KHR_materials_anisotropy.anisotropyStrength': " + ExactText(strength) + " is outside [0, 1]");
        }
        if (strength > 0) {
          mat.model = ModelKind::kGgxAniso;
          mat.anisotropy = strength;
        }
      } else if (name_ext == "KHR_materials_ior" || name_ext == "KHR_materials_specular") {
        // The F0 and F90 these set weight the split-sum terms: dfg covers them.
      } else if (name_ext == "KHR_materials_transmission") {
        mat.unsupported.push_back({name_ext, "a transmission (BTDF) albedo table over roughness and IOR"});
      } else if (name_ext == "KHR_materials_sheen") {
        mat.unsupported.push_back({name_ext, "a sheen (Charlie NDF) albedo table over roughness"});
      } else if (name_ext == "KHR_materials_clearcoat") {
        mat.unsupported.push_back({name_ext, "the clearcoat layer's GGX tables at its own roughness (not planned yet)"});
      } else {
        mat.unsupported.push_back({name_ext, "an extension brdfbake does not know"});
      }
    }
    s.materials.push_back(mat);
  }
  if (s.materials.empty()) Bad(path + ": the glTF file has no materials");
  return s;
}

std::string GroupKey(const SceneMaterial& m) {
  std::string k = ModelName(m.model);
  if (m.model == ModelKind::kStudentT) k += std::isinf(m.gamma) ? "_ginf" : "_g" + Num(m.gamma);
  if (m.masking == Masking::kSeparable) k += "_separable";
  return k;
}

// The exact values a table's channels hold at (mu, r), in channel order.
std::vector<double> ExactAt(const Table& t, double mu, double r) {
  const BakeSpec& s = t.spec;
  std::vector<double> out;
  if (s.table == TableKind::kEavg) {
    BakeSpec e = s;
    e.table = TableKind::kE;
    const double v = std::clamp(IntegrateEavg(e, std::max(r, s.roughness.clamp_min)).value, 0.0, 1.0);
    out.push_back(s.complement ? 1 - v : v);
    return out;
  }
  const TexelEstimate v = ClampToRange(IntegrateTexel(s, std::max(r, s.roughness.clamp_min), std::max(mu, s.mu.clamp_min)));
  if (s.table == TableKind::kE) {
    out.push_back(s.complement ? 1 - v.e : v.e);
  } else {
    out.push_back(v.scale);
    out.push_back(v.bias);
    if (s.complement) out.push_back(1 - v.e);
  }
  return out;
}

}  // namespace

Scene LoadScene(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) Bad(path + ": no such scene file");
  const std::string ext = Lowercase(std::filesystem::path(path).extension().string());
  if (ext == ".toml") return LoadToml(path);
  if (ext == ".gltf" || ext == ".glb") return LoadGltf(path);
  Bad(path + ": a scene is a .toml, .gltf or .glb file");
}

double InterpolationError(const Table& t, int probes) {
  const bool eavg = t.spec.table == TableKind::kEavg;
  const Axis& am = t.spec.mu;
  const Axis& ar = t.spec.roughness;
  const int nm = eavg ? 1 : am.size, nr = ar.size;
  // Probe positions in fractional texel index: the midpoint of (up to
  // `probes`) cells; for centres placement the two ends of the axis, where
  // a GPU's clamp-to-edge holds the last texel's value; and along mu, more
  // points in the first two cells and below texel 0, where E's grazing
  // boundary layer (E -> 1 as mu -> 0) is narrower than a cell.
  auto positions = [&](const Axis& a, int n, bool grazing) {
    std::vector<double> f;
    if (n == 1) return std::vector<double>{0.0};
    const int cells = n - 1, k = std::min(cells, probes);
    for (int i = 0; i < k; ++i) f.push_back(i * cells / k + 0.5);
    if (a.placement == Placement::kCenters) {
      f.push_back(-0.5);
      f.push_back(n - 0.5);
    }
    if (grazing) {
      for (double x : {0.05, 0.1, 0.2, 0.3, 0.7, 0.9}) f.push_back(x);
      if (cells > 1) {
        for (double x : {1.1, 1.25, 1.75, 1.9}) f.push_back(x);
      }
      if (a.placement == Placement::kCenters) {
        for (double x : {-0.45, -0.4, -0.3, -0.2, -0.1}) f.push_back(x);
      }
    }
    return f;
  };
  // The fractional texel index of value v on axis a (Axis::ValueAt
  // inverted), for the points where a table is not smooth.
  auto index_of = [](const Axis& a, int n, double v) {
    double t = std::clamp((v - a.min) / (a.max - a.min), 0.0, 1.0);
    if (a.warp == Warp::kSquare) t = std::sqrt(t);
    if (a.warp == Warp::kSqrt) t = t * t;
    return a.placement == Placement::kCenters ? t * n - 0.5 : t * (n - 1);
  };
  std::vector<double> fm = positions(am, nm, true), fr = positions(ar, nr, false);
  // The grazing layer down to the smallest NoV engines clamp to (1e-4).
  if (nm > 1) {
    for (double mu : {1e-4, 1e-3, 1e-2}) {
      if (mu > am.min && mu < am.max) fm.push_back(index_of(am, nm, mu));
    }
  }
  // Each side of the mirror cut (alpha = kMinAlpha: E jumps to 1), where
  // the roughness axis crosses it.
  const double cut = std::sqrt(kMinAlpha<double>);
  if (nr > 1 && cut > ar.min && cut < ar.max) {
    for (double r : {cut * (1 - 1e-9), cut, cut * (1 + 1e-6), cut * 1.01}) fr.push_back(index_of(ar, nr, r));
  }
  if (fm.size() == 1 && fr.size() == 1) return 0;
  const size_t nvalue = eavg || t.spec.table == TableKind::kE ? 1 : (t.spec.complement ? 3 : 2);
  std::vector<double> worst(fm.size() * fr.size(), 0.0);
  // Bilinear weights along one axis at fractional index f, clamped to the ends.
  auto taps = [](double f, int n, int* i0, int* i1, double* w) {
    const double c = std::clamp(f, 0.0, double(n - 1));
    *i0 = std::min(int(std::floor(c)), std::max(0, n - 2));
    *i1 = std::min(*i0 + 1, n - 1);
    *w = c - *i0;
  };
  tbb::parallel_for(size_t(0), worst.size(), [&](size_t k) {
    const double f_m = fm[k % fm.size()], f_r = fr[k / fm.size()];
    const double mu = nm > 1 ? am.ValueAt(f_m) : am.Value(0);
    const double r = nr > 1 ? ar.ValueAt(f_r) : ar.Value(0);
    const std::vector<double> exact = ExactAt(t, mu, r);
    int m0, m1, r0, r1;
    double wm, wr;
    taps(f_m, nm, &m0, &m1, &wm);
    taps(f_r, nr, &r0, &r1, &wr);
    for (size_t c = 0; c < nvalue; ++c) {
      const std::vector<float>& v = t.channels[c].stored;
      // E_avg is one row over roughness (x); the others x = mu, y = roughness.
      auto at = [&](int i, int j) { return double(eavg ? v[size_t(j)] : v[size_t(j) * t.width + i]); };
      const double interp = (1 - wr) * ((1 - wm) * at(m0, r0) + wm * at(m1, r0)) +
                            wr * ((1 - wm) * at(m0, r1) + wm * at(m1, r1));
      worst[k] = std::max(worst[k], std::abs(interp - exact[c]));
    }
  });
  return *std::max_element(worst.begin(), worst.end());
}

namespace {

// The EXR file of a planned table: the table and the material group.
std::string TableFile(TableKind kind, const std::string& group) {
  return std::string(TableName(kind)) + "_" + group + ".exr";
}

// Every file written for tables `table_files` into dir: each table's EXR,
// its header and shader files as the engine asks, then the manifest.
std::vector<std::string> FilesOf(const Scene& scene, const std::vector<std::string>& table_files,
                                 const std::string& dir) {
  std::vector<std::string> files;
  for (const std::string& f : table_files) {
    const std::string stem = f.substr(0, f.size() - 4);
    files.push_back(dir + "/" + f);
    if (scene.engine.header) files.push_back(dir + "/" + stem + ".h");
    for (ShaderLanguage l : scene.engine.shaders) files.push_back(dir + "/" + stem + "." + ShaderLanguageName(l));
  }
  files.push_back(dir + "/manifest.json");
  return files;
}

}  // namespace

std::vector<std::string> SceneOutputFiles(const Scene& scene, const std::string& dir) {
  std::set<std::string> groups;
  for (const SceneMaterial& m : scene.materials) {
    if (m.model != ModelKind::kGgxAniso) groups.insert(GroupKey(m));
  }
  std::vector<std::string> tables;
  for (const std::string& g : groups) {
    for (const TableKind kind : scene.engine.tables) tables.push_back(TableFile(kind, g));
  }
  return FilesOf(scene, tables, dir);
}

ScenePlan PlanScene(const Scene& scene, const std::function<void(const std::string&)>& progress) {
  ScenePlan plan;
  std::map<std::string, std::vector<const SceneMaterial*>> groups;
  for (const SceneMaterial& m : scene.materials) {
    for (const auto& u : m.unsupported) {
      plan.notes.push_back("material '" + Printable(m.name) + "' (" + u.first + "): needs " + u.second +
                           ", which brdfbake does not bake yet");
    }
    if (m.model == ModelKind::kGgxAniso) {
      plan.notes.push_back("material '" + Printable(m.name) + "' (anisotropic GGX, strength " + Num(m.anisotropy) +
                           "): needs E(mu, phi, r, s) tables, which brdfbake does not bake yet; no table planned");
      continue;
    }
    groups[GroupKey(m)].push_back(&m);
  }
  for (const auto& g : groups) {
    const SceneMaterial& first = *g.second.front();
    double rmin = 1, rmax = 0;
    std::vector<std::string> names;
    for (const SceneMaterial* m : g.second) {
      rmin = std::min(rmin, m->roughness_min);
      rmax = std::max(rmax, m->roughness_max);
      names.push_back(m->name);
    }
    for (const TableKind kind : scene.engine.tables) {
      BakeSpec base;
      base.table = kind;
      base.model.kind = first.model;
      base.model.gamma = first.model == ModelKind::kStudentT ? first.gamma : 2.0;
      base.masking = first.masking;
      base.half = scene.engine.pixel == PixelType::kHalf;
      base.complement = scene.engine.complement && kind != TableKind::kDfg;
      base.mu.placement = base.roughness.placement = scene.engine.placement;
      base.roughness.min = rmin;
      base.roughness.max = rmax;
      const bool one_r = rmin == rmax;
      PlannedTable best;
      best.total_error = std::numeric_limits<double>::infinity();
      bool done = false;
      for (int n = 2; n <= scene.engine.max_lut_size && !done; n *= 2) {
        for (const Warp warp : {Warp::kLinear, Warp::kSquare}) {
          if (kind == TableKind::kEavg && warp != Warp::kLinear) continue;
          BakeSpec spec = base;
          spec.mu.size = n;
          spec.mu.warp = warp;
          spec.roughness.size = one_r ? 1 : n;
          if (one_r) spec.roughness.placement = Placement::kCenters;
          if (kind == TableKind::kEavg && one_r) spec.roughness.size = 1;
          PlannedTable p;
          p.spec = spec;
          p.table = Bake(spec);
          p.interpolation_error = InterpolationError(p.table);
          p.total_error = p.interpolation_error + p.table.integration_error;
          if (progress) {
            progress(std::string(TableName(kind)) + " " + g.first + " " + std::to_string(p.table.width) + "x" +
                     std::to_string(p.table.height) + " mu " + WarpName(warp) + ": lookup error " +
                     Num(p.total_error));
          }
          const bool meets = p.total_error <= scene.engine.error_target;
          if (meets || p.total_error < best.total_error) {
            p.meets_target = meets;
            best = std::move(p);
          }
          if (meets) {
            done = true;
            break;
          }
          if (kind == TableKind::kEavg && one_r) {
            done = true;  // one value: nothing to refine
            break;
          }
        }
      }
      best.materials = names;
      best.file = TableFile(kind, g.first);
      best.why = "used by " + std::to_string(names.size()) + " material" + (names.size() > 1 ? "s" : "") +
                 " with model " + g.first + ", roughness " +
                 (one_r ? Num(rmin) : "[" + Num(rmin) + ", " + Num(rmax) + "]");
      plan.tables.push_back(std::move(best));
    }
  }
  return plan;
}

std::string PlanText(const Scene& scene, const ScenePlan& plan) {
  std::ostringstream os;
  const SceneEngine& e = scene.engine;
  os << "scene " << Printable(scene.path) << ": " << scene.materials.size() << " material"
     << (scene.materials.size() == 1 ? "" : "s") << "; engine: max LUT " << e.max_lut_size << ", "
     << PixelTypeName(e.pixel) << ", " << PlacementName(e.placement) << ", error target " << Num(e.error_target)
     << (e.complement ? ", complement" : "") << "\n";
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    const PlannedTable& p = plan.tables[i];
    const Table& t = p.table;
    os << "table " << i + 1 << ": " << p.file << " (" << TableName(p.spec.table) << ", " << MaskingName(p.spec.masking)
       << "), " << p.why << "\n";
    os << "  materials:";
    for (const std::string& m : p.materials) os << " " << Printable(m);
    os << "\n  axes:";
    for (const Axis& a : t.axes) {
      os << " " << a.name << " " << a.size << " in [" << Num(a.min) << ", " << Num(a.max) << "] " << WarpName(a.warp)
         << " " << PlacementName(a.placement) << ";";
    }
    os << "\n  bilinear lookup error " << Num(p.total_error) << " (interpolation at cell midpoints and axis ends "
       << Num(p.interpolation_error) << ", integration " << Num(t.integration_error) << ") "
       << (p.meets_target ? "<= target " : "ABOVE the target ") << Num(e.error_target)
       << (p.meets_target ? "" : " (the largest size allowed)") << "\n";
  }
  for (const std::string& n : plan.notes) os << "not baked: " << n << "\n";
  return os.str();
}

std::vector<std::string> WriteScenePlan(const Scene& scene, const ScenePlan& plan, const std::string& dir) {
  std::vector<std::string> table_files;
  for (const PlannedTable& p : plan.tables) table_files.push_back(p.file);
  const std::vector<std::string> files = FilesOf(scene, table_files, dir);
  for (const std::string& f : files) CheckOutputPath(f);
  auto stem = [](const std::string& f) { return f.substr(0, f.size() - 4); };
  nlohmann::json manifest;
  manifest["brdfbake"] = BRDFBAKE_VERSION;
  manifest["scene"] = scene.path;
  manifest["engine"] = {{"max_lut_size", scene.engine.max_lut_size},
                        {"pixel", PixelTypeName(scene.engine.pixel)},
                        {"placement", PlacementName(scene.engine.placement)},
                        {"error_target", scene.engine.error_target},
                        {"complement", scene.engine.complement}};
  manifest["tables"] = nlohmann::json::array();
  for (const PlannedTable& p : plan.tables) {
    WriteExr(p.table, dir + "/" + p.file);
    nlohmann::json extra = nlohmann::json::array();
    const Image im = ArrangeTable(p.table, DefaultLayout(p.table));
    const std::string symbol = "brdfbake_" + stem(p.file);
    if (scene.engine.header) {
      WriteImage(p.table, im, Container::kHeader, dir + "/" + stem(p.file) + ".h", symbol, "");
      extra.push_back(stem(p.file) + ".h");
    }
    for (ShaderLanguage l : scene.engine.shaders) {
      const std::string f = stem(p.file) + "." + ShaderLanguageName(l);
      WriteFileAtomically(dir + "/" + f, ShaderFunction(p.table, im, l, symbol));
      extra.push_back(f);
    }
    nlohmann::json axes = nlohmann::json::array();
    for (const Axis& a : p.table.axes) axes.push_back(nlohmann::json::parse(a.ToJson()));
    manifest["tables"].push_back({{"file", p.file},
                                  {"table", TableName(p.spec.table)},
                                  {"model", nlohmann::json::parse(p.table.model_json)},
                                  {"masking", MaskingName(p.spec.masking)},
                                  {"materials", p.materials},
                                  {"why", p.why},
                                  {"axes", axes},
                                  {"seconds", p.table.seconds},
                                  {"max_abs_error", p.table.max_abs_error},
                                  {"interpolation_error", p.interpolation_error},
                                  {"lookup_error", p.total_error},
                                  {"meets_target", p.meets_target},
                                  {"also", extra}});
  }
  manifest["not_baked"] = plan.notes;
  WriteFileAtomically(dir + "/manifest.json", manifest.dump(2) + "\n");
  return files;
}

}  // namespace brdfbake
