// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Evaluation over dense grids, in parallel over rows (oneTBB), one SIMD
// dispatch per row: BRDF slices in (theta_h, theta_d), the BRDF over the
// hemisphere of wi for a fixed wo, and G1 over (mu, roughness).

#ifndef BRDFBAKE_GRID_H_
#define BRDFBAKE_GRID_H_

#include <string>
#include <utility>
#include <vector>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"

namespace brdfbake {

// slice:      x = theta_h in [0, 90) deg, y = theta_d in [0, 90) deg, phi_d = 90 deg
//             (Rusinkiewicz half/difference angles, texel centres); value f(wi, wo)
// hemisphere: wi = (u, v, sqrt(1 - u^2 - v^2)) for (u, v) on the pixel centres of
//             [-1, 1]^2 (orthographic view from above; 0 outside the disk),
//             wo fixed by mu_o, phi_o; value f(wi, wo) cos(theta_i)
// g1:         x = mu in (0, 1], y = roughness in (0, 1] (texel centres, alpha = r^2);
//             value G1 (isotropic)
enum class GridKind { kSlice, kHemisphere, kG1 };

GridKind ParseGridKind(const std::string& s);  // throws std::invalid_argument
const char* GridKindName(GridKind k);

struct GridRequest {
  ModelParams model;
  Fresnel fresnel;
  Masking masking = Masking::kHeightCorrelated;
  GridKind kind = GridKind::kSlice;
  int width = 256, height = 256;
  double mu_o = 0.7, phi_o = 0.0;  // hemisphere
  int threads = 0;                 // 0 = all cores
};

struct Grid {
  int width = 0, height = 0;
  std::vector<float> values;  // row-major, row 0 first
  std::string path;           // "simd:<target>" or "scalar" (which code evaluated it)
};

void ValidateGridRequest(const GridRequest& req);
Grid EvalGrid(const GridRequest& req);

// The grid's header attributes (brdfbake.axes in the tables' form,
// brdfbake.model with what the grid sweeps, brdfbake.layout, ...), for
// WriteImageExr.
std::vector<std::pair<std::string, std::string>> GridAttributes(const GridRequest& req,
                                                                const Grid& grid);
// The grid's one channel: f, f_cos or G1.
const char* GridChannelName(GridKind k);

}  // namespace brdfbake

#endif  // BRDFBAKE_GRID_H_
