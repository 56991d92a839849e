// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The generated shader lookups. GLSL runs in a real browser: headless
// Chromium with WebGL2 on its software rasterizer uploads each preset's
// table, calls the generated function at random (NoV, roughness) points and
// at the edges and clamps, and reads the results back as floats; they are
// compared with a CPU model of the same bilinear lookup and with brdfbake's
// exact values. WGSL runs the same way in Chromium's WebGPU (Dawn and Tint
// on SwiftShader's Vulkan) in a compute shader. HLSL is compiled by
// glslangValidator.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/model.h"
#include "brdfbake/presets.h"
#include "brdfbake/shaders.h"
#include "util/file_util.h"
#include "util/lookup_util.h"

namespace brdfbake {
namespace {

using test::Have;
using test::Slurp;
using test::WriteText;

std::string Scratch(const std::string& name) { return test::Scratch("shader_" + name); }

// Runs a page in headless Chromium and returns the text of <pre id="out">.
std::string RunPage(const std::string& dir, const std::string& html, const std::string& extra_flags) {
  WriteText(dir + "/page.html", html);
  const std::string cmd =
      "timeout 120 chromium --headless --no-sandbox --disable-background-networking --disable-component-update "
      "--disable-sync --no-first-run --disable-quic --user-data-dir=" + dir + "/profile " + extra_flags +
      " --dump-dom file://" + dir + "/page.html > " + dir + "/dom.html 2> " + dir + "/chromium.log";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << Slurp(dir + "/chromium.log").substr(0, 2000);
  const std::string dom = Slurp(dir + "/dom.html");
  const size_t a = dom.find("<pre id=\"out\">"), b = dom.find("</pre>", a);
  if (a == std::string::npos || b == std::string::npos) return "no output: " + dom.substr(0, 500);
  return dom.substr(a + 14, b - a - 14);
}

struct Baked {
  Table table;
  Image image;
};

// A table to look up: a preset's, or one of the table kinds with more
// than two axes or with a single-entry axis.
struct Case {
  std::string name;
  std::string preset;  // empty: `spec` with its default layout
  size_t table = 0;
  BakeSpec spec;
};

// gtest prints a parameter in the test's name: the case's name.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

Baked BakeCase(const Case& c) {
  if (!c.preset.empty()) {
    const PresetTable& pt = FindPreset(c.preset).tables.at(c.table);
    Baked b{Bake(pt.spec), {}};
    b.image = ArrangePresetTable(pt, b.table);
    return b;
  }
  Baked b{Bake(c.spec), {}};
  b.image = ArrangeTable(b.table, DefaultLayout(b.table));
  return b;
}

Case PresetCase(const std::string& preset, size_t table) {
  return {preset + "_" + std::to_string(table), preset, table, {}};
}

// Small tables of every kind the lookups read: a gamma axis (3 axes; E_avg
// 2), ggx-aniso (4 axes; E_avg 2), the ellipsoid (mu x phi_o), and
// single-entry axes (one roughness; one anisotropy in a 4-axis table).
// The families this build leaves out (BRDFBAKE_MODELS) are skipped.
std::vector<Case> KindCases() {
  std::vector<Case> cases;
  const auto built = [](const Case& c) { return ModelBuilt(c.spec.model.kind); };
  auto centres = [](Axis& a, int n) {
    a.size = n;
    a.placement = Placement::kCenters;
  };
  {
    BakeSpec s;
    s.model.kind = ModelKind::kStudentT;
    s.table = TableKind::kE;
    s.mu.size = 9;
    s.roughness.size = 7;
    s.gamma.size = 5;
    s.gamma.min = 1.6;
    cases.push_back({"std_gamma_E", "", 0, s});
    s.table = TableKind::kEavg;
    cases.push_back({"std_gamma_Eavg", "", 0, s});
    s.table = TableKind::kDfg;
    s.half = true;
    centres(s.mu, 8);
    centres(s.gamma, 4);
    cases.push_back({"std_gamma_dfg_half", "", 0, s});
  }
  {
    BakeSpec s;
    s.model.kind = ModelKind::kGgxAniso;
    s.table = TableKind::kE;
    s.mu.size = 6;
    s.phi.size = 4;
    s.roughness.size = 5;
    s.anisotropy.size = 3;
    cases.push_back({"ggx_aniso_E", "", 0, s});
    centres(s.anisotropy, 1);
    s.anisotropy.min = s.anisotropy.max = 0.6;
    cases.push_back({"ggx_aniso_E_one_anisotropy", "", 0, s});
    s.table = TableKind::kEavg;
    s.roughness.size = 8;
    s.anisotropy = BakeSpec().anisotropy;
    s.anisotropy.size = 5;
    cases.push_back({"ggx_aniso_Eavg", "", 0, s});
  }
  {
    // ggx-glass: the ior axis in z = F0^(1/4) (fresnel-z), slices of mu x
    // roughness; E_avg over roughness x ior; the inverse side.
    BakeSpec s;
    s.model.kind = ModelKind::kGgxGlass;
    s.table = TableKind::kE;
    s.mu.size = 6;
    s.roughness.size = 5;
    s.roughness.min = 0.1;
    s.ior.size = 4;
    s.ior.min = 1.2;
    s.ior.max = 2.5;
    s.tolerance = 1e-5;
    cases.push_back({"ggx_glass_E", "", 0, s});
    s.inverse = true;
    centres(s.ior, 3);
    cases.push_back({"ggx_glass_E_inverse", "", 0, s});
    s.inverse = false;
    s.table = TableKind::kEavg;
    s.roughness.size = 4;
    cases.push_back({"ggx_glass_Eavg", "", 0, s});
  }
  {
    BakeSpec s;
    s.model.kind = ModelKind::kEllipsoid;
    s.model.alpha_x = 0.3;
    s.model.alpha_y = 0.08;
    s.model.theta_x = 0.4;
    s.model.theta_z = 0.7;
    s.table = TableKind::kE;
    s.mu.size = 8;
    s.phi.size = 9;
    s.phi.max = 2 * kPi<double>;
    cases.push_back({"ellipsoid_E", "", 0, s});
  }
  {
    // The F82-tint term, separable masking, as EEVEE's axes warp mu.
    BakeSpec s;
    s.table = TableKind::kF82Bias;
    s.masking = Masking::kSeparable;
    s.mu.size = 9;
    s.mu.warp = Warp::kOneMinusSquare;
    s.roughness.size = 7;
    cases.push_back({"f82_bias", "", 0, s});
  }
  {
    BakeSpec s;
    s.table = TableKind::kDfg;
    centres(s.mu, 16);
    centres(s.roughness, 1);
    s.roughness.min = s.roughness.max = 0.45;
    cases.push_back({"dfg_one_roughness", "", 0, s});
  }
  cases.erase(std::remove_if(cases.begin(), cases.end(), [&](const Case& c) { return !built(c); }), cases.end());
  return cases;
}

// The presets whose model families this build holds (BRDFBAKE_MODELS).
std::vector<Case> AllCases() {
  std::vector<Case> cases;
  for (const Case& c : {PresetCase("three", 0), PresetCase("filament", 0), PresetCase("hdrp", 0),
                        PresetCase("bevy", 0), PresetCase("materialx", 0), PresetCase("cycles", 0),
                        PresetCase("cycles", 1), PresetCase("cycles", 2), PresetCase("cycles", 7), PresetCase("godot", 0), PresetCase("unreal", 0),
                        PresetCase("enterprise-pbr", 0), PresetCase("enterprise-pbr", 1)}) {
    if (PresetBuilt(FindPreset(c.preset))) cases.push_back(c);
  }
  for (const Case& c : KindCases()) cases.push_back(c);
  return cases;
}

// The physical value of image axis `a` among a point's inputs, which come
// in the table's axis order.
double InputFor(const Table& t, const Axis& a, const std::vector<double>& in) {
  for (size_t k = 0; k < t.axes.size(); ++k) {
    if (t.axes[k].name == a.name) return in[k];
  }
  ADD_FAILURE() << "no input for axis " << a.name;
  return 0;
}

// What the function should return for inputs `in`, by a CPU model of the
// lookup: the texture unit's bilinear filter over axes 0 and 1 (within a
// slice, clamped to its first and last row centres), linear between the
// neighbouring slices of each further axis (docs/format.md).
std::vector<double> ModelLookup(const Table& t, const Image& im, const std::vector<double>& in) {
  const std::vector<Axis>& axes = im.axes;
  const size_t n = axes.size();
  const double u = n >= 1 ? test::TextureCoordinate(axes[0], InputFor(t, axes[0], in)) : 0.5;
  const double cy = n >= 2 ? test::TextureCoordinate(axes[1], InputFor(t, axes[1], in)) : 0.5;
  const int rows = n >= 2 ? axes[1].size : 1;
  std::vector<double> s(im.channels, 0.0);
  auto sample = [&](int slice, double weight) {
    double v = n > 2 ? (slice * rows + std::clamp(cy * rows, 0.5, rows - 0.5)) / im.height : cy;
    if (im.flip_rows) v = 1 - v;
    for (int c = 0; c < im.channels; ++c) {
      auto at = [&](int x, int y) { return im.values[(size_t(y) * im.width + x) * im.channels + c]; };
      s[c] += weight * test::TextureBilinear(at, im.width, im.height, u, v);
    }
  };
  if (n <= 2) {
    sample(0, 1.0);
  } else {
    // Corners of the slice axes, each with the product of its weights.
    const size_t k_axes = n - 2;
    for (int corner = 0; corner < (1 << k_axes); ++corner) {
      int slice = 0, stride = 1;
      double weight = 1;
      for (size_t k = 0; k < k_axes; ++k) {
        const Axis& a = axes[2 + k];
        const double f =
            std::clamp(test::TextureCoordinate(a, InputFor(t, a, in)) * a.size - 0.5, 0.0, a.size - 1.0);
        const int i0 = int(std::floor(f)), i1 = std::min(i0 + 1, a.size - 1);
        const double w = f - i0;
        const bool hi = (corner >> k) & 1;
        slice += stride * (hi ? i1 : i0);
        weight *= hi ? w : 1 - w;
        stride *= a.size;
      }
      sample(slice, weight);
    }
  }
  auto find = [&](const char* src) {
    for (size_t c = 0; c < im.channel_sources.size(); ++c) {
      if (im.channel_sources[c] == src) return int(c);
    }
    return -1;
  };
  if (t.spec.table == TableKind::kDfg) {
    const int sc = find("dfg.scale"), bi = find("dfg.bias"), e = find("E");
    const double bias = bi >= 0 ? s[bi] : s[e] - s[sc];
    const double scale = sc >= 0 ? s[sc] : s[e] - bias;
    return {scale, bias};
  }
  if (t.spec.GenSchlick()) return {s[find("s")]};
  if (t.spec.table == TableKind::kF82Bias) return {s[find("f82_bias")]};
  const bool eavg = t.spec.table == TableKind::kEavg;
  const int direct = find(eavg ? "E_avg" : "E");
  return {direct >= 0 ? s[direct] : 1 - s[find(eavg ? "1-E_avg" : "1-E")]};
}

// brdfbake's exact values of a 2D (NoV, roughness) GGX preset table, with
// the table's ranges and clamps.
std::vector<double> ExactLookup(const Table& t, double nov, double r) {
  const BakeSpec& s = t.spec;
  r = std::max(std::clamp(r, s.roughness.min, s.roughness.max), s.roughness.clamp_min);
  if (s.table == TableKind::kEavg) return {IntegrateEavg(BakeSpec(), r).value};
  nov = std::max(std::clamp(nov, s.mu.min, s.mu.max), s.mu.clamp_min);
  BakeSpec spec;
  spec.table = s.table;
  const TexelEstimate v = ClampToRange(IntegrateTexel(spec, r, nov));
  if (s.table == TableKind::kDfg) return {v.scale, v.bias};
  return {v.e};
}

std::string JsNumbers(const std::vector<double>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.9g", v[i]);
    s += (i ? "," : "") + std::string(buf);
  }
  return s;
}

// The page: the table as a texture (half or float), the points (up to four
// inputs each) as an RGBA32F texture, one fragment per point, results read
// back as floats.
std::string LookupPage(const Table& t, const Image& im, const std::string& function,
                       const std::string& name, const std::string& data_script,
                       const std::string& data_symbol, const std::vector<double>& points, int pw, int ph) {
  const bool half = im.pixel == PixelType::kHalf;
  const char* formats_half[] = {"R16F", "RG16F", "RGB16F", "RGBA16F"};
  const char* formats_float[] = {"R32F", "RG32F", "RGB32F", "RGBA32F"};
  const char* bases[] = {"RED", "RG", "RGB", "RGBA"};
  const bool dfg = t.spec.table == TableKind::kDfg;
  std::string call = name + "(lut";
  const char* xyzw[] = {"p.x", "p.y", "p.z", "p.w"};
  for (size_t k = 0; k < t.axes.size(); ++k) call += std::string(", ") + xyzw[k];
  call += ")";
  std::ostringstream os;
  os << "<!doctype html><html><body><pre id=\"out\">pending</pre><script>\n"
     << data_script << "\n"
     << "const points = new Float32Array([" << JsNumbers(points) << "]);\n"
     << "const fn = " << nlohmann::json(function).dump() << ";\n"
     << "const out = document.getElementById('out');\n"
     << "try {\n"
     << "  const canvas = document.createElement('canvas');\n"
     << "  const gl = canvas.getContext('webgl2');\n"
     << "  if (!gl) throw new Error('no WebGL2');\n"
     << "  if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');\n"
     << "  gl.getExtension('OES_texture_float_linear');\n"
     << "  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);\n"
     << "  const lut = gl.createTexture();\n"
     << "  gl.activeTexture(gl.TEXTURE0); gl.bindTexture(gl.TEXTURE_2D, lut);\n"
     << "  gl.texImage2D(gl.TEXTURE_2D, 0, gl." << (half ? formats_half : formats_float)[im.channels - 1] << ", "
     << im.width << ", " << im.height << ", 0, gl." << bases[im.channels - 1] << ", gl."
     << (half ? "HALF_FLOAT" : "FLOAT") << ", " << data_symbol << ");\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);\n"
     << "  const pts = gl.createTexture();\n"
     << "  gl.activeTexture(gl.TEXTURE1); gl.bindTexture(gl.TEXTURE_2D, pts);\n"
     << "  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, " << pw << ", " << ph << ", 0, gl.RGBA, gl.FLOAT, points);\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);\n"
     << "  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);\n"
     << "  const target = gl.createTexture();\n"
     << "  gl.activeTexture(gl.TEXTURE2); gl.bindTexture(gl.TEXTURE_2D, target);\n"
     << "  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, " << pw << ", " << ph << ", 0, gl.RGBA, gl.FLOAT, null);\n"
     << "  const fb = gl.createFramebuffer();\n"
     << "  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);\n"
     << "  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);\n"
     << "  const vs = '#version 300 es\\nvoid main() { vec2 p = vec2(float((gl_VertexID << 1) & 2), "
        "float(gl_VertexID & 2)); gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }';\n"
     << "  const fs = '#version 300 es\\nprecision highp float;\\nprecision highp sampler2D;\\n"
        "uniform sampler2D lut;\\nuniform sampler2D pts;\\nout vec4 color;\\n' + fn + "
        "'\\nvoid main() { vec4 p = texelFetch(pts, ivec2(gl_FragCoord.xy), 0); color = "
     << (dfg ? "vec4(" + call + ", 0.0, 1.0)" : "vec4(" + call + ", 0.0, 0.0, 1.0)") << "; }';\n"
     << "  function compile(type, src) { const s = gl.createShader(type); gl.shaderSource(s, src); "
        "gl.compileShader(s); if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new "
        "Error(gl.getShaderInfoLog(s)); return s; }\n"
     << "  const prog = gl.createProgram();\n"
     << "  gl.attachShader(prog, compile(gl.VERTEX_SHADER, vs));\n"
     << "  gl.attachShader(prog, compile(gl.FRAGMENT_SHADER, fs));\n"
     << "  gl.linkProgram(prog);\n"
     << "  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(prog));\n"
     << "  gl.useProgram(prog);\n"
     << "  gl.uniform1i(gl.getUniformLocation(prog, 'lut'), 0);\n"
     << "  gl.uniform1i(gl.getUniformLocation(prog, 'pts'), 1);\n"
     << "  gl.viewport(0, 0, " << pw << ", " << ph << ");\n"
     << "  gl.drawArrays(gl.TRIANGLES, 0, 3);\n"
     << "  const res = new Float32Array(" << pw * ph * 4 << ");\n"
     << "  gl.readPixels(0, 0, " << pw << ", " << ph << ", gl.RGBA, gl.FLOAT, res);\n"
     << "  out.textContent = 'ok ' + Array.from(res).join(' ');\n"
     << "} catch (e) { out.textContent = 'error: ' + e.message; }\n"
     << "</script></body></html>\n";
  return os.str();
}

// The data of an image as a classic script: the generated ES module for
// the js container (its `export`s dropped), a typed array otherwise.
std::string DataScript(const Table& t, const Image& im, const std::string& dir, std::string* symbol) {
  *symbol = "lut_data";
  if (im.pixel == PixelType::kHalf) {
    WriteImage(t, im, Container::kJs, dir + "/data.js", "lut_data", "");
    std::string js = Slurp(dir + "/data.js");
    for (size_t at; (at = js.find("export ")) != std::string::npos;) js.erase(at, 7);
    return js;
  }
  return "const lut_data = new Float32Array([" + JsNumbers(im.values) + "]);";
}

// A value of axis `a` for a point: inside its range mostly, sometimes
// outside it (the function clamps), sometimes exactly on an entry.
double PointValue(const Axis& a, std::mt19937_64& rng, int* entry) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  *entry = -1;
  const double pick = uni(rng);
  if (pick < 0.4) {
    *entry = std::min(a.size - 1, int(uni(rng) * a.size));
    const double v = a.Value(*entry);
    return std::isinf(v) ? 1e30 : v;
  }
  if (a.warp == Warp::kTail) {
    // gamma: log-uniform excess over 1.5 up to 1e6, sometimes beyond.
    return 1.5 + std::exp(std::log(0.05) + uni(rng) * std::log(2e7));
  }
  const double lo = a.min, hi = a.max;
  if (a.warp == Warp::kSchlickZ) {
    // The exponent: z = 5 / (exponent + 5) uniform, sometimes below 0.
    const double z = 0.001 + 0.998 * uni(rng);
    return pick < 0.45 ? -0.2 * uni(rng) : 5 * (1 - z) / z;
  }
  if (a.warp == Warp::kFresnelZ && std::isinf(hi)) {
    // An ior axis to inf (z = 1): z uniform, sometimes below the axis.
    const double z = 0.999 * uni(rng), ior = (1 + z * z) / (1 - z * z);
    return pick < 0.45 ? lo - 0.2 * uni(rng) : ior;
  }
  if (pick < 0.45) return lo - 0.2 * (hi - lo + 1) * uni(rng);
  if (pick < 0.5) return hi + 0.2 * (hi - lo + 1) * uni(rng);
  return lo + (hi - lo) * uni(rng);
}

