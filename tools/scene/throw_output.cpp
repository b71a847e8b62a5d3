#include "tools/scene/throw_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "solvers/scene/pond_extent.hpp"
#include "tools/io/printable_text.hpp"

namespace stoneskip {

namespace {
std::string num(double v, const char* f = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// A table cell `width` wide with `decimals` decimals, in scientific notation where that would
// overflow the width (a run that blew up: speeds of 1e124 m/s, not a 128-digit number).
std::string cell(double v, int width, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*f", width, decimals, v);
  if (static_cast<int>(std::string(b).size()) > width) std::snprintf(b, sizeof b, "%*.*e", width, 2, v);
  return b;
}
}  // namespace

bool contact_open_at_end(const ThrowResult& r, std::size_t i) {
  if (i + 1 != r.contacts.size() || r.outcome == Outcome::sank) return false;
  const ContactRecord& k = r.contacts[i];
  return !k.bounced && k.end_s >= r.end_time_s;
}

std::vector<std::string> run_notes(const StoneCase& c, const ThrowResult& r) {
  std::vector<std::string> notes;
  // The water laws push only faces advancing into the water (spec §1.4): no buoyancy. A stone
  // lighter than water then "sinks" where a real one would float.
  if (const double rho = c.stone.mass.mass_kg / c.stone.mass.volume_m3; rho < c.environment.water_density_kg_m3)
    notes.push_back("the stone's mean density " + num(rho, "%.4g") + " kg/m^3 is below the water's " +
                    num(c.environment.water_density_kg_m3, "%.4g") +
                    ": the model has no buoyancy (only faces advancing into the water push, model/README.md §1.4), so it sinks "
                    "where a real stone would float");
  // A release with a vertex at or under the surface: the throw starts in the water, and its first
  // "entry" is the release itself, not an arrival from the air.
  if (!r.contacts.empty() && r.contacts.front().start_s <= 0)
    notes.push_back("the stone was released touching the water (a vertex at or below the surface at t = 0; "
                    "throw.height_m is its centre's height): contact 1 starts at release and its entry values are the "
                    "release's, not an arrival from the air");
  // A contact begun beyond a walled pond's rim is not on the live water the case names: the stone
  // read the edge's height there, and a two-way field took none of its push.
  if (c.water && c.water->coupling != Coupling::none) {
    const PondExtent p = pond_extent(c.water->field, c.water->origin_x_m, c.water->origin_y_m, r.contacts);
    if (!p.off.empty()) notes.push_back(off_pond_sentence(p, r.contacts, c.water->coupling == Coupling::two_way));
  }
  if (!r.contacts.empty() && contact_open_at_end(r, r.contacts.size() - 1))
    notes.push_back("contact " + std::to_string(r.contacts.size()) + " was still open when the run ended (" +
                    (r.outcome == Outcome::failed ? std::string("the solve failed") : std::string("t_max_s")) +
                    "): its end and exit values are the state there, not where the stone left the water");
  return notes;
}

namespace {
double flight_gain_from(double release_J, const ThrowResult& r) {
  double before = release_J, gain = 0;
  for (const auto& k : r.contacts) {
    gain = std::max(gain, k.entry_energy_J - before);
    before = k.exit_energy_J;
  }
  return gain;
}
}  // namespace

double max_flight_energy_gain_J(const StoneCase& c, const ThrowResult& r) {
  return flight_gain_from(mechanical_energy(c.stone, c.environment, c.initial).total_J(), r);
}

UnresolvedFlights unresolved_flights(const StoneCase& c, const ThrowResult& r) {
  UnresolvedFlights u;
  if (c.spec.shape == StoneShape::mesh_file || c.spec.segments < 3 || !(c.environment.gravity_m_s2 > 0)) return u;
  u.rim_sagitta_m = c.spec.radius_m * (1 - std::cos(M_PI / c.spec.segments));
  u.shortest_resolved_s = 2 * std::sqrt(2 * u.rim_sagitta_m / c.environment.gravity_m_s2);
  u.bounces_before_short_flight = bounces_before_flight_shorter_than(r.contacts, u.shortest_resolved_s);
  return u;
}

double shortest_resolved_flight_s(const StoneCase& c) {
  const ThrowResult none;
  const UnresolvedFlights u = unresolved_flights(c, none);
  return u.assessed() ? u.shortest_resolved_s : std::numeric_limits<double>::quiet_NaN();
}

std::string text_summary(const StoneCase& c, const ThrowResult& r) {
  std::ostringstream s;
  // Title and file name as data: a control character in either is written escaped, not sent to
  // the terminal (a bell, an escape sequence, a line break that splits the summary).
  s << "case      " << printable_text(c.title) << " (" << printable_text(c.file) << ")\n";
  s << "stone     " << printable_text(c.stone.description) << ", mass " << num(c.stone.mass.mass_kg * 1e3) << " g\n";
  s << "model     " << to_string(c.environment.convention) << " convention, " << to_string(c.environment.water_law)
    << " water law, C_w = " << c.environment.water_coefficient;
  if (c.environment.convention == Convention::physical)
    s << ", " << to_string(c.environment.pressure_distribution) << " pressure";
  const bool held = c.environment.attitude == Attitude::held;
  if (held) s << ", held attitude (torques discarded)";
  s << "\n";
  s << "solver    " << r.solver << "\n";
  s << "bounces   " << r.bounces;
  if (const UnresolvedFlights u = unresolved_flights(c, r); u.assessed() && u.bounces_before_short_flight > 0)
    s << " (" << u.bounces_before_short_flight << " of them followed by a flight shorter than "
      << num(1e3 * u.shortest_resolved_s, "%.3g") << " ms, the time a ballistic stone takes to rise and fall by the "
      << num(1e3 * u.rim_sagitta_m, "%.3g") << " mm its " << c.spec.segments
      << "-gon's rim lies inside its circle: the mesh may not resolve those flights; model/README.md §1.8)";
  s << "\n";
  s << "outcome   " << to_string(r.outcome) << ": " << r.outcome_detail << "\n";
  s << "distance  " << num(r.distance_m) << " m, lateral deviation " << num(r.lateral_m) << " m (+y = thrower's left)\n";
  // A flight's rise above round-off (a millionth of the release energy): the paper's air law, or
  // the integrator.
  const double release_J = mechanical_energy(c.stone, c.environment, c.initial).total_J();
  const double flight_gain_J = flight_gain_from(release_J, r);
  if (flight_gain_J > 1e-6 * std::abs(release_J))
    s << "energy    a flight gained " << num(flight_gain_J) << " J ("
      << (c.environment.convention == Convention::paper ? "the paper's air law, Eq. 6 as printed, pushes along −n whatever the flow)\n"
                                                        : "the integrator's: the physical air law is passive)\n");
  // Whose gain it is (spec §1.6): the paper convention's printed laws can do positive work; a held
  // attitude discards the water's torque on the spin; otherwise the physical laws are passive
  // (P = F·v + τ·ω ≤ 0, model/README.md, tested over random states), and the gain is the integrator's.
  if (r.max_energy_gain_J > 0) {
    s << "energy    a contact gained " << num(r.max_energy_gain_J) << " J (";
    if (held && c.environment.convention == Convention::paper)
      s << "the model created energy: the paper's laws as printed can do positive work, model/README.md §1.6, and a "
           "held attitude discards the water's torque on the spin)\n";
    else if (held) s << "the model created energy: a held attitude is not passive, the water's torque on the spin is discarded)\n";
    else if (c.environment.convention == Convention::paper)
      s << "the model created energy: the paper's laws as printed can do positive work, model/README.md §1.6)\n";
    else s << "the integrator's: the physical water and air laws are passive, F.v + tau.omega <= 0)\n";
  }
  for (const std::string& n : run_notes(c, r)) s << "note      " << n << "\n";
  // A frame's budget (solver.rhs_per_frame) takes a step whatever its error test says: the run is
  // then not at its tolerance, and the text said nothing (a ratio of 7e6 flipped Clanet's disk).
  if (r.stats.steps_through_water > 0)
    s << "steps     " << r.stats.steps_through_water << " step" << (r.stats.steps_through_water == 1 ? "" : "s")
      << " met the water only inside (a stage felt its loads, neither end was wet; the first at t = "
      << num(r.stats.first_step_through_water_s, "%.4g") << " s): contacts no step resolved, unlogged and uncounted, "
         "though their loads changed the throw; shorten dt_s and contact_dt_s\n";
  if (r.stats.budget_forced_steps > 0)
    s << "budget    " << r.stats.budget_forced_steps << " step" << (r.stats.budget_forced_steps == 1 ? "" : "s")
      << " forced past the error test by the frame budget (largest error ratio " << num(r.stats.max_error_ratio, "%.3g")
      << ", summed position error estimate " << num(r.stats.position_error_estimate_m, "%.3g")
      << " m): this run is not at its tolerance\n";
  if (!r.contacts.empty()) {
    s << "contacts:\n";
    s << "   #   start_s     end_s  duration_ms  entry_m_s  exit_m_s  entry_path_deg  attack_deg in→out  roll_deg in→out  bounced\n";
    for (std::size_t i = 0; i < r.contacts.size(); ++i) {
      const ContactRecord& k = r.contacts[i];
      char line[256];
      std::snprintf(line, sizeof line, "%4zu %9.5f %9.5f %s %s %s %15.2f %8.2f→%-8.2f %7.2f→%-7.2f  %s\n", i + 1,
                    k.start_s, k.end_s, cell(1e3 * k.duration_s(), 12, 3).c_str(), cell(k.entry_speed_m_s, 10, 3).c_str(),
                    cell(k.exit_speed_m_s, 9, 3).c_str(), k.entry_path_angle_deg, k.entry_attack_angle_deg,
                    k.exit_attack_angle_deg, k.entry_roll_deg, k.exit_roll_deg,
                    k.bounced ? "yes" : contact_open_at_end(r, i) ? "open" : "no");
      s << line;
    }
  }
  s << "cost      " << r.stats.steps << " steps (" << r.stats.contact_steps << " in contact), " << r.stats.rhs_evaluations
    << " right-hand sides";
  if (r.stats.segments) s << ", " << r.stats.segments << " segments, " << r.stats.root_evaluations << " root evaluations";
  s << ", " << num(r.stats.cpu_s * 1e3) << " ms\n";
  return s.str();
}

nlohmann::json json_summary(const ThrowResult& r) {
  nlohmann::json j;
  j["solver"] = r.solver;
  j["bounces"] = r.bounces;
  j["outcome"] = to_string(r.outcome);
  j["outcome_detail"] = r.outcome_detail;
  j["end_time_s"] = r.end_time_s;
  j["distance_m"] = r.distance_m;
  j["lateral_m"] = r.lateral_m;
  j["max_energy_gain_J"] = r.max_energy_gain_J;
  j["final_position_m"] = {r.final_state.position_m.x(), r.final_state.position_m.y(), r.final_state.position_m.z()};
  nlohmann::json contacts = nlohmann::json::array();
  for (const auto& c : r.contacts) {
    contacts.push_back({{"start_s", c.start_s},
                        {"end_s", c.end_s},
                        {"duration_s", c.duration_s()},
                        {"entry_speed_m_s", c.entry_speed_m_s},
                        {"exit_speed_m_s", c.exit_speed_m_s},
                        {"entry_path_angle_deg", c.entry_path_angle_deg},
                        {"exit_path_angle_deg", c.exit_path_angle_deg},
                        {"entry_attack_angle_deg", c.entry_attack_angle_deg},
                        {"exit_attack_angle_deg", c.exit_attack_angle_deg},
                        {"entry_roll_deg", c.entry_roll_deg},
                        {"exit_roll_deg", c.exit_roll_deg},
                        {"entry_energy_J", c.entry_energy_J},
                        {"exit_energy_J", c.exit_energy_J},
                        {"first_touch_m", {c.first_touch_m.x(), c.first_touch_m.y(), c.first_touch_m.z()}},
                        {"bounced", c.bounced},
                        {"open_at_end", contact_open_at_end(r, contacts.size())}});
  }
  j["contacts"] = contacts;
  j["stats"] = {{"steps", r.stats.steps},
                {"contact_steps", r.stats.contact_steps},
                {"rhs_evaluations", r.stats.rhs_evaluations},
                {"root_evaluations", r.stats.root_evaluations},
                {"error_test_failures", r.stats.error_test_failures},
                {"nonlinear_iterations", r.stats.nonlinear_iterations},
                {"segments", r.stats.segments},
                {"max_error_ratio", r.stats.max_error_ratio},
                {"budget_forced_steps", r.stats.budget_forced_steps},
                {"steps_through_water", r.stats.steps_through_water},
                {"position_error_estimate_m", r.stats.position_error_estimate_m},
                {"cpu_s", r.stats.cpu_s}};
  return j;
}

nlohmann::json json_summary(const StoneCase& c, const ThrowResult& r) {
  nlohmann::json j = json_summary(r);
  j["max_flight_energy_gain_J"] = max_flight_energy_gain_J(c, r);
  j["attitude"] = to_string(c.environment.attitude);
  const UnresolvedFlights u = unresolved_flights(c, r);
  j["rim_sagitta_m"] = u.assessed() ? nlohmann::json(u.rim_sagitta_m) : nlohmann::json(nullptr);
  j["shortest_resolved_flight_s"] = u.assessed() ? nlohmann::json(u.shortest_resolved_s) : nlohmann::json(nullptr);
  j["bounces_before_short_flight"] = u.assessed() ? nlohmann::json(u.bounces_before_short_flight) : nlohmann::json(nullptr);
  j["notes"] = run_notes(c, r);  // what the text summary's note lines say
  return j;
}

Table trajectory_table(const Stone& stone, const ThrowResult& r) {
  Table t;
  t.columns = {"t_s", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s", "qw", "qx", "qy", "qz",
               "wx_rad_s", "wy_rad_s", "wz_rad_s", "energy_J", "momentum_kg_m_s", "wetted_area_m2"};
  t.values.reserve(r.trajectory.size() * t.columns.size());
  for (const auto& p : r.trajectory) {
    const auto& s = p.state;
    const auto& w = p.angular_velocity_rad_s;
    t.add_row({p.t_s, s.position_m.x(), s.position_m.y(), s.position_m.z(), s.velocity_m_s.x(), s.velocity_m_s.y(),
               s.velocity_m_s.z(), s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z(), w.x(), w.y(),
               w.z(), p.energy_J, stone.mass.mass_kg * s.velocity_m_s.norm(), p.wetted_area_m2});
  }
  return t;
}

Table contacts_table(const ThrowResult& r) {
  Table t;
  t.columns = {"start_s", "end_s", "duration_s", "entry_speed_m_s", "exit_speed_m_s", "entry_path_angle_deg",
               "exit_path_angle_deg", "entry_attack_angle_deg", "exit_attack_angle_deg", "entry_roll_deg",
               "exit_roll_deg", "entry_energy_J", "exit_energy_J", "first_touch_x_m", "first_touch_y_m", "exit_x_m",
               "exit_y_m", "max_wetted_area_m2", "bounced", "open_at_end"};
  for (const auto& c : r.contacts) {
    const bool open = contact_open_at_end(r, t.rows());
    t.add_row({c.start_s, c.end_s, c.duration_s(), c.entry_speed_m_s, c.exit_speed_m_s, c.entry_path_angle_deg,
               c.exit_path_angle_deg, c.entry_attack_angle_deg, c.exit_attack_angle_deg, c.entry_roll_deg,
               c.exit_roll_deg, c.entry_energy_J,
               c.exit_energy_J, c.first_touch_m.x(), c.first_touch_m.y(), c.exit_position_m.x(), c.exit_position_m.y(),
               c.max_wetted_area_m2, c.bounced ? 1.0 : 0.0, open ? 1.0 : 0.0});
  }
  return t;
}

void write_throw_file(const std::string& path, const StoneCase& c,
                      const std::vector<std::pair<std::string, const ThrowResult*>>& results,
                      const std::function<void(const H5Group& root)>& more) {
  Hdf5Writer w(path);
  const H5Group& root = w.root();
  stamp_provenance(root);
  root.set_attr("title", c.title);
  root.set_attr("case_file", c.file);
  root.set_attr("case_text", c.text);
  std::string ov;
  for (const auto& o : c.overrides) ov += (ov.empty() ? "" : "\n") + o;
  root.set_attr("overrides", ov);
  root.set_attr("resolved_settings", c.resolved_settings());

  H5Group stone = root.create_group("stone");
  stone.set_attr("description", c.stone.description);
  stone.set_attr("mass_kg", c.stone.mass.mass_kg);
  stone.set_attr("volume_m3", c.stone.mass.volume_m3);
  stone.set_attr("density_kg_m3", c.stone.mass.density_kg_m3);
  stone.set_attr("disk_radius_m", c.stone.disk_radius_m);
  std::vector<double> inertia;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inertia.push_back(c.stone.inertia_body_kg_m2(i, j));
  stone.write_vector("inertia_body_kg_m2", inertia, "kg m^2");
  Table verts;
  verts.columns = {"x_m", "y_m", "z_m"};
  for (const auto& v : c.stone.body_mesh.vertices) verts.add_row({v.x(), v.y(), v.z()});
  stone.write_table("vertices_m", verts);
  std::vector<long long> tris;
  for (const auto& t : c.stone.body_mesh.triangles) tris.insert(tris.end(), {t[0], t[1], t[2]});
  stone.write_ints("triangles", tris);

  for (const auto& [name, r] : results) {
    H5Group g = root.create_group(name);
    g.set_attr("solver", r->solver);
    g.set_attr("outcome", std::string(to_string(r->outcome)));
    g.set_attr("outcome_detail", r->outcome_detail);
    g.set_attr("bounces", static_cast<long long>(r->bounces));
    g.set_attr("distance_m", r->distance_m);
    g.set_attr("lateral_m", r->lateral_m);
    g.set_attr("end_time_s", r->end_time_s);
    g.set_attr("max_energy_gain_J", r->max_energy_gain_J);
    g.set_attr("stats_steps", static_cast<long long>(r->stats.steps));
    g.set_attr("stats_contact_steps", static_cast<long long>(r->stats.contact_steps));
    g.set_attr("stats_rhs_evaluations", static_cast<long long>(r->stats.rhs_evaluations));
    g.set_attr("stats_root_evaluations", static_cast<long long>(r->stats.root_evaluations));
    g.set_attr("stats_error_test_failures", static_cast<long long>(r->stats.error_test_failures));
    g.set_attr("stats_segments", static_cast<long long>(r->stats.segments));
    g.set_attr("stats_max_error_ratio", r->stats.max_error_ratio);
    g.set_attr("stats_budget_forced_steps", static_cast<long long>(r->stats.budget_forced_steps));
    g.set_attr("stats_steps_through_water", static_cast<long long>(r->stats.steps_through_water));
    g.set_attr("stats_position_error_estimate_m", r->stats.position_error_estimate_m);
    g.set_attr("stats_cpu_s", r->stats.cpu_s);
    g.write_table("trajectory", trajectory_table(c.stone, *r));
    g.write_table("contacts", contacts_table(*r));
    g.write_strings("notes", run_notes(c, *r));  // what the text summary's note lines say
  }
  if (more) more(root);
  w.commit();
}

}  // namespace stoneskip
