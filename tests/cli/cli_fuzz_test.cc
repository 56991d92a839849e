// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A seeded random sweep over the command line of `brdfbake eval` and
// `brdfbake bake`: arguments drawn from valid values, edge values (0, 1,
// 1e-300, huge), and garbage (NaN, inf, negative, text, empty). Every run
// must end with exit status 0, 1 or 2 (usage), never a signal; a failure prints one
// line on stderr, nothing on stdout, and leaves no output file; a success
// leaves a file (or CSV) whose every value is finite.

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

}  // namespace
}  // namespace brdfbake

#endif  // BRDFBAKE_CLI_PATH
