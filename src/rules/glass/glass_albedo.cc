// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/glass/glass_albedo.h"

#include "rules/glass/glass_albedo_rule.h"

namespace brdfbake {

RuleResult GlassAlbedo(const RoughDielectric<double, GgxNdf<double>>& bsdf, double mu, double tol, int max_pieces,
                       DielectricPart part, double eta) {
  const GlassFrame frame(bsdf.ndf().alpha_x(), GlassRuleEta(bsdf.eta(), eta, part), mu);
  const Vec3<double> wo{frame.so, 0, frame.mu};
  const double lambda_o = bsdf.Lambda(wo);
  const ScalarGlassNodes nodes{&bsdf, &frame, 1 + lambda_o, lambda_o, part};
  return GlassAlbedoWith(frame, tol, max_pieces, nodes);
}

RuleResult GlassAlbedo(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                       DielectricPart part) {
  if (alpha == 0) return SmoothGlassAlbedo(eta, mu, part);
  const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(alpha), eta, masking,
                                                     DielectricTransport::kImportance);
  return GlassAlbedo(bsdf, mu, tol, max_pieces, part, eta);
}

}  // namespace brdfbake
