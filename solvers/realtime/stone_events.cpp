#include "solvers/realtime/stone_events.hpp"

#include <cmath>

#include "model/stone/triangle_clip.hpp"

namespace stoneskip {

namespace {
// A normal velocity below this fraction of the stone's velocity scale is taken as exactly zero.
// Faces whose u_i vanishes identically (a rim face of a flat plate falling straight down) would
// otherwise flicker in sign at round-off level (~1e-16 of the scale) and raise spurious events;
// CVODE treats an exactly zero root function as inactive until it moves away from zero.
constexpr double kSwitchSnap = 1e-12;
// A vertex whose height disagrees with its mode by more than this was crossed twice (or more)
// within one step without a sign change for root finding to see; the mode is corrected from the
// state. Far above the root location error (~1e-14 s × vertex speed).
constexpr double kResyncTolerance_m = 1e-9;
// A face whose three vertices are all this close to the surface when one of them crosses lies in
// it: its wetted area goes from zero to whole (or back) within ~kFlatFace_m / |ż| ≲ 1e-9 s, a jump
// for any step CVODE takes. Far above the root location error (~1e-13 m).
constexpr double kFlatFace_m = 1e-9;

int sign_of(double u) { return u > 0 ? 1 : (u < 0 ? -1 : 0); }
}  // namespace

StoneEvents::StoneEvents(const Stone& stone, const Environment& env, bool locate_switches, const WaterSurface* surface)
    : stone_(stone), env_(env), surface_(surface) {
  nv_ = static_cast<int>(stone.body_mesh.vertices.size());
  const bool physical = env.convention == Convention::physical;
  faces_of_vertex_.assign(nv_, {});
  for (int i = 0; i < static_cast<int>(stone.body_mesh.triangles.size()); ++i)
    for (int j : stone.body_mesh.triangles[i]) faces_of_vertex_[j].push_back(i);
  nf_ = (locate_switches && physical) ? static_cast<int>(stone.body_mesh.triangles.size()) : 0;
  air_ = locate_switches && physical && env.air_density_kg_m3 > 0 && env.air_coefficient != 0;
  under_.assign(nv_, 0);
  sign_.assign(nf_ + (air_ ? 1 : 0), 0);
  directions_.assign(nv_ + nf_ + (air_ ? 1 : 0), 0);
}

StoneEvents::Kind StoneEvents::kind(int k) const {
  if (k < nv_) return Kind::vertex;
  if (k < nv_ + nf_) return Kind::face;
  return Kind::air;
}

int StoneEvents::submerged_vertices() const {
  int n = 0;
  for (char u : under_) n += u;
  return n;
}

bool StoneEvents::face_live(int i) const {
  const auto& t = stone_.body_mesh.triangles[i];
  return under_[t[0]] || under_[t[1]] || under_[t[2]];
}

double StoneEvents::velocity_scale(const RigidState& s, const Vec3& omega) const {
  return s.velocity_m_s.norm() + omega.norm() * stone_.bounding_radius_m;
}

// u_i = v_i·n_i with v_i = v + ω × r_i at the centroid of the submerged part (model/README.md §1.4 steps 2–4,
// physical Eq. 1), exactly as the force law evaluates it.
double StoneEvents::face_normal_velocity(int i, const RigidState& s, const Mat3& R, const Vec3& omega) const {
  const auto& t = stone_.body_mesh.triangles[i];
  Vec3 p[3];
  double d[3];
  for (int k = 0; k < 3; ++k) {
    p[k] = world_vertex(stone_, s, R, t[k]);
    d[k] = depth(p[k]);  // d = η − z
  }
  const ClippedArea c = clip_submerged(p[0], p[1], p[2], d[0], d[1], d[2]);
  Vec3 point;
  if (c.area_m2 > 0) {
    point = c.centroid_m;
  } else {
    // Live by the mode but not wet by round-off (a vertex just at the surface): the limit of the
    // clipped centroid as its area vanishes is the mean of the vertices going under.
    point = Vec3::Zero();
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      if (under_[t[k]]) {
        point += p[k];
        ++n;
      }
    }
    point /= std::max(n, 1);
  }
  const Vec3 r = point - s.position_m;
  const Vec3 vi = s.velocity_m_s + omega.cross(r);
  return vi.dot(R * stone_.face_normals_body[i]);
}

double StoneEvents::air_normal_velocity(const RigidState& s, const Mat3& R) const {
  return s.velocity_m_s.dot(R.col(2));  // model/README.md §1.5: u = v·n_d, n_d = body z in world
}

bool StoneEvents::evaluate(const double* y, double* g) const {
  for (int k = 0; k < kStateSize; ++k) {
    if (!std::isfinite(y[k])) return false;
  }
  const RigidState s = from_vector(y);
  // The quaternion is normalised here (as in the force law), so renormalising the state at a
  // restart moves no root function by more than round-off.
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  for (int j = 0; j < nv_; ++j) g[j] = y[kPosition + 2] + R.row(2).dot(stone_.body_mesh.vertices[j]);  // z_j
  if (nf_ > 0 || air_) {
    const Vec3 omega = angular_velocity(stone_, s);
    const double snap = kSwitchSnap * velocity_scale(s, omega);
    auto snapped = [snap](double u) { return std::abs(u) <= snap ? 0.0 : u; };
    for (int i = 0; i < nf_; ++i) {
      g[nv_ + i] = face_live(i) ? snapped(face_normal_velocity(i, s, R, omega)) : 1.0;
    }
    if (air_) g[nv_ + nf_] = snapped(air_normal_velocity(s, R));
  }
  for (int k = 0; k < count(); ++k) {
    if (!std::isfinite(g[k])) return false;
  }
  return true;
}

