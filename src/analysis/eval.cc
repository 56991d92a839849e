// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/eval.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/model.h"

namespace brdfbake {
namespace {

std::string Fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

}  // namespace

const std::vector<std::string>& EvalQuantities() {
  static const std::vector<std::string> kQ = {"D",       "Lambda", "G1",  "G2",    "brdf",          "pdf",
                                              "K",       "E",      "dfg", "E_avg", "gen_schlick_s", "gen_schlick_ior_s",
                                              "f82_bias"};
  return kQ;
}

namespace {

bool IsGenSchlick(const std::string& q) { return q == "gen_schlick_s" || q == "gen_schlick_ior_s"; }

// A table model (ggx-aniso, ggx-glass): a model kind of this build that is
// no family of Models(), with table quantities and no pointwise Model.
bool IsTableModel(ModelKind kind) {
  const std::vector<ModelInfo>& families = Models();
  return std::none_of(families.begin(), families.end(), [&](const ModelInfo& m) { return m.kind == kind; });
}

// Whether `kind`'s E table lies over a material's own widths and angles
// (the ellipsoid's mu x phi_o) rather than over the roughness.
bool TablesOverOwnWidths(ModelKind kind) {
  BakeSpec spec;
  spec.model.kind = kind;
  spec.table = TableKind::kE;
  return !TableHasAxis(spec, "roughness");
}

// The names of this build's models with the lobe quantity K (sel).
std::vector<std::string> ModelsWithK() {
  std::vector<std::string> names;
  for (const ModelKind m : ModelKindsBuilt()) {
    if (BatchSupports(m, Quantity::kK)) names.push_back(ModelName(m));
  }
  return names;
}
// The GGX lobe's Fresnel-shape tables: one value per view and roughness.
bool IsFresnelShape(const std::string& q) { return IsGenSchlick(q) || q == "f82_bias"; }

}  // namespace

bool IsTableQuantity(const std::string& q) { return q == "E" || q == "dfg" || q == "E_avg" || IsFresnelShape(q); }

void ValidateEvalRequest(const EvalRequest& req) {
  const bool aniso = req.model.kind == ModelKind::kGgxAniso;
  ModelParams params = req.model;
  if (aniso) params.kind = ModelKind::kGgx;  // the widths come from roughness and anisotropy
  bool tables_only = !req.quantities.empty();
  for (const std::string& q : req.quantities) tables_only &= IsTableQuantity(q);
  // Roughness 0 is the tables' mirror (E = 1): the table quantities take it.
  if (tables_only && params.alpha_x == 0 && params.alpha_y == 0) params.alpha_x = params.alpha_y = 1.0;
  ValidateModelParams(params);
  if (aniso && !(req.anisotropy >= 0 && req.anisotropy <= 1)) {
    Bad("{anisotropy} must lie in [0, 1] (the KHR_materials_anisotropy strength)");
  }
  if (!aniso && req.anisotropy != 0) Bad("{anisotropy} applies to {model} ggx-aniso only");
  if (req.quantities.empty()) Bad("{quantity}: at least one quantity is required");
  for (const std::string& q : req.quantities) {
    bool ok = false;
    for (const std::string& k : EvalQuantities()) ok |= q == k;
    if (!ok) {
      Bad("{quantity}: unknown quantity '" + q +
          "' (expected D, Lambda, G1, G2, brdf, pdf, K, E, dfg, E_avg, gen_schlick_s, gen_schlick_ior_s or "
          "f82_bias)");
    }
    // The models with a table of the quantity (ModelBakes).
    if (IsTableQuantity(q) && !ModelBakes(req.model.kind, ParseTable(q))) {
      Bad("{quantity}: " + q + " is baked for " + JoinList(ModelsBaking(ParseTable(q)), " and ") + " only (got '" +
          std::string(req.model.name()) + "')");
    }
    if (IsFresnelShape(q)) {
      if (q == "gen_schlick_s" && !(req.exponent >= 0)) {
        Bad("{exponent} must be >= 0 or inf (s_h = (1 - wo.h)^exponent; got " + ExactText(req.exponent) + ")");
      }
      if (q == "gen_schlick_ior_s" && !(req.model.ior >= 1 && req.model.ior <= kMaxFresnelIndex)) {
        Bad("{ior}: gen_schlick_ior_s takes the dielectric shape at an ior in [1, 100] (got " +
            ExactText(req.model.ior) + ")");
      }
    }
    const bool table_sweep = req.sweep == "roughness" || req.sweep == "none";
    if (IsTableQuantity(q)) {
      if (TablesOverOwnWidths(req.model.kind)) continue;
      if (req.model.alpha_x != req.model.alpha_y) {
        Bad("{quantity}: " + q + " is tabulated for isotropic models: give {alpha} or {roughness}, "
            "not {alpha_x}/{alpha_y}");
      }
      if (std::sqrt(req.model.alpha_x) > 1) {
        Bad("{quantity}: " + q + " is tabulated for roughness in [0, 1] (alpha <= 1)");
      }
      continue;
    }
    if (IsTableModel(req.model.kind)) {
      Bad("{quantity}: " + std::string(req.model.name()) + " has the table quantities E and E_avg only (got '" + q + "')");
    }
    if (table_sweep) {
      Bad("{sweep} " + req.sweep + ": only E, dfg and E_avg can be evaluated without a swept "
          "direction (got '" + q + "')");
    }
    const bool lobe = BatchSupports(req.model.kind, Quantity::kK);
    if (lobe != (q == "K")) {
      Bad(lobe ? "{quantity}: model " + std::string(req.model.name()) + " has only the quantity K"
               : "{quantity}: K is defined for model " + JoinList(ModelsWithK(), " and ") + " only");
    }
  }
  if (req.count < 1 || req.count > 10000000) Bad("{count} must be in [1, 10000000]");
  if (!std::isfinite(req.from) || !std::isfinite(req.to)) Bad("{from}/{to} must be finite");
  if (req.sweep == "mu") {
    if (req.from < -1 || req.from > 1 || req.to < -1 || req.to > 1) {
      Bad("{from}/{to} must lie in [-1, 1] for {sweep} mu");
    }
  } else if (req.sweep == "theta") {
    if (req.from < 0 || req.from > 180 || req.to < 0 || req.to > 180) {
      Bad("{from}/{to} must lie in [0, 180] degrees for {sweep} theta");
    }
  } else if (req.sweep == "roughness") {
    if (req.from < 0 || req.from > 1 || req.to < 0 || req.to > 1) {
      Bad("{from}/{to} must lie in [0, 1] for {sweep} roughness");
    }
  } else if (req.sweep != "none") {
    Bad("{sweep}: unknown sweep '" + req.sweep + "' (expected mu, theta, roughness or none)");
  }
  if (!std::isfinite(req.mu_o) || req.mu_o < 0 || req.mu_o > 1) Bad("{mu_o} must lie in [0, 1]");
  if (!std::isfinite(req.phi_o) || !std::isfinite(req.phi)) Bad("{phi}/{phi_o} must be finite");
  ValidateFresnel(req.fresnel);
}

namespace {

// E, dfg and E_avg at (mu, roughness), through the bake's integrator.
std::string TableQuantityColumns(const EvalRequest& req, const std::string& q, double mu,
                                 double roughness) {
  BakeSpec spec;
  spec.model = req.model;
  // The tables take alpha from `roughness` (0 is their mirror): the model's
  // own widths only stand in.
  const bool own_widths = TablesOverOwnWidths(spec.model.kind);
  if (!own_widths && spec.model.alpha_x == 0) {
    spec.model.alpha_x = spec.model.alpha_y = 1.0;
  }
  spec.masking = req.masking;
  if (own_widths) {
    // The material's E at the view (mu, --phi-o), or its E_avg.
    spec.table = q == "E_avg" ? TableKind::kEavg : TableKind::kE;
    if (q == "E_avg") {
      spec.mu.size = 2;  // unused: E_avg has no axes
      const Table t = Bake(spec);
      return "," + Fmt(t.channels[0].values[0]) + "," + Fmt(t.integration_error);
    }
    spec.mu.size = spec.phi.size = 1;
    spec.mu.placement = spec.phi.placement = Placement::kCenters;
    spec.mu.min = spec.mu.max = std::clamp(mu, 0.0, 1.0);
    spec.phi.min = spec.phi.max = std::fmod(std::fmod(req.phi_o, 2 * kPi<double>) + 2 * kPi<double>,
                                            2 * kPi<double>);
    const Table t = Bake(spec);
    return "," + Fmt(t.channels[0].values[0]) + "," + Fmt(t.integration_error);
  }
  if (spec.Anisotropic()) {
    if (q == "E_avg") {
      const EavgEstimate e = IntegrateAnisoEavg(spec, roughness, req.anisotropy);
      return "," + Fmt(std::clamp(e.value, 0.0, 1.0)) + "," + Fmt(e.error);
    }
    const TexelEstimate v =
        IntegrateAnisoTexel(spec, roughness, req.anisotropy, std::clamp(mu, 0.0, 1.0), req.phi_o);
    return "," + Fmt(std::clamp(v.e, 0.0, 1.0)) + "," + Fmt(v.err_e);
  }
  if (q == "E_avg") {
    const EavgEstimate e = IntegrateEavg(spec, roughness);
    return "," + Fmt(std::clamp(e.value, 0.0, StoredEMax(spec))) + "," + Fmt(e.error);
  }
  if (IsFresnelShape(q)) {
    spec.table = ParseTable(q);
    if (IsGenSchlick(q)) {
      // One slice of the table: its third axis at the one value asked
      // for (clamped as the bake clamps it).
      const bool exponent = spec.table == TableKind::kGenSchlickS;
      Axis& slice = exponent ? spec.exponent : spec.ior;
      slice.size = 1;
      slice.placement = Placement::kCenters;
      slice.min = slice.max = exponent ? req.exponent : req.model.ior;
    }
    // One value in e, stored as the bake stores it.
    const TexelEstimate v = IntegrateTexel(spec, roughness, std::clamp(mu, 0.0, 1.0));
    return "," + Fmt(std::clamp(v.e, 0.0, StoredEMax(spec))) + "," + Fmt(v.err_e);
  }
  spec.table = q == "E" ? TableKind::kE : TableKind::kDfg;
  const TexelEstimate v =
      ClampToRange(IntegrateTexel(spec, roughness, std::clamp(mu, 0.0, 1.0)), StoredEMax(spec));
  if (q == "E") return "," + Fmt(v.e) + "," + Fmt(v.err_e);
  return "," + Fmt(v.scale) + "," + Fmt(v.bias) + "," + Fmt(std::max(v.err_scale, v.err_bias));
}

}  // namespace

void EvalCsv(const EvalRequest& req, std::ostream& out) {
  ValidateEvalRequest(req);
  const bool table_sweep = req.sweep == "roughness" || req.sweep == "none";
  // A table model (ggx-aniso, ggx-glass) has no pointwise Model.
  const std::unique_ptr<Model> model = IsTableModel(req.model.kind) || table_sweep ? nullptr : MakeModel(req.model);
  const Vec3<double> wo = FromMuPhi(req.mu_o, req.phi_o);
  const bool grey = req.fresnel.IsGrey();

  std::ostringstream header;
  header << (req.sweep == "roughness" ? "roughness,mu" : req.sweep == "none" ? "mu,roughness"
                                                                              : "mu,theta_deg");
  for (const std::string& q : req.quantities) {
    if (q == "E") {
      header << ",E,E_error";
    } else if (q == "dfg") {
      header << ",dfg_scale,dfg_bias,dfg_error";
    } else if (q == "E_avg") {
      header << ",E_avg,E_avg_error";
    } else if (IsFresnelShape(q)) {
      header << "," << q << "," << q << "_error";
    } else if (q == "brdf" && !grey) {
      header << ",brdf_r,brdf_g,brdf_b";
    } else {
      header << "," << q;
    }
  }
  out << header.str() << "\n";

  const double model_roughness = std::sqrt(req.model.alpha_x);
  if (table_sweep) {
    const int count = req.sweep == "none" ? 1 : req.count;
    for (int i = 0; i < count; ++i) {
      const double t = count == 1 ? 0.0 : static_cast<double>(i) / (count - 1);
      const double r = req.sweep == "none" ? model_roughness : req.from + (req.to - req.from) * t;
      std::string row = req.sweep == "none" ? Fmt(req.mu_o) + "," + Fmt(r)
                                            : Fmt(r) + "," + Fmt(req.mu_o);
      for (const std::string& q : req.quantities) row += TableQuantityColumns(req, q, req.mu_o, r);
      out << row << "\n";
    }
    return;
  }
  for (int i = 0; i < req.count; ++i) {
    const double t = req.count == 1 ? 0.0 : static_cast<double>(i) / (req.count - 1);
    const double s = req.from + (req.to - req.from) * t;
    double mu, theta_deg;
    if (req.sweep == "mu") {
      mu = s;
      theta_deg = std::acos(mu) * 180.0 / kPi<double>;
    } else {
      theta_deg = s;
      mu = std::cos(s * kPi<double> / 180.0);
    }
    const Vec3<double> w = FromMuPhi(mu, req.phi);
    std::string row = Fmt(mu) + "," + Fmt(theta_deg);
    for (const std::string& q : req.quantities) {
      if (q == "D") {
        row += "," + Fmt(model->D(w));
      } else if (q == "Lambda") {
        row += "," + Fmt(model->Lambda(w));
      } else if (q == "G1") {
        row += "," + Fmt(model->G1(w));
      } else if (q == "G2") {
        row += "," + Fmt(model->G2(w, wo, req.masking));
      } else if (q == "pdf") {
        row += "," + Fmt(model->Pdf(wo, w));
      } else if (q == "K") {
        row += "," + Fmt(model->K(w));
      } else if (IsTableQuantity(q)) {
        // The swept direction is the view.
        row += TableQuantityColumns(req, q, mu, model_roughness);
      } else if (q == "brdf") {
        const int channels = grey ? 1 : 3;
        for (int c = 0; c < channels; ++c) {
          row += "," + Fmt(model->Brdf(w, wo, req.fresnel, req.masking, c));
        }
      }
    }
    out << row << "\n";
  }
}

}  // namespace brdfbake