// The points of a lookup test: four inputs each (the table's axes first),
// and per point the entry of each axis it sits on (-1: between entries).
struct Points {
  std::vector<double> xyzw;
  std::vector<std::vector<int>> entries;
};

Points MakePoints(const Case& c, const Table& t, int count) {
  const size_t n = t.axes.size();
  std::mt19937_64 rng(13);
  Points p;
  if (!c.preset.empty()) {
    // The corners and edges, NoV = 1e-4, and inputs outside [0, 1].
    const double specials[][2] = {{0, 0}, {1, 1}, {0, 1}, {1, 0}, {1e-4, 0.5}, {0.5, 1e-4}, {-0.2, 0.5},
                                  {1.3, 0.5}, {0.5, -1}, {0.5, 2}, {1, 0.02}, {0.02, 1}};
    for (const auto& s : specials) {
      p.xyzw.insert(p.xyzw.end(), {n == 1 ? s[1] : s[0], s[1], 0.0, 0.0});
      p.entries.push_back(std::vector<int>(n, -1));
    }
  }
  while (p.entries.size() < size_t(count)) {
    std::vector<int> e(n, -1);
    double v[4] = {0, 0, 0, 0};
    for (size_t k = 0; k < n; ++k) v[k] = PointValue(t.axes[k], rng, &e[k]);
    p.xyzw.insert(p.xyzw.end(), v, v + 4);
    p.entries.push_back(e);
  }
  return p;
}

