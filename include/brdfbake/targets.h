// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// SIMD targets: which ones this build compiled and which the CPU runs.

#ifndef BRDFBAKE_TARGETS_H_
#define BRDFBAKE_TARGETS_H_

#include <string>
#include <vector>

namespace brdfbake {

// Names of the Highway targets compiled into this binary, best first.
std::vector<std::string> CompiledTargets();
// The best compiled target this CPU supports (the one dynamic dispatch uses).
std::string BestTarget();

}  // namespace brdfbake

#endif  // BRDFBAKE_TARGETS_H_
