// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The bake loop over a table's texels (oneTBB; each texel depends on its
// own inputs only), its metadata, and the texel dispatch over the table
// kinds; each model's rules come from its family's row (family_row.h).

#include "brdfbake/bake.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>

#include <Imath/half.h>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "bake/family_row.h"
#include "bake/warp_coordinates.h"
#include "base/error.h"
#include "base/pixel.h"
#include "base/text.h"
#include "brdfbake/version.h"
#include "quadrature/adaptive_rule.h"
#include "quadrature/gauss_legendre.h"
#include "rules/glass/gen_schlick.h"
#include "sampling/sampling_integrators.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

// The families of this build (kernels/model_families.inc, written by CMake
// from BRDFBAKE_MODELS), each defined in its src/bake/families/<family>_tables.cc.
#define BRDFBAKE_FAMILY(f) extern const BakerFamily kBakerFamily_##f;
#include "kernels/model_families.inc"
#undef BRDFBAKE_FAMILY

namespace {

constexpr const BakerFamily* kBakerFamilies[] = {
#define BRDFBAKE_FAMILY(f) &kBakerFamily_##f,
#include "kernels/model_families.inc"
#undef BRDFBAKE_FAMILY
};

}  // namespace

const BakerRow* BakerRowOf(ModelKind kind) {
  for (const BakerFamily* family : kBakerFamilies) {
    for (int k = 0; k < family->count; ++k) {
      if (family->rows[k].kind == kind) return &family->rows[k];
    }
  }
  return nullptr;
}

namespace {

// gen_schlick_s / gen_schlick_ior_s: the factor s at one texel by the
// visible-normal rule of rules/glass/gen_schlick.h; below alpha 1e-4 the
// mirror, whose one half vector is the normal: s = s_h(mu).
TexelEstimate GenSchlickTexel(const BakeSpec& spec, double alpha, double mu, const GenSchlickShape& shape) {
  TexelEstimate v;
  const double m = std::max(mu, kMuMin);
  if (alpha < kMinAlpha<double>) {
    v.e = GenSchlickWeight(shape, m);
    return v;
  }
  const RuleResult r = GenSchlickFactor(alpha, shape, m, spec.tolerance, spec.EffectiveSamples());
  return AlbedoTexel(r);
}

// f82_bias: the F82-tint term at one texel by the visible-normal rule of
// rules/glass/gen_schlick.h; below alpha 1e-4 the mirror, b(mu).
TexelEstimate F82Texel(const BakeSpec& spec, double alpha, double mu) {
  TexelEstimate v;
  const double m = std::max(mu, kMuMin);
  if (alpha < kMinAlpha<double>) {
    v.e = F82TintWeight(m);
    return v;
  }
  const RuleResult r = F82TintBias(alpha, spec.masking, m, spec.tolerance, spec.EffectiveSamples());
  return AlbedoTexel(r);
}

// The shape of s_h in slice k of a gen_schlick table: the exponent axis'
// value or the dielectric shape at the ior axis' value, each clamped.
GenSchlickShape GenSchlickSlice(const BakeSpec& spec, int k) {
  if (spec.table == TableKind::kGenSchlickS) {
    const Axis& a = spec.exponent;
    return {std::clamp(a.Value(k), a.clamp_min, a.clamp_max), 1.0};
  }
  return {-1.0, std::min(spec.ior.Value(k), spec.ior.clamp_max)};
}

// E (or dfg) of the spec's model at (alpha, mu) (the families over mu x
// roughness), by its row.
TexelEstimate Texel(const BakeSpec& spec, double alpha, double mu, uint64_t texel_seed) {
  TexelAt at;
  at.mu = mu;
  at.alpha = alpha;
  return BakerRowOf(spec.model.kind)->texel(spec, at, texel_seed);
}

// A texel of spec's table in slice z at (alpha, mu), `slice` the spec Bake
// made for that slice (gamma or eta set): the one dispatch over the table
// kinds, Bake's and IntegrateTexel's.
TexelEstimate TableTexel(const BakeSpec& spec, const BakeSpec& slice, int z, double alpha, double mu,
                         uint64_t texel_seed) {
  if (spec.GenSchlick()) return GenSchlickTexel(spec, alpha, mu, GenSchlickSlice(spec, z));
  if (spec.table == TableKind::kF82Bias) return F82Texel(spec, alpha, mu);
  return Texel(slice, alpha, mu, texel_seed);
}

std::string ModelJson(const BakeSpec& spec) {
  nlohmann::json j;
  j["name"] = spec.model.name();
  BakerRowOf(spec.model.kind)->model_json(spec, &j);
  return j.dump();
}

// The entries every rule shares (the sampling integrators', the generic
// E_avg rules, grazing mu), then the row's own (nlohmann::json keeps its
// keys sorted: the order of the two does not show).
std::string IntegratorJson(const BakeSpec& spec) {
  nlohmann::json j;
  const int n = spec.EffectiveSamples();
  j["method"] = IntegratorName(spec.integrator);
  switch (spec.integrator) {
    case IntegratorKind::kQuadrature:
      j["tolerance"] = spec.tolerance;
      j["max_pieces"] = n;
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
    if (spec.integrator == IntegratorKind::kQuadrature) {
      j["E_avg"] = "2 int_0^1 E(mu) mu dmu, adaptive Gauss-Kronrod 15 in sqrt(mu) from the "
                   "pieces [0, 1/4], [1/4, 1], the worst bisected until the error estimate "
                   "meets the tolerance; E at each node from the integrator above; error: "
                   "sum of |K15 - G7| plus the propagated E error";
    } else {
      j["E_avg"] = "2 int_0^1 E(mu) mu dmu, 32-node Gauss-Legendre in sqrt(mu), "
                   "E at each node from the integrator above; error: difference from "
                   "the 16-node rule plus the propagated E error";
    }
  }
  j["grazing"] = "mu = 0 evaluated at mu = 1e-7";
  BakerRowOf(spec.model.kind)->integrator_json(spec, &j);
  return j.dump();
}

}  // namespace

