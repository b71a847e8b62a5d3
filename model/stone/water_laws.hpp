#pragma once
// The pressure of the water on one wetted triangle, one formula per law. water_loads()
// (model/stone/fluid_forces.hpp) clips each triangle exactly (model/README.md §1.4 steps 1–3), evaluates the
// law with the face's normal velocity u_i = v_i·n_i and the stone's own speed U = |v|, and applies
// F_i = −p_i S_i n_i (where the pressure acts: model/stone/pressure_distribution.hpp). Physical
// convention: a face carries load only while it advances into the water, u_i > 0 (the leeward side
// is ventilated, model/README.md §1.4 step 4); every law is zero for u_i ≤ 0.
//
// newtonian (Lee & Baek 2013, Eq. 2):            p_i = C_w ρ_w u_i²      published C_w = 1
// planing (Rosellini, Hersen, Clanet & Bocquet, J. Fluid Mech. 543:137, 2005, eq. 4.2; Clanet,
//   Hersen & Bocquet, Nature 427:29, 2004; Truscott, Belden & Hurd, Physics Today 67(12):70, 2014):
//   F = C_L ρ_w U² S sin(α + β) normal to the stone, U the stone's translational speed, C_L = ½.
//   Per face U sin(α + β) is the normal velocity, so
//                                                p_i = C_w ρ_w U u_i     published C_w = C_L = ½
//   U is |v| of the centre of mass, not of the face: the spin's in-plane velocity of a flat face
//   does not load it (at 65 rev/s a 2.5 cm disk's rim moves at ≈ 10 m/s, three times U).
// nagahiro_hayakawa (Nagahiro & Hayakawa, PRL 94:174501, 2005): their normal-pressure law
//   f = −½ C_D ρ (v·n)² S n with C_D = 1.4 fitted to SPH, i.e.
//                                                p_i = C_w ρ_w u_i²      published C_w = ½ C_D = 0.7
//   It is newtonian with their coefficient (an earlier `lift_drag` resolved this same force into
//   lift and drag; it is named for what it is).
//
// Passivity: a face's fluid power is −p_i u_i S_i ≤ 0 when p_i is evaluated with the normal
// velocity at the point where the face's pressure acts (pressure_distribution.hpp does so).
// Smoothness in the state (what the CVODE reference locates, solvers/realtime/stone_events.hpp):
// every law is zero at u_i = 0 and continuous there; newtonian (∝ max(u, 0)²) is C¹ with a jump in
// the second derivative, planing (∝ max(u, 0) |v|) C⁰ with a jump in the first; |v| is smooth
// wherever a face can be wet and advancing (u_i > 0 with |v| = 0 needs spin alone).
#include "model/stone/environment.hpp"
#include "model/stone/mesh.hpp"

namespace stoneskip {

// The law's pressure p_i ≥ 0 (Pa) on a face with normal velocity u (> 0 advancing) while the
// stone's centre of mass moves at stone_speed_m_s (physical convention; zero for u ≤ 0).
double law_pressure_Pa(const Environment& env, double normal_velocity_m_s, double stone_speed_m_s);

// Lee & Baek 2013 Eq. 2 as printed (paper convention): −C_w ρ_w u_i² S_i n_i on every wet face,
// whatever the sign of u_i.
Vec3 printed_face_force_N(const Environment& env, const Vec3& n, const Vec3& v_m_s, double area_m2);

}  // namespace stoneskip
