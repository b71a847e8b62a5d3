#include "solvers/realtime/throw_result.hpp"

#include <algorithm>
#include <cmath>

#include "model/stone/throw.hpp"

namespace stoneskip {

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::sank: return "sank";
    case Outcome::time_limit: return "time_limit";
    case Outcome::failed: return "failed";
  }
  return "?";
}

const char* to_string(ContactLog::Status s) {
  switch (s) {
    case ContactLog::Status::ok: return "ok";
    case ContactLog::Status::refused_start_while_open: return "refused: a contact start while a contact is open";
    case ContactLog::Status::refused_end_while_closed: return "refused: a contact end while no contact is open";
  }
  return "?";
}

ContactLog::Status ContactLog::start(double t_s, const RigidState& s, const Vec3& first_touch_m, double energy_J) {
  if (open_) return Status::refused_start_while_open;
  ContactRecord c;
  c.start_s = t_s;
  c.end_s = t_s;
  c.entry_speed_m_s = s.velocity_m_s.norm();
  const AttitudeAngles a = attitude_angles(s);
  c.entry_path_angle_deg = a.path_angle_deg;
  c.entry_attack_angle_deg = a.attack_angle_deg;
  c.entry_roll_deg = a.roll_angle_deg;
  c.entry_energy_J = energy_J;
  c.first_touch_m = first_touch_m;
  c.entry_position_m = s.position_m;
  contacts_.push_back(c);
  open_ = true;
  return Status::ok;
}

ContactLog::Status ContactLog::end(double t_s, const RigidState& s, double energy_J, bool left_water) {
  if (!open_) return Status::refused_end_while_closed;
  ContactRecord& c = contacts_.back();
  c.end_s = t_s;
  c.exit_speed_m_s = s.velocity_m_s.norm();
  const AttitudeAngles a = attitude_angles(s);
  c.exit_path_angle_deg = a.path_angle_deg;
  c.exit_attack_angle_deg = a.attack_angle_deg;
  c.exit_roll_deg = a.roll_angle_deg;
  c.exit_energy_J = energy_J;
  c.exit_position_m = s.position_m;
  c.bounced = left_water;
  open_ = false;
  return Status::ok;
}

void ContactLog::observe_wetted_area(double area_m2) {
  if (open_) contacts_.back().max_wetted_area_m2 = std::max(contacts_.back().max_wetted_area_m2, area_m2);
}

int ContactLog::bounces() const {
  int n = 0;
  for (const auto& c : contacts_) n += c.bounced ? 1 : 0;
  return n;
}

double shortest_flight_s(const std::vector<ContactRecord>& contacts) {
  double shortest = INFINITY;
  for (std::size_t k = 1; k < contacts.size(); ++k)
    shortest = std::min(shortest, contacts[k].start_s - contacts[k - 1].end_s);
  return shortest;
}

int bounces_before_flight_shorter_than(const std::vector<ContactRecord>& contacts, double tau_s) {
  int n = 0;
  for (std::size_t k = 0; k + 1 < contacts.size(); ++k)
    if (contacts[k].bounced && contacts[k + 1].start_s - contacts[k].end_s < tau_s) ++n;
  return n;
}

void finish_result(ThrowResult& r, const ContactLog& log, const RigidState& final_state, double end_time_s) {
  r.contacts = log.contacts();
  r.bounces = log.bounces();
  r.final_state = final_state;
  r.end_time_s = end_time_s;
  const Vec3 d = final_state.position_m - r.release_position_m;
  r.distance_m = std::hypot(d.x(), d.y());
  r.lateral_m = d.y();
  r.max_energy_gain_J = 0;
  for (const auto& c : r.contacts) {
    // A contact opened and closed within one step (end = start) counts too: its energies are those
    // of two located states, and a gain between them is a gain.
    if (c.end_s >= c.start_s) r.max_energy_gain_J = std::max(r.max_energy_gain_J, c.exit_energy_J - c.entry_energy_J);
  }
}

void measure_waterline(const Stone& stone, const RigidState& s, const WaterSurface* surface, Waterline& out) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const int nv = static_cast<int>(stone.body_mesh.vertices.size());
  out.depth_m.resize(nv);
  out.deepest = out.shallowest = -1;
  out.submerged = 0;
  for (int k = 0; k < nv; ++k) {
    const Vec3 w = s.position_m + R * stone.body_mesh.vertices[k];
    const double eta = surface ? surface->height_m(w.x(), w.y()) : 0.0;
    const double d = eta - w.z();
    out.depth_m[k] = d;
    if (d > 0) ++out.submerged;
    if (out.deepest < 0 || d > out.depth_m[out.deepest]) out.deepest = k;
    if (out.shallowest < 0 || d < out.depth_m[out.shallowest]) out.shallowest = k;
  }
}

DeepestPoint deepest_point(const Stone& stone, const RigidState& s, const WaterSurface* surface) {
  Waterline w;
  measure_waterline(stone, s, surface, w);
  DeepestPoint p;
  p.vertex_count = static_cast<int>(w.depth_m.size());
  p.submerged_vertices = w.submerged;
  if (w.deepest >= 0) {
    p.depth_m = w.deepest_m();
    p.position_m = world_vertex(stone, s, s.orientation.normalized().toRotationMatrix(), w.deepest);
  }
  return p;
}

}  // namespace stoneskip
