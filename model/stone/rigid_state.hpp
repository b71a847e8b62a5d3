#pragma once
// The state of the rigid stone (model/README.md §1.3): position and velocity of the centre of mass, the
// orientation (unit quaternion, body → world) and the angular momentum in the world frame.
// As a flat vector (for CVODE and generic integrators): [x(3), v(3), q(w,x,y,z)(4), L(3)].
#include <array>

#include "model/stone/stone.hpp"

namespace stoneskip {

struct RigidState {
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_s = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 angular_momentum_kg_m2_s = Vec3::Zero();  // world frame
};

// Offsets into the flat state vector (the SUNDIALS examples' Ith(v, i) habit): y[kPosition + k],
// y[kVelocity + k], y[kAngularMomentum + k] for k = 0..2 (x, y, z); y[kQuaternion + 0..3] = (w, x, y, z).
constexpr int kPosition = 0;
constexpr int kVelocity = 3;
constexpr int kQuaternion = 6;
constexpr int kAngularMomentum = 10;
constexpr int kStateSize = 13;
using StateVector = std::array<double, kStateSize>;

StateVector to_vector(const RigidState& s);
RigidState from_vector(const double* y);  // the quaternion is taken as stored (not normalised)

// ω = R I_body⁻¹ Rᵀ L (model/README.md §1.3).
Vec3 angular_velocity(const Stone& stone, const RigidState& s);
// The same state with its body angular velocity given (L = R I ω_body).
void set_body_angular_velocity(const Stone& stone, RigidState& s, const Vec3& omega_body_rad_s);

// World position of body vertex k.
inline Vec3 world_vertex(const Stone& stone, const RigidState& s, const Mat3& R, int k) {
  return s.position_m + R * stone.body_mesh.vertices[k];
}

}  // namespace stoneskip
