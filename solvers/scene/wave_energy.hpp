#pragma once
// The energy of the leapfrog's waves and what damping takes from them, exactly as the scheme
// keeps them (model/README.md §2.4, the energy budget of the pressure coupling). The forced,
// damped leapfrog of model/water/height_field.hpp,
//   (zⁿ⁺¹ − 2zⁿ + zⁿ⁻¹)/Δt² + μ (zⁿ⁺¹ − zⁿ⁻¹)/(2Δt) = c² L[zⁿ + hⁿ],
// multiplied by K = (−L)⁻¹ (on fields of zero mean) and summed against (zⁿ⁺¹ − zⁿ⁻¹)/2, gives
//   E^{n+½} − E^{n−½} = Wₙ − Dₙ,
//   E^{n+½} = ρ g d² [ ⟨v, K v⟩/(2c²) + ½⟨zⁿ, zⁿ⁺¹⟩ ],        v = (zⁿ⁺¹ − zⁿ)/Δt,
//   Wₙ = ρ g d² ⟨hⁿ, (zⁿ⁻¹ − zⁿ⁺¹)/2⟩   (the pressure's work on the water: −∫∫ p_s z_t dA dt),
//   Dₙ = ρ g d² μ Δt ⟨w, K w⟩/c²,       w = (zⁿ⁺¹ − zⁿ⁻¹)/(2Δt)  (what damping takes),
// the discrete form of the linear shallow-water energy ½ρH|u|² + ½ρ g z² (c² = gH, z_t = −H∇·u).
// It holds to round-off for any h, so W − D − ΔE measures only round-off and what the pressure
// work is not (a leak in the coupling). K is diagonal in the cosine basis of the reflecting pond
// (mirror ghosts: DCT-II), in the sine basis of the fixed one (zero ghosts: DST-I, where −L has no
// zero mode; until 7 December this said "no such basis" and a fixed pond had no budget) and in the
// Fourier basis of the periodic one (FFTW). available() is false only for c = 0.
// The energy per mode also gives the share of the waves at the grid scale: wavenumbers |k| d above
// π/2, half the grid's Nyquist (a checkerboard lives at |k| d ≈ π√2).
#include <vector>

#include "model/water/height_field.hpp"

namespace stoneskip {

struct WaveEnergyReading {
  double total_J = 0;
  double grid_scale_J = 0;  // modes with |k| d > π/2
  double grid_scale_fraction() const { return total_J > 0 ? grid_scale_J / total_J : 0; }
};

class WaveEnergy {
 public:
  WaveEnergy(const HeightFieldOptions& field, double rho_g);
  ~WaveEnergy();
  WaveEnergy(const WaveEnergy&) = delete;
  WaveEnergy& operator=(const WaveEnergy&) = delete;

  bool available() const { return available_; }
  // E^{n+½} of the field's two levels (previous = zⁿ, current = zⁿ⁺¹).
  WaveEnergyReading energy(const HeightField& field);
  // Dₙ of a step from zⁿ⁻¹ (before) to zⁿ⁺¹ (after), row-major nx·ny.
  double damping_loss_J(const std::vector<double>& before, const std::vector<double>& after);

 private:
  void transform(const std::vector<double>& in, std::vector<double>& re, std::vector<double>& im);
  int nx_, ny_, mx_;   // mx_: stored modes along x
  double cell_m_, c_, mu_, dt_s_, rho_g_;
  bool periodic_, fixed_, available_;
  std::vector<double> inverse_lambda_;  // 1/λ_m (m²), 0 for the mean mode
  std::vector<double> weight_;          // Parseval weight of each stored mode
  std::vector<char> grid_scale_;        // |k| d > π/2
  std::vector<double> buffer_, re_a_, im_a_, re_b_, im_b_, work_;
  void* plan_ = nullptr;
  void* out_ = nullptr;
};

}  // namespace stoneskip
