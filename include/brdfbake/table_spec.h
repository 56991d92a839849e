// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What a table is, in one place (docs/format.md): its kind and model
// (BakeSpec), its axes, image size and channels with their meanings
// (ShapeOf), what it may be baked with (ValidateBakeSpec). The baker, the
// command line, the containers, the presets, the scenes and the report
// all read a table's shape from here.

#ifndef BRDFBAKE_TABLE_SPEC_H_
#define BRDFBAKE_TABLE_SPEC_H_

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"

namespace brdfbake {

// kSelNorm: the integral over the sphere of the squared ellipsoidal lobe
// (model sel, [TokuyoshiHarada]) over alpha_x x alpha_y (sel_norm.h).
// kGenSchlickS, kGenSchlickIorS (model ggx): the factor s of the
// generalized Schlick Fresnel F = mix(F0, F90, s) over a GGX reflection
// lobe ([Cycles]; rules/glass/gen_schlick.h), over mu x roughness x the
// Schlick exponent (s_h = (1 - wo.h)^exponent) or x ior (s_h = (F(ior,
// wo.h) - F0) / (1 - F0), the dielectric shape): Cycles'
// table_ggx_gen_schlick_s and table_ggx_gen_schlick_ior_s.
// kF82Bias (model ggx): the F82-tint term of a GGX reflection lobe, the
// integral of (f / F) wo.h (1 - wo.h)^6 cos(theta_i) over mu x roughness
// ([Hoffman19]; rules/glass/gen_schlick.h): the third channel of Blender
// EEVEE's brdf_ggx.
enum class TableKind { kE, kEavg, kDfg, kSelNorm, kGenSchlickS, kGenSchlickIorS, kF82Bias };

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr double kHalfPi = 1.5707963267948966;
// kTail is the gamma axis's warp (STD over gamma, gamma in [1.500001, inf]):
// u = (gamma - 1.5) / (gamma - 0.5) is log-linear in t,
// u = u(min)^(1 - t) u(max)^t, so gamma = inf (u = 1) can end the axis and
// the knee of E near gamma = 1.5 (E ~ z / (z + C), z = gamma - 1.5, with C
// from 1e-4 to 0.1 across texels) gets slices at every scale of z.
// kFresnelZ is the ior axis's default warp (ggx-glass): z = F0^(1/4) =
// sqrt(|ior - 1| / (ior + 1)) is linear in t between z(min) and z(max), and
// ior = (1 + z^2) / (1 - z^2) (the coordinate Cycles looks its glass
// tables up with, [Cycles]; E changes about evenly in it, and the whole
// range from ior 1 (z = 0) to 100 (z = 0.99) fits one axis).
// kSchlickZ is the exponent axis's warp (gen_schlick_s): z = 5 / (exponent
// + 5) linear in t between z(min) and z(max) (exponent = inf is z = 0), and
// exponent = 5 (1 - z) / z: Cycles' lookup coordinate, z = 1/2 at Schlick's
// 5. The axis may run either way (Cycles' runs from inf down to 0).
// kTwoSided is an ior axis over both sides of an interface (edges, an even
// size N = 2H, min < 1 < max): entries 0 to H - 1 hold eta < 1 with 1 / eta
// linear from 1 / min down to 1, entries H to N - 1 eta linear from 1 up to
// max; both middle entries are 1 (OpenPBR's layout, [OpenPbrBsdf]).
// kOneMinusSquare (view and lobe axes) is w(t) = 1 - (1 - t)^2: the
// coordinate 1 - sqrt(1 - w) is linear in t, so over mu in [0, 1] sqrt(1 -
// mu) = 1 - t (EEVEE's sqrt(1 - NoV) with its rows reversed; entries
// gather at mu = 1 as the square warp gathers them at 0).
enum class Warp { kLinear, kSquare, kSqrt, kTail, kFresnelZ, kSchlickZ, kTwoSided, kOneMinusSquare };
enum class Placement { kCenters, kEdges };

// quadrature: Gauss-Legendre over the sampler's unit square with the horizon
//   crossing located per line and the rule split there, refined along a
//   ladder of node counts until two successive rules agree to a tolerance;
//   error from the last two rules.
// qmc: randomized quasi-Monte Carlo (Hammersley points with independent
//   Cranley-Patterson rotations), visible-normal importance sampling; error
//   from the spread of the replicas.
// mc: plain Monte Carlo with visible-normal sampling; error from the sample
//   variance.
// engine: the settings engines use today, N Hammersley points (1024 by
//   default) with NDF importance sampling of the half vector; its error is
//   measured against the quadrature.
enum class IntegratorKind { kQuadrature, kQmc, kMc, kEngine };

const char* TableName(TableKind t);
// Every table kind's name with a note where it needs one, for the command
// line's help: "E | E_avg | dfg | sel_norm (with {model} sel) | ...", the
// parameters marked as in error messages (error.h).
std::string TableKindsHelp();
const char* WarpName(Warp w);
const char* PlacementName(Placement p);
const char* IntegratorName(IntegratorKind k);
// Parsers throw std::invalid_argument naming the bad value.
TableKind ParseTable(const std::string& s);
Warp ParseWarp(const std::string& s);
Placement ParsePlacement(const std::string& s);
IntegratorKind ParseIntegrator(const std::string& s);

struct Axis {
  std::string name;  // "mu", "roughness" or "gamma"
  int size = 32;
  double min = 0, max = 1;
  Warp warp = Warp::kLinear;
  Placement placement = Placement::kEdges;
  // The integrand is evaluated at max(value, clamp_min) (Cycles' tables
  // clamp mu and roughness at 1e-4); 0 = no clamp.
  double clamp_min = 0;
  // ... and at most clamp_max (the ior axis only: Cycles' glass tables
  // end at z = 1, ior = inf, baked at z = 0.99); inf = no clamp.
  double clamp_max = kInfinity;

