#include "tools/scene/stone_case.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "tools/io/input_error.hpp"
#include "tools/scene/obj_reader.hpp"
#include "tools/scene/wave_case.hpp"

namespace stoneskip {

namespace {

const char* to_string(StoneShape s) {
  switch (s) {
    case StoneShape::prism: return "prism";
    case StoneShape::lens: return "lens";
    case StoneShape::mesh_file: return "mesh";
  }
  return "?";
}

StoneSpec read_stone(TomlTable t, const std::string& file) {
  StoneSpec s;
  const std::string shape = t.string_or("shape", "prism");
  if (shape == "prism")
    s.shape = StoneShape::prism;
  else if (shape == "lens")
    s.shape = StoneShape::lens;
  else if (shape == "mesh")
    s.shape = StoneShape::mesh_file;
  else
    t.fail("shape", "must be \"prism\", \"lens\" or \"mesh\" (got \"" + shape + "\")");
  if (s.shape == StoneShape::mesh_file) {
    s.mesh_file = t.string("mesh_file");
    std::filesystem::path p(s.mesh_file);
    if (p.is_relative()) s.mesh_file = (std::filesystem::path(file).parent_path() / p).lexically_normal().string();
    s.radius_m = t.number_or("disk_radius_m", 0.0);
    if (t.has("disk_radius_m")) t.require_positive("disk_radius_m", s.radius_m);
  } else {
    s.radius_m = t.number("radius_m");
    t.require_positive("radius_m", s.radius_m);
    s.thickness_m = t.number("thickness_m");
    t.require_positive("thickness_m", s.thickness_m);
    const long long n = t.integer_or("segments", s.shape == StoneShape::prism ? 11 : 22);
    if (n < 3) t.fail("segments", "must be at least 3 (got " + std::to_string(n) + ")");
    if (n > 100000) t.fail("segments", "must be at most 100000 (got " + std::to_string(n) + ")");
    s.segments = static_cast<int>(n);
  }
  const bool has_density = t.has("density_kg_m3"), has_mass = t.has("mass_kg");
  if (has_density == has_mass) t.fail(has_mass ? "mass_kg" : "density_kg_m3", "give exactly one of density_kg_m3 and mass_kg");
  if (has_density) {
    s.density_kg_m3 = t.number("density_kg_m3");
    t.require_positive("density_kg_m3", s.density_kg_m3);
  } else {
    s.mass_kg = t.number("mass_kg");
    t.require_positive("mass_kg", s.mass_kg);
  }
  t.finish();
  return s;
}

Environment read_environment(TomlTable t) {
  Environment e;
  const std::string conv = t.string_or("convention", "physical");
  if (!parse_convention(conv, e.convention)) t.fail("convention", "must be \"physical\" or \"paper\" (got \"" + conv + "\")");
  e.water_density_kg_m3 = t.number_or("water_density_kg_m3", e.water_density_kg_m3);
  t.require_non_negative("water_density_kg_m3", e.water_density_kg_m3);
  e.air_density_kg_m3 = t.number_or("air_density_kg_m3", e.air_density_kg_m3);
  t.require_non_negative("air_density_kg_m3", e.air_density_kg_m3);
  const std::string law = t.string_or("water_law", to_string(e.water_law));
  WaterLaw water_law = WaterLaw::newtonian;
  if (!parse_water_law(law, water_law))
    t.fail("water_law", "must be \"newtonian\", \"planing\" or \"lift_drag\" (got \"" + law + "\")");
  set_water_law(e, water_law);  // the law's published C_w unless water_coefficient is given
  if (e.convention == Convention::paper && water_law != WaterLaw::newtonian)
    t.fail("water_law", environment_problem(e));
  e.water_coefficient = t.number_or("water_coefficient", e.water_coefficient);
  t.require_non_negative("water_coefficient", e.water_coefficient);
  e.air_coefficient = t.number_or("air_coefficient", e.air_coefficient);
  t.require_non_negative("air_coefficient", e.air_coefficient);
  e.gravity_m_s2 = t.number_or("gravity_m_s2", e.gravity_m_s2);
  t.require_non_negative("gravity_m_s2", e.gravity_m_s2);
  t.finish();
  return e;
}

Vec3 vec3(TomlTable& t, const std::string& key) {
  const std::vector<double> v = t.numbers(key);
  if (v.size() != 3) t.fail(key, "expected 3 numbers, got " + std::to_string(v.size()));
  return Vec3(v[0], v[1], v[2]);
}

void read_throw(TomlTable t, StoneCase& c) {
  if (auto st = t.maybe_table("state")) {
    // A full initial state (what the Wii Remote path produces): world frame.
    c.throw_from_parameters = false;
    RigidState s;
    s.position_m = vec3(*st, "position_m");
    s.velocity_m_s = vec3(*st, "velocity_m_s");
    const std::vector<double> q = st->numbers("quaternion_wxyz");
    if (q.size() != 4) st->fail("quaternion_wxyz", "expected 4 numbers (w, x, y, z)");
    const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(qn > 0)) st->fail("quaternion_wxyz", "must not be zero");
    s.orientation = Quat(q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn);
    const Vec3 w = vec3(*st, "angular_velocity_rad_s");
    const Mat3 R = s.orientation.toRotationMatrix();
    set_body_angular_velocity(c.stone, s, R.transpose() * w);
    st->finish();
    for (const auto& k : t.keys()) {
      if (k != "state") t.fail(k, "give either [throw.state] or the throw parameters, not both");
    }
    c.initial = s;
    return;
  }
  ThrowParameters& p = c.throw_parameters;
  p.speed_m_s = t.number("speed_m_s");
  t.require_non_negative("speed_m_s", p.speed_m_s);
  p.path_angle_deg = t.number("path_angle_deg");
  t.require_in("path_angle_deg", p.path_angle_deg, -90, 90);
  p.attack_angle_deg = t.number("attack_angle_deg");
  t.require_in("attack_angle_deg", p.attack_angle_deg, -90, 90);
  p.spin_rev_s = t.number_or("spin_rev_s", 0.0);
  p.height_m = t.number("height_m");
  p.wobble_rad_s = t.number_or("wobble_rad_s", 0.0);
  t.finish();
  c.initial = initial_state(c.stone, p);
}

RealtimeOptions read_solver(TomlTable t) {
  RealtimeOptions o;
  const std::string scheme = t.string_or("scheme", to_string(o.scheme));
  if (!parse_scheme(scheme, o.scheme))
    t.fail("scheme", "must be \"semi_implicit_euler\", \"midpoint\" or \"rk4\" (got \"" + scheme + "\")");
  o.dt_s = t.number("dt_s");
  t.require_positive("dt_s", o.dt_s);
  o.contact_dt_s = t.number("contact_dt_s");
  t.require_positive("contact_dt_s", o.contact_dt_s);
  if (o.contact_dt_s > o.dt_s) t.fail("contact_dt_s", "must not exceed dt_s");
  o.t_max_s = t.number("t_max_s");
  t.require_positive("t_max_s", o.t_max_s);
  if (o.t_max_s / o.contact_dt_s > 1e9) t.fail("t_max_s", "t_max_s / contact_dt_s exceeds 1e9 steps");
  o.output_dt_s = t.number_or("output_dt_s", o.dt_s);
  t.require_non_negative("output_dt_s", o.output_dt_s);
  t.finish();
  return o;
}

ReferenceOptions read_reference(std::optional<TomlTable> maybe, double t_max_s, double output_dt_s) {
  ReferenceOptions o;
  o.t_max_s = t_max_s;
  o.output_dt_s = output_dt_s;
  if (!maybe) return o;
  TomlTable& t = *maybe;
  const std::string m = t.string_or("method", to_string(o.method));
  if (!parse_reference_method(m, o.method)) t.fail("method", "must be \"bdf\" or \"adams\" (got \"" + m + "\")");
  o.rtol = t.number_or("rtol", o.rtol);
  t.require_in("rtol", o.rtol, 1e-15, 1e-2);
  o.atol = t.number_or("atol", o.atol);
  t.require_positive("atol", o.atol);
  o.max_steps = t.integer_or("max_steps", o.max_steps);
  if (o.max_steps < 1) t.fail("max_steps", "must be at least 1");
  const std::string scaling = t.string_or("atol_scaling", to_string(o.atol_scaling));
  if (!parse_tolerance_scaling(scaling, o.atol_scaling))
    t.fail("atol_scaling", "must be \"per_component\" or \"uniform\" (got \"" + scaling + "\")");
  const std::string restart = t.string_or("restart", to_string(o.restart));
  if (!parse_restart_strategy(restart, o.restart))
    t.fail("restart", "must be \"every_event\", \"every_crossing\", \"at_jumps\" or \"never\" (got \"" + restart + "\")");
  o.max_step_s = t.number_or("max_step_s", o.max_step_s);
  t.require_non_negative("max_step_s", o.max_step_s);
  const long long events = t.integer_or("max_events_per_ms", o.max_events_per_ms);
  if (events < 1 || events > 1000000) t.fail("max_events_per_ms", "must be in [1, 1000000]");
  o.max_events_per_ms = static_cast<int>(events);
  t.finish();
  return o;
}

}  // namespace

