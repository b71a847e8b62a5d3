#pragma once
// Richardson extrapolation and the Grid Convergence Index of Celik et al., "Procedure for
// Estimation and Reporting of Uncertainty Due to Discretization in CFD Applications",
// J. Fluids Eng. 130 (2008) 078001 — on three solutions φ1 (fine), φ2, φ3 (coarse) with
// representative sizes h1 < h2 < h3.
#include <string>

namespace stoneskip {

enum class ConvergenceKind { monotone, oscillatory, divergent, converged_to_roundoff };
const char* to_string(ConvergenceKind k);

struct GciResult {
  ConvergenceKind kind = ConvergenceKind::divergent;
  double order = 0;               // apparent order p (Celik Eq. 3–5, fixed-point iteration)
  double extrapolated = 0;        // φ_ext^21 (Eq. 6)
  double relative_error = 0;      // e_a^21 = |(φ1 − φ2)/φ1| (Eq. 7)
  double extrapolated_relative_error = 0;  // e_ext^21 (Eq. 8)
  double gci_fine = 0;            // GCI_fine^21 = 1.25 e_a^21 / (r21^p − 1) (Eq. 9), a fraction
  double ratio_21 = 0, ratio_32 = 0;
  int iterations = 0;
  std::string brief() const;
};

// h: representative cell sizes (for N cells in D dimensions h = (1/N)^{1/D}).
GciResult grid_convergence_index(double phi1, double phi2, double phi3, double h1, double h2, double h3,
                                 double safety_factor = 1.25);

}  // namespace stoneskip