  // docs/format.md: t = (i + 0.5) / N (centers) or i / (N - 1) (edges),
  // value = min + (max - min) w(t); the tail warp maps t as its comment says.
  double Value(int i) const { return ValueAt(i); }
  // The same map at a fractional index (e.g. i + 0.5, a cell midpoint).
  double ValueAt(double fi) const;
  // Lists "values" (with "inf" for infinity) when the warp is tail.
  std::string ToJson() const;
};

struct BakeSpec {
  TableKind table = TableKind::kE;
  ModelParams model;  // ggx, beckmann or std; alpha comes from the roughness axis
  Masking masking = Masking::kHeightCorrelated;
  IntegratorKind integrator = IntegratorKind::kQuadrature;
  int samples = 0;  // max pieces of the theta_i rule (quadrature) or samples per
                    // texel; 0 = default
  // quadrature: stop refining when two rules agree to this. 1e-7 is the
  // precision of the float pixels the tables are stored in.
  double tolerance = 1e-7;
  uint64_t seed = 1;
  Axis mu{"mu", 32, 0.0, 1.0, Warp::kLinear, Placement::kEdges};
  Axis roughness{"roughness", 32, 0.0, 1.0, Warp::kLinear, Placement::kEdges};
  // std only: a third axis over gamma (E and dfg: slices of mu x roughness;
  // E_avg: rows over gamma), which then replaces model.gamma. size 0 = no
  // gamma axis, the table is baked at model.gamma.
  Axis gamma{"gamma", 0, 1.501, kInfinity, Warp::kTail, Placement::kEdges};
  bool HasGammaAxis() const { return gamma.size > 0; }
  // ggx-glass: the third axis (E: slices of mu x roughness; E_avg: rows
  // over roughness), the relative index of refraction in [1, 100] of the
  // medium below the view; it replaces model.ior.
  Axis ior{"ior", 16, 1.0, 3.0, Warp::kFresnelZ, Placement::kEdges};
  // ggx-glass: light leaving the medium (the view inside it, as Cycles'
  // inverse tables): each slice is baked at eta = 1 / ior < 1, with total
  // internal reflection; the axis keeps the medium's ior.
  bool inverse = false;
  // ggx-glass: which lobes E counts (models/dielectric.h): reflection plus
  // refraction (the default), the reflection alone or the refraction alone.
  DielectricPart part = DielectricPart::kBoth;
  bool Glass() const { return model.kind == ModelKind::kGgxGlass; }
  // gen_schlick_s: the third axis, the Schlick exponent (the default is
  // Cycles': z = 5 / (exponent + 5) = k / 15 from exponent inf to 0, baked
  // at z in [1e-4, 0.99], exponent 0.0505 to 49995). gen_schlick_ior_s
  // takes the ior axis (in [1, 100], or to inf with a clamp).
  Axis exponent{"exponent",           16, kInfinity, 0.0, Warp::kSchlickZ, Placement::kEdges, 5 * 0.01 / 0.99,
                5 * (1 - 1e-4) / 1e-4};
  bool GenSchlick() const { return table == TableKind::kGenSchlickS || table == TableKind::kGenSchlickIorS; }
  // ggx-aniso (anisotropic GGX as glTF KHR_materials_anisotropy defines it:
  // alpha_t = mix(r^2, 1, s^2) along the tangent, alpha_b = r^2): E over
  // mu x phi_o x roughness x anisotropy, E_avg over roughness x anisotropy.
  // phi_o is the azimuth of wo from the tangent in radians; E is even in
  // phi_o and symmetric about pi/2, so [0, pi/2] covers every azimuth.
  Axis phi{"phi_o", 16, 0.0, kHalfPi, Warp::kLinear, Placement::kEdges};
  Axis anisotropy{"anisotropy", 16, 0.0, 1.0, Warp::kLinear, Placement::kEdges};
  bool Anisotropic() const { return model.kind == ModelKind::kGgxAniso; }
  // sel_norm: the lobe's widths, in [0, 1] (clamped below at 1e-4).
  Axis alpha_x{"alpha_x", 32, 0.0, 1.0, Warp::kLinear, Placement::kEdges};
  Axis alpha_y{"alpha_y", 32, 0.0, 1.0, Warp::kLinear, Placement::kEdges};
  // E and dfg: 1 - E; E_avg: 1 - E_avg. E and E_avg store the complement
  // instead of the value, dfg adds it as a third channel.
  bool complement = false;
  bool error_channel = false;  // add a per-texel "error" channel
  bool half = false;           // half pixels (default float)
  int threads = 0;             // 0 = all cores, at most kMaxThreads
  bool estimate_error = true;  // engine: measure the error against the quadrature
  // quadrature: evaluate the integrand in double SIMD lanes (the best
  // Highway target, or the one ForceTarget chose); false runs the double
  // scalar reference of the same rule (`--target scalar`).
  bool simd = true;