// Checks a GPU's results (four floats per point) against the CPU model of
// the lookup at every point; at points on an entry of every axis against
// the stored texel itself (the mapping, independently of the model); and
// for the 2D GGX presets against brdfbake's exact values.
void CheckResults(const Case& c, const Baked& b, const Points& p, const std::vector<double>& res,
                  const char* api) {
  const Table& t = b.table;
  const size_t n = t.axes.size();
  const int count = int(p.entries.size());
  ASSERT_EQ(res.size(), size_t(4 * count));
  double worst_model = 0, worst_entry = 0, worst_exact = 0;
  int on_entries = 0;
  for (int i = 0; i < count; ++i) {
    const std::vector<double> in(p.xyzw.begin() + 4 * i, p.xyzw.begin() + 4 * i + n);
    const std::vector<double> model = ModelLookup(t, b.image, in);
    bool all_entries = true;
    for (int e : p.entries[i]) all_entries &= e >= 0;
    std::vector<double> stored;
    if (all_entries) {
      ++on_entries;
      size_t flat = 0, stride = 1;
      for (size_t k = 0; k < n; ++k) {
        flat += stride * size_t(p.entries[i][k]);
        stride *= size_t(t.axes[k].size);
      }
      // dfg: (scale, bias); E, E_avg, s, f82_bias: the value (1 - a stored
      // complement).
      for (const Channel& ch : t.channels) {
        if (ch.meaning == brdfbake::Meaning::kDfgScale || ch.meaning == brdfbake::Meaning::kDfgBias ||
            ch.meaning == brdfbake::Meaning::kE || ch.meaning == brdfbake::Meaning::kEavg ||
            ch.meaning == brdfbake::Meaning::kS || ch.meaning == brdfbake::Meaning::kF82Bias) {
          stored.push_back(ch.values[flat]);
        }
        if (ch.meaning == brdfbake::Meaning::kOneMinusE || ch.meaning == brdfbake::Meaning::kOneMinusEavg) stored.push_back(1 - ch.values[flat]);
      }
    }
    for (size_t k = 0; k < model.size(); ++k) {
      const double gpu = res[4 * i + k];
      worst_model = std::max(worst_model, std::abs(gpu - model[k]));
      ASSERT_NEAR(gpu, model[k], 2e-3) << api << " " << c.name << " point " << i << " component " << k;
      if (all_entries) {
        worst_entry = std::max(worst_entry, std::abs(gpu - stored[k]));
        ASSERT_NEAR(gpu, stored[k], 1e-3 + 0x1p-10 * std::abs(stored[k]))
            << api << " " << c.name << " entry point " << i << " component " << k;
      }
    }
    // The 2D GGX preset tables (not the glass or gen_schlick slices).
    if (!c.preset.empty() && n <= 2 && t.spec.model.kind == ModelKind::kGgx && !t.spec.GenSchlick()) {
      const double nov = n == 1 ? 0.5 : in[0], r = in[n - 1];
      const std::vector<double> exact = ExactLookup(t, nov, r);
      for (size_t k = 0; k < model.size(); ++k) {
        const double gpu = res[4 * i + k];
        const double interp = std::abs(model[k] - exact[k]);
        worst_exact = std::max(worst_exact, std::abs(gpu - exact[k]) - interp);
        // The table's interpolation error here, the stored precision and
        // the filtering.
        ASSERT_LE(std::abs(gpu - exact[k]), interp + 0x1p-10 * std::abs(exact[k]) + 2e-3)
            << api << " " << c.name << " point (" << nov << ", " << r << ") component " << k;
      }
    }
  }
  EXPECT_GT(on_entries, 0);
  std::printf("%s %s (%dx%d, %zu axes): GPU vs CPU model %.2g, on %d entry points vs stored %.2g%s\n", api,
              c.name.c_str(), b.image.width, b.image.height, n, worst_model, on_entries, worst_entry,
              c.preset.empty() ? "" : (", vs exact beyond interpolation " + std::to_string(worst_exact)).c_str());
}

