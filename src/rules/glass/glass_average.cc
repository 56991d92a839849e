// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/glass/glass_average.h"

#include "rules/glass/glass_average_rule.h"

namespace brdfbake {

RuleResult GlassAlbedoAverage(double alpha, double eta, Masking masking, double tol, int max_pieces,
                              DielectricPart part) {
  const AverageModel m = AverageModelOf(alpha, eta, masking, part);
  return GlassAlbedoAverageWith(m, tol, max_pieces, ScalarAverageLines{&m});
}

}  // namespace brdfbake
