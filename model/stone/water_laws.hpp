#pragma once
// The force of the water on one wetted triangle, one function per law (issue 11). water_loads()
// (model/stone/fluid_forces.hpp) clips each triangle exactly (spec §1.4 steps 1–3) and calls
// face_force_N() with the wetted area S_i, the outward unit normal n_i and the velocity v_i of the
// wetted centroid; the torque is r_i × F_i. Physical convention: a face carries load only while it
// advances into the water, u_i = v_i·n_i > 0 (the leeward side is ventilated, spec §1.4 step 4);
// every law below is zero for u_i ≤ 0.
//
// newtonian (Lee & Baek 2013, Eq. 2; spec §1.4):
//     F_i = −C_w ρ_w u_i² S_i n_i                                  published C_w = 1
// planing (Clanet, Hersen & Bocquet, Nature 427:29, 2004; Rosellini, Hersen, Clanet & Bocquet,
//   J. Fluid Mech. 543:137, 2005: a force ½ C ρ U² S on the immersed area, U the speed, C ≈ 1 from
//   their fits; per face the pressure is normal to it and scales with the speed times the normal
//   velocity, as in F = C_L ρ U² S sin(α + β), C_L = ½ for a disk (Truscott, Belden & Hurd,
//   Physics Today 67(12):70, 2014), since U sin(α + β) is the normal velocity):
//     F_i = −C_w ρ_w u_i |v_i| S_i n_i                             published C_w = ½ (½ C, C = 1)
// lift_drag (Nagahiro & Hayakawa, PRL 94:174501, 2005): a lift along the part of −n_i
//   perpendicular to v_i and a drag along −v_i,
//     F_i = ½ ρ_w |v_i|² S_i (C_L(θ_i) e_L − C_D(θ_i) v̂_i),  e_L = −(n_i − (n_i·v̂_i) v̂_i)/|…|,
//   θ_i ∈ (0, π/2] the face's angle of attack (between v_i and the face plane, sin θ_i = u_i/|v_i|).
//   The coefficient functions are Nagahiro & Hayakawa's normal-pressure law f = −½ C_D ρ (v·n)² S n
//   with C_D = 1.4 fitted to their SPH simulations, resolved into lift and drag:
//     C_L(θ) = C sin²θ cos θ,   C_D(θ) = C sin³θ,   C = 2 C_w     published C_w = 0.7 (C = 1.4)
//   Source of these forms: the PRL's text could not be read here; they are the law as spec §1.4
//   and a public summary of the paper state it (no separate lift and drag fits were found), so
//   with its published C_w this law equals newtonian with C_w = 0.7, term by term
//   (water_laws_test checks it to round-off).
//
// Passivity: the fluid power of a face is F_i·v_i (Σ F_i·v + (r_i × F_i)·ω = Σ F_i·(v + ω × r_i)),
//   newtonian −C_w ρ u³ S, planing −C_w ρ u² |v| S, lift_drag −½ ρ |v|³ S C_D(θ) (the lift is
//   perpendicular to v_i): each −(something ≥ 0) when u > 0, and zero otherwise.
// Smoothness in the state (what the CVODE reference locates, solvers/reference/stone_events.hpp):
//   every law is zero at u_i = 0 and continuous there; newtonian and lift_drag (∝ max(u, 0)²) are
//   C¹ with a jump in the second derivative; planing (∝ max(u, 0) |v|) is C⁰ with a jump in the
//   first derivative. |v_i| = 0 implies u_i = 0, so it is no separate point; C_L and C_D are
//   polynomials in sin θ and cos θ, smooth on (0, π/2].
#include "model/stone/environment.hpp"
#include "model/stone/mesh.hpp"

namespace stoneskip {

Vec3 newtonian_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2);
Vec3 planing_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2);
Vec3 lift_drag_face_force_N(double coefficient, double density_kg_m3, const Vec3& n, const Vec3& v_m_s, double area_m2);

// The law of env.water_law with env.water_coefficient and env.water_density_kg_m3 (physical
// convention; zero for u_i ≤ 0).
Vec3 face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2);

// Lee & Baek 2013 Eq. 2 as printed (paper convention): −C_w ρ_w u_i² S_i n_i on every wet face,
// whatever the sign of u_i.
Vec3 printed_face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2);

// The lift_drag law's coefficient functions of the attack angle θ (radians, [0, π/2]) for a
// normal-pressure coefficient C = 2 C_w (Nagahiro & Hayakawa: C = 1.4).
struct LiftDragCoefficients {
  double lift = 0;  // C_L(θ) = C sin²θ cos θ
  double drag = 0;  // C_D(θ) = C sin³θ
};
LiftDragCoefficients lift_drag_coefficients(double attack_angle_rad, double normal_coefficient);

// The attack angle of a face, θ = atan2(u, |v − u n|) ∈ [−π/2, π/2] (positive: advancing).
double face_attack_angle_rad(const Vec3& n, const Vec3& v_m_s);

}  // namespace stoneskip
