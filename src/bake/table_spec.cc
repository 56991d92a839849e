// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What a table is (table_spec.h): names, axes, shapes, channels and the
// checks of a BakeSpec.

#include "brdfbake/table_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bake/family_row.h"
#include "bake/warp_coordinates.h"
#include "base/error.h"
#include "base/text.h"
#include "brdfbake/models/constants.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/std_ndf.h"

namespace brdfbake {

namespace {

// Every table kind in one row: its name, what `--table`'s help says of it
// (marked parameters), whether the quadrature alone bakes it, and for the
// table of one model's lobe alone (sel_norm; gen_schlick and f82_bias of
// GGX) that model, what the table is and what it stores in place of a
// complement.
struct KindRow {
  TableKind kind;
  const char* name;
  const char* help;  // "" or a note after the name; rows with one note share it
  bool quadrature_only;
  const char* term;  // nullptr for the tables of every model
  ModelKind model;   // the model of `term`
  const char* stores;
};

constexpr KindRow kKindRows[] = {
    {TableKind::kE, "E", "", false, nullptr, ModelKind::kGgx, nullptr},
    {TableKind::kEavg, "E_avg", "", false, nullptr, ModelKind::kGgx, nullptr},
    {TableKind::kDfg, "dfg", "", false, nullptr, ModelKind::kGgx, nullptr},
    {TableKind::kSelNorm, "sel_norm", "with {model} sel", true, "the integral of the sel lobe", ModelKind::kSel,
     "N and N / (4 pi alpha_x alpha_y), no complement"},
    {TableKind::kGenSchlickS, "gen_schlick_s",
     "the generalized Schlick factor s of GGX over mu x roughness x exponent or ior", true,
     "the Fresnel factor of a GGX reflection lobe", ModelKind::kGgx, "s itself"},
    {TableKind::kGenSchlickIorS, "gen_schlick_ior_s",
     "the generalized Schlick factor s of GGX over mu x roughness x exponent or ior", true,
     "the Fresnel factor of a GGX reflection lobe", ModelKind::kGgx, "s itself"},
    {TableKind::kF82Bias, "f82_bias",
     "GGX's F82-tint term, wo.h (1 - wo.h)^6 weighting its energy, over mu x roughness", true,
     "the F82-tint term of a GGX reflection lobe", ModelKind::kGgx, "the term itself"},
};

const KindRow& RowOf(TableKind t) {
  for (const KindRow& r : kKindRows) {
    if (r.kind == t) return r;
  }
  return kKindRows[0];
}

}  // namespace

const char* TableName(TableKind t) { return RowOf(t).name; }

std::string TableKindsHelp() {
  std::string help;
  for (size_t k = 0; k < std::size(kKindRows); ++k) {
    const KindRow& r = kKindRows[k];
    const bool shares_next = k + 1 < std::size(kKindRows) && *r.help && std::string(r.help) == kKindRows[k + 1].help;
    help += r.name;
    if (shares_next) {
      help += ", ";
      continue;
    }
    if (*r.help) help += std::string(" (") + r.help + ")";
    if (k + 1 < std::size(kKindRows)) help += " | ";
  }
  return help;
}

const char* WarpName(Warp w) {
  switch (w) {
    case Warp::kLinear: return "linear";
    case Warp::kSquare: return "square";
    case Warp::kSqrt: return "sqrt";
    case Warp::kTail: return "tail";
    case Warp::kFresnelZ: return "fresnel-z";
    case Warp::kSchlickZ: return "schlick-z";
    case Warp::kTwoSided: return "two-sided";
    case Warp::kOneMinusSquare: return "one-minus-square";
  }
  return "linear";
}
const char* PlacementName(Placement p) { return p == Placement::kCenters ? "centers" : "edges"; }
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
  std::vector<std::string> names;
  for (const KindRow& r : kKindRows) {
    if (s == r.name) return r.kind;
    names.push_back(r.name);
  }
  Bad("{table}: unknown table '" + s + "' (expected " + OrList(names) + ")" +
      DidYouMean(s, names,
                 {{"albedo", "E"}, {"eavg", "E_avg"}, {"brdf_lut", "dfg"}, {"gen_schlick", "gen_schlick_s"}}));
}
Warp ParseWarp(const std::string& s) {
  if (s == "linear") return Warp::kLinear;
  if (s == "square") return Warp::kSquare;
  if (s == "sqrt") return Warp::kSqrt;
  if (s == "tail") return Warp::kTail;
  if (s == "fresnel-z") return Warp::kFresnelZ;
  if (s == "schlick-z") return Warp::kSchlickZ;
  if (s == "two-sided") return Warp::kTwoSided;
  if (s == "one-minus-square") return Warp::kOneMinusSquare;
  Bad("{warp}: unknown warp '" + s +
      "' (expected linear, square, sqrt, one-minus-square, tail for the gamma axis, "
      "fresnel-z or two-sided for the ior axis, or schlick-z for the exponent axis)");
}
Placement ParsePlacement(const std::string& s) {
  if (s == "centers") return Placement::kCenters;
  if (s == "edges") return Placement::kEdges;
  Bad("{placement}: unknown placement '" + s + "' (expected centers or edges)");
}
IntegratorKind ParseIntegrator(const std::string& s) {
  if (s == "quadrature") return IntegratorKind::kQuadrature;
  if (s == "qmc") return IntegratorKind::kQmc;
  if (s == "mc") return IntegratorKind::kMc;
  if (s == "engine") return IntegratorKind::kEngine;
  Bad("{integrator}: unknown integrator '" + s + "' (expected quadrature, qmc, mc or engine)");
}

