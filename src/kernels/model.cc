// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/sel.h"
#include "brdfbake/models/sheen.h"
#include "brdfbake/models/std_ndf.h"

namespace brdfbake {
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

// Shared implementation for every microfacet distribution type.
template <class Ndf>
class NdfModel : public Model {
 public:
  NdfModel(const ModelParams& p, Ndf ndf) : p_(p), ndf_(ndf) {}
  const ModelParams& params() const override { return p_; }
  double D(const Vec3<double>& m) const override { return ndf_.D(m); }
  double Lambda(const Vec3<double>& w) const override { return ndf_.Lambda(w); }
  double G1(const Vec3<double>& w) const override { return ndf_.G1(w); }
  double G2(const Vec3<double>& wi, const Vec3<double>& wo, Masking masking) const override {
    Vec3<double> h;
    if (!HalfVector(wi, wo, &h)) return 0.0;
    return brdfbake::G2(ndf_, wi, wo, h, masking);
  }
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel,
              Masking masking, int channel) const override {
    return brdfbake::Brdf(ndf_, fresnel, wi, wo, masking, channel);
  }
  Vec3<double> Sample(const Vec3<double>& wo, double u1, double u2) const override;
  double Pdf(const Vec3<double>& wo, const Vec3<double>& m) const override;

 private:
  ModelParams p_;
  Ndf ndf_;
};

#if BRDFBAKE_WITH_STD
template <>
Vec3<double> NdfModel<StudentTNdf<double>>::Sample(const Vec3<double>& wo, double u1,
                                              double u2) const {
  return ndf_.SamplePseudoVnis(wo, u1, u2);
}
template <>
double NdfModel<StudentTNdf<double>>::Pdf(const Vec3<double>& wo, const Vec3<double>& m) const {
  return ndf_.PdfPseudoVnis(wo, m);
}
#endif
template <class Ndf>
Vec3<double> NdfModel<Ndf>::Sample(const Vec3<double>& wo, double u1, double u2) const {
  return ndf_.SampleVisible(wo, u1, u2);
}
template <class Ndf>
double NdfModel<Ndf>::Pdf(const Vec3<double>& wo, const Vec3<double>& m) const {
  return ndf_.PdfVisible(wo, m);
}

class SelModel : public Model {
 public:
  explicit SelModel(const ModelParams& p)
      : p_(p), lobe_(SelLobe<double>::FromAngles(p.alpha_x, p.alpha_y, p.theta_x,
                                                 p.theta_y, p.theta_z)) {}
  const ModelParams& params() const override { return p_; }
  bool IsMicrofacet() const override { return false; }
  double D(const Vec3<double>&) const override { NotDefined("D"); }
  double Lambda(const Vec3<double>&) const override { NotDefined("Lambda"); }
  double G1(const Vec3<double>&) const override { NotDefined("G1"); }
  double G2(const Vec3<double>&, const Vec3<double>&, Masking) const override {
    NotDefined("G2");
  }
  double Brdf(const Vec3<double>&, const Vec3<double>&, const Fresnel&, Masking,
              int) const override {
    NotDefined("brdf");
  }
  Vec3<double> Sample(const Vec3<double>&, double, double) const override {
    NotDefined("sampling");
  }
  double Pdf(const Vec3<double>&, const Vec3<double>&) const override { NotDefined("pdf"); }
  double K(const Vec3<double>& w) const override { return lobe_.K(w); }

 private:
  [[noreturn]] static void NotDefined(const char* what) {
    Bad(std::string("model sel (a lobe, not a microfacet BRDF) has no ") + what +
        "; use the quantity K");
  }
  ModelParams p_;
  SelLobe<double> lobe_;
};

// The sheen and the diffuse lobe have no Fresnel factor (F = 1).
void NoFresnel(const char* model, const Fresnel& f) {
  if (f.kind != FresnelKind::kOne) {
    Bad(std::string("model ") + model + " has no Fresnel factor (F = 1); give no Fresnel");
  }
}

