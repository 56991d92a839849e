// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/bake.h"

#include <atomic>
#include <chrono>
#include <limits>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "brdfbake/version.h"
#include "azimuthal.h"
#include "integrate.h"

namespace brdfbake {
namespace {

[[noreturn]] void Bad(const std::string& what) { throw std::invalid_argument(what); }

}  // namespace

const char* TableName(TableKind t) {
  switch (t) {
    case TableKind::kE: return "E";
    case TableKind::kEavg: return "E_avg";
    case TableKind::kDfg: return "dfg";
  }
  return "E";
}
const char* WarpName(Warp w) {
  switch (w) {
    case Warp::kLinear: return "linear";
    case Warp::kSquare: return "square";
    case Warp::kSqrt: return "sqrt";
  }
  return "linear";
}
const char* PlacementName(Placement p) {
  return p == Placement::kCenters ? "centers" : "edges";
}
const char* IntegratorName(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::kQuadrature: return "quadrature";
    case IntegratorKind::kQmc: return "qmc";
    case IntegratorKind::kMc: return "mc";
    case IntegratorKind::kEngine: return "engine";
  }
  return "quadrature";
}

TableKind ParseTable(const std::string& s) {
  if (s == "E") return TableKind::kE;
  if (s == "E_avg") return TableKind::kEavg;
  if (s == "dfg") return TableKind::kDfg;
  Bad("--table: unknown table '" + s + "' (expected E, E_avg or dfg)");
}
Warp ParseWarp(const std::string& s) {
  if (s == "linear") return Warp::kLinear;
  if (s == "square") return Warp::kSquare;
  if (s == "sqrt") return Warp::kSqrt;
  Bad("--warp: unknown warp '" + s + "' (expected linear, square or sqrt)");
}
Placement ParsePlacement(const std::string& s) {
  if (s == "centers") return Placement::kCenters;
  if (s == "edges") return Placement::kEdges;
  Bad("--placement: unknown placement '" + s + "' (expected centers or edges)");
}
IntegratorKind ParseIntegrator(const std::string& s) {
  if (s == "quadrature") return IntegratorKind::kQuadrature;
  if (s == "qmc") return IntegratorKind::kQmc;
  if (s == "mc") return IntegratorKind::kMc;
  if (s == "engine") return IntegratorKind::kEngine;
  Bad("--integrator: unknown integrator '" + s + "' (expected quadrature, qmc, mc or engine)");
}

double Axis::ValueAt(double fi) const {
  double t;
  if (placement == Placement::kCenters) {
    t = (fi + 0.5) / size;
  } else {
    t = size == 1 ? 0.0 : fi / (size - 1);
  }
  double w = t;
  if (warp == Warp::kSquare) w = t * t;
  if (warp == Warp::kSqrt) w = std::sqrt(t);
  return min + (max - min) * w;
}

std::string Axis::ToJson() const {
  nlohmann::json j;
  j["name"] = name;
  j["size"] = size;
  j["min"] = min;
  j["max"] = max;
  j["warp"] = WarpName(warp);
  j["placement"] = PlacementName(placement);
  return j.dump();
}

int BakeSpec::EffectiveSamples() const {
  if (samples > 0) return samples;
  switch (integrator) {
    case IntegratorKind::kQuadrature: return 512;
    case IntegratorKind::kQmc: return 4096;
    case IntegratorKind::kMc: return 4096;
    case IntegratorKind::kEngine: return 1024;
  }
  return 32;
}

