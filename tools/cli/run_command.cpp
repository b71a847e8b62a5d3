// stoneskip run CASE [--set key=value ...] [--solver realtime|reference|both] [--rtol R] [--json] [--out FILE.h5]
//                    [--max-memory-gb G] [--allow-large]
//
// One throw of a stone case: prints a readable summary (bounces, each contact's times and speeds,
// distance, lateral deviation, why the throw ended, what it cost) or, with --json, one JSON object
// (with --solver both: {"case": ..., "realtime": {...}, "reference": {...}, "agreement": {...}}).
// With --solver both a last line says how far the two agree: the bounce counts, the first
// contact's start time in each and their difference, and the contact lists compared
// (verification/stones/contact_comparison.hpp).
//   stoneskip run cases/paper_8ms_spin.toml
//   stoneskip run cases/paper_8ms_spin.toml --set environment.convention=paper --json
//   stoneskip run cases/clanet_disk.toml --solver both --out clanet.h5
// Before any work: the case is validated, the run's memory and work are estimated and held to the
// limits of cases/README.md ("Limits"), and the --out file's place is checked by creating its
// temporary. A failed solve (exit 1) writes no result file.
#include <cmath>
#include <cstdio>
#include <limits>
#include <iostream>
#include <memory>

#include "solvers/reference/cvode_stone.hpp"
#include "verification/stones/contact_comparison.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/progress.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/scene_throw.hpp"
#include "tools/scene/throw_output.hpp"

