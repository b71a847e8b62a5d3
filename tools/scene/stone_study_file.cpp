#include "tools/scene/stone_study_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/scene/case_problem.hpp"
#include "tools/scene/study_keys.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

// A family's confidence (the Bonferroni families of the count ensembles and the mesh study): below
// one half its verdicts would be no better than a coin toss; at the top, 0.999 already holds each
// of a hundred comparisons to 0.99999.
constexpr double kMinFamilyConfidence = 0.5, kMaxFamilyConfidence = 0.999;

// A fixed scheme's flight steps, and the contact steps they imply (× contact_ratio; 1 where there is
// none), held to the range a case's steps keep (`run`: [1e-9, 1] s, cases/README.md): a study step
// of 1e-9 s (a contact step of 1e-10 s) sat for minutes with its progress line the only sign.
void require_case_steps(TomlTable& t, const std::string& key, const std::vector<double>& dt_s, double contact_ratio) {
  for (double dt : dt_s) {
    if (dt < 1e-9 || dt > 1) t.fail(key, "every step must be in [1e-09, 1] s, as a case's (got " + std::to_string(dt) + ")");
    if (dt * contact_ratio < 1e-9)
      t.fail(key, "the contact step dt_s × contact_ratio must be at least 1e-09 s, as a case's contact_dt_s");
  }
}

int count(TomlTable& t, const std::string& key, long long fallback, long long lo, long long hi) {
  return static_cast<int>(count_in(t, key, fallback, lo, hi));
}

Scheme scheme_of(TomlTable& t, const std::string& key, const std::string& name) {
  Scheme s;
  if (!parse_scheme(name, s)) t.fail(key, "'" + name + "' is not one of bs32, dp54, semi_implicit_euler, midpoint, rk4");
  return s;
}

// A list of water laws (unique; may be left out: `fallback`).
std::vector<WaterLaw> laws_of(TomlTable& t, const std::string& key, const std::vector<WaterLaw>& fallback) {
  auto names = t.maybe_strings(key);
  if (!names) return fallback;
  std::vector<WaterLaw> out;
  for (const auto& n : *names) {
    WaterLaw w;
    if (!parse_water_law(n, w)) t.fail(key, "'" + n + "' is not one of newtonian, planing, nagahiro_hayakawa");
    if (std::find(out.begin(), out.end(), w) != out.end()) t.fail(key, "'" + n + "' is listed twice");
    out.push_back(w);
  }
  return out;
}

// A list of pressure distributions (unique; may be left out: `fallback`).
std::vector<PressureDistribution> distributions_of(TomlTable& t, const std::string& key,
                                                   const std::vector<PressureDistribution>& fallback) {
  auto names = t.maybe_strings(key);
  if (!names) return fallback;
  std::vector<PressureDistribution> out;
  for (const auto& n : *names) {
    PressureDistribution d;
    if (!parse_pressure_distribution(n, d)) t.fail(key, "'" + n + "' is not one of uniform, savitsky, savitsky_wagner");
    if (std::find(out.begin(), out.end(), d) != out.end()) t.fail(key, "'" + n + "' is listed twice");
    out.push_back(d);
  }
  return out;
}

// Throws of the work-precision and restart studies ("nospin", "nospin@planing", "spin_paper").
std::vector<std::string> throw_names(TomlTable& t, const std::string& key, const std::vector<std::string>& names) {
  if (names.empty()) t.fail(key, "must not be empty");
  for (const auto& n : names)
    if (const std::string problem = study_throw_problem(n); !problem.empty()) t.fail(key, problem);
  return names;
}

std::vector<ReferenceMethod> methods_of(TomlTable& t, const std::string& key, const std::vector<ReferenceMethod>& fallback) {
  auto names = t.maybe_strings(key);
  if (!names) return fallback;
  if (names->empty()) t.fail(key, "must not be empty");
  std::vector<ReferenceMethod> out;
  for (const auto& n : *names) {
    ReferenceMethod m;
    if (!parse_reference_method(n, m)) t.fail(key, "'" + n + "' is not one of bdf, adams");
    out.push_back(m);
  }
  return out;
}

StudyThrow load_throw(const fs::path& study_dir, TomlTable& t, const std::string& key) {
  StudyThrow st;
  st.file = t.string(key);
  const fs::path path = study_dir / st.file;
  std::error_code ec;
  // From any folder: a study's "cases/…" path is looked up in the shipped cases (shipped_files.hpp).
  if (!fs::is_regular_file(locate_input(path), ec)) t.fail(key, "no case file '" + path.string() + "'");
  const StoneCase c = load_stone_case(path.string());
  if (c.water) t.fail(key, "the stone studies run on still water; '" + path.string() + "' has a [water] table");
  st.case_text = c.text;
  st.problem = problem_from_case(c);
  return st;
}

