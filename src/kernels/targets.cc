// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Target selection for every dynamically dispatched kernel (targets.h).

#include "brdfbake/targets.h"

#include <cstdint>
#include <stdexcept>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/targets.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/targets.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {

int64_t ThisTarget() { return HWY_TARGET; }

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(ThisTarget);

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

std::string BatchTarget() { return hwy::TargetName(HWY_DYNAMIC_DISPATCH(ThisTarget)()); }

std::vector<std::string> AvailableTargets() {
  std::vector<std::string> names;
  hwy::SetSupportedTargetsForTest(0);
  const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  for (int64_t t = usable; t != 0; t &= t - 1) names.push_back(hwy::TargetName(t & (~t + 1)));
  return names;
}

void ForceTarget(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);
  if (name == "best") return;
  const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  for (int64_t t = HWY_TARGETS; t != 0; t &= t - 1) {
    const int64_t bit = t & (~t + 1);
    if (name == hwy::TargetName(bit)) {
      if (!(usable & bit)) {
        throw std::invalid_argument("--target: " + name + " is compiled in but this CPU lacks it");
      }
      hwy::SetSupportedTargetsForTest(bit);
      return;
    }
  }
  std::string list;
  for (int64_t t = HWY_TARGETS; t != 0; t &= t - 1) {
    list += std::string(list.empty() ? "" : ", ") + hwy::TargetName(t & (~t + 1));
  }
  throw std::invalid_argument("--target: unknown target '" + name + "' (compiled: " + list +
                              ", or best)");
}

}  // namespace brdfbake
#endif  // HWY_ONCE
