// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The std family's baker row (family_row.h): the Student's-t NDF's E, dfg
// and E_avg by TexelFor (texel_for.h), E at finite gamma with the azimuth
// from tabulated moments (std_azimuth.h), at gamma = inf Beckmann's.

#include <cmath>

#include "bake/family_row.h"
#include "bake/texel_for.h"
#include "brdfbake/models/std_ndf.h"
#include "rules/std/std_azimuth.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {
namespace {

TexelEstimate StdTexel(const BakeSpec& slice, const TexelAt& at, uint64_t seed) {
  if (at.alpha < kMinAlpha<double>) return MirrorTexel(at.mu);
  return TexelFor(StudentTNdf<double>(at.alpha, at.alpha, slice.model.gamma), at.mu, slice, seed);
}

// For the STD below gamma 2 E(mu) is not smooth at normal incidence, and the
// adaptive E_avg rule bisected [1/4, 1] towards s = 1 again and again (8 to
// 10 times at gamma 1.501, each bisection 30 new E). Starting from the
// grading it converged to evaluates half as many E or fewer: measured over
// 64 roughnesses, Kronrod pieces (15 E each) evaluated per E_avg 18.0 -> 7.5
// at gamma 1.501 (4 levels), 14.2 -> 6.2 at 1.6 (3), 9.1 -> 4.8 at 1.8 (2);
// from gamma 2 on no grading is best (2.3 at 2 and 2.4 at 3, against 3.1
// with one level).
int StdEavgGrading(double gamma) { return gamma < 1.6 ? 4 : gamma < 1.75 ? 3 : gamma < 2 ? 2 : 0; }

void StdModelJson(const BakeSpec& spec, nlohmann::json* out) {
  nlohmann::json& j = *out;
  j["alpha"] = "roughness^2";
  if (spec.HasGammaAxis()) {
    j["gamma"] = "the gamma axis (brdfbake.axes); its last value inf is beckmann";
  } else {
    if (std::isinf(spec.model.gamma)) j["gamma"] = "inf"; else j["gamma"] = spec.model.gamma;
    if (std::isfinite(spec.model.gamma) && spec.model.gamma >= kStudentTBeckmannLimitGamma) {
      j["evaluated_as"] = "beckmann (the limit gamma -> inf; gamma >= 1e20 agrees with it to double precision)";
    }
  }
}

const BakerRow kStdRow = {
    ModelKind::kStudentT,
    Bit(TableKind::kE) | Bit(TableKind::kEavg) | Bit(TableKind::kDfg),
    false,
    "E, E_avg and dfg",
    StdTexel,
    nullptr,
    [](const BakeSpec& slice) { return StdEavgGrading(slice.model.gamma); },
    // The azimuthal moment tables, built here with every thread (a texel
    // that built one would hold the others waiting on its lock).
    [](const BakeSpec& slice) {
      if ((slice.integrator == IntegratorKind::kQuadrature || slice.integrator == IntegratorKind::kEngine) &&
          slice.table != TableKind::kDfg) {
        const double g = StudentTNdf<double>(1.0, 1.0, slice.model.gamma).gamma();
        if (std::isfinite(g)) StdAzimuthMomentsFor(g);
      }
    },
    StdModelJson,
    [](const BakeSpec& spec, nlohmann::json* j) {
      if (spec.integrator == IntegratorKind::kQuadrature) {
        const bool beckmann_e = spec.table != TableKind::kDfg && !spec.HasGammaAxis() &&
                                spec.model.gamma >= kStudentTBeckmannLimitGamma;
        MicrofacetQuadratureJson(spec, beckmann_e, j);
      }
      MirrorJson(j);
    },
    1.0,
    ClearStdAzimuthMoments};

}  // namespace

extern const BakerFamily kBakerFamily_std = {&kStdRow, 1};

}  // namespace brdfbake