void read_throws(const fs::path& dir, TomlTable t, StoneStudiesOptions& o) {
  o.convergence_throw = load_throw(dir, t, "convergence");
  o.spin_throw = load_throw(dir, t, "spin");
  o.nospin_throw = load_throw(dir, t, "nospin");
  o.sweep_base = load_throw(dir, t, "sweep_base");
  o.clanet = load_throw(dir, t, "clanet");
  o.bocquet = load_throw(dir, t, "bocquet");
  o.stable_step_base = load_throw(dir, t, "stable_step_base");
  if (t.has("flat_drop")) o.flat_drop = load_throw(dir, t, "flat_drop");
  const std::string hard = t.string("hard");
  const int limit = count(t, "hard_limit", 0, 0, 1000);
  const fs::path hard_dir = locate_input(dir / hard);
  std::error_code ec;
  if (!fs::is_directory(hard_dir, ec)) t.fail("hard", "no folder '" + (dir / hard).string() + "'");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(hard_dir, ec))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (limit > 0 && static_cast<int>(files.size()) > limit) files.resize(limit);
  for (const auto& f : files) {
    StudyThrow st;
    st.file = f.filename().string();
    const StoneCase c = load_stone_case(f.string());
    st.case_text = c.text;
    st.problem = problem_from_case(c);
    o.hard.push_back(st);
  }
  t.finish();
}

// The adaptive scheme's tolerances (rtol = atol_m), each within the bounds a case's [solver] allows.
std::vector<double> tolerance_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback) {
  std::vector<double> v = positive_list(t, key, fallback);
  for (double x : v) t.require_in(key, x, 1e-14, 0.1);
  return v;
}

void read_convergence(TomlTable t, StoneStudiesOptions& o) {
  RealtimeConvergenceOptions& c = o.convergence;
  o.convergence_laws = laws_of(t, "laws", o.convergence_laws);
  o.convergence_distributions = distributions_of(t, "distributions", o.convergence_distributions);
  if (auto s = t.maybe_strings("schemes")) {
    c.schemes.clear();
    for (const auto& n : *s) c.schemes.push_back(scheme_of(t, "schemes", n));
    if (c.schemes.empty()) t.fail("schemes", "must not be empty");
  }
  c.dt_s = positive_list(t, "dt_s", c.dt_s);
  c.adaptive_tolerances = tolerance_list(t, "adaptive_tolerances", c.adaptive_tolerances);
  c.contact_ratio = t.number_or("contact_ratio", c.contact_ratio);
  t.require_in("contact_ratio", c.contact_ratio, 1e-4, 1.0);
  require_case_steps(t, "dt_s", c.dt_s, c.contact_ratio);
  if (t.has("kinks")) {
    const std::string k = t.string("kinks");
    if (!parse_kink_steps(k, c.fixed_kinks)) t.fail("kinks", "must be \"none\", \"crossings\" or \"all\" (got \"" + k + "\")");
  }
  if (auto n = t.maybe_numbers("interval_steps")) {
    c.interval_steps.clear();
    for (double x : *n) {
      if (x != std::floor(x) || x < 1 || x > 1e7) t.fail("interval_steps", "step counts must be whole numbers in [1, 1e7]");
      c.interval_steps.push_back(static_cast<int>(x));
    }
    if (c.interval_steps.empty()) t.fail("interval_steps", "must not be empty");
  }
  c.reference_rtol = positive(t, "reference_rtol", c.reference_rtol);
  c.reference_atol = positive(t, "reference_atol", c.reference_atol);
  c.check_factor = positive(t, "check_factor", c.check_factor);
  // The check run at rtol × f bounds the reference's error e by |reference − check| ≈ |f − 1| e
  // (errors proportional to the tolerance, the worst case of equal signs): a bound for f ≥ 2. At
  // f = 1 the two runs are one run, and the bound was 0, so the reference's own error was blamed
  // on the stepper ("does not converge").
  if (c.check_factor < 2)
    t.fail("check_factor", "must be at least 2 (got " + num(c.check_factor, 6) +
                               "): the check run at reference_rtol × check_factor bounds the reference's error only when "
                               "its own is at least twice as large");
  c.floor_factor = t.number_or("floor_factor", c.floor_factor);
  t.require_non_negative("floor_factor", c.floor_factor);
  c.correction_term = t.boolean_or("correction_term", c.correction_term);
  o.convergence_judgement.tolerance = positive(t, "order_tolerance", o.convergence_judgement.tolerance);
  o.convergence_judgement.minimum_order = t.number_or("minimum_order", o.convergence_judgement.minimum_order);
  t.require_non_negative("minimum_order", o.convergence_judgement.minimum_order);
  t.finish();
}

