// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>

#include "brdfbake/batch.h"
#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/targets.h"
#include "kernels/model_row.h"
#include "kernels/stability_probe.h"

namespace brdfbake {
namespace {

// Values below this are compared absolutely (physically negligible, and
// below the range where float keeps its relative precision through
// products of small factors).
constexpr double kValueFloor = 1e-30;

// The stated bound of the float instantiation of the scalar reference: its
// largest error comes from exponentials of large arguments (Beckmann
// exp(-r2), the STD's exp(-gamma log1p(.))), which multiply the few-ulp
// rounding of the argument by the argument itself (up to ~100 before float
// underflows): 100 x 3 x 2^-24 = 2e-5; the ellipsoid's rotated products
// cancel by up to ~1/alpha in the same way. Measured maximum 5.6e-5.
constexpr double kFloatReferenceBound = 1e-4;

// The models a region draws for: every model with a stability probe
// (model_row.h), or those of them that take gamma or a rotation.
enum class RegionModels { kAll, kGamma, kRotation };

struct Region {
  const char* name;
  RegionModels models;
  // Draws parameters and two directions (mu of the first is the swept one).
  std::function<void(std::mt19937_64&, ModelParams*, double* mu)> draw;
};

// Whether the region draws for the row's model.
bool RegionDraws(const Region& region, const ModelRow& row) {
  if (!row.stability) return false;
  switch (region.models) {
    case RegionModels::kAll:
      return true;
    case RegionModels::kGamma:
      return (row.options & Bit(ModelOption::kGamma)) != 0;
    case RegionModels::kRotation:
      return (row.options & Bit(ModelOption::kRotation)) != 0;
  }
  return false;
}

double U(std::mt19937_64& r) { return std::uniform_real_distribution<double>(0, 1)(r); }
double LogU(std::mt19937_64& r, double lo, double hi) { return lo * std::pow(hi / lo, U(r)); }

std::vector<Region> Regions() {
  const double deg = 3.141592653589793 / 180;
  return {
      {"typical", RegionModels::kAll,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = p->alpha_y = LogU(r, 0.05, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = 0.05 + 0.95 * U(r);
       }},
      {"tiny alpha", RegionModels::kAll,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = p->alpha_y = LogU(r, 1e-4, 1e-3);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"grazing mu", RegionModels::kAll,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = p->alpha_y = LogU(r, 1e-3, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = LogU(r, 1e-6, 1e-2);
       }},
      {"heavy tails", RegionModels::kGamma,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = p->alpha_y = LogU(r, 1e-3, 1);
         p->gamma = 1.5 + LogU(r, 1e-3, 0.1);
         *mu = U(r);
       }},
      {"light tails", RegionModels::kGamma,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = p->alpha_y = LogU(r, 1e-3, 1);
         p->gamma = LogU(r, 1e2, 1e6);
         *mu = U(r);
       }},
      {"anisotropy 1000:1", RegionModels::kAll,
       [](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = LogU(r, 0.1, 1);
         p->alpha_y = p->alpha_x / LogU(r, 100, 1000);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"rotations to 80 deg", RegionModels::kRotation,
       [deg](std::mt19937_64& r, ModelParams* p, double* mu) {
         p->alpha_x = LogU(r, 1e-2, 1);
         p->alpha_y = LogU(r, 1e-2, 1);
         p->theta_x = (2 * U(r) - 1) * 80 * deg;
         p->theta_y = (2 * U(r) - 1) * 80 * deg;
         p->theta_z = (2 * U(r) - 1) * 80 * deg;
         *mu = U(r);
       }},
  };
}

double RelErr(double f, double d) { return std::abs(f - d) / std::max(std::abs(d), kValueFloor); }

// One row's running statistics: the worst relative error and the worst ratio
// of the error to the sample's own bound.
void Record(StabilityRow* row, double value, double ref, bool lambda, double bound,
            bool may_flush = false) {
  ++row->samples;
  if (!std::isfinite(value) && !(lambda && std::isinf(ref))) {
    ++row->non_finite;
    return;
  }
  // Lambda: the relative error of 1 + Lambda (what G1 and G2 use).
  double err = lambda ? (std::isinf(ref) ? 0.0 : std::abs(value - ref) / (1 + ref))
                      : RelErr(value, ref);
  // Exponent above 87: the float exponential is subnormal (flushed to 0 by
  // the batch calls, or with few bits left); only finiteness is checked.
  if (may_flush) err = 0;
  row->max_rel_error = std::max(row->max_rel_error, err);
  row->max_error_over_bound = std::max(row->max_error_over_bound, err / bound);
}

// The SIMD kernel of one model at one sample: D(m), Lambda(a) and the BRDF
// (a, b) at the float-rounded inputs, each against the row's double
// reference and its bound at the same inputs (the probe's); then the float
// instantiation of the scalar reference against double, bounded by
// kFloatReferenceBound or the SIMD kernel's bound at the same sample (the
// same arithmetic, conditioned by the same inputs), whichever is larger.
void Measure(const ModelRow& row, const ModelParams& p, const Vec3<double>& m_in, const Vec3<double>& a_in,
             const Vec3<double>& b_in, StabilityRow* rows, StabilityRow* srows) {
  const Vec3<float> af = RoundToFloat(a_in), bf = RoundToFloat(b_in), mf = RoundToFloat(m_in);
  const BatchModel bp = BatchModelOf(p);  // F = 1, height-correlated
  float d, l, f;
  EvalBatch(bp, Quantity::kD, {&mf.x, &mf.y, &mf.z}, &d, 1);
  EvalBatch(bp, Quantity::kLambda, {&af.x, &af.y, &af.z}, &l, 1);
  EvalBatch(bp, Quantity::kBrdf, {&af.x, &af.y, &af.z}, {&bf.x, &bf.y, &bf.z}, &f, 1);
  StabilitySample s;
  row.stability(p, m_in, a_in, b_in, &s);
  const double simd[3] = {d, l, f};
  const int simd_q[3] = {kStabilityD, kStabilityLambda, kStabilityBrdf};
  for (int k = 0; k < 3; ++k) {
    const int q = simd_q[k];
    Record(&srows[k], simd[k], s.ref[q], q == kStabilityLambda, s.bound[q], s.flush[q]);
  }
  // G1 = 1 / (1 + Lambda): its relative error is that of 1 + Lambda.
  for (int q = 0; q < 4; ++q) {
    const double kernel_bound = s.bound[q == kStabilityG1 ? kStabilityLambda : q];
    Record(&rows[q], s.float_value[q], s.double_value[q], q == kStabilityLambda,
           std::max(kFloatReferenceBound, kernel_bound));
  }
}

}  // namespace