void ValidateBakeSpec(const BakeSpec& spec) {
  ValidateModelParams(spec.model);
  const std::string& m = spec.model.name;
  if (m != "ggx" && m != "beckmann" && m != "std") {
    Bad("--model: tables are baked for ggx, beckmann and std (got '" + m + "')");
  }
  for (const Axis* a : {&spec.mu, &spec.roughness}) {
    if (a->size < 1 || a->size > 8192) Bad("--size: each axis must have 1 to 8192 entries");
    if (a->placement == Placement::kEdges && a->size < 2) {
      Bad("--size: edges placement needs at least 2 entries per axis");
    }
  }
  if (spec.samples < 0 || spec.samples > 1 << 24) Bad("--samples must be in [1, 16777216]");
  if (spec.integrator == IntegratorKind::kQuadrature && spec.samples > 4096) {
    Bad("--samples: the quadrature takes at most 4096 nodes per dimension");
  }
  if (spec.integrator == IntegratorKind::kQmc && spec.samples != 0 && spec.samples < 16) {
    Bad("--samples: qmc needs at least 16 samples (8 replicas of 2)");
  }
  if (spec.complement && spec.table != TableKind::kE) Bad("--complement applies to the E table only");
  if (spec.threads < 0) Bad("--threads must be >= 0");
  if (!(spec.tolerance >= 0) || !std::isfinite(spec.tolerance)) Bad("--tolerance must be a finite number >= 0");
}

