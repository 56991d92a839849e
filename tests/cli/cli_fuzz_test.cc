// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A seeded random sweep over the command line of `brdfbake eval` and
// `brdfbake bake`: arguments drawn from valid values, edge values (0, 1,
// 1e-300, huge), and garbage (NaN, inf, negative, text, empty). Every run
// must end with exit status 0, 1 or 2 (usage), never a signal; a failure prints one
// line on stderr, nothing on stdout, and leaves no output file; a success
// leaves a file (or CSV) whose every value is finite.
//
// Scene files at the limits, through `brdfbake plan` (and `bake`): nesting
// 20,000 and 100,000 levels deep (glTF extras, TOML arrays, inline tables
// and dotted keys), buffer and image URIs that name other files (absolute,
// ../ traversal, %2f-encoded, a FIFO, a sparse 3 GiB file, a data: URI of
// 6 MB), and type confusion (strings for numbers, objects for arrays,
// negative, huge and dangling indices, NaN and Infinity literals,
// duplicate keys, bytes that are not UTF-8, GLB containers whose lengths
// lie). Each run ends within a minute, with exit status 0 or 1, never a
// signal; an error is one line of at most 2000 bytes and nothing on
// stdout; and (under strace, where it runs) no file but the scene is
// opened.

#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/bake.h"
#include "brdfbake/exr.h"
#include "util/cli_util.h"
#include "util/file_util.h"

#ifdef BRDFBAKE_CLI_PATH

namespace brdfbake {
namespace {

struct Fuzzer {
  std::mt19937_64 rng;
  explicit Fuzzer(uint64_t seed) : rng(seed) {}
  size_t Index(size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); }
  bool Coin(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
  template <class T>
  const T& Pick(const std::vector<T>& v) { return v[Index(v.size())]; }
  // A number: mostly valid for the option, sometimes an edge or garbage.
  std::string Number(const std::vector<std::string>& valid) {
    static const std::vector<std::string> bad = {"nan", "inf", "-inf", "-1", "0", "1e-300",
                                                 "1e300", "abc", "", "0x1p-1074", "1,2"};
    return Coin(0.93) ? Pick(valid) : Pick(bad);
  }
};

// Every cell of a CSV is a finite number or text, except Lambda, which is
// +inf on and below the horizon by definition (G1 = 0 there).
bool CsvIsFinite(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  {
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) header.push_back(cell);
  }
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    for (size_t col = 0; std::getline(cells, cell, ','); ++col) {
      const bool lambda = col < header.size() && header[col].rfind("Lambda", 0) == 0;
      if (cell.find("nan") != std::string::npos) return false;
      if (cell.find("inf") != std::string::npos && !(lambda && cell == "inf")) return false;
    }
  }
  return true;
}

