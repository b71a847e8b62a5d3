#include "model/stone/water_laws.hpp"

#include <cmath>

namespace stoneskip {

double law_pressure_Pa(const Environment& env, double u, double stone_speed_m_s) {
  // A NaN normal speed (a NaN state) passes on as NaN, so that the solvers fail on it, saying where;
  // `!(u > 0)` alone would make it "no water".
  if (std::isnan(u)) return u;
  if (!(u > 0)) return 0;
  const double k = env.water_coefficient * env.water_density_kg_m3;
  switch (env.water_law) {
    case WaterLaw::newtonian:
    case WaterLaw::nagahiro_hayakawa: return k * u * u;         // Lee & Baek 2013 Eq. 2; Nagahiro & Hayakawa 2005
    case WaterLaw::planing: return k * stone_speed_m_s * u;      // Rosellini et al. 2005 eq. 4.2, per face
  }
  return 0;
}

Vec3 printed_face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double u = v_m_s.dot(n);
  return -(env.water_coefficient * env.water_density_kg_m3 * u * u * area_m2) * n;  // Eq. 2 as printed
}

}  // namespace stoneskip