void read_reference_tolerance(TomlTable t, StoneStudiesOptions& o) {
  ReferenceToleranceOptions& r = o.reference_tolerance;
  r.rtol = positive_list(t, "rtol", r.rtol);
  r.truth_rtol = positive(t, "truth_rtol", r.truth_rtol);
  r.atol_ratio = positive(t, "atol_ratio", r.atol_ratio);
  const std::string m = t.string_or("method", to_string(r.method));
  if (!parse_reference_method(m, r.method)) t.fail("method", "'" + m + "' is not one of bdf, adams");
  o.required_tolerance_drop = positive(t, "required_drop", o.required_tolerance_drop);
  t.finish();
}

void read_work_precision(TomlTable t, StoneStudiesOptions& o) {
  WorkPrecisionOptions& w = o.work_precision;
  if (auto s = t.maybe_strings("throws")) o.work_precision_throws = throw_names(t, "throws", *s);
  if (t.has("realtime")) {
    w.realtime.clear();
    for (TomlTable f : t.tables("realtime")) {
      WorkPrecisionOptions::RealtimeFamily fam{scheme_of(f, "scheme", f.string("scheme")), 0.0};
      if (is_adaptive(fam.scheme)) {  // steps from the study's adaptive_rtol, no contact step
        if (f.has("contact_ratio")) f.fail("contact_ratio", "scheme \"" + f.string("scheme") + "\" takes no contact step (its tolerances: adaptive_rtol)");
      } else {
        fam.contact_ratio = f.number("contact_ratio");
        f.require_in("contact_ratio", fam.contact_ratio, 1e-4, 1.0);
      }
      f.finish();
      w.realtime.push_back(fam);
    }
  } else {
    t.maybe_table("realtime");  // mark as read
  }
  w.dt_s = positive_list(t, "dt_s", w.dt_s);
  {
    double least_ratio = 1;
    for (const auto& fam : w.realtime)
      if (fam.contact_ratio > 0) least_ratio = std::min(least_ratio, fam.contact_ratio);
    require_case_steps(t, "dt_s", w.dt_s, least_ratio);
  }
  w.adaptive_rtol = tolerance_list(t, "adaptive_rtol", w.adaptive_rtol);
  w.methods = methods_of(t, "methods", w.methods);
  w.rtol = positive_list(t, "rtol", w.rtol);
  w.atol_ratio = positive(t, "atol_ratio", w.atol_ratio);
  w.truth_rtol = positive(t, "truth_rtol", w.truth_rtol);
  w.truth_check_factor = positive(t, "truth_check_factor", w.truth_check_factor);
  // The truth's check at rtol × f: |truth − check| ≈ |1 − f| e measures the truth's error e within
  // a factor 2 for f ≤ 1/2 (a tighter check) or f ≥ 2 (a looser one). At f = 1 the two are one
  // run: an uncertainty of 0, and a chaotic throw (truth and check disagreeing on its count) could
  // never be set aside.
  if (w.truth_check_factor > 0.5 && w.truth_check_factor < 2)
    t.fail("truth_check_factor",
           "must be at most 0.5 or at least 2 (got " + num(w.truth_check_factor, 6) +
               "): the check run at truth_rtol × truth_check_factor must differ from the truth by 2× or more");
  w.repeats = count(t, "repeats", w.repeats, 1, 100);
  w.target_errors_m = positive_list(t, "target_errors_m", w.target_errors_m);
  t.finish();
}

void read_restarts(TomlTable t, StoneStudiesOptions& o) {
  RestartStudyOptions& r = o.restarts;
  if (auto s = t.maybe_strings("throws")) r.throws = throw_names(t, "throws", *s);
  if (auto names = t.maybe_strings("strategies")) {
    r.strategies.clear();
    for (const auto& n : *names) {
      RestartStrategy rs;
      if (!parse_restart_strategy(n, rs))
        t.fail("strategies", "'" + n + "' is not one of every_event, every_crossing, at_jumps, never");
      r.strategies.push_back(rs);
    }
    if (std::find(r.strategies.begin(), r.strategies.end(), RestartStrategy::every_event) == r.strategies.end())
      t.fail("strategies", "must hold every_event (it sets the tolerance of the others)");
  }
  r.methods = methods_of(t, "methods", r.methods);
  r.rtol = positive_list(t, "rtol", r.rtol);
  r.repeats = count(t, "repeats", r.repeats, 1, 100);
  r.time_tolerance_s = positive(t, "time_tolerance_s", r.time_tolerance_s);
  r.error_factor = positive(t, "error_factor", r.error_factor);
  t.finish();
}

