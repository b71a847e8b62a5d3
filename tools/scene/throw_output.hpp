#pragma once
// A throw's result as words (terminal summary), as JSON, and as an HDF5 result file.
//
// HDF5 schema (see reports/README.md, "Result files of a throw"):
//   /                 attributes: code_version, created_utc, case_file, case_text, overrides,
//                     resolved_settings, title
//   /stone            attributes: description, mass_kg, volume_m3, density_kg_m3, disk_radius_m;
//                     datasets: inertia_body_kg_m2 (9, row-major), vertices_m (table x_m,y_m,z_m),
//                     triangles (3 per triangle, flattened)
//   /<solver>         one group per solver run ("realtime", "reference"), attributes: solver,
//                     outcome, outcome_detail, bounces, distance_m, lateral_m, end_time_s,
//                     max_energy_gain_J, stats_* (steps, rhs_evaluations, ..., cpu_s)
//   /<solver>/trajectory  table: t_s, x_m, y_m, z_m, vx_m_s, vy_m_s, vz_m_s, qw, qx, qy, qz,
//                     wx_rad_s, wy_rad_s, wz_rad_s (world), energy_J, momentum_kg_m_s, wetted_area_m2
//   /<solver>/contacts    table: start_s, end_s, duration_s, entry_speed_m_s, exit_speed_m_s,
//                     entry_path_angle_deg, exit_path_angle_deg, entry_attack_angle_deg,
//                     exit_attack_angle_deg, entry_roll_deg, exit_roll_deg, entry_energy_J, exit_energy_J, first_touch_x_m,
//                     first_touch_y_m, exit_x_m, exit_y_m, max_wetted_area_m2, bounced (1/0)
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"
#include "tools/scene/stone_case.hpp"

namespace stoneskip {

std::string text_summary(const StoneCase& c, const ThrowResult& r);
// The largest rise of total energy over a flight: from the release to the first contact's entry,
// from each contact's exit to the next one's entry (0 when none rose; a last flight that the run
// ends in, with no contact after it, is not counted). In the paper convention the
// air law (Eq. 6 as printed, (v·n)² along −n) can push the stone forward; in the physical one a
// rise is the integrator's.
double max_flight_energy_gain_J(const StoneCase& c, const ThrowResult& r);
// Flights the stone's mesh may not resolve (model/README.md §1.8). A prism's or lens's N-gon rim lies
// inside its circle by the sagitta δ = R (1 − cos(π/N)) at each edge's middle, so a corner turning
// out of the water can end a contact that the round stone would not have ended. A flight shorter
// than τ_δ = 2 √(2 δ / g), the time a ballistic stone takes to rise and fall by δ, may be such a
// corner's; spec §1.8 still counts the bounce before it. δ bounds the corner's vertical reach from
// above (δ sin α at a tilt α), so the count may name more bounces than the mesh explains. Not assessed (sagitta 0) for an OBJ mesh,
// whose outline is not a polygon of a circle, or without gravity.
struct UnresolvedFlights {
  double rim_sagitta_m = 0;         // δ
  double shortest_resolved_s = 0;   // τ_δ
  int bounces_before_short_flight = 0;  // bounces followed by a flight shorter than τ_δ
  bool assessed() const { return rim_sagitta_m > 0 && shortest_resolved_s > 0; }
};
UnresolvedFlights unresolved_flights(const StoneCase& c, const ThrowResult& r);
// τ_δ of the case's stone; NaN where not assessed (an OBJ mesh, no gravity).
double shortest_resolved_flight_s(const StoneCase& c);

nlohmann::json json_summary(const ThrowResult& r);
// The same with what needs the case: max_flight_energy_gain_J (above), the stone's attitude, and
// the flights its mesh may not resolve (rim_sagitta_m, shortest_resolved_flight_s,
// bounces_before_short_flight; null where not assessed).
nlohmann::json json_summary(const StoneCase& c, const ThrowResult& r);
// Whether contact i is the last and was still open when the run ended (at t_max_s, or a failed
// solve): its end and exit values are the state there, not an exit (bounced is false).
bool contact_open_at_end(const ThrowResult& r, std::size_t i);
// The notes beside a run's numbers, one sentence each: a stone lighter than water (no buoyancy),
// a release touching the water, contacts begun off a live pond (solvers/scene/pond_extent.hpp), a
// contact still open at the end. Text (note lines), JSON (notes) and the file (each result's notes).
std::vector<std::string> run_notes(const StoneCase& c, const ThrowResult& r);
Table trajectory_table(const Stone& stone, const ThrowResult& r);
Table contacts_table(const ThrowResult& r);

// Writes the case and every (name, result) pair to a new HDF5 file, atomically; `more` adds
// groups of its own before the file is committed (a scene's water frames).
void write_throw_file(const std::string& path, const StoneCase& c,
                      const std::vector<std::pair<std::string, const ThrowResult*>>& results,
                      const std::function<void(const H5Group& root)>& more = {});

}  // namespace stoneskip