namespace {

// Sets the coordinate of `at` that the view or lobe axis `a` gives at its
// entry i (mu and the roughness at least their clamps).
void SetAt(const Axis& a, int i, TexelAt* at) {
  const double v = a.Value(i);
  if (a.name == "mu") {
    at->mu = std::max(v, a.clamp_min);
  } else if (a.name == "roughness") {
    at->roughness = std::max(v, a.clamp_min);
  } else if (a.name == "phi_o") {
    at->phi = v;
  } else if (a.name == "anisotropy") {
    at->anisotropy = v;
  } else if (a.name == "alpha_x") {
    at->alpha_x = v;
  } else if (a.name == "alpha_y") {
    at->alpha_y = v;
  }
}

// For an E table over (mu, phi_o) (ellipsoid) or (mu, phi_o, r, s)
// (ggx-aniso, phi_o fastest of the rows): each texel's first texel of the
// same view and material. Where mu = 1 wo is the normal whatever phi_o;
// phi_o values within 1e-12 modulo 2 pi are one azimuth.
std::vector<int64_t> SameViewTexels(const BakeSpec& spec, const Axis& ax_mu, int width,
                                    int64_t total) {
  const int n_phi = spec.phi.size;
  std::vector<int> phi_first(n_phi);
  for (int y = 0; y < n_phi; ++y) {
    phi_first[y] = y;
    // (Quadratic in the phi_o count: skipped for very long axes.)
    for (int z = 0; z < y && n_phi <= 4096; ++z) {
      if (std::abs(std::remainder(spec.phi.Value(y) - spec.phi.Value(z), kTwoPi<double>)) <= 1e-12) {
        phi_first[y] = z;
        break;
      }
    }
  }
  std::vector<int64_t> same(static_cast<size_t>(total));
  for (int64_t idx = 0; idx < total; ++idx) {
    const int x = static_cast<int>(idx % width);
    const int64_t y = idx / width;
    const int yp = static_cast<int>(y % n_phi);
    const int64_t rest = y / n_phi;
    const int first = ax_mu.Value(x) >= 1 ? 0 : phi_first[yp];
    same[idx] = (rest * n_phi + first) * width + x;
  }
  return same;
}

}  // namespace

EavgEstimate IntegrateBiasAvg(const BakeSpec& spec, double roughness) {
  BakeSpec s = spec;
  s.table = TableKind::kDfg;
  ValidateBakeSpec(s);  // a model with a dfg table
  if (s.integrator != IntegratorKind::kQuadrature) Bad("the dfg bias average is integrated by the quadrature");
  const double alpha = AlphaFromRoughness(roughness);
  return AdaptiveEavg(
      [&](double mu) {
        const TexelEstimate v = Texel(s, alpha, mu, 0);
        TexelEstimate b;
        b.e = v.bias;
        b.err_e = v.err_bias;
        return b;
      },
      s.tolerance, EavgGrading(*BakerRowOf(s.model.kind), s));
}

