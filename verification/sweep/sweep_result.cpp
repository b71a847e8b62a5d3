#include "verification/sweep/sweep_result.hpp"

#include <sstream>

#include "tools/io/input_error.hpp"
#include "tools/io/isolated_read.hpp"
#include "verification/sweep/sweep_table_check.hpp"

namespace stoneskip {

namespace {

std::string join_lines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "\n") + x;
  return s;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

}  // namespace

void write_sweep_file(const std::filesystem::path& path, const SweepData& d) {
  Hdf5Writer w(path);
  const H5Group& root = w.root();
  stamp_provenance(root);
  const SweepProvenance& p = d.provenance;
  root.set_attr("title", p.title);
  root.set_attr("sweep_file", p.sweep_file);
  root.set_attr("sweep_text", p.sweep_text);
  root.set_attr("base_case_file", p.base_case_file);
  root.set_attr("base_case_text", p.base_case_text);
  root.set_attr("base_overrides", join_lines(p.base_overrides));
  root.set_attr("resolved_settings", p.resolved_settings);
  root.set_attr("input_files", p.input_files);
  root.set_attr("build", p.build);
  root.set_attr("solvers", std::string(to_string(d.solvers)));
  root.set_attr("throws", static_cast<long long>(d.throws.rows()));
  root.set_attr("outcome_codes", std::string(kOutcomeCodes));
  root.write_table("throws", d.throws);

  H5Group design = root.create_group("design");
  design.set_attr("kind", std::string(to_string(d.design.kind)));
  design.set_attr("samples", d.design.samples);
  design.set_attr("seed", static_cast<long long>(d.design.seed));
  design.set_attr("axes", static_cast<long long>(d.design.axes.size()));
  for (std::size_t k = 0; k < d.design.axes.size(); ++k) {
    const SweepAxis& a = d.design.axes[k];
    H5Group g = design.create_group("axis_" + std::to_string(k));
    g.set_attr("key", a.key);
    g.set_attr("from", a.from);
    g.set_attr("to", a.to);
    g.set_attr("count", a.count);
    g.set_attr("scale", std::string(to_string(a.scale)));
    if (d.design.kind == DesignKind::grid) g.write_vector("values", d.design.grid_values(k));
  }

  H5Group notes = root.create_group("notes");
  std::vector<long long> ids;
  std::vector<std::string> solvers, details;
  for (const auto& n : d.notes) {
    ids.push_back(static_cast<long long>(n.throw_index));
    solvers.push_back(n.solver);
    details.push_back(n.detail);
  }
  notes.write_ints("throw", ids);
  notes.write_strings("solver", solvers);
  notes.write_strings("detail", details);

  H5Group run = root.create_group("run");
  const ScheduleStats& s = d.run.schedule;
  run.set_attr("ranks", static_cast<long long>(s.ranks));
  run.set_attr("master_threads", static_cast<long long>(s.master_threads));
  run.set_attr("wall_s", s.wall_s);
  run.set_attr("throws_computed", static_cast<long long>(s.throws));
  run.set_attr("throws_remote", static_cast<long long>(s.remote_throws));
  run.set_attr("throws_recovered", static_cast<long long>(d.run.throws_recovered));
  run.set_attr("throws_per_s", s.wall_s > 0 ? s.throws / s.wall_s : 0.0);
  run.set_attr("chunks", static_cast<long long>(s.chunks));
  run.set_attr("max_chunk", static_cast<long long>(d.run.max_chunk));
  run.set_attr("master_cpu_s", s.master_cpu_s);
  run.set_attr("master_busy_cpu_s", s.master_busy_cpu_s);
  run.set_attr("master_busy_cpu_per_throw_s", s.throws ? s.master_busy_cpu_s / s.throws : 0.0);
  run.set_attr("journal_wall_s", d.run.journal_wall_s);
  run.set_attr("journal_damage", d.run.journal_damage);
  w.commit();
}

