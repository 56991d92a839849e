// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The 15-point Gauss-Kronrod rule every adaptive rule of the baker uses,
// and what an adaptive rule returns.

#ifndef BRDFBAKE_SRC_QUADRATURE_KRONROD_H_
#define BRDFBAKE_SRC_QUADRATURE_KRONROD_H_

namespace brdfbake {

// The 15-point Kronrod rule on [-1, 1] with its embedded 7-point Gauss rule
// (Gauss weight 0 at the Kronrod-only nodes), nodes ascending.
struct KronrodRule {
  double x[15], wk[15], wg[15];
};
const KronrodRule& Kronrod15();

// An adaptive rule's integral, its error estimate and the pieces it took.
struct RuleResult {
  double value = 0, error = 0;
  int pieces = 0;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_KRONROD_H_
