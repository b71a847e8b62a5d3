#pragma once
// The convergence throw of the stones report (cases/studies/convergence_bounce.toml), built here
// so that tests need no case parsing: the seed's 3 cm 44-triangle stone, 8 m/s, β = 10°, α = 20°,
// 40 rev/s, physical convention. Its first contact lasts from ≈ 53 ms to ≈ 96 ms and ends with a
// bounce; the second, a long planing run from ≈ 187 ms, ends at ≈ 614 ms with the stone sinking.
#include "model/stone/mass_properties.hpp"
#include "model/stone/throw.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

inline ThrowProblem convergence_throw() {
  ThrowProblem p;
  p.label = "convergence throw: 8 m/s, 40 rev/s, alpha 20, beta 10";
  const Mesh mesh = make_prism(0.03, 0.008, 11);
  p.stone = make_stone(mesh, mass_properties_from_density(mesh, 2500.0), 0.0, "prism R=0.03 h=0.008 N=11");
  p.parameters.speed_m_s = 8.0;
  p.parameters.path_angle_deg = 10.0;
  p.parameters.attack_angle_deg = 20.0;
  p.parameters.spin_rev_s = 40.0;
  p.parameters.height_m = 0.1;
  p.initial = initial_state(p.stone, p.parameters);
  p.realtime.t_max_s = 3.0;
  p.reference.rtol = 1e-12;
  p.reference.atol = 1e-14;
  p.reference.t_max_s = 3.0;
  return p;
}

}  // namespace stoneskip