std::vector<double> ParseNumbers(const std::string& text) {
  std::stringstream ss(text);
  std::vector<double> v;
  for (double x; ss >> x;) v.push_back(x);
  return v;
}

class BrowserLookupTest : public ::testing::TestWithParam<Case> {};

// GLSL in WebGL2 (SwiftShader).
TEST_P(BrowserLookupTest, GlslMatchesTheTableAndTheExactValues) {
  ASSERT_TRUE(Have("chromium")) << "chromium is needed: sh tools/setup.sh test installs it";
  const Case c = GetParam();
  const std::string dir = Scratch(c.name);
  const Baked b = BakeCase(c);
  const std::string name = "brdfbake_lookup";
  const std::string fn = ShaderFunction(b.table, b.image, ShaderLanguage::kGlsl, name);
  const int pw = 40, ph = 25;
  const Points p = MakePoints(c, b.table, pw * ph);
  std::string symbol;
  const std::string data = DataScript(b.table, b.image, dir, &symbol);
  const std::string out = RunPage(dir, LookupPage(b.table, b.image, fn, name, data, symbol, p.xyzw, pw, ph),
                                  "--use-angle=swiftshader --enable-unsafe-swiftshader");
  ASSERT_EQ(out.rfind("ok ", 0), 0u) << out.substr(0, 400) << "\n" << fn;
  CheckResults(c, b, p, ParseNumbers(out.substr(3)), "GLSL");
}

