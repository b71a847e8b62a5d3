#include "solvers/spectral/forced_walled_wave.hpp"

#include <stdexcept>

namespace stoneskip {

ForcedWalledWave::ForcedWalledWave(const WalledWaveOptions& options, DraughtField draught, const DuhamelQuadrature& quadrature)
    : free_(options), draught_(std::move(draught)), quadrature_(quadrature) {
  if (!draught_) throw std::invalid_argument("ForcedWalledWave: no draught");
  if (quadrature.intervals < 1 || quadrature.nodes < 1)
    throw std::invalid_argument("ForcedWalledWave: quadrature needs intervals, nodes >= 1");
  free_.set_initial(std::vector<double>(static_cast<std::size_t>(options.nx) * options.ny, 0.0));
}

void ForcedWalledWave::set_initial(const std::vector<double>& z0, const std::vector<double>& v0) { free_.set_initial(z0, v0); }

void ForcedWalledWave::evaluate(double t_s, std::vector<double>& z) {
  free_.evaluate_modes(t_s, modes_);
  transforms_ += add_duhamel_integral(
      t_s, free_.lambdas(), free_.options().damping_per_s, quadrature_, draught_,
      [this](const std::vector<double>& b, std::vector<double>& b_hat) { free_.transform(b, b_hat); }, modes_, b_, b_hat_);
  free_.synthesise(modes_, z);
}

}  // namespace stoneskip
