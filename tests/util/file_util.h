// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Files in tests: a scratch directory per test, whole-file reads and
// writes, the numbers a test program prints.

#ifndef BRDFBAKE_TESTS_UTIL_FILE_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_FILE_UTIL_H_

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace brdfbake {
namespace test {

inline std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void WriteText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The numbers in a text, in order (a test program's output).
inline std::vector<double> Numbers(const std::string& text) {
  std::stringstream ss(text);
  std::vector<double> v;
  for (double x; ss >> x;) v.push_back(x);
  return v;
}

// An empty directory of its own under the test's temporary directory.
inline std::string Scratch(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/brdfbake_" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Whether `tool` is on the PATH.
inline bool Have(const char* tool) {
  return std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) == 0;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_FILE_UTIL_H_