// Runs a page whose script ends with console.log('RESULT ...') and
// window.close(), so that Chromium exits once the asynchronous WebGPU work
// is done (--dump-dom may save the page before it is); the text after
// "RESULT ".
std::string RunConsolePage(const std::string& dir, const std::string& html) {
  WriteText(dir + "/page.html", html);
  const std::string cmd =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu-sandbox --disable-background-networking "
      "--disable-component-update --disable-sync --no-first-run --disable-quic --user-data-dir=" + dir +
      "/profile --enable-logging=stderr --log-level=0 --enable-unsafe-webgpu --enable-features=Vulkan,WebGPU "
      "--use-vulkan=swiftshader --use-webgpu-adapter=swiftshader --disable-vulkan-surface file://" + dir +
      "/page.html > /dev/null 2> " + dir + "/chromium.log";
  const int status = std::system(cmd.c_str());
  const std::string log = Slurp(dir + "/chromium.log");
  const size_t a = log.find("\"RESULT ");
  const size_t b = log.find("\", source: ", a);
  if (a == std::string::npos || b == std::string::npos) {
    return "no RESULT (status " + std::to_string(status) + "): " + log.substr(log.size() > 2000 ? log.size() - 2000 : 0);
  }
  return log.substr(a + 8, b - a - 8);
}

