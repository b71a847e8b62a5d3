// stoneskip wave CASE [--set key=value ...] [--json]
//
// Steps a wave case (a height field with one of the stencils of model/README.md §2.2, the damped leapfrog of
// §2.1) to its end time and compares it with the exact spectral reference (§2.3) on the same
// grid: the continuum solution by default, or the stencil's own semi-discrete solution with
// [reference] symbol = "stencil" (then the difference is the time error alone).
//   stoneskip wave cases/wave_gaussian_five_point.toml
//   stoneskip wave cases/wave_gaussian_five_point.toml --set water.stencil=nine_point_isotropic --json
//   stoneskip wave cases/wave_lengyel_counterexample.toml      # an unstable run, shown as such: exit 1
// Prints the resolved configuration, the RMS ("L2") and max errors in metres, the solution's own
// RMS for scale, the steps and the CPU time. A periodic grid's reference is a Fourier series
// (solvers/spectral/spectral_wave.hpp); a walled one's, reflecting or fixed, a cosine or sine series
// with the walls where the ghost cells put them (solvers/spectral/walled_wave.hpp). An unstable run — σ above
// the stencil's von Neumann limit, or a surface that overflowed — says so first ("UNSTABLE: ...",
// JSON stable = false and the reason in stability) and exits 1; one whose surface overflowed also
// says "BLEW UP" (JSON finite = false, blew_up_by_step, errors null) and counts the steps it took.
// Memory and cell updates are estimated first and held to the limits of cases/README.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "solvers/realtime/clocks.hpp"
#include "solvers/spectral/spectral_wave.hpp"
#include "solvers/spectral/walled_wave.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/io/printable_text.hpp"
#include "tools/io/progress.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/wave_case.hpp"
#include "verification/waves/wave_problem.hpp"

