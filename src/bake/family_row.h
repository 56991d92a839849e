// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What the baker knows of a model kind, as one row its family's own file
// (src/bake/families/<family>_tables.cc) defines: the tables it bakes, how one
// texel and one E_avg of them are integrated, and what their metadata say
// of the model and the rule. table_spec.cc and bake.cc read the rows of the
// families this build contains (the list CMake writes from BRDFBAKE_MODELS,
// kernels/model_families.inc); neither names a family's rule.

#ifndef BRDFBAKE_SRC_BAKE_FAMILY_ROW_H_
#define BRDFBAKE_SRC_BAKE_FAMILY_ROW_H_

#include <cmath>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/table_spec.h"
#include "quadrature/adaptive_rule.h"

namespace brdfbake {

// One texel's coordinates, as the table's axes give them (mu and the
// roughness at least their axes' clamps).
struct TexelAt {
  double mu = 1;
  double roughness = 0;
  double alpha = 0;       // the roughness squared
  double phi = 0;         // phi_o (ellipsoid, ggx-aniso)
  double anisotropy = 0;  // ggx-aniso
  double alpha_x = 0, alpha_y = 0;  // sel_norm's axes
};

constexpr unsigned Bit(TableKind t) { return 1u << static_cast<unsigned>(t); }

// The axes of a family's tables where they are its own rather than mu x
// roughness with an optional gamma axis: the ellipsoid's mu x phi_o over
// one material, ggx-aniso's mu x phi_o x roughness x anisotropy, ggx-glass's
// slices over the ior. table_spec.cc's AxesOf, DefaultSizes and SizeForm
// read them; the bake fills a texel's TexelAt from the axes' names.
struct OwnAxes {
  std::vector<Axis BakeSpec::*> axes;  // fastest first
  std::vector<int> sizes;              // each one's size when --size gives none
  const char* form;                    // --size's form for messages: "WxH (mu x phi_o, e.g. 64x64)"
  // The largest phi_o the phi_o axis may reach: pi/2 where E is even in
  // phi_o and symmetric about pi/2 (ggx-aniso), 2 pi without symmetry.
  double phi_max = kHalfPi;
};

struct BakerRow {
  ModelKind kind;
  // The table kinds it bakes (besides the tables of another model's lobe,
  // which KindRow::term refuses first), whether its rules have no sampling
  // counterpart, and what the refusal of another table says it bakes:
  // "{table}: <model> bakes <bakes>".
  unsigned tables;
  bool quadrature_only;
  const char* bakes;
  // E (and dfg's scale and bias) at one texel of `slice` (the table's spec
  // at the texel's parameter slice); sel_norm's N in e and its ratio in
  // bias. `seed` picks the sampling integrators' streams.
  TexelEstimate (*texel)(const BakeSpec& slice, const TexelAt& at, uint64_t seed);
  // E_avg by the quadrature at one texel (its roughness and anisotropy);
  // null for AdaptiveEavg over `texel`, with `eavg_grading` levels
  // (null: none) for E_avg and the dfg bias average.
  EavgEstimate (*eavg)(const BakeSpec& slice, const TexelAt& at);
  int (*eavg_grading)(const BakeSpec& slice);
  // Work shared by every texel of the table, done once before them with
  // every thread (null: none).
  void (*prepare)(const BakeSpec& slice);
  // Its entries of brdfbake.model and brdfbake.integrator (added to, or
  // replacing, the common ones bake.cc writes first).
  void (*model_json)(const BakeSpec& spec, nlohmann::json* j);
  void (*integrator_json)(const BakeSpec& spec, nlohmann::json* j);
  // The largest E it stores: 1, or +inf for a lobe that does not conserve
  // energy (StoredEMax).
  double e_max;
  // Frees what its tables keep between bakes (ReleaseBakeCaches; null:
  // nothing).
  void (*release)() = nullptr;
  // Whether its tables take a Smith masking (BakeSpec::masking); false for
  // a lobe whose shadowing is its own (charlie's visibility) or that has
  // none (ModelTakesMasking).
  bool masking = true;
  // Its tables' own axes (E's or E_avg's, as spec.table says); null: mu x
  // roughness (x gamma).
  OwnAxes (*own_axes)(const BakeSpec& spec) = nullptr;
  // The parameters ValidateBakeSpec checks its model with where the table's
  // axes give them (ggx-aniso: ggx at the spec's widths; ggx-glass: any
  // roughness); null: the spec's model itself.
  void (*checked_as)(ModelParams* p) = nullptr;
  // The definition of its E channel where it is not the common albedo with
  // F = 1 (ggx-glass: its parts, Fresnel included); null: the common one.
  const char* (*e_definition)(const BakeSpec& spec) = nullptr;
};

// The row of `kind`, or null if this build does not contain it.
const BakerRow* BakerRowOf(ModelKind kind);

// One family's rows, in the order of its kinds.
struct BakerFamily {
  const BakerRow* rows;
  int count;
};

// E_avg = 2 int E(mu) mu dmu = 4 int_0^1 E(s^2) s^3 ds by adaptive
// Gauss-Kronrod 15 in s from the pieces [0, 1/4], [1/4, 1]: the worst piece
// is bisected until the sum of |K15 - G7| plus the propagated error of E
// meets the tolerance (or bisection stops helping: the rule's part below a
// tenth of it, or 64 pieces). E near grazing has a boundary layer, and for
// the heavy-tailed STD a non-smooth one, which a fixed rule resolved only to
// ~1e-5. `e_at(mu)` gives E and its error. `grade_levels` > 0 cuts [1/4, 1]
// geometrically (ratio 4) towards s = 1 from the start (the STD's grading).
template <class EAt>
EavgEstimate AdaptiveEavg(const EAt& e_at, double tolerance, int grade_levels = 0) {
  using Piece = GkPiece;
  auto piece = [&](double a, double b) {
    return KronrodPiece(a, b, 1.0, [&](double sv, double* err) {
      const TexelEstimate v = e_at(sv * sv);
      const double jac = 4 * sv * sv * sv;
      *err = jac * v.err_e;
      return jac * v.e;
    });
  };
  std::vector<Piece> pieces = {piece(0.0, 0.25)};
  double a = 0.25;
  for (int k = 1; k <= grade_levels; ++k) {
    const double b = 1 - 0.75 * std::pow(4.0, -k);
    pieces.push_back(piece(a, b));
    a = b;
  }
  pieces.push_back(piece(a, 1.0));
  auto sums = [&](double* rule, double* prop) {
    *rule = *prop = 0;
    for (const Piece& p : pieces) {
      *rule += p.err;
      *prop += p.prop;
    }
  };
  double rule_err, prop_err;
  sums(&rule_err, &prop_err);
  while (rule_err + prop_err > tolerance && rule_err > 0.1 * tolerance && pieces.size() < 64) {
    BisectWorst(&pieces, piece);
    sums(&rule_err, &prop_err);
  }
  double value = 0;
  for (const Piece& p : pieces) value += p.value;
  return {value, rule_err + prop_err + 4e-16 * value};
}

// The row's grading of the adaptive E_avg rule for `slice`.
inline int EavgGrading(const BakerRow& row, const BakeSpec& slice) {
  return row.eavg_grading ? row.eavg_grading(slice) : 0;
}

// AdaptiveEavg over the row's texel at the roughness of `at` (mu varies),
// with the row's grading.
inline EavgEstimate AdaptiveEavgOf(const BakerRow& row, const BakeSpec& slice, const TexelAt& at) {
  return AdaptiveEavg(
      [&](double mu) {
        TexelAt m = at;
        m.mu = mu;
        return row.texel(slice, m, 0);
      },
      slice.tolerance, EavgGrading(row, slice));
}

// E and its error from an albedo rule's result.
inline TexelEstimate AlbedoTexel(const RuleResult& r) {
  TexelEstimate v;
  v.e = r.value;
  v.err_e = r.error;
  return v;
}

// brdfbake.integrator's description of a quadrature rule.
inline void Describe(nlohmann::json* j, const char* domain, const char* rule, const char* error_estimate) {
  (*j)["domain"] = domain;
  (*j)["rule"] = rule;
  (*j)["error_estimate"] = error_estimate;
}

// The mirror's entry of brdfbake.integrator (alpha below 1e-4: E = 1).
inline void MirrorJson(nlohmann::json* j) { (*j)["mirror"] = "alpha < 1e-4 is a mirror: E = 1"; }

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BAKE_FAMILY_ROW_H_