// The work-precision study over a grid of throws (verification/stones/work_precision_grid.hpp).
void read_work_precision_grid(const fs::path& dir, TomlTable t, StoneStudiesOptions& o) {
  WorkPrecisionGridOptions& g = o.work_precision_grid;
  o.work_precision_grid_base = load_throw(dir, t, "base");
  if (o.work_precision_grid_base.problem.environment.convention != Convention::physical)
    t.fail("base", "the grid's base throw must be in the physical convention");
  if (!o.work_precision_grid_base.problem.from_parameters) t.fail("base", "the grid's base throw must give [throw] parameters");
  g.spins_rev_s = any_list(t, "spins_rev_s", g.spins_rev_s);
  g.attack_angles_deg = any_list(t, "attack_angles_deg", g.attack_angles_deg);
  for (double a : g.attack_angles_deg) t.require_in("attack_angles_deg", a, -90.0, 90.0);
  if (auto s = t.maybe_strings("fixed_schemes")) {
    g.fixed_schemes.clear();
    for (const auto& n : *s) {
      const Scheme sc = scheme_of(t, "fixed_schemes", n);
      if (is_adaptive(sc)) t.fail("fixed_schemes", "'" + n + "' is adaptive (its tolerances: work_precision.adaptive_rtol)");
      g.fixed_schemes.push_back(sc);
    }
  }
  g.dt_s = positive_list(t, "dt_s", g.dt_s);
  g.contact_ratio = t.number_or("contact_ratio", g.contact_ratio);
  t.require_in("contact_ratio", g.contact_ratio, 1e-4, 1.0);
  require_case_steps(t, "dt_s", g.dt_s, g.contact_ratio);
  const std::string m = t.string_or("method", to_string(g.method));
  if (!parse_reference_method(m, g.method)) t.fail("method", "'" + m + "' is not one of bdf, adams");
  g.cvode_rtol = positive_list(t, "cvode_rtol", g.cvode_rtol);
  g.agreement_target = t.number_or("agreement_target", g.agreement_target);
  t.require_in("agreement_target", g.agreement_target, 0.5, 1.0);
  const std::string b = t.string_or("agreement_bound", to_string(g.agreement_bound));
  if (!parse_agreement_bound(b, g.agreement_bound)) t.fail("agreement_bound", "'" + b + "' is not one of point_estimate, wilson_lower");
  g.contact_time_threshold_s = positive(t, "contact_time_threshold_s", g.contact_time_threshold_s);
  // The real-time budget family (bs32 at the cases' default tolerance, N right-hand sides per frame).
  if (t.has("budget_rhs_per_frame")) {
    g.budget_rhs_per_frame.clear();
    for (double n : positive_list(t, "budget_rhs_per_frame", {})) {
      if (n != std::floor(n) || n < double(kMinRhsPerFrame) || n > double(kMaxRhsPerFrame))
        t.fail("budget_rhs_per_frame", "each budget must be a whole number of right-hand sides in [" +
                                           std::to_string(kMinRhsPerFrame) + ", " + std::to_string(kMaxRhsPerFrame) + "]");
      g.budget_rhs_per_frame.push_back(static_cast<long>(n));
    }
  }
  g.budget_frame_dt_s = t.number_or("budget_frame_dt_s", g.budget_frame_dt_s);
  t.require_in("budget_frame_dt_s", g.budget_frame_dt_s, kMinStep_s, kMaxStep_s);
  t.finish();
}

