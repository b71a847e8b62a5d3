// stoneskip sweep SWEEP.toml [--out FILE.h5] [--resume] [--threads N] [--max-chunk N] [--quiet]
//
// Runs every throw of a sweep file (a base stone case, the keys to vary on a grid or a random
// design, the solvers) and writes one HDF5 file whose /throws table has a row per throw
// (verification/sweep/sweep_result.hpp). On one machine it uses all cores; under an MPI launcher
// it spreads the throws over the ranks, rank 0 scheduling and writing:
//   stoneskip sweep cases/sweeps/paper_speed_spin.toml --out speed_spin.h5
//   mpirun -n 8 stoneskip sweep cases/sweeps/paper_speed_spin.toml --out speed_spin.h5
//   stoneskip sweep cases/sweeps/paper_speed_spin.toml --out speed_spin.h5 --resume   # after a crash
// The table is the same bits whatever the number of ranks or threads, every column but cost_*.
//
// Steps: (1) every rank reads the sweep file and the base case and builds the case at the
// design's extreme points (a bad file fails here, exit 2, nothing written); (2) rank 0 checks the
// output and opens the journal (--resume: reads it back); (3) the throws run; (4) rank 0 writes
// the file in throw order and removes the journal.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <thread>

#include "solvers/reference/cvode_stone.hpp"
#include "solvers/scene/pond_extent.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/dotted_key.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/printable_text.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/scene_throw.hpp"
#include "tools/scene/sweep_file.hpp"
#include "tools/scene/throw_output.hpp"
#include "verification/sweep/row_batch.hpp"
#include "verification/sweep/sweep_run.hpp"
#include "solvers/realtime/clocks.hpp"
#include "tools/io/usable_cores.hpp"

namespace stoneskip::cli {
namespace {

// The most compute threads rank 0 may be asked for: far more than the cores of any machine it runs
// on, far fewer than would exhaust a process's memory with their stacks (8 MB each by default).
constexpr int kMaxSweepThreads = 256;

struct SweepArgs {
  std::string file;
  std::optional<std::string> out;
  bool resume = false;
  std::optional<int> threads;  // none given: every core alone, 1 beside MPI workers (SweepRunOptions)
  std::size_t max_chunk = 32;
  bool quiet = false;
  ResourceLimits limits;
};

// The result file: --out, or SWEEP's stem + .h5 in the current folder.
std::filesystem::path out_file(const SweepArgs& a) {
  return a.out ? std::filesystem::path(*a.out) : std::filesystem::path(std::filesystem::path(a.file).stem().string() + ".h5");
}

// Collective: true when every rank got this far without an error. Otherwise the lowest failing
// rank's error is printed once and every rank exits with 2 (bad input). Alone, the error is thrown
// as an InputError. Under mpirun, every message is written before a barrier that no rank passes
// until all have written: mpirun stops the job's other ranks as soon as one exits non-zero, so a
// rank 0 that printed on its way out (after the others had left) could be stopped first.
bool all_ranks_ok(const MpiSession& mpi, const std::string& error) {
  const int failed = mpi.first_failed_rank(error.empty());
  if (failed < 0) return true;
  if (!mpi.active()) throw InputError(error);
  if (mpi.rank() == 0)
    print_input_error(failed == 0 ? error
                                  : "rank " + std::to_string(failed) + " could not set up the sweep (its message is above)");
  else if (failed == mpi.rank())
    print_input_error("rank " + std::to_string(mpi.rank()) + ": " + error);
  mpi.barrier();
  set_exit_code(2);
  return false;
}

std::string describe(const SweepFile& s, const SweepCases& cases) {
  std::string d = "sweep     " + printable_text(s.title) + " (" + printable_text(s.file) + ")\nbase      " +
                  printable_text(cases.base().title) + " (" + printable_text(s.base_file) + ")";
  for (const auto& o : s.base_sets) d += " --set " + printable_text(o);
  d += "\ndesign    " + std::string(to_string(s.design.kind)) + ", " + std::to_string(s.design.size()) + " throws";
  if (s.design.kind != DesignKind::grid) d += " (seed " + std::to_string(s.design.seed) + ")";
  for (const auto& a : s.design.axes) {
    char b[256];
    std::snprintf(b, sizeof b, "\n  vary    %s from %.6g to %.6g%s", a.key.c_str(), a.from, a.to,
                  a.scale == AxisScale::log ? " (log)" : "");
    d += b;
    if (s.design.kind == DesignKind::grid) d += ", " + std::to_string(a.count) + " points";
  }
  d += "\nsolvers   " + std::string(to_string(s.solvers)) + "\n";
  return d;
}

// One throw: its case from the base and its values, the solvers, its row.
ThrowEvaluator make_evaluator(const SweepFile& sweep, const SweepCases& cases, const ThrowRecord& record) {
  return [&sweep, &cases, &record](std::uint64_t i, const ThrowSite& site, RowBatch& out) {
    const std::vector<double> point = sweep.design.point(i);
    SweepThrowCost cost;
    cost.rank = site.rank;
    cost.thread = site.thread;
    cost.start_unix_s = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    const auto t0 = std::chrono::steady_clock::now();
    auto not_run = [&](const std::string& who, const std::string& why) {
      out.add_row(record.not_run_row(i, point, cost));
      out.notes.push_back({i, who, why});
    };
    StoneCase c;
    try {
      c = cases.at(point);
    } catch (const InputError& e) {
      cost.setup_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return not_run("case", e.what());
    }
    cost.setup_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::optional<ThrowResult> rt, ref;
    try {
      if (runs_realtime(sweep.solvers)) {
        c.realtime.record_trajectory = false;  // the row needs contacts and the end state only
        const CpuTimer cpu;
        rt = run_scene_realtime(c).result;
        cost.realtime_cpu_s = cpu.seconds();
      }
      if (runs_reference(sweep.solvers)) {
        const CpuTimer cpu;  // the trajectory stays on: CVODE then stops where `stoneskip run` does
        ref = run_reference(c.stone, c.environment, c.initial, c.reference);
        cost.reference_cpu_s = cpu.seconds();
      }
    } catch (const std::exception& e) {
      return not_run(rt ? "reference" : "realtime", std::string("the solver threw: ") + e.what());
    }
    // A contact begun beyond a walled pond's rim was not on the live water the case names (the
    // stone read the edge's height; a two-way field took none of its push): `run` says so in its
    // notes, and so does the table, in the same words (solvers/scene/pond_extent.hpp).
    if (rt && c.water && c.water->coupling != Coupling::none) {
      const PondExtent p = pond_extent(c.water->field, c.water->origin_x_m, c.water->origin_y_m, rt->contacts);
      if (!p.off.empty())
        out.notes.push_back({i, "realtime", off_pond_sentence(p, rt->contacts, c.water->coupling == Coupling::two_way)});
    }
    out.add_row(record.row(i, point, rt ? &*rt : nullptr, ref ? &*ref : nullptr, cost, shortest_resolved_flight_s(c), out.notes));
  };
}

// The files a throw reads besides the sweep and base texts, by content (a resume must not mix
// rows of an edited mesh with the new one's): "mesh PATH fnv1a64 HEX".
std::string input_files_of(const StoneCase& base) {
  if (base.spec.mesh_file.empty()) return "";
  const std::string text = read_text_file(base.spec.mesh_file);
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a64(reinterpret_cast<const unsigned char*>(text.data()), text.size())));
  return "mesh " + base.spec.mesh_file + " fnv1a64 " + hex;
}