TEST(CliFuzzTest, RandomArgumentsNeverCrashOrLeaveNonFiniteOutput) {
  const std::string dir = ::testing::TempDir() + "/brdfbake_cli_fuzz";
  std::filesystem::create_directories(dir);
  const std::string exr = dir + "/out.exr";
  Fuzzer fz(20261122);
  const std::vector<std::string> models = {"ggx", "beckmann", "std", "ellipsoid", "sel", "phong"};
  int ok_runs = 0, error_runs = 0;
  const int kRuns = 400;
  for (int run = 0; run < kRuns; ++run) {
    std::filesystem::remove(exr);
    std::vector<std::string> args;
    const bool bake = fz.Coin(0.5);
    // Mostly the models each command takes, sometimes one it does not.
    const std::string model = fz.Coin(0.85) ? fz.Pick(bake ? std::vector<std::string>{"ggx", "beckmann", "std"}
                                                            : std::vector<std::string>{"ggx", "beckmann", "std", "ellipsoid", "sel"})
                                            : fz.Pick(models);
    if (bake) {
      const std::string table =
          fz.Pick(std::vector<std::string>{"E", "E", "E_avg", "E_avg", "dfg", "dfg", "F"});
      args = {"bake", "--table", table, "--model", model};
      if (model == "std") {
        args.push_back("--gamma");
        // gamma < 2 bakes take seconds per texel row; keep them on tiny tables.
        args.push_back(fz.Number({"2.5", "3", "7", "1e6", "inf", "1.4", "1.5"}));
      }
      const std::string n =
          table == "E_avg"
              ? fz.Pick(std::vector<std::string>{"2", "3", "5", "7", "1", "0", "-3", "4x3"})
              : fz.Pick(std::vector<std::string>{"2x2", "3x3", "4x3", "5x2", "1x1", "3", "0x2",
                                                 "x4", "100000x1", "2x2x2"});
      args.insert(args.end(), {"--size", n});
      if (fz.Coin(0.3)) {
        args.insert(args.end(), {"--warp", fz.Pick(std::vector<std::string>{
                                               "square", "sqrt", "mu=square", "roughness=sqrt",
                                               "mu=cubic", "linear,", "bogus"})});
      }
      if (fz.Coin(0.3)) {
        args.insert(args.end(), {"--placement", fz.Pick(std::vector<std::string>{
                                                    "centers", "edges", "middle"})});
      }
      if (fz.Coin(0.3)) {
        args.insert(args.end(), {"--masking", fz.Pick(std::vector<std::string>{
                                                  "separable", "height-correlated", "none"})});
      }
      if (fz.Coin(0.4)) {
        args.insert(args.end(), {"--integrator", fz.Pick(std::vector<std::string>{
                                                     "quadrature", "qmc", "mc", "engine", "x"})});
      }
      if (fz.Coin(0.3)) args.insert(args.end(), {"--samples", fz.Number({"16", "64", "200"})});
      if (fz.Coin(0.3)) args.insert(args.end(), {"--tolerance", fz.Number({"1e-4", "1e-6"})});
      if (fz.Coin(0.2)) args.insert(args.end(), {"--pixel", fz.Pick(std::vector<std::string>{"half", "float", "double"})});
      if (fz.Coin(0.2)) args.push_back("--complement");
      if (fz.Coin(0.2)) args.push_back("--error-channel");
      if (fz.Coin(0.2)) args.insert(args.end(), {"--threads", fz.Number({"1", "2"})});
      args.insert(args.end(), {"-o", exr});
    } else {
      args = {"eval", "--model", model};
      if (fz.Coin(0.7)) args.insert(args.end(), {"--alpha", fz.Number({"0.3", "1e-4", "1", "2"})});
      if (fz.Coin(0.3)) args.insert(args.end(), {"--alpha-y", fz.Number({"0.01", "0.5"})});
      // Options of other models are rejected: mostly given where they apply.
      const bool rotated = model == "ellipsoid" || model == "sel";
      if (fz.Coin(model == "std" ? 0.6 : 0.03)) {
        args.insert(args.end(), {"--gamma", fz.Number({"1.501", "2", "1e6", "inf"})});
      }
      if (fz.Coin(rotated ? 0.5 : 0.03)) {
        args.insert(args.end(), {"--theta-x", fz.Number({"30", "80", "-80"})});
      }
      if (fz.Coin(0.5)) {
        args.insert(args.end(), {"--quantity", fz.Pick(std::vector<std::string>{
                                                   "D", "Lambda,G1", "G2,brdf", "pdf", "K", "Q"})});
      }
      if (fz.Coin(0.3)) args.insert(args.end(), {"--sweep", fz.Pick(std::vector<std::string>{"mu", "theta", "phi"})});
      if (fz.Coin(0.4)) args.insert(args.end(), {"--from", fz.Number({"0", "0.5", "1e-7"})});
      if (fz.Coin(0.4)) args.insert(args.end(), {"--to", fz.Number({"1", "89.9", "90"})});
      if (fz.Coin(0.4)) args.insert(args.end(), {"--count", fz.Number({"1", "7", "33"})});
      if (fz.Coin(0.3)) args.insert(args.end(), {"--mu-o", fz.Number({"1e-6", "0.5", "1"})});
      std::string fresnel = "one";
      if (fz.Coin(0.3)) {
        fresnel = fz.Pick(std::vector<std::string>{"schlick", "dielectric", "conductor", "one", "x"});
        args.insert(args.end(), {"--fresnel", fresnel});
      }
      if (fz.Coin(fresnel == "dielectric" ? 0.6 : 0.03)) {
        args.insert(args.end(), {"--eta", fz.Number({"1.5", "1", "0.7"})});
      }
      if (fz.Coin(fresnel == "schlick" ? 0.6 : 0.03)) {
        args.insert(args.end(), {"--f0", fz.Number({"0.04", "1", "0.9,0.6,0.3"})});
      }
      if (fz.Coin(0.3)) {
        args.insert(args.end(), {"--grid", fz.Pick(std::vector<std::string>{
                                               "slice", "hemisphere", "g1", "cube"})});
        args.insert(args.end(), {"--width", fz.Number({"8", "17", "1"}), "--height",
                                 fz.Number({"8", "5"}), "-o", exr});
        if (fz.Coin(0.3)) {
          args.insert(args.end(), {"--target", fz.Pick(std::vector<std::string>{
                                                   "SSE4", "AVX2", "SCALAR", "best", "NEON"})});
        }
      }
    }
    const ToolRun r = Execute(args, dir);
    std::string line;
    for (const std::string& a : args) line += " " + a;
    ASSERT_FALSE(r.signaled) << "crashed:" << line << "\n" << r.err;
    // 0 success, 1 bad value, 2 bad usage (a parse error).
    ASSERT_TRUE(r.status >= 0 && r.status <= 2) << "exit " << r.status << ":" << line;
    if (r.status == 0) {
      ++ok_runs;
      const bool wrote_exr = std::find(args.begin(), args.end(), "-o") != args.end();
      if (wrote_exr) {
        ASSERT_TRUE(std::filesystem::exists(exr)) << line;
        const ExrContents c = ReadExr(exr);
        for (const auto& ch : c.channels) {
          for (float v : ch.second) ASSERT_TRUE(std::isfinite(v)) << ch.first << ":" << line;
        }
      } else {
        EXPECT_TRUE(CsvIsFinite(r.out)) << line << "\n" << r.out.substr(0, 400);
      }
    } else {
      ++error_runs;
      if (std::getenv("BRDFBAKE_FUZZ_VERBOSE")) std::printf("%s\n  -> %s", line.c_str(), r.err.c_str());
      std::string err = r.err;
      while (!err.empty() && err.back() == '\n') err.pop_back();
      EXPECT_FALSE(err.empty()) << line;
      EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line:" << line << "\n" << err;
      EXPECT_TRUE(r.out.empty()) << line;
      EXPECT_FALSE(std::filesystem::exists(exr)) << "partial file left:" << line;
    }
    // No temporary files left beside the output either way.
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == "out.exr" || name == "stdout" || name == "stderr")
          << "stray file " << name << " after" << line;
    }
  }
  std::printf("%d runs: %d succeeded, %d rejected with a one-line error\n", kRuns, ok_runs,
              error_runs);
  EXPECT_GT(ok_runs, kRuns / 5);
  EXPECT_GT(error_runs, kRuns / 5);
}