// Bounce counts against the stone's mesh (verification/stones/mesh_study.hpp): the base case's
// prism rebuilt with each number of segments and each rim cut.
void read_mesh(const fs::path& dir, TomlTable t, StoneStudiesOptions& o) {
  MeshStudyOptions& m = o.mesh;
  o.mesh_base = load_throw(dir, t, "base");
  const fs::path path = dir / o.mesh_base.file;
  const StoneCase c = load_stone_case(path.string());
  if (c.spec.shape != StoneShape::prism) t.fail("base", "the mesh study rebuilds a prism; '" + path.string() + "' has another shape");
  if (!o.mesh_base.problem.from_parameters) t.fail("base", "the mesh study's base throw must give [throw] parameters");
  if (o.mesh_base.problem.environment.convention != Convention::physical)
    t.fail("base", "the mesh study's base throw must be in the physical convention (the paper's gains energy: no mirror, no settled count)");
  std::vector<int> segments;
  for (double n : positive_list(t, "segments", {11, 16, 32, 64})) {
    if (n != std::floor(n) || n < 3 || n > 4096) t.fail("segments", "each must be a whole number in [3, 4096]");
    if (std::find(segments.begin(), segments.end(), static_cast<int>(n)) != segments.end()) t.fail("segments", "lists one value twice");
    segments.push_back(static_cast<int>(n));
  }
  std::vector<RimSplit> splits{RimSplit::diagonal, RimSplit::centre};
  if (auto names = t.maybe_strings("rim_splits")) {
    if (names->empty()) t.fail("rim_splits", "must not be empty");
    splits.clear();
    for (const auto& n : *names) {
      RimSplit r;
      if (!parse_rim_split(n, r)) t.fail("rim_splits", "'" + n + "' is not one of diagonal, centre");
      if (std::find(splits.begin(), splits.end(), r) != splits.end()) t.fail("rim_splits", "'" + n + "' is listed twice");
      splits.push_back(r);
    }
  }
  m.meshes.clear();
  for (int n : segments)
    for (RimSplit r : splits) {
      StoneSpec spec = c.spec;
      spec.segments = n;
      spec.rim_split = r;
      m.meshes.push_back(MeshVariant{n, r, build_stone(spec, path.string())});
    }
  if (m.meshes.size() < 2) t.fail("segments", "the study needs at least 2 meshes (segments × rim_splits)");
  m.spins_rev_s = any_list(t, "spins_rev_s", m.spins_rev_s);
  for (double s : m.spins_rev_s) t.require_in("spins_rev_s", s, -200.0, 200.0);
  m.attack_angles_deg = any_list(t, "attack_angles_deg", m.attack_angles_deg);
  for (double a : m.attack_angles_deg) t.require_in("attack_angles_deg", a, -90.0, 90.0);
  for (const char* key : {"spins_rev_s", "attack_angles_deg"}) {
    const std::vector<double>& v = std::string(key) == "spins_rev_s" ? m.spins_rev_s : m.attack_angles_deg;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (std::find(v.begin() + i + 1, v.end(), v[i]) != v.end()) t.fail(key, "lists one value twice");
  }
  m.members = count(t, "members", m.members, 2, 1000);
  if (m.members % 2 != 0) t.fail("members", "must be even (members of both signs)");
  m.perturbation_smallest = positive(t, "perturbation_smallest", m.perturbation_smallest);
  m.perturbation_largest = positive(t, "perturbation_largest", m.perturbation_largest);
  t.require_in("perturbation_largest", m.perturbation_largest, m.perturbation_smallest, 0.1);
  // The level each family of verdicts (the cuts', the mirror pairs') is held to together.
  m.family_confidence = t.number_or("family_confidence", m.family_confidence);
  t.require_in("family_confidence", m.family_confidence, kMinFamilyConfidence, kMaxFamilyConfidence);
  t.finish();
}

void read_sweeps(TomlTable t, StoneStudiesOptions& o) {
  o.max_thresholds = count(t, "max_thresholds", o.max_thresholds, 0, 1000);
  o.sweep_reference_rtol = positive(t, "reference_rtol", o.sweep_reference_rtol);
  o.sweep_reference_atol = positive(t, "reference_atol", o.sweep_reference_atol);
  // The paper convention's counts, solver against solver, on ensembles (verification/stones/count_ensembles.hpp).
  o.count_ensembles.members = count(t, "ensemble_members", o.count_ensembles.members, 2, 1000);
  if (o.count_ensembles.members % 2 != 0) t.fail("ensemble_members", "must be even (members of both signs)");
  o.count_ensembles.throws_per_axis = count(t, "ensemble_throws_per_axis", o.count_ensembles.throws_per_axis, 0, 1000);
  // The level the sampled throws' verdicts are held to together.
  o.count_ensembles.family_confidence =
      t.number_or("ensemble_family_confidence", o.count_ensembles.family_confidence);
  t.require_in("ensemble_family_confidence", o.count_ensembles.family_confidence, kMinFamilyConfidence,
               kMaxFamilyConfidence);
  o.sweep_axes.clear();
  for (TomlTable a : t.tables("axis")) {
    SweepAxisOptions ax;
    const std::string p = a.string("parameter");
    if (!parse_sweep_parameter(p, ax.parameter))
      a.fail("parameter", "'" + p + "' is not one of spin_rev_s, speed_m_s, attack_angle_deg, path_angle_deg");
    if (auto v = a.maybe_numbers("values")) {
      if (a.has("from") || a.has("to") || a.has("step")) a.fail("values", "give values or from/to/step, not both");
      ax.values = *v;
    } else {
      const double from = a.number("from"), to = a.number("to"), step = a.number("step");
      a.require_positive("step", step);
      if (!(to >= from)) a.fail("to", "must be >= from");
      ax.values = from_to_step(a, "step", from, to, step, 10001);
    }
    if (ax.values.size() < 2) a.fail("values", "a sweep needs at least 2 values");
    if (!std::is_sorted(ax.values.begin(), ax.values.end())) a.fail("values", "values must ascend");
    ax.threshold_tolerance = positive(a, "tolerance", ax.threshold_tolerance);
    a.finish();
    o.sweep_axes.push_back(ax);
  }
  t.finish();
}