// The Charlie sheen (models/sheen.h): an NDF with its own visibility; the
// masking argument does not apply (the conty-kulla G2 is height-correlated).
class CharlieModel : public Model {
 public:
  explicit CharlieModel(const ModelParams& p) : p_(p), sheen_(p.alpha_x, p.visibility) {}
  const ModelParams& params() const override { return p_; }
  double D(const Vec3<double>& m) const override { return sheen_.D(m); }
  double Lambda(const Vec3<double>& w) const override {
    NeedsMasking("Lambda");
    return sheen_.Lambda(w);
  }
  double G1(const Vec3<double>& w) const override {
    NeedsMasking("G1");
    return sheen_.G1(w);
  }
  double G2(const Vec3<double>& wi, const Vec3<double>& wo, Masking) const override {
    NeedsMasking("G2");
    return sheen_.G2Cos(wi.z, wo.z);
  }
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel, Masking,
              int) const override {
    NoFresnel("charlie", fresnel);
    return sheen_.Brdf(wi, wo);
  }
  // The NDF's own sampler (density D(m) m.z): the sheen has no visible-normal one.
  Vec3<double> Sample(const Vec3<double>&, double u1, double u2) const override {
    return sheen_.SampleNdf(u1, u2);
  }
  double Pdf(const Vec3<double>&, const Vec3<double>& m) const override { return sheen_.PdfNdf(m); }

 private:
  void NeedsMasking(const char* what) const {
    if (!SheenHasLambda(p_.visibility)) {
      Bad(std::string("charlie with the ") + SheenVisibilityName(p_.visibility) + " visibility has no " +
          what + " (it has no masking term); use the conty-kulla visibility");
    }
  }
  ModelParams p_;
  CharlieSheen<double> sheen_;
};

// The Disney diffuse BRDF (models/disney_diffuse.h) at r = sqrt(alpha_x).
class DisneyDiffuseModel : public Model {
 public:
  explicit DisneyDiffuseModel(const ModelParams& p) : p_(p), diffuse_(std::sqrt(p.alpha_x)) {}
  const ModelParams& params() const override { return p_; }
  bool IsMicrofacet() const override { return false; }
  double D(const Vec3<double>&) const override { NotDefined("D"); }
  double Lambda(const Vec3<double>&) const override { NotDefined("Lambda"); }
  double G1(const Vec3<double>&) const override { NotDefined("G1"); }
  double G2(const Vec3<double>&, const Vec3<double>&, Masking) const override {
    NotDefined("G2");
  }
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel, Masking,
              int) const override {
    NoFresnel("disney-diffuse", fresnel);
    return diffuse_.Brdf(wi, wo);
  }
  Vec3<double> Sample(const Vec3<double>&, double, double) const override {
    NotDefined("normal sampling");
  }
  double Pdf(const Vec3<double>&, const Vec3<double>&) const override { NotDefined("pdf"); }

 private:
  [[noreturn]] static void NotDefined(const char* what) {
    Bad(std::string("model disney-diffuse (a diffuse BRDF, no microfacets) has no ") + what +
        "; use the quantity brdf");
  }
  ModelParams p_;
  DisneyDiffuse<double> diffuse_;
};

}  // namespace

double Model::K(const Vec3<double>&) const {
  Bad("quantity K is defined for model sel only; model " + std::string(params().name()) + " has D, Lambda, G1, G2, brdf, pdf");
}

std::string ModelParams::ToJson() const {
  nlohmann::json j;
  j["name"] = name();
  j["alpha_x"] = alpha_x;
  j["alpha_y"] = alpha_y;
  if (kind == ModelKind::kStudentT) {
    if (std::isinf(gamma)) j["gamma"] = "inf"; else j["gamma"] = gamma;
  }
  if (kind == ModelKind::kCharlie) j["visibility"] = SheenVisibilityName(visibility);
  if (kind == ModelKind::kGgxGlass) j["ior"] = ior;
  if (kind == ModelKind::kEllipsoid || kind == ModelKind::kSel) {
    j["theta_x"] = theta_x;
    j["theta_y"] = theta_y;
    j["theta_z"] = theta_z;
  }
  return j.dump();
}

