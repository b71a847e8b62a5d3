#pragma once
// How fast a bounce's ring spreads (model/README.md §2.4: "a bounce makes a ring whose radius grows at c
// minus the stencil's phase error"). The scene is run once to find the contact and its centre
// (halfway between the first touch and the stone's exit point), then again with a recorder that
// takes, at every frame of a window after the contact, the azimuthal RMS of the surface in rings
// of one cell's width around that centre. The ring's radius at a frame is its leading edge: the
// largest radius where the RMS profile reaches half of its maximum outside the splash (beyond
// min_radius_m). A least-squares line through radius against time gives the speed with its 95 %
// interval (verification/convergence/order_fit.hpp: fit_line).
// The prediction: the leapfrog with the stencil carries a wave of number k at the phase speed
// ω(k)/k and its energy at the group speed dω/dk, from the scheme's own dispersion relation
// cos(ωΔt) = 1 + σ² s(kd)/2 (s the stencil's symbol, averaged over directions), both below c
// for kd > 0. The ring's leading edge carries its longest waves: it moves at most at c, and at
// least at the group speed of the ring's dominant wave number k*, measured from the azimuthal mean
// profile (the distance from the leading crest to the trough behind it is half a wavelength).
#include <string>
#include <vector>

#include "solvers/scene/coupled_scene.hpp"

namespace stoneskip {

struct RingSpeedOptions {
  int contact = 0;             // which contact makes the ring (0: the first)
  double start_after_s = 0.2;  // the fit's window after the contact ends
  double end_after_s = 1.2;
  double min_radius_m = 0.1;   // the splash at the centre is left out of the maximum
  double max_radius_m = 1.5;   // the profile's extent (keep it clear of walls and other rings)
  bool is_valid(std::string* why = nullptr) const;
};

struct RingSpeed {
  bool found = false;          // false: the scene has no such contact, or no field
  std::string problem;
  double centre_x_m = 0, centre_y_m = 0, contact_end_s = 0;
  std::vector<double> t_s, radius_m;   // the leading edge against time (frames in the window)
  std::vector<double> profile_r_m, profile_rms_m, profile_mean_m;  // the profiles at the window's middle frame
  double profile_t_s = 0;
  double speed_m_s = 0, speed_low_m_s = 0, speed_high_m_s = 0, r_squared = 0, intercept_m = 0;  // radius = intercept + speed·t
  double c_m_s = 0;
  double wavelength_m = 0, kd = 0;     // the ring's dominant wave (at the middle frame)
  double phase_speed_m_s = 0, group_speed_m_s = 0;  // the scheme's, at that kd (direction mean)
};

RingSpeed measure_ring_speed(const SceneOptions& scene, const RingSpeedOptions& options);

// The fully discrete leapfrog's phase and group speed of a wave of number kd (per cell) with this
// stencil at Courant number σ, averaged over directions; relative to c. NaN beyond the scheme's
// resolvable range.
double discrete_phase_speed(const Stencil& stencil, double sigma, double kd);
double discrete_group_speed(const Stencil& stencil, double sigma, double kd);

}  // namespace stoneskip