namespace {

// E_avg at the roughness (and ggx-aniso's anisotropy) of `at`: by the
// quadrature the row's own rule or AdaptiveEavg over its texel, by a
// sampling integrator the fixed rule below; `index` picks the latter's
// random streams.
EavgEstimate EavgAt(const BakeSpec& spec, const TexelAt& at, uint64_t index) {
  if (spec.integrator == IntegratorKind::kQuadrature) {
    const BakerRow& row = *BakerRowOf(spec.model.kind);
    return row.eavg ? row.eavg(spec, at) : AdaptiveEavgOf(row, spec, at);
  }
  // The sampling integrators: a fixed rule, 32-node Gauss-Legendre in s
  // with the 16-node rule for the error estimate (each E carries its own
  // random error; bisecting on noise would not converge).
  static const GaussLegendre fine(32), coarse(16);
  auto rule = [&](const GaussLegendre& gl, uint64_t salt, double* err) {
    double acc = 0, acc_err = 0;
    for (size_t k = 0; k < gl.x.size(); ++k) {
      const double sv = gl.x[k];
      const TexelEstimate v =
          Texel(spec, at.alpha, sv * sv, Mix64(spec.seed ^ Mix64((index << 20) + k + salt)));
      const double wk = 4 * gl.w[k] * sv * sv * sv;
      acc += wk * v.e;
      acc_err += wk * v.err_e;
    }
    *err = acc_err;
    return acc;
  };
  double err_f, err_c;
  const double f = rule(fine, 0, &err_f);
  const double c = rule(coarse, 1 << 10, &err_c);
  return {f, std::abs(f - c) + err_f};
}

}  // namespace

EavgEstimate IntegrateEavg(const BakeSpec& spec, double roughness, uint64_t index) {
  TexelAt at;
  at.roughness = roughness;
  at.alpha = AlphaFromRoughness(roughness);
  return EavgAt(spec, at, index);
}

void ReleaseBakeCaches() {
  for (const BakerFamily* family : kBakerFamilies) {
    for (int k = 0; k < family->count; ++k) {
      if (family->rows[k].release) family->rows[k].release();
    }
  }
}