void StoneEvents::set_mode(const RigidState& s) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  for (int j = 0; j < nv_; ++j) under_[j] = depth(world_vertex(stone_, s, R, j)) > 0;
}

double StoneEvents::depth(const Vec3& p) const { return (surface_ ? surface_->height_m(p.x(), p.y()) : 0.0) - p.z(); }

double StoneEvents::value(const double* y, int k) const {
  const RigidState s = from_vector(y);
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  if (k < nv_) return y[kPosition + 2] + R.row(2).dot(stone_.body_mesh.vertices[k]);
  const Vec3 omega = angular_velocity(stone_, s);
  const double snap = kSwitchSnap * velocity_scale(s, omega);
  const double u = k < nv_ + nf_ ? (face_live(k - nv_) ? face_normal_velocity(k - nv_, s, R, omega) : 1.0)
                                 : air_normal_velocity(s, R);
  return std::abs(u) <= snap ? 0.0 : u;
}

void StoneEvents::reset(const RigidState& s) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  // A vertex exactly at the surface counts as under water when it is going under: moving down,
  // or at rest under gravity (no load acts on a zero wetted area to hold it). Counted as above
  // water, its crossing at t = 0 was not a root CVODE reports (a root at the initial point is not
  // one), and a stone released resting on the water began its contact where it sank.
  const Vec3 omega = angular_velocity(stone_, s);
  for (int j = 0; j < nv_; ++j) {
    const Vec3 p = world_vertex(stone_, s, R, j);
    const double vz = (s.velocity_m_s + omega.cross(p - s.position_m)).z();
    under_[j] = p.z() < 0 || (p.z() == 0 && (vz < 0 || (vz == 0 && env_.gravity_m_s2 > 0)));
  }
  std::fill(sign_.begin(), sign_.end(), 0);
  refresh_directions(s, std::vector<int>(sign_.size(), 0));
}

EventChange StoneEvents::apply(const int* found, const RigidState& s) {
  EventChange c;
  c.submerged_before = submerged_vertices();
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  double deepest = 1e300;
  for (int j = 0; j < nv_; ++j) {
    if (found[j] == 0) continue;
    const bool goes_under = found[j] < 0;  // z_j falling through 0
    if (goes_under == static_cast<bool>(under_[j])) continue;  // not the watched direction
    under_[j] = goes_under;
    if (goes_under) {
      ++c.vertices_under;
      const double z = world_vertex(stone_, s, R, j).z();
      if (z < deepest) {
        deepest = z;
        c.deepest_new_vertex = j;
      }
    } else {
      ++c.vertices_out;
    }
  }
  // A face lying in the surface as one of its vertices crosses: its area jumps.
  std::vector<char> counted(stone_.body_mesh.triangles.size(), 0);
  for (int j = 0; j < nv_; ++j) {
    if (found[j] == 0) continue;
    for (int i : faces_of_vertex_[j]) {
      if (counted[i]) continue;
      counted[i] = 1;
      bool flat = true;
      for (int k : stone_.body_mesh.triangles[i]) flat = flat && std::abs(world_vertex(stone_, s, R, k).z()) <= kFlatFace_m;
      if (flat) ++c.flat_faces;
    }
  }
  for (int j = 0; j < nv_; ++j) {
    const double z = world_vertex(stone_, s, R, j).z();
    const bool wrong = under_[j] ? z > kResyncTolerance_m : z < -kResyncTolerance_m;
    if (wrong) {
      under_[j] = !under_[j];
      ++c.resynced_vertices;
      if (under_[j] && c.deepest_new_vertex < 0) c.deepest_new_vertex = j;
    }
  }
  std::vector<int> hint(sign_.size(), 0);
  for (int k = nv_; k < count(); ++k) {
    if (found[k] == 0) continue;
    hint[k - nv_] = found[k];  // rising: now positive; falling: now negative
    if (kind(k) == Kind::face) ++c.face_switches;
    else ++c.air_switches;
  }
  refresh_directions(s, hint);
  c.submerged_after = submerged_vertices();
  return c;
}

void StoneEvents::refresh_directions(const RigidState& s, const std::vector<int>& hint) {
  // A submerged vertex can only come out (z rising), a dry one only go under (z falling).
  for (int j = 0; j < nv_; ++j) directions_[j] = under_[j] ? +1 : -1;
  if (nf_ == 0 && !air_) return;
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const Vec3 omega = angular_velocity(stone_, s);
  const double snap = kSwitchSnap * velocity_scale(s, omega);
  auto sign_now = [snap](double u) { return std::abs(u) <= snap ? 0 : sign_of(u); };
  for (int k = 0; k < static_cast<int>(sign_.size()); ++k) {
    const bool is_face = k < nf_;
    if (is_face && !face_live(k)) {
      sign_[k] = 0;
    } else if (hint[k] != 0) {
      sign_[k] = hint[k];
    } else if (sign_[k] == 0) {
      // Newly live (or of unknown sign): take the sign of the value; 0 watches both ways.
      sign_[k] = sign_now(is_face ? face_normal_velocity(k, s, R, omega) : air_normal_velocity(s, R));
    }
    // Otherwise no root was crossed: the sign of the last segment still holds.
    directions_[nv_ + k] = -sign_[k];  // positive: watch it fall; negative: watch it rise
  }
}

}  // namespace stoneskip