const std::vector<ModelInfo>& Models() {
  static const std::vector<ModelInfo> kModels = {
      {ModelKind::kGgx, "alpha_x, alpha_y", "Trowbridge-Reitz; VNDF sampling from [Heitz18]"},
#if BRDFBAKE_WITH_BECKMANN
      {ModelKind::kBeckmann, "alpha_x, alpha_y", "Gaussian slopes; exact VNDF sampling by CDF inversion"},
#endif
#if BRDFBAKE_WITH_STD
      {ModelKind::kStudentT, "alpha_x, alpha_y, gamma in [1.500001, inf]", "Student's t slopes, [Ribardiere17]; gamma=2 is ggx, inf is beckmann"},
#endif
#if BRDFBAKE_WITH_ELLIPSOID
      {ModelKind::kEllipsoid, "alpha_x, alpha_y, theta_x, theta_y, theta_z", "Walter et al. ellipsoid NDF, [Walter15]; A = S Rx Ry Rz"},
#endif
#if BRDFBAKE_WITH_SEL
      {ModelKind::kSel, "alpha_x, alpha_y, theta_x, theta_y, theta_z (lobe frame Q = Rx Ry Rz)", "squared ellipsoidal lobe K(w), [TokuyoshiHarada]"},
#endif
#if BRDFBAKE_WITH_CHARLIE
      {ModelKind::kCharlie, "alpha in (0, 1] (isotropic), visibility neubelt or conty-kulla", "Charlie sheen, [EstevezKulla17]; visibility [Neubelt13] or the paper's fitted Lambda"},
#endif
#if BRDFBAKE_WITH_DISNEY
      {ModelKind::kDisneyDiffuse, "r = sqrt(alpha) in [0, 1] (isotropic)", "Disney diffuse, [Burley12]; no microfacets"},
#endif
  };
  return kModels;
}