double Axis::ValueAt(double fi) const {
  double t;
  if (placement == Placement::kCenters) {
    t = (fi + 0.5) / size;
  } else {
    t = size == 1 ? 0.0 : fi / (size - 1);
  }
  if (warp == Warp::kTail) {
    // ln u linear in t between the ends; gamma = 1.5 + u / (1 - u), with
    // 1 - u = -expm1(ln u) exact as u -> 1 (gamma -> inf).
    auto log_u = [](double g) { return std::isinf(g) ? 0.0 : std::log((g - 1.5) / (g - 0.5)); };
    const double lu = (1 - t) * log_u(min) + t * log_u(max);
    if (lu >= 0) return kInfinity;
    return 1.5 + std::exp(lu) / -std::expm1(lu);
  }
  if (warp == Warp::kFresnelZ) {
    // z = sqrt(|ior - 1| / (ior + 1)) linear in t; the axis lies on one
    // side of 1 (ValidateBakeSpec), where ior(z) is monotonic.
    if (t == 0) return min;
    if (t == 1) return max;
    const double z = (1 - t) * FresnelZOfIor(min) + t * FresnelZOfIor(max), z2 = z * z;
    return min >= 1 ? (1 + z2) / (1 - z2) : (1 - z2) / (1 + z2);
  }
  if (warp == Warp::kSchlickZ) {
    // z = 5 / (exponent + 5) linear in t (z = 0 is exponent = inf).
    if (t == 0) return min;
    if (t == 1) return max;
    const double z = (1 - t) * SchlickZOfExponent(min) + t * SchlickZOfExponent(max);
    return z > 0 ? 5 * (1 - z) / z : kInfinity;
  }
  if (warp == Warp::kTwoSided) {
    // The fractional index u (edges, N = 2H): 1 / eta linear from 1 / min
    // at u = 0 to 1 at H - 1, eta linear from 1 at H to max at N - 1.
    const double u = placement == Placement::kEdges ? fi : t * (size - 1);
    const double h = size / 2;
    if (u <= h - 1) return 1 / (1 + (1 / min - 1) * ((h - 1 - u) / (h - 1)));
    if (u >= h) return 1 + (max - 1) * ((u - h) / (h - 1));
    return 1;
  }
  double w = t;
  if (warp == Warp::kSquare) w = t * t;
  if (warp == Warp::kSqrt) w = std::sqrt(t);
  if (warp == Warp::kOneMinusSquare) w = t * (2 - t);  // 1 - (1 - t)^2, exact at both ends
  return min + (max - min) * w;
}

