// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The generated shader lookups. GLSL runs in a real browser: headless
// Chromium with WebGL2 on its software rasterizer uploads each preset's
// table, calls the generated function at random (NoV, roughness) points and
// at the edges and clamps, and reads the results back as floats; they are
// compared with a CPU model of the same bilinear lookup and with brdfbake's
// exact values. HLSL is compiled by glslangValidator; WGSL (no parser in
// Debian 12) by Chromium's WebGPU (createShaderModule, getCompilationInfo).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
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

struct Case {
  std::string preset;
  size_t table = 0;
};

struct Baked {
  Table table;
  Image image;
};

// What the function should return at (NoV, r), by the CPU model.
std::vector<double> ModelLookup(const Table& t, const Image& im, double nov, double r) {
  const bool one_d = t.spec.table == TableKind::kEavg;
  auto value_of = [&](const Axis& a) { return a.name == "mu" ? nov : r; };
  const double u = test::TextureCoordinate(im.axes[0], value_of(im.axes[0]));
  double v = one_d ? 0.5 : test::TextureCoordinate(im.axes[1], value_of(im.axes[1]));
  if (im.flip_rows) v = 1 - v;
  std::vector<double> s(im.channels);
  for (int c = 0; c < im.channels; ++c) {
    auto at = [&](int x, int y) { return im.values[(size_t(y) * im.width + x) * im.channels + c]; };
    s[c] = test::TextureBilinear(at, im.width, im.height, u, v);
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
  const int e = find(one_d ? "E_avg" : "E");
  return {s[e]};
}

// brdfbake's exact values at (NoV, r), with the table's ranges and clamps.
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

// The page: the table as a texture (half or float), the points as an
// RG32F texture, one fragment per point, results read back as floats.
std::string LookupPage(const Table& t, const Image& im, const std::string& function,
                       const std::string& name, const std::string& data_script,
                       const std::string& data_symbol, const std::vector<double>& points, int pw, int ph) {
  const bool half = im.pixel == PixelType::kHalf;
  const char* formats_half[] = {"R16F", "RG16F", "RGB16F", "RGBA16F"};
  const char* formats_float[] = {"R32F", "RG32F", "RGB32F", "RGBA32F"};
  const char* bases[] = {"RED", "RG", "RGB", "RGBA"};
  const bool one_d = t.spec.table == TableKind::kEavg;
  const bool dfg = t.spec.table == TableKind::kDfg;
  const std::string call = name + (one_d ? "(lut, p.y)" : "(lut, p.x, p.y)");
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
     << "  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RG32F, " << pw << ", " << ph << ", 0, gl.RG, gl.FLOAT, points);\n"
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
        "'\\nvoid main() { vec2 p = texelFetch(pts, ivec2(gl_FragCoord.xy), 0).xy; color = "
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
  if (im.pixel == PixelType::kHalf) {
    WriteImage(t, im, Container::kJs, dir + "/data.js", "lut_data", "");
    std::string js = Slurp(dir + "/data.js");
    for (size_t at; (at = js.find("export ")) != std::string::npos;) js.erase(at, 7);
    *symbol = "lut_data";
    return js;
  }
  *symbol = "lut_data";
  return "const lut_data = new Float32Array([" + JsNumbers(im.values) + "]);";
}

Baked BakeCase(const Case& c) {
  const PresetTable& pt = FindPreset(c.preset).tables.at(c.table);
  Baked b{Bake(pt.spec), {}};
  b.image = ArrangeTable(b.table, pt.layout);
  return b;
}

// Each layout feature in at least one case: transposed (three, cycles),
// rows flipped and (bias, E) channels (filament), sqrt(NoV) with the
// endpoints on texel centres (hdrp), an alpha axis (materialx), float
// textures, edges with clamps (cycles), a one-row E_avg table (cycles).
class BrowserLookupTest : public ::testing::TestWithParam<Case> {};

TEST_P(BrowserLookupTest, GlslMatchesTheTableAndTheExactValues) {
  if (!Have("chromium")) GTEST_SKIP() << "chromium is not installed (sh tools/setup.sh test installs it)";
  const Case c = GetParam();
  const std::string dir = Scratch(c.preset + std::to_string(c.table));
  const Baked b = BakeCase(c);
  const std::string name = "brdfbake_lookup";
  const std::string fn = ShaderFunction(b.table, b.image, ShaderLanguage::kGlsl, name);
  // Points: random, the corners and edges, and inputs outside [0, 1] that
  // the function must clamp.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const int pw = 40, ph = 25;
  std::vector<double> pts;
  const double specials[][2] = {{0, 0}, {1, 1}, {0, 1}, {1, 0}, {1e-4, 0.5}, {0.5, 1e-4}, {-0.2, 0.5},
                                {1.3, 0.5}, {0.5, -1}, {0.5, 2}, {1, 0.02}, {0.02, 1}};
  for (const auto& s : specials) pts.insert(pts.end(), {s[0], s[1]});
  while (pts.size() < size_t(2 * pw * ph)) pts.insert(pts.end(), {uni(rng), uni(rng)});
  std::string symbol;
  const std::string data = DataScript(b.table, b.image, dir, &symbol);
  const std::string out = RunPage(dir, LookupPage(b.table, b.image, fn, name, data, symbol, pts, pw, ph),
                                  "--use-angle=swiftshader --enable-unsafe-swiftshader");
  ASSERT_EQ(out.rfind("ok ", 0), 0u) << out.substr(0, 400);
  std::stringstream ss(out.substr(3));
  std::vector<double> res;
  for (double v; ss >> v;) res.push_back(v);
  ASSERT_EQ(res.size(), size_t(pw * ph * 4));
  double worst_model = 0, worst_exact = 0, worst_interp = 0;
  for (int i = 0; i < pw * ph; ++i) {
    // Fragment (x, y) read point y * pw + x; readPixels returns rows from y = 0.
    const double nov = pts[2 * i], r = pts[2 * i + 1];
    const std::vector<double> model = ModelLookup(b.table, b.image, nov, r);
    const std::vector<double> exact = ExactLookup(b.table, nov, r);
    for (size_t k = 0; k < model.size(); ++k) {
      const double gpu = res[4 * i + k];
      const double interp = std::abs(model[k] - exact[k]);
      worst_model = std::max(worst_model, std::abs(gpu - model[k]));
      worst_exact = std::max(worst_exact, std::abs(gpu - exact[k]));
      worst_interp = std::max(worst_interp, interp);
      // The texture unit's filtering against the CPU model of it.
      ASSERT_NEAR(gpu, model[k], 2e-3) << "point (" << nov << ", " << r << ") component " << k;
      // Against the exact value: the table's interpolation error here plus
      // the stored precision plus the filtering.
      ASSERT_LE(std::abs(gpu - exact[k]), interp + 0x1p-10 * std::abs(exact[k]) + 2e-3)
          << "point (" << nov << ", " << r << ") component " << k;
    }
  }
  std::printf("%s table %zu (%dx%d): GPU vs CPU bilinear %.2g, vs exact %.3g (interpolation %.3g)\n",
              c.preset.c_str(), c.table, b.image.width, b.image.height, worst_model, worst_exact, worst_interp);
}

INSTANTIATE_TEST_SUITE_P(Presets, BrowserLookupTest,
                         ::testing::Values(Case{"three", 0}, Case{"filament", 0}, Case{"hdrp", 0},
                                           Case{"bevy", 0}, Case{"materialx", 0}, Case{"cycles", 0},
                                           Case{"cycles", 1}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string n = info.param.preset + "_" + std::to_string(info.param.table);
                           for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return n;
                         });

// Every preset table at a small size (the mapping, not the values, matters
// for compiling), with a fragment program in `lang` that calls its lookup.
std::vector<std::string> PresetPrograms(ShaderLanguage lang) {
  std::vector<std::string> programs;
  for (const Preset& p : Presets()) {
    for (PresetTable pt : p.tables) {
      pt.spec.mu.size = std::min(pt.spec.mu.size, 8);
      pt.spec.roughness.size = std::min(pt.spec.roughness.size, 8);
      const Table t = Bake(pt.spec);
      const Image im = ArrangeTable(t, pt.layout);
      const bool one_d = t.spec.table == TableKind::kEavg;
      const bool dfg = t.spec.table == TableKind::kDfg;
      const std::string texture = lang == ShaderLanguage::kGlsl ? "lut" : "lut, lut_sampler";
      const std::string call = "lookup(" + texture + (one_d ? ", 0.5)" : ", 0.5, 0.5)") +
                               (dfg ? ", 0.0" : ", 0.0, 0.0") + ", 1.0";
      const std::string fn = ShaderFunction(t, im, lang, "lookup");
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
  }
  return programs;
}

// Every preset's GLSL and HLSL compile with glslang.
TEST(ShaderCompileTest, GlslAndHlslCompileWithGlslang) {
  if (!Have("glslangValidator")) GTEST_SKIP() << "glslang-tools is not installed";
  const std::string dir = Scratch("glslang");
  const std::vector<std::string> glsl = PresetPrograms(ShaderLanguage::kGlsl);
  const std::vector<std::string> hlsl = PresetPrograms(ShaderLanguage::kHlsl);
  ASSERT_EQ(glsl.size(), 11u);
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

// WGSL: Debian 12 packages no WGSL parser (no tint, no naga); Chromium's
// WebGPU compiles it (SwiftShader's Vulkan).
TEST(ShaderCompileTest, WgslCompilesInChromiumWebGpu) {
  if (!Have("chromium")) GTEST_SKIP() << "chromium is not installed";
  const std::string dir = Scratch("wgsl");
  std::string modules = "[";
  for (const std::string& src : PresetPrograms(ShaderLanguage::kWgsl)) {
    modules += (modules.size() > 1 ? "," : "") + nlohmann::json(src).dump();
  }
  modules += "]";
  const std::string html =
      "<!doctype html><html><body><pre id=\"out\">pending</pre><script>\n"
      "const sources = " + modules + ";\n"
      "const out = document.getElementById('out');\n"
      "(async () => { try {\n"
      "  if (!navigator.gpu) throw new Error('no WebGPU');\n"
      "  const adapter = await navigator.gpu.requestAdapter();\n"
      "  if (!adapter) throw new Error('no WebGPU adapter');\n"
      "  const device = await adapter.requestDevice();\n"
      "  const errors = [];\n"
      // All at once: awaited one by one, headless Chromium's virtual time
      // stops before the last.
      "  const infos = await Promise.all(sources.map(code => "
      "device.createShaderModule({code}).getCompilationInfo()));\n"
      "  for (const info of infos) for (const m of info.messages) if (m.type === 'error') "
      "errors.push(m.message);\n"
      "  out.textContent = 'ok ' + sources.length + ' ' + errors.length + ' ' + errors.join('; ');\n"
      "} catch (e) { out.textContent = 'error: ' + e.message; } })();\n"
      "</script></body></html>\n";
  // WebGPU is asynchronous, and headless Chromium's --dump-dom does not
  // always wait for it (the page is then still "pending"): a few attempts.
  std::string out;
  for (int attempt = 0; attempt < 6; ++attempt) {
    out = RunPage(dir, html,
                  "--enable-unsafe-webgpu --enable-features=Vulkan,WebGPU --use-vulkan=swiftshader "
                  "--use-webgpu-adapter=swiftshader --virtual-time-budget=60000");
    if (out != "pending") break;
    std::filesystem::remove_all(dir + "/profile");
  }
  if (out.rfind("error: no WebGPU", 0) == 0 || out == "pending") {
    GTEST_SKIP() << "WebGPU did not answer in headless Chromium here: " << out;
  }
  EXPECT_EQ(out, "ok 11 0 ") << out;
}

}  // namespace
}  // namespace brdfbake
