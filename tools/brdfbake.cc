// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The brdfbake command-line tool: parses arguments, calls the library,
// prints. No math here.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <chrono>
#include <filesystem>
#include <mutex>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/eval.h"
#include "brdfbake/grid.h"
#include "brdfbake/model.h"
#include "brdfbake/report.h"
#include "brdfbake/stability.h"
#include "brdfbake/targets.h"
#include "brdfbake/version.h"

namespace {

using brdfbake::EvalRequest;
using brdfbake::Fresnel;
using brdfbake::FresnelKind;
using brdfbake::Masking;

double ParseNumber(const std::string& opt, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || std::isnan(v)) {
    throw std::invalid_argument(opt + ": '" + text + "' is not a number");
  }
  return v;
}

std::array<double, 3> ParseRgb(const std::string& opt, const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(ParseNumber(opt, item));
  if (v.size() == 1) return {v[0], v[0], v[0]};
  if (v.size() != 3) throw std::invalid_argument(opt + ": expected one value or three (r,g,b), got '" + text + "'");
  return {v[0], v[1], v[2]};
}

std::vector<std::string> SplitComma(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

// Options shared by every command that names a model.
struct ModelOptions {
  std::string model = "ggx";
  std::string alpha, alpha_x, alpha_y, roughness;
  std::string gamma = "2";
  double theta_x_deg = 0, theta_y_deg = 0, theta_z_deg = 0;

  void Add(CLI::App* app) {
    app->add_option("--model,-m", model, "ggx | beckmann | std | ellipsoid | sel")
        ->capture_default_str();
    app->add_option("--alpha", alpha, "NDF width alpha (both axes); default 0.25");
    app->add_option("--alpha-x", alpha_x, "alpha along the tangent");
    app->add_option("--alpha-y", alpha_y, "alpha along the bitangent");
    app->add_option("--roughness,-r", roughness, "perceptual roughness r, alpha = r^2 (both axes)");
    app->add_option("--gamma", gamma, "std: tail parameter in (1.5, inf]; 'inf' is Beckmann")
        ->capture_default_str();
    app->add_option("--theta-x", theta_x_deg, "ellipsoid/sel: rotation about x, degrees");
    app->add_option("--theta-y", theta_y_deg, "ellipsoid/sel: rotation about y, degrees");
    app->add_option("--theta-z", theta_z_deg, "ellipsoid/sel: rotation about z, degrees");
  }

  brdfbake::ModelParams Get() const {
    brdfbake::ModelParams p;
    p.name = model;
    double a = 0.25;
    int given = !alpha.empty() + !roughness.empty();
    if (given > 1) throw std::invalid_argument("--alpha and --roughness are exclusive");
    if (!alpha.empty()) a = ParseNumber("--alpha", alpha);
    if (!roughness.empty()) {
      const double r = ParseNumber("--roughness", roughness);
      if (!(r > 0) || !std::isfinite(r)) throw std::invalid_argument("--roughness must be a finite number > 0");
      a = r * r;
    }
    p.alpha_x = alpha_x.empty() ? a : ParseNumber("--alpha-x", alpha_x);
    p.alpha_y = alpha_y.empty() ? a : ParseNumber("--alpha-y", alpha_y);
    p.gamma = ParseNumber("--gamma", gamma);
    const double deg = 3.14159265358979323846 / 180.0;
    p.theta_x = theta_x_deg * deg;
    p.theta_y = theta_y_deg * deg;
    p.theta_z = theta_z_deg * deg;
    brdfbake::ValidateModelParams(p);
    return p;
  }
};

struct FresnelOptions {
  std::string kind = "one";
  std::string f0 = "0.04", n = "0.2,0.92,1.1", k = "3.9,2.45,2.14";
  std::string eta = "1.5";

  void Add(CLI::App* app) {
    app->add_option("--fresnel", kind, "one | schlick | dielectric | conductor")->capture_default_str();
    app->add_option("--f0", f0, "schlick: F0, one value or r,g,b")->capture_default_str();
    app->add_option("--eta", eta, "dielectric: relative index of refraction")->capture_default_str();
    app->add_option("--n", n, "conductor: real part of the index, r,g,b")->capture_default_str();
    app->add_option("--k", k, "conductor: imaginary part of the index, r,g,b")->capture_default_str();
  }

  Fresnel Get() const {
    if (kind == "one") return Fresnel::One();
    if (kind == "schlick") return Fresnel::Schlick(ParseRgb("--f0", f0));
    if (kind == "dielectric") return Fresnel::Dielectric(ParseNumber("--eta", eta));
    if (kind == "conductor") return Fresnel::Conductor(ParseRgb("--n", n), ParseRgb("--k", k));
    throw std::invalid_argument("--fresnel: unknown model '" + kind +
                                "' (expected one, schlick, dielectric or conductor)");
  }
};

Masking ParseMasking(const std::string& s) {
  if (s == "height-correlated") return Masking::kHeightCorrelated;
  if (s == "separable") return Masking::kSeparable;
  throw std::invalid_argument("--masking: unknown variant '" + s +
                              "' (expected height-correlated or separable)");
}

std::string VersionText() {
  std::string s = std::string("brdfbake ") + BRDFBAKE_VERSION + "\nSIMD target in use: " +
                  brdfbake::BestTarget() + "\ncompiled targets:";
  for (const std::string& t : brdfbake::CompiledTargets()) s += " " + t;
  return s;
}

std::string ModelsHelp() {
  std::string s = "Models:\n";
  for (const brdfbake::ModelInfo& m : brdfbake::Models()) {
    s += std::string("  ") + m.name + ": " + m.parameters + "\n      " + m.source + "\n";
  }
  s += "Quantities (--quantity, comma-separated):\n"
       "  D, pdf      swept direction is the microfacet normal m (pdf: density of the\n"
       "              model's visible-normal sampler for the view wo, per steradian)\n"
       "  Lambda, G1  swept direction is w\n"
       "  G2, brdf    swept direction is the light wi; the view wo is fixed by --mu-o, --phi-o\n"
       "  K           swept direction is w (model sel only)\n";
  return s;
}

struct BakeOptions {
  std::string table, model = "ggx", gamma = "2", size = "32x32", warp = "linear";
  std::string placement = "edges", masking = "height-correlated", integrator = "quadrature";
  std::string pixel = "float", output;
  int samples = 0, threads = 0;
  double tolerance = brdfbake::BakeSpec().tolerance;
  uint64_t seed = 1;
  bool complement = false, error_channel = false;

  void Add(CLI::App* app, bool for_report = false) {
    app->add_option("--table,-t", table, "E | E_avg | dfg")->required();
    app->add_option("--model,-m", model, "ggx | beckmann | std")->capture_default_str();
    app->add_option("--gamma", gamma, "std: tail parameter in (1.5, inf]")->capture_default_str();
    app->add_option("--size", size, "mu x roughness entries, e.g. 32x32 (E_avg: roughness entries)")
        ->capture_default_str();
    app->add_option("--warp", warp, "linear | square | sqrt, or per axis: mu=linear,roughness=square")
        ->capture_default_str();
    app->add_option("--placement", placement, "edges | centers (texel centres for GPU bilinear)")
        ->capture_default_str();
    app->add_option("--masking", masking, "height-correlated | separable")->capture_default_str();
    app->add_option("--threads", threads, "worker threads; 0 = all cores")->capture_default_str();
    app->add_option("--seed", seed, "seed of the randomized integrators")->capture_default_str();
    if (for_report) {
      app->add_option("-o,--output", output, "output directory (created if missing)")->required();
      return;
    }
    app->add_option("--integrator", integrator, "quadrature | qmc | mc | engine")->capture_default_str();
    app->add_option("--samples", samples, "max nodes per dimension (quadrature) or samples per texel; 0 = default");
    app->add_option("--tolerance", tolerance, "quadrature: refine until two rules agree to this")
        ->capture_default_str();
    app->add_option("--pixel", pixel, "float | half")->capture_default_str();
    app->add_flag("--complement", complement, "store 1-E instead of E (E table)");
    app->add_flag("--error-channel", error_channel, "add a per-texel 'error' channel");
    app->add_option("-o,--output", output, "output .exr file")->required();
  }

  brdfbake::BakeSpec Get() const {
    brdfbake::BakeSpec spec;
    spec.table = brdfbake::ParseTable(table);
    spec.model.name = model;
    spec.model.gamma = ParseNumber("--gamma", gamma);
    spec.masking = ParseMasking(masking);
    spec.integrator = brdfbake::ParseIntegrator(integrator);
    spec.samples = samples;
    spec.tolerance = tolerance;
    spec.seed = seed;
    spec.complement = complement;
    spec.error_channel = error_channel;
    spec.threads = threads;
    if (pixel != "float" && pixel != "half") {
      throw std::invalid_argument("--pixel: expected float or half, got '" + pixel + "'");
    }
    spec.half = pixel == "half";
    // Size: WxH for 2D tables, N for E_avg.
    auto parse_int = [](const std::string& opt, const std::string& text) {
      const double v = ParseNumber(opt, text);
      if (v != std::floor(v) || v < 1 || v > 8192) {
        throw std::invalid_argument(opt + ": '" + text + "' is not an integer in [1, 8192]");
      }
      return static_cast<int>(v);
    };
    const size_t x = size.find('x');
    if (spec.table == brdfbake::TableKind::kEavg) {
      spec.roughness.size = parse_int("--size", x == std::string::npos ? size : size.substr(x + 1));
    } else {
      if (x == std::string::npos) throw std::invalid_argument("--size: expected WxH, got '" + size + "'");
      spec.mu.size = parse_int("--size", size.substr(0, x));
      spec.roughness.size = parse_int("--size", size.substr(x + 1));
    }
    const brdfbake::Placement pl = brdfbake::ParsePlacement(placement);
    spec.mu.placement = spec.roughness.placement = pl;
    for (const std::string& item : SplitComma(warp)) {
      const size_t eq = item.find('=');
      if (eq == std::string::npos) {
        spec.mu.warp = spec.roughness.warp = brdfbake::ParseWarp(item);
      } else if (item.substr(0, eq) == "mu") {
        spec.mu.warp = brdfbake::ParseWarp(item.substr(eq + 1));
      } else if (item.substr(0, eq) == "roughness") {
        spec.roughness.warp = brdfbake::ParseWarp(item.substr(eq + 1));
      } else {
        throw std::invalid_argument("--warp: unknown axis '" + item.substr(0, eq) +
                                    "' (expected mu or roughness)");
      }
    }
    if (output.empty()) throw std::invalid_argument("-o: an output file is required");
    brdfbake::ValidateBakeSpec(spec);
    return spec;
  }
};

// A progress bar on stderr when it is a terminal and the bake has taken
// more than a second.
class Progress {
 public:
  Progress() : tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  void operator()(int64_t done, int64_t total) {
    if (!tty_) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < 1.0) return;
    std::lock_guard<std::mutex> lock(mu_);
    if (done < total && std::chrono::duration<double>(now - last_).count() < 0.1) return;
    last_ = now;
    const int width = 40;
    const int filled = static_cast<int>(width * done / std::max<int64_t>(1, total));
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %.1fs", filled, "========================================",
                 width - filled, "", static_cast<int>(100 * done / std::max<int64_t>(1, total)),
                 elapsed);
    shown_ = true;
  }
  void Finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  bool tty_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mu_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brdfbake: microfacet BRDF models and the lookup tables real-time engines sample."};
  app.set_version_flag("--version", VersionText());
  app.require_subcommand(1);

  CLI::App* eval = app.add_subcommand(
      "eval", "Evaluate a model's D, Lambda, G1, G2, BRDF or pdf along a sweep, as CSV on stdout.");
  eval->footer(ModelsHelp());
  ModelOptions model_opts;
  model_opts.Add(eval);
  FresnelOptions fresnel_opts;
  fresnel_opts.Add(eval);
  std::string quantity = "D", masking = "height-correlated", sweep = "mu";
  EvalRequest req;
  double phi_deg = 0, phi_o_deg = 0;
  eval->add_option("--quantity,-q", quantity, "D, Lambda, G1, G2, brdf, pdf, K (comma-separated)")
      ->capture_default_str();
  eval->add_option("--masking", masking, "height-correlated | separable")->capture_default_str();
  eval->add_option("--sweep", sweep, "mu (cos theta) or theta (degrees)")->capture_default_str();
  eval->add_option("--from", req.from, "first value of the sweep")->capture_default_str();
  eval->add_option("--to", req.to, "last value of the sweep")->capture_default_str();
  eval->add_option("--count,-n", req.count, "number of samples")->capture_default_str();
  eval->add_option("--phi", phi_deg, "azimuth of the swept direction, degrees")->capture_default_str();
  eval->add_option("--mu-o", req.mu_o, "cos(theta) of the view wo (G2, brdf, pdf)")->capture_default_str();
  eval->add_option("--phi-o", phi_o_deg, "azimuth of the view wo, degrees")->capture_default_str();
  std::string grid_kind, grid_out, target = "best";
  int grid_w = 256, grid_h = 256, grid_threads = 0;
  eval->add_option("--grid", grid_kind,
                   "evaluate a grid to EXR instead of a sweep: slice (theta_h x theta_d BRDF), "
                   "hemisphere (f cos over wi for the view --mu-o/--phi-o), g1 (mu x roughness)");
  eval->add_option("--width", grid_w, "grid width")->capture_default_str();
  eval->add_option("--height", grid_h, "grid height")->capture_default_str();
  eval->add_option("--threads", grid_threads, "grid: worker threads; 0 = all cores")->capture_default_str();
  eval->add_option("-o,--output", grid_out, "grid: output .exr file");
  eval->add_option("--target", target, "force a SIMD target (AVX3, AVX2, SSE4, SSSE3, SCALAR, or best)")
      ->capture_default_str();

  CLI::App* bake = app.add_subcommand(
      "bake", "Bake a lookup table (E, E_avg or dfg) to a self-describing OpenEXR file.");
  BakeOptions bake_opts;
  bake_opts.Add(bake);

  CLI::App* report = app.add_subcommand(
      "report", "Error against run time of every integrator over a ladder of budgets, and the "
                "interpolation error against table size: CSV and SVG plots in a directory.");
  BakeOptions report_opts;
  report_opts.size = "16x16";
  report_opts.Add(report, true);
  int repeats = 3;
  double reference_tolerance = 1e-11;
  report->add_option("--repeats", repeats, "timing: median of this many bakes")->capture_default_str();
  report->add_option("--reference-tolerance", reference_tolerance,
                     "tolerance of the converged quadrature used as the reference")
      ->capture_default_str();

  CLI::App* stability = app.add_subcommand(
      "stability", "Float kernels against the double reference, region by region over the "
                   "documented domain: max relative error and non-finite count, as CSV.");
  int stability_samples = 20000;
  uint64_t stability_seed = 1;
  stability->add_option("--samples", stability_samples, "samples per region and model")
      ->capture_default_str();
  stability->add_option("--seed", stability_seed, "seed")->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (char& c : msg) if (c == '\n') c = ' ';
    std::fprintf(stderr, "brdfbake: error: %s (see brdfbake --help)\n", msg.c_str());
    return 2;
  }

  try {
    if (*bake) {
      const brdfbake::BakeSpec spec = bake_opts.Get();
      Progress progress;
      const brdfbake::Table table =
          brdfbake::Bake(spec, [&](int64_t d, int64_t t) { progress(d, t); });
      progress.Finish();
      brdfbake::WriteExr(table, bake_opts.output);
      std::printf("wrote %s: %s %s %dx%d, %s integrator, baked in %.3f s, max abs error %.2e\n",
                  bake_opts.output.c_str(), brdfbake::TableName(spec.table), spec.model.name.c_str(),
                  table.width, table.height, brdfbake::IntegratorName(spec.integrator),
                  table.seconds, table.max_abs_error);
    }
    if (*report) {
      brdfbake::ReportSpec rs;
      rs.table = report_opts.Get();
      rs.repeats = repeats;
      if (!(reference_tolerance > 0) || !std::isfinite(reference_tolerance)) {
        throw std::invalid_argument("--reference-tolerance must be a finite number > 0");
      }
      rs.reference_tolerance = reference_tolerance;
      if (rs.repeats < 1 || rs.repeats > 100) throw std::invalid_argument("--repeats must be in [1, 100]");
      std::error_code ec;
      std::filesystem::create_directories(report_opts.output, ec);
      if (ec || !std::filesystem::is_directory(report_opts.output)) {
        throw std::invalid_argument("-o: cannot create directory '" + report_opts.output + "'");
      }
      const brdfbake::Report r = brdfbake::RunReport(
          rs, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
      brdfbake::WriteReport(r, report_opts.output);
      std::printf("wrote %s/report.csv, report.svg, interpolation.csv, interpolation.svg\n",
                  report_opts.output.c_str());
    }
    if (*stability) {
      if (stability_samples < 1 || stability_samples > 100000000) {
        throw std::invalid_argument("--samples must be in [1, 100000000]");
      }
      std::ostringstream out;
      const std::vector<brdfbake::StabilityRow> rows =
          brdfbake::RunStability(stability_samples, stability_seed);
      brdfbake::WriteStabilityCsv(rows, out);
      std::cout << out.str();
      int64_t outside = 0, non_finite = 0;
      for (const brdfbake::StabilityRow& r : rows) {
        outside += r.Within() ? 0 : 1;
        non_finite += r.non_finite;
      }
      std::cerr << rows.size() << " rows: " << non_finite << " non-finite outputs, " << outside
                << " rows outside their stated bound\n";
      if (outside > 0) return 1;
    }
    if (*eval && !grid_kind.empty()) {
      brdfbake::ForceTarget(target);
      brdfbake::GridRequest gr;
      gr.model = model_opts.Get();
      gr.fresnel = fresnel_opts.Get();
      gr.masking = ParseMasking(masking);
      gr.kind = brdfbake::ParseGridKind(grid_kind);
      gr.width = grid_w;
      gr.height = grid_h;
      gr.threads = grid_threads;
      gr.mu_o = req.mu_o;
      gr.phi_o = phi_o_deg * 3.14159265358979323846 / 180.0;
      if (grid_out.empty()) throw std::invalid_argument("-o: --grid writes an EXR file; name it with -o");
      const auto start = std::chrono::steady_clock::now();
      const brdfbake::Grid g = brdfbake::EvalGrid(gr);
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const char* names[] = {"f", "f_cos", "G1"};
      const std::string channel = names[static_cast<int>(gr.kind)];
      brdfbake::WriteImageExr(
          grid_out, g.width, g.height, {{channel, &g.values}},
          {{"brdfbake.version", BRDFBAKE_VERSION},
           {"brdfbake.grid", brdfbake::GridKindName(gr.kind)},
           {"brdfbake.model", gr.model.ToJson()},
           {"brdfbake.masking", brdfbake::MaskingName(gr.masking)},
           {"brdfbake.fresnel", gr.fresnel.Name()},
           {"brdfbake.evaluated_by", g.path}});
      std::printf("wrote %s: %s grid %dx%d of %s in %.3f s (%s)\n", grid_out.c_str(),
                  brdfbake::GridKindName(gr.kind), g.width, g.height, gr.model.name.c_str(), secs,
                  g.path.c_str());
    } else if (*eval) {
      if (target != "best") brdfbake::ForceTarget(target);
      req.model = model_opts.Get();
      req.fresnel = fresnel_opts.Get();
      req.masking = ParseMasking(masking);
      req.quantities = SplitComma(quantity);
      req.sweep = sweep;
      const double deg = 3.14159265358979323846 / 180.0;
      req.phi = phi_deg * deg;
      req.phi_o = phi_o_deg * deg;
      std::ostringstream out;  // nothing is printed unless the whole sweep succeeds
      brdfbake::EvalCsv(req, out);
      std::cout << out.str();
      std::cout.flush();
      if (!std::cout) {
        std::fprintf(stderr, "brdfbake: error: could not write to standard output\n");
        return 1;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brdfbake: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
