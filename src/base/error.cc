// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/error.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace brdfbake {

// Each "{name}" of a parameter in `text` as spell(name); other braces as
// they are.
std::string SpellParameters(const std::string& text, const std::function<std::string(const std::string&)>& spell) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    const size_t open = text.find('{', i);
    if (open == std::string::npos) break;
    const size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    const std::string name = text.substr(open + 1, close - open - 1);
    out += text.substr(i, open - i);
    if (IsParameterName(name)) {
      out += spell(name);
      i = close + 1;
    } else {
      out += '{';
      i = open + 1;
    }
  }
  return out + text.substr(i);
}

bool IsParameterName(const std::string& name) {
  static const char* const kNames[] = {
      // BakeSpec and its axes
      "table", "model", "masking", "integrator", "samples", "tolerance", "seed", "size", "range", "warp", "placement",
      "complement", "inverse", "part", "threads", "target", "pixel", "channels",
      // the output
      "output", "format", "shader", "symbol", "preset",
      // eval, grids and the report
      "quantity", "sweep", "from", "to", "count", "mu_o", "phi_o", "phi", "alpha", "alpha_x", "alpha_y", "roughness",
      "anisotropy", "ior", "exponent", "gamma", "visibility", "grid", "width", "height", "repeats"};
  return std::any_of(std::begin(kNames), std::end(kNames), [&](const char* n) { return name == n; });
}

ParameterError::ParameterError(const std::string& text)
    : std::invalid_argument(SpellParameters(text, [](const std::string& n) { return n; })), text_(text) {}

std::string ParameterError::Render(const std::function<std::string(const std::string&)>& spell) const {
  return SpellParameters(text_, spell);
}

std::string ErrorText(const std::exception& e) {
  const auto* p = dynamic_cast<const ParameterError*>(&e);
  return p ? p->text() : std::string(e.what());
}

}  // namespace brdfbake