Table Bake(const BakeSpec& spec, const ProgressFn& progress) {
  ValidateBakeSpec(spec);
  const auto start = std::chrono::steady_clock::now();
  Table t;
  t.spec = spec;
  t.model_json = ModelJson(spec);
  t.integrator_json = IntegratorJson(spec);
  const Axis& ax_mu = spec.mu;
  const Axis& ax_r = spec.roughness;
  const bool eavg = spec.table == TableKind::kEavg;
  const bool sel = spec.table == TableKind::kSelNorm;
  TableShape shape = ShapeOf(spec);
  t.axes = std::move(shape.axes);
  t.width = int(shape.width);
  t.height = int(shape.height);
  // One spec per slice of a parameter axis, so every slice is baked
  // exactly as a table at that parameter would be: gamma (model.gamma set
  // from the axis), ggx-glass's ior (eta = ior, or 1 / ior inside);
  // gen_schlick's slices are set up per texel (GenSchlickSlice).
  std::vector<BakeSpec> slice_specs(1, spec);
  if (!t.axes.empty() && ParameterAxis(t.axes.back())) slice_specs.assign(size_t(t.axes.back().size), spec);
  if (spec.HasGammaAxis()) {
    for (int k = 0; k < spec.gamma.size; ++k) slice_specs[k].model.gamma = spec.gamma.Value(k);
  }
  if (spec.Glass()) {
    for (int k = 0; k < spec.ior.size; ++k) {
      const double ior = std::min(spec.ior.Value(k), spec.ior.clamp_max);
      slice_specs[k].model.ior = spec.inverse ? 1 / ior : ior;
    }
  }
  const int64_t total = shape.Texels();
  std::vector<double> error;
  // Every output buffer is allocated before the bake: a memory failure
  // comes first, not after the work.
  try {
    for (ChannelSpec& c : shape.channels) {
      t.channels.push_back({std::move(c.name), c.meaning, std::move(c.definition), {}, {}, {}});
    }
    for (Channel& c : t.channels) {
      c.values.resize(size_t(total));
      c.stored.resize(size_t(total));
      if (spec.half) c.half_bits.resize(size_t(total));
    }
    error.resize(size_t(total));
  } catch (const std::bad_alloc&) {
    char msg[160];
    std::snprintf(msg, sizeof(msg), "cannot allocate %.1f MiB for the %dx%d %s table (out of memory)",
                  double(BakeOutputBytes(spec)) / (1 << 20), t.width, t.height,
                  TableName(spec.table));
    throw std::runtime_error(msg);
  }

  std::unique_ptr<tbb::global_control> limit;
  if (spec.threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  spec.threads);
  }
  const BakerRow& row = *BakerRowOf(spec.model.kind);
  // A table over the family's own view axes (the ellipsoid's mu x phi_o,
  // ggx-aniso's four): each texel's coordinates from the axes' names.
  const bool own_view = row.own_axes && !t.axes.empty() && !ParameterAxis(t.axes.back());
  if (row.prepare) {
    for (const BakeSpec& s : slice_specs) row.prepare(s);
  }
  std::atomic<int64_t> done{0};
  std::vector<double>& v0 = t.channels[0].values;
  const double e_max = StoredEMax(spec);
  if (sel) {
    // N in e, N / (4 pi alpha_x alpha_y) in bias.
    tbb::parallel_for(int64_t(0), total, [&](int64_t i) {
      const int x = static_cast<int>(i % t.width), y = static_cast<int>(i / t.width);
      TexelAt at;
      SetAt(t.axes[0], x, &at);
      SetAt(t.axes[1], y, &at);
      const TexelEstimate n = row.texel(spec, at, 0);
      v0[i] = n.e;
      t.channels[1].values[i] = n.bias;
      error[i] = std::max(n.err_e, n.err_bias);
      if (progress) progress(++done, total);
    });
  } else if (eavg) {
    tbb::parallel_for(int64_t(0), total, [&](int64_t i) {
      const int x = static_cast<int>(i % t.width), z = static_cast<int>(i / t.width);
      // Rows: a parameter axis's slices, or a family's own axis (ggx-aniso's
      // anisotropy).
      TexelAt at;
      at.roughness = std::max(ax_r.Value(x), ax_r.clamp_min);
      at.alpha = AlphaFromRoughness(at.roughness);
      if (t.axes.size() > 1 && !ParameterAxis(t.axes[1])) SetAt(t.axes[1], z, &at);
      const EavgEstimate e = EavgAt(slice_specs[slice_specs.size() > 1 ? z : 0], at, uint64_t(i));
      const double value = std::clamp(e.value, 0.0, e_max);
      v0[i] = spec.complement ? 1.0 - value : value;
      error[i] = e.error;
      if (progress) progress(++done, total);
    });
  } else {
    // Texels whose views coincide are computed once: where mu = 1 every
    // phi_o is the same view, and phi_o values equal modulo 2 pi (0 and
    // 2 pi on an edges axis) are too. same_as[idx] is the first texel of
    // idx's view.
    const bool views = own_view && spec.table == TableKind::kE && t.axes.size() > 1 && t.axes[1].name == "phi_o";
    const std::vector<int64_t> same_as =
        views ? SameViewTexels(spec, ax_mu, t.width, total) : std::vector<int64_t>();
    tbb::parallel_for(int64_t(0), total, [&](int64_t idx) {
      if (!same_as.empty() && same_as[idx] != idx) return;
      const int x = static_cast<int>(idx % t.width), y = static_cast<int>(idx / t.width);
      const double mu = std::max(ax_mu.Value(x), ax_mu.clamp_min);
      TexelEstimate v;
      if (own_view) {
        TexelAt at;
        int64_t rest = idx;
        for (const Axis& a : t.axes) {
          SetAt(a, static_cast<int>(rest % a.size), &at);
          rest /= a.size;
        }
        v = row.texel(spec, at, 0);
      } else {
        const int ry = y % ax_r.size, z = y / ax_r.size;
        const double r = std::max(ax_r.Value(ry), ax_r.clamp_min);
        v = TableTexel(spec, slice_specs[z], z, r * r, mu, Mix64(spec.seed ^ Mix64(uint64_t(idx))));
      }
      if (spec.table != TableKind::kDfg) {
        // E, or a table of one quantity of its own (gen_schlick's s,
        // f82_bias) in v.e.
        const double e = std::clamp(v.e, 0.0, e_max);  // ClampToRange's E
        v0[idx] = spec.complement ? 1.0 - e : e;
        error[idx] = v.err_e;
      } else {
        const TexelEstimate c = ClampToRange({v.e, v.scale, v.bias, v.err_e, v.err_scale, v.err_bias});
        v0[idx] = c.scale;
        t.channels[1].values[idx] = c.bias;
        error[idx] = std::max(c.err_scale, c.err_bias);
        if (spec.complement) {
          t.channels[2].values[idx] = 1.0 - c.e;
          error[idx] = std::max(error[idx], c.err_e);
        }
      }
      if (progress) progress(++done, total);
    });
    for (int64_t idx = 0; idx < total && !same_as.empty(); ++idx) {
      if (same_as[idx] == idx) continue;
      v0[idx] = v0[same_as[idx]];
      error[idx] = error[same_as[idx]];
      if (progress) progress(++done, total);
    }
  }
  for (double e : error) t.integration_error = std::max(t.integration_error, e);
  if (spec.error_channel) t.channels.back().values = error;

  // Rounding to the pixel type, with dfg's scale + bias <= 1 kept in the
  // stored precision; the claim adds each texel's rounding to its error.
  const size_t nv = size_t(shape.value_channels);
  const PixelType pixel = spec.half ? PixelType::kHalf : PixelType::kFloat;
  double claim = 0;
  for (int64_t i = 0; i < total; ++i) {
    double worst = 0;
    double stored[3];
    for (size_t c = 0; c < nv; ++c) stored[c] = RoundToPixel(t.channels[c].values[i], pixel);
    if (spec.table == TableKind::kDfg) {
      RoundScaleBias(t.channels[0].values[i], t.channels[1].values[i], pixel, &stored[0], &stored[1]);
    }
    for (size_t c = 0; c < nv; ++c) {
      t.channels[c].stored[i] = float(stored[c]);
      worst = std::max(worst, std::abs(stored[c] - t.channels[c].values[i]));
    }
    claim = std::max(claim, error[i] + worst);
  }
  if (spec.error_channel) {
    Channel& ce = t.channels.back();
    for (int64_t i = 0; i < total; ++i) ce.stored[i] = float(RoundToPixel(ce.values[i], pixel));
  }
  if (spec.half) {
    for (Channel& c : t.channels) {
      for (int64_t i = 0; i < total; ++i) c.half_bits[i] = Imath::half(c.stored[i]).bits();
    }
  }
  t.max_abs_error = claim;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