void read_validation(TomlTable t, StoneStudiesOptions& o) {
  ValidationOptions& v = o.validation;
  v.laws = laws_of(t, "laws", v.laws);
  if (v.laws.empty()) t.fail("laws", "must not be empty");
  v.reference_rtol = positive(t, "reference_rtol", v.reference_rtol);
  v.speed_tolerance_m_s = positive(t, "speed_tolerance_m_s", v.speed_tolerance_m_s);
  v.angle_tolerance_deg = positive(t, "angle_tolerance_deg", v.angle_tolerance_deg);
  v.clanet_attack_deg = any_list(t, "clanet_attack_deg", v.clanet_attack_deg);
  v.clanet_speed_low_m_s = positive(t, "clanet_speed_low_m_s", v.clanet_speed_low_m_s);
  v.clanet_speed_high_m_s = positive(t, "clanet_speed_high_m_s", v.clanet_speed_high_m_s);
  if (!(v.clanet_speed_high_m_s > v.clanet_speed_low_m_s)) t.fail("clanet_speed_high_m_s", "must exceed clanet_speed_low_m_s");
  v.clanet_contact_speeds_m_s = positive_list(t, "clanet_contact_speeds_m_s", v.clanet_contact_speeds_m_s);
  v.bocquet_speeds_m_s = positive_list(t, "bocquet_speeds_m_s", v.bocquet_speeds_m_s);
  v.bocquet_spins_rev_s = any_list(t, "bocquet_spins_rev_s", v.bocquet_spins_rev_s);
  v.regime_spins_rev_s = any_list(t, "regime_spins_rev_s", v.regime_spins_rev_s);
  v.regime_attack_deg = t.number_or("regime_attack_deg", v.regime_attack_deg);
  if (auto names = t.maybe_strings("distributions")) {
    if (names->empty()) t.fail("distributions", "must not be empty");
    v.distributions.clear();
    for (const auto& n : *names) {
      PressureDistribution d;
      if (!parse_pressure_distribution(n, d)) t.fail("distributions", "'" + n + "' is not one of uniform, savitsky, savitsky_wagner");
      if (std::find(v.distributions.begin(), v.distributions.end(), d) != v.distributions.end())
        t.fail("distributions", "'" + n + "' repeats");
      v.distributions.push_back(d);
    }
    if (std::find(v.distributions.begin(), v.distributions.end(), PressureDistribution::uniform) == v.distributions.end())
      t.fail("distributions", "must include uniform (the model-beside-model rows and Fig. 9 use it)");
  }
  v.diving_spin_rev_s = t.number_or("diving_spin_rev_s", v.diving_spin_rev_s);
  v.trout_spin_rev_s = t.number_or("trout_spin_rev_s", v.trout_spin_rev_s);
  for (const char* key : {"diving_spin_rev_s", "trout_spin_rev_s"}) {
    const double w = std::string(key) == "diving_spin_rev_s" ? v.diving_spin_rev_s : v.trout_spin_rev_s;
    if (std::find(v.regime_spins_rev_s.begin(), v.regime_spins_rev_s.end(), w) == v.regime_spins_rev_s.end())
      t.fail(key, "must be one of regime_spins_rev_s");
  }
  v.surfing_attack_deg = t.number_or("surfing_attack_deg", v.surfing_attack_deg);
  v.surfing_path_angle_deg = positive(t, "surfing_path_angle_deg", v.surfing_path_angle_deg);
  v.sphere_radius_m = positive(t, "sphere_radius_m", v.sphere_radius_m);
  v.sphere_density_ratio = positive(t, "sphere_density_ratio", v.sphere_density_ratio);
  v.sphere_speed_m_s = positive(t, "sphere_speed_m_s", v.sphere_speed_m_s);
  v.sphere_subdivisions = count(t, "sphere_subdivisions", v.sphere_subdivisions, 0, 5);
  v.sphere_theta_coefficient_deg = positive(t, "sphere_theta_coefficient_deg", v.sphere_theta_coefficient_deg);
  v.contact_time_speed_m_s = positive(t, "contact_time_speed_m_s", v.contact_time_speed_m_s);
  v.min_speed_attack_deg = t.number_or("min_speed_attack_deg", v.min_speed_attack_deg);
  v.contact_exponent_expected = t.number_or("contact_exponent_expected", v.contact_exponent_expected);
  v.count_exponent_expected = t.number_or("count_exponent_expected", v.count_exponent_expected);
  v.exponent_tolerance = positive(t, "exponent_tolerance", v.exponent_tolerance);
  v.history_dt_s = positive(t, "history_dt_s", v.history_dt_s);
  v.peer_description = t.string_or("peer_description", "");
  if (auto r = t.maybe_table("ranking")) {
    RankingOptions& k = v.ranking;
    k.miss_distance = positive(*r, "miss_distance", k.miss_distance);
    k.held_spin_rev_s = r->number_or("held_spin_rev_s", k.held_spin_rev_s);
    if (std::find(v.regime_spins_rev_s.begin(), v.regime_spins_rev_s.end(), k.held_spin_rev_s) == v.regime_spins_rev_s.end())
      r->fail("held_spin_rev_s", "must be one of [validation] regime_spins_rev_s");
    SkipBounds& b = k.bounds;
    for (auto [key, x] : {std::pair<const char*, double*>{"min_speed_fraction", &b.min_speed_fraction},
                          {"best_attack_bound_deg", &b.best_attack_deg},
                          {"max_path_angle_bound_deg", &b.max_path_angle_deg},
                          {"contact_time_fraction", &b.contact_time_fraction},
                          {"attitude_bound_deg", &b.attitude_deg}}) {
      *x = r->number_or(key, *x);
      r->require_non_negative(key, *x);
    }
    k.cost_repeats = count(*r, "cost_repeats", k.cost_repeats, 1, 100);
    if (auto names = r->maybe_strings("cost_throws")) {
      if (names->empty()) r->fail("cost_throws", "must not be empty");
      for (const auto& n : *names)
        if (std::find(cost_throw_names().begin(), cost_throw_names().end(), n) == cost_throw_names().end())
          r->fail("cost_throws", "'" + n + "' is not one of clanet, seed_spin, seed_nospin");
      k.cost_throws = *names;
    }
    r->finish();
  }
  v.curves.clear();
  if (t.has("curve")) {
    for (TomlTable c : t.tables("curve")) {
      MeasuredCurve m;
      m.key = c.string("key");
      if (m.key != "clanet_min_speed") c.fail("key", "'" + m.key + "' is not a model curve (clanet_min_speed)");
      m.label = c.string("label");
      m.source = c.string("source");
      m.x = c.numbers("x");
      m.low = c.numbers("low");
      m.high = c.numbers("high");
      if (m.x.empty()) c.fail("x", "must not be empty");
      if (m.low.size() != m.x.size()) c.fail("low", "needs one value per x");
      if (m.high.size() != m.x.size()) c.fail("high", "needs one value per x");
      for (std::size_t i = 0; i < m.x.size(); ++i)
        if (!(m.low[i] <= m.high[i])) c.fail("high", "every high must be >= its low");
      c.finish();
      v.curves.push_back(m);
    }
  } else {
    t.maybe_table("curve");
  }
  v.measured.clear();
  if (t.has("measured")) {
    for (TomlTable m : t.tables("measured")) {
      MeasuredValue x;
      x.key = m.string("key");
      x.quantity = m.string("quantity");
      x.measured = m.string("measured");
      x.expected = m.string_or("expected", "–");
      x.source = m.string("source");
      x.kind = m.string_or("kind", "measurement");
      x.peer = m.string_or("peer", "");
      if (!x.peer.empty() && v.peer_description.empty())
        m.fail("peer", "a peer's value needs validation.peer_description (what the peer is and where its numbers come from)");
      if (x.kind != "measurement" && x.kind != "model") m.fail("kind", "'" + x.kind + "' is not one of measurement, model");
      if (x.kind == "model" && (m.has("score_low") || m.has("score_high")))
        m.fail("kind", "a model's estimate is shown beside the model, never scored");
      const auto lo = m.maybe_number("score_low"), hi = m.maybe_number("score_high");
      if (lo.has_value() != hi.has_value()) m.fail(lo ? "score_high" : "score_low", "give score_low and score_high together");
      if (lo) {
        const auto& known = scorable_quantities();
        if (std::find(known.begin(), known.end(), x.key) == known.end())
          m.fail("score_low", "'" + x.key + "' is not a quantity the ranking can score");
        if (!(*lo <= *hi)) m.fail("score_high", "must be >= score_low");
        if (!(*lo * *hi > 0)) m.fail("score_low", "score_low and score_high must be non-zero and of one sign");
        x.score = MeasuredRange{*lo, *hi};
        x.score_unit = m.string("score_unit");
      } else if (m.has("score_unit")) {
        m.fail("score_unit", "only with score_low and score_high");
      }
      m.finish();
      v.measured.push_back(x);
    }
  } else {
    t.maybe_table("measured");
  }
  t.finish();
}

