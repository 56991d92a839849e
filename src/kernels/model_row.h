// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What the core layer knows of a model kind, as one row its family's own
// dispatch file (src/kernels/batch_<family>.cc) defines: its help text, the
// optional parameters it takes, its batch kernels and what they evaluate,
// its parameter checks and its double-precision Model. model.cc and
// batch.cc read the rows of the families this build contains (the list
// CMake writes from BRDFBAKE_MODELS, model_families.inc); nothing else
// names a family's kernels.

#ifndef BRDFBAKE_SRC_KERNELS_MODEL_ROW_H_
#define BRDFBAKE_SRC_KERNELS_MODEL_ROW_H_

#include <memory>
#include <string>

#include "base/error.h"
#include "brdfbake/batch.h"
#include "brdfbake/model.h"
#include "kernels/batch_dispatch.h"
#include "kernels/stability_probe.h"

namespace brdfbake {

// The bit of a quantity or a sampler in a row's sets.
constexpr unsigned Bit(Quantity q) { return 1u << static_cast<unsigned>(q); }
constexpr unsigned Bit(Sampler s) { return 1u << static_cast<unsigned>(s); }
constexpr unsigned Bit(ModelOption o) { return 1u << static_cast<unsigned>(o); }
// Every quantity of a microfacet NDF with a BRDF (all but the sel lobe's K).
constexpr unsigned kMicrofacetQuantities = Bit(Quantity::kD) | Bit(Quantity::kLambda) | Bit(Quantity::kG1) |
                                           Bit(Quantity::kPdfNdf) | Bit(Quantity::kG2) | Bit(Quantity::kBrdf) |
                                           Bit(Quantity::kPdfVisible);

struct ModelRow {
  ModelKind kind;
  // The help's line: its parameters and what it is (with the reference's
  // key); null parameters for a model the help does not list (ggx-aniso).
  const char* parameters;
  const char* source;
  // A family of Models(), or a table model of one (ggx-aniso, ggx-glass:
  // tables and eval's table quantities only).
  bool family;
  unsigned options;  // Bit(ModelOption) of the parameters it takes beside its widths
  bool no_fresnel;   // a lobe without a Fresnel factor (F = 1): the batch takes f0 = 1 only
  // The batch kernels (batch_dispatch.h), null where it has none, and
  // whether they run with subnormals flushed to zero (flush_subnormals.h):
  // the exponential factors of Beckmann and the STD pass through the
  // subnormal range in many lanes of an ordinary row, which x86 handles in
  // microcode.
  BatchEvalFn eval;
  BatchSampleFn sample;
  bool flush_subnormals;
  BatchEvalFn eval_elements;
  BatchSampleFn sample_elements;
  unsigned quantities;  // Bit(Quantity) the batch evaluates
  unsigned samplers;    // Bit(Sampler)
  // Its parameters' domain beyond the build (a one-line ParameterError),
  // and its Model for parameters that passed it (MakeModel).
  void (*check)(const ModelParams& p);
  std::unique_ptr<Model> (*make)(const ModelParams& p);
  // Its part of the stability study (stability_probe.h), null where its
  // kernels have none: the study draws for it in every general region,
  // in the tail regions if it takes gamma, in the rotated ones if it
  // takes a rotation (src/analysis/stability.cc).
  StabilityProbeFn stability;
  // Why the batch, as `model` configures it, has no quantity q among
  // `quantities` (a sheen visibility without masking has no Lambda), or
  // "" where it has it; null: every quantity of `quantities`.
  std::string (*lacks)(const BatchModel& model, Quantity q) = nullptr;
  // Why a model without batch kernels has none, completing "model <name>"
  // (a table model: where its batch is); null for a model with kernels.
  const char* no_batch = nullptr;
};

// The rows of one family (BRDFBAKE_MODELS), in the order of its kinds.
struct ModelFamily {
  const ModelRow* rows;
  int count;
};

// The row of `kind`, or null if this build does not contain it.
const ModelRow* RowOfModel(ModelKind kind);

// The common checks of model.cc a row's check is made of: alpha_x and
// alpha_y in (0, kMaxAlpha], the three angles in [-pi/2, pi/2].
void CheckWidths(const ModelParams& p);
void CheckAngles(const ModelParams& p);
// The one-line error of a model without a Fresnel factor given one.
void CheckNoFresnel(const char* model, const Fresnel& f);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_MODEL_ROW_H_
