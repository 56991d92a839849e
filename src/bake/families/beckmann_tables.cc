// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The beckmann family's baker row (family_row.h): E, dfg and E_avg by
// TexelFor (texel_for.h), E with the azimuth in closed form
// (beckmann_azimuth.h).

#include "bake/family_row.h"
#include "bake/texel_for.h"
#include "brdfbake/models/beckmann.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {
namespace {

const BakerRow kBeckmannRow = {
    ModelKind::kBeckmann,
    Bit(TableKind::kE) | Bit(TableKind::kEavg) | Bit(TableKind::kDfg),
    false,
    "E, E_avg and dfg",
    [](const BakeSpec& slice, const TexelAt& at, uint64_t seed) {
      if (at.alpha < kMinAlpha<double>) return MirrorTexel(at.mu);
      return TexelFor(BeckmannNdf<double>(at.alpha), at.mu, slice, seed);
    },
    nullptr,
    nullptr,
    nullptr,
    [](const BakeSpec&, nlohmann::json* j) { (*j)["alpha"] = "roughness^2"; },
    [](const BakeSpec& spec, nlohmann::json* j) {
      if (spec.integrator == IntegratorKind::kQuadrature) {
        MicrofacetQuadratureJson(spec, spec.table != TableKind::kDfg, j);
      }
      MirrorJson(j);
    },
    1.0};

}  // namespace

extern const BakerFamily kBakerFamily_beckmann = {&kBeckmannRow, 1};

}  // namespace brdfbake
