// stoneskip run CASE [--set key=value ...] [--solver realtime|reference|both] [--rtol R] [--json] [--out FILE.h5]
//
// One throw of a stone case: prints a readable summary (bounces, each contact's times and speeds,
// distance, lateral deviation, why the throw ended, what it cost) or, with --json, one JSON object
// (with --solver both: {"case": ..., "realtime": {...}, "reference": {...}}).
//   stoneskip run cases/paper_8ms_spin.toml
//   stoneskip run cases/paper_8ms_spin.toml --set environment.convention=paper --json
//   stoneskip run cases/clanet_disk.toml --solver both --out clanet.h5
#include <cstdio>
#include <iostream>
#include <memory>

#include "solvers/reference/cvode_stone.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/scene/scene_throw.hpp"
#include "tools/scene/throw_output.hpp"

namespace stoneskip::cli {
namespace {

struct RunArgs {
  std::string case_file;
  std::vector<std::string> sets;
  std::string solver = "realtime";
  double rtol = 0;
  bool json = false;
  std::string out;
};

void run(const RunArgs& a) {
  StoneCase c = load_stone_case(a.case_file, a.sets);
  if (a.rtol != 0) {
    if (!(a.rtol >= 1e-15 && a.rtol <= 1e-2)) throw_input_error("--rtol", 0, "", "must be in [1e-15, 1e-2]");
    c.reference.rtol = a.rtol;
  }
  if (!a.out.empty()) AtomicOutput check(a.out);  // fail on an unwritable path before computing
  if (c.water && a.solver != "realtime")
    throw_input_error(c.file, 0, "water", "the CVODE reference supports still water only: use --solver realtime with [water]");

  std::vector<std::pair<std::string, ThrowResult>> results;
  if (a.solver == "realtime" || a.solver == "both")
    results.emplace_back("realtime", run_scene_realtime(c).result);
  if (a.solver == "reference" || a.solver == "both")
    results.emplace_back("reference", run_reference(c.stone, c.environment, c.initial, c.reference));

  if (a.json) {
    nlohmann::json j;
    if (results.size() == 1) {
      j = json_summary(results[0].second);
      j["case"] = c.title;
    } else {
      j["case"] = c.title;
      for (const auto& [name, r] : results) j[name] = json_summary(r);
    }
    j["convention"] = to_string(c.environment.convention);
    std::cout << j.dump(2) << std::endl;
  } else {
    for (const auto& [name, r] : results) std::cout << text_summary(c, r) << (results.size() > 1 ? "\n" : "");
  }
  if (!a.out.empty()) {
    std::vector<std::pair<std::string, const ThrowResult*>> refs;
    for (const auto& [name, r] : results) refs.emplace_back(name, &r);
    write_throw_file(a.out, c, refs);
    if (!a.json) std::cout << "wrote " << a.out << "\n";
  }
  for (const auto& [name, r] : results)
    if (r.outcome == Outcome::failed) set_exit_code(1);
}

void add_run(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run one throw of a stone case and print its bounces");
  cmd->add_option("CASE", a->case_file, "Stone case file (TOML, see cases/README.md)")->required();
  cmd->add_option("--set", a->sets, "Override a case key: section.key=value (repeatable)");
  cmd->add_option("--solver", a->solver, "realtime (default), reference (CVODE) or both")
      ->check(CLI::IsMember({"realtime", "reference", "both"}));
  cmd->add_option("--rtol", a->rtol, "Relative tolerance of the reference solver (default from the case, 1e-10)");
  cmd->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  cmd->add_option("--out", a->out, "Write the trajectory, contacts and case to this HDF5 file");
  cmd->callback([a] { run(*a); });
}

const bool kRegistered = register_command(add_run);

}  // namespace
}  // namespace stoneskip::cli
