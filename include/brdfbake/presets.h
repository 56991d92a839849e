// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets: the tables an engine ships, in its layouts and containers.

#ifndef BRDFBAKE_PRESETS_H_
#define BRDFBAKE_PRESETS_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"

namespace brdfbake {

// Engine presets.
struct PresetTable {
  BakeSpec spec;
  ImageLayout layout;
  Container container = Container::kExr;
  std::string file;    // default file name
  std::string symbol;  // array name (header, js)
};
struct Preset {
  std::string name;
  std::string description;  // one line: what the engine ships and what differs
  std::vector<PresetTable> tables;
  std::string header_file;  // when non-empty, every table also goes into this one header
};
const std::vector<Preset>& Presets();
const Preset& FindPreset(const std::string& name);  // throws std::invalid_argument

}  // namespace brdfbake

#endif  // BRDFBAKE_PRESETS_H_
