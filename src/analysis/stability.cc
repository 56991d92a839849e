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
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/targets.h"

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

struct Params {
  double ax, ay, gamma, tx, ty, tz;
};

struct Region {
  const char* name;
  std::vector<ModelKind> models;
  // Draws parameters and two directions (mu of the first is the swept one).
  std::function<void(std::mt19937_64&, Params*, double* mu)> draw;
};

double U(std::mt19937_64& r) { return std::uniform_real_distribution<double>(0, 1)(r); }
double LogU(std::mt19937_64& r, double lo, double hi) { return lo * std::pow(hi / lo, U(r)); }

std::vector<Region> Regions() {
  const double deg = 3.141592653589793 / 180;
  return {
      {"typical", {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT, ModelKind::kEllipsoid},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 0.05, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = 0.05 + 0.95 * U(r);
       }},
      {"tiny alpha", {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT, ModelKind::kEllipsoid},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-4, 1e-3);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"grazing mu", {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT, ModelKind::kEllipsoid},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = LogU(r, 1e-6, 1e-2);
       }},
      {"heavy tails", {ModelKind::kStudentT},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = 1.5 + LogU(r, 1e-3, 0.1);
         *mu = U(r);
       }},
      {"light tails", {ModelKind::kStudentT},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = LogU(r, 1e2, 1e6);
         *mu = U(r);
       }},
      {"anisotropy 1000:1", {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT, ModelKind::kEllipsoid},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = LogU(r, 0.1, 1);
         p->ay = p->ax / LogU(r, 100, 1000);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"rotations to 80 deg", {ModelKind::kEllipsoid},
       [deg](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = LogU(r, 1e-2, 1);
         p->ay = LogU(r, 1e-2, 1);
         p->tx = (2 * U(r) - 1) * 80 * deg;
         p->ty = (2 * U(r) - 1) * 80 * deg;
         p->tz = (2 * U(r) - 1) * 80 * deg;
         *mu = U(r);
       }},
  };
}

