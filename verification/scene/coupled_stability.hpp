#pragma once
// The coupled stability limit of model/README.md §2.4 shown on either side: a flat-bottomed stone (an
// 11-gon prism) held still on a periodic pond, b recomputed from the field every step
// (model/coupling/draught.hpp), started in its closed-form equilibrium (z = C off the stone,
// (C + s)/2 under it) plus round-off noise; the departure's growth per step is measured at
// σ = (1 ∓ margin) × coupled_courant_limit, and without the stone at the upper σ (so the growth
// is the coupling's, not the free stencil's).
#include <string>

#include "model/water/stencil.hpp"

namespace stoneskip {

struct CoupledStabilityOptions {
  std::string stencil = "nine_point_isotropic";
  double margin = 0.03;   // σ = (1 ∓ margin) × the coupled limit
  int n = 48;             // n × n periodic cells of 1/n m; the stone covers half the side
  double damping_per_s = 0.2;
  long steps = 400;       // below the limit and without the stone
  long steps_above = 40;  // above: until the departure is still in b's linear range
  bool is_valid(std::string* why = nullptr) const;
};

struct CoupledStability {
  std::string stencil;
  double free_limit = 0, coupled_limit = 0;
  double sigma_below = 0, sigma_above = 0;
  double growth_below = 0, growth_above = 0, growth_free_above = 0;  // per step, from step 10 on
  double departure_above_m = 0;  // at the end of the run above the limit
};

CoupledStability measure_coupled_stability(const CoupledStabilityOptions& options);

}  // namespace stoneskip
