#pragma once
// The fluids and gravity around the stone, and which form of the force laws to use (spec §1.6).
#include <string>

namespace stoneskip {

// physical: the corrected laws (default). paper: Lee & Baek 2013's Eq. 1–3 and 6 exactly as printed.
enum class Convention { physical, paper };

const char* to_string(Convention c);
bool parse_convention(const std::string& s, Convention& out);

struct Environment {
  Convention convention = Convention::physical;
  double water_density_kg_m3 = 1000.0;  // ρ_w
  double air_density_kg_m3 = 1.2;       // ρ_a
  double water_coefficient = 1.0;       // C_w (Lee & Baek: 1, i.e. ½ C_D with C_D = 2)
  double air_coefficient = 1.0;         // C_a
  double gravity_m_s2 = 9.81;           // along −z
};

}  // namespace stoneskip
