// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A table baked in-process through brdfbake::baker: the GGX E table,
// 8 x 8, checked at mu = 1, alpha = 1 against the exact 1 - ln 2
// (height-correlated masking). Exits non-zero on any disagreement.

#include <cmath>
#include <cstdio>

#include "brdfbake/bake.h"

int main() {
  using namespace brdfbake;
  BakeSpec spec;  // E, ggx, height-correlated, quadrature, edges placement
  spec.mu.size = 8;
  spec.roughness.size = 8;
  const Table table = Bake(spec);
  // Edges placement: the last column is mu = 1, the last row roughness = 1.
  const double e = table.channels[0].values[table.width * table.height - 1];
  const double exact = 1 - std::log(2.0);
  std::printf("E(mu = 1, alpha = 1) = %.12f (exact %.12f), claimed max error %.3g\n", e, exact,
              table.max_abs_error);
  return std::abs(e - exact) <= table.max_abs_error + 1e-12 ? 0 : 1;
}