// A compute shader that calls the WGSL lookup at every point (a storage
// array of vec4) and writes its result as a vec4, with the table as a
// texture (three channels padded to four: WebGPU has no RGB formats).
std::string WgslPage(const Table& t, const Image& im, const std::string& function, const std::string& name,
                     const std::vector<double>& points) {
  const bool half = im.pixel == PixelType::kHalf;
  const int tch = im.channels == 3 ? 4 : im.channels;
  std::string data;
  for (size_t i = 0; i < size_t(im.width) * im.height; ++i) {
    for (int c = 0; c < tch; ++c) {
      const bool pad = c >= im.channels;
      const size_t at = i * im.channels + c;
      if (!data.empty()) data += ",";
      if (half) {
        data += std::to_string(pad ? 0x3c00 : im.bits16[at]);
      } else {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.9g", pad ? 1.0 : im.values[at]);
        data += buf;
      }
    }
  }
  const char* formats[] = {"r", "rg", "rgba", "rgba"};
  const std::string format = std::string(formats[im.channels - 1]) + (half ? "16float" : "32float");
  std::string call = name + "(lut, lut_sampler";
  const char* xyzw[] = {"p.x", "p.y", "p.z", "p.w"};
  for (size_t k = 0; k < t.axes.size(); ++k) call += std::string(", ") + xyzw[k];
  call += ")";
  const bool dfg = t.spec.table == TableKind::kDfg;
  const std::string shader =
      "@group(0) @binding(0) var lut: texture_2d<f32>;\n"
      "@group(0) @binding(1) var lut_sampler: sampler;\n"
      "@group(0) @binding(2) var<storage, read> pts: array<vec4<f32>>;\n"
      "@group(0) @binding(3) var<storage, read_write> res: array<vec4<f32>>;\n" +
      function +
      "@compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {\n"
      "  if (id.x >= arrayLength(&pts)) { return; }\n"
      "  let p = pts[id.x];\n"
      "  let r = " + call + ";\n"
      "  res[id.x] = " + (dfg ? "vec4<f32>(r, 0.0, 0.0)" : "vec4<f32>(r, 0.0, 0.0, 0.0)") + ";\n}\n";
  std::ostringstream os;
  os << "<!doctype html><html><body><script>\n"
     << "function done(s) { console.log('RESULT ' + s); window.close(); }\n"
     << "(async () => { try {\n"
     << "  if (!navigator.gpu) throw new Error('no navigator.gpu');\n"
     << "  const adapter = await navigator.gpu.requestAdapter();\n"
     << "  if (!adapter) throw new Error('no WebGPU adapter');\n"
     << "  const features = " << (half ? "[]" : "['float32-filterable']") << ";\n"
     << "  for (const f of features) if (!adapter.features.has(f)) throw new Error('no ' + f);\n"
     << "  const device = await adapter.requestDevice({requiredFeatures: features});\n"
     << "  const module = device.createShaderModule({code: " << nlohmann::json(shader).dump() << "});\n"
     << "  const info = await module.getCompilationInfo();\n"
     << "  const errs = info.messages.filter(m => m.type === 'error').map(m => m.lineNum + ':' + m.linePos + ' ' + m.message);\n"
     << "  if (errs.length) { done('compile-error ' + errs.join('; ')); return; }\n"
     << "  const pts = new Float32Array([" << JsNumbers(points) << "]);\n"
     << "  const n = pts.length / 4;\n"
     << "  const tex = device.createTexture({size: [" << im.width << ", " << im.height << "], format: '" << format
     << "', usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST});\n"
     << "  const data = new " << (half ? "Uint16Array" : "Float32Array") << "([" << data << "]);\n"
     << "  device.queue.writeTexture({texture: tex}, data, {bytesPerRow: " << im.width * tch * (half ? 2 : 4)
     << "}, [" << im.width << ", " << im.height << "]);\n"
     << "  const sampler = device.createSampler({magFilter: 'linear', minFilter: 'linear', "
        "addressModeU: 'clamp-to-edge', addressModeV: 'clamp-to-edge'});\n"
     << "  const pbuf = device.createBuffer({size: pts.byteLength, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST});\n"
     << "  device.queue.writeBuffer(pbuf, 0, pts);\n"
     << "  const rbuf = device.createBuffer({size: n * 16, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC});\n"
     << "  const read = device.createBuffer({size: n * 16, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST});\n"
     << "  device.pushErrorScope('validation');\n"
     << "  const pipeline = device.createComputePipeline({layout: 'auto', compute: {module, entryPoint: 'main'}});\n"
     << "  const bind = device.createBindGroup({layout: pipeline.getBindGroupLayout(0), entries: [\n"
     << "      {binding: 0, resource: tex.createView()}, {binding: 1, resource: sampler},\n"
     << "      {binding: 2, resource: {buffer: pbuf}}, {binding: 3, resource: {buffer: rbuf}}]});\n"
     << "  const enc = device.createCommandEncoder();\n"
     << "  const pass = enc.beginComputePass();\n"
     << "  pass.setPipeline(pipeline); pass.setBindGroup(0, bind); pass.dispatchWorkgroups(Math.ceil(n / 64)); pass.end();\n"
     << "  enc.copyBufferToBuffer(rbuf, 0, read, 0, n * 16);\n"
     << "  device.queue.submit([enc.finish()]);\n"
     << "  const verr = await device.popErrorScope();\n"
     << "  if (verr) { done('validation-error ' + verr.message); return; }\n"
     << "  await read.mapAsync(GPUMapMode.READ);\n"
     << "  done('ok ' + Array.from(new Float32Array(read.getMappedRange())).join(' '));\n"
     << "} catch (e) { done('error ' + String(e && e.message || e)); } })();\n"
     << "</script></body></html>\n";
  return os.str();
}

