// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// An engine preset's tables baked and arranged as `bake --preset` does
// (default tolerance, every core), for the preset suites to share.

#ifndef BRDFBAKE_TESTS_UTIL_PRESET_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_PRESET_UTIL_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/presets.h"

namespace brdfbake {
namespace test {

struct BakedPreset {
  std::vector<Table> tables;
  std::vector<Image> images;  // each table in its preset table's layout
};

inline BakedPreset BakePreset(const std::string& name) {
  BakedPreset out;
  for (const PresetTable& pt : FindPreset(name).tables) {
    out.tables.push_back(Bake(pt.spec));
    out.images.push_back(ArrangePresetTable(pt, out.tables.back()));
  }
  return out;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_PRESET_UTIL_H_