void compute(const SweepArgs& a, const SweepFile& sweep, const SweepCases& cases, SweepPlan& plan,
             const ThrowEvaluator& evaluate, MpiSession& mpi);

void run(const SweepArgs& a) {
  MpiSession mpi;
  // 1. Every rank: the sweep file, the base case, the case at the design's extreme points.
  std::optional<SweepFile> sweep;
  std::unique_ptr<SweepCases> cases;
  std::string error;
  try {
    if (!MpiSession::built_with_mpi() && MpiSession::launched_size() > 1)
      throw_input_error("mpirun", 0, "", "this stoneskip was built without MPI, so its " +
                                             std::to_string(MpiSession::launched_size()) +
                                             " processes cannot share a sweep: install libopenmpi-dev and rebuild");
    sweep = load_sweep_file(a.file);
    cases = std::make_unique<SweepCases>(*sweep);
    if (a.threads && (*a.threads < 0 || *a.threads > kMaxSweepThreads))
      throw_input_error("--threads", 0, "",
                        "must be in [0, " + std::to_string(kMaxSweepThreads) + "] (got " + std::to_string(*a.threads) + ")");
    if (a.threads && *a.threads == 0 && mpi.size() <= 1)
      throw_input_error("--threads", 0, "",
                        "0 leaves rank 0 only to schedule, and no MPI workers are running to compute: give 1 or "
                        "more, or run under mpirun");
    if (a.max_chunk < 1) throw_input_error("--max-chunk", 0, "", "must be >= 1");
    if (a.out && a.out->empty()) throw_input_error("--out", 0, "", "needs a file name (got an empty one)");
    refuse_output_over_inputs(out_file(a), OutputKind::file, {sweep->file, sweep->base_file, cases->base().spec.mesh_file});
    refuse_foreign_output(out_file(a), OutputFormat::hdf5_sweep);
    // Limits decided before any throw (cases/README.md, Limits): the table, the heaviest throw, all.
    const double width = static_cast<double>(sweep_record(sweep->design, sweep->solvers).width());
    const double threads = a.threads.value_or(0) > 0 ? *a.threads : usable_cores();
    enforce_limits(estimate_sweep(cases->heaviest_throw(), static_cast<double>(sweep->design.size()),
                                  (width + 1) * sizeof(double), threads),
                   a.limits, sweep->file);
  } catch (const InputError& e) {
    error = e.what();
  }
  if (!all_ranks_ok(mpi, error)) return;

  SweepData spec;
  spec.design = sweep->design;
  spec.solvers = sweep->solvers;
  SweepProvenance& p = spec.provenance;
  p.title = sweep->title;
  p.sweep_file = sweep->file;
  p.sweep_text = sweep->text;
  p.base_case_file = sweep->base_file;
  p.base_case_text = cases->base().text;
  p.base_overrides = sweep->base_sets;
  p.resolved_settings = cases->base().resolved_settings();
  p.input_files = input_files_of(cases->base());
  SweepRunOptions options;
  options.out = out_file(a);
  options.resume = a.resume;
  options.master_threads = a.threads.value_or(-1);
  options.max_chunk = a.max_chunk;
  if (!a.quiet) options.progress = terminal_progress();

  // 2. Rank 0: the output and the journal.
  std::optional<SweepPlan> plan;
  if (mpi.rank() == 0) {
    try {
      plan.emplace(SweepPlan::prepare(spec, options));
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  if (!all_ranks_ok(mpi, error)) return;

  // 3. The throws.
  const ThrowRecord record = sweep_record(sweep->design, sweep->solvers);
  const ThrowEvaluator evaluate = make_evaluator(*sweep, *cases, record);
  try {
    if (mpi.rank() == 0)
      compute(a, *sweep, *cases, *plan, evaluate, mpi);
    else
      run_worker(record.width(), evaluate, mpi);
  } catch (const std::exception& e) {
    if (mpi.size() == 1) throw;
    // One rank cannot finish: the others would wait for it forever. The journal keeps what is done.
    std::fprintf(stderr, "stoneskip: rank %d: internal error: %s (the sweep can be finished with --resume)\n",
                 mpi.rank(), e.what());
    mpi.abort(3);
  }
}

void compute(const SweepArgs& a, const SweepFile& sweep, const SweepCases& cases, SweepPlan& plan,
             const ThrowEvaluator& evaluate, MpiSession& mpi) {
  // A key the sweep both fixes (`set`) and varies: legal (a base case may need the fixed value to
  // load, e.g. a fixed scheme's contact_dt_s), but the axis replaces it, which is said.
  for (std::size_t k = 0; k < sweep.design.axes.size(); ++k)
    for (const std::string& fixed : sweep.base_sets)
      if (canonical_dotted_key(fixed.substr(0, assignment_equals(fixed))) == sweep.design.axes[k].key)
        std::fprintf(stderr, "warning: %s:%ld: vary[%zu].key: \"%s\" is also fixed by the top-level set (\"%s\"): the axis's values replace it\n",
                     printable_text(sweep.file).c_str(), sweep.axis_lines[k], k + 1, sweep.design.axes[k].key.c_str(),
                     printable_text(fixed).c_str());
  if (!a.quiet) {
    std::printf("%s", describe(sweep, cases).c_str());
    std::printf("run       %d rank%s%s; %zu of %zu throws to compute; output %s\n", mpi.size(), mpi.size() == 1 ? "" : "s",
                MpiSession::built_with_mpi() ? "" : " (built without MPI)", plan.pending(), sweep.design.size(),
                plan.output().c_str());
    std::fflush(stdout);
  }
  const SweepSummary summary = plan.run(evaluate, mpi);
  for (const auto& w : summary.warnings) std::fprintf(stderr, "warning: %s\n", printable_text(w).c_str());
  std::printf("%s\n", summary.brief().c_str());
}

void add_sweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand("sweep", "Run every throw of a sweep file (grid or random design) into one HDF5 table; "
                                          "runs under mpirun across ranks");
  cmd->add_option("SWEEP", a->file, "Sweep file (TOML, see cases/README.md)")->required();
  cmd->add_option("--out", a->out, "Result file (default: SWEEP's stem + .h5 in the current folder)");
  cmd->add_flag("--resume", a->resume, "Finish an interrupted sweep from its journal (FILE.h5.journal)");
  cmd->add_option("--threads", a->threads,
                  "Compute threads on rank 0 (default: every core when it runs alone, 1 beside MPI workers; "
                  "0 with workers: rank 0 only schedules; at most 256)");
  cmd->add_option("--max-chunk", a->max_chunk, "Largest number of throws handed out at once (default 32)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 40));
  cmd->add_flag("--quiet", a->quiet, "No configuration, no progress line");
  add_limit_options(cmd, a->limits);
  cmd->callback([a] { run(*a); });
}

const bool kRegistered = register_command(add_sweep);

}  // namespace
}  // namespace stoneskip::cli