double StoredEMax(const BakeSpec& spec) { return BakerRowOf(spec.model.kind)->e_max; }

TexelEstimate ClampToRange(const TexelEstimate& v, double e_max) {
  TexelEstimate c = v;
  // E: the true value lies in [0, e_max], so the clamp only moves towards it.
  c.e = std::clamp(v.e, 0.0, e_max);
  // scale, bias >= 0 likewise; scale + bias <= 1 is kept by moving both
  // down by half the excess, and the move is added to their errors.
  double s = std::max(v.scale, 0.0), b = std::max(v.bias, 0.0);
  const double excess = s + b - 1.0;
  if (excess > 0) {
    s -= excess / 2;
    b -= excess / 2;
    if (s < 0) { b += s; s = 0; }
    if (b < 0) { s += b; b = 0; }
    c.err_scale += excess;
    c.err_bias += excess;
  }
  c.scale = s;
  c.bias = b;
  return c;
}

TexelEstimate IntegrateTexel(const BakeSpec& spec, double roughness, double mu,
                             uint64_t texel_seed) {
  ValidateBakeSpec(spec);
  if (spec.GenSchlick()) {
    // Its value depends on the slice: one exponent or ior, a size-1 axis.
    const Axis& slice = spec.table == TableKind::kGenSchlickS ? spec.exponent : spec.ior;
    if (slice.size != 1) {
      Bad("{size}: one texel of " + std::string(TableName(spec.table)) + " is at one " + slice.name + " (got " +
          std::to_string(slice.size) + " slices)");
    }
  }
  return TableTexel(spec, spec, 0, AlphaFromRoughness(roughness), mu, Mix64(spec.seed ^ texel_seed));
}

}  // namespace brdfbake
