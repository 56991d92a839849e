// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The run-time model registry (model.h) over the rows of this build's
// families (model_row.h): names, help, parameter checks, MakeModel.

#include "brdfbake/model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/models/std_ndf.h"
#include "kernels/model_row.h"

namespace brdfbake {

// The families of this build (model_families.inc, written by CMake from
// BRDFBAKE_MODELS), each defined in its src/kernels/batch_<family>.cc.
#define BRDFBAKE_FAMILY(f) extern const ModelFamily kFamily_##f;
#include "kernels/model_families.inc"
#undef BRDFBAKE_FAMILY

namespace {

void CheckAlpha(const char* name, double a) {
  if (!std::isfinite(a) || !(a > 0) || a > kMaxAlpha) {
    std::ostringstream os;
    os << name << " must lie in (0, " << kMaxAlpha << "] (got " << ExactText(a) << ")";
    Bad(os.str());
  }
}

void CheckAngle(const char* name, double t) {
  if (!std::isfinite(t) || std::abs(t) > 1.5707963267948966) {
    std::ostringstream os;
    os << name << " must be finite and within [-pi/2, pi/2] radians (got " << ExactText(t) << ")";
    Bad(os.str());
  }
}

constexpr const ModelFamily* kFamilies[] = {
#define BRDFBAKE_FAMILY(f) &kFamily_##f,
#include "kernels/model_families.inc"
#undef BRDFBAKE_FAMILY
};

// Every row of this build, family by family.
template <class F>
void ForEachRow(const F& f) {
  for (const ModelFamily* family : kFamilies) {
    for (int k = 0; k < family->count; ++k) f(family->rows[k]);
  }
}

}  // namespace

const ModelRow* RowOfModel(ModelKind kind) {
  const ModelRow* found = nullptr;
  ForEachRow([&](const ModelRow& r) {
    if (r.kind == kind) found = &r;
  });
  return found;
}

void CheckWidths(const ModelParams& p) {
  CheckAlpha("alpha_x", p.alpha_x);
  CheckAlpha("alpha_y", p.alpha_y);
}

void CheckAngles(const ModelParams& p) {
  CheckAngle("theta_x", p.theta_x);
  CheckAngle("theta_y", p.theta_y);
  CheckAngle("theta_z", p.theta_z);
}

void CheckNoFresnel(const char* model, const Fresnel& f) {
  if (f.kind != FresnelKind::kOne) {
    Bad(std::string("model ") + model + " has no Fresnel factor (F = 1); give no Fresnel");
  }
}

double Model::K(const Vec3<double>&) const {
  Bad("quantity K is defined for model sel only; model " + std::string(params().name()) + " has D, Lambda, G1, G2, brdf, pdf");
}

std::string ModelParams::ToJson() const {
  nlohmann::json j;
  j["name"] = name();
  j["alpha_x"] = alpha_x;
  j["alpha_y"] = alpha_y;
  if (ModelTakes(kind, ModelOption::kGamma)) {
    if (std::isinf(gamma)) j["gamma"] = "inf"; else j["gamma"] = gamma;
  }
  if (ModelTakes(kind, ModelOption::kVisibility)) j["visibility"] = SheenVisibilityName(visibility);
  if (ModelTakes(kind, ModelOption::kIor)) j["ior"] = ior;
  if (ModelTakes(kind, ModelOption::kRotation)) {
    j["theta_x"] = theta_x;
    j["theta_y"] = theta_y;
    j["theta_z"] = theta_z;
  }
  return j.dump();
}

namespace {

// The help lines of the rows `keep` takes, in the registry's order.
template <class Keep>
std::vector<ModelInfo> InfoOf(const Keep& keep) {
  std::vector<ModelInfo> m;
  ForEachRow([&](const ModelRow& r) {
    if (keep(r)) m.push_back({r.kind, r.parameters, r.source});
  });
  return m;
}

}  // namespace

const std::vector<ModelInfo>& Models() {
  static const std::vector<ModelInfo> kModels = InfoOf([](const ModelRow& r) { return r.family; });
  return kModels;
}

const std::vector<ModelInfo>& ModelsDescribed() {
  static const std::vector<ModelInfo> kModels = InfoOf([](const ModelRow& r) { return r.parameters != nullptr; });
  return kModels;
}

std::vector<ModelKind> ModelKindsBuilt() {
  std::vector<ModelKind> kinds;
  ForEachRow([&](const ModelRow& r) { kinds.push_back(r.kind); });
  return kinds;
}

bool ModelTakes(ModelKind kind, ModelOption option) {
  const ModelRow* r = RowOfModel(kind);
  return r && (r->options & Bit(option)) != 0;
}

std::vector<std::string> ModelsTaking(ModelOption option) {
  std::vector<std::string> names;
  ForEachRow([&](const ModelRow& r) {
    if (r.options & Bit(option)) names.push_back(ModelName(r.kind));
  });
  return names;
}

namespace {

// Every known kind, built or not.
constexpr ModelKind kKinds[] = {
#define BRDFBAKE_MODEL_KIND_VALUE(family, kind, name) ModelKind::k##kind,
    BRDFBAKE_MODEL_KINDS(BRDFBAKE_MODEL_KIND_VALUE)
#undef BRDFBAKE_MODEL_KIND_VALUE
};

// Every model name this build accepts, family by family (ggx-aniso after
// ggx, ggx-glass with the glass family).
std::vector<std::string> BuiltModelNames() {
  std::vector<std::string> names;
  for (const ModelKind k : ModelKindsBuilt()) names.push_back(ModelName(k));
  return names;
}

std::string BuiltModels() {
  std::string built;
  for (const std::string& n : BuiltModelNames()) built += (built.empty() ? "" : ", ") + n;
  return built;
}

}  // namespace

const char* ModelName(ModelKind kind) {
  switch (kind) {
#define BRDFBAKE_MODEL_KIND_NAME(family, kind, name) \
  case ModelKind::k##kind:                         \
    return name;
    BRDFBAKE_MODEL_KINDS(BRDFBAKE_MODEL_KIND_NAME)
#undef BRDFBAKE_MODEL_KIND_NAME
  }
  return "ggx";
}

ModelKind ParseModelKind(const std::string& name) {
  for (ModelKind k : kKinds) {
    if (name == ModelName(k)) return k;
  }
  Bad("unknown model '" + name + "' (expected " + BuiltModels() + ")" +
      DidYouMean(name, BuiltModelNames(), {{"trowbridge-reitz", "ggx"}, {"student-t", "std"}}));
}

SheenVisibility ParseSheenVisibility(const std::string& name) {
  std::vector<std::string> names;
  for (SheenVisibility v : kSheenVisibilities) {
    if (name == SheenVisibilityName(v)) return v;
    names.push_back(SheenVisibilityName(v));
  }
  Bad("unknown sheen visibility '" + name + "' (expected " + OrList(names) + ")" +
      DidYouMean(name, names, {{"ashikhmin", "neubelt"}, {"kulla", "conty-kulla"}, {"enterprise", "enterprise-pbr"}}));
}

bool ModelBuilt(ModelKind kind) { return RowOfModel(kind) != nullptr; }

bool StudentTGammaAllowed(double gamma) { return gamma >= kMinStudentTGamma<double>; }

std::string StudentTGammaDomain(double gamma) {
  return "must be >= " + ExactText(kMinStudentTGamma<double>) +
         " or inf (the STD's mean slope diverges at 1.5; got " + ExactText(gamma) + ")";
}

void ValidateModelParams(const ModelParams& p) {
  const ModelRow* row = RowOfModel(p.kind);
  if (!row) {
    Bad("model '" + std::string(p.name()) + "' is not in this build (BRDFBAKE_MODELS; built: " +
        BuiltModels() + ")");
  }
  row->check(p);
}

void ValidateFresnel(const Fresnel& f) {
  const auto check = [](const char* name, int channel, double v, double lo, double hi) {
    if (v >= lo && v <= hi) return;  // false for NaN
    std::ostringstream os;
    os << "Fresnel " << name;
    if (channel >= 0) os << "[" << channel << "]";
    os << " = " << ExactText(v) << " is outside [" << lo << ", " << hi << "]";
    Bad(os.str());
  };
  for (int c = 0; c < 3; ++c) {
    if (f.kind == FresnelKind::kSchlick) check("f0", c, f.f0[c], 0, 1);
    if (f.kind == FresnelKind::kConductor) {
      check("n", c, f.n[c], kMinFresnelIndex, kMaxFresnelIndex);
      check("k", c, f.k[c], 0, kMaxFresnelIndex);
    }
  }
  if (f.kind == FresnelKind::kDielectric) check("eta", -1, f.eta, kMinFresnelIndex, kMaxFresnelIndex);
}

std::unique_ptr<Model> MakeModel(const ModelParams& p) {
  ValidateModelParams(p);
  return RowOfModel(p.kind)->make(p);
}

}  // namespace brdfbake
