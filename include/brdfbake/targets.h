// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// SIMD targets: which ones this build compiled, which the CPU runs, which
// one the batch kernels (batch.h) and the baker's SIMD rules dispatch to.

#ifndef BRDFBAKE_TARGETS_H_
#define BRDFBAKE_TARGETS_H_

#include <string>
#include <vector>

namespace brdfbake {

// Every target compiled into this build, best first.
std::vector<std::string> CompiledTargets();
// The best target this CPU runs, or "none".
std::string BestTarget();
// The target dynamic dispatch picks now (BestTarget unless ForceTarget).
std::string BatchTarget();
// Restricts dynamic dispatch to the named target (AVX3, AVX2, SSE4, ...,
// or "best" to undo). Throws std::invalid_argument naming the target if it
// was not compiled in or this CPU lacks it.
void ForceTarget(const std::string& name);
// Every target that is compiled in and runs on this CPU, best first.
std::vector<std::string> AvailableTargets();

}  // namespace brdfbake

#endif  // BRDFBAKE_TARGETS_H_
