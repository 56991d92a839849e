// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/targets.h"

#include <hwy/highway.h>
#include <hwy/targets.h>

namespace brdfbake {

std::vector<std::string> CompiledTargets() {
  std::vector<std::string> names;
  for (int64_t targets = HWY_TARGETS; targets != 0; targets &= targets - 1) {
    const int64_t bit = targets & (~targets + 1);
    names.push_back(hwy::TargetName(bit));
  }
  return names;
}

std::string BestTarget() {
  const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  if (usable == 0) return "none";
  return hwy::TargetName(usable & (~usable + 1));
}

}  // namespace brdfbake
