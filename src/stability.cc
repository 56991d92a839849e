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
#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/ellipsoid.h"
#include "brdfbake/ggx.h"
#include "brdfbake/std_ndf.h"

namespace brdfbake {
namespace {

struct Params {
  double ax, ay, gamma, tx, ty, tz;
};

struct Region {
  const char* name;
  std::vector<const char*> models;
  // Draws parameters and two directions (mu of the first is the swept one).
  std::function<void(std::mt19937_64&, Params*, double* mu)> draw;
};

double U(std::mt19937_64& r) { return std::uniform_real_distribution<double>(0, 1)(r); }
double LogU(std::mt19937_64& r, double lo, double hi) { return lo * std::pow(hi / lo, U(r)); }

std::vector<Region> Regions() {
  const double deg = 3.141592653589793 / 180;
  return {
      {"typical", {"ggx", "beckmann", "std", "ellipsoid"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 0.05, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = 0.05 + 0.95 * U(r);
       }},
      {"tiny alpha", {"ggx", "beckmann", "std", "ellipsoid"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-4, 1e-3);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"grazing mu", {"ggx", "beckmann", "std", "ellipsoid"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = 1.6 + 10 * U(r);
         *mu = LogU(r, 1e-6, 1e-2);
       }},
      {"heavy tails", {"std"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = 1.5 + LogU(r, 1e-3, 0.1);
         *mu = U(r);
       }},
      {"light tails", {"std"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = p->ay = LogU(r, 1e-3, 1);
         p->gamma = LogU(r, 1e2, 1e6);
         *mu = U(r);
       }},
      {"anisotropy 1000:1", {"ggx", "beckmann", "std", "ellipsoid"},
       [](std::mt19937_64& r, Params* p, double* mu) {
         p->ax = LogU(r, 0.1, 1);
         p->ay = p->ax / LogU(r, 100, 1000);
         p->gamma = 1.6 + 10 * U(r);
         *mu = U(r);
       }},
      {"rotations to 80 deg", {"ellipsoid"},
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

template <class T>
struct Ndfs {
  static GgxNdf<T> Ggx(const Params& p) { return GgxNdf<T>(T(p.ax), T(p.ay)); }
};

double RelErr(double f, double d) { return std::abs(f - d) / std::max(std::abs(d), 1e-30); }

// Float-vs-double statistics of one quantity of one model type.
template <class NdfD, class NdfF>
void Measure(const NdfD& nd, const NdfF& nf, const Vec3<double>& a, const Vec3<double>& b,
             StabilityRow* rows) {
  const Vec3<float> af(a), bf(b);
  // Compare against the double reference at the float-rounded inputs.
  const Vec3<double> ad(af), bd(bf);
  const double vals_f[4] = {nf.D(af), nf.Lambda(af), nf.G1(af),
                            Brdf(nf, Fresnel::One(), af, bf, Masking::kHeightCorrelated)};
  const double vals_d[4] = {nd.D(ad), nd.Lambda(ad), nd.G1(ad),
                            Brdf(nd, Fresnel::One(), ad, bd, Masking::kHeightCorrelated)};
  for (int q = 0; q < 4; ++q) {
    ++rows[q].samples;
    if (!std::isfinite(vals_f[q]) && !(q == 1 && std::isinf(vals_d[q]))) {
      ++rows[q].non_finite;
      continue;
    }
    const double err = q == 1 ? std::abs(vals_f[q] - vals_d[q]) / (1 + vals_d[q])
                              : RelErr(vals_f[q], vals_d[q]);
    rows[q].max_rel_error = std::max(rows[q].max_rel_error, err);
  }
}

}  // namespace

std::vector<StabilityRow> RunStability(int samples_per_region, uint64_t seed) {
  std::vector<StabilityRow> out;
  static const char* kQuantities[4] = {"D", "Lambda", "G1", "brdf"};
  const std::string simd_kernel = "simd:" + BatchTarget();
  for (const Region& region : Regions()) {
    for (const char* model : region.models) {
      std::mt19937_64 rng(seed ^ std::hash<std::string>()(std::string(region.name) + model));
      StabilityRow rows[4];
      for (int q = 0; q < 4; ++q) {
        rows[q].region = region.name;
        rows[q].model = model;
        rows[q].quantity = kQuantities[q];
        rows[q].kernel = "float";
      }
      // SIMD rows (GGX D, Lambda, brdf), batched per region.
      std::vector<float> ix, iy, iz, ox, oy, oz;
      std::vector<Params> ps;
      for (int i = 0; i < samples_per_region; ++i) {
        Params p{0.25, 0.25, 2.0, 0, 0, 0};
        double mu;
        region.draw(rng, &p, &mu);
        const Vec3<double> a = FromMuPhi(mu, 2 * 3.141592653589793 * U(rng));
        const Vec3<double> b = FromMuPhi(U(rng), 2 * 3.141592653589793 * U(rng));
        const std::string m = model;
        if (m == "ggx") {
          Measure(GgxNdf<double>(p.ax, p.ay), GgxNdf<float>(float(p.ax), float(p.ay)), a, b, rows);
          ps.push_back(p);
          ix.push_back(float(a.x)); iy.push_back(float(a.y)); iz.push_back(float(a.z));
          ox.push_back(float(b.x)); oy.push_back(float(b.y)); oz.push_back(float(b.z));
        } else if (m == "beckmann") {
          Measure(BeckmannNdf<double>(p.ax, p.ay), BeckmannNdf<float>(float(p.ax), float(p.ay)), a,
                  b, rows);
        } else if (m == "std") {
          Measure(StdNdf<double>(p.ax, p.ay, p.gamma),
                  StdNdf<float>(float(p.ax), float(p.ay), float(p.gamma)), a, b, rows);
        } else {
          Measure(EllipsoidNdf<double>(p.ax, p.ay, p.tx, p.ty, p.tz),
                  EllipsoidNdf<float>(float(p.ax), float(p.ay), float(p.tx), float(p.ty),
                                      float(p.tz)),
                  a, b, rows);
        }
      }
      for (const StabilityRow& r : rows) out.push_back(r);
      if (!ps.empty()) {
        StabilityRow srows[3];
        const char* names[3] = {"D", "Lambda", "brdf"};
        for (int q = 0; q < 3; ++q) {
          srows[q].region = region.name;
          srows[q].model = model;
          srows[q].quantity = names[q];
          srows[q].kernel = simd_kernel;
        }
        float val[3];
        for (size_t i = 0; i < ps.size(); ++i) {
          GgxBatchParams bp;
          bp.alpha_x = float(ps[i].ax);
          bp.alpha_y = float(ps[i].ay);
          GgxDBatch(bp, &ix[i], &iy[i], &iz[i], &val[0], 1);
          GgxLambdaBatch(bp, &ix[i], &iy[i], &iz[i], &val[1], 1);
          GgxBrdfBatch(bp, &ix[i], &iy[i], &iz[i], &ox[i], &oy[i], &oz[i], &val[2], 1);
          const GgxNdf<double> nd(bp.alpha_x, bp.alpha_y);
          const Vec3<double> a(ix[i], iy[i], iz[i]), b(ox[i], oy[i], oz[i]);
          const double ref[3] = {nd.D(a), nd.Lambda(a),
                                 Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated)};
          for (int q = 0; q < 3; ++q) {
            ++srows[q].samples;
            if (!std::isfinite(val[q])) {
              ++srows[q].non_finite;
              continue;
            }
            const double err = q == 1 ? std::abs(val[q] - ref[q]) / (1 + ref[q])
                                      : RelErr(val[q], ref[q]);
            srows[q].max_rel_error = std::max(srows[q].max_rel_error, err);
          }
        }
        for (const StabilityRow& r : srows) out.push_back(r);
      }
    }
  }
  return out;
}

void WriteStabilityCsv(const std::vector<StabilityRow>& rows, std::ostream& out) {
  out << "region,model,quantity,kernel,samples,non_finite,max_rel_error\n";
  for (const StabilityRow& r : rows) {
    char err[32];
    std::snprintf(err, sizeof(err), "%.3g", r.max_rel_error);
    out << r.region << "," << r.model << "," << r.quantity << "," << r.kernel << "," << r.samples
        << "," << r.non_finite << "," << err << "\n";
  }
}

}  // namespace brdfbake