// WGSL in WebGPU (Dawn on SwiftShader's Vulkan, which Debian's Chromium
// ships): compiled by Tint and run in a compute shader.
TEST_P(BrowserLookupTest, WgslMatchesTheTableAndTheExactValues) {
  ASSERT_TRUE(Have("chromium")) << "chromium is needed: sh tools/setup.sh test installs it";
  const Case c = GetParam();
  const std::string dir = Scratch("wgsl_" + c.name);
  const Baked b = BakeCase(c);
  const std::string name = "brdfbake_lookup";
  const std::string fn = ShaderFunction(b.table, b.image, ShaderLanguage::kWgsl, name);
  const Points p = MakePoints(c, b.table, 1000);
  const std::string out = RunConsolePage(dir, WgslPage(b.table, b.image, fn, name, p.xyzw));
  ASSERT_EQ(out.rfind("ok ", 0), 0u) << out.substr(0, 600) << "\n" << fn;
  CheckResults(c, b, p, ParseNumbers(out.substr(3)), "WGSL");
}

INSTANTIATE_TEST_SUITE_P(Tables, BrowserLookupTest, ::testing::ValuesIn(AllCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return n;
                         });

// Every table of AllCases() at a small size for the presets (the mapping,
// not the values, matters for compiling), with a fragment program in
// `lang` that calls its lookup.
std::vector<std::string> Programs(ShaderLanguage lang) {
  std::vector<std::string> programs;
  for (const Case& c0 : AllCases()) {
    Case c = c0;
    Baked b;
    if (!c.preset.empty()) {
      PresetTable pt = FindPreset(c.preset).tables.at(c.table);
      pt.spec.mu.size = std::min(pt.spec.mu.size, 8);
      pt.spec.roughness.size = std::min(pt.spec.roughness.size, 8);
      b.table = Bake(pt.spec);
      b.image = ArrangePresetTable(pt, b.table);
    } else {
      b = BakeCase(c);
    }
    const Table& t = b.table;
    const bool dfg = t.spec.table == TableKind::kDfg;
    std::string args;
    for (const Axis& a : t.axes) args += a.warp == Warp::kTail ? ", 2.5" : ", 0.5";
    const std::string texture = lang == ShaderLanguage::kGlsl ? "lut" : "lut, lut_sampler";
    const std::string call = "lookup(" + texture + args + ")" + (dfg ? ", 0.0" : ", 0.0, 0.0") + ", 1.0";
    const std::string fn = ShaderFunction(t, b.image, lang, "lookup");
    switch (lang) {
      case ShaderLanguage::kGlsl:
        programs.push_back("#version 300 es\nprecision highp float;\nuniform sampler2D lut;\nout vec4 color;\n" +
                           fn + "void main() { color = vec4(" + call + "); }\n");
        break;
      case ShaderLanguage::kHlsl:
        programs.push_back("Texture2D<float4> lut : register(t0);\nSamplerState lut_sampler : register(s0);\n" +
                           fn + "float4 main() : SV_Target { return float4(" + call + "); }\n");
        break;
      case ShaderLanguage::kWgsl:
        programs.push_back("@group(0) @binding(0) var lut: texture_2d<f32>;\n"
                           "@group(0) @binding(1) var lut_sampler: sampler;\n" + fn +
                           "@fragment fn main() -> @location(0) vec4<f32> { return vec4<f32>(" + call + "); }\n");
        break;
    }
  }
  return programs;
}

