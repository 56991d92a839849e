// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// `brdfbake eval`: one or more quantities of a model along a sweep of one
// direction, as CSV.

#ifndef BRDFBAKE_EVAL_H_
#define BRDFBAKE_EVAL_H_

#include <ostream>
#include <string>
#include <vector>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"

namespace brdfbake {

// Quantities and the direction each one sweeps:
//   D, pdf      the microfacet normal m (pdf: density of the model's sampler
//               for the fixed view wo, per steradian)
//   Lambda, G1  the direction w
//   G2, brdf    the light direction wi, with the view wo fixed
//   K           the direction w (sel)
//   E, dfg      the view wo (E(mu) and dfg.scale, dfg.bias of the tables,
//               through the same integrator as `bake`); columns with the
//               integrator's error estimate
//   E_avg       none (a function of roughness alone)
//   gen_schlick_s, gen_schlick_ior_s
//               the view wo: the generalized Schlick factor s of a GGX
//               lobe (bake's tables of that name) at one `exponent`, or at
//               the dielectric shape of one ior (model.ior in [1, 100])
//   f82_bias    the view wo: the F82-tint term of a GGX lobe (the table of
//               that name) with the request's masking
// Sweeps: "mu" (cos theta), "theta" (degrees), "roughness" (the table
// quantities only; alpha = r^2, the view at mu_o), or "none" (one row at
// mu_o and the model's roughness sqrt(alpha), table quantities only).
struct EvalRequest {
  ModelParams model;
  std::vector<std::string> quantities = {"D"};
  Masking masking = Masking::kHeightCorrelated;
  Fresnel fresnel;
  double mu_o = 1.0;   // cos(theta) of the fixed view wo
  double phi_o = 0.0;  // azimuth of wo, radians
  double phi = 0.0;    // azimuth of the swept direction, radians
  double anisotropy = 0.0;  // ggx-aniso (E, E_avg): KHR_materials_anisotropy strength
  double exponent = 5.0;    // gen_schlick_s: s_h = (1 - wo.h)^exponent, in [0, inf]
  std::string sweep = "mu";  // mu | theta | roughness | none
  double from = 0.0, to = 1.0;
  int count = 11;
};

const std::vector<std::string>& EvalQuantities();

// Throws std::invalid_argument (one line, naming the bad input) on bad input.
void ValidateEvalRequest(const EvalRequest& req);

// True for E, dfg, E_avg, gen_schlick_s, gen_schlick_ior_s and f82_bias
// (the quantities the tables hold).
bool IsTableQuantity(const std::string& q);

// Writes a header line and `count` rows. Throws on bad input before writing.
void EvalCsv(const EvalRequest& req, std::ostream& out);

}  // namespace brdfbake

#endif  // BRDFBAKE_EVAL_H_