// The float-rounded copy of a direction, built from float values that went
// through memory: with GCC 12 at -O2 a Vec3<float> constructed from a
// Vec3<double> was seen to keep its double values (printed (double) of the
// float members had 52-bit mantissas), so the "float" path ran on unrounded
// inputs and the comparison measured the inputs' rounding instead of the
// arithmetic.
Vec3<float> RoundToFloat(const Vec3<double>& v) {
  volatile float c[3] = {static_cast<float>(v.x), static_cast<float>(v.y),
                         static_cast<float>(v.z)};
  return Vec3<float>(c[0], c[1], c[2]);
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

// Squared unit-roughness slope of the normal m under the stretch (ax, ay).
double UnitSlope2(const Vec3<double>& m, double ax, double ay) {
  const double sx = m.x / ax, sy = m.y / ay;
  return (sx * sx + sy * sy) / (m.z * m.z);
}
// a = cot(theta) / alpha of the direction w (the argument of Lambda_std).
double LambdaArg(const Vec3<double>& w, double ax, double ay) {
  const double px = ax * w.x, py = ay * w.y;
  return w.z / std::sqrt(std::max(px * px + py * py, 1e-300));
}
Vec3<double> Half(const Vec3<double>& a, const Vec3<double>& b) {
  Vec3<double> h(0, 0, 1);
  HalfVector(a, b, &h);
  return h;
}

// The SIMD kernel of one model at one sample: D(m), Lambda(a) and the BRDF
// (a, b), each against the double reference at the same float inputs and
// against its documented bound (include/brdfbake/models/kernel_bounds.h).
struct SampleBounds {
  double d = 0, lambda = 0, brdf = 0;
};

SampleBounds MeasureSimd(ModelKind model, const Params& p, const Vec3<double>& m_in,
                         const Vec3<double>& a_in, const Vec3<double>& b_in, StabilityRow* rows) {
  SampleBounds sb;
  const Vec3<float> af = RoundToFloat(a_in), bf = RoundToFloat(b_in), mf = RoundToFloat(m_in);
  const Vec3<double> a(af), b(bf), m(mf);
  const float ax = static_cast<float>(p.ax), ay = static_cast<float>(p.ay);
  BatchModel bp;
  bp.kind = model;
  bp.alpha_x = ax;
  bp.alpha_y = ay;
  bp.gamma = static_cast<float>(p.gamma);
  bp.theta_x = static_cast<float>(p.tx);
  bp.theta_y = static_cast<float>(p.ty);
  bp.theta_z = static_cast<float>(p.tz);
  float d, l, f;
  EvalBatch(bp, Quantity::kD, {&mf.x, &mf.y, &mf.z}, &d, 1);
  EvalBatch(bp, Quantity::kLambda, {&af.x, &af.y, &af.z}, &l, 1);
  EvalBatch(bp, Quantity::kBrdf, {&af.x, &af.y, &af.z}, {&bf.x, &bf.y, &bf.z}, &f, 1);
  if (model == ModelKind::kGgx) {
    const GgxNdf<double> nd(ax, ay);
    sb = {bounds::kGgxRel, bounds::kGgxRel, bounds::kGgxRel};
    Record(&rows[0], d, nd.D(m), false, sb.d);
    Record(&rows[1], l, nd.Lambda(a), true, sb.lambda);
    Record(&rows[2], f, Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated), false,
           sb.brdf);
  }
#if BRDFBAKE_WITH_BECKMANN
  if (model == ModelKind::kBeckmann || model == ModelKind::kStudentT) {
    const bool beck = model == ModelKind::kBeckmann;
    const double gamma = beck ? std::numeric_limits<double>::infinity()
                              : static_cast<double>(static_cast<float>(p.gamma));
    const double slope = beck ? bounds::kBeckmannExpSlope : bounds::kStudentTExpSlope;
    const double brdf_slope = beck ? bounds::kBeckmannBrdfExpSlope : bounds::kStudentTExpSlope;
    const StudentTNdf<double> nd(ax, ay, gamma);  // gamma = inf is Beckmann
    // The exponent E of the exponential factor (see kernel_bounds.h).
    auto exponent = [&](const Vec3<double>& n) {
      const double r2 = UnitSlope2(n, ax, ay);
      return beck ? r2 : gamma * std::log1p(r2 / (gamma - 1));
    };
    const double e_m = exponent(m), e_h = exponent(Half(a, b));
    const double lref = nd.Lambda(a);
    const double l_bound =
        std::isinf(lref) ? 1.0 : bounds::SlopeLambdaAbs(LambdaArg(a, ax, ay), lref) / (1 + lref);
    sb = {bounds::SlopeD(e_m, slope), l_bound, bounds::SlopeBrdf(e_h, brdf_slope)};
    Record(&rows[0], d, nd.D(m), false, sb.d, e_m > bounds::kFlushExponent);
    Record(&rows[1], l, lref, true, sb.lambda);
    Record(&rows[2], f, Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated), false,
           sb.brdf, e_h > bounds::kFlushExponent);
  }
#endif  // BRDFBAKE_WITH_BECKMANN
#if BRDFBAKE_WITH_ELLIPSOID
  if (model == ModelKind::kEllipsoid) {
    const EllipsoidNdf<double> nd(bp.alpha_x, bp.alpha_y, bp.theta_x, bp.theta_y, bp.theta_z);
    const Mat3<double>& m_a = nd.shape_matrix();
    const Mat3<double> m_ait =
        bounds::EllipsoidKernelInvT(ax, ay, bp.theta_x, bp.theta_y, bp.theta_z);
    const double li = nd.Lambda(a), lo = nd.Lambda(b);
    const double l_bound = std::isinf(li) ? 1.0
                                          : bounds::kEllipsoidLambdaRel * bounds::Kappa(m_a, a) *
                                                bounds::EllipsoidLambdaScale(m_a, a, li) / (1 + li);
    sb = {bounds::kEllipsoidDRel * bounds::Kappa(m_ait, m), l_bound,
          bounds::kEllipsoidBrdfRel * bounds::EllipsoidBrdfCondition(m_a, m_ait, a, b, li, lo)};
    Record(&rows[0], d, nd.D(m), false, sb.d);
    Record(&rows[1], l, li, true, sb.lambda);
    Record(&rows[2], f, Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated), false,
           sb.brdf);
  }