// No lookup is written for sel_norm tables: refused with one line.
TEST(ShaderFunctionTest, SelNormIsRefused) {
  BakeSpec s;
  s.table = TableKind::kSelNorm;
  try {
    CheckShaderTable(s);
    FAIL() << "sel_norm accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sel_norm"), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

// A single-entry axis compiles to a constant coordinate: no division by
// the axis' zero width in any language.
TEST(ShaderFunctionTest, SingleEntryAxesHaveNoDivisionByZero) {
  for (const Case& c : KindCases()) {
    if (c.name.find("one_") == std::string::npos) continue;
    const Baked b = BakeCase(c);
    for (ShaderLanguage l : {ShaderLanguage::kGlsl, ShaderLanguage::kHlsl, ShaderLanguage::kWgsl}) {
      const std::string fn = ShaderFunction(b.table, b.image, l, "f");
      EXPECT_EQ(fn.find("/ 0.0"), std::string::npos) << c.name << "\n" << fn;
      EXPECT_EQ(fn.find("/ 0)"), std::string::npos) << c.name << "\n" << fn;
    }
  }
}

// Every preset's GLSL and HLSL compile with glslang.
TEST(ShaderCompileTest, GlslAndHlslCompileWithGlslang) {
  ASSERT_TRUE(Have("glslangValidator")) << "glslang-tools is needed: sh tools/setup.sh test installs it";
  const std::string dir = Scratch("glslang");
  const std::vector<std::string> glsl = Programs(ShaderLanguage::kGlsl);
  const std::vector<std::string> hlsl = Programs(ShaderLanguage::kHlsl);
  ASSERT_EQ(glsl.size(), AllCases().size());
  for (size_t i = 0; i < glsl.size(); ++i) {
    const std::string stem = dir + "/p" + std::to_string(i);
    WriteText(stem + ".frag", glsl[i]);
    EXPECT_EQ(std::system(("glslangValidator " + stem + ".frag > " + stem + ".glsl.log 2>&1").c_str()), 0)
        << Slurp(stem + ".glsl.log") << glsl[i];
    WriteText(stem + ".hlsl", hlsl[i]);
    EXPECT_EQ(std::system(("glslangValidator -D -V -S frag -e main -o " + stem + ".spv " + stem + ".hlsl > " +
                           stem + ".hlsl.log 2>&1").c_str()), 0)
        << Slurp(stem + ".hlsl.log") << hlsl[i];
  }
}

// The code blocks of docs/engines.md, by language.
std::vector<std::pair<std::string, std::string>> DocBlocks(const std::string& md) {
  std::vector<std::pair<std::string, std::string>> blocks;
  for (size_t at = 0; (at = md.find("\n```", at)) != std::string::npos;) {
    const size_t lang_end = md.find('\n', at + 4);
    const std::string lang = md.substr(at + 4, lang_end - at - 4);
    const size_t end = md.find("\n```", lang_end);
    if (end == std::string::npos) break;
    if (!lang.empty()) blocks.push_back({lang, md.substr(lang_end + 1, end - lang_end)});
    at = end + 4;
  }
  return blocks;
}

// Every GLSL, HLSL, WGSL and C++ block of docs/engines.md compiles, with the
// generated lookups (brdfbake_ggx_dfg; Unreal's brdfbake_PreIntegratedGF)
// and Enterprise PBR's pbrlut.hpp in scope.
TEST(DocsTest, EngineSnippetsCompile) {
  ASSERT_TRUE(Have("glslangValidator")) << "glslang-tools is needed: sh tools/setup.sh test installs it";
  ASSERT_TRUE(Have("chromium")) << "chromium is needed: sh tools/setup.sh test installs it";
  const std::string dir = Scratch("docs");
  const auto blocks = DocBlocks(Slurp(std::string(BRDFBAKE_TEST_DATA) + "/../../docs/engines.md"));
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = spec.roughness.size = 8;
  const Table t = Bake(spec);
  const Image im = ArrangeTable(t, DefaultLayout(t));
  PresetTable unreal = FindPreset("unreal").tables[0];
  unreal.spec.mu.size = unreal.spec.roughness.size = 8;
  const Table ut = Bake(unreal.spec);
  const Image uim = ArrangeTable(ut, unreal.layout);
  std::map<std::string, int> counts;
  std::string wgsl_modules;
  for (size_t i = 0; i < blocks.size(); ++i) {
    const auto& [lang, code] = blocks[i];
    const std::string stem = dir + "/b" + std::to_string(i);
    ++counts[lang];
    if (lang == "glsl") {
      WriteText(stem + ".frag", "#version 300 es\nprecision highp float;\n" +
                                    ShaderFunction(t, im, ShaderLanguage::kGlsl, "brdfbake_ggx_dfg") + code +
                                    "out vec4 color;\nvoid main() { color = vec4(0.0); }\n");
      EXPECT_EQ(std::system(("glslangValidator " + stem + ".frag > " + stem + ".log 2>&1").c_str()), 0)
          << Slurp(stem + ".log") << code;
    } else if (lang == "hlsl") {
      WriteText(stem + ".hlsl", ShaderFunction(ut, uim, ShaderLanguage::kHlsl, "brdfbake_PreIntegratedGF") + code +
                                    "float4 main() : SV_Target { return float4(0.0, 0.0, 0.0, 1.0); }\n");
      EXPECT_EQ(std::system(("glslangValidator -D -V -S frag -e main -o " + stem + ".spv " + stem + ".hlsl > " +
                             stem + ".log 2>&1").c_str()), 0)
          << Slurp(stem + ".log") << code;
    } else if (lang == "wgsl") {
      const std::string module = ShaderFunction(t, im, ShaderLanguage::kWgsl, "brdfbake_ggx_dfg") + code +
                                 "@compute @workgroup_size(1) fn main() {}\n";
      wgsl_modules += (wgsl_modules.empty() ? "" : ",") + nlohmann::json(module).dump();
    } else if (lang == "cpp") {
      PresetRun run;
      run.dir = dir;
      const Preset& e = FindPreset("enterprise-pbr");
      if (!PresetBuilt(e)) continue;  // its sheen tables need charlie
      std::vector<Table> tables;
      std::vector<Image> images;
      for (const PresetTable& pt : e.tables) {
        tables.push_back(Bake(pt.spec));
        images.push_back(ArrangePresetTable(pt, tables.back()));
      }
      WritePresetFiles(e, run, tables, images);
      WriteText(stem + ".cc", code + "int main() { return KullaConty(0.5f, 0.7f, 0.5f) > 0.0f ? 0 : 1; }\n");
      EXPECT_EQ(std::system(("c++ -std=c++17 -Wall -Werror -I" + dir + " -o " + stem + " " + stem + ".cc > " +
                             stem + ".log 2>&1 && " + stem).c_str()), 0)
          << Slurp(stem + ".log") << code;
    }
  }
  EXPECT_GE(counts["glsl"], 2);
  EXPECT_GE(counts["hlsl"], 1);
  EXPECT_GE(counts["wgsl"], 1);
  EXPECT_GE(counts["cpp"], 1);
  const std::string out = RunConsolePage(
      dir, "<!doctype html><html><body><script>\n"
           "function done(s) { console.log('RESULT ' + s); window.close(); }\n"
           "(async () => { try {\n"
           "  const adapter = await navigator.gpu.requestAdapter();\n"
           "  if (!adapter) throw new Error('no WebGPU adapter');\n"
           "  const device = await adapter.requestDevice();\n"
           "  const infos = await Promise.all([" + wgsl_modules + "].map(code => "
           "device.createShaderModule({code}).getCompilationInfo()));\n"
           "  const errors = [];\n"
           "  for (const info of infos) for (const m of info.messages) if (m.type === 'error') "
           "errors.push(m.lineNum + ':' + m.linePos + ' ' + m.message);\n"
           "  done('ok ' + infos.length + ' ' + errors.length + ' ' + errors.join('; '));\n"
           "} catch (e) { done('error ' + String(e && e.message || e)); } })();\n"
           "</script></body></html>\n");
  EXPECT_EQ(out, "ok " + std::to_string(counts["wgsl"]) + " 0 ");
}

}  // namespace
}  // namespace brdfbake
