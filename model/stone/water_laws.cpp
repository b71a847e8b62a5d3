#include "model/stone/water_laws.hpp"

#include <cmath>

namespace stoneskip {

Vec3 newtonian_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double u = v_m_s.dot(n);
  if (u <= 0) return Vec3::Zero();
  return -(coefficient * density_kg_m3 * u * u * area_m2) * n;  // Lee & Baek 2013 Eq. 2
}

Vec3 planing_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double u = v_m_s.dot(n);
  if (u <= 0) return Vec3::Zero();
  // Clanet et al. 2004, Rosellini et al. 2005: ½ C ρ U² S sin(α + β) = C_w ρ |v| u S, normal to the face.
  return -(coefficient * density_kg_m3 * u * v_m_s.norm() * area_m2) * n;
}

double face_attack_angle_rad(const Vec3& n, const Vec3& v_m_s) {
  const double u = v_m_s.dot(n);
  return std::atan2(u, (v_m_s - u * n).norm());
}

LiftDragCoefficients lift_drag_coefficients(double attack_angle_rad, double normal_coefficient) {
  // Nagahiro & Hayakawa 2005: f = −½ C ρ (v·n)² S n resolved along and across v.
  const double s = std::sin(attack_angle_rad), c = std::cos(attack_angle_rad);
  return {normal_coefficient * s * s * c, normal_coefficient * s * s * s};
}

Vec3 lift_drag_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double u = v_m_s.dot(n);
  if (u <= 0) return Vec3::Zero();
  const double speed = v_m_s.norm();  // > 0, since u > 0
  const Vec3 v_hat = v_m_s / speed;
  const Vec3 across = n - n.dot(v_hat) * v_hat;  // n's part perpendicular to v_i; zero at θ = 90°
  const double across_norm = across.norm();
  const LiftDragCoefficients k = lift_drag_coefficients(face_attack_angle_rad(n, v_m_s), 2 * coefficient);
  const double q = 0.5 * density_kg_m3 * speed * speed * area_m2;  // dynamic pressure × area
  Vec3 f = -(q * k.drag) * v_hat;
  if (across_norm > 0) f -= (q * k.lift / across_norm) * across;  // C_L ∝ cos θ vanishes with `across`
  return f;
}

Vec3 face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double c = env.water_coefficient, rho = env.water_density_kg_m3;
  switch (env.water_law) {
    case WaterLaw::newtonian: return newtonian_face_force_N(c, rho, n, v_m_s, area_m2);
    case WaterLaw::planing: return planing_face_force_N(c, rho, n, v_m_s, area_m2);
    case WaterLaw::lift_drag: return lift_drag_face_force_N(c, rho, n, v_m_s, area_m2);
  }
  return Vec3::Zero();
}

Vec3 printed_face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2) {
  const double u = v_m_s.dot(n);
  return -(env.water_coefficient * env.water_density_kg_m3 * u * u * area_m2) * n;  // Eq. 2 as printed
}

}  // namespace stoneskip