// One run of the tool on a scene file: within `seconds` (timeout), and an
// error, if any, on one line. `expect` is "" for a scene that loads, else a
// part of the one-line error.
struct SceneCase {
  std::string name;  // file name, with its extension
  std::string text;
  std::string expect;
};

void ExpectSceneRun(const std::string& dir, const SceneCase& c, const std::string& command = "plan") {
  const std::string path = dir + "/" + c.name;
  test::WriteText(path, c.text);
  const ToolRun r = ExecuteShell("timeout 60 \"$BRDFBAKE\" " + command + " " + Quote(path) +
                                     (command == "bake" ? " -o " + Quote(dir + "/out") : ""),
                                 dir);
  ASSERT_FALSE(r.signaled) << c.name << ": " << r.err.substr(0, 300);
  ASSERT_NE(r.status, 124) << c.name << ": timed out";
  std::string err = r.err;
  while (!err.empty() && err.back() == '\n') err.pop_back();
  if (c.expect.empty()) {
    EXPECT_EQ(r.status, 0) << c.name << ": " << err.substr(0, 300);
    EXPECT_EQ(err, "") << c.name;
    return;
  }
  EXPECT_EQ(r.status, 1) << c.name << ": " << err.substr(0, 300);
  EXPECT_EQ(err.find('\n'), std::string::npos) << c.name << ": " << err.substr(0, 300);
  EXPECT_EQ(err.rfind("brdfbake: error: ", 0), 0u) << c.name << ": " << err.substr(0, 300);
  EXPECT_LE(err.size(), 2100u) << c.name << ": " << err.substr(0, 300);
  EXPECT_NE(err.find(c.expect), std::string::npos) << c.name << ": " << err.substr(0, 300);
  EXPECT_EQ(r.out, "") << c.name;
}

