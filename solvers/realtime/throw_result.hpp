#pragma once
// What a solver returns for one throw (spec §1.8): the sampled trajectory, the contacts (a
// contact is a maximal interval during which some S_i > 0; a bounce is the end of a contact
// followed by free flight), why the throw ended, and what it cost. Both the real-time stepper and
// the CVODE reference fill this struct, so every report compares like with like.
#include <string>
#include <vector>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

struct TrajectorySample {
  double t_s = 0;
  RigidState state;
  Vec3 angular_velocity_rad_s = Vec3::Zero();  // world frame
  double energy_J = 0;                         // kinetic + rotational + m g z
  double wetted_area_m2 = 0;
};

struct ContactRecord {
  double start_s = 0, end_s = 0;
  double entry_speed_m_s = 0, exit_speed_m_s = 0;
  double entry_path_angle_deg = 0, exit_path_angle_deg = 0;
  double entry_attack_angle_deg = 0, exit_attack_angle_deg = 0;
  double entry_energy_J = 0, exit_energy_J = 0;
  Vec3 first_touch_m = Vec3::Zero();  // the first vertex to go under
  Vec3 entry_position_m = Vec3::Zero();  // centre of mass when the contact started
  Vec3 exit_position_m = Vec3::Zero();  // centre of mass when the contact ended
  double max_wetted_area_m2 = 0;
  bool bounced = false;  // ended with the stone leaving the water
  double duration_s() const { return end_s - start_s; }
};

enum class Outcome { sank, time_limit, failed };
const char* to_string(Outcome o);

struct SolverStats {
  long steps = 0;              // accepted steps (all segments)
  long contact_steps = 0;      // real-time: steps taken with the contact step size
  long rhs_evaluations = 0;
  long root_evaluations = 0;   // reference only
  long error_test_failures = 0;  // reference only
  long nonlinear_iterations = 0;  // reference only
  long segments = 0;           // reference: integrations between located events
  double cpu_s = 0;            // wall time of the solve on one thread
};

struct ThrowResult {
  std::string solver;          // "realtime (semi_implicit_euler, dt=..)" / "reference (CVODE BDF rtol=..)"
  std::vector<TrajectorySample> trajectory;
  std::vector<ContactRecord> contacts;
  int bounces = 0;
  Outcome outcome = Outcome::time_limit;
  std::string outcome_detail;  // words: why it ended (or failed)
  double end_time_s = 0;
  RigidState final_state;
  Vec3 release_position_m = Vec3::Zero();
  double distance_m = 0;       // horizontal distance from release to the end point
  double lateral_m = 0;        // final y − release y (y to the thrower's left)
  double max_energy_gain_J = 0;  // largest rise of total energy over any contact (> 0: energy created)
  SolverStats stats;
};

// Builds the contact list as a solver reports transitions; shared by both solvers.
class ContactLog {
 public:
  void start(double t_s, const RigidState& s, const Vec3& first_touch_m, double energy_J);
  void end(double t_s, const RigidState& s, double energy_J, bool left_water);
  void observe_wetted_area(double area_m2);
  bool in_contact() const { return open_; }
  const std::vector<ContactRecord>& contacts() const { return contacts_; }
  int bounces() const;

 private:
  std::vector<ContactRecord> contacts_;
  bool open_ = false;
};

// Fills distance, lateral deviation, bounces, energy gain from the contacts and final state.
void finish_result(ThrowResult& r, const ContactLog& log, const RigidState& final_state, double end_time_s);

// The point of the stone deepest below the surface and its depth (d = η − z; > 0 under water).
struct DeepestPoint {
  double depth_m = -1e300;
  Vec3 position_m = Vec3::Zero();
  int submerged_vertices = 0;
  int vertex_count = 0;
};
DeepestPoint deepest_point(const Stone& stone, const RigidState& s, const WaterSurface* surface = nullptr);

}  // namespace stoneskip