std::vector<StabilityRow> RunStability(int samples_per_region, uint64_t seed) {
  std::vector<StabilityRow> out;
  static const char* kFloatQuantities[4] = {"D", "Lambda", "G1", "brdf"};
  static const char* kSimdQuantities[3] = {"D", "Lambda", "brdf"};
  const std::string simd_kernel = "simd:" + BatchTarget();
  for (const Region& region : Regions()) {
    for (const ModelKind kind : ModelKindsBuilt()) {
      const ModelRow& row = *RowOfModel(kind);
      if (!RegionDraws(region, row)) continue;
      const char* model = ModelName(kind);
      std::mt19937_64 rng(seed ^ std::hash<std::string>()(std::string(region.name) + model));
      StabilityRow rows[4], srows[3];
      for (int q = 0; q < 4; ++q) {
        rows[q].region = region.name;
        rows[q].model = model;
        rows[q].quantity = kFloatQuantities[q];
        rows[q].kernel = "float";
      }
      for (int q = 0; q < 3; ++q) {
        srows[q].region = region.name;
        srows[q].model = model;
        srows[q].quantity = kSimdQuantities[q];
        srows[q].kernel = simd_kernel;
      }
      for (int i = 0; i < samples_per_region; ++i) {
        ModelParams p;  // alpha 0.25, gamma 2, no rotation, until drawn
        p.kind = kind;
        double mu;
        region.draw(rng, &p, &mu);
        const double phi_a = 2 * 3.141592653589793 * U(rng);
        const double mu_b = U(rng);
        const double phi_b = 2 * 3.141592653589793 * U(rng);
        Vec3<double> a = FromMuPhi(mu, phi_a);
        const Vec3<double> b = FromMuPhi(mu_b, phi_b);
        // Every other sample in the lobe: a normal m tilted by 0.01 to 30
        // alpha (where D and the BRDF are large, and most sensitive to the
        // rounding of their inputs), and a = reflect(b, m), so that m is
        // the half vector of the BRDF pair; otherwise m = a.
        Vec3<double> m = a;
        if (i % 2 == 1) {
          const double tilt = std::min(1.5, std::min(p.alpha_x, p.alpha_y) * LogU(rng, 0.01, 30));
          m = FromMuPhi(std::cos(tilt), 2 * 3.141592653589793 * U(rng));
          const Vec3<double> r = Reflect(b, m);
          if (r.z > 0) a = r;
        }
        Measure(row, p, m, a, b, rows, srows);
      }
      for (const StabilityRow& r : rows) out.push_back(r);
      for (const StabilityRow& r : srows) out.push_back(r);
    }
  }
  return out;
}

void WriteStabilityCsv(const std::vector<StabilityRow>& rows, std::ostream& out) {
  out << "region,model,quantity,kernel,samples,non_finite,max_rel_error,max_error_over_bound,"
         "within_bound\n";
  for (const StabilityRow& r : rows) {
    char err[32], ratio[32];
    std::snprintf(err, sizeof(err), "%.3g", r.max_rel_error);
    std::snprintf(ratio, sizeof(ratio), "%.3g", r.max_error_over_bound);
    out << r.region << "," << r.model << "," << r.quantity << "," << r.kernel << "," << r.samples
        << "," << r.non_finite << "," << err << "," << ratio << "," << (r.Within() ? "yes" : "NO")
        << "\n";
  }
}

}  // namespace brdfbake
