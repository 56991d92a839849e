// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A model chosen at run time (from the command line or a scene): its name
// and parameters, validated once, and a type-erased double-precision view of
// the scalar reference for tools that do not know the model at compile time.

#ifndef BRDFBAKE_MODEL_H_
#define BRDFBAKE_MODEL_H_

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "brdfbake/config.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/sheen.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// The model kinds, one per registration of CMakeLists.txt's
// brdfbake_family (BRDFBAKE_MODEL_KINDS, brdfbake/config.h), family by
// family: kGgx and kGgxAniso (GGX whose widths a table takes from the
// roughness and the glTF anisotropy strength; bake and eval of E only),
// kBeckmann, kStudentT, kEllipsoid, kSel, kCharlie (the Charlie sheen,
// models/sheen.h), kDisneyDiffuse (models/disney_diffuse.h) and kGgxGlass
// (the rough dielectric over GGX, models/dielectric.h, [Walter07]: a table
// model of the glass family, E of reflection and refraction over mu,
// roughness and ior, and E_avg).
enum class ModelKind {
#define BRDFBAKE_MODEL_KIND_ENUMERATOR(family, kind, name) k##kind,
  BRDFBAKE_MODEL_KINDS(BRDFBAKE_MODEL_KIND_ENUMERATOR)
#undef BRDFBAKE_MODEL_KIND_ENUMERATOR
};

// The kind's name on the command line and in files: ggx, ggx-aniso,
// beckmann, std, ellipsoid, sel, charlie, disney-diffuse, ggx-glass.
const char* ModelName(ModelKind kind);

// The kind `name` names; std::invalid_argument with a one-line message
// listing this build's models if it names none.
ModelKind ParseModelKind(const std::string& name);

struct ModelParams {
  ModelKind kind = ModelKind::kGgx;
  double alpha_x = 0.25;
  double alpha_y = 0.25;
  double gamma = 2.0;  // std only; +inf = Beckmann
  double theta_x = 0, theta_y = 0, theta_z = 0;  // ellipsoid A = S R, sel Q (radians)
  // charlie only: the visibility term (models/sheen.h). charlie and
  // disney-diffuse are isotropic (alpha_x = alpha_y = r^2; disney-diffuse
  // takes r = sqrt(alpha_x)) with alpha in (0, 1].
  SheenVisibility visibility = SheenVisibility::kContyKulla;
  // ggx-glass only: the relative index of refraction eta = n_below / n_above
  // of the interface the view wo (above) meets; eta < 1 is light leaving
  // the denser medium (total internal reflection). In [0.01, 100].
  double ior = 1.5;

  const char* name() const { return ModelName(kind); }

  // One-line JSON such as {"name":"ggx","alpha_x":0.25,"alpha_y":0.25}.
  std::string ToJson() const;
};

// Every model name, with a one-line description of its parameters.
struct ModelInfo {
  ModelKind kind;  // its name is ModelName(kind)
  const char* parameters;
  const char* source;
};
const std::vector<ModelInfo>& Models();  // the families this build contains
// The families and the table models with a description of their own
// (ggx-glass), as the help lists them.
const std::vector<ModelInfo>& ModelsDescribed();
// Every model kind of this build, the table models included, family by
// family (ggx, ggx-aniso, beckmann, ...).
std::vector<ModelKind> ModelKindsBuilt();

// The parameters some models take beside their widths: std's gamma, the
// ellipsoid's and sel's rotation (theta_x, theta_y, theta_z), charlie's
// visibility, ggx-glass's ior.
enum class ModelOption { kGamma, kRotation, kVisibility, kIor };
// Whether `kind` takes `option` (false for a model not in this build).
bool ModelTakes(ModelKind kind, ModelOption option);
// The names of this build's models that take `option`, in their order.
std::vector<std::string> ModelsTaking(ModelOption option);

// The visibility `name` names (neubelt, conty-kulla); std::invalid_argument
// with a one-line message otherwise.
SheenVisibility ParseSheenVisibility(const std::string& name);

// Whether `kind` is a model family of this build (BRDFBAKE_MODELS);
// ggx-aniso is built with ggx, ggx-glass with the glass family.
bool ModelBuilt(ModelKind kind);

// The largest alpha accepted (roughness 100). Every model quantity, in
// double, in float and in the SIMD kernels, is finite up to it
// (PropertyTest.*AtTheDomainBounds); beyond about 1e19 squares of alpha
// overflow float and the SIMD grids would give NaN.
inline constexpr double kMaxAlpha = 1e4;

// Throws std::invalid_argument with a one-line message naming the bad
// parameter if `p` is outside the documented domain.
void ValidateModelParams(const ModelParams& p);
// The std model's gamma domain: [1.5 + 1e-6, inf] (kMinStudentTGamma in
// models/std_ndf.h). The mean slope, hence Lambda, diverges as
// 1 / (2 gamma - 3) at 1.5, and the models evaluate nothing below the
// floor, so a gamma in (1.5, 1.5 + 1e-6) is refused rather than replaced.
// StudentTGammaAllowed is false for NaN; StudentTGammaDomain says
// "must be >= 1.500001 or inf (the STD's mean slope diverges at 1.5; got G)"
// for `name`'s prefix to complete.
bool StudentTGammaAllowed(double gamma);
std::string StudentTGammaDomain(double gamma);
// Throws std::invalid_argument naming the parameter outside the domain of
// fresnel.h (F0 in [0, 1]; eta, n in [0.01, 100]; k in [0, 100]; NaN).
void ValidateFresnel(const Fresnel& f);

// A validated model, evaluated in double. Quantities a model does not define
// (Lambda for sel, say) throw std::invalid_argument.
class Model {
 public:
  virtual ~Model() = default;
  virtual const ModelParams& params() const = 0;
  virtual bool IsMicrofacet() const { return true; }

  virtual double D(const Vec3<double>& m) const = 0;
  virtual double Lambda(const Vec3<double>& w) const = 0;
  virtual double G1(const Vec3<double>& w) const = 0;
  virtual double G2(const Vec3<double>& wi, const Vec3<double>& wo,
                    Masking masking) const = 0;
  virtual double Brdf(const Vec3<double>& wi, const Vec3<double>& wo,
                      const Fresnel& fresnel, Masking masking, int channel) const = 0;
  // The model's importance sampler of microfacet normals for a view wo
  // (visible normals where available) and its density per steradian.
  virtual Vec3<double> Sample(const Vec3<double>& wo, double u1, double u2) const = 0;
  virtual double Pdf(const Vec3<double>& wo, const Vec3<double>& m) const = 0;
  // Lobe value (sel only).
  virtual double K(const Vec3<double>& w) const;
};

std::unique_ptr<Model> MakeModel(const ModelParams& p);

}  // namespace brdfbake

#endif  // BRDFBAKE_MODEL_H_