void read_hard_cases(TomlTable t, StoneStudiesOptions& o) {
  HardCaseOptions& h = o.hard_cases;
  h.single_steps_s = positive_list(t, "single_steps_s", h.single_steps_s);
  if (!std::is_sorted(h.single_steps_s.begin(), h.single_steps_s.end())) t.fail("single_steps_s", "steps must ascend");
  h.reference_rtol = positive(t, "reference_rtol", h.reference_rtol);
  h.reference_atol = positive(t, "reference_atol", h.reference_atol);
  h.energy_tolerance_fraction = positive(t, "energy_tolerance_fraction", h.energy_tolerance_fraction);
  t.finish();
}

void read_stable_step(TomlTable t, StoneStudiesOptions& o) {
  StableStepOptions& s = o.stable_step;
  s.speeds_m_s = positive_list(t, "speeds_m_s", s.speeds_m_s);
  s.steps_s = positive_list(t, "steps_s", s.steps_s);
  if (!std::is_sorted(s.steps_s.begin(), s.steps_s.end())) t.fail("steps_s", "steps must ascend");
  s.reference_rtol = positive(t, "reference_rtol", s.reference_rtol);
  s.energy_tolerance_fraction = positive(t, "energy_tolerance_fraction", s.energy_tolerance_fraction);
  s.scheme = scheme_of(t, "scheme", t.string_or("scheme", to_string(s.scheme)));
  t.finish();
}

}  // namespace