std::string Axis::ToJson() const {
  nlohmann::json j;
  j["name"] = name;
  j["size"] = size;
  auto number = [](double v) { return std::isinf(v) ? nlohmann::json("inf") : nlohmann::json(v); };
  j["min"] = number(min);
  j["max"] = number(max);
  j["warp"] = WarpName(warp);
  j["placement"] = PlacementName(placement);
  if (clamp_min > 0) j["clamp_min"] = clamp_min;
  if (clamp_max < kInfinity) j["clamp_max"] = clamp_max;
  // The warps that are not a power of t state their map and list every
  // entry's value.
  const char* map = nullptr;
  switch (warp) {
    case Warp::kTail:
      map =
          "u = (gamma - 1.5) / (gamma - 0.5) with ln u = (1 - t) ln u(min) + t ln u(max), "
          "gamma = 1.5 + u / (1 - u); u = 1 is gamma = inf";
      break;
    case Warp::kSchlickZ:
      map =
          "z = 5 / (exponent + 5) with z = (1 - t) z(min) + t z(max), exponent = 5 (1 - z) / z; "
          "z = 0 is exponent = inf";
      break;
    case Warp::kTwoSided:
      map =
          "index i of N = 2H entries (edges): i < H, 1 / ior = 1 + (1 / min - 1) (H - 1 - i) / (H - 1); "
          "i >= H, ior = 1 + (max - 1) (i - H) / (H - 1); ior < 1 is the view inside the denser medium";
      break;
    case Warp::kFresnelZ:
      map =
          "z = sqrt(|ior - 1| / (ior + 1)) (= F0^(1/4)) with z = (1 - t) z(min) + t z(max), "
          "ior = (1 + z^2) / (1 - z^2)";
      break;
    case Warp::kLinear:
    case Warp::kSquare:
    case Warp::kSqrt:
    case Warp::kOneMinusSquare: break;
  }
  if (map) {
    j["map"] = map;
    nlohmann::json values = nlohmann::json::array();
    for (int i = 0; i < size; ++i) values.push_back(number(Value(i)));
    j["values"] = values;
  }
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

const char* MeaningName(Meaning m) {
  switch (m) {
    case Meaning::kE: return "E";
    case Meaning::kOneMinusE: return "1-E";
    case Meaning::kEavg: return "E_avg";
    case Meaning::kOneMinusEavg: return "1-E_avg";
    case Meaning::kDfgScale: return "dfg.scale";
    case Meaning::kDfgBias: return "dfg.bias";
    case Meaning::kSelIntegral: return "sel.integral";
    case Meaning::kSelRatio: return "sel.ratio";
    case Meaning::kS: return "s";
    case Meaning::kF82Bias: return "f82_bias";
    case Meaning::kError: return "error";
  }
  return "E";
}

namespace {

// The baker row of the spec's model; a model this build does not contain
// is refused with ValidateModelParams' message (its family's row would
// say its axes).
const BakerRow& BuiltRow(const BakeSpec& spec) {
  const BakerRow* row = BakerRowOf(spec.model.kind);
  if (!row) {
    ValidateModelParams(spec.model);
    Bad("{model}: " + std::string(spec.model.name()) + " is not in this build");
  }
  return *row;
}

// The table's axes, fastest first (S: BakeSpec or const BakeSpec).
template <class S>
auto AxesOf(S& spec) {
  using A = std::remove_pointer_t<decltype(&spec.mu)>;  // Axis or const Axis
  const bool eavg = spec.table == TableKind::kEavg;
  const BakerRow& row = BuiltRow(spec);
  if (spec.table == TableKind::kSelNorm) return std::vector<A*>{&spec.alpha_x, &spec.alpha_y};
  std::vector<A*> axes;
  if (row.own_axes) {
    for (Axis BakeSpec::*a : row.own_axes(spec).axes) axes.push_back(&(spec.*a));
    return axes;
  }
  if (!eavg) axes.push_back(&spec.mu);
  axes.push_back(&spec.roughness);
  if (spec.table == TableKind::kGenSchlickS) {
    axes.push_back(&spec.exponent);
  } else if (spec.table == TableKind::kGenSchlickIorS) {
    axes.push_back(&spec.ior);
  } else if (spec.HasGammaAxis()) {
    axes.push_back(&spec.gamma);
  }
  return axes;
}

const char* Definition(Meaning meaning, const BakeSpec& spec) {
  if (meaning == Meaning::kS && spec.table == TableKind::kGenSchlickS) {
    return "s(mu) = integral D_wo(h) (1 - wo.h)^exponent 1{r.z > 0} dh over the visible normals h of a GGX "
           "reflection lobe (r the reflection): the generalized Schlick Fresnel is mix(F0, F90, s); no masking weight";
  }
  if (meaning == Meaning::kF82Bias) {
    return spec.masking == Masking::kSeparable
               ? "b(mu) = integral of (f / F) b(wo.h) cos(theta_i) dwi, b(c) = c (1 - c)^6 ([Hoffman19]'s F82 "
                 "tint: F = F0 scale + F90 bias - F82_tint b), GGX with separable masking"
               : "b(mu) = integral of (f / F) b(wo.h) cos(theta_i) dwi, b(c) = c (1 - c)^6 ([Hoffman19]'s F82 "
                 "tint: F = F0 scale + F90 bias - F82_tint b), GGX with height-correlated masking";
  }
  if (meaning == Meaning::kS) {
    return "s(mu) = integral D_wo(h) clamp((F(ior, wo.h) - F0) / (1 - F0), 0, 1) 1{r.z > 0} dh over the "
           "visible normals h of a GGX reflection lobe, F the exact dielectric Fresnel, F0 = ((ior - 1) / "
           "(ior + 1))^2: the dielectric Fresnel is mix(F0, 1, s); no masking weight";
  }
  if (meaning == Meaning::kE) {
    const BakerRow* row = BakerRowOf(spec.model.kind);
    if (row && row->e_definition) return row->e_definition(spec);
  }
  if (meaning == Meaning::kE) return "directional albedo E(mu) = integral of f cos(theta_i) dwi with F = 1";
  if (meaning == Meaning::kOneMinusE) return "1 - E(mu), computed in double before rounding";
  if (meaning == Meaning::kEavg) return "average albedo E_avg = 2 integral_0^1 E(mu) mu dmu";
  if (meaning == Meaning::kOneMinusEavg) return "1 - E_avg, computed in double before rounding";
  if (meaning == Meaning::kSelIntegral) {
    return "N = integral over the sphere of the squared ellipsoidal lobe K ([TokuyoshiHarada]); K / N "
           "integrates to 1; independent of the lobe's rotation";
  }
  if (meaning == Meaning::kSelRatio) return "N / (4 pi alpha_x alpha_y): 1 for alpha_x = alpha_y";
  if (meaning == Meaning::kDfgScale) {
    return "integral of (f/F) (1 - Fc) cos(theta_i) dwi, Fc = (1 - wo.h)^5 (Schlick weight); "
           "the specular albedo is F0 scale + F90 bias";
  }
  if (meaning == Meaning::kDfgBias) {
    return "integral of (f/F) Fc cos(theta_i) dwi, Fc = (1 - wo.h)^5 (Schlick weight); "
           "the specular albedo is F0 scale + F90 bias";
  }
  return "the integrator's estimate of the absolute error of this texel before storage";
}

}  // namespace

std::vector<Axis*> TableAxes(BakeSpec* spec) { return AxesOf(*spec); }

bool TableHasAxis(const BakeSpec& spec, const std::string& name) {
  const std::vector<const Axis*> axes = AxesOf(spec);
  return std::any_of(axes.begin(), axes.end(), [&](const Axis* a) { return a->name == name; });
}

bool ParameterAxis(const Axis& axis) { return axis.name == "gamma" || axis.name == "ior" || axis.name == "exponent"; }

TableShape ShapeOf(const BakeSpec& spec) {
  TableShape s;
  for (const Axis* a : AxesOf(spec)) s.axes.push_back(*a);
  for (size_t i = 0; i < s.axes.size(); ++i) (i == 0 ? s.width : s.height) *= s.axes[i].size;
  std::vector<Meaning> meanings;
  switch (spec.table) {
    case TableKind::kE: meanings = {spec.complement ? Meaning::kOneMinusE : Meaning::kE}; break;
    case TableKind::kEavg: meanings = {spec.complement ? Meaning::kOneMinusEavg : Meaning::kEavg}; break;
    case TableKind::kDfg:
      meanings = {Meaning::kDfgScale, Meaning::kDfgBias};
      if (spec.complement) meanings.push_back(Meaning::kOneMinusE);
      break;
    case TableKind::kSelNorm: meanings = {Meaning::kSelIntegral, Meaning::kSelRatio}; break;
    case TableKind::kGenSchlickS:
    case TableKind::kGenSchlickIorS: meanings = {Meaning::kS}; break;
    case TableKind::kF82Bias: meanings = {Meaning::kF82Bias}; break;
  }
  s.value_channels = int(meanings.size());
  if (spec.error_channel) meanings.push_back(Meaning::kError);
  // dfg and sel_norm name their channels in a layer, numbered in order:
  // dfg.0_scale, dfg.1_bias, dfg.2_1-E, dfg.N_error; the error channel of
  // the others is "error".
  const char* layer = spec.table == TableKind::kDfg ? "dfg." : spec.table == TableKind::kSelNorm ? "sel." : nullptr;
  for (size_t c = 0; c < meanings.size(); ++c) {
    std::string name = MeaningName(meanings[c]);
    if (layer) {
      const std::string m = name;
      const size_t dot = m.find('.');
      name = layer + std::to_string(c) + "_" + (dot == std::string::npos ? m : m.substr(dot + 1));
    }
    s.channels.push_back({name, meanings[c], Definition(meanings[c], spec)});
  }
  return s;
}

std::vector<int> DefaultSizes(const BakeSpec& spec) {
  const bool eavg = spec.table == TableKind::kEavg;
  if (spec.GenSchlick()) return {16, 16, 16};
  const BakerRow& row = BuiltRow(spec);
  if (row.own_axes && spec.table != TableKind::kSelNorm) return row.own_axes(spec).sizes;
  std::vector<int> sizes(eavg ? 1 : 2, 32);
  if (spec.table != TableKind::kSelNorm && spec.HasGammaAxis()) sizes.push_back(spec.gamma.size);
  return sizes;
}

std::string SizeForm(const BakeSpec& spec) {
  const bool eavg = spec.table == TableKind::kEavg;
  if (spec.table == TableKind::kSelNorm) return "WxH (alpha_x x alpha_y, e.g. 32x32)";
  if (spec.table == TableKind::kGenSchlickS) return "WxHxD (mu x roughness x exponent, e.g. 16x16x16)";
  if (spec.table == TableKind::kGenSchlickIorS) return "WxHxD (mu x roughness x ior, e.g. 16x16x16)";
  const BakerRow& row = BuiltRow(spec);
  if (row.own_axes) return row.own_axes(spec).form;
  if (spec.HasGammaAxis()) {
    return eavg ? "NxD (roughness x gamma, e.g. 32x16)" : "WxHxD (mu x roughness x gamma, e.g. 32x32x16)";
  }
  return eavg ? "N (roughness, e.g. 32)" : "WxH (mu x roughness, e.g. 32x32)";
}

namespace {

// "only std", "only a and b": this build's models taking `option` (or "no
// model of this build"), for a message on a setting of theirs.
std::string OnlyModelsTaking(ModelOption option) {
  const std::vector<std::string> names = ModelsTaking(option);
  return names.empty() ? "no model of this build" : "only " + JoinList(names, " and ");
}

// Every axis: 1 to 8192 entries, at least 2 with edges placement.
void CheckAxisSize(const Axis& a) {
  if (a.size < 1 || a.size > 8192) Bad("{size}: each axis must have 1 to 8192 entries");
  if (a.placement == Placement::kEdges && a.size < 2) Bad("{size}: edges placement needs at least 2 entries per axis");
}
}  // namespace

std::vector<IntegratorKind> TableIntegrators(const BakeSpec& spec) {
  const BakerRow* row = BakerRowOf(spec.model.kind);
  if (RowOf(spec.table).quadrature_only || (row && row->quadrature_only)) return {IntegratorKind::kQuadrature};
  return {IntegratorKind::kQuadrature, IntegratorKind::kQmc, IntegratorKind::kMc, IntegratorKind::kEngine};
}

bool ModelBakes(ModelKind model, TableKind table) {
  const BakerRow* row = BakerRowOf(model);
  return row && (row->tables & Bit(table)) != 0;
}

std::vector<std::string> ModelsBaking(TableKind table) {
  std::vector<std::string> names;
  for (const ModelKind m : ModelKindsBuilt()) {
    if (ModelBakes(m, table)) names.push_back(ModelName(m));
  }
  return names;
}

bool ModelTakesMasking(ModelKind model) {
  const BakerRow* row = BakerRowOf(model);
  return row && row->masking;
}

void ValidateBakeSpec(const BakeSpec& spec) {
  const BakerRow* row = BakerRowOf(spec.model.kind);
  ModelParams params = spec.model;
  if (row && row->checked_as) row->checked_as(&params);
  ValidateModelParams(params);
  const ModelKind m = spec.model.kind;
  // A dielectric interface (the models taking an ior): light on either
  // side of it, and its lobes apart.
  const bool dielectric = ModelTakes(m, ModelOption::kIor);
  if (spec.inverse && !dielectric) {
    Bad("{inverse}: " + OnlyModelsTaking(ModelOption::kIor) + " has an inside (light leaving the medium)");
  }
  const KindRow& kind = RowOf(spec.table);
  if (kind.term) {
    if (m != kind.model) {
      Bad(std::string("{model}: ") + kind.name + " is " + kind.term + " (give {model} " + ModelName(kind.model) +
          "; got '" + spec.model.name() + "')");
    }
    if (spec.complement) Bad(std::string("{complement}: ") + kind.name + " stores " + kind.stores);
  }
  if (!ModelBakes(m, spec.table)) {
    Bad(std::string("{table}: ") + spec.model.name() + " bakes " + BakerRowOf(m)->bakes);
  }
  if (spec.part != DielectricPart::kBoth && !dielectric) {
    Bad("{part}: " + OnlyModelsTaking(ModelOption::kIor) + " has reflection and refraction parts (got {part} " +
        std::string(DielectricPartName(spec.part)) + ")");
  }
  const double phi_max = row->own_axes ? row->own_axes(spec).phi_max : kHalfPi;
  const std::vector<IntegratorKind> integrators = TableIntegrators(spec);
  if (std::find(integrators.begin(), integrators.end(), spec.integrator) == integrators.end()) {
    Bad("{integrator}: " +
        std::string(kind.quadrature_only ? kind.name : spec.model.name()) +
        " tables are baked with the quadrature only (got " + IntegratorName(spec.integrator) + ")");
  }
  // The view and lobe axes here; the parameter axes below.
  const std::vector<const Axis*> axes = AxesOf(spec);
  for (const Axis* a : axes) {
    if (ParameterAxis(*a)) continue;
    if (a->warp == Warp::kTail)
      Bad("{warp}: tail is the gamma axis's warp (the " + a->name + " axis takes linear, square, sqrt or one-minus-square)");
    if (a->warp == Warp::kFresnelZ || a->warp == Warp::kSchlickZ) {
      Bad("{warp}: " + std::string(WarpName(a->warp)) + " is the " + (a->warp == Warp::kFresnelZ ? "ior" : "exponent") +
          " axis's warp (the " + a->name + " axis takes linear, square, sqrt or one-minus-square)");
    }
    CheckAxisSize(*a);
    // One entry may sit at one value (min = max), as the report's probes do.
    const bool ordered = a->size == 1 ? a->min <= a->max : a->min < a->max;
    if (!(a->clamp_min >= 0 && a->clamp_min <= 1)) Bad("the " + a->name + " axis clamp must lie in [0, 1]");
    const bool angle = a->name == "phi_o";
    const double upper = angle ? phi_max : 1.0;
    if (!std::isfinite(a->min) || !std::isfinite(a->max) || !ordered || a->min < 0 || a->max > upper * (1 + 1e-15)) {
      std::ostringstream os;
      os << "{range}: the " << a->name
         << " axis must satisfy 0 <= min < max <= "
         << (angle ? (phi_max > kHalfPi ? "2 pi (radians)" : "pi/2 (radians)") : "1")
         << " (got " << a->min << ":" << a->max << ")";
      Bad(os.str());
    }
  }
  if (spec.HasGammaAxis()) {
    const Axis& g = spec.gamma;
    if (!ModelTakes(m, ModelOption::kGamma)) {
      Bad("{size}: " + OnlyModelsTaking(ModelOption::kGamma) + " has a gamma axis (got model '" +
          std::string(spec.model.name()) + "')");
    }
    CheckAxisSize(g);
    if (g.warp != Warp::kTail) Bad("{warp}: the gamma axis takes the tail warp only");
    const bool ordered = g.size == 1 ? g.min <= g.max : g.min < g.max;
    if (std::isnan(g.max) || !StudentTGammaAllowed(g.min) || std::isinf(g.min) || !ordered) {
      Bad("{range}: the gamma axis must satisfy " + ExactText(kMinStudentTGamma<double>) +
          " <= min < max <= inf (the STD's mean slope diverges at 1.5; got " + ExactText(g.min) + ":" +
          ExactText(g.max) + ")");
    }
  }
  if (spec.table == TableKind::kGenSchlickS) {
    const Axis& a = spec.exponent;
    CheckAxisSize(a);
    if (a.warp != Warp::kSchlickZ && a.warp != Warp::kLinear) {
      Bad("{warp}: the exponent axis takes schlick-z (z = 5 / (exponent + 5), the default) or linear (got " +
          std::string(WarpName(a.warp)) + ")");
    }
    // Either direction with schlick-z (Cycles' runs from inf down to 0);
    // every value baked must be finite: inf needs a clamp.
    const bool ordered = a.size == 1 || a.min != a.max;
    const bool increasing = a.warp == Warp::kLinear ? a.min < a.max || a.size == 1 : true;
    const bool finite = std::isfinite(std::min(std::max(a.min, a.max), a.clamp_max));
    if (!(a.min >= 0) || !(a.max >= 0) || !ordered || !increasing || !finite ||
        !(a.clamp_min >= 0 && a.clamp_min <= a.clamp_max)) {
      Bad("{range}: the exponent axis must satisfy 0 <= min, max <= inf, min != max (inf with the "
          "schlick-z warp and a clamp; got " +
          ExactText(a.min) + ":" + ExactText(a.max) + ")");
    }
  }
  if (std::any_of(axes.begin(), axes.end(), [](const Axis* a) { return a->name == "ior"; })) {
    const Axis& a = spec.ior;
    CheckAxisSize(a);
    if (a.warp != Warp::kFresnelZ && a.warp != Warp::kLinear && a.warp != Warp::kTwoSided) {
      Bad("{warp}: the ior axis takes fresnel-z (z = F0^(1/4), the default), linear or two-sided (got " +
          std::string(WarpName(a.warp)) + ")");
    }
    if (a.warp == Warp::kTwoSided) {
      if (a.placement != Placement::kEdges || a.size < 4 || a.size % 2 != 0) {
        Bad("{size}: a two-sided ior axis has edges placement and an even size of at least 4 (got " +
            std::to_string(a.size) + ", " + PlacementName(a.placement) + ")");
      }
      if (!(a.min >= 1 / kMaxFresnelIndex && a.min < 1) || !(a.max > 1 && a.max <= kMaxFresnelIndex)) {
        Bad("{range}: a two-sided ior axis must satisfy 0.01 <= min < 1 < max <= 100 (got " + ExactText(a.min) + ":" +
            ExactText(a.max) + ")");
      }
      if (spec.inverse) Bad("{inverse}: a two-sided ior axis holds both sides already");
    }
    const bool ordered = a.size == 1 ? a.min <= a.max : a.min < a.max;
    // The axis may end at ior = inf (z = 1, as Cycles' tables do) when a
    // clamp of at most 100 bakes its last slices; a two-sided axis holds
    // both sides of the interface.
    // The Schlick-weighted refraction has no Fresnel factor: its axis may
    // reach ior = inf unclamped (t = -h there).
    const bool schlick = spec.part == DielectricPart::kTransmissionSchlick;
    if (schlick && (spec.inverse || a.warp == Warp::kTwoSided)) {
      Bad("{part} transmission-schlick: light entering the medium only, ior >= 1 (no {inverse}, no two-sided "
          "axis)");
    }
    const double top = schlick ? 1.0 : std::min(a.max, a.clamp_max);
    if (a.warp != Warp::kTwoSided &&
        (!(a.min >= 1) || !(top <= kMaxFresnelIndex) || !ordered || !(a.min <= a.clamp_max))) {
      Bad("{range}: the ior axis must satisfy 1 <= min < max <= 100 (light leaving the medium, "
          "eta = 1/ior: {inverse}; got " +
          ExactText(a.min) + ":" + ExactText(a.max) + ")");
    }
    if (std::isinf(a.max) && a.warp != Warp::kFresnelZ) Bad("{range}: an ior axis to inf needs the fresnel-z warp");
    if (spec.table == TableKind::kGenSchlickIorS && a.warp == Warp::kTwoSided) {
      Bad("{warp}: gen_schlick_ior_s is over ior >= 1 (the dielectric shape outside the medium): no two-sided axis");
    }
  }
  if (spec.samples < 0 || spec.samples > 1 << 24) Bad("{samples} must be in [1, 16777216]");
  if (spec.integrator == IntegratorKind::kQuadrature && spec.samples > 4096) {
    Bad("{samples}: the quadrature takes at most 4096 nodes per dimension");
  }
  if (spec.integrator == IntegratorKind::kQmc && spec.samples != 0 && spec.samples < 16) {
    Bad("{samples}: qmc needs at least 16 samples (8 replicas of 2)");
  }
  if (spec.threads < 0 || spec.threads > kMaxThreads) {
    Bad("{threads} must be in [0, " + std::to_string(kMaxThreads) + "] (0 = all cores)");
  }
  if (!(spec.tolerance >= 0) || !std::isfinite(spec.tolerance)) Bad("{tolerance} must be a finite number >= 0");
  // A table is one image of int width and height (a 3D or 4D table stacks
  // its slices): at most 2^31 - 1 texels.
  const int64_t texels = ShapeOf(spec).Texels();
  if (texels > int64_t(std::numeric_limits<int>::max())) {
    Bad("{size}: " + std::to_string(texels) + " texels exceed the 2147483647 a table holds");
  }
}

const char* const kStoredRange =
    "E, 1-E, E_avg and 1-E_avg clamped to [0, 1] (charlie and disney-diffuse: E and E_avg "
    "clamped to >= 0 only, neither lobe conserves energy); dfg.scale and dfg.bias clamped to >= 0 with "
    "scale + bias <= 1 in the stored precision; brdfbake.max_abs_error covers the clamp and the "
    "rounding to the pixel type";

const char* const kLayoutText =
    "axes fastest first: x = columns, then y = rows, then slices (a 3D table stores its 2D "
    "slices stacked vertically); row 0 is the first row of the data window; channels in the "
    "order of brdfbake.channel_order; axis i of size N: t = (i + 0.5) / N (centers) or "
    "t = i / (N - 1) (edges), value = min + (max - min) w(t), w(t) = t (linear), t^2 (square), sqrt(t) (sqrt)";

size_t BakeOutputBytes(const BakeSpec& spec) {
  const TableShape shape = ShapeOf(spec);
  const size_t n = size_t(shape.Texels());
  const size_t channels = shape.channels.size();
  // values (double), stored (float) and half bits per channel, plus the
  // error vector.
  const size_t half = spec.half ? sizeof(uint16_t) : 0;
  return n * (channels * (sizeof(double) + sizeof(float) + half) + sizeof(double));
}

int64_t BakeOutputValues(const BakeSpec& spec) {
  const TableShape shape = ShapeOf(spec);
  return shape.Texels() * int64_t(shape.channels.size());
}

}  // namespace brdfbake
