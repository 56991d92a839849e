// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A reference for the rough dielectric's E_avg (rules/glass/glass_average.h)
// the other way round: E_avg = 2 integral_0^1 E(mu) mu dmu = 4 integral_0^1
// E(s^2) s^3 ds over the visible-normal rule for E (glass_albedo.h), which
// integrates over h at a fixed view, where the E_avg rule integrates over
// the view about each h. The pieces in s are [0, 1/4], [1/4, 1], cut at
// the critical cosine's root s_c = (1 - eta^2)^(1/4) for eta < 1 (E has a
// square-root edge there) and mapped t^2 towards it; Gauss-Kronrod 15,
// the worst piece bisected, each E to a tenth of the tolerance.

#ifndef BRDFBAKE_TESTS_REFERENCE_GLASS_EAVG_REFERENCE_H_
#define BRDFBAKE_TESTS_REFERENCE_GLASS_EAVG_REFERENCE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "rules/glass/glass_albedo.h"
#include "rules/glass/glass_albedo_rule.h"

namespace brdfbake {
namespace test {

inline RuleResult GlassEavgOverMu(double alpha, double eta, Masking masking, double tol,
                                  DielectricPart part = DielectricPart::kBoth) {
  const bool edge = eta < 1 && part != DielectricPart::kTransmissionSchlick;
  const double sc = edge ? std::sqrt(std::sqrt((1 - eta) * (1 + eta))) : -1;
  std::vector<double> cuts = {0, 0.25, 1};
  if (sc > 0 && sc < 1) cuts.push_back(sc);
  std::sort(cuts.begin(), cuts.end());
  std::vector<MappedSegment> segs;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] > cuts[i]) segs.push_back({cuts[i], cuts[i + 1], cuts[i] == sc, cuts[i + 1] == sc});
  }
  return GlassSegmentsRule(segs, 1.0, tol, 400, [&](const double* x, double* v, double* e, int k) {
    for (int i = 0; i < 15 * k; ++i) {
      const double s = x[i];
      const RuleResult r = GlassAlbedo(alpha, eta, masking, std::max(s * s, 1e-7), 0.1 * tol, 4096, part);
      v[i] = 4 * s * s * s * r.value;
      e[i] = 4 * s * s * s * r.error;
    }
  });
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_GLASS_EAVG_REFERENCE_H_
