#pragma once
// The exact reference for the damped wave equation with a prescribed draught (model/README.md §2.5)
// in a walled pond: z_tt = c² ∇²(z + b) − μ z_t with the walls of solvers/spectral/walled_wave.hpp,
// reflecting (zero slope half a cell beyond the edge points) or fixed (z = 0 one cell beyond).
// The draught is extended as the field is: mirrored across a reflecting wall, as the forced
// leapfrog's ghost cells mirror b (model/water/height_field.hpp: a point on the edge also feeds the
// cell it mirrors into), and 0 on a fixed rim. Each cosine or sine mode is then a forced damped
// oscillator, ẑ'' + μ ẑ' + λ ẑ = −λ b̂(t): the free walled solution plus the Duhamel integral
// (solvers/spectral/duhamel.hpp), continuum symbol or the stencil's own (the exact semi-discrete
// solution of the forced leapfrog's system with those walls).
#include <vector>

#include "solvers/spectral/duhamel.hpp"
#include "solvers/spectral/walled_wave.hpp"

namespace stoneskip {

class ForcedWalledWave {
 public:
  // draught: b on the nx × ny points; quadrature: the Duhamel integral's. Throws as WalledWave, and
  // std::invalid_argument for no draught or a quadrature without nodes.
  ForcedWalledWave(const WalledWaveOptions& options, DraughtField draught, const DuhamelQuadrature& quadrature);

  void set_initial(const std::vector<double>& z0, const std::vector<double>& v0 = {});  // empty v0: at rest
  void evaluate(double t_s, std::vector<double>& z);  // the exact solution at t (nx·ny)
  long draught_transforms() const { return transforms_; }

 private:
  WalledWave free_;
  DraughtField draught_;
  DuhamelQuadrature quadrature_;
  long transforms_ = 0;
  std::vector<double> b_, b_hat_, modes_;
};

}  // namespace stoneskip
