#include "model/stone/environment.hpp"

namespace stoneskip {

const char* to_string(Convention c) { return c == Convention::paper ? "paper" : "physical"; }

bool parse_convention(const std::string& s, Convention& out) {
  if (s == "physical") {
    out = Convention::physical;
    return true;
  }
  if (s == "paper") {
    out = Convention::paper;
    return true;
  }
  return false;
}

const char* to_string(WaterLaw w) {
  switch (w) {
    case WaterLaw::newtonian: return "newtonian";
    case WaterLaw::planing: return "planing";
    case WaterLaw::lift_drag: return "lift_drag";
  }
  return "unknown";
}

bool parse_water_law(const std::string& s, WaterLaw& out) {
  for (WaterLaw w : {WaterLaw::newtonian, WaterLaw::planing, WaterLaw::lift_drag}) {
    if (s == to_string(w)) {
      out = w;
      return true;
    }
  }
  return false;
}

double published_water_coefficient(WaterLaw w) {
  switch (w) {
    case WaterLaw::newtonian: return 1.0;  // Lee & Baek 2013 Eq. 2 has no coefficient
    case WaterLaw::planing: return 0.5;    // ½ C, C = 1 (Truscott, Belden & Hurd 2014: C_L = ½ for a disk)
    case WaterLaw::lift_drag: return 0.7;  // ½ C_D, C_D = 1.4 (Nagahiro & Hayakawa 2005, fitted to SPH)
  }
  return 1.0;
}

void set_water_law(Environment& env, WaterLaw law) {
  env.water_law = law;
  env.water_coefficient = published_water_coefficient(law);
}

std::string environment_problem(const Environment& env) {
  if (env.convention == Convention::paper && env.water_law != WaterLaw::newtonian)
    return std::string("water law \"") + to_string(env.water_law) +
           "\" with the paper convention: the paper convention is Lee & Baek's Eq. 1-3 as printed, whose law is "
           "newtonian; the other laws exist in the physical convention only";
  // NaN passes on purpose: the solvers meet it in the right-hand side and fail there, saying where.
  if (env.water_density_kg_m3 < 0) return "water density must be >= 0";
  if (env.air_density_kg_m3 < 0) return "air density must be >= 0";
  if (env.water_coefficient < 0) return "water coefficient must be >= 0";
  if (env.air_coefficient < 0) return "air coefficient must be >= 0";
  if (env.gravity_m_s2 < 0) return "gravity must be >= 0";
  return "";
}

}  // namespace stoneskip
