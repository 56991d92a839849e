// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The table baker (docs/format.md): bakes the table a BakeSpec
// (table_spec.h) describes, with a choice of integrators, each estimating
// its own error per texel, and integrates single texels.

#ifndef BRDFBAKE_BAKE_H_
#define BRDFBAKE_BAKE_H_

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "brdfbake/estimate.h"
#include "brdfbake/model.h"
#include "brdfbake/pixel_type.h"
#include "brdfbake/table_spec.h"

namespace brdfbake {

// One baked channel: its name, meaning and definition (ShapeOf) and values.
struct Channel {
  std::string name;
  Meaning meaning;
  std::string definition;
  std::vector<double> values;  // the baked values (after the range clamp)
  std::vector<float> stored;   // the values rounded to the pixel type
  std::vector<uint16_t> half_bits;  // the same as IEEE half bits (half pixels only)
};

struct Table {
  BakeSpec spec;
  std::vector<Axis> axes;  // fastest varying first
  // A gamma axis stacks its slices vertically: height = rows x slices.
  int width = 0, height = 0;
  std::vector<Channel> channels;
  double max_abs_error = 0;   // largest estimated error of any stored value
  double integration_error = 0;  // the same before rounding to the pixel type
  double seconds = 0;         // wall time of the bake
  std::string model_json;     // brdfbake.model
  std::string integrator_json;
};

// Progress callback: done, total (texels or rows).
using ProgressFn = std::function<void(int64_t done, int64_t total)>;

Table Bake(const BakeSpec& spec, const ProgressFn& progress = nullptr);

// Bakes build some tables of their own once per process and keep them for
// the next bakes: the STD's azimuthal moments per gamma (a few ms each).
// This frees them, so that the next bake builds them again (benchmarks time
// whole bakes this way). Not while a bake runs.
void ReleaseBakeCaches();

// One texel of the E / dfg tables (brdfbake/estimate.h) with the spec's
// model, masking and integrator at (roughness, mu); of gen_schlick_s and
// gen_schlick_ior_s (in `e`) at the one exponent or ior of a size-1 axis.
TexelEstimate IntegrateTexel(const BakeSpec& spec, double roughness, double mu,
                             uint64_t texel_seed = 0);

// The largest E (and E_avg) of the spec's model: 1, or +inf for charlie
// and disney-diffuse, which do not conserve energy (the Disney diffuse
// lobe reflects more than it receives at high roughness, the sheen's
// visibility terms exceed the masking bound at grazing angles).
double StoredEMax(const BakeSpec& spec);

// The estimate moved into the physical range (E in [0, e_max]; scale,
// bias >= 0 and scale + bias <= 1), as the tables store it; the errors
// cover the move.
TexelEstimate ClampToRange(const TexelEstimate& v, double e_max = 1.0);

// E_avg at one roughness, as the E_avg table bakes it (texel `index` picks
// the random streams of the sampling integrators), and its error estimate.
struct EavgEstimate {
  double value = 0, error = 0;
};
EavgEstimate IntegrateEavg(const BakeSpec& spec, double roughness, uint64_t index = 0);
// 2 int_0^1 dfg.bias(mu) mu dmu at one roughness by the same rule (the
// quadrature): with E_avg, the hemispherical average of f F for Schlick's
// F is F0 E_avg + (1 - F0) bias_avg.
EavgEstimate IntegrateBiasAvg(const BakeSpec& spec, double roughness);

// ggx-aniso: E at (roughness, anisotropy, mu, phi_o) and E_avg at
// (roughness, anisotropy), as the tables bake them (the quadrature).
TexelEstimate IntegrateAnisoTexel(const BakeSpec& spec, double roughness, double anisotropy,
                                  double mu, double phi_o);
EavgEstimate IntegrateAnisoEavg(const BakeSpec& spec, double roughness, double anisotropy);

}  // namespace brdfbake

#endif  // BRDFBAKE_BAKE_H_