Stone build_stone(const StoneSpec& spec, const std::string& file) {
  Mesh mesh;
  std::ostringstream d;
  switch (spec.shape) {
    case StoneShape::prism:
      mesh = make_prism(spec.radius_m, spec.thickness_m, spec.segments);
      d << "prism R=" << spec.radius_m << " m, h=" << spec.thickness_m << " m, N=" << spec.segments;
      break;
    case StoneShape::lens:
      mesh = make_lens(spec.radius_m, spec.thickness_m, spec.segments);
      d << "lens R=" << spec.radius_m << " m, h=" << spec.thickness_m << " m, N=" << spec.segments;
      break;
    case StoneShape::mesh_file: {
      mesh = read_obj(spec.mesh_file);
      const MeshCheck check = check_mesh(mesh);
      if (!check.ok) throw_input_error(file, 0, "stone.mesh_file", spec.mesh_file + ": " + check.problem);
      d << "mesh " << spec.mesh_file;
      break;
    }
  }
  d << " (" << mesh.triangles.size() << " triangles)";
  const MassProperties mp = spec.density_kg_m3 > 0 ? mass_properties_from_density(mesh, spec.density_kg_m3)
                                                   : mass_properties_from_mass(mesh, spec.mass_kg);
  if (!(mp.mass_kg > 0) || !mp.inertia_kg_m2.allFinite())
    throw_input_error(file, 0, "stone", "the mesh has no positive volume");
  return make_stone(mesh, mp, spec.radius_m, d.str());
}