namespace {

// The deterministic quadrature. Tables that need E only (E, E_avg) of the
// isotropic GGX use the one-dimensional rule with the azimuth integrated in
// closed form (azimuthal.h); dfg and the other models the two-dimensional
// rule over the visible-normal disk. Only E is filled in the first case.
template <class Ndf>
TexelValue QuadratureFor(const Ndf& ndf, double mu, const BakeSpec& spec, int max_nodes,
                         double tol) {
  if constexpr (std::is_same_v<Ndf, GgxNdf<double>>) {
    if (spec.table != TableKind::kDfg && ndf.alpha_x() == ndf.alpha_y()) {
      const AzimuthalResult r =
          GgxAzimuthalAlbedo(ndf.alpha_x(), std::max(mu, kMuMin), spec.masking, tol, max_nodes);
      TexelValue v;
      v.e = r.value;
      v.err_e = r.error;
      return v;
    }
  }
  return QuadratureTexel(ndf, mu, spec.masking, max_nodes, tol);
}

template <class Ndf>
TexelValue TexelFor(const Ndf& ndf, double mu, const BakeSpec& spec, uint64_t texel_seed) {
  const int n = spec.EffectiveSamples();
  switch (spec.integrator) {
    case IntegratorKind::kQuadrature:
      return QuadratureFor(ndf, mu, spec, n, spec.tolerance);
    case IntegratorKind::kQmc:
      return QmcTexel(ndf, mu, spec.masking, n, texel_seed, false);
    case IntegratorKind::kMc:
      return QmcTexel(ndf, mu, spec.masking, n, texel_seed, true);
    case IntegratorKind::kEngine: {
      const QuadratureResult r = EngineRule(ndf, mu, spec.masking, n);
      if (!spec.estimate_error) {
        TexelValue v;
        v.e = r.e;
        v.bias = r.fc;
        v.scale = r.e - r.fc;
        v.err_e = v.err_bias = v.err_scale = std::numeric_limits<double>::infinity();
        return v;
      }
      const TexelValue ref = QuadratureFor(ndf, mu, spec, 512, 1e-10);
      TexelValue v;
      v.e = r.e;
      v.bias = r.fc;
      v.scale = r.e - r.fc;
      // Measured against the converged quadrature (plus its own error).
      v.err_e = std::abs(v.e - ref.e) + ref.err_e;
      v.err_bias = std::abs(v.bias - ref.bias) + ref.err_bias;
      v.err_scale = std::abs(v.scale - ref.scale) + ref.err_scale;
      return v;
    }
  }
  return {};
}

TexelValue Texel(const BakeSpec& spec, double alpha, double mu, uint64_t texel_seed) {
  if (alpha < kMinAlpha<double>) return MirrorTexel(mu);
  const std::string& m = spec.model.name;
  if (m == "ggx") return TexelFor(GgxNdf<double>(alpha), mu, spec, texel_seed);
  if (m == "beckmann") return TexelFor(BeckmannNdf<double>(alpha), mu, spec, texel_seed);
  return TexelFor(StdNdf<double>(alpha, alpha, spec.model.gamma), mu, spec, texel_seed);
}

std::string ModelJson(const BakeSpec& spec) {
  nlohmann::json j;
  j["name"] = spec.model.name;
  j["alpha"] = "roughness^2";
  if (spec.model.name == "std") {
    if (std::isinf(spec.model.gamma)) j["gamma"] = "inf"; else j["gamma"] = spec.model.gamma;
  }
  return j.dump();
}

std::string IntegratorJson(const BakeSpec& spec) {
  nlohmann::json j;
  const int n = spec.EffectiveSamples();
  j["method"] = IntegratorName(spec.integrator);
  switch (spec.integrator) {
    case IntegratorKind::kQuadrature:
      j["tolerance"] = spec.tolerance;
      if (spec.model.name == "ggx" && spec.table != TableKind::kDfg) {
        j["max_pieces"] = n;
        j["domain"] = "theta_i in [0, pi/2], the azimuth of wi integrated in closed form "
                      "(isotropic GGX); mesh graded geometrically (ratio 3) from the specular "
                      "peak (scale 2 alpha) and the horizon";
        j["rule"] = "Gauss-Kronrod 15 per piece, pieces bisected worst first until the "
                    "summed error estimate meets the tolerance";
        j["error_estimate"] = "sum over the pieces of |K15 - G7|";
        break;
      }
      j["max_nodes_per_dimension"] = n;
      j["domain"] = "unit square of the GGX visible-normal sampler with the model's alpha "
                    "(weight D G2 (wo.m) / (wo.z pdf_ggx(m)) for beckmann and std), split where "
                    "wi crosses the horizon; std with gamma < 2: inner mesh graded towards the "
                    "disk rim, azimuth mapped by Sidi's sin^4 transformation";
      j["rule"] = "Gauss-Legendre (trapezoidal in a periodic azimuth), node ladder 12, 24, 48, ... (doubling) up to the max until two successive rules agree to the tolerance";
      j["error_estimate"] = "difference between the last two rules of the ladder (plus the "
                            "difference before it when the node cap stops the ladder short of "
                            "the tolerance)";
      break;
    case IntegratorKind::kQmc:
      j["samples"] = 8 * std::max(1, n / 8);
      j["sequence"] = "Hammersley, 8 Cranley-Patterson rotations";
      j["sampling"] = "visible normals";
      j["error_estimate"] = "4 x standard error over the 8 replicas";
      j["seed"] = spec.seed;
      break;
    case IntegratorKind::kMc:
      j["samples"] = 8 * std::max(1, n / 8);
      j["sampling"] = "visible normals, pseudo-random (SplitMix64 per texel)";
      j["error_estimate"] = "4 x standard error over 8 batches";
      j["seed"] = spec.seed;
      break;
    case IntegratorKind::kEngine:
      j["samples"] = n;
      j["sequence"] = "Hammersley (unrandomized)";
      j["sampling"] = "NDF importance sampling of the half vector";
      j["error_estimate"] = "difference from the converged quadrature (tolerance 1e-10) plus its error";
      break;
  }
  if (spec.table == TableKind::kEavg) {
    j["E_avg"] = "2 int_0^1 E(mu) mu dmu, 32-node Gauss-Legendre in sqrt(mu), "
                 "E at each node from the integrator above; error: difference from "
                 "the 16-node rule plus the propagated E error";
  }
  j["grazing"] = "mu = 0 evaluated at mu = 1e-7";
  j["mirror"] = "alpha < 1e-4 is a mirror: E = 1";
  return j.dump();
}

}  // namespace

