// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Model of a microfacet NDF (model.h) over its scalar double
// reference, shared by the families' rows (model_row.h): D, Lambda, the
// maskings and the BRDF, and its sampler (the visible normals unless the
// family names another).

#ifndef BRDFBAKE_SRC_KERNELS_NDF_MODEL_H_
#define BRDFBAKE_SRC_KERNELS_NDF_MODEL_H_

#include <memory>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"

namespace brdfbake {

// The sampler a Model reports: the NDF's visible normals.
struct VisibleNormals {
  template <class Ndf>
  static Vec3<double> Sample(const Ndf& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SampleVisible(wo, u1, u2);
  }
  template <class Ndf>
  static double Pdf(const Ndf& ndf, const Vec3<double>& wo, const Vec3<double>& m) {
    return ndf.PdfVisible(wo, m);
  }
};

template <class Ndf, class Sampling = VisibleNormals>
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
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel, Masking masking,
              int channel) const override {
    return brdfbake::Brdf(ndf_, fresnel, wi, wo, masking, channel);
  }
  Vec3<double> Sample(const Vec3<double>& wo, double u1, double u2) const override {
    return Sampling::Sample(ndf_, wo, u1, u2);
  }
  double Pdf(const Vec3<double>& wo, const Vec3<double>& m) const override { return Sampling::Pdf(ndf_, wo, m); }

 private:
  ModelParams p_;
  Ndf ndf_;
};

template <class Sampling = VisibleNormals, class Ndf>
std::unique_ptr<Model> MakeNdfModel(const ModelParams& p, const Ndf& ndf) {
  return std::make_unique<NdfModel<Ndf, Sampling>>(p, ndf);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_NDF_MODEL_H_