StoneCase stone_case_from_document(const TomlDocument& doc) {
  StoneCase c;
  c.file = doc.file;
  c.text = doc.text;
  c.overrides = doc.overrides;
  TomlTable top = doc.top();
  c.title = read_case_title(top);
  c.spec = read_stone(top.table("stone"), doc.file);
  c.stone = build_stone(c.spec, doc.file);
  if (auto env = top.maybe_table("environment"))
    c.environment = read_environment(*env);
  read_throw(top.table("throw"), c);
  c.realtime = read_solver(top.table("solver"));
  c.reference = read_reference(top.maybe_table("reference"), c.realtime.t_max_s, c.realtime.output_dt_s);
  read_scene_keys(top, c.water, c.frames);  // [water], [scene]: tools/scene/scene_case.cpp
  top.finish();
  return c;
}

StoneCase load_stone_case(const std::string& path, const std::vector<std::string>& overrides) {
  return stone_case_from_document(load_toml(path, overrides));
}

std::string StoneCase::resolved_settings() const {
  std::ostringstream s;
  s.precision(12);
  s << "[stone]\nshape = \"" << to_string(spec.shape) << "\"\n";
  if (spec.shape == StoneShape::mesh_file) s << "mesh_file = \"" << spec.mesh_file << "\"\n";
  else s << "radius_m = " << spec.radius_m << "\nthickness_m = " << spec.thickness_m << "\nsegments = " << spec.segments << "\n";
  s << "density_kg_m3 = " << stone.mass.density_kg_m3 << "\nmass_kg = " << stone.mass.mass_kg << "\n";
  s << "disk_radius_m = " << stone.disk_radius_m << "\n";
  s << "\n[environment]\nconvention = \"" << to_string(environment.convention) << "\"\nwater_law = \""
    << to_string(environment.water_law) << "\"\n"
    << "water_density_kg_m3 = " << environment.water_density_kg_m3 << "\nair_density_kg_m3 = " << environment.air_density_kg_m3
    << "\nwater_coefficient = " << environment.water_coefficient << "\nair_coefficient = " << environment.air_coefficient
    << "\ngravity_m_s2 = " << environment.gravity_m_s2 << "\n";
  if (throw_from_parameters) {
    s << "\n[throw]\nspeed_m_s = " << throw_parameters.speed_m_s << "\npath_angle_deg = " << throw_parameters.path_angle_deg
      << "\nattack_angle_deg = " << throw_parameters.attack_angle_deg << "\nspin_rev_s = " << throw_parameters.spin_rev_s
      << "\nheight_m = " << throw_parameters.height_m << "\nwobble_rad_s = " << throw_parameters.wobble_rad_s << "\n";
  }
  const Vec3 w = angular_velocity(stone, initial);
  const auto& q = initial.orientation;
  s << "\n[throw.state]\nposition_m = [" << initial.position_m.x() << ", " << initial.position_m.y() << ", " << initial.position_m.z()
    << "]\nvelocity_m_s = [" << initial.velocity_m_s.x() << ", " << initial.velocity_m_s.y() << ", " << initial.velocity_m_s.z()
    << "]\nquaternion_wxyz = [" << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z()
    << "]\nangular_velocity_rad_s = [" << w.x() << ", " << w.y() << ", " << w.z() << "]\n";
  s << "\n[solver]\nscheme = \"" << to_string(realtime.scheme) << "\"\ndt_s = " << realtime.dt_s << "\ncontact_dt_s = "
    << realtime.contact_dt_s << "\nt_max_s = " << realtime.t_max_s << "\noutput_dt_s = " << realtime.output_dt_s << "\n";
  s << scene_settings_toml(water, frames);
  s << "\n[reference]\nmethod = \"" << to_string(reference.method) << "\"\nrtol = " << reference.rtol << "\natol = "
    << reference.atol << "\natol_scaling = \"" << to_string(reference.atol_scaling) << "\"\nmax_steps = " << reference.max_steps
    << "\nrestart = \"" << to_string(reference.restart) << "\"\nmax_step_s = " << reference.max_step_s
    << "\nmax_events_per_ms = " << reference.max_events_per_ms << "\n";
  return s.str();
}

}  // namespace stoneskip
