#pragma once
// Richardson extrapolation and the Grid Convergence Index of Celik et al., "Procedure for
// Estimation and Reporting of Uncertainty Due to Discretization in CFD Applications",
// J. Fluids Eng. 130 (2008) 078001 — on three solutions φ1 (fine), φ2, φ3 (coarse) with
// representative sizes h1 < h2 < h3.
#include <string>

namespace stoneskip {

enum class ConvergenceKind { monotone, oscillatory, divergent, converged_to_roundoff };
const char* to_string(ConvergenceKind k);

struct GciOptions {
  // Celik's factor of safety for three grids whose apparent order is reasonable (Eq. 9).
  double safety_factor = 1.25;
  // The scheme's formal order (0: unknown). Where it is known and the apparent order lies farther
  // from it than `order_band`, the apparent order is not reasonable: the GCI reverts to the formal
  // order and a factor of safety of 3 (Roache, "Discussion: Factors of Safety for Richardson
  // Extrapolation", J. Fluids Eng. 133 (2011) 115501: "if p_RE is unreasonable one at least reverts
  // to using p_th and FS = 3 rather than blindly applying FS = 1.25"). A round-off or error-floor
  // value among the three gives such an order (p = 35 from 1 − 3e-14, 1, 1 + 1e-3 at r = 2).
  double formal_order = 0;
  double order_band = 0.1;                // absolute, as the order verdicts' tolerance
  double reverted_safety_factor = 3;
};

struct GciResult {
  ConvergenceKind kind = ConvergenceKind::divergent;
  double order = 0;               // apparent order p (Celik Eq. 3–5; the root of Eq. 4 by bisection)
  double order_used = 0;          // the order in Eq. 6 and 9: p, or the formal order where p is not reasonable
  double safety_factor = 0;       // the factor of safety used in Eq. 9
  bool reverted = false;          // order_used is the formal order, with the reverted factor of safety
  double extrapolated = 0;        // φ_ext^21 (Eq. 6)
  double relative_error = 0;      // e_a^21 = |(φ1 − φ2)/φ1| (Eq. 7)
  double extrapolated_relative_error = 0;  // e_ext^21 (Eq. 8)
  double gci_fine = 0;            // GCI_fine^21 = Fs e_a^21 / (r21^p − 1) (Eq. 9), a fraction
  double gci_fine_absolute = 0;   // Fs |φ1 − φ2| / (r21^p − 1): the same band in φ's unit (defined at φ1 = 0)
  double ratio_21 = 0, ratio_32 = 0;
  int iterations = 0;             // bisection steps
  std::string brief() const;
};

// h: representative cell sizes (for N cells in D dimensions h = (1/N)^{1/D}).
GciResult grid_convergence_index(double phi1, double phi2, double phi3, double h1, double h2, double h3,
                                 const GciOptions& options = {});

}  // namespace stoneskip
