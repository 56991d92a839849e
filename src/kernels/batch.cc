// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The batch interface (batch.h): checks the (model, quantity) pair and the
// shape once, then hands the rows to the model's dispatcher
// (batch_dispatch.h), under the subnormal flush for the models whose
// kernels need it.

#include "brdfbake/batch.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>

#include "base/error.h"
#include "brdfbake/config.h"
#include "kernels/batch_dispatch.h"
#include "kernels/flush_subnormals.h"
#include "kernels/model_row.h"

namespace brdfbake {
namespace {

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

// `what` = value is outside `domain`, as one line naming the call.
[[noreturn]] void Outside(const char* entry, const std::string& what, float value,
                          const char* domain) {
  std::ostringstream os;
  os << entry << ": " << what << " = " << value << " is outside " << domain;
  Bad(os.str());
}

bool Within(float v, float lo, float hi) { return v >= lo && v <= hi; }  // false for NaN

// The Fresnel domain of fresnel.h in float.
constexpr float kMinIndex = float(kMinFresnelIndex), kMaxIndex = float(kMaxFresnelIndex);

void CheckFresnel(const char* entry, const BatchModel& m) {
  switch (m.fresnel) {
    case BatchFresnel::kSchlick:
      if (!Within(m.f0, 0, 1)) Outside(entry, "f0", m.f0, "[0, 1]");
      return;
    case BatchFresnel::kDielectric:
      if (!Within(m.eta, kMinIndex, kMaxIndex)) Outside(entry, "eta", m.eta, "[0.01, 100]");
      return;
    case BatchFresnel::kConductor:
      if (!Within(m.eta, kMinIndex, kMaxIndex)) Outside(entry, "eta", m.eta, "[0.01, 100]");
      if (!Within(m.k, 0, kMaxIndex)) Outside(entry, "k", m.k, "[0, 100]");
      return;
  }
  Bad(std::string(entry) + ": unknown BatchFresnel");
}

// The row of a built model with batch kernels whose parameters lie in the
// domain (batch.h), or a one-line error.
const ModelRow& Checked(const char* entry, const BatchModel& model) {
  const ModelRow* row = RowOfModel(model.kind);
  if (!row || !row->eval) {
    Bad(std::string(entry) + ": model " + ModelName(model.kind) +
        (row && row->no_batch ? row->no_batch : " is not in this build (BRDFBAKE_MODELS)"));
  }
  try {
    ValidateModelParams(ModelParamsOf(model));
  } catch (const std::invalid_argument& e) {
    Bad(std::string(entry) + ": " + ErrorText(e));
  }
  CheckFresnel(entry, model);
  if (row->no_fresnel && !(model.fresnel == BatchFresnel::kSchlick && model.f0 == 1.0f)) {
    Bad(std::string(entry) + ": model " + ModelName(model.kind) +
        " has no Fresnel factor (F = 1): give BatchFresnel::kSchlick with f0 = 1");
  }
  return *row;
}

// The per-element arrays of `e` as the kernels take them (alpha_y falls
// back on alpha_x), each element checked.
std::array<const float*, 3> CheckedElements(const char* entry, const BatchModel& model,
                                            const ModelRow& m, const BatchElements& e,
                                            size_t n) {
  if (!m.eval_elements) {
    Bad(std::string(entry) + ": model " + ModelName(model.kind) +
        " takes its parameters per call (per-element parameters: ggx, beckmann)");
  }
  const float* ay = e.alpha_y ? e.alpha_y : e.alpha_x;
  const auto check = [&](const char* name, const float* a, float lo, bool open_lo, float hi,
                         const char* domain) {
    if (!a || AllWithinBatch(a, n, lo, hi, open_lo)) return;
    for (size_t j = 0; j < n; ++j) {
      if (!(open_lo ? a[j] > lo : a[j] >= lo) || !(a[j] <= hi)) {
        Outside(entry, std::string(name) + "[" + std::to_string(j) + "]", a[j], domain);
      }
    }
  };
  check("alpha_x", e.alpha_x, 0, true, 1e4f, "(0, 1e4]");
  if (e.alpha_y != e.alpha_x) check("alpha_y", e.alpha_y, 0, true, 1e4f, "(0, 1e4]");
  if (e.f0 && model.fresnel != BatchFresnel::kSchlick) {
    Bad(std::string(entry) + ": per-element f0 needs BatchFresnel::kSchlick");
  }
  check("f0", e.f0, 0, false, 1, "[0, 1]");
  return {e.alpha_x, ay, e.f0};
}

void CheckQuantity(const BatchModel& model, Quantity q, bool pair) {
  if (!BatchSupports(model.kind, q)) {
    Bad(std::string("EvalBatch: model ") + ModelName(model.kind) + " has no quantity " +
        QuantityName(q));
  }
  const ModelRow* row = RowOfModel(model.kind);
  if (row->lacks) {
    const std::string why = row->lacks(model, q);
    if (!why.empty()) Bad("EvalBatch: " + why);
  }
  if (pair != IsPairQuantity(q)) {
    Bad(std::string("EvalBatch: ") + QuantityName(q) + " takes " +
        (IsPairQuantity(q) ? "a pair of directions" : "one direction"));
  }
}

void CheckSampler(const char* entry, const BatchModel& model, Sampler s) {
  if (!BatchSupports(model.kind, s)) {
    Bad(std::string(entry) + ": model " + ModelName(model.kind) + " has no " +
        (s == Sampler::kNdf ? "NDF" : "visible-normal") + " sampler");
  }
}

// Evaluation of checked arguments: `in` holds the 3 or 6 direction arrays,
// then (with elements) the 3 per-element arrays.
void EvalChecked(const ModelRow& m, const BatchModel& model, bool elements, Quantity q,
                 const float* const* in, float* out, size_t n) {
  (elements ? m.eval_elements : m.eval)(model, q, in, out, n);
}

void Eval(const BatchModel& model, const BatchElements* e, Quantity q, const DirArrays* dirs,
          int count, float* out, size_t n) {
  const ModelRow& m = Checked("EvalBatch", model);
  CheckQuantity(model, q, count == 2);
  const float* in[9] = {};
  for (int k = 0; k < count; ++k) {
    in[3 * k] = dirs[k].x;
    in[3 * k + 1] = dirs[k].y;
    in[3 * k + 2] = dirs[k].z;
  }
  if (e) {
    const std::array<const float*, 3> pe = CheckedElements("EvalBatch", model, m, *e, n);
    for (int k = 0; k < 3; ++k) in[3 * count + k] = pe[k];
  }
  if (n == 0) return;
  MaybeFlushed(m.flush_subnormals, [&] { EvalChecked(m, model, e != nullptr, q, in, out, n); });
}

void Sample(const BatchModel& model, const BatchElements* e, Sampler s, DirArrays wo,
            const float* u1, const float* u2, DirOutArrays mo, size_t n) {
  const ModelRow& m = Checked("SampleBatch", model);
  CheckSampler("SampleBatch", model, s);
  const float* in[8] = {wo.x, wo.y, wo.z, u1, u2};
  if (e) {
    const std::array<const float*, 3> pe = CheckedElements("SampleBatch", model, m, *e, n);
    for (int k = 0; k < 3; ++k) in[5 + k] = pe[k];
  }
  if (n == 0) return;
  float* out[3] = {mo.x, mo.y, mo.z};
  MaybeFlushed(m.flush_subnormals,
               [&] { (e ? m.sample_elements : m.sample)(model, s, in, out, n); });
}

// Light directions: per chunk of elements, the visible normals, the
// reflection, the normals' density, the BRDF, then pdf and weight (each
// one vector loop on the dispatched target).
void SampleLight(const BatchModel& model, const BatchElements* e, DirArrays wo, const float* u1,
                 const float* u2, LightSampleArrays wi, size_t n) {
  const char* entry = "SampleLightBatch";
  const ModelRow& m = Checked(entry, model);
  CheckSampler(entry, model, Sampler::kVisible);
  std::array<const float*, 3> pe = {};
  if (e) pe = CheckedElements(entry, model, m, *e, n);
  if (n == 0) return;
  constexpr size_t kChunk = 256;
  alignas(64) float mx[kChunk], my[kChunk], mz[kChunk], pdf_m[kChunk], f[kChunk];
  MaybeFlushed(m.flush_subnormals, [&] {
    for (size_t i = 0; i < n; i += kChunk) {
      const size_t c = std::min(kChunk, n - i);
      const float* ox = wo.x + i;
      const float* oy = wo.y + i;
      const float* oz = wo.z + i;
      float* ix = wi.x + i;
      float* iy = wi.y + i;
      float* iz = wi.z + i;
      const float* in[11] = {ox, oy, oz, u1 + i, u2 + i};
      for (int k = 0; k < 3; ++k) in[5 + k] = pe[k] ? pe[k] + i : nullptr;
      float* normal[3] = {mx, my, mz};
      (e ? m.sample_elements : m.sample)(model, Sampler::kVisible, in, normal, c);
      const float* wo_m[6] = {ox, oy, oz, mx, my, mz};
      float* wi_out[3] = {ix, iy, iz};
      ReflectBatch(wo_m, wi_out, c);
      // (wo, m) for the density, (wi, wo) for the BRDF, then the elements.
      const float* pair[9] = {ox, oy, oz, mx, my, mz};
      for (int k = 0; k < 3; ++k) pair[6 + k] = in[5 + k];
      EvalChecked(m, model, e != nullptr, Quantity::kPdfVisible, pair, pdf_m, c);
      const float* brdf[9] = {ix, iy, iz, ox, oy, oz};
      for (int k = 0; k < 3; ++k) brdf[6 + k] = in[5 + k];
      EvalChecked(m, model, e != nullptr, Quantity::kBrdf, brdf, f, c);
      const float* parts[9] = {ox, oy, oz, mx, my, mz, iz, pdf_m, f};
      float* light[2] = {wi.weight + i, wi.pdf + i};
      LightWeightBatch(parts, light, c);
    }
  });
}

void CheckDielectric(const BatchDielectric& m) {
  const char* entry = "DielectricBsdfBatch";
#if !BRDFBAKE_WITH_GLASS
  Bad(std::string(entry) + ": the glass family is not in this build (BRDFBAKE_MODELS)");
#endif
  if (m.ndf != ModelKind::kGgx && m.ndf != ModelKind::kBeckmann) {
    Bad(std::string(entry) + ": ndf " + ModelName(m.ndf) + " is not ggx or beckmann");
  }
#if !BRDFBAKE_WITH_BECKMANN
  if (m.ndf == ModelKind::kBeckmann) {
    Bad(std::string(entry) + ": ndf beckmann is not in this build (BRDFBAKE_MODELS)");
  }
#endif
  if (!(m.alpha_x > 0 && m.alpha_x <= 1e4f)) Outside(entry, "alpha_x", m.alpha_x, "(0, 1e4]");
  if (!(m.alpha_y > 0 && m.alpha_y <= 1e4f)) Outside(entry, "alpha_y", m.alpha_y, "(0, 1e4]");
  if (!Within(m.eta, kMinIndex, kMaxIndex)) Outside(entry, "eta", m.eta, "[0.01, 100]");
}

}  // namespace

void DielectricBsdfBatch(const BatchDielectric& model, DielectricQuantity q, DirArrays wi,
                         DirArrays wo, float* out, size_t n) {
  CheckDielectric(model);
#if BRDFBAKE_WITH_GLASS
  if (n == 0) return;
  const float* in[6] = {wi.x, wi.y, wi.z, wo.x, wo.y, wo.z};
  // With subnormals flushed where the NDF's own kernels flush them
  // (Beckmann's exponential: ModelRow::flush_subnormals).
  MaybeFlushed(RowOfModel(model.ndf)->flush_subnormals, [&] { GlassEvalBatch(model, q, in, out, n); });
#else
  (void)q, (void)wi, (void)wo, (void)out, (void)n;
#endif
}

BatchModel BatchModelOf(const ModelParams& model, Masking masking, const Fresnel& fresnel) {
  BatchModel p;
  p.kind = model.kind;
  p.alpha_x = float(model.alpha_x);
  p.alpha_y = float(model.alpha_y);
  p.gamma = float(model.gamma);
  p.theta_x = float(model.theta_x);
  p.theta_y = float(model.theta_y);
  p.theta_z = float(model.theta_z);
  p.visibility = model.visibility;
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

ModelParams ModelParamsOf(const BatchModel& model) {
  ModelParams p;
  p.kind = model.kind;
  p.alpha_x = model.alpha_x;
  p.alpha_y = model.alpha_y;
  p.gamma = model.gamma;
  p.theta_x = model.theta_x;
  p.theta_y = model.theta_y;
  p.theta_z = model.theta_z;
  p.visibility = model.visibility;
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
  const ModelRow* r = RowOfModel(kind);
  return r && (r->quantities & Bit(q)) != 0;
}

bool BatchSupports(ModelKind kind, Sampler s) {
  const ModelRow* r = RowOfModel(kind);
  return r && (r->samplers & Bit(s)) != 0;
}

bool BatchTakesFresnel(ModelKind kind) {
  const ModelRow* r = RowOfModel(kind);
  return r && !r->no_fresnel;
}

bool BatchSupportsElements(ModelKind kind) {
  const ModelRow* r = RowOfModel(kind);
  return r && r->eval_elements != nullptr;
}

void EvalBatch(const BatchModel& model, Quantity q, DirArrays w, float* out, size_t n) {
  Eval(model, nullptr, q, &w, 1, out, n);
}

void EvalBatch(const BatchModel& model, Quantity q, DirArrays a, DirArrays b, float* out,
               size_t n) {
  const DirArrays dirs[2] = {a, b};
  Eval(model, nullptr, q, dirs, 2, out, n);
}

void EvalBatch(const BatchModel& model, const BatchElements& elements, Quantity q, DirArrays w,
               float* out, size_t n) {
  Eval(model, &elements, q, &w, 1, out, n);
}

void EvalBatch(const BatchModel& model, const BatchElements& elements, Quantity q, DirArrays a,
               DirArrays b, float* out, size_t n) {
  const DirArrays dirs[2] = {a, b};
  Eval(model, &elements, q, dirs, 2, out, n);
}

void SampleBatch(const BatchModel& model, Sampler s, DirArrays wo, const float* u1, const float* u2,
                 DirOutArrays m, size_t n) {
  Sample(model, nullptr, s, wo, u1, u2, m, n);
}

void SampleBatch(const BatchModel& model, const BatchElements& elements, Sampler s, DirArrays wo,
                 const float* u1, const float* u2, DirOutArrays m, size_t n) {
  Sample(model, &elements, s, wo, u1, u2, m, n);
}

void SampleLightBatch(const BatchModel& model, DirArrays wo, const float* u1, const float* u2,
                      LightSampleArrays wi, size_t n) {
  SampleLight(model, nullptr, wo, u1, u2, wi, n);
}

void SampleLightBatch(const BatchModel& model, const BatchElements& elements, DirArrays wo,
                      const float* u1, const float* u2, LightSampleArrays wi, size_t n) {
  SampleLight(model, &elements, wo, u1, u2, wi, n);
}

}  // namespace brdfbake
