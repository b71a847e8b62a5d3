#include "verification/waves/precision_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/water/height_field.hpp"

namespace stoneskip {

bool PrecisionErrorOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* what) {
    if (why) *why = what;
    return false;
  };
  if (n < 8) return fail("precision error: n must be >= 8");
  if (!(sigma > 0)) return fail("precision error: sigma must be > 0");
  if (!(problem.t_end_s > 0)) return fail("precision error: t_end_s must be > 0");
  return true;
}

std::string PrecisionError::brief() const {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "%ld steps: float32 − float64 max %.3g m (rms %.3g m); float64 − exact max %.3g m (rms %.3g m); ratio %.2g; "
                "amplitude %.3g m",
                steps, float_vs_double_max_m, float_vs_double_rms_m, discretisation_max_m, discretisation_rms_m, ratio(),
                amplitude_m);
  return buf;
}

PrecisionError measure_precision_error(const PrecisionErrorOptions& o) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument(why);
  const WaveProblem& p = o.problem;
  const double d = p.length_m / o.n;
  PrecisionError r;
  r.steps = std::max(1L, std::lround(p.t_end_s * p.wave_speed_m_s / (o.sigma * d)));
  auto run = [&](Precision precision) {
    HeightFieldOptions f = leapfrog_options(p, o.stencil, o.n, r.steps);
    f.precision = precision;
    HeightField field(f);
    field.set_state(initial_surface(p, o.n));
    field.advance(r.steps);
    std::vector<double> z;
    field.heights(z);
    return z;
  };
  const auto z64 = run(Precision::float64), z32 = run(Precision::float32);
  const auto exact = solve_spectral(p, o.n, SpectralSymbol::continuum);
  const FieldError fd = field_error(z32, z64), dd = field_error(z64, exact);
  r.float_vs_double_max_m = fd.max_m;
  r.float_vs_double_rms_m = fd.l2_m;
  r.discretisation_max_m = dd.max_m;
  r.discretisation_rms_m = dd.l2_m;
  for (double v : z64) r.amplitude_m = std::max(r.amplitude_m, std::abs(v));
  return r;
}

}  // namespace stoneskip
