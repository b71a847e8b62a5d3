#pragma once
// What a solver returns for one throw (model/README.md §1.8): the sampled trajectory, the contacts (a
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
  double entry_roll_deg = 0, exit_roll_deg = 0;  // sideways inclination (model/stone/throw.hpp)
  double entry_energy_J = 0, exit_energy_J = 0;
  Vec3 first_touch_m = Vec3::Zero();  // the vertex that crossed first, where it crossed
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
  long contact_steps = 0;      // real-time: steps taken with the contact step size (bs32: started wet)
  long rhs_evaluations = 0;
  long root_evaluations = 0;   // reference; real-time: trial steps cut back to a kink (KinkSteps)
  long error_test_failures = 0;  // reference; real-time bs32: trial steps rejected by the error test
  long nonlinear_iterations = 0;  // reference only
  long segments = 0;           // reference: integrations between located events
  // Real-time bs32: the largest error-test ratio of an accepted step (≤ 1 unless a frame's budget
  // forced it), the steps a budget forced, and the summed local error estimates of the positions
  // (m; ‖ŷ − y‖ over x, accepted steps): the error made, before propagation.
  double max_error_ratio = 0;
  long budget_forced_steps = 0;
  // Real-time fixed steps: steps whose stages felt the water while neither end was wet (a contact
  // passed through inside one step, unlogged; its loads changed the throw), and the first one's start.
  long steps_through_water = 0;
  double first_step_through_water_s = 0;
  double position_error_estimate_m = 0;
  double cpu_s = 0;            // CPU time of the solve: its own thread's (solvers/realtime/clocks.hpp)
  double wall_s = 0;           // wall-clock time of the solve (longer than cpu_s when cores are shared)
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
  // Reference only: the times of the located events (a vertex crossing the surface, a wet face's
  // or the air flow's switch), one per root return: where the right-hand side is not smooth.
  std::vector<double> event_times_s;
  SolverStats stats;
};

// Builds the contact list as a solver reports transitions; shared by both solvers. Contacts are
// disjoint intervals (model/README.md §1.8): a start while a contact is open, or an end while none is, is
// refused (the list is left as it was) and said so in the returned status.
class ContactLog {
 public:
  enum class Status { ok, refused_start_while_open, refused_end_while_closed };
  Status start(double t_s, const RigidState& s, const Vec3& first_touch_m, double energy_J);
  Status end(double t_s, const RigidState& s, double energy_J, bool left_water);
  void observe_wetted_area(double area_m2);
  bool in_contact() const { return open_; }
  const std::vector<ContactRecord>& contacts() const { return contacts_; }
  int bounces() const;

 private:
  std::vector<ContactRecord> contacts_;
  bool open_ = false;
};
const char* to_string(ContactLog::Status s);

// The shortest free flight between two contacts of a throw (s): min over consecutive contacts of
// the next start minus this end; +∞ with fewer than two contacts. A flight far shorter than a
// contact (a rim vertex lifting clear for a fraction of a millisecond) is still a bounce
// (model/README.md §1.8), and whether it happens turns on how far the vertex clears the water:
// bench says how many of a sweep's bounce-count disagreements lie on such throws.
double shortest_flight_s(const std::vector<ContactRecord>& contacts);
// Bounces followed by a flight shorter than tau_s (to the next contact's start): those a stone's
// mesh may not resolve (tools/scene/throw_output.hpp, UnresolvedFlights). 0 for tau_s NaN or ≤ 0.
int bounces_before_flight_shorter_than(const std::vector<ContactRecord>& contacts, double tau_s);

// Fills distance, lateral deviation, bounces, energy gain from the contacts and final state.
void finish_result(ThrowResult& r, const ContactLog& log, const RigidState& final_state, double end_time_s);

// Every vertex's depth below the surface at one state (d = η − z; > 0 under water), and which
// vertices are the deepest and the shallowest. measure_waterline reuses out's storage (no
// allocation in a step loop once it has the stone's size).
struct Waterline {
  std::vector<double> depth_m;  // per vertex of stone.body_mesh
  int deepest = -1, shallowest = -1;
  int submerged = 0;            // vertices with d > 0
  bool wet() const { return submerged > 0; }
  bool sunk() const { return !depth_m.empty() && submerged == static_cast<int>(depth_m.size()); }
  double deepest_m() const { return depth_m[deepest]; }
};
void measure_waterline(const Stone& stone, const RigidState& s, const WaterSurface* surface, Waterline& out);

// The point of the stone deepest below the surface and its depth (d = η − z; > 0 under water).
struct DeepestPoint {
  double depth_m = -1e300;
  Vec3 position_m = Vec3::Zero();
  int submerged_vertices = 0;
  int vertex_count = 0;
};
DeepestPoint deepest_point(const Stone& stone, const RigidState& s, const WaterSurface* surface = nullptr);

}  // namespace stoneskip
