// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scene files (TOML and glTF 2.0), plans and scene bakes (scene.h). The
// TOML schema is documented in examples/README.md.

#include "brdfbake/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <vector>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/exr.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/output_file.h"
#include "brdfbake/outputs.h"
#include "brdfbake/probe.h"
#include "brdfbake/report.h"
#include "brdfbake/version.h"
#include "rules/ggx_aniso/aniso_ggx.h"

namespace brdfbake {
namespace {

// The tables a preset's engine samples, each once: "E, E_avg, ggx-glass
// E, ..." (another model than GGX named before its table).
std::string PresetTablesText(const Preset& preset) {
  std::vector<std::string> names;
  for (const PresetTable& pt : preset.tables) {
    const ModelKind m = pt.spec.model.kind;
    std::string name = TableName(pt.spec.table);
    if (m != ModelKind::kGgx) name = std::string(pt.spec.model.name()) + " " + name;
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

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

// A field that is a number in [lim_lo, lim_hi], or a range [min, max]
// within it.
void NumberRange(const Fields& f, const std::string& field, double lim_lo, double lim_hi, double* lo, double* hi) {
  const toml::node* r = f.t.get(field);
  if (r->is_array()) {
    const toml::array& a = *r->as_array();
    if (a.size() != 2 || !a[0].is_number() || !a[1].is_number()) f.Fail(field, "a range is two numbers [min, max]");
    *lo = a[0].value<double>().value() + 0.0;  // -0 as 0
    *hi = a[1].value<double>().value() + 0.0;
    if (!(*lo >= lim_lo && *lo <= *hi && *hi <= lim_hi)) {
      f.Fail(field, "the range must satisfy " + Num(lim_lo) + " <= min <= max <= " + Num(lim_hi));
    }
  } else {
    *lo = *hi = f.Number(field, lim_lo, lim_lo, lim_hi, true);
  }
}

// A roughness field: in [0, 1].
void RoughnessRange(const Fields& f, const std::string& field, double* lo, double* hi) {
  NumberRange(f, field, 0, 1, lo, hi);
}

// An index of refraction: in [1, 100] (the dielectric Fresnel's domain,
// fresnel.h, from the side of index 1).
void IorRange(const Fields& f, const std::string& field, double* lo, double* hi) {
  NumberRange(f, field, 1, kMaxFresnelIndex, lo, hi);
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

// An engine preset's name in a scene: FindPreset's message after `where`.
void CheckScenePreset(const std::string& where, const std::string& name) {
  try {
    FindPreset(name);
  } catch (const std::invalid_argument& e) {
    std::string what = ErrorText(e);
    const std::string prefix = "{preset}: ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    Bad(where + ": " + what);
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
  if (const toml::node* e = root.get("engine"); e && e->is_string()) {
    // engine = "bevy": the engine preset alone, every other setting its own
    // or the default.
    s.engine.preset = std::string(**e->as_string());
    CheckScenePreset(path + ": field 'engine'", s.engine.preset);
  } else if (e) {
    if (!e->is_table()) Bad(path + ": 'engine' must be a table ([engine]) or an engine preset's name (engine = \"bevy\")");
    const Fields f{*e->as_table(), path + ": [engine]"};
    f.OnlyKnown({"preset", "max_lut_size", "pixel", "placement", "error_target", "complement", "tables", "header",
                 "shaders"});
    if (f.Has("preset")) {
      s.engine.preset = f.String("preset", "");
      CheckScenePreset(path + ": [engine]: field 'preset'", s.engine.preset);
      // The engine's layout fixes these.
      for (const char* fixed : {"pixel", "placement", "complement", "header"}) {
        if (f.Has(fixed)) f.Fail(fixed, "fixed by the engine preset '" + s.engine.preset + "' (its layout and containers)");
      }
    }
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
  if (!s.engine.preset.empty()) {
    // The engine must sample one of the scene's tables.
    bool any = false;
    for (const PresetTable& pt : FindPreset(s.engine.preset).tables) {
      any |= std::find(s.engine.tables.begin(), s.engine.tables.end(), pt.spec.table) != s.engine.tables.end();
    }
    if (!any) {
      Bad(path + ": [engine]: field 'tables': engine preset '" + s.engine.preset + "' samples " +
          PresetTablesText(FindPreset(s.engine.preset)) + " only");
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
    f.OnlyKnown({"name", "model", "roughness", "gamma", "anisotropy", "masking", "sheen_roughness", "ior",
                 "transmission", "volume"});
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
    if (!f.Has("roughness")) f.Fail("roughness", "missing (a number in [0, 1] or a range [min, max])");
    RoughnessRange(f, "roughness", &mat.roughness_min, &mat.roughness_max);
    if (f.Has("sheen_roughness")) {
      // A sheen layer over the base (glTF's KHR_materials_sheen): the
      // charlie model's tables over its roughness.
      if (!ModelBuilt(ModelKind::kCharlie)) {
        f.Fail("sheen_roughness", "a sheen layer needs the charlie model, which is not in this build (BRDFBAKE_MODELS)");
      }
      mat.sheen = true;
      RoughnessRange(f, "sheen_roughness", &mat.sheen_roughness_min, &mat.sheen_roughness_max);
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
      mat.anisotropy = mat.anisotropy_min = f.Number("anisotropy", 0, 0, 1, true);
    } else if (f.Has("anisotropy")) {
      f.Fail("anisotropy", "only ggx-aniso has an anisotropy");
    }
    mat.masking = MaskingOf(f);
    if (f.Has("ior")) {
      IorRange(f, "ior", &mat.ior_min, &mat.ior_max);
      mat.ior_given = true;
    }
    mat.transmission = f.Bool("transmission", false);
    mat.volume = f.Bool("volume", false);
    if (mat.volume && !mat.transmission) f.Fail("volume", "a volume needs transmission = true");
    if (mat.transmission) {
      if (mat.model != ModelKind::kGgx) f.Fail("transmission", "transmissive materials are ggx (the rough dielectric over GGX)");
      if (mat.masking != Masking::kHeightCorrelated) {
        f.Fail("transmission", "the glass tables are height-correlated (masking = \"height-correlated\")");
      }
      if (!ModelBuilt(ModelKind::kGgxGlass)) {
        f.Fail("transmission", "transmission needs the glass family, which is not in this build (BRDFBAKE_MODELS)");
      }
    }
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
    // A texture reference of an extension: an object with an integer index.
    const auto check_texture = [&](const nlohmann::json& obj, const char* key, const std::string& field) {
      const auto tex = obj.find(key);
      if (tex == obj.end()) return;
      const auto index = tex->is_object() ? tex->find("index") : tex->end();
      if (!tex->is_object() || index == tex->end() || !index->is_number_unsigned()) {
        Bad(where + ": field '" + field + key + "': expected an object with an integer 'index' >= 0");
      }
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
          const auto tex = ext.find("anisotropyTexture");
          if (tex != ext.end()) {
            const auto index = tex->is_object() ? tex->find("index") : tex->end();
            if (!tex->is_object() || index == tex->end() || !index->is_number_unsigned()) {
              Bad(where + ": field 'KHR_materials_anisotropy.anisotropyTexture': expected an object with an "
                          "integer 'index' >= 0");
            }
          }
          // The texture's blue channel scales the strength: [0, strength].
          mat.anisotropy_min = tex != ext.end() ? 0.0 : strength;
        }
      } else if (name_ext == "KHR_materials_ior") {
        // On an opaque material the ior sets F0, which weights the
        // split-sum terms (dfg covers it); a transmissive one refracts by
        // it. The schema's minimum is 1; brdfbake's Fresnel reaches 100.
        const double ior = number(ext, "ior", "KHR_materials_ior.ior", 1.5);
        if (!(ior >= 1 && ior <= kMaxFresnelIndex)) {
          Bad(where + ": field 'KHR_materials_ior.ior': " + ExactText(ior) + " is outside [1, " +
              Num(kMaxFresnelIndex) + "]");
        }
        mat.ior_min = mat.ior_max = ior;
        mat.ior_given = true;
      } else if (name_ext == "KHR_materials_specular") {
        // The F0 and F90 this sets weight the split-sum terms: dfg covers them.
      } else if (name_ext == "KHR_materials_transmission") {
        // The rough dielectric's BTDF at the material's roughness and ior;
        // a transmissionTexture multiplies the factor (0 stays 0).
        const std::string field = "KHR_materials_transmission.";
        const double t = number(ext, "transmissionFactor", field + "transmissionFactor", 0.0) + 0.0;
        if (!(t >= 0 && t <= 1)) {
          Bad(where + ": field '" + field + "transmissionFactor': " + ExactText(t) + " is outside [0, 1]");
        }
        check_texture(ext, "transmissionTexture", field);
        if (t > 0 && !ModelBuilt(ModelKind::kGgxGlass)) {
          mat.unsupported.push_back({name_ext,
                                     "needs the ggx-glass tables over roughness and ior, and this build leaves "
                                     "the glass family out (BRDFBAKE_MODELS)"});
        } else if (t > 0) {
          mat.transmission = true;
        }
      } else if (name_ext == "KHR_materials_volume") {
        // A thickness above 0 makes the surface bound a medium (light
        // enters and leaves it); 0 is thin-walled.
        const std::string field = "KHR_materials_volume.";
        const double thickness = number(ext, "thicknessFactor", field + "thicknessFactor", 0.0) + 0.0;
        if (!(thickness >= 0) || std::isinf(thickness)) {
          Bad(where + ": field '" + field + "thicknessFactor': " + ExactText(thickness) + " is not a finite number >= 0");
        }
        const double distance = number(ext, "attenuationDistance", field + "attenuationDistance", 1.0);
        if (!(distance > 0)) {
          Bad(where + ": field '" + field + "attenuationDistance': " + ExactText(distance) + " is not above 0");
        }
        if (const auto c = ext.find("attenuationColor"); c != ext.end()) {
          if (!c->is_array() || c->size() != 3) {
            Bad(where + ": field '" + field + "attenuationColor': expected an array of three numbers");
          }
          for (size_t k = 0; k < 3; ++k) {
            const nlohmann::json& v = (*c)[k];
            if (!v.is_number() || !(v.get<double>() >= 0)) {
              Bad(where + ": field '" + field + "attenuationColor[" + std::to_string(k) + "]': expected a number >= 0");
            }
          }
        }
        check_texture(ext, "thicknessTexture", field);
        mat.volume = thickness > 0;
      } else if (name_ext == "KHR_materials_sheen") {
        // The sheen layer: the Charlie NDF, conty-kulla visibility, at
        // sheenRoughnessFactor (its texture's alpha modulates it over [0,
        // factor]); a sheenColorFactor of 0 (the default) is no layer.
        const std::string field = "KHR_materials_sheen.";
        double colour = 0;
        if (const auto c = ext.find("sheenColorFactor"); c != ext.end()) {
          if (!c->is_array() || c->size() != 3) {
            Bad(where + ": field '" + field + "sheenColorFactor': expected an array of three numbers");
          }
          for (size_t k = 0; k < 3; ++k) {
            const nlohmann::json& v = (*c)[k];
            if (!v.is_number()) {
              Bad(where + ": field '" + field + "sheenColorFactor[" + std::to_string(k) + "]': expected a number, got a " +
                  JsonType(v));
            }
            const double x = v.get<double>() + 0.0;
            if (!(x >= 0 && x <= 1)) {
              Bad(where + ": field '" + field + "sheenColorFactor[" + std::to_string(k) + "]': " + ExactText(x) +
                  " is outside [0, 1]");
            }
            colour = std::max(colour, x);
          }
        }
        const double rough = number(ext, "sheenRoughnessFactor", field + "sheenRoughnessFactor", 0.0) + 0.0;
        if (!(rough >= 0 && rough <= 1)) {
          Bad(where + ": field '" + field + "sheenRoughnessFactor': " + ExactText(rough) + " is outside [0, 1]");
        }
        for (const char* key : {"sheenColorTexture", "sheenRoughnessTexture"}) {
          const auto tex = ext.find(key);
          if (tex == ext.end()) continue;
          const auto index = tex->is_object() ? tex->find("index") : tex->end();
          if (!tex->is_object() || index == tex->end() || !index->is_number_unsigned()) {
            Bad(where + ": field '" + field + key + "': expected an object with an integer 'index' >= 0");
          }
        }
        if (colour > 0 && !ModelBuilt(ModelKind::kCharlie)) {
          mat.unsupported.push_back({name_ext,
                                     "needs the charlie sheen E table over sheen roughness, and this build leaves "
                                     "the charlie model out (BRDFBAKE_MODELS)"});
        } else if (colour > 0) {
          mat.sheen = true;
          mat.sheen_roughness_max = rough;
          mat.sheen_roughness_min = ext.contains("sheenRoughnessTexture") ? 0.0 : rough;
        }
      } else if (name_ext == "KHR_materials_clearcoat") {
        // A GGX layer (IOR 1.5) at its own roughness; a roughness texture
        // modulates the factor over [0, factor].
        const std::string field = "KHR_materials_clearcoat.";
        const double factor_cc = number(ext, "clearcoatFactor", field + "clearcoatFactor", 0.0) + 0.0;
        const double rough_cc = number(ext, "clearcoatRoughnessFactor", field + "clearcoatRoughnessFactor", 0.0) + 0.0;
        for (const auto& [key, value] : {std::pair<const char*, double>{"clearcoatFactor", factor_cc},
                                         {"clearcoatRoughnessFactor", rough_cc}}) {
          if (!(value >= 0 && value <= 1)) {
            Bad(where + ": field '" + field + key + "': " + ExactText(value) + " is outside [0, 1]");
          }
        }
        for (const char* key : {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"}) {
          const auto tex = ext.find(key);
          if (tex == ext.end()) continue;
          const auto index = tex->is_object() ? tex->find("index") : tex->end();
          if (!tex->is_object() || index == tex->end() || !index->is_number_unsigned()) {
            Bad(where + ": field '" + field + key + "': expected an object with an integer 'index' >= 0");
          }
        }
        mat.clearcoat = factor_cc;
        mat.clearcoat_roughness_max = rough_cc;
        mat.clearcoat_roughness_min = ext.contains("clearcoatRoughnessTexture") ? 0.0 : rough_cc;
      } else {
        mat.unsupported.push_back({name_ext, "an extension brdfbake does not know: not baked"});
      }
    }
    if (!mat.transmission) mat.volume = false;  // a medium behind an opaque surface changes no table
    if (mat.transmission && mat.model == ModelKind::kGgxAniso) {
      // The glass tables are isotropic; an anisotropic BTDF would need 4D
      // ones.
      mat.unsupported.push_back({"KHR_materials_transmission",
                                 "anisotropic transmission needs 4D glass tables, which brdfbake does not bake: "
                                 "not baked"});
      mat.transmission = mat.volume = false;
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

// The isotropic GGX group of a masking: where clearcoat layers and
// anisotropic materials looked up at their collapsed roughness go.
std::string IsoKey(Masking m) { return m == Masking::kSeparable ? "ggx_separable" : "ggx"; }

// The collapse engines use (Cycles: sqrt(sqrt(alpha_x alpha_y)) as
// roughness; MaterialX and Enterprise PBR: the geometric mean of the
// widths): r_c = (alpha_t alpha_b)^(1/4).
constexpr const char* kCollapse = "geometric-mean";
double CollapsedRoughness(double r, double s) {
  return std::sqrt(CollapsedAlpha(kCollapse, AnisotropyAlphaT(r, s), AlphaFromRoughness(r), 0));
}

// An identifier from a file stem (E_std_g1.6 -> E_std_g1_6).
std::string Identifier(std::string s) {
  for (char& c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return s;
}

const char* ExtensionOf(Container c) {
  switch (c) {
    case Container::kExr: return ".exr";
    case Container::kHeader: return ".h";
    case Container::kJs: return ".js";
    case Container::kKtx2: return ".ktx2";
    case Container::kDds: return ".dds";
    case Container::kPng: return ".png";
    case Container::kInc: return ".inc";
  }
  return ".exr";
}

// The group of a scene's sheen layers: the Charlie NDF with the
// conty-kulla visibility (glTF's KHR_materials_sheen), or under a preset
// the visibility of the engine's own sheen table.
constexpr const char* kSheenGroup = "charlie";
// The smallest NoV at which the sheen's E is evaluated (IsoBase).
constexpr double kSheenMinNoV = 1e-4;

// The model of the engine table a group is written through: the engine's
// GGX table serves every microfacet group (renamed for the others), its
// sheen table (if it ships one) the sheen group.
ModelKind EngineModel(ModelKind group_model) {
  return group_model == ModelKind::kCharlie ? ModelKind::kCharlie : ModelKind::kGgx;
}
// The groups of the transmissive materials' glass tables: light entering
// the medium (eta = ior), and for a volume also leaving it (eta = 1 / ior).
constexpr const char* kGlassGroup = "ggx-glass";
constexpr const char* kGlassInverseGroup = "ggx-glass_inverse";
bool IsGlassGroup(const std::string& g) { return g == kGlassGroup || g == kGlassInverseGroup; }

ModelKind EngineModel(const std::string& group) {
  return group == kSheenGroup ? ModelKind::kCharlie : IsGlassGroup(group) ? ModelKind::kGgxGlass : ModelKind::kGgx;
}

// The preset's table of a kind for the engine's model: GGX, the Charlie
// sheen with a masking visibility (conty-kulla, or the engine's variant of
// it), or ggx-glass entering or (`inverse`) leaving the medium; nullptr if
// it has none. An engine whose glass E entering the medium is the
// refraction weighted by Schlick's complement (EEVEE's btdf_ggx, which its
// renderer scales by 1 - F0) serves it with that table when it has no
// table of both lobes.
const PresetTable* EngineTable(const Preset& preset, TableKind kind, ModelKind model = ModelKind::kGgx,
                               bool inverse = false) {
  const PresetTable* schlick = nullptr;
  for (const PresetTable& pt : preset.tables) {
    if (pt.spec.table != kind || pt.spec.model.kind != model || pt.over != PresetTable::Over::kNone) continue;
    if (pt.spec.inverse != inverse) continue;
    if (pt.spec.part == DielectricPart::kTransmissionSchlick && !schlick) schlick = &pt;
    if (pt.spec.part != DielectricPart::kBoth) continue;
    if (model == ModelKind::kCharlie && !SheenHasLambda(pt.spec.model.visibility)) continue;
    return &pt;
  }
  return schlick;
}

// Whether the preset ships a glass table of its own: then the scene's
// glass tables are the engine's, and a kind or side it does not ship is
// served by its renderer's own means, not by a file it never reads.
bool EngineHasGlass(const Preset& preset) {
  return std::any_of(preset.tables.begin(), preset.tables.end(),
                     [](const PresetTable& pt) { return pt.spec.model.kind == ModelKind::kGgxGlass; });
}

// Whether a scene bakes the glass table of `kind` entering or (`inverse`)
// leaving the medium: always without a preset or under one that ships no
// glass table (brdfbake's own file), else only where the engine has it.
bool GlassSlotBaked(const Scene& scene, TableKind kind, bool inverse) {
  if (scene.engine.preset.empty()) return true;
  const Preset& preset = FindPreset(scene.engine.preset);
  return !EngineHasGlass(preset) || EngineTable(preset, kind, ModelKind::kGgxGlass, inverse) != nullptr;
}

// The preset's table whose layout carries the Charlie sheen E in a channel
// of its own (Filament's and Godot's cloth, MaterialX's sheen), or nullptr.
const PresetTable* SheenChannelTable(const Preset& preset) {
  for (const PresetTable& pt : preset.tables) {
    for (const BakeSpec& w : pt.with) {
      if (w.model.kind == ModelKind::kCharlie) return &pt;
    }
  }
  return nullptr;
}

// The table kinds a scene bakes: the engine's, and under a preset only
// those its engine samples.
std::vector<TableKind> SceneKinds(const Scene& scene) {
  if (scene.engine.preset.empty()) return scene.engine.tables;
  const Preset& preset = FindPreset(scene.engine.preset);
  std::vector<TableKind> kinds;
  for (TableKind k : scene.engine.tables) {
    if (EngineTable(preset, k)) kinds.push_back(k);
  }
  return kinds;
}

bool HasSheen(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(), [](const SceneMaterial& m) { return m.sheen; });
}

// Whether the engine's own table carries the sheen: a channel of a table
// the scene bakes holds the Charlie E over every roughness.
bool SheenInEngineChannel(const Scene& scene) {
  if (scene.engine.preset.empty()) return false;
  const PresetTable* pt = SheenChannelTable(FindPreset(scene.engine.preset));
  if (!pt) return false;
  const std::vector<TableKind> kinds = SceneKinds(scene);
  return std::find(kinds.begin(), kinds.end(), pt->spec.table) != kinds.end();
}

// The sheen group's table kinds: E and E_avg among the scene's tables (the
// conty-kulla E is what glTF's sheen scales the base layer by, E_avg what
// energy-compensation schemes use; the sheen has no Fresnel factor, so no
// dfg). Under a preset they are the engine's own sheen tables, or
// brdfbake's own files where it has none; none when a channel of the
// engine's table carries the sheen.
std::vector<TableKind> SheenKinds(const Scene& scene) {
  std::vector<TableKind> kinds;
  if (!HasSheen(scene) || SheenInEngineChannel(scene)) return kinds;
  for (TableKind k : scene.engine.tables) {
    if (k == TableKind::kE || k == TableKind::kEavg) kinds.push_back(k);
  }
  return kinds;
}

// The glass groups' table kinds: E and E_avg among the scene's tables (a
// dielectric's Fresnel is inside its E: no dfg split), whatever the
// preset (the engine's own glass tables where it ships them, brdfbake's
// own files otherwise).
std::vector<TableKind> GlassKinds(const Scene& scene) {
  std::vector<TableKind> kinds;
  const bool any = std::any_of(scene.materials.begin(), scene.materials.end(),
                               [](const SceneMaterial& m) { return m.transmission; });
  if (!any) return kinds;
  for (TableKind k : scene.engine.tables) {
    if (k == TableKind::kE || k == TableKind::kEavg) kinds.push_back(k);
  }
  return kinds;
}

// Whether a preset's own glass table serves one of the scene's
// transmissive groups.
bool EngineServesGlass(const Scene& scene) {
  if (scene.engine.preset.empty()) return false;
  const Preset& preset = FindPreset(scene.engine.preset);
  const bool volume = std::any_of(scene.materials.begin(), scene.materials.end(),
                                  [](const SceneMaterial& m) { return m.transmission && m.volume; });
  for (TableKind k : GlassKinds(scene)) {
    if (EngineTable(preset, k, ModelKind::kGgxGlass, false)) return true;
    if (volume && EngineTable(preset, k, ModelKind::kGgxGlass, true)) return true;
  }
  return false;
}

// One table slot of a plan: its kind and material group; `generic` when
// the engine has no layout for it (the ggx-aniso tables under a preset,
// and the sheen tables of an engine without a sheen table).
struct Slot {
  TableKind kind;
  std::string group;
  bool generic = false;
};

// The slot of a planned table of `group`.
Slot SlotOf(const Scene& scene, TableKind kind, const std::string& group, bool anisotropic) {
  bool generic = anisotropic;
  if (IsGlassGroup(group)) {
    generic = scene.engine.preset.empty() || !EngineTable(FindPreset(scene.engine.preset), kind, ModelKind::kGgxGlass,
                                                          group == kGlassInverseGroup);
  }
  if (group == kSheenGroup && !scene.engine.preset.empty()) {
    generic = !EngineTable(FindPreset(scene.engine.preset), kind, ModelKind::kCharlie);
  }
  return {kind, group, generic};
}

// The file name of a slot without a preset: E_ggx.exr.
std::string TableFile(const Scene& scene, const Slot& slot) {
  const Container c = scene.engine.format.empty() ? Container::kExr : ParseContainer(scene.engine.format);
  return std::string(TableName(slot.kind)) + "_" + slot.group + ExtensionOf(c);
}

std::string Stem(const std::string& f) { return std::filesystem::path(f).replace_extension().string(); }

// The preset a scene bake writes through: the engine's tables, one per
// slot, renamed for groups other than height-correlated GGX (the engine's
// own model), and brdfbake's EXR for the tables the engine has no layout
// for. `specs` and `layouts` (parallel to `slots`) may be empty when only
// the file names are needed.
Preset ScenePreset(const Scene& scene, const std::vector<Slot>& slots, const std::vector<const PlannedTable*>& planned) {
  const Preset& engine = FindPreset(scene.engine.preset);
  Preset p;
  p.name = engine.name;
  p.description = engine.description;
  p.header_file = engine.header_file;
  p.header_form = engine.header_form;
  for (size_t i = 0; i < slots.size(); ++i) {
    const Slot& slot = slots[i];
    PresetTable t;
    const ModelKind model = EngineModel(slot.group);
    const PresetTable* et =
        slot.generic ? nullptr : EngineTable(engine, slot.kind, model, slot.group == kGlassInverseGroup);
    if (et) {
      t = *et;
      const bool own_group = model == ModelKind::kCharlie    ? slot.group == kSheenGroup
                             : model == ModelKind::kGgxGlass ? true
                                                             : slot.group == "ggx";
      if (!own_group) {
        if (!t.file.empty()) {
          const std::filesystem::path f(t.file);
          t.file = f.stem().string() + "_" + slot.group + f.extension().string();
        }
        t.symbol += "_" + Identifier(slot.group);
      }
    } else {
      t.spec.table = slot.kind;
      t.container = Container::kExr;
      t.also = {Container::kKtx2, Container::kDds};
      t.file = std::string(TableName(slot.kind)) + "_" + slot.group + ".exr";
      t.symbol = Identifier(Stem(t.file));
    }
    if (i < planned.size() && planned[i]) {
      t.spec = planned[i]->spec;
      t.layout = planned[i]->layout;
    }
    p.tables.push_back(t);
  }
  return p;
}

PresetRun ScenePresetRun(const Scene& scene, const std::string& dir) {
  PresetRun run;
  run.dir = dir;
  run.format = scene.engine.format;
  run.shaders = scene.engine.shaders;
  return run;
}

// The files of a table a scene writes without a preset: its container
// (the table's own EXR, or the engine's format), a C header and lookups
// as the scene's engine asks.
std::vector<OutputFile> OwnFilesOf(const Scene& scene, const Slot& slot, const std::string& dir, int table) {
  const std::string file = TableFile(scene, slot);
  const Container c = scene.engine.format.empty() ? Container::kExr : ParseContainer(scene.engine.format);
  return OwnTableFiles(dir + "/" + file, c, true, scene.engine.header, scene.engine.shaders,
                       "brdfbake_" + Identifier(Stem(file)), table);
}

// Every file written for `slots` into dir, then the manifest; with a
// preset, PresetFiles' list.
std::vector<std::string> FilesOf(const Scene& scene, const std::vector<Slot>& slots, const std::string& dir) {
  std::vector<std::string> files;
  if (!scene.engine.preset.empty()) {
    for (const PresetFile& f : PresetFiles(ScenePreset(scene, slots, {}), ScenePresetRun(scene, dir))) {
      files.push_back(f.path);
    }
  } else {
    for (size_t i = 0; i < slots.size(); ++i) {
      for (const OutputFile& f : OwnFilesOf(scene, slots[i], dir, int(i))) files.push_back(f.path);
    }
  }
  files.push_back(dir + "/manifest.json");
  return files;
}

// An anisotropic group's box: its materials' roughness and anisotropy.
struct AnisoBox {
  double rmin = 1, rmax = 0, smin = 1, smax = 0;
};

// The transmissive materials' box: their roughness and ior.
struct GlassBox {
  double rmin = 1, rmax = 0, ior_min = kMaxFresnelIndex, ior_max = 1;
};

// Axis over [lo, hi] with n entries (one entry at lo = hi: centres).
void SetAxis(Axis* a, double lo, double hi, int n, Placement placement) {
  a->min = lo;
  a->max = hi;
  a->size = lo == hi ? 1 : n;
  a->placement = lo == hi ? Placement::kCenters : placement;
}

int64_t Texels(const Table& t) { return int64_t(t.width) * t.height; }

// The texels a bake of `spec` holds (E, E_avg, dfg of the scene's models).
int64_t SpecTexels(const BakeSpec& s) {
  const int64_t r = s.roughness.size;
  if (s.Glass()) {
    const int64_t ri = r * s.ior.size;
    return s.table == TableKind::kEavg ? ri : ri * s.mu.size;
  }
  if (s.Anisotropic()) {
    const int64_t rs = r * s.anisotropy.size;
    return s.table == TableKind::kEavg ? rs : rs * s.mu.size * s.phi.size;
  }
  return s.table == TableKind::kEavg ? r : r * s.mu.size;
}

std::string SizeText(const Table& t) {
  std::string s;
  for (const Axis& a : t.axes) s += (s.empty() ? "" : "x") + std::to_string(a.size);
  return s.empty() ? "1" : s;
}

using Progress = std::function<void(const std::string&)>;
using LayoutOf = std::function<ImageLayout(const Table&)>;

// One candidate: baked, arranged, its lookup error probed (probe.h), and
// the stated bound: the probed error plus the stored values' claim (or,
// when the layout's pixel type differs from the table's, the arranged
// image's claim: integration plus rounding).
PlannedTable Evaluate(const BakeSpec& spec, const LayoutOf& layout_of, const ProbeOptions& probe, double collapse,
                      double target, const std::string& label, const Progress& progress) {
  PlannedTable p;
  p.spec = spec;
  p.table = Bake(spec);
  p.layout = layout_of(p.table);
  p.interpolation_error = LookupError(p.table, probe).max_abs_error;
  // The claim of this table's own channels (an engine layout's channels
  // from other tables, Filament's sheen say, are theirs).
  ImageLayout own = p.layout;
  own.channels.erase(std::remove_if(own.channels.begin(), own.channels.end(),
                                    [](const ImageLayout::Out& o) { return o.table != 0; }),
                     own.channels.end());
  const Image im = ArrangeTable(p.table, own);
  const PixelType stored = spec.half ? PixelType::kHalf : PixelType::kFloat;
  p.total_error = p.interpolation_error + (im.pixel == stored ? p.table.integration_error : im.max_abs_error);
  // The probe's exact values are the table's integrator at its tolerance:
  // a glass table, baked at a tolerance tied to the target (GlassBase),
  // counts that too.
  if (spec.Glass()) p.total_error += spec.tolerance;
  p.collapse_error = collapse;
  p.meets_target = p.total_error + collapse <= target;
  if (progress) {
    std::string warp = p.spec.table == TableKind::kEavg ? "" : std::string(" mu ") + WarpName(spec.mu.warp);
    progress(label + " " + SizeText(p.table) + warp + ": lookup error " + Num(p.total_error));
  }
  return p;
}

// A ladder of candidates, smallest first: the first that meets the target
// is kept, else the one with the smallest error. `stop_texels`: give up
// once candidates are larger than this (another choice is smaller).
struct Rung {
  int n;
  Warp warp;
};
PlannedTable Climb(const std::vector<Rung>& rungs, const std::function<BakeSpec(const Rung&)>& make,
                   const LayoutOf& layout_of, const ProbeOptions& probe, double collapse, double target,
                   const std::string& label, const Progress& progress,
                   int64_t stop_texels = std::numeric_limits<int64_t>::max()) {
  PlannedTable best;
  best.total_error = std::numeric_limits<double>::infinity();
  for (const Rung& rung : rungs) {
    const BakeSpec spec = make(rung);
    if (SpecTexels(spec) > stop_texels) break;
    PlannedTable p = Evaluate(spec, layout_of, probe, collapse, target, label, progress);
    const bool better = p.total_error < best.total_error;
    if (p.meets_target || better) best = std::move(p);
    if (best.meets_target) break;
  }
  return best;
}

// The sizes 2, 4, ... up to n_max.
std::vector<int> Doublings(int from, int n_max) {
  std::vector<int> v;
  for (int n = from; n <= n_max; n *= 2) v.push_back(n);
  return v;
}

std::vector<Rung> Rungs(const std::vector<int>& sizes, const std::vector<Warp>& warps) {
  std::vector<Rung> r;
  for (int n : sizes) {
    for (Warp w : warps) r.push_back({n, w});
  }
  return r;
}

// The planner of one scene: the engine's layouts, the target, the probe.
class Planner {
 public:
  Planner(const Scene& scene, const Progress& progress) : scene_(scene), progress_(progress) {
    if (!scene.engine.preset.empty()) preset_ = &FindPreset(scene.engine.preset);
  }

  // The engine's table of `kind` for a group of `model` (nullptr without
  // a preset, or when the engine has none: brdfbake's own file).
  const PresetTable* Engine(TableKind kind, ModelKind model) const {
    return preset_ ? EngineTable(*preset_, kind, EngineModel(model)) : nullptr;
  }

  // The spec of an isotropic table of `kind` for the group `model`,
  // roughness [rmin, rmax] (before its size is chosen). A table without
  // the engine's layout under a preset is float, at texel centres, as the
  // 4D anisotropic tables.
  BakeSpec IsoBase(TableKind kind, const SceneMaterial& model, double rmin, double rmax) const {
    const PresetTable* et = Engine(kind, model.model);
    BakeSpec base;
    if (et) base = et->spec;  // the engine's axes, placement, warps, clamps
    base.table = kind;
    base.model.kind = model.model == ModelKind::kGgxAniso ? ModelKind::kGgx : model.model;
    base.model.gamma = model.model == ModelKind::kStudentT ? model.gamma : 2.0;
    base.masking = model.masking;
    if (et) return base;
    // A sheen table the engine does not ship (E_avg) takes the visibility
    // of the sheen E it does ship, so that the two agree.
    if (base.model.kind == ModelKind::kCharlie && preset_) {
      if (const PresetTable* e = EngineTable(*preset_, TableKind::kE, ModelKind::kCharlie)) {
        base.model.visibility = e->spec.model.visibility;
      }
    }
    base.half = !preset_ && scene_.engine.pixel == PixelType::kHalf;
    base.complement = !preset_ && scene_.engine.complement && kind != TableKind::kDfg;
    base.mu.placement = base.roughness.placement = preset_ ? Placement::kCenters : scene_.engine.placement;
    base.roughness.min = rmin;
    base.roughness.max = rmax;
    // The Charlie sheen's E (conty-kulla) keeps growing below NoV = 1e-4
    // (at r = 0.7: 0.71 at 1e-4, 1.23 at 1e-6, 2.9 at 1e-8), a layer no
    // table resolves: its texels and its probe take NoV at least 1e-4,
    // where engines clamp NoV, and the file's mu axis says so (clamp_min).
    if (base.model.kind == ModelKind::kCharlie && kind != TableKind::kEavg) base.mu.clamp_min = kSheenMinNoV;
    return base;
  }

  LayoutOf IsoLayout(TableKind kind, ModelKind model) const {
    if (const PresetTable* et = Engine(kind, model)) {
      const ImageLayout l = et->layout;
      return [l](const Table&) { return l; };
    }
    return GenericLayout();
  }
  LayoutOf GenericLayout() const {
    const bool unorm16 = scene_.engine.unorm16;
    return [unorm16](const Table& t) {
      ImageLayout l = DefaultLayout(t);
      if (unorm16) l.pixel = PixelType::kUnorm16;
      return l;
    };
  }

  bool IsoSizeFixed(TableKind kind, ModelKind model) const {
    const PresetTable* et = Engine(kind, model);
    return et && et->size_fixed;
  }

  // The ladder of an isotropic table: sizes 2, 4, ... up to the limit per
  // axis and mu linear or square (E_avg: one axis); under a preset, the
  // engine's warps, and its size where it fixes it.
  // [rmin, rmax]: the materials' roughness (under a preset, within the
  // engine's axis).
  PlannedTable PlanIso(const BakeSpec& base, double rmin, double rmax, double collapse, const std::string& label,
                       bool with_hint) const {
    const TableKind kind = base.table;
    const ModelKind model = base.model.kind;
    const bool sheen = model == ModelKind::kCharlie;
    const bool engine = Engine(kind, model) != nullptr;  // the engine's layout and axes
    const double target = scene_.engine.error_target;
    const bool one_r = !engine && base.roughness.min == base.roughness.max;
    const bool fixed = IsoSizeFixed(kind, model);
    std::vector<Warp> warps = {Warp::kLinear, Warp::kSquare};
    if (kind == TableKind::kEavg) warps = {Warp::kLinear};
    if (engine) warps = {base.mu.warp};
    auto make = [&](const Rung& rung) {
      BakeSpec spec = base;
      if (fixed) return spec;
      spec.mu.size = rung.n;
      spec.mu.warp = rung.warp;
      spec.roughness.size = one_r ? 1 : rung.n;
      if (one_r) spec.roughness.placement = Placement::kCenters;
      return spec;
    };
    ProbeOptions probe;
    if (engine) {
      probe.roughness_min = rmin;
      probe.roughness_max = rmax;
    }
    const std::vector<Rung> rungs =
        fixed ? std::vector<Rung>{{base.mu.size, base.mu.warp}} : Rungs(Doublings(2, scene_.engine.max_lut_size), warps);
    const bool single = kind == TableKind::kEavg && one_r;  // one value: nothing to refine
    PlannedTable p = Climb(single ? std::vector<Rung>{rungs.front()} : rungs, make, IsoLayout(kind, model), probe,
                           collapse, target, label, progress_);
    p.size_fixed = fixed;
    // A roughness axis across the mirror cut (alpha = 1e-4, r = 0.01: E
    // jumps to 1 below it) is never resolved by interpolation, whatever the
    // size; a range that starts at the cut is. The Charlie sheen has no
    // such cut: its lobe narrows smoothly towards the grazing ring.
    const double cut = std::sqrt(kMinAlpha<double>);
    const bool crosses = kind != TableKind::kSelNorm && !sheen && rmin < rmax && rmin < cut && rmax > cut;
    std::string prefix;
    if (!p.meets_target && with_hint && collapse >= target) {
      p.hint = "the collapse alone (" + Num(collapse) + ") is above the target: no table size meets it";
      return p;
    }
    if (!p.meets_target && with_hint && !single && crosses && engine) {
      p.hint = "the materials' roughness crosses the mirror cut (r = 0.01, where E jumps to 1), which no size resolves";
      return p;
    }
    BakeSpec hint_base = base;
    if (crosses) {
      hint_base.roughness.min = cut;
      prefix = "the roughness range crosses the mirror cut (r = 0.01, where E jumps to 1), which no size resolves; "
               "with roughness from 0.01, ";
    }
    if (!p.meets_target && with_hint && !single) {
      // The smallest size (and warp) beyond the limit that would meet the
      // target, up to 4 times the limit and at most 1024 per axis (the
      // Charlie sheen over a roughness range, slower to bake: twice the
      // limit, at most 256).
      const int from = crosses ? 2 : fixed ? 2 : 2 * scene_.engine.max_lut_size;
      const int reach = std::max(scene_.engine.max_lut_size, fixed ? base.mu.size : 0);
      const int to = sheen && !one_r ? std::min(256, 2 * reach) : std::min(1024, 4 * reach);
      auto beyond = [&](const Rung& rung) {
        BakeSpec spec = hint_base;
        spec.mu.size = rung.n;
        spec.mu.warp = rung.warp;
        spec.roughness.size = one_r ? 1 : rung.n;
        if (one_r) spec.roughness.placement = Placement::kCenters;
        return spec;
      };
      std::vector<Rung> more;
      for (const Rung& r : Rungs(Doublings(from, to), warps)) {
        if (crosses || !fixed || r.n != base.mu.size) more.push_back(r);
      }
      const PlannedTable h = Climb(more, beyond, IsoLayout(kind, model), probe, collapse, target,
                                   label + " (beyond the limit)", progress_);
      if (h.meets_target) {
        p.hint = prefix + SizeText(h.table) + (kind == TableKind::kEavg ? "" : std::string(", mu warp ") + WarpName(h.spec.mu.warp)) +
                 " would meet it (lookup error " + Num(h.total_error) + ")";
      } else {
        p.hint = prefix + "no size up to " + std::to_string(to) + " per axis meets it";
      }
    }
    return p;
  }

  // The ggx-aniso tables over a box: E over mu x phi_o x r x s, E_avg over
  // r x s, each axis that the box spans.
  BakeSpec AnisoBase(TableKind kind, Masking masking, const AnisoBox& b) const {
    BakeSpec base;
    base.table = kind;
    base.model.kind = ModelKind::kGgxAniso;
    base.masking = masking;
    const Placement pl = preset_ ? Placement::kCenters : scene_.engine.placement;
    base.half = !preset_ && scene_.engine.pixel == PixelType::kHalf;
    base.complement = !preset_ && scene_.engine.complement;
    base.mu.placement = base.phi.placement = pl;
    SetAxis(&base.roughness, b.rmin, b.rmax, 2, pl);
    SetAxis(&base.anisotropy, b.smin, b.smax, 2, pl);
    return base;
  }

  // A rung of the ggx-aniso ladder: E with n mu entries and n / 2 on the
  // other axes the box spans, E_avg n per spanned axis.
  static BakeSpec AnisoRung(const BakeSpec& base, const Rung& rung) {
    const bool eavg = base.table == TableKind::kEavg;
    const bool span_r = base.roughness.size > 1, span_s = base.anisotropy.size > 1;
    BakeSpec spec = base;
    const int half = std::max(2, rung.n / 2);
    if (!eavg) {
      spec.mu.size = rung.n;
      spec.mu.warp = rung.warp;
      spec.phi.size = half;
    }
    spec.roughness.size = span_r ? (eavg ? rung.n : half) : 1;
    spec.anisotropy.size = span_s ? (eavg ? rung.n : half) : 1;
    return spec;
  }

  PlannedTable PlanAniso(const BakeSpec& base, const std::string& label, int64_t stop_texels) const {
    const double target = scene_.engine.error_target;
    const bool eavg = base.table == TableKind::kEavg;
    const bool span_r = base.roughness.size > 1, span_s = base.anisotropy.size > 1;
    auto make = [&](const Rung& rung) { return AnisoRung(base, rung); };
    // E_avg(r, s) costs a hemispherical integral per entry: at most 8 per
    // axis; E at most 2^16 texels.
    std::vector<Rung> rungs;
    if (eavg) {
      rungs = span_r || span_s ? Rungs(Doublings(2, std::min(8, scene_.engine.max_lut_size)), {Warp::kLinear})
                               : std::vector<Rung>{{1, Warp::kLinear}};
    } else {
      for (const Rung& r : Rungs(Doublings(2, scene_.engine.max_lut_size), {Warp::kLinear, Warp::kSquare})) {
        if (SpecTexels(make(r)) <= (int64_t(1) << 16)) rungs.push_back(r);
      }
    }
    return Climb(rungs, make, GenericLayout(), AnisoProbe(eavg), 0.0, target, label, progress_, stop_texels);
  }

  static ProbeOptions AnisoProbe(bool eavg) {
    ProbeOptions probe;
    probe.probes = eavg ? 4 : 8;
    probe.minor_probes = 4;
    return probe;
  }

  // For a 4D table that misses the target within the size limit: the
  // smallest one beyond the limit that would meet it (E: up to 4 times
  // the limit per mu and 2^18 texels; E_avg: up to 16 per axis), as
  // PlanIso's hint says it for the isotropic tables.
  std::string AnisoHint(const BakeSpec& base, const std::string& label) const {
    const bool eavg = base.table == TableKind::kEavg;
    const int limit = scene_.engine.max_lut_size;
    std::vector<Rung> rungs;
    if (eavg) {
      if (base.roughness.size <= 1 && base.anisotropy.size <= 1) return "";
      rungs = Rungs(Doublings(2 * std::min(8, limit), 16), {Warp::kLinear});
    } else {
      for (const Rung& r : Rungs(Doublings(2 * limit, 4 * limit), {Warp::kLinear, Warp::kSquare})) {
        if (SpecTexels(AnisoRung(base, r)) <= (int64_t(1) << 18)) rungs.push_back(r);
      }
    }
    const std::string reach = eavg ? "16 per axis" : "2^18 texels";
    if (rungs.empty()) return "no larger table within " + reach;
    const PlannedTable h = Climb(rungs, [&](const Rung& r) { return AnisoRung(base, r); }, GenericLayout(),
                                 AnisoProbe(eavg), 0.0, scene_.engine.error_target, label + " (beyond the limit)",
                                 progress_);
    if (!h.meets_target) return "no size up to " + reach + " meets it";
    return SizeText(h.table) + (eavg ? "" : std::string(", mu warp ") + WarpName(h.spec.mu.warp)) +
           " would meet it (lookup error " + Num(h.total_error) + ")";
  }

  // The ggx-glass tables of the transmissive materials: E over mu x
  // roughness x ior, E_avg over roughness x ior, over the materials'
  // roughness and ior ranges (one entry where a range is one value), the
  // ior axis in z = F0^(1/4) (bake.h); `inverse`: light leaving the
  // medium (eta = 1 / ior). brdfbake's own file under every preset: no
  // engine preset ships a glass table yet.
  BakeSpec GlassBase(TableKind kind, const GlassBox& b, bool inverse) const {
    BakeSpec base;
    base.table = kind;
    base.model.kind = ModelKind::kGgxGlass;
    base.inverse = inverse;
    // A glass texel costs thousands of ray integrals: the texels and the
    // probe's exact values are integrated to a thousandth of the target
    // (at least 1e-7, at most 1e-5) rather than 1e-7, and the bound
    // counts it (Evaluate).
    base.tolerance = std::clamp(1e-3 * scene_.engine.error_target, 1e-7, 1e-5);
    const Placement pl = preset_ ? Placement::kCenters : scene_.engine.placement;
    base.half = !preset_ && scene_.engine.pixel == PixelType::kHalf;
    base.complement = !preset_ && scene_.engine.complement;
    base.mu.placement = pl;
    SetAxis(&base.roughness, b.rmin, b.rmax, 2, pl);
    SetAxis(&base.ior, b.ior_min, b.ior_max, 2, pl);
    base.ior.warp = Warp::kFresnelZ;
    return base;
  }

  // A rung of the glass ladder: n entries along mu and roughness, n / 2
  // along ior (E changes less across an ior range than across roughness);
  // E_avg n along each spanned axis.
  static BakeSpec GlassRung(const BakeSpec& base, const Rung& rung) {
    const bool eavg = base.table == TableKind::kEavg;
    BakeSpec spec = base;
    if (!eavg) {
      spec.mu.size = rung.n;
      spec.mu.warp = rung.warp;
    }
    if (base.roughness.size > 1) spec.roughness.size = rung.n;
    if (base.ior.size > 1) spec.ior.size = eavg ? rung.n : std::max(2, rung.n / 2);
    return spec;
  }

  // The engine's own glass table of `kind` (entering, or leaving the
  // medium), or nullptr.
  const PresetTable* GlassEngine(TableKind kind, bool inverse) const {
    return preset_ ? EngineTable(*preset_, kind, ModelKind::kGgxGlass, inverse) : nullptr;
  }

  // The engine's glass table as it ships (its axes, size, tolerance and
  // layout), its lookup error probed over the materials' roughness and ior
  // range only.
  PlannedTable PlanEngineGlass(const PresetTable& et, const GlassBox& b, const std::string& label) const {
    ProbeOptions probe;
    probe.probes = 8;
    probe.minor_probes = 4;
    probe.roughness_min = b.rmin;
    probe.roughness_max = b.rmax;
    probe.ior_min = b.ior_min;
    probe.ior_max = b.ior_max;
    const ImageLayout l = et.layout;
    const BakeSpec spec = et.spec;
    PlannedTable p = Climb({{spec.mu.size, spec.mu.warp}}, [&](const Rung&) { return spec; },
                           [l](const Table&) { return l; }, probe, 0.0, scene_.engine.error_target, label, progress_);
    p.size_fixed = et.size_fixed;
    return p;
  }

  // The smallest rung that meets the target: E up to the size limit and
  // 2^15 texels (a glass texel is a two-dimensional integral, thousands of
  // rays), mu square only (linear was 5 to 15 times worse at every size
  // tried: E changes fastest at grazing views); E_avg, a hundred E
  // integrals per entry, up to 8 per axis as the 4D E_avg.
  PlannedTable PlanGlass(const BakeSpec& base, const std::string& label) const {
    const double target = scene_.engine.error_target;
    const bool eavg = base.table == TableKind::kEavg;
    const bool single = eavg && base.roughness.size <= 1 && base.ior.size <= 1;
    std::vector<Rung> rungs;
    if (single) {
      rungs = {{1, Warp::kLinear}};
    } else {
      const int limit = eavg ? std::min(8, scene_.engine.max_lut_size) : scene_.engine.max_lut_size;
      for (const Rung& r : Rungs(Doublings(2, limit), {eavg ? Warp::kLinear : Warp::kSquare})) {
        if (SpecTexels(GlassRung(base, r)) <= (int64_t(1) << 15)) rungs.push_back(r);
      }
    }
    ProbeOptions probe;
    probe.probes = 8;
    probe.minor_probes = 4;
    PlannedTable p = Climb(rungs, [&](const Rung& r) { return GlassRung(base, r); }, GenericLayout(), probe, 0.0,
                           target, label, progress_);
    if (!p.meets_target && !single) {
      p.hint = eavg ? "no size up to 8 per axis meets it"
                    : "no size within the limit (" + std::to_string(scene_.engine.max_lut_size) +
                          " per axis, 2^15 texels) meets it";
    }
    return p;
  }

  const Preset* preset() const { return preset_; }

 private:
  const Scene& scene_;
  Progress progress_;
  const Preset* preset_ = nullptr;
};

// Isotropic lookups of one group and table kind: who, over which
// roughness, and the largest collapse error among them.
struct Member {
  std::string name;
  double rmin, rmax;
  double collapse = 0;
  std::string how;  // "", "clearcoat", "collapsed"
};

std::string Range(double lo, double hi) { return lo == hi ? Num(lo) : "[" + Num(lo) + ", " + Num(hi) + "]"; }

// What an engine does with a sheen layer, where brdfbake knows it
// (docs/engines.md): empty for the others.
std::string EngineSheen(const std::string& preset) {
  if (preset == "filament") {
    return "Filament's lit model shades sheen (sheenColor, sheenRoughness) with the Charlie NDF and the neubelt "
           "visibility and reads its E from the cloth channel (B) of dfg.inc, for the sheen's image-based light and "
           "for the base layer's scaling 1 - max(sheenColor) E";
  }
  if (preset == "godot") {
    return "Godot's DFG carries the Charlie E with the neubelt visibility (its cloth term) in the B channel";
  }
  if (preset == "materialx") {
    return "MaterialX's sheen_bsdf (mx_imageworks_sheen_brdf) reads the sheen albedo, the Charlie E with the "
           "neubelt visibility clamped at 1, from the B channel of its albedo table and scales the layer beneath by "
           "1 - albedo";
  }
  if (preset == "enterprise-pbr") {
    return "Enterprise PBR's pbrlut.hpp ships Sheen_E, the Charlie E with its refined Lambda fit (the "
           "enterprise-pbr visibility)";
  }
  if (preset == "khronos") {
    return "the Khronos renderer's lut_sheen_E.png holds the Charlie E with its V_Sheen capped at 1 (the "
           "conty-kulla-clamped visibility)";
  }
  return "";
}

// How a scene's sheen layers are served: by a channel of the engine's own
// table, by the engine's sheen tables, or by brdfbake's charlie tables.
std::string SheenDecision(const Scene& scene, const std::vector<TableKind>& kinds, bool in_channel) {
  const std::string& preset = scene.engine.preset;
  const std::string engine = EngineSheen(preset);
  if (in_channel) {
    return "engine preset '" + preset + "' serves the sheen from a channel of its own table, over every roughness" +
           (engine.empty() ? "" : " (" + engine + ")") +
           ": no sheen table of its own; that is the engine's visibility, not glTF's conty-kulla one";
  }
  std::string tables;
  for (TableKind k : kinds) {
    tables += std::string(tables.empty() ? "" : " and ") +
              (k == TableKind::kE ? "the charlie E over (mu, sheen roughness), by which glTF scales the base layer "
                                    "(1 - max(sheenColor) E, looked up at the view and at the light)"
                                  : "the charlie E_avg over sheen roughness, for energy-compensation schemes");
  }
  std::string s = "the Charlie NDF with the conty-kulla visibility, as glTF's KHR_materials_sheen defines it (the "
                  "Khronos sample renderer caps its V_Sheen at 1); its Fresnel factor is 1 (sheenColor tints it), so "
                  "no dfg";
  if (kinds.empty()) return s + "; the engine samples no E or E_avg table, so no sheen table is baked";
  s += ": " + tables;
  if (!preset.empty()) {
    std::vector<TableKind> own;
    for (TableKind k : kinds) {
      if (EngineTable(FindPreset(preset), k, ModelKind::kCharlie)) own.push_back(k);
    }
    const PresetTable* own_e = EngineTable(FindPreset(preset), TableKind::kE, ModelKind::kCharlie);
    if (own_e && own_e->spec.model.visibility != SheenVisibility::kContyKulla) {
      s += "; engine preset '" + preset + "' shades it with the " +
           SheenVisibilityName(own_e->spec.model.visibility) + " visibility" + (engine.empty() ? "" : " (" + engine + ")") +
           ", and every sheen table here takes it";
    }
    if (own.size() == kinds.size()) {
      s += ", in engine preset '" + preset + "''s own sheen layout";
    } else {
      s += "; engine preset '" + preset + "' has no " + (own.empty() ? "sheen table" : "sheen E_avg table") +
           (engine.empty() ? "" : " (" + engine + ")") + ": " + (own.empty() ? "they go" : "E_avg goes") +
           " out as brdfbake's own EXR files, for a sheen lobe in its shaders";
    }
  }
  return s;
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

namespace {

// A number that is the whole of `text` (NaN otherwise, which every range
// check refuses).
double WholeNumber(const std::string& text) {
  char* end = nullptr;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                       ? std::numeric_limits<double>::quiet_NaN()
                       : std::strtod(text.c_str(), &end);
  return end && *end == '\0' ? v : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void ApplySceneOverrides(Scene* scene, const SceneOverrides& overrides) {
  SceneEngine& e = scene->engine;
  std::string pixel;
  for (const auto& [option, value] : overrides) {
    if (option == "--preset") {
      FindPreset(value);  // its message names --preset
      e.preset = value;
    } else if (option == "--format") {
      ParseContainer(value);
      e.format = Lowercase(value);
    } else if (option == "--pixel") {
      if (value != "float" && value != "half" && value != "unorm16") {
        Bad("--pixel: expected float, half or unorm16, got '" + value + "'");
      }
      pixel = value;
    } else if (option == "--shader") {
      std::vector<ShaderLanguage> langs;
      std::stringstream ss(value);
      for (std::string item; std::getline(ss, item, ',');) {
        const ShaderLanguage l = ParseShaderLanguage(item);
        if (std::find(langs.begin(), langs.end(), l) != langs.end()) Bad("--shader: '" + item + "' is given twice");
        langs.push_back(l);
      }
      if (value.empty() || value.back() == ',') Bad("--shader: an empty language after the last comma");
      e.shaders = langs;
    } else if (option == "--max-size") {
      const double n = WholeNumber(value);
      if (!(n >= 2 && n <= 8192) || n != std::floor(n)) Bad("--max-size: '" + value + "' is not an integer in [2, 8192]");
      e.max_lut_size = int(n);
    } else if (option == "--error-target") {
      const double t = WholeNumber(value);
      if (!(t >= 1e-7 && t <= 1)) Bad("--error-target: '" + value + "' is outside [1e-07, 1]");
      e.error_target = t;
    } else {
      Bad(option + ": a scene bake takes its settings from the scene file");
    }
    scene->overrides.push_back({option, value});
  }
  if (!pixel.empty()) {
    if (!e.preset.empty()) Bad("--pixel: fixed by the engine preset '" + e.preset + "' (its layout)");
    if (pixel == "unorm16" && (e.format.empty() || ParseContainer(e.format) != Container::kDds)) {
      Bad("--pixel unorm16: only the dds format holds unorm16 pixels (add --format dds)");
    }
    e.unorm16 = pixel == "unorm16";
    e.pixel = pixel == "float" ? PixelType::kFloat : PixelType::kHalf;
  }
  if (e.preset.empty() && !e.format.empty()) {
    const Container c = ParseContainer(e.format);
    if (c == Container::kHeader && e.header) {
      Bad("--format header: the scene writes a header beside each table already (header = true)");
    }
    // A scene's tables are float, half or unorm16: no png (unorm8 or
    // unorm16 codes of values that may exceed 1).
    if (c == Container::kPng) Bad("--format png: a scene's tables are written as exr, header, js, ktx2, dds or inc");
  }
  if (!e.preset.empty() && SceneKinds(*scene).empty() && !EngineServesGlass(*scene)) {
    Bad("engine preset '" + e.preset + "' samples " + PresetTablesText(FindPreset(e.preset)) +
        ", none of the scene's tables");
  }
}

namespace {

// The slots a scene may need, each group's (for an anisotropic group, the
// tables of both choices), sorted by group.
std::vector<Slot> PossibleSlots(const Scene& scene) {
  const std::vector<TableKind> kinds = SceneKinds(scene);
  std::map<std::string, bool> groups;  // group -> anisotropic
  for (const SceneMaterial& m : scene.materials) {
    groups[GroupKey(m)] = m.model == ModelKind::kGgxAniso;
    if (m.model == ModelKind::kGgxAniso) groups[IsoKey(m.masking)] = false;
    if (m.clearcoat > 0) groups["ggx"] = false;
  }
  const std::vector<TableKind> sheen_kinds = SheenKinds(scene);
  if (!sheen_kinds.empty()) groups[kSheenGroup] = false;
  const std::vector<TableKind> glass_kinds = GlassKinds(scene);
  for (const SceneMaterial& m : scene.materials) {
    if (glass_kinds.empty() || !m.transmission) continue;
    groups[kGlassGroup] = false;
    if (m.volume) groups[kGlassInverseGroup] = false;
  }
  std::vector<Slot> slots;
  for (const auto& [group, aniso] : groups) {
    for (TableKind k : group == kSheenGroup ? sheen_kinds : IsGlassGroup(group) ? glass_kinds : kinds) {
      if (aniso && k == TableKind::kDfg) continue;
      if (IsGlassGroup(group) && !GlassSlotBaked(scene, k, group == kGlassInverseGroup)) continue;
      slots.push_back(SlotOf(scene, k, group, aniso));
    }
  }
  return slots;
}

}  // namespace

std::vector<std::string> SceneOutputFiles(const Scene& scene, const std::string& dir) {
  return FilesOf(scene, PossibleSlots(scene), dir);
}

ScenePlan PlanScene(const Scene& scene, const std::function<void(const std::string&)>& progress) {
  ScenePlan plan;
  const Planner planner(scene, progress);
  const std::vector<TableKind> kinds = SceneKinds(scene);
  const double target = scene.engine.error_target;
  auto wants = [&](TableKind k) { return std::find(kinds.begin(), kinds.end(), k) != kinds.end(); };
  const std::vector<TableKind> sheen_kinds = SheenKinds(scene);
  if (planner.preset()) {
    for (TableKind k : scene.engine.tables) {
      if (!wants(k)) {
        const bool sheen_k = std::find(sheen_kinds.begin(), sheen_kinds.end(), k) != sheen_kinds.end();
        plan.notes.push_back(std::string(TableName(k)) + " tables: engine preset '" + scene.engine.preset +
                             "' samples none (only its own tables are baked" +
                             (sheen_k ? std::string("; the sheen layers' charlie ") + TableName(k) + " aside" : "") +
                             ")");
      }
    }
  }
  // Isotropic lookups per group and kind; the model of each group.
  std::map<std::string, std::map<TableKind, std::vector<Member>>> iso;
  std::map<std::string, SceneMaterial> model_of;
  std::map<std::string, std::vector<const SceneMaterial*>> aniso;
  std::vector<const SceneMaterial*> sheen, glass;
  for (const SceneMaterial& m : scene.materials) {
    if (m.transmission) glass.push_back(&m);
    if (!m.transmission && m.ior_given) {
      const double f0_lo = std::pow((m.ior_min - 1) / (m.ior_min + 1), 2);
      const double f0_hi = std::pow((m.ior_max - 1) / (m.ior_max + 1), 2);
      plan.decisions.push_back("material '" + Printable(m.name) + "' (ior " + Range(m.ior_min, m.ior_max) +
                               ", opaque): the ior sets only F0 = ((ior - 1) / (ior + 1))^2 = " +
                               Range(f0_lo, f0_hi) +
                               ", which weights the split-sum terms: the scene's dfg (scale and bias) serves it, "
                               "and E and E_avg (F = 1) do not change");
    }
    if (m.sheen) {
      sheen.push_back(&m);
      SceneMaterial charlie;
      charlie.model = ModelKind::kCharlie;  // the conty-kulla visibility
      model_of.emplace(kSheenGroup, charlie);
      for (TableKind k : sheen_kinds) {
        iso[kSheenGroup][k].push_back({m.name + " (sheen)", m.sheen_roughness_min, m.sheen_roughness_max, 0, "sheen"});
      }
    }
    for (const auto& u : m.unsupported) {
      plan.notes.push_back("material '" + Printable(m.name) + "' (" + u.first + "): " + u.second);
    }
    if (m.clearcoat > 0) {
      SceneMaterial cc;
      cc.model = ModelKind::kGgx;
      model_of.emplace("ggx", cc);
      for (TableKind k : kinds) {
        iso["ggx"][k].push_back({m.name + " (clearcoat)", m.clearcoat_roughness_min, m.clearcoat_roughness_max, 0,
                                 "clearcoat"});
      }
      plan.decisions.push_back(
          "material '" + Printable(m.name) + "' (KHR_materials_clearcoat, roughness " +
          Range(m.clearcoat_roughness_min, m.clearcoat_roughness_max) +
          "): the clearcoat layer is GGX with height-correlated masking at its own roughness; its Fresnel (IOR 1.5, "
          "F0 0.04) weights the split-sum terms and never changes E, E_avg or dfg (they are integrated with F = 1 "
          "or split by Schlick), so it reuses the isotropic GGX tables");
    }
    if (m.model == ModelKind::kGgxAniso) {
      aniso[GroupKey(m)].push_back(&m);
      continue;
    }
    model_of.emplace(GroupKey(m), m);
    for (TableKind k : kinds) iso[GroupKey(m)][k].push_back({m.name, m.roughness_min, m.roughness_max, 0, ""});
  }
  // Sheen layers: the charlie tables over their roughness, or the engine's
  // channel.
  double smin = 1, smax = 0;
  size_t sheen_decision = 0;
  if (!sheen.empty()) {
    std::string names;
    for (const SceneMaterial* m : sheen) {
      smin = std::min(smin, m->sheen_roughness_min);
      smax = std::max(smax, m->sheen_roughness_max);
      names += (names.empty() ? "'" : ", '") + Printable(m->name) + "'";
    }
    const std::string who = "the sheen layer" + std::string(sheen.size() > 1 ? "s" : "") + " of " + names +
                            " (sheen roughness " + Range(smin, smax) + ")";
    const bool in_channel = SheenInEngineChannel(scene);
    sheen_decision = plan.decisions.size();
    plan.decisions.push_back(who + ": " + SheenDecision(scene, sheen_kinds, in_channel));
    if (sheen_kinds.empty() && !in_channel) {
      plan.notes.push_back(who + ": the charlie E over (mu, sheen roughness) that glTF's sheen scales the base layer "
                                 "by: the engine samples no E or E_avg table (its 'tables')");
    }
  }
  // Transmissive materials: the ggx-glass E and E_avg over their box,
  // entering the medium, and for volumes leaving it too.
  std::vector<PlannedTable> glass_tables;
  const std::vector<TableKind> glass_kinds = GlassKinds(scene);
  if (!glass.empty()) {
    GlassBox box;
    std::string names;
    bool volume = false;
    for (const SceneMaterial* m : glass) {
      box.rmin = std::min(box.rmin, m->roughness_min);
      box.rmax = std::max(box.rmax, m->roughness_max);
      box.ior_min = std::min(box.ior_min, m->ior_min);
      box.ior_max = std::max(box.ior_max, m->ior_max);
      volume |= m->volume;
      names += (names.empty() ? "'" : ", '") + Printable(m->name) + "'";
    }
    std::string d = "transmissive material" + std::string(glass.size() > 1 ? "s " : " ") + names +
                    " (KHR_materials_transmission, roughness " + Range(box.rmin, box.rmax) + ", ior " +
                    Range(box.ior_min, box.ior_max) +
                    "): the rough dielectric over GGX (ggx-glass: reflection by the exact Fresnel plus refraction, "
                    "[Walter07])";
    // An engine with glass tables of its own gets those only; one without
    // gets brdfbake's files.
    const bool engine_glass = planner.preset() && EngineHasGlass(*planner.preset());
    const PresetTable* schlick = planner.GlassEngine(TableKind::kE, false);
    if (schlick && schlick->spec.part != DielectricPart::kTransmissionSchlick) schlick = nullptr;
    if (glass_kinds.empty()) {
      d += "; the engine samples no E or E_avg table, so no glass table is baked";
    } else if (schlick) {
      d += "; engine preset '" + scene.engine.preset + "' ships its own glass table for light entering the medium, " +
           schlick->symbol +
           ": the refraction without F weighted by 1 - (1 - wo.h)^5, which its renderer scales by 1 - F0, at the "
           "engine's axes and size, its lookup error measured over the materials' range";
    } else {
      d += engine_glass ? ": its E over (mu, roughness, ior) and E_avg over (roughness, ior), the ior axis in z = "
                          "F0^(1/4)"
                        : ": its E over (mu, roughness, ior) and E_avg over (roughness, ior), over the materials' ior "
                          "range only, the ior axis in z = F0^(1/4)";
      d += volume ? "; a volume (KHR_materials_volume) also lets light leave the medium: the inverse tables "
                    "(eta = 1 / ior, total internal reflection beyond the critical angle)"
                  : "; thin-walled (no KHR_materials_volume): light only enters, eta = ior";
      if (planner.preset()) {
        d += engine_glass ? "; engine preset '" + scene.engine.preset + "' ships its own glass tables: those, at the "
                                "engine's axes and size, their lookup error measured over the materials' range"
                          : "; engine preset '" + scene.engine.preset + "' ships no glass table: brdfbake's own EXR "
                                                                        "files";
      }
    }
    d += "; its specular reflection looks up the isotropic GGX tables as the opaque materials do";
    plan.decisions.push_back(d);
    for (bool inverse : {false, true}) {
      if (inverse && !volume) continue;
      const std::string group = inverse ? kGlassInverseGroup : kGlassGroup;
      for (TableKind k : glass_kinds) {
        const std::string label = std::string(TableName(k)) + " " + group;
        if (!GlassSlotBaked(scene, k, inverse)) {
          const PresetTable* entering = planner.GlassEngine(k, false);
          const bool two_sided = inverse && entering && entering->spec.ior.warp == Warp::kTwoSided;
          std::string n = std::string(TableName(k)) + " of the glass" +
                          (inverse ? " leaving the medium (the volumes)" : " entering the medium") +
                          ": engine preset '" + scene.engine.preset + "'";
          n += two_sided ? " holds it in its own glass table, whose ior axis covers both sides (eta = 1 / ior below "
                           "1), so no table of its own is baked"
                         : " samples no such table of its own (its renderer serves it otherwise), so none is baked";
          plan.notes.push_back(n);
          continue;
        }
        const PresetTable* et = planner.GlassEngine(k, inverse);
        PlannedTable p = et ? planner.PlanEngineGlass(*et, box, label)
                            : planner.PlanGlass(planner.GlassBase(k, box, inverse), label);
        p.group = group;
        for (const SceneMaterial* m : glass) {
          if (!inverse || m->volume) p.materials.push_back(m->name);
        }
        p.file = TableFile(scene, {k, group, true});
        p.why = "used by " + std::to_string(p.materials.size()) + " transmissive material" +
                (p.materials.size() > 1 ? "s" : "") + ", roughness " + Range(box.rmin, box.rmax) + ", ior " +
                Range(box.ior_min, box.ior_max) +
                (inverse ? "; light leaving the medium (eta = 1 / ior)" : "; light entering the medium (eta = ior)");
        glass_tables.push_back(std::move(p));
      }
    }
  }
  // Anisotropic groups: the 4D tables over their box, or the isotropic
  // tables at the collapsed roughness, whichever meets the target smaller.
  std::vector<PlannedTable> aniso_tables;
  for (const auto& [group, members] : aniso) {
    const Masking masking = members.front()->masking;
    AnisoBox box;
    std::string names;
    for (const SceneMaterial* m : members) {
      box.rmin = std::min(box.rmin, m->roughness_min);
      box.rmax = std::max(box.rmax, m->roughness_max);
      box.smin = std::min(box.smin, m->anisotropy_min);
      box.smax = std::max(box.smax, m->anisotropy);
      names += (names.empty() ? "'" : ", '") + Printable(m->name) + "'";
    }
    const double rc_min = CollapsedRoughness(box.rmin, box.smin), rc_max = CollapsedRoughness(box.rmax, box.smax);
    SceneMaterial ggx;
    ggx.model = ModelKind::kGgx;
    ggx.masking = masking;
    model_of.emplace(IsoKey(masking), ggx);
    // The collapse's error over the box (report's collapse study): E over
    // mu (square warp from 1e-4: the grazing layer), phi_o, r and s.
    BakeSpec study = planner.AnisoBase(TableKind::kE, masking, box);
    study.mu = Axis{"mu", 13, 1e-4, 1.0, Warp::kSquare, Placement::kEdges};
    study.phi = Axis{"phi_o", 7, 0.0, kHalfPi, Warp::kLinear, Placement::kEdges};
    SetAxis(&study.roughness, box.rmin, box.rmax, 5, Placement::kEdges);
    SetAxis(&study.anisotropy, box.smin, box.smax, 5, Placement::kEdges);
    std::map<TableKind, double> collapse;
    for (const CollapseRow& row : CollapseStudy(study, {kCollapse})) {
      collapse[TableKind::kE] = std::max(collapse[TableKind::kE], row.max_abs_error);
    }
    // dfg has no anisotropic counterpart: its scale + bias is E, off by
    // the same.
    collapse[TableKind::kDfg] = collapse[TableKind::kE];
    if (wants(TableKind::kEavg)) {
      BakeSpec avg = study;
      avg.table = TableKind::kEavg;
      SetAxis(&avg.roughness, box.rmin, box.rmax, 3, Placement::kEdges);
      SetAxis(&avg.anisotropy, box.smin, box.smax, 3, Placement::kEdges);
      for (const CollapseRow& row : CollapseStudy(avg, {kCollapse})) {
        collapse[TableKind::kEavg] = std::max(collapse[TableKind::kEavg], row.max_abs_error);
      }
    }
    const std::string who = "anisotropic GGX (" + group + ": " + names + ", roughness " + Range(box.rmin, box.rmax) +
                            ", anisotropy " + Range(box.smin, box.smax) + ")";
    const std::string collapsed = "the collapsed roughness r_c = (alpha_t alpha_b)^(1/4) in " + Range(rc_min, rc_max) +
                                  " (the geometric mean of the widths, as Cycles, MaterialX and Enterprise PBR)";
    // (b): isotropic tables over the collapsed range alone.
    std::vector<TableKind> choice_kinds;
    for (TableKind k : kinds) {
      if (k != TableKind::kDfg) choice_kinds.push_back(k);
    }
    bool b_meets = true, a_meets = true;
    int64_t b_texels = 0, a_texels = 0;
    double b_error = 0, a_error = 0;
    std::vector<PlannedTable> a_plan;
    std::string b_text, a_text;
    for (TableKind k : choice_kinds) {
      const PlannedTable b = planner.PlanIso(planner.IsoBase(k, ggx, rc_min, rc_max), rc_min, rc_max, collapse[k],
                                             std::string(TableName(k)) + " " + group + " collapsed", false);
      b_meets &= b.meets_target;
      b_texels += Texels(b.table);
      b_error = std::max(b_error, b.total_error + b.collapse_error);
      b_text += std::string(b_text.empty() ? "" : ", ") + TableName(k) + " " + SizeText(b.table) + " (collapse " +
                Num(b.collapse_error) + " + lookup " + Num(b.total_error) + ")";
      PlannedTable a = planner.PlanAniso(planner.AnisoBase(k, masking, box), std::string(TableName(k)) + " " + group,
                                         b.meets_target ? Texels(b.table) : std::numeric_limits<int64_t>::max());
      const bool a_ok = std::isfinite(a.total_error);
      a_meets &= a_ok && a.meets_target;
      a_texels += a_ok ? Texels(a.table) : 0;
      a_error = std::max(a_error, a_ok ? a.total_error : std::numeric_limits<double>::infinity());
      a_text += std::string(a_text.empty() ? "" : ", ") + TableName(k) + " " +
                (a_ok ? SizeText(a.table) + " (lookup " + Num(a.total_error) + ")" : "larger than that");
      if (a_ok) a_plan.push_back(std::move(a));
    }
    bool use_4d;
    std::string why;
    const std::string tgt = "the target " + Num(target);
    const std::string a_says = "the 4D ggx-aniso tables over the box: " + a_text;
    const std::string b_says = "isotropic GGX at " + collapsed + ": " + b_text;
    if (choice_kinds.empty()) {
      use_4d = false;
      why = "the engine samples no E or E_avg table: its dfg is looked up at " + collapsed;
    } else if (a_meets && b_meets) {
      use_4d = a_texels < b_texels;
      why = "both meet " + tgt + "; " + (use_4d ? a_says + " (" + std::to_string(a_texels) + " texels) is smaller than " + b_says
                                               : b_says + " (" + std::to_string(b_texels) + " texels) is smaller than " + a_says);
    } else if (b_meets) {
      use_4d = false;
      why = b_says + " meets " + tgt + " (" + std::to_string(b_texels) + " texels); " + a_says;
    } else if (a_meets) {
      use_4d = true;
      why = a_says + " meets " + tgt + "; " + b_says + " does not";
    } else {
      use_4d = a_error < b_error;
      why = "neither meets " + tgt + ": " + a_says + "; " + b_says + "; the smaller error (" +
            Num(std::min(a_error, b_error)) + ") is kept";
    }
    plan.decisions.push_back(who + ": " + (use_4d ? "the 4D tables; " : "the isotropic tables at the collapsed roughness; ") +
                             why + (wants(TableKind::kDfg) ? "; dfg has no anisotropic table: the base layer looks it up at the collapsed roughness, its scale + bias (= E) off by up to " + Num(collapse[TableKind::kDfg]) : ""));
    for (TableKind k : kinds) {
      const bool collapsed_k = k == TableKind::kDfg || !use_4d;
      if (!collapsed_k) continue;
      for (const SceneMaterial* m : members) {
        iso[IsoKey(masking)][k].push_back({m->name + " (collapsed)", CollapsedRoughness(m->roughness_min, m->anisotropy_min),
                                            CollapsedRoughness(m->roughness_max, m->anisotropy), collapse[k], "collapsed"});
      }
    }
    if (use_4d) {
      for (PlannedTable& a : a_plan) {
        a.group = group;
        for (const SceneMaterial* m : members) a.materials.push_back(m->name);
        a.file = TableFile(scene, {a.spec.table, group, true});
        a.why = "used by " + std::to_string(members.size()) + " anisotropic material" + (members.size() > 1 ? "s" : "") +
                ", roughness " + Range(box.rmin, box.rmax) + ", anisotropy " + Range(box.smin, box.smax);
        if (planner.preset()) a.why += "; engine preset '" + scene.engine.preset + "' has no layout for it: brdfbake's own";
        if (!a.meets_target) {
          a.hint = planner.AnisoHint(planner.AnisoBase(a.spec.table, masking, box),
                                     std::string(TableName(a.spec.table)) + " " + group);
        }
        aniso_tables.push_back(std::move(a));
      }
    }
  }
  // Isotropic groups, sorted; the anisotropic tables after their group's
  // name sorts them.
  for (const auto& [group, by_kind] : iso) {
    const SceneMaterial& model = model_of.at(group);
    for (TableKind kind : group == kSheenGroup ? sheen_kinds : kinds) {
      const auto it = by_kind.find(kind);
      if (it == by_kind.end()) continue;
      const std::vector<Member>& ms = it->second;
      double rmin = 1, rmax = 0, collapse = 0;
      std::vector<std::string> names;
      std::string extra;
      int plain = 0;
      for (const Member& m : ms) {
        rmin = std::min(rmin, m.rmin);
        rmax = std::max(rmax, m.rmax);
        collapse = std::max(collapse, m.collapse);
        names.push_back(m.name);
        plain += m.how.empty() ? 1 : 0;
        if (m.how == "collapsed") extra += "; " + m.name + " at roughness " + Range(m.rmin, m.rmax);
        if (m.how == "clearcoat") extra += "; " + m.name + " at roughness " + Range(m.rmin, m.rmax);
      }
      const std::string label = std::string(TableName(kind)) + " " + group;
      PlannedTable p = planner.PlanIso(planner.IsoBase(kind, model, rmin, rmax), rmin, rmax, collapse, label, true);
      p.materials = names;
      p.group = group;
      p.file = TableFile(scene, {kind, group});
      const Slot slot = SlotOf(scene, kind, group, false);
      if (group == kSheenGroup) {
        p.why = "used by the sheen layer of " + std::to_string(ms.size()) + " material" + (ms.size() > 1 ? "s" : "") +
                " (the Charlie NDF with the " + SheenVisibilityName(p.spec.model.visibility) + " visibility" +
                (p.spec.model.visibility == SheenVisibility::kContyKulla ? ", as glTF's KHR_materials_sheen"
                                                                         : ", the engine's") +
                "), sheen roughness " +
                Range(rmin, rmax) +
                (kind == TableKind::kE ? "; the base layer under it is scaled by 1 - max(sheenColor) E(NoV, r), E "
                                         "looked up at the view and at the light"
                                       : "; E_avg, for energy-compensation schemes");
        if (slot.generic) {
          p.why += "; engine preset '" + scene.engine.preset + "' has no sheen " +
                   (kind == TableKind::kE ? "table" : std::string(TableName(kind)) + " table") + ": brdfbake's own";
        }
      } else {
        p.why = "used by " + std::to_string(ms.size()) + " material" + (ms.size() > 1 ? "s" : "") + " with model " +
                group + ", roughness " + Range(rmin, rmax) + extra;
      }
      if (p.size_fixed) p.why += "; size fixed by engine preset '" + scene.engine.preset + "'";
      if (planner.preset() && !slot.generic) {
        p.why += "; axes as the engine's shader samples them, the lookup error measured over the materials' roughness";
      }
      plan.tables.push_back(std::move(p));
    }
  }
  for (PlannedTable& a : aniso_tables) plan.tables.push_back(std::move(a));
  for (PlannedTable& g : glass_tables) plan.tables.push_back(std::move(g));
  std::stable_sort(plan.tables.begin(), plan.tables.end(),
                   [](const PlannedTable& x, const PlannedTable& y) { return x.group < y.group; });
  // Under a preset, the files are the engine's.
  if (planner.preset()) {
    std::vector<Slot> slots;
    std::vector<const PlannedTable*> planned;
    for (const PlannedTable& p : plan.tables) {
      slots.push_back(SlotOf(scene, p.spec.table, p.group, p.spec.Anisotropic()));
      planned.push_back(&p);
    }
    const Preset sp = ScenePreset(scene, slots, planned);
    for (size_t i = 0; i < plan.tables.size(); ++i) {
      const PresetTable& pt = sp.tables[i];
      plan.tables[i].file = pt.file.empty() ? sp.header_file : pt.file;
      if (!scene.engine.format.empty() && !pt.file.empty()) {
        for (const PresetFile& f : PresetFiles(sp, ScenePresetRun(scene, "."))) {
          if (f.table == int(i) && !f.lookup) plan.tables[i].file = std::filesystem::path(f.path).filename().string();
        }
      }
    }
  }
  // The engine's sheen channel: its lookup error over the sheen roughness,
  // the channel's table (the Charlie E with the engine's visibility)
  // baked over the axes of the first planned table that carries it, and
  // probed as the planned tables are (before the engine's pixel rounding
  // and any clamp of its layout).
  if (!sheen.empty() && SheenInEngineChannel(scene)) {
    const PresetTable& carrier = *SheenChannelTable(*planner.preset());
    for (const PlannedTable& p : plan.tables) {
      if (p.spec.table != carrier.spec.table || SlotOf(scene, p.spec.table, p.group, p.spec.Anisotropic()).generic) {
        continue;
      }
      for (const BakeSpec& w : carrier.with) {
        if (w.model.kind != ModelKind::kCharlie) continue;
        BakeSpec channel = w;
        channel.mu = p.table.spec.mu;
        channel.roughness = p.table.spec.roughness;
        channel.threads = p.table.spec.threads;
        ProbeOptions probe;
        probe.roughness_min = smin;
        probe.roughness_max = smax;
        const Table ct = Bake(channel);
        const double error = LookupError(ct, probe).max_abs_error + ct.integration_error;
        if (progress) progress("sheen channel of " + p.file + " " + SizeText(ct) + ": lookup error " + Num(error));
        plan.decisions[sheen_decision] +=
            "; in " + p.file + " (" + SizeText(ct) + ") the channel's bilinear lookup error over the sheen roughness is " +
            Num(error) + (error <= target ? ", within" : ", ABOVE") + " the target " + Num(target) +
            " (before the engine's pixel rounding)";
        break;
      }
      break;
    }
  }
  return plan;
}

std::string PlanText(const Scene& scene, const ScenePlan& plan) {
  std::ostringstream os;
  const SceneEngine& e = scene.engine;
  os << "scene " << Printable(scene.path) << ": " << scene.materials.size() << " material"
     << (scene.materials.size() == 1 ? "" : "s") << "; engine: ";
  if (!e.preset.empty()) {
    os << "preset " << e.preset << " (its layouts and containers), max LUT " << e.max_lut_size << ", error target "
       << Num(e.error_target);
  } else {
    os << "max LUT " << e.max_lut_size << ", " << (e.unorm16 ? "unorm16" : PixelTypeName(e.pixel)) << ", "
       << PlacementName(e.placement) << ", error target " << Num(e.error_target) << (e.complement ? ", complement" : "");
  }
  if (!e.format.empty()) os << ", format " << e.format;
  os << "\n";
  if (!scene.overrides.empty()) {
    os << "overrides:";
    for (const auto& [option, value] : scene.overrides) os << " " << option << " " << Printable(value);
    os << "\n";
  }
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    const PlannedTable& p = plan.tables[i];
    const Table& t = p.table;
    // The sheen has a visibility term, not a masking variant.
    std::string shape = p.spec.model.kind == ModelKind::kCharlie
                            ? std::string(SheenVisibilityName(p.spec.model.visibility)) + " visibility"
                            : MaskingName(p.spec.masking);
    if (p.spec.Glass() && p.spec.part != DielectricPart::kBoth) {
      shape += std::string(", part ") + DielectricPartName(p.spec.part);
    }
    os << "table " << i + 1 << ": " << p.file << " (" << TableName(p.spec.table) << ", " << shape << "), " << p.why
       << "\n";
    os << "  materials:";
    for (const std::string& m : p.materials) os << " " << Printable(m);
    os << "\n  axes:";
    for (const Axis& a : t.axes) {
      os << " " << a.name << " " << a.size << " in [" << Num(a.min) << ", " << Num(a.max) << "] " << WarpName(a.warp)
         << " " << PlacementName(a.placement) << ";";
    }
    os << "\n  bilinear lookup error " << Num(p.total_error) << " (interpolation at cell midpoints, axis ends, the grazing "
       << "layer and the mirror cut " << Num(p.interpolation_error) << ", integration " << Num(t.integration_error) << ")";
    if (p.collapse_error > 0) os << " + collapse " << Num(p.collapse_error);
    os << " " << (p.meets_target ? "<= target " : "ABOVE the target ") << Num(e.error_target);
    if (!p.meets_target) os << (p.size_fixed ? " (the engine's size)" : " (the largest size allowed)");
    os << "\n";
    if (!p.hint.empty()) os << "  to meet the target: " << p.hint << "\n";
  }
  for (const std::string& d : plan.decisions) os << "decision: " << d << "\n";
  for (const std::string& n : plan.notes) os << "not baked: " << n << "\n";
  return os.str();
}

std::vector<std::string> WriteScenePlan(const Scene& scene, const ScenePlan& plan, const std::string& dir) {
  std::vector<Slot> slots;
  std::vector<const PlannedTable*> planned;
  for (const PlannedTable& p : plan.tables) {
    slots.push_back(SlotOf(scene, p.spec.table, p.group, p.spec.Anisotropic()));
    planned.push_back(&p);
  }
  const std::vector<std::string> files = FilesOf(scene, slots, dir);
  for (const std::string& f : files) CheckOutputPath(f);
  nlohmann::json manifest;
  manifest["brdfbake"] = BRDFBAKE_VERSION;
  manifest["scene"] = scene.path;
  manifest["engine"] = {{"max_lut_size", scene.engine.max_lut_size},
                        {"pixel", scene.engine.unorm16 ? "unorm16" : PixelTypeName(scene.engine.pixel)},
                        {"placement", PlacementName(scene.engine.placement)},
                        {"error_target", scene.engine.error_target},
                        {"complement", scene.engine.complement}};
  if (!scene.engine.preset.empty()) manifest["engine"]["preset"] = scene.engine.preset;
  if (!scene.engine.format.empty()) manifest["engine"]["format"] = scene.engine.format;
  manifest["overrides"] = nlohmann::json::object();
  for (const auto& [option, value] : scene.overrides) manifest["overrides"][option] = value;
  // The tables in the engine's files (its preset) or their own, through
  // the one orchestration of outputs.h.
  OutputSet set;
  std::vector<Table> tables;
  for (const PlannedTable& p : plan.tables) tables.push_back(p.table);
  if (!scene.engine.preset.empty()) {
    set = PresetOutputs(ScenePreset(scene, slots, planned), ScenePresetRun(scene, dir));
  } else {
    for (size_t i = 0; i < plan.tables.size(); ++i) {
      PresetTable pt;
      pt.spec = plan.tables[i].table.spec;
      pt.layout = plan.tables[i].layout;
      set.preset.tables.push_back(pt);
      for (const OutputFile& f : OwnFilesOf(scene, slots[i], dir, int(i))) set.files.push_back(f);
    }
  }
  WriteOutputs(set, tables, ArrangeOutputs(set, tables));
  // Each table's files: its own (the first that holds it alone; a
  // preset's header for a table without a file of its own), then the
  // others that hold it.
  std::vector<std::string> own(plan.tables.size());
  std::vector<nlohmann::json> extra(plan.tables.size(), nlohmann::json::array());
  for (const OutputFile& f : set.files) {
    const std::string name = std::filesystem::path(f.path).filename().string();
    if (f.table < 0) {
      for (size_t i = 0; i < plan.tables.size(); ++i) {
        if (set.preset.tables[i].file.empty()) own[i] = name;
      }
    } else if (!f.lookup && own[size_t(f.table)].empty()) {
      own[size_t(f.table)] = name;
    } else {
      extra[size_t(f.table)].push_back(name);
    }
  }
  manifest["tables"] = nlohmann::json::array();
  for (size_t i = 0; i < plan.tables.size(); ++i) {
    const PlannedTable& p = plan.tables[i];
    nlohmann::json axes = nlohmann::json::array();
    for (const Axis& a : p.table.axes) axes.push_back(nlohmann::json::parse(a.ToJson()));
    nlohmann::json entry = {{"file", own[i]},
                            {"table", TableName(p.spec.table)},
                            {"model", nlohmann::json::parse(p.table.model_json)},
                            {"materials", p.materials},
                            {"why", p.why},
                            {"axes", axes},
                            {"seconds", p.table.seconds},
                            {"max_abs_error", p.table.max_abs_error},
                            {"interpolation_error", p.interpolation_error},
                            {"lookup_error", p.total_error},
                            {"meets_target", p.meets_target},
                            {"also", extra[i]}};
    // The sheen's visibility is in its model; it has no masking variant.
    if (p.spec.model.kind != ModelKind::kCharlie) entry["masking"] = MaskingName(p.spec.masking);
    if (p.collapse_error > 0) entry["collapse_error"] = p.collapse_error;
    if (p.size_fixed) entry["size_fixed_by_engine"] = true;
    if (!p.hint.empty()) entry["to_meet_the_target"] = p.hint;
    manifest["tables"].push_back(entry);
  }
  manifest["decisions"] = plan.decisions;
  manifest["not_baked"] = plan.notes;
  WriteFileAtomically(dir + "/manifest.json", manifest.dump(2) + "\n");
  return files;
}

}  // namespace brdfbake