static SweepData read_in_process(const std::filesystem::path& path) {
  Hdf5Reader r(path);
  const H5Group& root = r.root();
  if (!root.has("throws") || !root.has("design") || !root.has_attr("sweep_text"))
    throw_input_error(path.string(), 0, "", "not a sweep result file (no /throws, /design or sweep_text)");
  SweepData d;
  try {
    SweepProvenance& p = d.provenance;
    p.title = root.attr_string("title");
    p.sweep_file = root.attr_string("sweep_file");
    p.sweep_text = root.attr_string("sweep_text");
    p.base_case_file = root.attr_string("base_case_file");
    p.base_case_text = root.attr_string("base_case_text");
    p.base_overrides = split_lines(root.attr_string("base_overrides"));
    p.resolved_settings = root.attr_string("resolved_settings");
    // Absent from files of older builds: such a result is not this build's.
    if (root.has_attr("input_files")) p.input_files = root.attr_string("input_files");
    if (root.has_attr("build")) p.build = root.attr_string("build");
    p.code_version = root.attr_string("code_version");
    p.created_utc = root.attr_string("created_utc");
    const std::string solvers = root.attr_string("solvers");
    bool known = false;
    for (SweepSolvers s : {SweepSolvers::realtime, SweepSolvers::reference, SweepSolvers::both})
      if (solvers == to_string(s)) {
        d.solvers = s;
        known = true;
      }
    if (!known)
      throw_input_error(path.string(), 0, "solvers", "'" + solvers + "' is not realtime, reference or realtime,reference");
    d.throws = root.read_table("throws");
    const H5Group design = root.open_group("design");
    if (!parse_design_kind(design.attr_string("kind"), d.design.kind))
      throw_input_error(path.string(), 0, "design.kind", "unknown design kind");
    d.design.samples = design.attr_int("samples");
    d.design.seed = static_cast<std::uint64_t>(design.attr_int("seed"));
    const long long axes = design.attr_int("axes");
    for (long long k = 0; k < axes; ++k) {
      const H5Group g = design.open_group("axis_" + std::to_string(k));
      SweepAxis a;
      a.key = g.attr_string("key");
      a.from = g.attr_double("from");
      a.to = g.attr_double("to");
      a.count = g.attr_int("count");
      parse_axis_scale(g.attr_string("scale"), a.scale);
      d.design.axes.push_back(a);
    }
    // A damaged or edited design is refused here, before anything sizes a figure or a map by it
    // (an axis count of 0 divided by zero, -3 indexed out of bounds, 1e6 allocated gigabytes).
    DesignProblem why;
    if (!d.design.is_valid(&why))
      throw_input_error(path.string(), 0, "design" + (why.axis >= 0 ? ".axis_" + std::to_string(why.axis) : std::string()) + "." + why.key,
                        why.what);
    if (d.design.size() != d.throws.rows())
      throw_input_error(path.string(), 0, "design", "describes " + std::to_string(d.design.size()) + " throws but /throws has " +
                                                       std::to_string(d.throws.rows()) + " rows");
    check_sweep_table(path.string(), d.design, d.solvers, d.throws);
    const H5Group notes = root.open_group("notes");
    const auto ids = notes.read_ints("throw");
    const auto solver = notes.read_strings("solver");
    const auto detail = notes.read_strings("detail");
    for (std::size_t i = 0; i < ids.size() && i < solver.size() && i < detail.size(); ++i)
      d.notes.push_back({static_cast<std::uint64_t>(ids[i]), solver[i], detail[i]});
    const H5Group run = root.open_group("run");
    ScheduleStats& s = d.run.schedule;
    s.ranks = static_cast<int>(run.attr_int("ranks"));
    s.master_threads = static_cast<int>(run.attr_int("master_threads"));
    s.wall_s = run.attr_double("wall_s");
    s.throws = static_cast<std::size_t>(run.attr_int("throws_computed"));
    s.remote_throws = static_cast<std::size_t>(run.attr_int("throws_remote"));
    s.chunks = static_cast<std::size_t>(run.attr_int("chunks"));
    s.master_cpu_s = run.attr_double("master_cpu_s");
    s.master_busy_cpu_s = run.attr_double("master_busy_cpu_s");
    d.run.throws_recovered = static_cast<std::size_t>(run.attr_int("throws_recovered"));
    d.run.journal_wall_s = run.attr_double("journal_wall_s");
    d.run.max_chunk = static_cast<std::size_t>(run.attr_int("max_chunk"));
    if (run.has_attr("journal_damage")) d.run.journal_damage = run.attr_string("journal_damage");
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw_input_error(path.string(), 0, "", std::string("not a complete sweep result file: ") + e.what());
  }
  return d;
}

SweepData read_sweep_file(const std::filesystem::path& path) {
  // A damaged file can crash or hang the HDF5 library before any check of ours: read it in a
  // child first (tools/io/isolated_read.hpp).
  read_in_child_first(path, [&] { read_in_process(path); });
  return read_in_process(path);
}

}  // namespace stoneskip
