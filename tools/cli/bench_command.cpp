// stoneskip bench [--json] [--quick] [--every-isa] [--scene CASE] [--sweep-case CASE] [--repeats N]
//
// The headline speed figures, measured in one run of this binary
// (verification/scene/headline_speed.hpp): the seed's scene in simulated frames per second with
// the field on one thread and on two; the stencil's cell updates per second at 500² and 2048² and
// the fraction of the copy bound measured by the same binary at 2048²; real-time throws per
// second in a bounce-count sweep on two workers. Printed beside their targets with the
// machine it ran on (CPU model, core count, the kernel's instruction-set path, load average before
// and after); the temporal-blocked kernel against the same copy bound and a plain loop of the
// stencil beside the SIMD kernel. STONESKIP_ISA=scalar|sse2|avx2|avx512|neon forces the kernel's
// path; --every-isa adds the stencil on every path the CPU supports, side by side. A benchmark, not a test: the numbers depend on the
// machine and on what else runs on it.
// The sweep runs the adaptive real-time stepper (bs32 at --sweep-rtol, rtol = atol_m; the default
// chosen from the work-precision table in solvers/README.md; --sweep-scheme dp54 for
// Dormand–Prince 5(4)) on two workers; beside its throws/s,
// untimed, the fraction of its throws whose bounce count equals CVODE's where CVODE (BDF, the case's
// reference settings) at rtol = atol 1e-8 and 1e-10 agrees, and the same fraction apart on the
// throws whose CVODE solution has no flight shorter than 1 ms (kShortFlight_s).
// The real-time budget (the sweep's scheme at the same tolerance, at most N right-hand sides per 1/90 s frame),
// untimed, on the same throws at N = 16 … 2048: per N the throws keeping CVODE's agreed count, the
// steps the budget forced, the largest error ratio accepted and the CPU a frame costs at most
// (N × thread CPU per right-hand side); and the smallest N at which, and at every larger one, the
// match reaches the sweep's target.
//   stoneskip bench
//   stoneskip bench --json
//   stoneskip bench --quick --json      # a smoke run (seconds): rougher numbers, the large grid at 1024² (keys _1024)
//   STONESKIP_ISA=avx2 stoneskip bench --every-isa
//   stoneskip bench --cpu-clock         # the stencil on thread CPU time (a loaded machine)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/io/input_error.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/case_problem.hpp"
#include "tools/scene/scene_throw.hpp"
#include "verification/scene/headline_speed.hpp"
#include "verification/stones/frame_budget_ladder.hpp"
#include "verification/stones/parallel_runs.hpp"
#include "verification/stones/throw_problem.hpp"
#include "verification/stones/work_precision_grid_stats.hpp"
#include "stoneskip_version.hpp"