const std::string kGltfHead = "{\"asset\":{\"version\":\"2.0\"},";
const std::string kTomlMaterial = "[[material]]\nname = \"m\"\nmodel = \"ggx\"\nroughness = 0.5\n";

// A recursive parser overflows its stack on deep enough nesting (toml++ on
// a table header of 100,000 dotted parts): such files are refused before
// they are parsed.
TEST(SceneFuzzTest, DeepNestingFailsInOneLine) {
  const std::string dir = test::Scratch("fuzz_deep");
  for (int n : {20000, 100000}) {
    const std::string k = std::to_string(n);
    std::string dotted = "a";
    for (int i = 1; i < n; ++i) dotted += ".a";
    const SceneCase cases[] = {
        {"arrays" + k + ".gltf",
         kGltfHead + "\"materials\":[{\"extras\":" + std::string(n, '[') + std::string(n, ']') + "}]}",
         "nested deeper than 512 levels"},
        {"objects" + k + ".gltf",
         [&] {
           std::string t = kGltfHead + "\"materials\":[{\"extras\":";
           for (int i = 0; i < n; ++i) t += "{\"a\":";
           return t + "1" + std::string(n, '}') + "}]}";
         }(),
         "nested deeper than 512 levels"},
        {"arrays" + k + ".toml", kTomlMaterial + "x = " + std::string(n, '[') + std::string(n, ']') + "\n",
         "exceeded maximum nested value depth"},
        {"tables" + k + ".toml",
         [&] {
           std::string t = kTomlMaterial + "x = ";
           for (int i = 0; i < n; ++i) t += "{a=";
           return t + "1" + std::string(n, '}') + "\n";
         }(),
         "exceeded maximum nested value depth"},
        {"header" + k + ".toml", kTomlMaterial + "[" + dotted + "]\n", "a key of more than 64 dotted parts"},
        {"key" + k + ".toml", kTomlMaterial + dotted + " = 1\n", "a key of more than 64 dotted parts"},
    };
    for (const SceneCase& c : cases) ExpectSceneRun(dir, c);
  }
  // Dots inside strings and comments, and values' decimal points, are no key.
  ExpectSceneRun(dir, {"dots.toml",
                       "# " + std::string(200, '.') + "\n[[material]]\nname = \"" + std::string(200, '.') +
                           "\"\nmodel = \"ggx\"\nroughness = [0.1, 0.5]\n",
                       ""});
}

// Whether strace can trace the tool here (it needs ptrace).
bool CanTrace(const std::string& dir) {
  if (!test::Have("strace")) return false;
  return ExecuteShell("strace -f -qq -e trace=%file -o /dev/null true", dir).status == 0;
}