namespace {

constexpr ModelKind kKinds[] = {ModelKind::kGgx,       ModelKind::kBeckmann, ModelKind::kStudentT,
                                ModelKind::kEllipsoid, ModelKind::kSel,      ModelKind::kGgxAniso,
                                ModelKind::kCharlie,   ModelKind::kDisneyDiffuse, ModelKind::kGgxGlass};

// Every model name this build accepts: the families, ggx-aniso (a table
// model of the ggx family) and ggx-glass (of the glass family).
std::vector<std::string> BuiltModelNames() {
  std::vector<std::string> names;
  for (const ModelInfo& m : Models()) {
    names.push_back(ModelName(m.kind));
    if (m.kind == ModelKind::kGgx) names.push_back(ModelName(ModelKind::kGgxAniso));
  }
  if (ModelBuilt(ModelKind::kGgxGlass)) names.push_back(ModelName(ModelKind::kGgxGlass));
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
    case ModelKind::kGgx: return "ggx";
    case ModelKind::kBeckmann: return "beckmann";
    case ModelKind::kStudentT: return "std";
    case ModelKind::kEllipsoid: return "ellipsoid";
    case ModelKind::kSel: return "sel";
    case ModelKind::kGgxAniso: return "ggx-aniso";
    case ModelKind::kCharlie: return "charlie";
    case ModelKind::kDisneyDiffuse: return "disney-diffuse";
    case ModelKind::kGgxGlass: return "ggx-glass";
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

bool ModelBuilt(ModelKind kind) {
  if (kind == ModelKind::kGgxGlass) return BRDFBAKE_WITH_GLASS != 0;
  if (kind == ModelKind::kGgxAniso) kind = ModelKind::kGgx;
  for (const ModelInfo& m : Models()) {
    if (kind == m.kind) return true;
  }
  return false;
}

bool StudentTGammaAllowed(double gamma) { return gamma >= kMinStudentTGamma<double>; }

std::string StudentTGammaDomain(double gamma) {
  return "must be >= " + ExactText(kMinStudentTGamma<double>) +
         " or inf (the STD's mean slope diverges at 1.5; got " + ExactText(gamma) + ")";
}

void ValidateModelParams(const ModelParams& p) {
  if (p.kind == ModelKind::kGgxAniso) {
    Bad("model ggx-aniso has only the table quantities E and E_avg (bake them, or eval {quantity} "
        "E); for its BRDF give {model} ggx with {alpha_x} and {alpha_y}");
  }
  if (!ModelBuilt(p.kind)) {
    Bad("model '" + std::string(p.name()) + "' is not in this build (BRDFBAKE_MODELS; built: " +
        BuiltModels() + ")");
  }
  if (p.kind == ModelKind::kGgxGlass) {
    if (!(p.ior >= kMinFresnelIndex && p.ior <= kMaxFresnelIndex)) {
      Bad("ior must lie in [0.01, 100] (the relative index of refraction; below 1 light leaves the "
          "denser medium; got " + ExactText(p.ior) + ")");
    }
    CheckAlpha("alpha_x", p.alpha_x);
    CheckAlpha("alpha_y", p.alpha_y);
    return;
  }
  if (p.kind == ModelKind::kDisneyDiffuse) {
    // r = sqrt(alpha) in [0, 1]: r = 0 is an ordinary diffuse lobe.
    if (!(p.alpha_x >= 0 && p.alpha_x <= 1) || p.alpha_x != p.alpha_y) {
      Bad("model disney-diffuse takes one roughness r in [0, 1] (alpha = r^2; got alpha_x " +
          ExactText(p.alpha_x) + ", alpha_y " + ExactText(p.alpha_y) + ")");
    }
    return;
  }
  CheckAlpha("alpha_x", p.alpha_x);
  CheckAlpha("alpha_y", p.alpha_y);
  if (p.kind == ModelKind::kStudentT && !StudentTGammaAllowed(p.gamma)) {
    Bad("gamma " + StudentTGammaDomain(p.gamma));
  }
  if (p.kind == ModelKind::kCharlie) {
    if (p.alpha_x != p.alpha_y) {
      Bad("model " + std::string(p.name()) + " is isotropic: alpha_x and alpha_y must be equal (got " +
          ExactText(p.alpha_x) + " and " + ExactText(p.alpha_y) + ")");
    }
    if (p.alpha_x > 1) {
      Bad("alpha of model " + std::string(p.name()) + " must lie in (0, 1] (roughness at most 1; got " +
          ExactText(p.alpha_x) + ")");
    }
  }
  if (p.kind == ModelKind::kEllipsoid || p.kind == ModelKind::kSel) {
    CheckAngle("theta_x", p.theta_x);
    CheckAngle("theta_y", p.theta_y);
    CheckAngle("theta_z", p.theta_z);
  }
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
  if (p.kind == ModelKind::kGgxGlass) {
    Bad("model ggx-glass has only the table quantities E and E_avg (bake them, or eval {quantity} "
        "E or E_avg); its BSDF is evaluated by DielectricBsdfBatch");
  }
#if BRDFBAKE_WITH_BECKMANN
  if (p.kind == ModelKind::kBeckmann) {
    return std::make_unique<NdfModel<BeckmannNdf<double>>>(
        p, BeckmannNdf<double>(p.alpha_x, p.alpha_y));
  }
#endif
#if BRDFBAKE_WITH_STD
  if (p.kind == ModelKind::kStudentT) {
    return std::make_unique<NdfModel<StudentTNdf<double>>>(
        p, StudentTNdf<double>(p.alpha_x, p.alpha_y, p.gamma));
  }
#endif
#if BRDFBAKE_WITH_ELLIPSOID
  if (p.kind == ModelKind::kEllipsoid) {
    return std::make_unique<NdfModel<EllipsoidNdf<double>>>(
        p, EllipsoidNdf<double>(p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z));
  }
#endif
#if BRDFBAKE_WITH_SEL
  if (p.kind == ModelKind::kSel) return std::make_unique<SelModel>(p);
#endif
#if BRDFBAKE_WITH_CHARLIE
  if (p.kind == ModelKind::kCharlie) return std::make_unique<CharlieModel>(p);
#endif
#if BRDFBAKE_WITH_DISNEY
  if (p.kind == ModelKind::kDisneyDiffuse) return std::make_unique<DisneyDiffuseModel>(p);
#endif
  return std::make_unique<NdfModel<GgxNdf<double>>>(p, GgxNdf<double>(p.alpha_x, p.alpha_y));
}

}  // namespace brdfbake
