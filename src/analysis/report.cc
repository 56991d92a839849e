// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "base/error.h"
#include "brdfbake/model.h"
#include "brdfbake/output_file.h"
#include "brdfbake/probe.h"
#include "rules/ggx_aniso/aniso_ggx.h"

namespace brdfbake {
namespace {

// Largest and RMS difference over every value channel (not "error").
void CompareTables(const Table& t, const Table& ref, double* max_err, double* rms) {
  double m = 0, s = 0;
  size_t n = 0;
  for (size_t c = 0; c < t.channels.size(); ++c) {
    if (t.channels[c].meaning == Meaning::kError) continue;
    for (size_t i = 0; i < t.channels[c].values.size(); ++i) {
      const double d = t.channels[c].values[i] - ref.channels[c].values[i];
      m = std::max(m, std::abs(d));
      s += d * d;
      ++n;
    }
  }
  *max_err = m;
  *rms = n ? std::sqrt(s / n) : 0.0;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string Num(double v, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof(buf), fmt, v);
  return buf;
}

// Interpolation error along the gamma axis: tables with 2 ... N gamma
// slices (mu and roughness as given), linear lookup between two slices at
// the gamma cell midpoints, against the quadrature at that gamma, at the
// (mu, roughness) nodes of the table (up to `probes` per axis).
InterpolationRow GammaInterpolation(const BakeSpec& base, int n, int probes) {
  BakeSpec s = base;
  s.gamma.size = n;
  const Table t = Bake(s);
  ProbeOptions o;
  o.probes = o.minor_probes = probes;
  o.stored = false;
  for (const Axis& a : t.axes) o.points.push_back(a.name == "gamma" ? ProbePoints::kMidpoints : ProbePoints::kNodes);
  const ProbeResult p = LookupError(t, o);
  InterpolationRow row;
  row.size = n;
  row.max_abs_error = row.max_abs_error_inner = p.max_abs_error;
  row.rms_error = p.rms_error;
  row.probes = int(p.probes);
  row.bake_seconds = t.seconds;
  return row;
}

}  // namespace

double CollapsedAlpha(const std::string& collapse, double at, double ab, double phi) {
  // Cycles uses sqrt(sqrt(alpha_t alpha_b)) as roughness, MaterialX and
  // Enterprise PBR the geometric mean: both are alpha = sqrt(alpha_t alpha_b).
  if (collapse == "geometric-mean") return std::sqrt(at * ab);
  if (collapse == "arithmetic-mean") return 0.5 * (at + ab);
  if (collapse != "view-projected") throw std::invalid_argument("unknown collapse '" + collapse + "'");
  // The width the view sees: Lambda(wo) of the anisotropic GGX equals the
  // isotropic one at this alpha, so G1(wo) is exact.
  const double c = std::cos(phi), s = std::sin(phi);
  return std::sqrt(at * at * c * c + ab * ab * s * s);
}

std::vector<CollapseRow> CollapseStudy(const BakeSpec& spec, const std::vector<std::string>& collapses,
                                       const ReportLog& say) {
  const bool eavg = spec.table == TableKind::kEavg;
  const int nm = eavg ? 1 : spec.mu.size, np = eavg ? 1 : spec.phi.size, nr = spec.roughness.size;
  const int nc = int(collapses.size());
  for (const std::string& c : collapses) {
    CollapsedAlpha(c, 1, 1, 0);  // a known name
    if (eavg && c == "view-projected") throw std::invalid_argument("E_avg has no view to project onto");
  }
  std::vector<CollapseRow> rows;
  for (int ys = 0; ys < spec.anisotropy.size; ++ys) {
    const double s = spec.anisotropy.Value(ys);
    // True E (or E_avg) and the collapsed values at every (mu, phi_o, r),
    // in parallel; the reduction is serial (thread-count independent).
    std::vector<double> truth(size_t(nm) * np * nr), iso(truth.size() * nc);
    tbb::parallel_for(0, nm * np * nr, [&](int k) {
      const int x = k % nm, yp = (k / nm) % np, yr = k / (nm * np);
      const double r = std::max(spec.roughness.Value(yr), spec.roughness.clamp_min);
      const double mu = eavg ? 1.0 : std::max(spec.mu.Value(x), spec.mu.clamp_min);
      const double phi = eavg ? 0.0 : spec.phi.Value(yp);
      truth[k] = std::clamp(eavg ? IntegrateAnisoEavg(spec, r, s).value : IntegrateAnisoTexel(spec, r, s, mu, phi).e,
                            0.0, 1.0);
      BakeSpec g;
      g.masking = spec.masking;
      g.tolerance = spec.tolerance;
      const double at = AnisotropyAlphaT(r, s), ab = r * r;
      for (int c = 0; c < nc; ++c) {
        const double alpha = CollapsedAlpha(collapses[size_t(c)], at, ab, phi);
        const double v = eavg ? IntegrateEavg(g, std::sqrt(alpha)).value : IntegrateTexel(g, std::sqrt(alpha), mu).e;
        iso[size_t(k) * nc + c] = std::clamp(v, 0.0, 1.0);
      }
    });
    for (int c = 0; c < nc; ++c) {
      CollapseRow row;
      row.anisotropy = s;
      row.collapse = collapses[size_t(c)];
      double sum2 = 0;
      for (size_t k = 0; k < truth.size(); ++k) {
        const double d = std::abs(iso[k * nc + c] - truth[k]);
        sum2 += d * d;
        if (d > row.max_abs_error) {
          row.max_abs_error = d;
          row.worst_roughness = spec.roughness.Value(int(k) / (nm * np));
          row.worst_mu = eavg ? 0.0 : spec.mu.Value(int(k) % nm);
          row.worst_phi = eavg ? 0.0 : spec.phi.Value((int(k) / nm) % np);
        }
      }
      row.rms_error = truth.empty() ? 0 : std::sqrt(sum2 / truth.size());
      if (say) {
        say("anisotropy " + Num(s, "%.3g") + ", " + row.collapse + ": max error " +
            Num(row.max_abs_error, "%.2e") + " (r " + Num(row.worst_roughness, "%.3g") + ", mu " +
            Num(row.worst_mu, "%.3g") + ", phi_o " + Num(row.worst_phi * 180 / kPi<double>, "%.3g") +
            " deg), rms " + Num(row.rms_error, "%.2e"));
      }
      rows.push_back(row);
    }
  }
  return rows;
}

namespace {

// The converged reference of the report's table.
Table ReferenceTable(const ReportSpec& spec, const ReportLog& say) {
  BakeSpec ref_spec = spec.table;
  ref_spec.integrator = IntegratorKind::kQuadrature;
  ref_spec.tolerance = spec.reference_tolerance;
  ref_spec.samples = 2048;
  ref_spec.error_channel = false;
  ref_spec.complement = false;
  say("reference: quadrature, tolerance " + Num(spec.reference_tolerance));
  return Bake(ref_spec);
}

// Each integrator along its ladder of budgets: median time of the repeats,
// error against the reference, and the error it claims.
std::vector<ReportRow> BudgetLadders(const ReportSpec& spec, const Table& ref,
                                     const ReportLog& say) {
  std::vector<ReportRow> rows;
  struct Ladder {
    IntegratorKind kind;
    const char* budget_name;
    std::vector<double> budgets;
  };
  const std::vector<Ladder> ladders = {
      {IntegratorKind::kQuadrature, "tolerance", {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}},
      {IntegratorKind::kQmc, "samples", {64, 256, 1024, 4096, 16384}},
      {IntegratorKind::kMc, "samples", {64, 256, 1024, 4096, 16384}},
      {IntegratorKind::kEngine, "samples", {64, 256, 1024, 4096}},
  };
  const std::vector<IntegratorKind> allowed = TableIntegrators(spec.table);
  for (const Ladder& ladder : ladders) {
    if (std::find(allowed.begin(), allowed.end(), ladder.kind) == allowed.end()) continue;
    for (double budget : ladder.budgets) {
      BakeSpec s = spec.table;
      s.integrator = ladder.kind;
      s.error_channel = false;
      s.complement = false;
      if (ladder.kind == IntegratorKind::kQuadrature) {
        s.tolerance = budget;
        s.samples = 0;
      } else {
        s.samples = static_cast<int>(budget);
      }
      // Timed runs: the engine's error measurement (a quadrature) is not part
      // of what an engine bake costs, so it is timed without it.
      s.estimate_error = ladder.kind != IntegratorKind::kEngine;
      std::vector<double> times;
      Table t;
      for (int r = 0; r < spec.repeats; ++r) {
        t = Bake(s);
        times.push_back(t.seconds);
      }
      ReportRow row;
      row.integrator = IntegratorName(ladder.kind);
      row.budget_name = ladder.budget_name;
      row.budget = budget;
      row.seconds_median = Median(times);
      row.seconds_min = *std::min_element(times.begin(), times.end());
      CompareTables(t, ref, &row.max_abs_error, &row.rms_error);
      if (ladder.kind == IntegratorKind::kEngine) {
        s.estimate_error = true;
        row.claimed_max_error = Bake(s).integration_error;
      } else {
        row.claimed_max_error = t.integration_error;
      }
      say(row.integrator + " " + row.budget_name + "=" + Num(budget) + ": " +
          Num(row.seconds_median, "%.3g") + " s, max error " + Num(row.max_abs_error, "%.2e") +
          " (claimed " + Num(row.claimed_max_error, "%.2e") + ")");
      rows.push_back(row);
    }
  }

  return rows;
}

// Interpolation error of bilinear (or linear, for E_avg) lookup at cell
// midpoints of an n-entry table, against the converged integrator at those
// points; false if the table has no interior cell to probe.
bool PlaneInterpolation(const BakeSpec& s_in, int n, int interpolation_probes,
                        InterpolationRow* out) {
  BakeSpec s = s_in;
  const bool one_d = s.table == TableKind::kEavg;
  s.roughness.size = n;
  if (!one_d) s.mu.size = n;
  if (s.Glass()) s.ior.size = n;  // n entries on every axis: an n^3 cube (E_avg n^2)
  if (n < 2) return false;  // no cell to probe
  const Table t = Bake(s);
  ProbeOptions o;
  o.points.assign(t.axes.size(), ProbePoints::kMidpoints);
  o.probes = interpolation_probes;
  o.stored = false;
  const ProbeResult p = LookupError(t, o);
  InterpolationRow& row = *out;
  row.size = n;
  row.max_abs_error = p.max_abs_error;
  row.max_abs_error_inner = p.max_abs_error_inner;
  row.rms_error = p.rms_error;
  row.probes = int(p.probes);
  row.bake_seconds = t.seconds;
  return true;
}

}  // namespace

void ValidateReportSpec(const ReportSpec& spec) {
  ValidateBakeSpec(spec.table);
  if (spec.repeats < 1 || spec.repeats > 100) {
    Bad("{repeats} must be in [1, 100]");
  }
  // The interpolation study probes the table over all its axes (gamma and
  // ior slices too); a table with an axis of its own the probe does not
  // know (gen_schlick's exponent or ior) and the quadrature alone has
  // neither study to show.
  const std::vector<Axis> axes = ShapeOf(spec.table).axes;
  if (!axes.empty() && ParameterAxis(axes.back()) && !ProbeSupports(spec.table) &&
      TableIntegrators(spec.table).size() == 1) {
    throw std::invalid_argument(std::string("report: ") +
                                (spec.table.Glass() ? "ggx-glass" : TableName(spec.table.table)) +
                                " has one integrator (the quadrature) and an axis over " + axes.back().name +
                                " the report does not interpolate; its claims are checked by the tests against "
                                "independent integration");
  }
}

Report RunReport(const ReportSpec& spec, const ReportLog& log) {
  ValidateReportSpec(spec);
  const ReportLog say = [&](const std::string& s) {
    if (log) log(s);
  };
  Report report;
  report.spec = spec;
  if (spec.table.Anisotropic()) {
    if (spec.table.table != TableKind::kE) {
      Bad("report: ggx-aniso reports the collapse study of E ({table} E)");
    }
    report.collapse = CollapseStudy(spec.table, {"geometric-mean", "arithmetic-mean", "view-projected"}, say);
    return report;
  }
  const Table ref = ReferenceTable(spec, say);
  report.reference_seconds = ref.seconds;
  report.reference_claimed_error = ref.integration_error;
  report.rows = BudgetLadders(spec, ref, say);
  // The interpolation study probes tables over mu x roughness (and gamma
  // or ior slices) against their exact values: those ProbeSupports knows.
  // The slope-plane tables (sel_norm over alpha_x x alpha_y, the ellipsoid
  // over mu x phi_o, its E_avg one value) have the ladder alone.
  const bool plane = ProbeSupports(spec.table);
  if (!plane) say("no interpolation study: the table's axes are not mu x roughness");
  // With a gamma axis, the error of linear lookup between gamma slices.
  for (int n : plane ? spec.interpolation_sizes : std::vector<int>{}) {
    BakeSpec s = spec.table;
    s.integrator = IntegratorKind::kQuadrature;
    s.tolerance = std::min(s.tolerance, 1e-8);
    s.samples = 0;
    s.error_channel = false;
    s.complement = false;
    InterpolationRow row;
    if (spec.table.HasGammaAxis()) {
      if (n < 2) continue;
      row = GammaInterpolation(s, n, spec.interpolation_probes);
      say("interpolation along gamma, " + std::to_string(n) + " slices: max error " +
          Num(row.max_abs_error, "%.2e"));
    } else {
      if (!PlaneInterpolation(s, n, spec.interpolation_probes, &row)) continue;
      say("interpolation " + std::to_string(n) + ": max error " + Num(row.max_abs_error, "%.2e"));
    }
    report.interpolation.push_back(row);
  }
  return report;
}

std::string LogLogSvg(const std::string& title, const std::string& x_label,
                      const std::string& y_label, const std::vector<Series>& series,
                      const std::string& footnote) {
  const double W = 940, H = 620, left = 90, right = 260, top = 60, bottom = 105;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const Series& s : series) {
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!(s.x[i] > 0) || !(s.y[i] > 0)) continue;
      xmin = std::min(xmin, s.x[i]);
      xmax = std::max(xmax, s.x[i]);
      ymin = std::min(ymin, s.y[i]);
      ymax = std::max(ymax, s.y[i]);
    }
  }
  if (xmin > xmax) xmin = 1, xmax = 10, ymin = 1, ymax = 10;
  const double lx0 = std::floor(std::log10(xmin)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(xmax)));
  const double ly0 = std::floor(std::log10(ymin)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(ymax)));
  const double pw = W - left - right, ph = H - top - bottom;
  auto X = [&](double x) { return left + pw * (std::log10(x) - lx0) / (lx1 - lx0); };
  auto Y = [&](double y) { return top + ph * (1 - (std::log10(y) - ly0) / (ly1 - ly0)); };
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << W / 2 << "\" y=\"30\" text-anchor=\"middle\" font-size=\"17\">" << title
    << "</text>\n";
  // Grid and ticks at decades (and 2, 5 within a decade as light lines).
  for (double d = lx0; d <= lx1 + 1e-9; d += 1) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (std::log10(v) > lx1 + 1e-9) break;
      const double x = X(v);
      o << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + ph
        << "\" stroke=\"" << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
      if (m == 1) {
        o << "<text x=\"" << x << "\" y=\"" << top + ph + 20 << "\" text-anchor=\"middle\">1e"
          << static_cast<int>(d) << "</text>\n";
      }
    }
  }
  for (double d = ly0; d <= ly1 + 1e-9; d += 1) {
    const double y = Y(std::pow(10.0, d));
    o << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y
      << "\" stroke=\"#bbb\"/>\n";
    o << "<text x=\"" << left - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e"
      << static_cast<int>(d) << "</text>\n";
  }
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"black\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << top + ph + 45
    << "\" text-anchor=\"middle\" font-size=\"15\">" << x_label << "</text>\n";
  o << "<text transform=\"translate(25," << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"15\">" << y_label << "</text>\n";
  static const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"};
  for (size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    const char* color = kColors[k % 6];
    std::ostringstream pts;
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!(s.x[i] > 0) || !(s.y[i] > 0)) continue;
      pts << X(s.x[i]) << "," << Y(s.y[i]) << " ";
      o << "<circle cx=\"" << X(s.x[i]) << "\" cy=\"" << Y(s.y[i]) << "\" r=\"4\" fill=\"" << color
        << "\"/>\n";
    }
    o << "<polyline points=\"" << pts.str() << "\" fill=\"none\" stroke=\"" << color
      << "\" stroke-width=\"2\"/>\n";
    const double ly = top + 20 + 24 * k;
    o << "<line x1=\"" << left + pw + 15 << "\" y1=\"" << ly << "\" x2=\"" << left + pw + 45
      << "\" y2=\"" << ly << "\" stroke=\"" << color << "\" stroke-width=\"3\"/>\n";
    o << "<text x=\"" << left + pw + 52 << "\" y=\"" << ly + 4 << "\">" << s.name << "</text>\n";
  }
  // Footnote, wrapped at '; '.
  std::vector<std::string> lines;
  {
    std::string rest = footnote;
    size_t cut;
    while (rest.size() > 110 && (cut = rest.rfind("; ", 110)) != std::string::npos) {
      lines.push_back(rest.substr(0, cut + 1));
      rest = rest.substr(cut + 2);
    }
    lines.push_back(rest);
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    o << "<text x=\"" << left << "\" y=\"" << H - 12 - 15 * (lines.size() - 1 - i)
      << "\" font-size=\"11\" fill=\"#444\">" << lines[i] << "</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

namespace {

// All or nothing: every file is written to its temporary first, and the
// set is committed together (CommitAll).
void WriteFiles(const std::vector<std::pair<std::string, std::string>>& files,
                const std::string& dir) {
  std::vector<std::unique_ptr<AtomicFile>> out;
  std::vector<AtomicFile*> set;
  for (const auto& f : files) {
    out.push_back(std::make_unique<AtomicFile>(dir + "/" + f.first));
    out.back()->Append(f.second);
    set.push_back(out.back().get());
  }
  CommitAll(set);
}

void WriteCollapse(const Report& report, const std::string& dir) {
  const BakeSpec& t = report.spec.table;
  std::ostringstream csv;
  csv << "anisotropy,collapse,max_abs_error,rms_error,worst_roughness,worst_mu,worst_phi_o_deg\n";
  std::vector<Series> series;
  for (const CollapseRow& r : report.collapse) {
    csv << Num(r.anisotropy) << "," << r.collapse << "," << Num(r.max_abs_error) << ","
        << Num(r.rms_error) << "," << Num(r.worst_roughness) << "," << Num(r.worst_mu) << ","
        << Num(r.worst_phi * 180 / kPi<double>) << "\n";
    if (!(r.anisotropy > 0)) continue;  // log axes: s = 0 has no error
    Series* s = nullptr;
    for (Series& x : series) {
      if (x.name == r.collapse) s = &x;
    }
    if (!s) {
      series.push_back({r.collapse, {}, {}});
      s = &series.back();
    }
    s->x.push_back(r.anisotropy);
    s->y.push_back(std::max(r.max_abs_error, 1e-12));
  }
  const std::string footnote =
      "max |E_iso(collapsed alpha) - E_aniso| over mu " + Num(t.mu.min) + ".." + Num(t.mu.max) +
      " (" + std::to_string(t.mu.size) + "), phi_o 0..90 deg (" + std::to_string(t.phi.size) +
      "), roughness " + Num(t.roughness.min) + ".." + Num(t.roughness.max) + " (" +
      std::to_string(t.roughness.size) + "); exact isotropic E, no table lookup";
  WriteFiles({{"collapse.csv", csv.str()},
              {"collapse.svg",
               LogLogSvg("ggx-aniso E (" + std::string(MaskingName(t.masking)) +
                             "): the cost of one isotropic width",
                         "anisotropy strength s (KHR_materials_anisotropy)", "max abs error of E",
                         series, footnote)}},
             dir);
}

}  // namespace

void WriteReport(const Report& report, const std::string& dir) {
  const BakeSpec& t = report.spec.table;
  if (t.Anisotropic()) {
    WriteCollapse(report, dir);
    return;
  }
  std::ostringstream csv;
  csv << "integrator,budget_name,budget,seconds_median,seconds_min,max_abs_error,rms_error,"
         "claimed_max_error\n";
  for (const ReportRow& r : report.rows) {
    csv << r.integrator << "," << r.budget_name << "," << Num(r.budget) << ","
        << Num(r.seconds_median) << "," << Num(r.seconds_min) << "," << Num(r.max_abs_error)
        << "," << Num(r.rms_error) << "," << Num(r.claimed_max_error) << "\n";
  }
  std::string what = std::string(TableName(t.table)) + " " + t.model.name();
  const bool gamma_axis = t.HasGammaAxis();
  if (ModelTakes(t.model.kind, ModelOption::kGamma) && !gamma_axis) what += " gamma=" + Num(t.model.gamma);
  std::string size = t.table == TableKind::kEavg
                         ? std::to_string(t.roughness.size)
                         : std::to_string(t.mu.size) + "x" + std::to_string(t.roughness.size);
  if (gamma_axis) size += "x" + std::to_string(t.gamma.size) + " (gamma " + Num(t.gamma.min) + " to " + Num(t.gamma.max) + ")";
  const std::string footnote =
      "error: max |value - reference| over all texels; reference: quadrature at tolerance " +
      Num(report.spec.reference_tolerance) + " (its own estimate " +
      Num(report.reference_claimed_error, "%.1e") + "); time: median of " +
      std::to_string(report.spec.repeats) + " bakes, all cores";
  std::vector<Series> series;
  for (const ReportRow& r : report.rows) {
    if (series.empty() || series.back().name.rfind(r.integrator, 0) != 0) {
      std::string label = r.integrator;
      if (r.integrator == "engine") label = "engine (NDF, Hammersley)";
      if (r.integrator == "qmc") label = "qmc (VNDF)";
      if (r.integrator == "mc") label = "mc (VNDF)";
      series.push_back({label, {}, {}});
    }
    series.back().x.push_back(r.seconds_median);
    series.back().y.push_back(std::max(r.max_abs_error, 1e-12));
  }
  const std::string title = what + " " + size + " (" + MaskingName(t.masking) +
                            "): max error against bake time";
  std::ostringstream icsv;
  icsv << (gamma_axis ? "gamma_slices" : "size") << ",max_abs_error,max_abs_error_without_first_mu_cell,rms_error,probes,bake_seconds\n";
  Series interp{"all cells", {}, {}};
  Series interp_inner{"without the first mu cell", {}, {}};
  for (const InterpolationRow& r : report.interpolation) {
    icsv << r.size << "," << Num(r.max_abs_error) << "," << Num(r.max_abs_error_inner) << ","
         << Num(r.rms_error) << "," << r.probes << "," << Num(r.bake_seconds) << "\n";
    interp.x.push_back(r.size);
    interp.y.push_back(std::max(r.max_abs_error, 1e-12));
    interp_inner.x.push_back(r.size);
    interp_inner.y.push_back(std::max(r.max_abs_error_inner, 1e-12));
  }
  const std::vector<std::pair<std::string, std::string>> files = {
      {"report.csv", csv.str()},
      {"report.svg", LogLogSvg(title, "bake time (s)", "max abs error", series, footnote)},
      {"interpolation.csv", icsv.str()},
      {"interpolation.svg",
       gamma_axis
           ? LogLogSvg(what + " " + size + ": error of linear lookup between gamma slices",
                       "gamma slices", "max abs error", {interp},
                       std::string("placement ") + PlacementName(t.gamma.placement) +
                           ", warp gamma tail; exact values from the quadrature at the gamma cell "
                           "midpoints, at the table's mu and roughness nodes")
           : LogLogSvg(what + ": error of " + (t.table == TableKind::kEavg ? "linear" : "bilinear") +
                           " lookup against table size",
                       "entries per axis", "max abs error",
                       t.table == TableKind::kEavg ? std::vector<Series>{interp}
                                                   : std::vector<Series>{interp, interp_inner},
                       std::string("placement ") + PlacementName(t.roughness.placement) +
                           ", warp mu " + WarpName(t.mu.warp) + ", roughness " +
                           WarpName(t.roughness.warp) +
                           "; exact values from the quadrature at cell midpoints")}};
  WriteFiles(files, dir);
}

}  // namespace brdfbake