Table Bake(const BakeSpec& spec, const ProgressFn& progress) {
  ValidateBakeSpec(spec);
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<tbb::global_control> limit;
  if (spec.threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  spec.threads);
  }
  Table t;
  t.spec = spec;
  t.integrator_json = IntegratorJson(spec);
  const Axis& ax_mu = spec.mu;
  const Axis& ax_r = spec.roughness;
  std::atomic<int64_t> done{0};

  if (spec.table == TableKind::kEavg) {
    t.axes = {ax_r};
    t.width = ax_r.size;
    t.height = 1;
    std::vector<double> value(t.width), error(t.width);
    const GaussLegendre fine(32), coarse(16);
    const int64_t total = t.width;
    tbb::parallel_for(0, t.width, [&](int i) {
      const double r = ax_r.Value(i);
      const double alpha = r * r;
      // E_avg = 2 int E(mu) mu dmu = 4 int_0^1 E(s^2) s^3 ds.
      auto rule = [&](const GaussLegendre& gl, uint64_t salt, double* err) {
        double acc = 0, acc_err = 0;
        for (size_t k = 0; k < gl.x.size(); ++k) {
          const double s = gl.x[k];
          const TexelValue v = Texel(spec, alpha, s * s,
                                     Mix64(spec.seed ^ Mix64((uint64_t(i) << 20) + k + salt)));
          const double wk = 4 * gl.w[k] * s * s * s;
          acc += wk * v.e;
          acc_err += wk * v.err_e;
        }
        *err = acc_err;
        return acc;
      };
      double err_f, err_c;
      const double f = rule(fine, 0, &err_f);
      const double c = rule(coarse, 1 << 10, &err_c);
      value[i] = f;
      error[i] = std::abs(f - c) + err_f;
      if (progress) progress(++done, total);
    });
    t.channels.push_back({"E_avg", "E_avg", value});
    t.max_abs_error = 0;
    for (double e : error) t.max_abs_error = std::max(t.max_abs_error, e);
    if (spec.error_channel) t.channels.push_back({"error", "error", error});
  } else {
    t.axes = {ax_mu, ax_r};
    t.width = ax_mu.size;
    t.height = ax_r.size;
    const int64_t total = int64_t(t.width) * t.height;
    std::vector<TexelValue> texels(total);
    tbb::parallel_for(int64_t(0), total, [&](int64_t idx) {
      const int x = static_cast<int>(idx % t.width), y = static_cast<int>(idx / t.width);
      const double r = ax_r.Value(y);
      texels[idx] = Texel(spec, r * r, ax_mu.Value(x), Mix64(spec.seed ^ Mix64(uint64_t(idx))));
      if (progress) progress(++done, total);
    });
    std::vector<double> error(total);
    if (spec.table == TableKind::kE) {
      std::vector<double> v(total);
      for (int64_t i = 0; i < total; ++i) {
        v[i] = spec.complement ? 1.0 - texels[i].e : texels[i].e;
        error[i] = texels[i].err_e;
      }
      t.channels.push_back({spec.complement ? "1-E" : "E", spec.complement ? "1-E" : "E", v});
    } else {
      std::vector<double> s(total), b(total);
      for (int64_t i = 0; i < total; ++i) {
        s[i] = texels[i].scale;
        b[i] = texels[i].bias;
        error[i] = std::max(texels[i].err_scale, texels[i].err_bias);
      }
      t.channels.push_back({"dfg.scale", "dfg.scale", s});
      t.channels.push_back({"dfg.bias", "dfg.bias", b});
    }
    for (double e : error) t.max_abs_error = std::max(t.max_abs_error, e);
    if (spec.error_channel) t.channels.push_back({"error", "error", error});
  }
  t.integration_error = t.max_abs_error;
  // Storing the values adds the rounding error of the pixel type.
  double max_value = 0;
  for (const Channel& c : t.channels) {
    if (c.meaning == "error") continue;
    for (double v : c.values) max_value = std::max(max_value, std::abs(v));
  }
  t.max_abs_error += max_value * (spec.half ? 0x1p-11 : 0x1p-24);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

TexelEstimate IntegrateTexel(const BakeSpec& spec, double roughness, double mu,
                             uint64_t texel_seed) {
  ValidateBakeSpec(spec);
  const TexelValue v = Texel(spec, roughness * roughness, mu, Mix64(spec.seed ^ texel_seed));
  return {v.e, v.scale, v.bias, v.err_e, v.err_scale, v.err_bias};
}

// Shared helpers for the EXR writer (exr.cc).
std::string BakeModelJson(const BakeSpec& spec) { return ModelJson(spec); }

}  // namespace brdfbake