// Buffers and images that name other files: the scene loads (it needs only
// its materials), nothing of those files shows in the output, the FIFO
// does not block, and under strace no file syscall names any of them
// (opened, a FIFO would block the tool, a missing or short file reveal its
// existence or size, and a huge one be read whole).
TEST(SceneFuzzTest, UrisNamingOtherFilesAreNeverOpened) {
  const std::string root = test::Scratch("fuzz_uris");
  const std::string dir = root + "/scenes";
  std::filesystem::create_directories(dir);
  const std::string secret = root + "/secret_b7.txt";
  test::WriteText(secret, "TOPSECRET-b7 contents\n");
  ASSERT_EQ(ExecuteShell("mkfifo " + Quote(root + "/fifo_b7") + " && truncate -s 3G " +
                             Quote(root + "/huge_b7.bin"),
                         root)
                .status,
            0);
  const std::vector<std::string> uris = {
      secret,
      "../secret_b7.txt",
      "..%2fsecret_b7.txt",
      "%2fetc%2fpasswd",
      "/etc/passwd",
      "../../../../../../../../etc/passwd",
      root + "/fifo_b7",
      "../fifo_b7",
      root + "/huge_b7.bin",
      "../huge_b7.bin",
      "file://" + secret,
      "data:application/octet-stream;base64," + std::string(6 << 20, 'A'),
  };
  const bool trace = CanTrace(root);
  if (!trace) std::printf("strace unavailable: checking output and time only\n");
  // One scene per URI, whose one material (anisotropic GGX at roughness 1,
  // where the collapse is exact and the tables small) plans at once, and
  // one scene with every URI and a GGX material, planned and baked.
  for (size_t i = 0; i <= uris.size(); ++i) {
    const bool all = i == uris.size();
    std::string buffers, images;
    for (size_t j = 0; j < uris.size(); ++j) {
      if (!all && j != i) continue;
      const std::string sep = buffers.empty() ? "" : ",";
      buffers += sep + "{\"uri\":\"" + uris[j] + "\",\"byteLength\":16}";
      images += sep + "{\"uri\":\"" + uris[j] + "\"}";
    }
    const std::string name = "uri" + std::to_string(i) + ".gltf";
    const std::string material =
        all ? "\"pbrMetallicRoughness\":{\"roughnessFactor\":0.4,\"metallicRoughnessTexture\":{\"index\":0}}"
            : "\"extensions\":{\"KHR_materials_anisotropy\":{\"anisotropyStrength\":0.5}}";
    test::WriteText(dir + "/" + name, kGltfHead + "\"buffers\":[" + buffers + "],\"images\":[" + images +
                                          "],\"textures\":[{\"source\":0}],\"materials\":[{\"name\":\"m\"," +
                                          material + "}]}");
    const std::string what = all ? "every URI" : uris[i].substr(0, 60);
    // Each run within a minute, exit 0 and quiet on stderr, and nothing of
    // the named files in the output.
    const auto check = [&](const ToolRun& r, const std::string& run) {
      ASSERT_FALSE(r.signaled) << run << " " << what;
      ASSERT_NE(r.status, 124) << run << " " << what << ": timed out";
      EXPECT_EQ(r.status, 0) << run << " " << what << ": " << r.err.substr(0, 300);
      EXPECT_EQ(r.err, "") << run << " " << what;
      for (const std::string& leak : {std::string("TOPSECRET"), std::string("3221225472"),
                                      std::string("3 GiB"), std::string("root:")}) {
        EXPECT_EQ(r.out.find(leak), std::string::npos) << run << " " << what << " printed " << leak;
      }
    };
    const std::string plan = "\"$BRDFBAKE\" plan " + name;
    check(ExecuteShell("cd " + Quote(dir) + " && timeout 60 " + plan, root), "plan");
    if (!trace) continue;
    // Under strace, which records every system call that takes a path: the
    // plan, and for the scene with every URI the bake. (LeakSanitizer cannot
    // run under ptrace, so it is off in these runs of a sanitized build;
    // the plan above ran with it.)
    for (const std::string& run : {plan, "\"$BRDFBAKE\" bake " + name + " -o " + Quote(root + "/out")}) {
      if (!all && run != plan) continue;
      const ToolRun t = ExecuteShell("cd " + Quote(dir) +
                                         " && ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" "
                                         "timeout 60 strace -f -qq -e trace=%file -o " +
                                         Quote(root + "/trace") + " " + run,
                                     root);
      check(t, run == plan ? "strace plan" : "strace bake");
      const std::string log = test::Slurp(root + "/trace");
      EXPECT_NE(log.find(name), std::string::npos) << "the trace has no scene open: " << log.substr(0, 300);
      std::istringstream lines(log);
      for (std::string line; std::getline(lines, line);) {
        for (const std::string& named : {std::string("secret_b7"), std::string("fifo_b7"),
                                         std::string("huge_b7"), std::string("/etc/passwd")}) {
          EXPECT_EQ(line.find(named), std::string::npos) << what << " touched a named file: " << line;
        }
      }
    }
    if (all) {
      EXPECT_TRUE(std::filesystem::exists(root + "/out/manifest.json"));
    }
  }
  std::filesystem::remove(root + "/huge_b7.bin");
}