#endif  // BRDFBAKE_WITH_ELLIPSOID
  return sb;
}

// Float instantiation of the scalar reference against double, at the same
// float inputs, bounded by kFloatReferenceBound or the SIMD kernel's bound
// at the same sample (the same arithmetic, conditioned by the same inputs),
// whichever is larger.
template <class NdfD, class NdfF>
void MeasureFloat(const NdfD& nd, const NdfF& nf, const Vec3<double>& m, const Vec3<double>& a,
                  const Vec3<double>& b, const SampleBounds& sb, StabilityRow* rows) {
  const Vec3<float> af = RoundToFloat(a), bf = RoundToFloat(b), mf = RoundToFloat(m);
  const Vec3<double> ad(af), bd(bf), md(mf);
  const double vals_f[4] = {nf.D(mf), nf.Lambda(af), nf.G1(af),
                            Brdf(nf, Fresnel::One(), af, bf, Masking::kHeightCorrelated)};
  const double vals_d[4] = {nd.D(md), nd.Lambda(ad), nd.G1(ad),
                            Brdf(nd, Fresnel::One(), ad, bd, Masking::kHeightCorrelated)};
  // G1 = 1 / (1 + Lambda): its relative error is that of 1 + Lambda.
  const double kernel_bound[4] = {sb.d, sb.lambda, sb.lambda, sb.brdf};
  for (int q = 0; q < 4; ++q) {
    Record(&rows[q], vals_f[q], vals_d[q], q == 1,
           std::max(kFloatReferenceBound, kernel_bound[q]));
  }
}

}  // namespace

std::vector<StabilityRow> RunStability(int samples_per_region, uint64_t seed) {
  std::vector<StabilityRow> out;
  static const char* kFloatQuantities[4] = {"D", "Lambda", "G1", "brdf"};
  static const char* kSimdQuantities[3] = {"D", "Lambda", "brdf"};
  const std::string simd_kernel = "simd:" + BatchTarget();
  for (const Region& region : Regions()) {
    for (const ModelKind kind : region.models) {
      if (!ModelBuilt(kind)) continue;
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
        Params p{0.25, 0.25, 2.0, 0, 0, 0};
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
          const double tilt = std::min(1.5, std::min(p.ax, p.ay) * LogU(rng, 0.01, 30));
          m = FromMuPhi(std::cos(tilt), 2 * 3.141592653589793 * U(rng));
          const Vec3<double> r = Reflect(b, m);
          if (r.z > 0) a = r;
        }
        const SampleBounds sb = MeasureSimd(kind, p, m, a, b, srows);
        if (kind == ModelKind::kGgx) {
          MeasureFloat(GgxNdf<double>(p.ax, p.ay), GgxNdf<float>(float(p.ax), float(p.ay)), m, a, b,
                       sb, rows);
        } else if (kind == ModelKind::kBeckmann) {
          MeasureFloat(BeckmannNdf<double>(p.ax, p.ay),
                       BeckmannNdf<float>(float(p.ax), float(p.ay)), m, a, b, sb, rows);
        } else if (kind == ModelKind::kStudentT) {
          MeasureFloat(StudentTNdf<double>(p.ax, p.ay, p.gamma),
                       StudentTNdf<float>(float(p.ax), float(p.ay), float(p.gamma)), m, a, b, sb,
                       rows);
        } else {
          MeasureFloat(EllipsoidNdf<double>(p.ax, p.ay, p.tx, p.ty, p.tz),
                       EllipsoidNdf<float>(float(p.ax), float(p.ay), float(p.tx), float(p.ty),
                                           float(p.tz)),
                       m, a, b, sb, rows);
        }
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
