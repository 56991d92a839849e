// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What the scene suites share: a planned table by its file name, and the
// plan's lines joined for a message.

#ifndef BRDFBAKE_TESTS_UTIL_SCENE_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_SCENE_UTIL_H_

#include <string>
#include <vector>

#include "brdfbake/scene.h"

namespace brdfbake {
namespace test {

// The planned table written to `file`, or nullptr.
inline const PlannedTable* FindPlanned(const ScenePlan& plan, const std::string& file) {
  for (const PlannedTable& p : plan.tables) {
    if (p.file == file) return &p;
  }
  return nullptr;
}

// Lines joined, each ended by a newline.
inline std::string Joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_SCENE_UTIL_H_