  // Default samples for the integrator (the value used when samples == 0).
  int EffectiveSamples() const;
};

inline constexpr int kMaxThreads = 1024;

// Throws std::invalid_argument (one line, naming the bad input).
void ValidateBakeSpec(const BakeSpec& spec);

// Bytes of memory Bake() allocates for its outputs (checked before baking).
size_t BakeOutputBytes(const BakeSpec& spec);
// The values a bake of `spec` stores: texels times channels (with the
// error channel).
int64_t BakeOutputValues(const BakeSpec& spec);

// What a channel holds, one value per texel (docs/format.md).
enum class Meaning {
  kE,             // directional albedo E(mu)
  kOneMinusE,     // 1 - E
  kEavg,          // E_avg
  kOneMinusEavg,  // 1 - E_avg
  kDfgScale,      // the split-sum DFG's scale (F0's factor)
  kDfgBias,       // ... and bias (F90's factor)
  kSelIntegral,   // sel_norm: the integral N of the squared ellipsoidal lobe
  kSelRatio,      // sel_norm: N / (4 pi alpha_x alpha_y)
  kS,             // gen_schlick: the factor s
  kF82Bias,       // f82_bias: the F82-tint term
  kError,         // the integrator's error estimate per texel (the last)
};
inline constexpr int kMeaningCount = int(Meaning::kError) + 1;
// As the files' brdfbake.channels name it: E, 1-E, E_avg, 1-E_avg,
// dfg.scale, dfg.bias, sel.integral, sel.ratio, s, error.
const char* MeaningName(Meaning m);

struct ChannelSpec {
  std::string name;  // the EXR channel name
  Meaning meaning;
  std::string definition;  // one sentence, for the file header
};

// The shape of the table `spec` describes. Axes run fastest first: x is
// the first axis, y every other axis stacked (a 3D or 4D table stores its
// 2D slices one above the other); a table without axes (the ellipsoid's
// E_avg) is one texel. Channel names sort into the intended order (OpenEXR
// stores channels sorted by name), so a loader that takes channels by
// index gets
//   E:        E (or 1-E), [error]
//   E_avg:    E_avg (or 1-E_avg), [error]
//   dfg:      dfg.0_scale, dfg.1_bias, [dfg.2_1-E], [dfg.N_error]
//   sel_norm: sel.0_integral, sel.1_ratio, [sel.2_error]
//   gen_schlick_s, gen_schlick_ior_s: s, [error]
struct TableShape {
  std::vector<Axis> axes;
  int64_t width = 1, height = 1;
  std::vector<ChannelSpec> channels;  // with the error channel last when the spec asks for it
  int value_channels = 1;             // the channels before the error channel
  int64_t Texels() const { return width * height; }
};
// A model this build does not contain (BRDFBAKE_MODELS) has no shape:
// std::invalid_argument, as ValidateModelParams says.
TableShape ShapeOf(const BakeSpec& spec);

// The same axes as ShapeOf's, as pointers into `spec`: to set their sizes,
// ranges and warps.
std::vector<Axis*> TableAxes(BakeSpec* spec);
// Whether the table has the axis `name` ("roughness", "phi_o", ...).
bool TableHasAxis(const BakeSpec& spec, const std::string& name);
// Whether an axis is a slice axis over a model parameter (gamma, ior,
// exponent) rather than over the view or the lobe (mu, roughness, phi_o,
// anisotropy, alpha_x, alpha_y): settings meant for every axis skip it.
bool ParameterAxis(const Axis& axis);
// Each axis's size when none is given: 32 per axis for E, dfg, E_avg and
// sel_norm, 32 x 16 (x 32 x 16) for ggx-aniso, 32^3 for ggx-glass, 16^3
// for gen_schlick; the sizes of TableAxes(spec).
std::vector<int> DefaultSizes(const BakeSpec& spec);
// The form of a size, for messages: "WxH (mu x roughness, e.g. 32x32)".
std::string SizeForm(const BakeSpec& spec);

// The integrators a table of `spec`'s kind and model is baked with: every
// one for E, E_avg and dfg of the isotropic microfacet models and the
// lobes, the quadrature alone for the others (ValidateBakeSpec's rule).
// A model this build does not contain is known by its table kind alone.
std::vector<IntegratorKind> TableIntegrators(const BakeSpec& spec);
// Whether `model` bakes tables of kind `table` (ValidateBakeSpec refuses
// any other), and the names of this build's models that bake it.
bool ModelBakes(ModelKind model, TableKind table);
std::vector<std::string> ModelsBaking(TableKind table);
// Whether `model`'s tables take a Smith masking (BakeSpec::masking): not
// the lobes whose shadowing is their own (charlie) or that have none
// (disney-diffuse); false for a model this build does not contain.
bool ModelTakesMasking(ModelKind model);

// Stored values are clamped to the physical range: E, 1-E, E_avg and
// 1-E_avg to [0, 1]; dfg.scale, dfg.bias >= 0 with scale + bias <= 1 in the
// stored precision. Every claimed error covers the clamp.
extern const char* const kStoredRange;

// "axes fastest first: ..." and the axis map, for the brdfbake.layout
// attribute.
extern const char* const kLayoutText;

}  // namespace brdfbake

#endif  // BRDFBAKE_TABLE_SPEC_H_
