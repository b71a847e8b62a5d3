#pragma once
// What float32 storage costs in accuracy, so that float or double is picked by measured error:
// the same leapfrog run stored in float32 and in float64, against each other and against
// the exact continuum reference, on the wave studies' standard problem
// (verification/waves/wave_problem.hpp) at the scene's grid size. float32 is acceptable where its
// difference from float64 is far below the discretisation error the double run already has.
#include "model/water/stencil.hpp"
#include "verification/waves/wave_problem.hpp"

namespace stoneskip {

struct PrecisionErrorOptions {
  WaveProblem problem;
  int n = 500;                 // n × n cells
  double sigma = 0.5;          // cΔt/d
  Stencil stencil = named_stencil("nine_point_isotropic");
  bool is_valid(std::string* why = nullptr) const;
};

struct PrecisionError {
  long steps = 0;
  double amplitude_m = 0;                 // max |z| of the float64 run at the end
  double float_vs_double_max_m = 0;       // max |z_f32 − z_f64| at the end
  double float_vs_double_rms_m = 0;
  double discretisation_max_m = 0;        // max |z_f64 − z_exact| (continuum reference) at the end
  double discretisation_rms_m = 0;
  double ratio() const { return discretisation_max_m > 0 ? float_vs_double_max_m / discretisation_max_m : 0; }
  std::string brief() const;
};

PrecisionError measure_precision_error(const PrecisionErrorOptions& options);

}  // namespace stoneskip