StoneStudyFile load_stone_study_file(const std::string& path, const std::vector<std::string>& overrides) {
  const TomlDocument doc = load_toml(path, overrides);
  StoneStudyFile f;
  f.file = doc.file;
  f.text = doc.text;
  TomlTable top = doc.top();
  f.title = read_case_title(top);
  StoneStudiesOptions& o = f.options;
  {
    TomlTable s = top.table("study");
    o.preset = study_preset(s, "stones");
    s.finish();
  }
  const fs::path dir = fs::path(path).parent_path();
  read_throws(dir, top.table("throws"), o);
  if (auto t = top.maybe_table("convergence")) read_convergence(*t, o);
  if (auto t = top.maybe_table("reference_tolerance")) read_reference_tolerance(*t, o);
  if (auto t = top.maybe_table("work_precision")) read_work_precision(*t, o);
  if (auto t = top.maybe_table("restarts")) read_restarts(*t, o);
  if (auto t = top.maybe_table("work_precision_grid")) read_work_precision_grid(dir, *t, o);
  read_sweeps(top.table("sweeps"), o);
  if (auto t = top.maybe_table("mesh")) read_mesh(dir, *t, o);
  if (auto t = top.maybe_table("validation")) read_validation(*t, o);
  if (auto t = top.maybe_table("hard_cases")) read_hard_cases(*t, o);
  if (auto t = top.maybe_table("stable_step")) read_stable_step(*t, o);
  top.finish();
  // Everything the findings depend on: the study file and the text of every case it names.
  f.settings_text = "# " + f.file + "\n" + f.text;
  for (const StudyThrow* t : {&o.convergence_throw, &o.spin_throw, &o.nospin_throw, &o.sweep_base, &o.clanet, &o.bocquet,
                              &o.stable_step_base, &o.flat_drop})
    if (!t->file.empty()) f.settings_text += "\n# case " + t->file + "\n" + t->case_text;
  for (const auto& h : o.hard) f.settings_text += "\n# hard case " + h.file + "\n" + h.case_text;
  if (!o.mesh_base.file.empty()) f.settings_text += "\n# case " + o.mesh_base.file + "\n" + o.mesh_base.case_text;
  if (!o.work_precision_grid_base.file.empty())
    f.settings_text += "\n# case " + o.work_precision_grid_base.file + "\n" + o.work_precision_grid_base.case_text;
  std::string why;
  if (!o.valid(&why)) throw_input_error(f.file, 0, "", why);
  return f;
}

}  // namespace stoneskip