// Values of the wrong type, out of range or malformed: refused in one line
// naming the field, or (where the value is valid) loaded. A value of
// megabytes is shown by its start and size.
TEST(SceneFuzzTest, TypeConfusionFailsInOneLine) {
  const std::string dir = test::Scratch("fuzz_types");
  const std::string mat = kGltfHead + "\"materials\":[{\"name\":\"c\",";
  const std::string pbr = mat + "\"pbrMetallicRoughness\":";
  const std::string toml_std = "[[material]]\nname = \"m\"\nmodel = \"std\"\nroughness = 0.5\n";
  const std::string toml_ggx = "[[material]]\nname = \"m\"\nmodel = \"ggx\"\n";
  const std::string big(4 << 20, 'x');
  const std::vector<SceneCase> cases = {
      // glTF: strings for numbers, objects for arrays and back, booleans, null.
      {"str.gltf", pbr + "{\"roughnessFactor\":\"0.5\"}}]}", "roughnessFactor': expected a number, got a string"},
      {"bool.gltf", pbr + "{\"roughnessFactor\":true}}]}", "expected a number, got a boolean"},
      {"objarr.gltf", kGltfHead + "\"materials\":{\"0\":{}}}", "'materials' is a object, not an array"},
      {"arrobj.gltf", pbr + "[0.5]}]}", "field 'pbrMetallicRoughness': expected an object"},
      {"extarr.gltf", mat + "\"extensions\":{\"KHR_materials_anisotropy\":[1]}}]}",
       "field 'extensions.KHR_materials_anisotropy': expected an object"},
      {"nullname.gltf", kGltfHead + "\"materials\":[{\"name\":null}]}", "field 'name': expected a string"},
      {"nullmats.gltf", kGltfHead + "\"materials\":null}", "'materials' is a null, not an array"},
      {"version.gltf", "{\"asset\":{\"version\":2.0},\"materials\":[{}]}", "no 'asset.version' string"},
      // Indices: negative, fractional, beyond 2^64, and naming no texture.
      {"negindex.gltf", pbr + "{\"metallicRoughnessTexture\":{\"index\":-1}}}]}", "integer 'index' >= 0"},
      {"fracindex.gltf", pbr + "{\"metallicRoughnessTexture\":{\"index\":0.5}}}]}", "integer 'index' >= 0"},
      {"hugeindex.gltf", pbr + "{\"metallicRoughnessTexture\":{\"index\":18446744073709551616}}}]}",
       "integer 'index' >= 0"},
      {"maxindex.gltf", pbr + "{\"metallicRoughnessTexture\":{\"index\":18446744073709551615}}}]}",
       "index': 18446744073709551615 names no texture (the file has 0)"},
      {"dangling.gltf",
       kGltfHead + "\"textures\":[{\"source\":0}],\"materials\":[{\"pbrMetallicRoughness\":"
                   "{\"metallicRoughnessTexture\":{\"index\":1}}}]}",
       "1 names no texture (the file has 1)"},
      // Numbers JSON does not have, or cannot hold.
      {"nan.gltf", pbr + "{\"roughnessFactor\":NaN}}]}", "invalid JSON"},
      {"inf.gltf", pbr + "{\"roughnessFactor\":Infinity}}]}", "invalid JSON"},
      {"ninf.gltf", pbr + "{\"roughnessFactor\":-Infinity}}]}", "invalid JSON"},
      {"overflow.gltf", pbr + "{\"roughnessFactor\":1e400}}]}", "number overflow"},
      {"underflow.gltf", pbr + "{\"roughnessFactor\":1e-400}}]}", ""},
      {"negzero.gltf", pbr + "{\"roughnessFactor\":-0.0}}]}", ""},
      // Duplicate keys: which one a reader keeps is not defined.
      {"dupkey.gltf", pbr + "{\"roughnessFactor\":0.2,\"roughnessFactor\":0.9}}]}",
       "the key 'roughnessFactor' appears twice in one object"},
      {"dupmats.gltf", kGltfHead + "\"materials\":[{}],\"materials\":[{}]}", "the key 'materials' appears twice"},
      // Bytes that are not UTF-8, a NUL, and a byte-order mark (allowed).
      {"latin1.gltf", kGltfHead + "\"materials\":[{\"name\":\"\xff\xfe\x80\"}]}", "ill-formed UTF-8"},
      {"latin1key.gltf", kGltfHead + "\"materials\":[{\"\xff\":1}]}", "ill-formed UTF-8"},
      {"nul.gltf", kGltfHead + "\"materials\":[{\"name\":\"a" + '\0' + "b\"}]}", "NUL"},
      {"bom.gltf", "\xef\xbb\xbf" + kGltfHead + "\"materials\":[{}]}", ""},
      // Megabytes where a name or version goes.
      {"longname.gltf", kGltfHead + "\"materials\":[{\"name\":\"" + big +
                            "\",\"pbrMetallicRoughness\":{\"roughnessFactor\":2}}]}",
       "xxx... (4194304 bytes)'"},
      {"longversion.gltf", "{\"asset\":{\"version\":\"" + big + "\"},\"materials\":[{}]}", "(4194304 bytes)"},
      // TOML.
      {"str.toml", toml_ggx + "roughness = \"0.5\"\n", "field 'roughness': expected a number"},
      {"table.toml", toml_ggx + "roughness = {a = 1}\n", "field 'roughness': expected a number"},
      {"strs.toml", toml_ggx + "roughness = [\"a\", \"b\"]\n", "a range is two numbers"},
      {"nan.toml", toml_ggx + "roughness = nan\n", "nan is outside [0, 1]"},
      {"negnan.toml", toml_ggx + "roughness = -nan\n", "nan is outside [0, 1]"},
      {"inf.toml", toml_ggx + "roughness = inf\n", "inf is outside [0, 1]"},
      {"int.toml", toml_ggx + "roughness = 99999999999999999999\n", "not representable in 64 bits"},
      {"date.toml", toml_ggx + "roughness = 1979-05-27\n", "field 'roughness': expected a number"},
      {"negzero.toml", toml_ggx + "roughness = -0.0\n", ""},
      {"dupkey.toml", toml_ggx + "roughness = 0.5\nroughness = 0.6\n", "cannot redefine"},
      {"duptable.toml", "[engine]\npixel = \"half\"\n[engine]\npixel = \"float\"\n" + kTomlMaterial,
       "cannot redefine existing table 'engine'"},
      {"mattable.toml", "[material]\nname = \"m\"\n", "'material' must be an array of tables"},
      {"enginearray.toml", "engine = [1]\n" + kTomlMaterial, "'engine' must be a table"},
      {"mixed.toml", "[engine]\ntables = [\"E\", 1]\n" + kTomlMaterial, "expected an array of strings"},
      {"lut.toml", "[engine]\nmax_lut_size = -9223372036854775808\n" + kTomlMaterial, "is outside [2, 8192]"},
      {"nameint.toml", "[[material]]\nname = 5\nmodel = \"ggx\"\nroughness = 0.5\n", "field 'name': expected a string"},
      {"gammastr.toml", toml_std + "gamma = \"1.6\"\n", "field 'gamma': expected a number or \"inf\""},
      {"gammanan.toml", toml_std + "gamma = nan\n", "gamma': must be >= 1.500001 or inf"},
      {"gammaninf.toml", toml_std + "gamma = -inf\n", "gamma': must be >= 1.500001 or inf"},
      {"gammainf.toml", toml_std + "gamma = inf\n", ""},
      {"latin1.toml", "[[material]]\nname = \"\xff\xfe\"\nmodel = \"ggx\"\nroughness = 0.5\n", "invalid utf-8"},
      {"latin1key.toml", kTomlMaterial + "\xff = 1\n", "invalid utf-8"},
      {"nul.toml", "[[material]]\nname = \"m" + std::string(1, '\0') + "\"\nmodel = \"ggx\"\nroughness = 0.5\n",
       "control characters"},
      {"longkey.toml", kTomlMaterial + big + " = 1\n", "field 'xxx"},
      {"longmodel.toml", "[[material]]\nname = \"m\"\nmodel = \"" + big + "\"\nroughness = 0.5\n",
       "(4194304 bytes)' is not ggx"},
  };
  for (const SceneCase& c : cases) ExpectSceneRun(dir, c);
  // GLB containers whose header or chunk lengths lie.
  const auto le32 = [](uint32_t v) {
    std::string b(4, '\0');
    for (int k = 0; k < 4; ++k) b[k] = char((v >> (8 * k)) & 0xff);
    return b;
  };
  std::string json = kGltfHead + "\"materials\":[{\"name\":\"g\"}]}";
  while (json.size() % 4) json += ' ';
  const auto glb = [&](uint32_t version, uint32_t total, uint32_t chunk, const std::string& type,
                       const std::string& body) {
    return "glTF" + le32(version) + le32(total) + le32(chunk) + type + body;
  };
  const uint32_t size = uint32_t(20 + json.size()), len = uint32_t(json.size());
  const std::string bin("BIN\0", 4);
  const std::vector<SceneCase> glbs = {
      {"ok.glb", glb(2, size, len, "JSON", json), ""},
      {"chunkmax.glb", glb(2, size, 0xffffffffu, "JSON", json), "the GLB lengths exceed the file"},
      {"totalmax.glb", glb(2, 0xffffffffu, len, "JSON", json), "the GLB lengths exceed the file"},
      {"totalzero.glb", glb(2, 0, len, "JSON", json), "the GLB lengths exceed the file"},
      {"totalsmall.glb", glb(2, 12, len, "JSON", json), "the GLB lengths exceed the file"},
      {"chunkover.glb", glb(2, size, len + 4, "JSON", json), "the GLB lengths exceed the file"},
      {"chunkzero.glb", glb(2, size, 0, "JSON", json), "invalid JSON"},
      {"chunkshort.glb", glb(2, size, len - 3, "JSON", json), "invalid JSON"},
      {"binfirst.glb", glb(2, size, len, bin, json), "the first GLB chunk is not JSON"},
      {"version.glb", glb(0xffffffffu, size, len, "JSON", json), "GLB version 4294967295, not 2"},
      {"header.glb", "glTF" + le32(2) + le32(12), "shorter than a GLB header"},
      {"garbage.glb", glb(2, size, len, "JSON", std::string(json.size(), '\xff')), "invalid JSON"},
  };
  for (const SceneCase& c : glbs) ExpectSceneRun(dir, c);
}

}  // namespace
}  // namespace brdfbake

#endif  // BRDFBAKE_CLI_PATH
