#pragma once
// The fluids and gravity around the stone, which form of the force laws to use (spec §1.6), and
// which water force law acts on a wetted triangle (issue 11; model/stone/water_laws.hpp).
#include <string>

namespace stoneskip {

// physical: the corrected laws (default). paper: Lee & Baek 2013's Eq. 1–3 and 6 exactly as printed.
enum class Convention { physical, paper };

const char* to_string(Convention c);
bool parse_convention(const std::string& s, Convention& out);

// The force of the water on one wetted triangle in the physical convention
// (model/stone/water_laws.hpp has each equation beside its source):
//   newtonian: F_i = −C_w ρ_w u_i² S_i n_i                 (Lee & Baek 2013 Eq. 2; the default)
//   planing:   F_i = −C_w ρ_w u_i |v_i| S_i n_i            (Clanet, Hersen & Bocquet 2004; Rosellini et al. 2005)
//   lift_drag: F_i = ½ ρ_w |v_i|² S_i (C_L(θ_i) e_L − C_D(θ_i) v̂_i)   (Nagahiro & Hayakawa 2005)
// The paper convention is the printed Eq. 2 only: another law with it is refused
// (environment_problem), since no paper prints that combination.
enum class WaterLaw { newtonian, planing, lift_drag };

const char* to_string(WaterLaw w);
bool parse_water_law(const std::string& s, WaterLaw& out);

// C_w of each law as published (model/stone/water_laws.hpp says where each comes from):
// newtonian 1 (Lee & Baek: no coefficient), planing ½ (½ C with C = 1), lift_drag 0.7 (½ C_D with
// Nagahiro & Hayakawa's C_D = 1.4).
double published_water_coefficient(WaterLaw w);

struct Environment {
  Convention convention = Convention::physical;
  WaterLaw water_law = WaterLaw::newtonian;
  double water_density_kg_m3 = 1000.0;  // ρ_w
  double air_density_kg_m3 = 1.2;       // ρ_a
  double water_coefficient = 1.0;       // C_w of the water law (newtonian default: Lee & Baek's 1, ½ C_D with C_D = 2)
  double air_coefficient = 1.0;         // C_a
  double gravity_m_s2 = 9.81;           // along −z
};

// Chooses a law together with its published C_w (set water_coefficient afterwards to depart from it).
void set_water_law(Environment& env, WaterLaw law);

// Empty when the environment can be used; else what is wrong, in words (a non-newtonian law in the
// paper convention, a negative density, coefficient or gravity).
std::string environment_problem(const Environment& env);

}  // namespace stoneskip