namespace stoneskip::cli {
namespace {

struct BenchArgs {
  bool json = false;
  bool quick = false;
  bool every_isa = false;
  bool cpu_clock = false;
  bool sweep_only = false;
  std::string scene = "cases/scenes/seed_8ms.toml";
  std::string sweep_case = "cases/spin_sweep_base.toml";
  double sweep_rtol = kDefaultAdaptiveTolerance;  // the cases' default (kSweepTolerance below)
  std::string sweep_scheme = "bs32";  // an adaptive scheme (stone_stepper.hpp)
  std::string sweep_kinks;  // the scheme's default unless --sweep-kinks is given
  CLI::Option* sweep_kinks_option = nullptr;
  CLI::Option* repeats_option = nullptr;
  int repeats = 3;
  ResourceLimits limits;
};

// The targets.
constexpr double kSceneFpsTarget = 3000;
constexpr double kBandwidthFractionTarget = 0.9;
constexpr double kPerCellRatioTarget = 2;
constexpr double kThrowsPerSecondTarget = 1000;
constexpr double kTemporalFractionTarget = 1.5;  // temporal blocking against the one-pass copy bound
constexpr double kOverPlainLoopTarget = 4;       // the SIMD stencil over a plain loop of it
constexpr double kMatchFractionTarget = 0.98;    // the sweep's bounce counts equal to CVODE's

// The sweep's solver: bs32 at rtol = atol_m = kSweepTolerance, the cases' default: the tolerance
// whose bounce counts match CVODE's on ≥ 98 % of the bench grid with the 95 % Wilson interval's
// lower end above 98 % (work-precision table, solvers/README.md).
constexpr double kSweepTolerance = kDefaultAdaptiveTolerance;
// CVODE's two tolerances (rtol = atol, m): a throw's reference count is where they agree.
constexpr double kCvodeTolerances[2] = {1e-8, 1e-10};

// A flight shorter than this between two contacts is a short flight: at the sweep's 5–7 m/s the
// stone travels a few millimetres while a rim vertex lifts clear and the next dips in (at 40 rev/s
// an 11-sided rim passes a vertex every 2.3 ms). Whether such a bounce happens turns on how far a
// vertex clears the water in that time. The agreement is also reported on the throws whose
// reference has none: on the bench grid the sweep's disagreements lie almost all on the others
// (solvers/README.md).
constexpr double kShortFlight_s = 1e-3;

// The sweep's bounce counts against CVODE's, solved apart from the timed sweep.
struct CvodeAgreement {
  std::vector<int> bounces[2];  // per tolerance of kCvodeTolerances, per throw (−1: the solve failed)
  std::vector<double> shortest_flight_s;  // per throw, at the finer tolerance (+∞: fewer than 2 contacts)
  long agreeing = 0;            // throws where both tolerances give the same count
  long matched = 0;             // of those, throws where the sweep's count equals it
  long with_short_flight = 0;   // of the agreeing throws, those whose reference has a short flight
  long matched_with_short_flight = 0;
  double fraction() const { return agreeing > 0 ? static_cast<double>(matched) / agreeing : std::nan(""); }
  long without_short_flight() const { return agreeing - with_short_flight; }
  double fraction_without_short_flight() const {
    const long n = without_short_flight();
    return n > 0 ? static_cast<double>(matched - matched_with_short_flight) / n : std::nan("");
  }
};

CvodeAgreement cvode_agreement(const SweepSpeedOptions& sweep, const std::vector<int>& realtime_bounces) {
  const std::vector<ThrowProblem> throws = sweep_throws(sweep);
  CvodeAgreement a;
  for (int k = 0; k < 2; ++k) {
    ReferenceOptions ro = sweep.base.reference;
    ro.rtol = ro.atol = kCvodeTolerances[k];
    SolverChoice c = reference_choice(ro);
    c.reference.record_trajectory = false;
    std::vector<int>& b = a.bounces[k];
    b.assign(throws.size(), -1);
    if (k == 1) a.shortest_flight_s.assign(throws.size(), INFINITY);
    ParallelOptions po;
    po.workers = sweep.workers;
    parallel_for(
        throws.size(),
        [&](std::size_t i) {
          const ThrowResult r = solve(throws[i], c);
          if (r.outcome != Outcome::failed) b[i] = r.bounces;
          if (k == 1) a.shortest_flight_s[i] = shortest_flight_s(r.contacts);
        },
        po);
  }
  for (std::size_t i = 0; i < throws.size(); ++i) {
    if (a.bounces[0][i] < 0 || a.bounces[0][i] != a.bounces[1][i]) continue;
    ++a.agreeing;
    const bool matched = i < realtime_bounces.size() && realtime_bounces[i] == a.bounces[0][i];
    if (matched) ++a.matched;
    if (a.shortest_flight_s[i] < kShortFlight_s) {
      ++a.with_short_flight;
      if (matched) ++a.matched_with_short_flight;
    }
  }
  return a;
}

// The real-time budget's ladder: right-hand sides per 1/90 s frame (the paper's > 90 frames/s).
const std::vector<long> kBudgetLadder{16, 32, 64, 128, 256, 512, 1024, 2048};

// Per throw, CVODE's count where its two tolerances agree, else −1 (the budget ladder's reference).
std::vector<int> agreed_counts(const CvodeAgreement& a) {
  std::vector<int> out(a.bounces[0].size(), -1);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (a.bounces[0][i] >= 0 && a.bounces[0][i] == a.bounces[1][i]) out[i] = a.bounces[0][i];
  return out;
}

std::vector<double> range(double lo, double hi, double step) {
  std::vector<double> v;
  for (double x = lo; x <= hi + 1e-9; x += step) v.push_back(x);
  return v;
}

// A whole number below 1e15 in full (a target of 3000 read "3e+03"), else `significant` digits.
std::string g(double v, int significant = 3) {
  char buf[64];
  if (v == std::floor(v) && std::abs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

void bench(const BenchArgs& a) {
  if (a.repeats < 1 || a.repeats > 100) throw_input_error("--repeats", 0, "", "must be in [1, 100]");
  const StoneCase scene_case = load_stone_case(a.scene);
  const StoneCase sweep_case = load_stone_case(a.sweep_case);
  if (!sweep_case.throw_from_parameters)
    throw_input_error(sweep_case.file, 0, "throw", "the sweep varies spin and attack angle: give the throw as [throw] parameters");
  // The sweep's throws and CVODE's know no live surface: a case with [water] would be timed on still
  // water without a word (as a baseline would, tools/scene/baseline_file.cpp).
  if (sweep_case.water)
    throw_input_error(sweep_case.file, 0, "water",
                      "the sweep's throws run on still water (the CVODE reference supports no live surface): "
                      "give a case without [water]; a live-water scene is timed by --scene");
  HeadlineSpeedOptions o;
  o.scene = scene_options(scene_case, SceneEnd::at_duration);
  o.scene_repeats = a.repeats;
  o.stencil.stencil = o.scene.water ? o.scene.water->field.stencil : named_stencil("nine_point_isotropic");
  o.stencil.precision = Precision::float64;
  o.stencil.clock = a.cpu_clock ? ThroughputClock::cpu : ThroughputClock::wall;
  o.stencil.temporal_two_threads = !a.cpu_clock;  // two threads need the wall clock
  o.sweep.base = problem_from_case(sweep_case);
  // The adaptive stepper at the named tolerance, whatever the case's own [solver] says.
  const double sweep_tolerance = a.sweep_rtol;  // checked as given: 0 or a negative value is refused, not read as the default
  if (!(sweep_tolerance >= 1e-12 && sweep_tolerance <= 1e-2))
    throw_input_error("--sweep-rtol", 0, "", "must be in [1e-12, 1e-2] (got " + g(sweep_tolerance, 17) + ")");
  Scheme sweep_scheme{};
  if (!parse_scheme(a.sweep_scheme, sweep_scheme) || !is_adaptive(sweep_scheme))
    throw_input_error("--sweep-scheme", 0, "", "must be an adaptive scheme, bs32 or dp54 (got " + a.sweep_scheme + ")");
  o.sweep.base.realtime.scheme = sweep_scheme;
  o.sweep.base.realtime.rtol = o.sweep.base.realtime.atol_m = sweep_tolerance;
  KinkSteps kinks = default_kink_steps(sweep_scheme);
  if (a.sweep_kinks_option->count() > 0 && !parse_kink_steps(a.sweep_kinks, kinks))
    throw_input_error("--sweep-kinks", 0, "", "must be none, crossings or all (got " + a.sweep_kinks + ")");
  o.sweep.base.realtime.kinks = kinks;
  o.sweep.spins_rev_s = range(0, 60, 2.5);
  o.sweep.attack_angles_deg = range(0, 30, 2.5);
  o.sweep.repeats = a.repeats;
  o.every_isa = a.every_isa;
  o.sweep_only = a.sweep_only;
  if (a.quick) {
    o.scene.duration_s = std::min(o.scene.duration_s, 0.5);
    // --quick runs each part once unless --repeats says otherwise.
    if (a.repeats_option->count() == 0) o.scene_repeats = 1;
    o.stencil.samples = 4;
    o.stencil.sample_s = 0.002;
    o.stencil_large_n = 1024;
    o.sweep.spins_rev_s = {0, 20, 40};
    o.sweep.attack_angles_deg = {10, 20};
    if (a.repeats_option->count() == 0) o.sweep.repeats = 1;
  }
  if (a.sweep_only && a.every_isa)
    throw InputError("bench: --every-isa measures the stencil, which --sweep-only leaves out: give one of them");
  std::string why;
  if (!o.is_valid(&why)) throw_input_error(a.scene, 0, "", why);
  // The scene and the sweep case are held to the limits of `scene` and `run` (cases/README.md, Limits).
  enforce_limits(estimate_scene(scene_case, o.scene.duration_s, o.scene.frame_rate_hz), a.limits, scene_case.file);
  enforce_limits(estimate_run(sweep_case, RunSolvers{}), a.limits, sweep_case.file);
  const HeadlineSpeed h = measure_headline_speed(o, terminal_progress());
  const CvodeAgreement cvode = cvode_agreement(o.sweep, h.sweep.bounces);  // not timed
  // The real-time budget on the same throws at the same tolerance (CPU per frame from thread CPU).
  FrameBudgetLadderOptions bo;
  bo.rhs_per_frame = a.quick ? std::vector<long>{16, 64} : kBudgetLadder;
  bo.workers = o.sweep.workers;
  bo.progress = terminal_progress();
  const std::vector<FrameBudgetRung> ladder = run_frame_budget_ladder(sweep_throws(o.sweep), agreed_counts(cvode), bo);
  const long budget_for_target = smallest_budget_meeting(ladder, kMatchFractionTarget);

  nlohmann::json j;
  j["scene_fps_1core"] = h.scene_one.fps_best_wall();
  j["scene_fps_2cores"] = h.scene_many.fps_best_wall();
  j["scene_fps_1core_median"] = h.scene_one.fps_median_wall();
  j["scene_fps_2cores_median"] = h.scene_many.fps_median_wall();
  j["scene_fps_1core_cpu"] = h.scene_one.fps_cpu();
  j["scene_frames"] = h.scene_one.frames;
  j["scene_wall_s_1core"] = h.scene_one.best_wall_s;
  j["scene_cpu_s_1core"] = h.scene_one.best_cpu_s;
  j["scene_slowest_frame_ms_1core"] = 1e3 * h.scene_one.best.slowest_frame_wall_s;
  j["scene_parts_wall_s_1core"] = {{"stone", h.scene_one.best.stone_wall_s},
                                   {"draught", h.scene_one.best.draught_wall_s},
                                   {"water", h.scene_one.best.water_wall_s},
                                   {"recording", h.scene_one.best.recording_wall_s}};
  j["stencil"] = h.stencil_large.options.stencil.name;
  j["stencil_isa"] = h.stencil_large.kernel_isa;
  j["stencil_n_small"] = h.stencil_small.options.n;
  j["stencil_n_large"] = h.stencil_large.options.n;
  j["stencil_cells_per_s_500"] = h.stencil_small.cells_per_s;
  j["stencil_cells_per_s_2048"] = h.stencil_large.cells_per_s;
  j["bandwidth_fraction_2048"] = h.stencil_large.fraction;
  j["copy_bound_cells_per_s_2048"] = h.stencil_large.bound_cells_per_s;
  j["bandwidth_fraction_2048_median"] = h.stencil_large.fraction_median;
  j["bandwidth_fraction_500"] = h.stencil_small.fraction;
  j["per_cell_ratio_500_over_2048"] = h.per_cell_ratio;
  j["sweep_throws_per_s"] = h.sweep.throws_per_s();
  j["sweep_throws"] = h.sweep.throws;
  j["sweep_workers"] = h.sweep.workers;
  j["sweep_cpu_s"] = h.sweep.cpu_s;
  j["sweep_wall_s"] = h.sweep.best_wall_s;
  j["sweep_steps"] = h.sweep.steps;
  j["sweep_contact_steps"] = h.sweep.contact_steps;
  j["sweep_simulated_s"] = h.sweep.simulated_s;
  j["sweep_scheme"] = to_string(o.sweep.base.realtime.scheme);
  j["sweep_rtol"] = o.sweep.base.realtime.rtol;
  j["sweep_atol_m"] = o.sweep.base.realtime.atol_m;
  j["sweep_kinks"] = to_string(*o.sweep.base.realtime.kinks);
  j["sweep_rhs_evaluations"] = h.sweep.rhs_evaluations;
  j["sweep_bounces"] = h.sweep.bounces;
  j["sweep_max_energy_gain_J"] = h.sweep.max_energy_gain_J;
  j["sweep_throws_gaining_energy"] = h.sweep.throws_gaining_energy;
  j["sweep_cvode_rtols"] = {kCvodeTolerances[0], kCvodeTolerances[1]};
  j["sweep_cvode_bounces"] = {cvode.bounces[0], cvode.bounces[1]};
  j["sweep_cvode_agreeing_throws"] = cvode.agreeing;
  j["sweep_cvode_matched_throws"] = cvode.matched;
  j["sweep_cvode_match_fraction"] = cvode.fraction();
  j["sweep_cvode_short_flight_s"] = kShortFlight_s;
  j["sweep_cvode_throws_with_short_flight"] = cvode.with_short_flight;
  j["sweep_cvode_matched_with_short_flight"] = cvode.matched_with_short_flight;
  j["sweep_cvode_match_fraction_without_short_flight"] = cvode.fraction_without_short_flight();
  j["budget_frame_dt_s"] = bo.frame_dt_s;
  nlohmann::json rungs = nlohmann::json::array();
  for (const FrameBudgetRung& r : ladder)
    rungs.push_back({{"rhs_per_frame", r.rhs_per_frame},
                     {"bounces", r.bounces},
                     {"cvode_matched_throws", r.matched},
                     {"cvode_compared_throws", r.compared},
                     {"cvode_match_fraction", r.match_fraction()},
                     {"cvode_match_fraction_low", wilson_interval(static_cast<int>(r.matched), static_cast<int>(r.compared)).low},
                     {"forced_step_fraction", r.forced_fraction()},
                     {"max_error_ratio", r.max_error_ratio},
                     {"max_energy_gain_J", r.max_energy_gain_J},
                     {"throws_gaining_energy", r.throws_gaining_energy},
                     {"rhs_per_throw", double(r.rhs_evaluations) / std::max<std::size_t>(1, r.bounces.size())},
                     {"cpu_per_frame_bound_us", 1e6 * r.cpu_per_frame_bound_s()},
                     {"mean_cpu_per_frame_us", 1e6 * r.mean_cpu_per_frame_s()}});
  j["budget_ladder"] = rungs;
  j["budget_rhs_per_frame_for_match_target"] = budget_for_target > 0 ? nlohmann::json(budget_for_target) : nlohmann::json();
  const double over_plain = h.stencil_small.plain_cells_per_s > 0 ? h.stencil_small.cells_per_s / h.stencil_small.plain_cells_per_s : 0;
  j["temporal_blocking_fraction_2048"] = h.stencil_large.temporal_fraction;
  j["temporal_blocking_cells_per_s_2048"] = h.stencil_large.temporal_cells_per_s;
  j["temporal_blocking_steps"] = h.stencil_large.options.temporal_steps;
  j["temporal_blocking_fraction_2048_2threads"] = h.stencil_large.temporal_two_threads_fraction;
  j["temporal_blocking_cells_per_s_2048_2threads"] = h.stencil_large.temporal_two_threads_cells_per_s;
  j["plain_loop_cells_per_s_500"] = h.stencil_small.plain_cells_per_s;
  j["stencil_over_plain_loop_500"] = over_plain;
  j["stencil_clock"] = h.stencil_large.clock;
  j["cpu_model"] = h.cpu_model;
  j["supported_isas"] = h.supported_isas;
  if (!h.by_isa.empty()) {
    nlohmann::json by = nlohmann::json::object();
    for (const IsaStencilSpeed& s : h.by_isa)
      by[s.isa] = {{"stencil_cells_per_s_500", s.small.cells_per_s},
                   {"stencil_cells_per_s_2048", s.large.cells_per_s},
                   {"bandwidth_fraction_2048", s.large.fraction},
                   {"per_cell_ratio_500_over_2048", s.large.cells_per_s > 0 ? s.small.cells_per_s / s.large.cells_per_s : 0},
                   {"temporal_blocking_fraction_2048", s.large.temporal_fraction}};
    j["stencil_by_isa"] = by;
  }
  j["load_average_before"] = h.load_before;
  j["load_average_after"] = h.load_after;
  j["cores"] = h.cores;
  j["clocks"] = "frames/s and throws/s: wall (best of the repeats; _median: median), _cpu: the scene thread's CPU; "
                "stencil: wall (thread CPU with --cpu-clock: stencil_clock), best sample against the copy kernel's best sample";
  j["quick"] = a.quick;
  j["scene_repeats"] = o.scene_repeats;  // runs whose best (and median) the figures are
  j["sweep_repeats"] = o.sweep.repeats;
  // The proportion's 95 % Wilson interval (verification/stones/work_precision_grid_stats.hpp): the
  // verdict on the 0.98 target reads its lower end, not the point estimate.
  const ProportionInterval match = wilson_interval(static_cast<int>(cvode.matched), static_cast<int>(cvode.agreeing));
  j["sweep_cvode_match_fraction_low"] = match.low;
  j["sweep_cvode_match_fraction_high"] = match.high;
  j["sweep_cvode_match_verdict_on"] = "the 95 % Wilson interval's lower end";
  j["scene_case"] = scene_case.file;
  j["sweep_case"] = sweep_case.file;
  j["code_version"] = std::string(kGitDescribe);
  if (o.sweep_only) {
    // Not measured: null, never a zero that reads as a measurement.
    for (auto it = j.begin(); it != j.end(); ++it)
      if (it.key().rfind("scene_", 0) == 0 || it.key().rfind("stencil", 0) == 0 || it.key().rfind("bandwidth_", 0) == 0 ||
          it.key().rfind("copy_bound_", 0) == 0 || it.key().rfind("per_cell_", 0) == 0 ||
          it.key().rfind("temporal_blocking_", 0) == 0 || it.key().rfind("plain_loop_", 0) == 0)
        if (it.key() != "scene_case") it.value() = nullptr;
  }
  if (!o.sweep_only && h.stencil_large.options.n != 2048) {
    // --quick measures the large grid at another size: its figures go under keys naming that size,
    // and the 2048² keys are null (not measured), never a figure of another grid under their name.
    const std::string size = "_" + std::to_string(h.stencil_large.options.n);
    auto move_keys = [&](nlohmann::json& obj) {
      const nlohmann::json copy = obj;
      for (auto it = copy.begin(); it != copy.end(); ++it) {
        const auto at = it.key().find("_2048");
        if (at == std::string::npos) continue;
        std::string renamed = it.key();
        renamed.replace(at, 5, size);
        obj[renamed] = it.value();
        obj[it.key()] = nullptr;
      }
    };
    move_keys(j);
    if (j.contains("stencil_by_isa"))
      for (auto& by : j["stencil_by_isa"]) move_keys(by);
  }
  if (a.json) {
    std::cout << json_text(j) << std::endl;
    return;
  }
  // A figure without a target says "—" and no verdict.
  auto line = [](const std::string& what, const std::string& value, const std::string& target, bool met) {
    std::printf("%-58s %-26s %s\n", what.c_str(), value.c_str(),
                target.empty() ? "—" : (target + (met ? "  met" : "  MISSED")).c_str());
  };
  std::printf("stoneskip bench%s — %s, %d core%s, stencil path %s; load average %s before, %s after; wall clock unless marked CPU%s\n",
              a.quick ? " (quick: a smoke run)" : "", h.cpu_model.c_str(), h.cores, h.cores == 1 ? "" : "s", h.stencil_large.kernel_isa.empty() ? "– (not measured)" : h.stencil_large.kernel_isa.c_str(),
              g(h.load_before).c_str(), g(h.load_after).c_str(), a.cpu_clock ? " (stencil: thread CPU)" : "");
  // (The stencil path is empty with --sweep-only: no stencil ran.)
  std::printf("scene case %s; sweep case %s; code %s\n", scene_case.file.c_str(), sweep_case.file.c_str(), kGitDescribe);
  if (h.sweep.workers > h.cores)
    std::printf("note: %d sweep workers on %d usable core%s (the affinity mask): throws/s is not the %d-core figure\n",
                h.sweep.workers, h.cores, h.cores == 1 ? "" : "s", h.sweep.workers);
  std::printf("%-58s %-26s %s\n", "", "measured", "target");
  if (o.sweep_only) std::printf("scene and stencil: not measured (--sweep-only)\n");
  if (!o.sweep_only) {
  // The frame-rate target is the seed's scene's; another scene (--scene) is named by its file, no target.
  std::error_code same_error;
  const bool seed_scene = std::filesystem::equivalent(locate_input(a.scene), locate_input(BenchArgs{}.scene), same_error);
  const std::string scene_name = seed_scene ? "seed's scene" : "scene " + std::filesystem::path(a.scene).filename().string();
  line(scene_name + " (" + std::to_string(h.scene_one.frames) + " frames), 1 thread: frames/s", g(h.scene_one.fps_best_wall(), 4) +
           " (median " + g(h.scene_one.fps_median_wall(), 4) + ", CPU " + g(h.scene_one.fps_cpu(), 4) + ")",
       seed_scene ? ">= " + g(kSceneFpsTarget) : std::string(), h.scene_one.fps_best_wall() >= kSceneFpsTarget);
  line(scene_name + ", " + std::to_string(h.scene_many.threads) + " threads: frames/s",
       g(h.scene_many.fps_best_wall(), 4) + " (median " + g(h.scene_many.fps_median_wall(), 4) + ")", "", true);
  line("stencil " + h.stencil_large.options.stencil.name + " at " + std::to_string(h.stencil_small.options.n) + "²: cells/s",
       g(h.stencil_small.cells_per_s) + " (" + g(h.stencil_small.fraction) + " of its copy bound)", "", true);
  line("stencil at " + std::to_string(h.stencil_large.options.n) + "²: cells/s, fraction of the copy bound",
       g(h.stencil_large.cells_per_s) + ", " + g(h.stencil_large.fraction) + " (median " + g(h.stencil_large.fraction_median) + ")",
       ">= " + g(kBandwidthFractionTarget), h.stencil_large.fraction >= kBandwidthFractionTarget);
  line("stencil: rate per cell at " + std::to_string(h.stencil_small.options.n) + "² / at " +
           std::to_string(h.stencil_large.options.n) + "²", g(h.per_cell_ratio), ">= " + g(kPerCellRatioTarget),
       h.per_cell_ratio >= kPerCellRatioTarget);
  line("temporal blocking (" + std::to_string(h.stencil_large.options.temporal_steps) + " steps a call) at " +
           std::to_string(h.stencil_large.options.n) + "²: fraction of the copy bound",
       g(h.stencil_large.temporal_cells_per_s) + " cells/s, " + g(h.stencil_large.temporal_fraction), ">= " + g(kTemporalFractionTarget),
       h.stencil_large.temporal_fraction >= kTemporalFractionTarget);
  if (h.stencil_large.temporal_two_threads_cells_per_s > 0)
    line("temporal blocking on two threads (two halves, no rows exchanged): fraction of the one-thread copy bound",
         g(h.stencil_large.temporal_two_threads_cells_per_s) + " cells/s, " + g(h.stencil_large.temporal_two_threads_fraction), "", true);
  line("stencil at " + std::to_string(h.stencil_small.options.n) + "² over a plain loop of it (no SIMD, " +
           g(h.stencil_small.plain_cells_per_s) + " cells/s)", g(over_plain), ">= " + g(kOverPlainLoopTarget),
       over_plain >= kOverPlainLoopTarget);
  }
  line("bounce-count sweep (" + std::to_string(h.sweep.throws) + " throws, " + std::string(to_string(o.sweep.base.realtime.scheme)) +
           " rtol " + g(o.sweep.base.realtime.rtol) + ", " + std::to_string(h.sweep.workers) + " workers): throws/s",
       g(h.sweep.throws_per_s(), 4) + " (CPU " + g(h.sweep.cpu_s, 3) + " s)", ">= " + g(kThrowsPerSecondTarget),
       h.sweep.throws_per_s() >= kThrowsPerSecondTarget);
  line("sweep: bounce counts equal to CVODE's (where rtol " + g(kCvodeTolerances[0]) + " and " + g(kCvodeTolerances[1]) + " agree: " +
           std::to_string(cvode.agreeing) + " throws)",
       g(cvode.fraction(), 4) + " [" + g(match.low, 3) + ", " + g(match.high, 3) + "] (" + std::to_string(cvode.matched) + ")",
       ">= " + g(kMatchFractionTarget) + " (95 % interval)", match.low >= kMatchFractionTarget);
  std::printf("  of those, %ld have a flight shorter than %s ms in CVODE's solution (a rim vertex lifting clear): "
              "%ld of them match; of the other %ld, %ld match (%s)\n",
              cvode.with_short_flight, g(1e3 * kShortFlight_s).c_str(), cvode.matched_with_short_flight,
              cvode.without_short_flight(), cvode.matched - cvode.matched_with_short_flight,
              g(cvode.fraction_without_short_flight(), 4).c_str());
  std::printf("sweep passivity: the largest energy gain over a contact is %s J; %ld of %ld throws gain energy in a contact\n",
              g(h.sweep.max_energy_gain_J).c_str(), h.sweep.throws_gaining_energy, h.sweep.throws);
  std::printf("real-time budget (%s rtol %s, at most N right-hand sides per %s ms frame; CPU: thread CPU of the same runs):\n",
              to_string(o.sweep.base.realtime.scheme), g(o.sweep.base.realtime.rtol).c_str(), g(1e3 * bo.frame_dt_s).c_str());
  std::printf("  %6s %22s %14s %16s %20s %20s %22s\n", "N", "counts = CVODE's", "forced steps", "worst error ratio",
              "frame CPU bound µs", "mean frame CPU µs", "energy gain J (throws)");
  for (const FrameBudgetRung& r : ladder)
    std::printf("  %6ld %22s %14s %16s %20s %20s %22s\n", r.rhs_per_frame,
                (g(r.match_fraction(), 4) + " (" + std::to_string(r.matched) + " of " + std::to_string(r.compared) + ")").c_str(),
                g(r.forced_fraction()).c_str(), g(r.max_error_ratio).c_str(), g(1e6 * r.cpu_per_frame_bound_s()).c_str(),
                g(1e6 * r.mean_cpu_per_frame_s()).c_str(),
                (g(r.max_energy_gain_J) + " (" + std::to_string(r.throws_gaining_energy) + ")").c_str());
  std::printf("  the smallest budget of these whose match, 95 %% Wilson interval, lies at or above %s (and every larger one's): %s\n",
              g(kMatchFractionTarget).c_str(), budget_for_target > 0 ? std::to_string(budget_for_target).c_str() : "none");
  std::printf("sweep profile: %s ms CPU per throw, %s s simulated per throw, %s steps per throw (%s with the contact step), %s µs CPU per step\n",
              g(1e3 * h.sweep.cpu_s / std::max(1L, h.sweep.throws)).c_str(), g(h.sweep.simulated_s / std::max(1L, h.sweep.throws)).c_str(),
              g(double(h.sweep.steps) / std::max(1L, h.sweep.throws)).c_str(),
              g(double(h.sweep.contact_steps) / std::max(1L, h.sweep.throws)).c_str(),
              g(1e6 * h.sweep.cpu_s / std::max(1L, h.sweep.steps)).c_str());
  if (!o.sweep_only)
  std::printf("scene parts (1 thread, best run, wall): stone %s ms, draught %s ms, water %s ms; slowest frame %s ms\n",
              g(1e3 * h.scene_one.best.stone_wall_s).c_str(), g(1e3 * h.scene_one.best.draught_wall_s).c_str(),
              g(1e3 * h.scene_one.best.water_wall_s).c_str(), g(1e3 * h.scene_one.best.slowest_frame_wall_s).c_str());
  if (!h.by_isa.empty()) {
    std::printf("\nstencil on every path (cells/s; fraction of the copy bound at %d²):\n", h.stencil_large.options.n);
    const std::string small = std::to_string(h.stencil_small.options.n) + "²", large = std::to_string(h.stencil_large.options.n) + "²";
    std::printf("%-8s %14s %14s %10s %12s %18s\n", "path", small.c_str(), large.c_str(), "fraction", (small + "/" + large).c_str(),
                "temporal fraction");
    for (const IsaStencilSpeed& s : h.by_isa)
      std::printf("%-8s %14s %14s %10s %12s %18s\n", s.isa.c_str(), g(s.small.cells_per_s).c_str(), g(s.large.cells_per_s).c_str(),
                  g(s.large.fraction).c_str(), g(s.large.cells_per_s > 0 ? s.small.cells_per_s / s.large.cells_per_s : 0).c_str(),
                  g(s.large.temporal_fraction).c_str());
  }
}

void add_bench(CLI::App& app) {
  auto a = std::make_shared<BenchArgs>();
  auto* cmd = app.add_subcommand("bench", "Measure the headline speed figures (scene frames/s, stencil against the copy bound, sweep throws/s)");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->add_flag("--quick", a->quick, "A smoke run of seconds (shorter scene, fewer samples, a small sweep, 1024² instead of 2048²: its JSON keys say _1024, the _2048 keys are null)");
  cmd->add_flag("--sweep-only", a->sweep_only,
                "Only the bounce-count sweep and its CVODE agreement (the scene and stencil keys are then null)");
  cmd->add_flag("--every-isa", a->every_isa, "Also measure the stencil on every instruction-set path the CPU supports, side by side");
  cmd->add_flag("--cpu-clock", a->cpu_clock,
                "Time the stencil on the thread's CPU clock (one thread), not wall: on a loaded machine it leaves out the time "
                "other processes held the core");
  const auto named = [](const std::string& f) { return f.empty() ? std::string("needs a file name (got an empty one)") : std::string(); };
  cmd->add_option("--scene", a->scene, "The scene to time")->capture_default_str()->check(named);
  cmd->add_option("--sweep-case", a->sweep_case, "The throw whose spin and attack angle the sweep varies")->capture_default_str()->check(named);
  cmd->add_option("--sweep-rtol", a->sweep_rtol,
                  "The sweep's tolerance (rtol = atol_m; default " + g(kSweepTolerance) + ", from solvers/README.md's work-precision table)");
  cmd->add_option("--sweep-scheme", a->sweep_scheme,
                  "The sweep's adaptive scheme: bs32 (Bogacki–Shampine 3(2)) or dp54 (Dormand–Prince 5(4))")
      ->capture_default_str();
  a->sweep_kinks_option = cmd->add_option("--sweep-kinks", a->sweep_kinks, "Which kinks end the sweep's steps: none, crossings or all (default: the scheme's own, crossings for bs32, all for dp54)");
  a->repeats_option =
      cmd->add_option("--repeats", a->repeats, "Runs of the scene and of the sweep (the best is reported; --quick: 1 unless given)")
          ->capture_default_str();
  add_limit_options(cmd, a->limits);
  cmd->callback([a] { bench(*a); });
}

const bool kRegistered = register_command(add_bench);

}  // namespace
}  // namespace stoneskip::cli
