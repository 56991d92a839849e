// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The batch interface (batch.h): checks the (model, quantity) pair and the
// shape once, then hands the rows to the model's dispatcher
// (batch_dispatch.h), under the subnormal flush for the models whose
// kernels need it.

#include "brdfbake/batch.h"

#include <stdexcept>
#include <string>

#include "base/error.h"
#include "brdfbake/config.h"
#include "kernels/batch_dispatch.h"
#include "kernels/flush_subnormals.h"

namespace brdfbake {
namespace {

// A model's dispatchers (null when the model is not in this build) and
// whether its kernels run with subnormals flushed to zero: the exponential
// factors of Beckmann and STD pass through the subnormal range in many
// lanes of an ordinary row, which x86 handles in microcode
// (flush_subnormals.h).
struct ModelDispatch {
  BatchEvalFn eval = nullptr;
  BatchSampleFn sample = nullptr;
  bool flush_subnormals = false;
};

ModelDispatch DispatchOf(ModelKind kind) {
  switch (kind) {
    case ModelKind::kGgx:
      return {GgxEvalBatch, GgxSampleBatch, false};
#if BRDFBAKE_WITH_BECKMANN
    case ModelKind::kBeckmann:
      return {BeckmannEvalBatch, BeckmannSampleBatch, true};
#endif
#if BRDFBAKE_WITH_STD
    case ModelKind::kStudentT:
      return {StudentTEvalBatch, StudentTSampleBatch, true};
#endif
#if BRDFBAKE_WITH_ELLIPSOID
    case ModelKind::kEllipsoid:
      return {EllipsoidEvalBatch, EllipsoidSampleBatch, false};
#endif
#if BRDFBAKE_WITH_SEL
    case ModelKind::kSel:
      return {SelEvalBatch, nullptr, false};
#endif
    default:
      return {};
  }
}

// Runs f, under the subnormal flush if `flush`.
template <class F>
void MaybeFlushed(bool flush, const F& f) {
  if (flush) {
    const FlushSubnormals ftz;
    f();
  } else {
    f();
  }
}

// The dispatch of a built model, or a one-line error.
ModelDispatch Checked(const char* entry, ModelKind kind) {
  const ModelDispatch m = DispatchOf(kind);
  if (!m.eval) {
    Bad(std::string(entry) + ": model " + ModelName(kind) +
        (kind == ModelKind::kGgxAniso ? " is a table model; give ggx with its two widths"
                                      : " is not in this build (BRDFBAKE_MODELS)"));
  }
  return m;
}

void Eval(const BatchModel& model, Quantity q, bool pair, const float* const* in, float* out,
          size_t n) {
  const ModelDispatch m = Checked("EvalBatch", model.kind);
  if (!BatchSupports(model.kind, q)) {
    Bad(std::string("EvalBatch: model ") + ModelName(model.kind) + " has no quantity " +
        QuantityName(q));
  }
  if (pair != IsPairQuantity(q)) {
    Bad(std::string("EvalBatch: ") + QuantityName(q) + " takes " +
        (IsPairQuantity(q) ? "a pair of directions" : "one direction"));
  }
  if (n == 0) return;
  MaybeFlushed(m.flush_subnormals, [&] { m.eval(model, q, in, out, n); });
}

}  // namespace

BatchModel BatchModelOf(const ModelParams& model, Masking masking, const Fresnel& fresnel) {
  BatchModel p;
  p.kind = model.kind;
  p.alpha_x = float(model.alpha_x);
  p.alpha_y = float(model.alpha_y);
  p.gamma = float(model.gamma);
  p.theta_x = float(model.theta_x);
  p.theta_y = float(model.theta_y);
  p.theta_z = float(model.theta_z);
  p.masking = masking;
  switch (fresnel.kind) {
    case FresnelKind::kOne:
      p.f0 = 1.0f;
      break;
    case FresnelKind::kSchlick:
      p.f0 = float(fresnel.f0[0]);
      break;
    case FresnelKind::kDielectric:
      p.fresnel = BatchFresnel::kDielectric;
      p.eta = float(fresnel.eta);
      break;
    case FresnelKind::kConductor:
      p.fresnel = BatchFresnel::kConductor;
      p.eta = float(fresnel.n[0]);
      p.k = float(fresnel.k[0]);
      break;
  }
  return p;
}

const char* QuantityName(Quantity q) {
  switch (q) {
    case Quantity::kD:
      return "D";
    case Quantity::kLambda:
      return "Lambda";
    case Quantity::kG1:
      return "G1";
    case Quantity::kPdfNdf:
      return "pdf_ndf";
    case Quantity::kK:
      return "K";
    case Quantity::kG2:
      return "G2";
    case Quantity::kBrdf:
      return "brdf";
    case Quantity::kPdfVisible:
      return "pdf_visible";
  }
  return "?";
}

bool IsPairQuantity(Quantity q) {
  return q == Quantity::kG2 || q == Quantity::kBrdf || q == Quantity::kPdfVisible;
}

bool BatchSupports(ModelKind kind, Quantity q) {
  switch (kind) {
    case ModelKind::kGgx:
    case ModelKind::kBeckmann:
    case ModelKind::kStudentT:
      return q != Quantity::kK;
    case ModelKind::kEllipsoid:
      return q != Quantity::kK && q != Quantity::kPdfNdf;
    case ModelKind::kSel:
      return q == Quantity::kK;
    case ModelKind::kGgxAniso:
      return false;
  }
  return false;
}

bool BatchSupports(ModelKind kind, Sampler s) {
  switch (kind) {
    case ModelKind::kGgx:
    case ModelKind::kBeckmann:
    case ModelKind::kStudentT:
      return true;
    case ModelKind::kEllipsoid:
      return s == Sampler::kVisible;
    case ModelKind::kSel:
    case ModelKind::kGgxAniso:
      return false;
  }
  return false;
}

void EvalBatch(const BatchModel& model, Quantity q, DirArrays w, float* out, size_t n) {
  const float* in[3] = {w.x, w.y, w.z};
  Eval(model, q, false, in, out, n);
}

void EvalBatch(const BatchModel& model, Quantity q, DirArrays a, DirArrays b, float* out,
               size_t n) {
  const float* in[6] = {a.x, a.y, a.z, b.x, b.y, b.z};
  Eval(model, q, true, in, out, n);
}

void SampleBatch(const BatchModel& model, Sampler s, DirArrays wo, const float* u1, const float* u2,
                 DirOutArrays m, size_t n) {
  const ModelDispatch d = Checked("SampleBatch", model.kind);
  if (!BatchSupports(model.kind, s)) {
    Bad(std::string("SampleBatch: model ") + ModelName(model.kind) + " has no " +
        (s == Sampler::kNdf ? "NDF" : "visible-normal") + " sampler");
  }
  if (n == 0) return;
  const float* in[5] = {wo.x, wo.y, wo.z, u1, u2};
  float* out[3] = {m.x, m.y, m.z};
  MaybeFlushed(d.flush_subnormals, [&] { d.sample(model, s, in, out, n); });
}

}  // namespace brdfbake
