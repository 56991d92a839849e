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

namespace {

// The names of the targets in `mask`, best first.
std::vector<std::string> Names(int64_t mask) {
  std::vector<std::string> names;
  for (int64_t t = mask; t != 0; t &= t - 1) names.push_back(hwy::TargetName(t & (~t + 1)));
  return names;
}

// The compiled targets this CPU runs. hwy::SupportedTargets() returns the
// forced set once ForceTarget has narrowed it, so the CPU's own set is read
// once, before this file's functions first narrow anything.
int64_t UsableTargets() {
  static const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  return usable;
}

}  // namespace

std::vector<std::string> CompiledTargets() { return Names(HWY_TARGETS); }

std::string BestTarget() {
  const int64_t usable = UsableTargets();
  if (usable == 0) return "none";
  return hwy::TargetName(usable & (~usable + 1));
}

std::string BatchTarget() { return hwy::TargetName(HWY_DYNAMIC_DISPATCH(ThisTarget)()); }

std::vector<std::string> AvailableTargets() { return Names(UsableTargets()); }

void ForceTarget(const std::string& name) {
  const int64_t usable = UsableTargets();
  if (name == "best") {
    hwy::SetSupportedTargetsForTest(0);
    return;
  }
  for (int64_t t = HWY_TARGETS; t != 0; t &= t - 1) {
    const int64_t bit = t & (~t + 1);
    if (name == hwy::TargetName(bit)) {
      if (!(usable & bit)) {
        throw std::invalid_argument("target " + name + " is compiled in but this CPU lacks it");
      }
      hwy::SetSupportedTargetsForTest(bit);
      return;
    }
  }
  std::string list;
  for (const std::string& n : CompiledTargets()) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown target '" + name + "' (compiled: " + list + ", or best)");
}

}  // namespace brdfbake
#endif  // HWY_ONCE