namespace stoneskip::cli {
namespace {

struct WaveArgs {
  std::string case_file;
  std::vector<std::string> sets;
  bool json = false;
  ResourceLimits limits;
};

bool all_finite(const std::vector<double>& z) {
  return std::all_of(z.begin(), z.end(), [](double v) { return std::isfinite(v); });
}

void run_wave(const WaveArgs& a) {
  WaveCase c = load_wave_case(a.case_file, a.sets);
  enforce_limits(estimate_wave(c), a.limits, c.file);
  const HeightFieldOptions& w = c.water;
  const long steps = c.steps();
  const double sigma = w.courant(), mu_dt = w.damping_per_s * w.dt_s;
  const WaterStability stability = water_stability(w);  // the exact limit, on the plane and over this grid's modes

  // 1. Initial surface and the run, in up to 100 chunks: progress, and a surface that overflows
  //    is caught by the end of the chunk where it did (then nothing is compared: its error is not 0).
  std::vector<double> z0, z;
  sample_disturbance(c.initial, w.nx, w.ny, w.cell_m, z0);
  HeightField field(w);
  field.set_state(z0);
  CpuTimer timer;
  long blown_up_by = -1;  // the step by which the surface was no longer finite
  {
    Progress progress("wave", static_cast<std::size_t>(steps), 2.0);
    const long chunk = std::max(1L, steps / 100);
    for (long done = 0; done < steps;) {
      const long n = std::min(chunk, steps - done);
      field.advance(n);
      done += n;
      progress.tick(static_cast<std::size_t>(n));
      field.heights(z);
      if (!all_finite(z)) {
        blown_up_by = field.steps();
        break;
      }
    }
  }
  const double cpu_s = timer.seconds();
  const bool finite = blown_up_by < 0;
  const long steps_taken = field.steps();
  // An unstable run's numbers are not discretisation errors: σ above the von Neumann limit, or a
  // surface that overflowed, makes the run unstable, said on stdout and in JSON, with exit 1.
  const bool stable = stability.stable() && finite;
  std::string why = stability.reason();
  if (!finite) why += "; the surface was no longer finite by step " + std::to_string(blown_up_by);

  // 2. The reference on the same grid and at the same time.
  const bool periodic = w.boundary == Boundary::periodic;
  // A plane wave on a periodic grid is smooth only if whole wavelengths fit along each axis:
  // otherwise its periodic copy has a seam, whose short waves the scheme carries wrongly, and the
  // error includes the seam's (0.80 mm at 31° on the shipped case against 0.35 mm at 30°, which
  // fits). Said, not left to look like the scheme's error.
  std::string seam;
  if (periodic && c.initial.kind == DisturbanceKind::plane_wave) {
    const double angle = c.initial.angle_deg * M_PI / 180;
    const double mx = std::cos(angle) * w.nx * w.cell_m / c.initial.wavelength_m;
    const double my = std::sin(angle) * w.ny * w.cell_m / c.initial.wavelength_m;
    if (std::abs(mx - std::round(mx)) > 1e-6 || std::abs(my - std::round(my)) > 1e-6) {
      char b[320];
      std::snprintf(b, sizeof b,
                    "the plane wave does not fit the periodic grid (%.4g and %.4g wavelengths along x and y, not whole "
                    "numbers): its periodic copy has a seam, and the error includes the seam's",
                    mx, my);
      seam = b;
    }
  }
  // A Gaussian wide against the periodic grid sums with its images to a surface higher than its
  // amplitude (0.32 m RMS from amplitude_m = 0.01 on 4 × 4 cells): the case's amplitude is then not
  // the surface's, said as the seam is (the error is still the scheme's on that surface).
  if (periodic && c.initial.kind == DisturbanceKind::gaussian && seam.empty()) {
    const double peak = gaussian_image_peak_m(c.initial, w.nx * w.cell_m, w.ny * w.cell_m);
    if (peak > 1.01 * std::abs(c.initial.amplitude_m)) {
      char b[320];
      std::snprintf(b, sizeof b,
                    "the Gaussian (width_m %.4g) is wide against the %.4g m x %.4g m periodic grid: with its periodic "
                    "images it sums to %.4g m at its centre, %.3g times amplitude_m",
                    c.initial.width_m, w.nx * w.cell_m, w.ny * w.cell_m, peak, peak / std::abs(c.initial.amplitude_m));
      seam = b;
    }
  }
  FieldError err{NAN, NAN};
  if (!periodic && finite) {
    WalledWave ref(walled_wave_options(w, c.reference_semi_discrete ? SpectralSymbol::stencil : SpectralSymbol::continuum));
    ref.set_initial(z0);
    std::vector<double> zr;
    ref.evaluate(field.time_s(), zr);
    err = field_error(z, zr);
    // The continuum reference is the cosine (sine) series of the sampled surface: spectrally
    // accurate for a surface that meets the walls smoothly. One that meets them with a kink or a
    // step (a plane wave across the pond, a bump at a fixed rim), or that the grid does not
    // resolve, has a slowly falling series whose short waves every stencil carries wrongly: said,
    // as the periodic seam is, when over 1 % of its RMS lies in the upper half of the modes.
    const double upper = ref.upper_half_fraction();
    if (!c.reference_semi_discrete && upper > 0.01) {
      char b[400];
      std::snprintf(b, sizeof b,
                    "%.3g %% of the initial surface's RMS is in the upper half of the %s pond's modes (waves under "
                    "four cells): it meets a wall with a %s, or the grid does not resolve it, and the error includes "
                    "what the scheme does to those waves",
                    100 * upper, to_string(w.boundary), w.boundary == Boundary::reflecting ? "kink" : "step");
      seam = b;
    }
  }
  if (periodic && finite) {
    SpectralWave ref(spectral_wave_options(w, c.reference_semi_discrete ? SpectralSymbol::stencil : SpectralSymbol::continuum));
    ref.set_initial(z0);
    std::vector<double> zr;
    ref.evaluate(field.time_s(), zr);
    err = field_error(z, zr);
  }

  if (a.json) {
    nlohmann::json j;
    j["case"] = c.title;
    j["stencil"] = w.stencil.name;
    j["weights"] = {{"centre", w.stencil.centre}, {"orth", w.stencil.orth}, {"diag", w.stencil.diag}};
    j["nx"] = w.nx;
    j["ny"] = w.ny;
    j["cell_m"] = w.cell_m;
    j["dt_s"] = w.dt_s;
    j["steps"] = steps_taken;  // taken: fewer than planned when the run blew up
    j["steps_planned"] = steps;
    j["t_end_s"] = field.time_s();
    j["courant"] = sigma;
    j["mu_dt"] = mu_dt;
    // null with kind "unbounded" (no spatial coupling); 0 with kind "none" (no stable step).
    j["stability_limit"] = stability.unbounded() ? nlohmann::json(nullptr) : nlohmann::json(stability.limit);
    j["stability_limit_kind"] = stability.limit_kind();
    // What decides: the limit over the modes this grid holds (≥ the plane's; above it on a grid
    // without the zone's corner, e.g. an odd periodic one).
    j["grid_stability_limit"] = stability.unbounded() ? nlohmann::json(nullptr) : nlohmann::json(stability.grid_limit);
    j["stable"] = stable;  // false: the errors (null if it blew up) are not discretisation errors
    j["stability"] = why;
    j["boundary"] = to_string(w.boundary);
    j["initial"] = to_string(c.initial.kind);
    j["reference"] = c.reference_semi_discrete ? "stencil" : "continuum";
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
    j["l2_error"] = num(err.l2_m);
    j["initial_fits_grid"] = seam.empty();  // false: a seam on the periodic grid, a kink or step at a wall (note)
    if (!seam.empty()) j["note"] = seam;
    j["max_error"] = num(err.max_m);
    j["solution_rms_m"] = finite ? num(root_mean_square(z)) : nlohmann::json(nullptr);
    j["finite"] = finite;
    j["blew_up_by_step"] = finite ? nlohmann::json(nullptr) : nlohmann::json(blown_up_by);
    j["cpu_s"] = cpu_s;
    j["cell_updates_per_s"] = cpu_s > 0 ? static_cast<double>(w.nx) * w.ny * steps_taken / cpu_s : 0.0;
    std::cout << json_text(j) << std::endl;
  } else {
    std::printf("%s: %s stencil (centre %.6g, orth %.6g, diag %.6g)/d², %d x %d cells of %.6g m, %s boundary\n",
                printable_text(c.title).c_str(), printable_text(w.stencil.name).c_str(), w.stencil.centre, w.stencil.orth, w.stencil.diag, w.nx, w.ny,
                w.cell_m, to_string(w.boundary));
    std::printf("  c = %.6g m/s, mu = %.6g /s, dt = %.6g s, sigma = c dt/d = %.4f (%s; mu dt = %.4g)\n",
                w.wave_speed_m_s, w.damping_per_s, w.dt_s, sigma, stability.limit_text().c_str(), mu_dt);
    std::printf("  initial %s, amplitude %.6g m; %ld steps%s to t = %.6g s in %.3g s CPU (%.3g cell updates/s)\n",
                to_string(c.initial.kind), c.initial.amplitude_m, steps_taken,
                finite ? "" : (" of " + std::to_string(steps) + " planned").c_str(), field.time_s(), cpu_s,
                cpu_s > 0 ? static_cast<double>(w.nx) * w.ny * steps_taken / cpu_s : 0.0);
    if (!stable)
      std::printf("  UNSTABLE: %s%s\n", why.c_str(),
                  finite ? ": the figures below are those of an unstable run, not a discretisation error" : "");
    if (!finite)
      std::printf("  BLEW UP: the surface was no longer finite by step %ld (t = %.6g s); no error is reported\n",
                  blown_up_by, field.time_s());
    else {
      const double rms = root_mean_square(z);
      std::printf("  error vs the %s spectral reference%s: L2 (RMS) %.4g m, max %.4g m (solution RMS %.4g m)\n",
                  c.reference_semi_discrete ? "semi-discrete (stencil symbol)" : "continuum",
                  periodic ? "" : w.boundary == Boundary::reflecting ? " (cosine series, walls half a cell outside the edge points)"
                                                                       : " (sine series, rims one cell outside the edge points)",
                  err.l2_m, err.max_m, rms);
      // A surface that is zero everywhere (an amplitude of 0, a bump far outside the pond) makes
      // a zero error that says nothing of the scheme: said, not left to look like exactness.
      if (rms == 0)
        std::printf("  note: the solution is zero everywhere (initial amplitude 0, or the initial shape outside the grid): "
                    "the zero error says nothing about the scheme\n");
      else if (stable && err.l2_m > 0.5 * rms)
        std::printf("  note: the L2 error is %.3g of the solution's RMS: the computed surface is not this solution (an "
                    "inconsistent stencil such as paper_eq11, a surface the grid does not resolve, or an initial shape "
                    "mostly outside the grid), however small the error looks in metres\n",
                    err.l2_m / rms);
      if (!seam.empty()) std::printf("  note: %s\n", seam.c_str());
    }
  }
  if (!stable) set_exit_code(1);  // an unstable run is a failed run, like one that blew up or a failed solve
}

void add_wave(CLI::App& app) {
  auto a = std::make_shared<WaveArgs>();
  auto* cmd = app.add_subcommand("wave", "Step a water-surface case and print its error against the exact spectral reference");
  cmd->add_option("CASE", a->case_file, "Wave case file (TOML, see cases/README.md)")->required();
  cmd->add_option("--set", a->sets, "Override a case key: section.key=value (repeatable)");
  cmd->add_flag("--json", a->json, "Print one JSON object (l2_error, max_error, steps, stencil, ...)");
  add_limit_options(cmd, a->limits);
  cmd->callback([a] { run_wave(*a); });
}

const bool kRegistered = register_command(add_wave);

}  // namespace
}  // namespace stoneskip::cli
