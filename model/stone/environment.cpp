#include "model/stone/environment.hpp"

#include <cstdio>

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
    case WaterLaw::nagahiro_hayakawa: return "nagahiro_hayakawa";
  }
  return "unknown";
}

bool parse_water_law(const std::string& s, WaterLaw& out) {
  for (WaterLaw w : {WaterLaw::newtonian, WaterLaw::planing, WaterLaw::nagahiro_hayakawa}) {
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
    case WaterLaw::planing: return 0.5;    // C_L = ½ (Rosellini et al. 2005; Truscott, Belden & Hurd 2014)
    case WaterLaw::nagahiro_hayakawa: return 0.7;  // ½ C_D, C_D = 1.4 (Nagahiro & Hayakawa 2005, fitted to SPH)
  }
  return 1.0;
}

const char* to_string(PressureDistribution d) {
  switch (d) {
    case PressureDistribution::uniform: return "uniform";
    case PressureDistribution::savitsky: return "savitsky";
    case PressureDistribution::savitsky_wagner: return "savitsky_wagner";
  }
  return "unknown";
}

bool parse_pressure_distribution(const std::string& s, PressureDistribution& out) {
  for (PressureDistribution d :
       {PressureDistribution::uniform, PressureDistribution::savitsky, PressureDistribution::savitsky_wagner}) {
    if (s == to_string(d)) {
      out = d;
      return true;
    }
  }
  return false;
}

const char* to_string(Attitude a) { return a == Attitude::held ? "held" : "free"; }

bool parse_attitude(const std::string& s, Attitude& out) {
  if (s == "free" || s == "held") {
    out = s == "held" ? Attitude::held : Attitude::free;
    return true;
  }
  return false;
}

void set_water_law(Environment& env, WaterLaw law) {
  env.water_law = law;
  env.water_coefficient = published_water_coefficient(law);
}

void set_default_water_model(Environment& env) {
  if (env.convention == Convention::paper) {
    set_water_law(env, WaterLaw::newtonian);
    env.pressure_distribution = PressureDistribution::uniform;
  } else {
    set_water_law(env, WaterLaw::planing);
    env.pressure_distribution = PressureDistribution::savitsky_wagner;
  }
}

void set_convention(Environment& env, Convention c) {
  env.convention = c;
  if (c == Convention::paper) {
    set_default_water_model(env);
    env.air_coefficient = 1;           // Eq. 6 as printed has no coefficient
    env.attitude = Attitude::free;     // the paper's stone turns under its torques (Eq. 3, 5)
  }
}

namespace {

// A coefficient in a message, as %.6g writes it.
std::string six_digits(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

}  // namespace

std::string environment_problem(const Environment& env) {
  if (env.convention == Convention::paper && env.water_law != WaterLaw::newtonian)
    return std::string("water law \"") + to_string(env.water_law) +
           "\" with the paper convention: the paper convention is Lee & Baek's Eq. 1-3 as printed, whose law is "
           "newtonian; the other laws exist in the physical convention only";
  if (env.convention == Convention::paper && env.water_coefficient != 1)
    return "water coefficient " + six_digits(env.water_coefficient) +
           " with the paper convention: Lee & Baek's Eq. 2 as printed has no coefficient (C_w = 1, model/README.md §1.4); "
           "another C_w exists in the physical convention only";
  if (env.convention == Convention::paper && env.pressure_distribution != PressureDistribution::uniform)
    return std::string("pressure distribution \"") + to_string(env.pressure_distribution) +
           "\" with the paper convention: Lee & Baek's Eq. 2-3 act at each wetted face's centroid; the "
           "distributions exist in the physical convention only";
  if (env.convention == Convention::paper && env.air_coefficient != 1)
    return "air coefficient " + six_digits(env.air_coefficient) +
           " with the paper convention: Lee & Baek's Eq. 6 as printed, -rho (v.n)^2 S n, has no coefficient (C_a = 1, "
           "spec section 1.6); another C_a exists in the physical convention only";
  if (env.convention == Convention::paper && env.attitude == Attitude::held)
    return "attitude \"held\" with the paper convention: Lee & Baek's stone turns under its water torques (Eq. 3 and 5 "
           "as printed); the held attitude (torques discarded, Clanet et al.'s high-spin limit) is a reduction of the physical "
           "convention only";
  // NaN passes on purpose: the solvers meet it in the right-hand side and fail there, saying where.
  if (env.water_density_kg_m3 < 0) return "water density must be >= 0";
  if (env.air_density_kg_m3 < 0) return "air density must be >= 0";
  if (env.water_coefficient < 0) return "water coefficient must be >= 0";
  if (env.air_coefficient < 0) return "air coefficient must be >= 0";
  if (env.gravity_m_s2 < 0) return "gravity must be >= 0";
  return "";
}

}  // namespace stoneskip