namespace stoneskip::cli {
namespace {

struct RunArgs {
  std::string case_file;
  std::vector<std::string> sets;
  std::string solver = "realtime";
  double rtol = 0;
  CLI::Option* rtol_option = nullptr;
  bool json = false;
  std::string out;
  CLI::Option* out_option = nullptr;
  ResourceLimits limits;
};

// The first contact's start (s), or NaN when the throw never touched the water.
double first_contact_s(const ThrowResult& r) {
  return r.contacts.empty() ? std::numeric_limits<double>::quiet_NaN() : r.contacts.front().start_s;
}

std::string seconds(double t_s) {
  if (!std::isfinite(t_s)) return "none";
  char b[32];
  std::snprintf(b, sizeof b, "%.4f s", t_s);
  return b;
}

// Which runs failed ("" when none): a failed run's bounces until the failure are not its count,
// so the counts are then not compared.
std::string failed_runs(const ThrowResult& rt, const ThrowResult& ref) {
  const bool a = rt.outcome == Outcome::failed, b = ref.outcome == Outcome::failed;
  return a && b ? "both runs failed" : a ? "the real-time run failed" : b ? "the reference run failed" : "";
}

// Where two runs whose counts differ part: the first contact, in order, whose start differs by
// more than kPartStart_s or whose exit speed differs by more than kPartSpeed (relative), or that
// one run has and the other not. Thresholds for naming the place only: no verdict rests on them.
constexpr double kPartStart_s = 5e-4, kPartSpeed = 5e-3;
struct Parting {
  int contact = 0;   // 1-based; 0: the runs do not part (same counts, or a failed run)
  std::string what;  // "start 0.8567 s and 0.8567 s, exit 33.231 and 32.985 m/s"
  std::string cause; // the likely cause and what to do
};

Parting parting(const StoneCase& c, const ThrowResult& rt, const ThrowResult& ref) {
  Parting p;
  if (rt.bounces == ref.bounces || !failed_runs(rt, ref).empty()) return p;
  const std::size_t n = std::min(rt.contacts.size(), ref.contacts.size());
  char b[512];
  for (std::size_t i = 0; i < n && p.contact == 0; ++i) {
    const ContactRecord &a = rt.contacts[i], &r = ref.contacts[i];
    const double speed = std::max(std::abs(r.exit_speed_m_s), 1e-12);
    if (std::abs(a.start_s - r.start_s) > kPartStart_s || std::abs(a.exit_speed_m_s - r.exit_speed_m_s) > kPartSpeed * speed ||
        a.bounced != r.bounced) {
      p.contact = static_cast<int>(i) + 1;
      std::snprintf(b, sizeof b, "start %.5g s and %.5g s, exit %.5g and %.5g m/s%s", a.start_s, r.start_s, a.exit_speed_m_s,
                    r.exit_speed_m_s, a.bounced != r.bounced ? (a.bounced ? ", a bounce against a sinking" : ", a sinking against a bounce") : "");
      p.what = b;
    }
  }
  if (p.contact == 0) {
    p.contact = static_cast<int>(n) + 1;
    p.what = std::string("only the ") + (rt.contacts.size() > n ? "real-time" : "reference") + " run has it";
  }
  if (c.environment.convention == Convention::paper) {
    p.cause = "the paper convention's laws create energy and its counts are chaotic (model/README.md §1.6): one pair of "
              "runs decides nothing; compare ensembles (the stones report's section on the conventions)";
  } else if (is_adaptive(c.realtime.scheme)) {
    std::snprintf(b, sizeof b,
                  "the solvers' error (at rtol %.3g / %.3g) or a chaotic count: tighten both (solver.rtol and solver.atol_m, "
                  "--rtol) until neither count changes; a count that still moves when the release is nudged by 1e-9 "
                  "is chaotic and only ensembles decide it (solvers/README.md, \"Where the disagreements are\")",
                  c.realtime.rtol, c.reference.rtol);
    p.cause = b;
  } else {
    std::snprintf(b, sizeof b,
                  "the fixed step's error (dt_s %.3g s, contact_dt_s %.3g s): shorten both until the count stops changing, "
                  "or name no scheme for the adaptive default",
                  c.realtime.dt_s, c.realtime.contact_dt_s);
    p.cause = b;
  }
  return p;
}

// How the real-time run agrees with the reference: one line (and, where the counts differ, where
// the runs part and why they may), and the same as JSON.
std::string agreement_line(const StoneCase& sc, const ThrowResult& rt, const ThrowResult& ref) {
  const Parting part = parting(sc, rt, ref);
  const ContactComparison c = compare_contacts(rt, ref);
  const double d = first_contact_s(rt) - first_contact_s(ref);
  char diff[64] = "";
  if (std::isfinite(d)) std::snprintf(diff, sizeof diff, ", difference %+.3g ms", 1e3 * d);
  return "agreement bounces realtime " + std::to_string(rt.bounces) + ", reference " + std::to_string(ref.bounces) +
         (!failed_runs(rt, ref).empty() ? " (not compared: " + failed_runs(rt, ref) + ")"
          : rt.bounces == ref.bounces    ? " (same)"
                                         : " (differ)") +
         "; first contact at " + seconds(first_contact_s(rt)) +
         " and " + seconds(first_contact_s(ref)) + diff + "; contacts: " + c.brief() + "\n" +
         (part.contact > 0 ? "          the runs part at contact " + std::to_string(part.contact) + " (" + part.what +
                                 "); likely cause: " + part.cause + "\n"
                           : "");
}

nlohmann::json agreement_json(const StoneCase& sc, const ThrowResult& rt, const ThrowResult& ref) {
  const ContactComparison c = compare_contacts(rt, ref);
  const Parting part = parting(sc, rt, ref);
  const double d = first_contact_s(rt) - first_contact_s(ref);
  nlohmann::json j;
  j["bounces_realtime"] = rt.bounces;
  j["bounces_reference"] = ref.bounces;
  // null where a run failed: its count is not known (failed_runs above).
  j["same_bounces"] = failed_runs(rt, ref).empty() ? nlohmann::json(rt.bounces == ref.bounces) : nlohmann::json(nullptr);
  j["first_contact_difference_s"] = std::isfinite(d) ? nlohmann::json(d) : nlohmann::json(nullptr);
  j["same_contacts"] = c.same_contacts();
  j["contacts"] = c.brief();
  // Where the counts differ: the first contact at which the runs part, and the likely cause.
  j["parts_at_contact"] = part.contact > 0 ? nlohmann::json(part.contact) : nlohmann::json(nullptr);
  j["parting"] = part.contact > 0 ? nlohmann::json(part.what) : nlohmann::json(nullptr);
  j["likely_cause"] = part.contact > 0 ? nlohmann::json(part.cause) : nlohmann::json(nullptr);
  return j;
}

void run(const RunArgs& a) {
  StoneCase c = load_stone_case(a.case_file, a.sets);
  const bool realtime = a.solver == "realtime" || a.solver == "both";
  const bool reference = a.solver == "reference" || a.solver == "both";
  if (a.rtol_option->count() > 0) {
    if (!reference) throw_input_error("--rtol", 0, "", "sets the CVODE reference's tolerance: add --solver reference or both (the real-time stepper's is --set solver.rtol=... --set solver.atol_m=...)");
    if (!(a.rtol >= 1e-15 && a.rtol <= 1e-2)) {
      char got[32];
      std::snprintf(got, sizeof got, "%g", a.rtol);
      throw_input_error("--rtol", 0, "", std::string("must be in [1e-15, 1e-2] (got ") + got + ")");
    }
    c.reference.rtol = a.rtol;
  }
  const bool writes = a.out_option->count() > 0;
  if (writes && a.out.empty()) throw_input_error("--out", 0, "", "needs a file name (got an empty one)");
  if (writes) refuse_output_over_inputs(a.out, OutputKind::file, {c.file, c.spec.mesh_file});
  if (writes) refuse_foreign_output(a.out, OutputFormat::hdf5);
  if (c.water && reference)
    throw_input_error(c.file, 0, "water", "the CVODE reference supports still water only: use --solver realtime with [water]");
  enforce_limits(estimate_run(c, RunSolvers{realtime, reference, writes}), a.limits, c.file);
  if (writes) AtomicOutput probe(a.out);  // an unwritable place is refused before any work

  std::vector<std::pair<std::string, ThrowResult>> results;
  {
    const Heartbeat alive("run");
    if (realtime) results.emplace_back("realtime", run_scene_realtime(c).result);
    if (reference) results.emplace_back("reference", run_reference(c.stone, c.environment, c.initial, c.reference));
  }
  bool failed = false;
  for (const auto& [name, r] : results) failed = failed || r.outcome == Outcome::failed;

  if (a.json) {
    nlohmann::json j;
    if (results.size() == 1) {
      j = json_summary(c, results[0].second);
      j["case"] = c.title;
    } else {
      j["case"] = c.title;
      for (const auto& [name, r] : results) j[name] = json_summary(c, r);
      j["agreement"] = agreement_json(c, results[0].second, results[1].second);
    }
    j["convention"] = to_string(c.environment.convention);
    // The paper convention is Eq. 2 as printed: its law is newtonian, its pressure uniform.
    j["water_law"] = to_string(c.environment.water_law);
    j["pressure_distribution"] = to_string(c.environment.pressure_distribution);
    j["attitude"] = to_string(c.environment.attitude);
    // A title from a file name need not be UTF-8: replace what is not, never throw.
    std::cout << json_text(j) << std::endl;
  } else {
    for (const auto& [name, r] : results) std::cout << text_summary(c, r) << (results.size() > 1 ? "\n" : "");
    if (results.size() == 2) std::cout << agreement_line(c, results[0].second, results[1].second);
  }
  if (writes) {
    if (failed) {
      std::fprintf(stderr, "stoneskip: %s not written: the solve failed (a failed run writes no result file; one already at "
                   "that name is left as it was)\n",
                   a.out.c_str());
    } else {
      std::vector<std::pair<std::string, const ThrowResult*>> refs;
      for (const auto& [name, r] : results) refs.emplace_back(name, &r);
      write_throw_file(a.out, c, refs);
      if (!a.json) std::cout << "wrote " << a.out << "\n";
    }
  }
  if (failed) set_exit_code(1);
}

void add_run(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run one throw of a stone case and print its bounces");
  cmd->add_option("CASE", a->case_file, "Stone case file (TOML, see cases/README.md)")->required();
  cmd->add_option("--set", a->sets, "Override a case key: section.key=value (repeatable)");
  cmd->add_option("--solver", a->solver, "realtime (default), reference (CVODE) or both")
      ->check(CLI::IsMember({"realtime", "reference", "both"}));
  a->rtol_option = cmd->add_option("--rtol", a->rtol, "Relative tolerance of the reference solver, in [1e-15, 1e-2] (default from the case, 1e-10)");
  cmd->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  a->out_option = cmd->add_option("--out", a->out, "Write the trajectory, contacts and case to this HDF5 file (not on a failed solve)");
  add_limit_options(cmd, a->limits);
  cmd->callback([a] { run(*a); });
}

const bool kRegistered = register_command(add_run);

}  // namespace
}  // namespace stoneskip::cli
