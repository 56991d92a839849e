// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sel family's baker row (family_row.h): sel_norm, the integral N of
// the squared ellipsoidal lobe over alpha_x x alpha_y, and N / (4 pi
// alpha_x alpha_y), by the rule of sel_norm.h.

#include "bake/family_row.h"
#include "lanes/sel_lanes.h"
#include "rules/sel/sel_norm.h"

namespace brdfbake {
namespace {

// N in e, the ratio in bias, each with its error.
TexelEstimate SelTexel(const BakeSpec& spec, const TexelAt& at, uint64_t) {
  const SelIntegral n = spec.simd ? SimdSelLobeIntegral(at.alpha_x, at.alpha_y, spec.tolerance)
                                  : SelLobeIntegral(at.alpha_x, at.alpha_y, spec.tolerance);
  TexelEstimate v;
  v.e = n.n;
  v.bias = n.ratio;
  v.err_e = n.n_error;
  v.err_bias = n.ratio_error;
  return v;
}

const BakerRow kSelRow = {
    ModelKind::kSel,
    Bit(TableKind::kSelNorm),
    true,
    "sel_norm, its lobe's integral ({table} sel_norm)",
    SelTexel,
    nullptr,
    nullptr,
    nullptr,
    [](const BakeSpec&, nlohmann::json* j) {
      (*j)["definition"] = "squared ellipsoidal lobe K(w; Q, alpha_x, alpha_y) of [TokuyoshiHarada]; its "
                           "integral does not depend on Q";
      (*j)["closed_form"] = "alpha_x = alpha_y = alpha: N = 4 pi alpha^2; as both go to 0, "
                            "N / (4 pi alpha_x alpha_y) -> 1";
    },
    [](const BakeSpec& spec, nlohmann::json* j) {
      if (spec.integrator == IntegratorKind::kQuadrature) {
        Describe(j,
                 "N = 4 pi alpha_x alpha_y G, G = (2/pi) int_0^{pi/2} int_0^1 g dx dphi over the "
                 "half vector of the stretched direction and the lobe axis in GGX slope "
                 "coordinates (x = 1 - u), g = 1 / |v' / k| (src/rules/sel/sel_norm.h)",
                 "Gauss-Kronrod 15 in x graded towards 0 and in phi graded towards the peak of g, "
                 "worst pieces bisected; the tolerance applies to G",
                 "sum of |K15 - G7| of both rules");
      }
      MirrorJson(j);
    },
    1.0};

}  // namespace

extern const BakerFamily kBakerFamily_sel = {&kSelRow, 1};

}  // namespace brdfbake
