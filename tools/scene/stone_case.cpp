#include "tools/scene/stone_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/scene/mesh_solid.hpp"
#include "tools/scene/obj_reader.hpp"
#include "tools/scene/wave_case.hpp"

namespace stoneskip {

namespace {

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

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
  // A key of the other shapes is named as such, not as a misspelling.
  const std::vector<std::string> own =
      s.shape == StoneShape::mesh_file ? std::vector<std::string>{"mesh_file", "disk_radius_m"}
      : s.shape == StoneShape::prism   ? std::vector<std::string>{"radius_m", "thickness_m", "segments", "rim_split"}
                                       : std::vector<std::string>{"radius_m", "thickness_m", "segments"};
  for (const char* key : {"mesh_file", "disk_radius_m", "radius_m", "thickness_m", "segments", "rim_split"})
    if (t.has(key) && std::find(own.begin(), own.end(), key) == own.end())
      t.fail(key, std::string("is a key of ") +
                      (std::string(key) == "rim_split"           ? "shape \"prism\""
                       : s.shape == StoneShape::mesh_file ? "shape \"prism\" or \"lens\""
                                                          : "shape \"mesh\"") +
                      ", not of shape \"" + shape + "\"");
  if (s.shape == StoneShape::prism && t.has("rim_split")) {
    const std::string split = t.string("rim_split");
    if (!parse_rim_split(split, s.rim_split)) t.fail("rim_split", "must be \"diagonal\" or \"centre\" (got \"" + split + "\")");
  }
  if (s.shape == StoneShape::mesh_file) {
    s.mesh_file = t.string("mesh_file");
    if (s.mesh_file.empty()) t.fail("mesh_file", "must name a Wavefront OBJ file (got an empty string)");
    std::filesystem::path p(s.mesh_file);
    if (p.is_relative()) s.mesh_file = (std::filesystem::path(file).parent_path() / p).lexically_normal().string();
    try {
      require_regular_file(s.mesh_file);
    } catch (const InputError& e) {
      t.fail("mesh_file", e.what());
    }
    s.radius_m = t.bounded_or("disk_radius_m", 0.0, kStoneRadius.lo, kStoneRadius.hi);
  } else {
    s.radius_m = t.bounded("radius_m", kStoneRadius.lo, kStoneRadius.hi);
    s.thickness_m = t.bounded("thickness_m", kStoneThickness.lo, kStoneThickness.hi);
    s.segments = static_cast<int>(t.bounded_integer_or("segments", s.shape == StoneShape::prism ? 11 : 22, 3, kMaxSegments));
  }
  const bool has_density = t.has("density_kg_m3"), has_mass = t.has("mass_kg");
  if (has_density == has_mass) t.fail(has_mass ? "mass_kg" : "density_kg_m3", "give exactly one of density_kg_m3 and mass_kg");
  if (has_density)
    s.density_kg_m3 = t.bounded("density_kg_m3", kStoneDensity.lo, kStoneDensity.hi);
  else
    s.mass_kg = t.bounded("mass_kg", kStoneMass.lo, kStoneMass.hi);
  t.finish();
  return s;
}

Environment read_environment(TomlTable t) {
  Environment e;
  const std::string conv = t.string_or("convention", "physical");
  if (!parse_convention(conv, e.convention)) t.fail("convention", "must be \"physical\" or \"paper\" (got \"" + conv + "\")");
  e.water_density_kg_m3 = t.bounded_or("water_density_kg_m3", e.water_density_kg_m3, 1, 1e5);
  e.air_density_kg_m3 = t.bounded_or("air_density_kg_m3", e.air_density_kg_m3, 0, 100);
  set_default_water_model(e);  // by convention; a named law or distribution replaces it
  if (t.has("water_law")) {
    const std::string law = t.string("water_law");
    WaterLaw water_law = WaterLaw::newtonian;
    if (!parse_water_law(law, water_law))
      t.fail("water_law", "must be \"newtonian\", \"planing\" or \"nagahiro_hayakawa\" (got \"" + law + "\")" +
                              (law == "lift_drag" ? ": lift_drag was newtonian with C_w 0.7 and is now named nagahiro_hayakawa" : ""));
    set_water_law(e, water_law);  // the law's published C_w unless water_coefficient is given
    if (e.convention == Convention::paper && water_law != WaterLaw::newtonian) t.fail("water_law", environment_problem(e));
  }
  e.water_coefficient = t.bounded_or("water_coefficient", e.water_coefficient, 0, 100);
  if (e.convention == Convention::paper && e.water_coefficient != 1) t.fail("water_coefficient", environment_problem(e));
  if (t.has("pressure_distribution")) {
    const std::string dist = t.string("pressure_distribution");
    if (!parse_pressure_distribution(dist, e.pressure_distribution))
      t.fail("pressure_distribution",
             "must be \"uniform\", \"savitsky\" or \"savitsky_wagner\" (got \"" + dist + "\")");
    if (e.convention == Convention::paper && e.pressure_distribution != PressureDistribution::uniform)
      t.fail("pressure_distribution", environment_problem(e));
  }
  const std::string att = t.string_or("attitude", to_string(e.attitude));
  if (!parse_attitude(att, e.attitude)) t.fail("attitude", "must be \"free\" or \"held\" (got \"" + att + "\")");
  if (e.convention == Convention::paper && e.attitude == Attitude::held) t.fail("attitude", environment_problem(e));
  e.air_coefficient = t.bounded_or("air_coefficient", e.air_coefficient, 0, 100);
  if (e.convention == Convention::paper && e.air_coefficient != 1) t.fail("air_coefficient", environment_problem(e));
  e.gravity_m_s2 = t.bounded_or("gravity_m_s2", e.gravity_m_s2, 0, 1000);
  t.finish();
  return e;
}

// Three numbers, each in [lo, hi].
Vec3 vec3(TomlTable& t, const std::string& key, double lo, double hi) {
  const std::vector<double> v = t.numbers(key);
  if (v.size() != 3) t.fail(key, "expected 3 numbers, got " + std::to_string(v.size()));
  for (double x : v)
    if (!(x >= lo && x <= hi)) t.fail(key, "each component must be in [" + num(lo) + ", " + num(hi) + "] (got " + num(x) + ")");
  return Vec3(v[0], v[1], v[2]);
}

void read_throw(TomlTable t, StoneCase& c) {
  if (auto st = t.maybe_table("state")) {
    // A full initial state (what the Wii Remote path produces): world frame.
    c.throw_from_parameters = false;
    RigidState s;
    s.position_m = vec3(*st, "position_m", -kMaxPosition_m, kMaxPosition_m);
    if (!(s.position_m.z() >= kReleaseHeight.lo && s.position_m.z() <= kReleaseHeight.hi))
      st->fail("position_m", "the height z must be in [" + num(kReleaseHeight.lo) + ", " + num(kReleaseHeight.hi) +
                                 "] (got " + num(s.position_m.z()) + ")");
    s.velocity_m_s = vec3(*st, "velocity_m_s", -kMaxSpeed_m_s, kMaxSpeed_m_s);
    const std::vector<double> q = st->numbers("quaternion_wxyz");
    if (q.size() != 4) st->fail("quaternion_wxyz", "expected 4 numbers (w, x, y, z)");
    // Normalised with its largest component taken out first, so that neither 1e300 nor 1e-300
    // overflows or underflows on the way (any direction but zero is an orientation).
    const double big = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
    if (!(big > 0)) st->fail("quaternion_wxyz", "must not be zero");
    const double qw = q[0] / big, qx = q[1] / big, qy = q[2] / big, qz = q[3] / big;
    const double qn = std::sqrt(qw * qw + qx * qx + qy * qy + qz * qz);
    s.orientation = Quat(qw / qn, qx / qn, qy / qn, qz / qn);
    const Vec3 w = vec3(*st, "angular_velocity_rad_s", -kMaxAngularSpeed_rad_s, kMaxAngularSpeed_rad_s);
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
  p.speed_m_s = t.bounded("speed_m_s", 0, kMaxSpeed_m_s);
  p.path_angle_deg = t.bounded("path_angle_deg", -90, 90);
  p.attack_angle_deg = t.bounded("attack_angle_deg", -90, 90);
  p.spin_rev_s = t.bounded_or("spin_rev_s", 0.0, -kMaxSpin_rev_s, kMaxSpin_rev_s);
  p.height_m = t.bounded("height_m", kReleaseHeight.lo, kReleaseHeight.hi);
  p.wobble_rad_s = t.bounded_or("wobble_rad_s", 0.0, -kMaxAngularSpeed_rad_s, kMaxAngularSpeed_rad_s);
  t.finish();
  c.initial = initial_state(c.stone, p);
}

RealtimeOptions read_solver(TomlTable t) {
  RealtimeOptions o;
  // No scheme named: the adaptive bs32, unless the case types a contact step, the fixed stepper's
  // key (such a case keeps the semi-implicit Euler it was written for).
  const Scheme fallback = t.has("contact_dt_s") ? Scheme::semi_implicit_euler : Scheme::bs32;
  const std::string scheme = t.string_or("scheme", to_string(fallback));
  if (!parse_scheme(scheme, o.scheme))
    t.fail("scheme",
           "must be \"bs32\", \"dp54\", \"semi_implicit_euler\", \"midpoint\" or \"rk4\" (got \"" + scheme + "\")");
  if (is_adaptive(o.scheme)) {
    // A fixed scheme's contact step is read and not used, so that a case written for one can be
    // switched with --set solver.scheme=bs32 (cases/README.md says so).
    if (t.has("contact_dt_s")) o.contact_dt_s = t.bounded("contact_dt_s", kMinStep_s, kMaxStep_s);
    // The default tolerance (solvers/realtime/stone_stepper.hpp says how it was chosen).
    o.dt_s = t.number_or("dt_s", kAdaptiveLargestStep_s);
    o.rtol = t.number_or("rtol", kDefaultAdaptiveTolerance);
    o.atol_m = t.number_or("atol_m", kDefaultAdaptiveTolerance);
  } else {
    for (const char* key : {"rtol", "atol_m"})
      if (t.has(key)) t.fail(key, std::string("sets the adaptive scheme's tolerance; scheme \"") + scheme +
                                      "\" takes fixed steps (dt_s, contact_dt_s)");
    if (!t.has("scheme") && !t.has("dt_s"))
      t.fail("dt_s", "missing key: a [solver] that types contact_dt_s and names no scheme is a fixed-step "
                     "(semi_implicit_euler) case, which needs dt_s too; or name scheme = \"bs32\" for the adaptive default");
    o.dt_s = t.number("dt_s");
    o.contact_dt_s = t.number("contact_dt_s");
  }
  if (t.has("kinks")) {
    const std::string k = t.string_or("kinks", "");
    KinkSteps kinks{};
    if (!parse_kink_steps(k, kinks)) t.fail("kinks", "must be \"none\", \"crossings\" or \"all\" (got \"" + k + "\")");
    o.kinks = kinks;
  }
  if (t.has("rhs_per_frame")) {
    if (!is_adaptive(o.scheme)) t.fail("rhs_per_frame", std::string("is the adaptive scheme's budget; scheme \"") + scheme + "\" takes fixed steps");
    o.rhs_per_frame = t.bounded_integer_or("rhs_per_frame", 0, kMinRhsPerFrame, kMaxRhsPerFrame);
    o.frame_dt_s = t.bounded_or("frame_dt_s", o.frame_dt_s, kMinStep_s, kMaxStep_s);
  } else if (t.has("frame_dt_s")) {
    t.fail("frame_dt_s", "sets the frame of a right-hand-side budget: give rhs_per_frame too");
  }
  o.t_max_s = t.number("t_max_s");
  o.output_dt_s = t.number_or("output_dt_s", is_adaptive(o.scheme) ? kAdaptiveOutputStep_s : o.dt_s);
  if (const auto problem = realtime_options_problem(o)) t.fail(problem->first, problem->second);
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
  o.rtol = t.bounded_or("rtol", o.rtol, 1e-15, 1e-2);
  o.atol = t.bounded_or("atol", o.atol, 1e-20, 1);
  o.max_steps = t.bounded_integer_or("max_steps", o.max_steps, 1, 1000000000);
  const std::string scaling = t.string_or("atol_scaling", to_string(o.atol_scaling));
  if (!parse_tolerance_scaling(scaling, o.atol_scaling))
    t.fail("atol_scaling", "must be \"per_component\" or \"uniform\" (got \"" + scaling + "\")");
  const std::string restart = t.string_or("restart", to_string(o.restart));
  if (!parse_restart_strategy(restart, o.restart))
    t.fail("restart", "must be \"every_event\", \"every_crossing\", \"at_jumps\" or \"never\" (got \"" + restart + "\")");
  o.max_step_s = t.bounded_or("max_step_s", o.max_step_s, 0, t_max_s);
  o.max_events_per_ms = static_cast<int>(t.bounded_integer_or("max_events_per_ms", o.max_events_per_ms, 1, 1000000));
  o.max_steps_per_ms = t.bounded_integer_or("max_steps_per_ms", o.max_steps_per_ms, 1, 1000000000);
  t.finish();
  return o;
}

}  // namespace

std::optional<std::pair<std::string, std::string>> realtime_options_problem(const RealtimeOptions& o) {
  auto range = [](const char* key, double v, double lo, double hi) -> std::optional<std::pair<std::string, std::string>> {
    if (v >= lo && v <= hi) return std::nullopt;
    return std::make_pair(std::string(key), "must be in [" + num(lo) + ", " + num(hi) + "] (got " + num(v) + ")");
  };
  if (auto p = range("dt_s", o.dt_s, kMinStep_s, kMaxStep_s)) return p;
  if (is_adaptive(o.scheme)) {
    if (auto p = range("rtol", o.rtol, kMinTolerance, kMaxTolerance)) return p;
    if (auto p = range("atol_m", o.atol_m, kMinTolerance, kMaxTolerance)) return p;
    if (auto p = range("t_max_s", o.t_max_s, kMinDuration_s, kMaxDuration_s)) return p;
    if (auto p = range("output_dt_s", o.output_dt_s, 0, o.t_max_s)) return p;
    return std::nullopt;
  }
  if (auto p = range("contact_dt_s", o.contact_dt_s, kMinStep_s, kMaxStep_s)) return p;
  if (o.contact_dt_s > o.dt_s) return std::make_pair(std::string("contact_dt_s"), std::string("must not exceed dt_s"));
  if (auto p = range("t_max_s", o.t_max_s, kMinDuration_s, kMaxDuration_s)) return p;
  // A step longer than the run (and output_dt_s, whose default is dt_s, with it).
  if (o.dt_s > o.t_max_s)
    return std::make_pair(std::string("dt_s"), "must not exceed t_max_s = " + num(o.t_max_s) + " s (got " + num(o.dt_s) + ")");
  if (auto p = range("output_dt_s", o.output_dt_s, 0, o.t_max_s)) return p;
  if (o.t_max_s / o.contact_dt_s > kMaxStepsPerThrow)
    return std::make_pair(std::string("t_max_s"), "t_max_s / contact_dt_s = " + num(o.t_max_s / o.contact_dt_s) +
                                                      " steps exceeds " + num(kMaxStepsPerThrow));
  return std::nullopt;
}

Stone build_stone(const StoneSpec& spec, const std::string& file) {
  Mesh mesh;
  std::ostringstream d;
  switch (spec.shape) {
    case StoneShape::prism:
      mesh = make_prism(spec.radius_m, spec.thickness_m, spec.segments, spec.rim_split);
      d << "prism R=" << spec.radius_m << " m, h=" << spec.thickness_m << " m, N=" << spec.segments;
      if (spec.rim_split == RimSplit::centre) d << ", rim faces split at their centres";
      break;
    case StoneShape::lens:
      mesh = make_lens(spec.radius_m, spec.thickness_m, spec.segments);
      d << "lens R=" << spec.radius_m << " m, h=" << spec.thickness_m << " m, N=" << spec.segments;
      break;
    case StoneShape::mesh_file: {
      std::vector<long> lines, vertex_lines;  // each triangle's and each vertex's line in the OBJ file
      mesh = read_obj(spec.mesh_file, &lines, &vertex_lines);
      // An unwelded export (each face with its own copies of its corners) describes the same solid
      // as a welded one: copies at exactly one position are one vertex (model/stone/mesh.hpp).
      const int merged = merge_repeated_vertices(mesh, &vertex_lines);
      // A problem names the OBJ file's line of the first triangle at fault (and of the second, for
      // two that cross), or of the vertex at fault: a triangle's number alone is no help where
      // polygons were fanned.
      auto refuse = [&](const std::string& problem, int at_fault, int other, int vertex = -1) {
        const auto line = [&](int t) { return t >= 0 && t < static_cast<int>(lines.size()) ? lines[t] : 0L; };
        const long at = vertex >= 0 && vertex < static_cast<int>(vertex_lines.size()) ? vertex_lines[vertex] : line(at_fault);
        std::string where = spec.mesh_file;
        if (at > 0) where += ":" + std::to_string(at);
        std::string more;
        if (line(other) > 0)
          more = " (triangle " + std::to_string(at_fault + 1) + " is on line " + std::to_string(line(at_fault)) + ", triangle " +
                 std::to_string(other + 1) + " on line " + std::to_string(line(other)) + ")";
        throw_input_error(file, 0, "stone.mesh_file", where + ": " + problem + more);
      };
      const MeshCheck check = check_mesh(mesh);
      if (!check.ok) refuse(check.problem, check.at_fault, -1, check.vertex_at_fault);
      const SolidCheck solid = check_solid(mesh);
      if (!solid.ok) refuse(solid.problem, solid.at_fault, solid.other_at_fault);
      d << "mesh " << spec.mesh_file;
      if (merged > 0) d << ", " << merged << " repeated vertices merged";
      break;
    }
  }
  d << " (" << mesh.triangles.size() << " triangles)";
  const MassProperties mp = spec.density_kg_m3 > 0 ? mass_properties_from_density(mesh, spec.density_kg_m3)
                                                   : mass_properties_from_mass(mesh, spec.mass_kg);
  if (!(mp.mass_kg > 0) || !mp.inertia_kg_m2.allFinite())
    throw_input_error(file, 0, "stone", "the mesh has no positive volume");
  // A mesh's size first: one in millimetres makes its mass and density implausible too, and the
  // size says why (the same reach from the centre of mass as make_stone's bounding radius).
  if (spec.shape == StoneShape::mesh_file) {
    double reach = 0;
    for (const Vec3& v : mesh.vertices) reach = std::max(reach, (v - mp.center_of_mass_m).norm());
    if (!(reach >= kStoneRadius.lo && reach <= kStoneRadius.hi))
      throw_input_error(file, 0, "stone.mesh_file",
                        spec.mesh_file + ": the stone reaches " + num(reach) + " m from its centre of mass, outside [" +
                            num(kStoneRadius.lo) + ", " + num(kStoneRadius.hi) + "] m (a mesh in millimetres?)");
  }
  // Plausibility of what the keys only imply (cases/README.md, Limits).
  if (!(mp.density_kg_m3 >= kStoneDensity.lo && mp.density_kg_m3 <= kStoneDensity.hi))
    throw_input_error(file, 0, "stone", "mass " + num(mp.mass_kg) + " kg in a volume of " + num(mp.volume_m3) +
                                            " m^3 is a density of " + num(mp.density_kg_m3) + " kg/m^3, outside [" +
                                            num(kStoneDensity.lo) + ", " + num(kStoneDensity.hi) + "]");
  if (!(mp.mass_kg >= kStoneMass.lo && mp.mass_kg <= kStoneMass.hi))
    throw_input_error(file, 0, "stone", "the stone's mass " + num(mp.mass_kg) + " kg is outside [" + num(kStoneMass.lo) +
                                            ", " + num(kStoneMass.hi) + "] kg");
  // A prism or a lens keeps its symmetry axis as body z, however thick (BodyAxes::mesh); a mesh
  // read from a file is turned onto its principal axes.
  Stone stone = make_stone(mesh, mp, spec.radius_m, d.str(), spec.shape == StoneShape::mesh_file ? BodyAxes::principal : BodyAxes::mesh);
  // The air's disk (model/README.md §1.5, S_d = π R²) stands for the stone's own planform: a disk
  // wider than the stone's farthest point from its axis (the default radius) is no stone's.
  if (spec.shape == StoneShape::mesh_file && spec.radius_m > 0) {
    double rim = 0;
    for (const Vec3& v : stone.body_mesh.vertices) rim = std::max(rim, std::hypot(v.x(), v.y()));
    if (spec.radius_m > rim * (1 + 1e-9))
      throw_input_error(file, 0, "stone.disk_radius_m",
                        num(spec.radius_m) + " m is wider than the stone: its farthest point from its axis is " + num(rim) +
                            " m (the default, where the key is left out)");
  }
  return stone;
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
  else
    set_default_water_model(c.environment);  // physical convention: its default law and distribution
  read_throw(top.table("throw"), c);
  c.realtime = read_solver(top.table("solver"));
  c.reference = read_reference(top.maybe_table("reference"), c.realtime.t_max_s, c.realtime.output_dt_s);
  read_scene_keys(top, c.water, c.frames);  // [water], [scene]: tools/scene/scene_case.cpp
  top.finish();
  return c;
}

StoneCase load_stone_case(const std::string& path, const std::vector<std::string>& overrides) {
  StoneCase c = stone_case_from_document(load_toml(path, overrides));
  // The file's title names the file's throw ("8 m/s"): an overridden case says what changed.
  if (!overrides.empty()) {
    std::string changed;
    for (const auto& o : overrides) changed += (changed.empty() ? "" : ", ") + o;
    c.title += " [--set " + changed + "]";
  }
  return c;
}

std::string StoneCase::resolved_settings() const {
  std::ostringstream s;
  s.precision(12);
  s << "[stone]\nshape = \"" << to_string(spec.shape) << "\"\n";
  if (spec.shape == StoneShape::mesh_file) s << "mesh_file = \"" << spec.mesh_file << "\"\n";
  else s << "radius_m = " << spec.radius_m << "\nthickness_m = " << spec.thickness_m << "\nsegments = " << spec.segments << "\n";
  if (spec.shape == StoneShape::prism) s << "rim_split = \"" << to_string(spec.rim_split) << "\"\n";
  // The keys a case file takes (so the settings run as a case): the one of density and mass the
  // case gave, and disk_radius_m only for a mesh (a prism's and a lens's is their radius).
  if (spec.mass_kg > 0) s << "mass_kg = " << stone.mass.mass_kg << "\n";
  else s << "density_kg_m3 = " << stone.mass.density_kg_m3 << "\n";
  if (spec.shape == StoneShape::mesh_file) s << "disk_radius_m = " << stone.disk_radius_m << "\n";
  s << "\n[environment]\nconvention = \"" << to_string(environment.convention) << "\"\nwater_law = \""
    << to_string(environment.water_law) << "\"\npressure_distribution = \"" << to_string(environment.pressure_distribution)
    << "\"\nattitude = \"" << to_string(environment.attitude) << "\"\n"
    << "water_density_kg_m3 = " << environment.water_density_kg_m3 << "\nair_density_kg_m3 = " << environment.air_density_kg_m3
    << "\nwater_coefficient = " << environment.water_coefficient << "\nair_coefficient = " << environment.air_coefficient
    << "\ngravity_m_s2 = " << environment.gravity_m_s2 << "\n";
  if (throw_from_parameters) {
    s << "\n[throw]\nspeed_m_s = " << throw_parameters.speed_m_s << "\npath_angle_deg = " << throw_parameters.path_angle_deg
      << "\nattack_angle_deg = " << throw_parameters.attack_angle_deg << "\nspin_rev_s = " << throw_parameters.spin_rev_s
      << "\nheight_m = " << throw_parameters.height_m << "\nwobble_rad_s = " << throw_parameters.wobble_rad_s << "\n";
  }
  // A case gives the throw's parameters or its state, never both (cases/README.md): with parameters
  // the state they give is written as comments, so the settings still run as a case.
  const Vec3 w = angular_velocity(stone, initial);
  const auto& q = initial.orientation;
  const char* c = throw_from_parameters ? "# " : "";
  s << "\n" << c << "[throw.state]" << (throw_from_parameters ? "  (the state the parameters above give)" : "") << "\n"
    << c << "position_m = [" << initial.position_m.x() << ", " << initial.position_m.y() << ", " << initial.position_m.z()
    << "]\n" << c << "velocity_m_s = [" << initial.velocity_m_s.x() << ", " << initial.velocity_m_s.y() << ", "
    << initial.velocity_m_s.z() << "]\n" << c << "quaternion_wxyz = [" << q.w() << ", " << q.x() << ", " << q.y() << ", " << q.z()
    << "]\n" << c << "angular_velocity_rad_s = [" << w.x() << ", " << w.y() << ", " << w.z() << "]\n";
  s << "\n[solver]\nscheme = \"" << to_string(realtime.scheme) << "\"\ndt_s = " << realtime.dt_s;
  if (is_adaptive(realtime.scheme))
    s << "\nrtol = " << realtime.rtol << "\natol_m = " << realtime.atol_m;
  else
    s << "\ncontact_dt_s = " << realtime.contact_dt_s;
  s << "\nt_max_s = " << realtime.t_max_s << "\noutput_dt_s = " << realtime.output_dt_s << "\n";
  s << scene_settings_toml(water, frames);
  s << "\n[reference]\nmethod = \"" << to_string(reference.method) << "\"\nrtol = " << reference.rtol << "\natol = "
    << reference.atol << "\natol_scaling = \"" << to_string(reference.atol_scaling) << "\"\nmax_steps = " << reference.max_steps
    << "\nrestart = \"" << to_string(reference.restart) << "\"\nmax_step_s = " << reference.max_step_s
    << "\nmax_events_per_ms = " << reference.max_events_per_ms << "\nmax_steps_per_ms = " << reference.max_steps_per_ms
    << "\n";
  return s.str();
}

}  // namespace stoneskip
