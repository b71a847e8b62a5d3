#include "verification/stones/stone_studies.hpp"

#include <algorithm>
#include <stdexcept>

#include "verification/study/order_record.hpp"

namespace stoneskip {

namespace {

std::vector<const StudyThrow*> named_throws(const StoneStudiesOptions& o) {
  return {&o.convergence_throw, &o.spin_throw, &o.nospin_throw, &o.sweep_base, &o.clanet, &o.bocquet, &o.stable_step_base,
          &o.flat_drop};
}
const char* kThrowNames[] = {"convergence", "spin",  "nospin",           "sweep_base",
                             "clanet",      "bocquet", "stable_step_base", "flat_drop"};

ThrowProblem work_throw(const StoneStudiesOptions& o, const std::string& entry) {
  const std::size_t at = entry.find('@');
  const std::string name = entry.substr(0, at);
  ThrowProblem p;
  if (name == "spin_paper") {
    p = with_convention(o.spin_throw.problem, Convention::paper);
    p.label += " (paper convention)";
  } else {
    const auto all = named_throws(o);
    const auto it = std::find(std::begin(kThrowNames), std::end(kThrowNames), name);
    if (it == std::end(kThrowNames)) throw std::invalid_argument("no study throw named '" + name + "'");
    p = all[static_cast<std::size_t>(it - std::begin(kThrowNames))]->problem;
  }
  if (at != std::string::npos) {
    WaterLaw law = WaterLaw::newtonian;
    parse_water_law(entry.substr(at + 1), law);
    set_water_law(p.environment, law);
    p.label += std::string(" (") + to_string(law) + ")";
  }
  return p;
}

// The throw under each law with its published C_w and under each pressure distribution (labelled
// with them), or as given when no law is named; a distribution left out is the throw's own.
std::vector<ThrowProblem> under_laws(const ThrowProblem& p, const std::vector<WaterLaw>& laws,
                                     const std::vector<PressureDistribution>& distributions) {
  if (laws.empty() && distributions.empty()) return {p};
  const std::vector<WaterLaw> ls = laws.empty() ? std::vector<WaterLaw>{p.environment.water_law} : laws;
  std::vector<ThrowProblem> out;
  for (WaterLaw law : ls) {
    ThrowProblem q = p;
    set_water_law(q.environment, law);
    const std::vector<PressureDistribution> ds =
        distributions.empty() ? std::vector<PressureDistribution>{q.environment.pressure_distribution} : distributions;
    for (PressureDistribution d : ds) {
      ThrowProblem r = q;
      r.environment.pressure_distribution = d;
      r.label += std::string(" (") + to_string(law) + ", " + to_string(d) + ")";
      out.push_back(r);
    }
  }
  return out;
}

// The name of a convergence series: its law, and its distribution when the study lists several.
std::string series_name(const ThrowProblem& p, const std::vector<PressureDistribution>& distributions) {
  std::string n = to_string(p.environment.water_law);
  if (distributions.size() > 1) n += std::string("_") + to_string(p.environment.pressure_distribution);
  return n;
}

Record settings_findings(const StoneStudiesOptions& o) {
  Record r;
  r.set("preset", o.preset);
  r.set("workers", o.workers);
  const auto all = named_throws(o);
  std::vector<std::string> names;
  auto store = [&](const std::string& key, const StudyThrow& t) {
    names.push_back(key);
    Record& c = r.child(key);
    c.set("file", t.file);
    c.set("case_text", t.case_text);
    c.set("label", t.problem.label);
    c.set("stone", t.problem.stone.description);
    c.set("mass_kg", t.problem.stone.mass.mass_kg);
    c.set("convention", std::string(to_string(t.problem.environment.convention)));
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!all[i]->file.empty()) store(kThrowNames[i], *all[i]);  // an optional throw left out is not stored
  for (const auto& h : o.hard) store("hard_" + record_key(h.file), h);
  if (!o.work_precision_grid_base.file.empty()) store("work_precision_grid_base", o.work_precision_grid_base);
  r.set_strings("throws", names);
  return r;
}

}  // namespace

std::string study_throw_problem(const std::string& entry) {
  const std::size_t at = entry.find('@');
  const std::string name = entry.substr(0, at);
  if (name != "spin_paper" && std::find(std::begin(kThrowNames), std::end(kThrowNames), name) == std::end(kThrowNames))
    return "'" + name + "' is not one of the study's throws (or spin_paper)";
  if (at == std::string::npos) return "";
  WaterLaw law;
  if (!parse_water_law(entry.substr(at + 1), law))
    return "'" + entry.substr(at + 1) + "' in '" + entry + "' is not one of newtonian, planing, nagahiro_hayakawa";
  if (name == "spin_paper") return "'" + entry + "': the paper convention has only its printed law";
  return "";
}

bool StoneStudiesOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (workers < 1) return fail("workers must be >= 1");
  if (!mesh_base.file.empty() && !mesh.valid(why)) return false;
  if (convergence.dt_s.empty() || convergence.interval_steps.empty()) return fail("convergence needs steps");
  if (work_precision.dt_s.empty() || work_precision.rtol.empty()) return fail("work_precision needs steps and tolerances");
  for (const auto* list : {&work_precision_throws, &restarts.throws})
    for (const auto& n : *list) {
      const std::string study = list == &restarts.throws ? "restarts" : "work_precision";
      if (const std::string problem = study_throw_problem(n); !problem.empty()) return fail(study + " throw " + problem);
      const std::string name = n.substr(0, n.find('@'));
      if (name == "flat_drop" && flat_drop.file.empty())
        return fail(study + " throw 'flat_drop': the study file names no flat_drop case in [throws]");
      if (n.find('@') != std::string::npos && name != "spin_paper") {
        const auto all = named_throws(*this);
        const auto it = std::find(std::begin(kThrowNames), std::end(kThrowNames), name);
        if (all[static_cast<std::size_t>(it - std::begin(kThrowNames))]->problem.environment.convention == Convention::paper)
          return fail(study + " throw '" + n + "': its case is in the paper convention, which has only its printed law");
      }
    }
  // The same throw twice (a plain name whose case already has the law an "@law" entry names)
  // would count one throw twice in a study's totals.
  for (const auto* list : {&work_precision_throws, &restarts.throws})
    for (std::size_t i = 0; i < list->size(); ++i)
      for (std::size_t k = 0; k < i; ++k) {
        const ThrowProblem a = work_throw(*this, (*list)[k]), b = work_throw(*this, (*list)[i]);
        const std::string na = (*list)[k].substr(0, (*list)[k].find('@')), nb = (*list)[i].substr(0, (*list)[i].find('@'));
        if (na == nb && a.environment.convention == b.environment.convention && a.environment.water_law == b.environment.water_law &&
            a.environment.water_coefficient == b.environment.water_coefficient &&
            a.environment.pressure_distribution == b.environment.pressure_distribution)
          return fail(std::string(list == &restarts.throws ? "restarts" : "work_precision") + " throws '" + (*list)[k] +
                      "' and '" + (*list)[i] + "' are the same throw under the same law");
      }
  if (restarts.rtol.empty() || restarts.methods.empty()) return fail("the restart study needs methods and tolerances");
  if (!work_precision_grid_base.file.empty()) {
    if (!work_precision_grid.valid(why)) return false;
    if (work_precision_grid_base.problem.environment.convention != Convention::physical)
      return fail("work_precision_grid: the base throw must be in the physical convention");
  }
  if (!validation.valid(why)) return false;
  for (const auto& a : sweep_axes) {
    if (a.values.size() < 2) return fail(std::string("sweep over ") + to_string(a.parameter) + " needs at least 2 values");
    if (!std::is_sorted(a.values.begin(), a.values.end())) return fail("sweep values must ascend");
    if (!(a.threshold_tolerance > 0)) return fail("sweep threshold tolerance must be > 0");
  }
  if (!count_ensembles.valid(why)) return false;
  return true;
}

Record run_stone_studies(const StoneStudiesOptions& o, StudySink& sink) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("stone study settings: " + why);
  const ProgressFactory& progress = sink.progress();
  run_section(sink, "settings", [&] { return settings_findings(o); });

  run_section(sink, "convergence", [&] {
    RealtimeConvergenceOptions co = o.convergence;
    co.workers = o.workers;
    co.progress = progress;
    co.order_tolerance = o.convergence_judgement.tolerance;  // one judgement for the series and their stored verdicts
    ReferenceToleranceOptions to = o.reference_tolerance;
    to.workers = o.workers;
    to.progress = progress;
    // The first law in full (with the reference's own tolerance study), every other law's series.
    const std::vector<ThrowProblem> throws =
        under_laws(o.convergence_throw.problem, o.convergence_laws, o.convergence_distributions);
    const RealtimeConvergenceResult conv = run_realtime_convergence(throws.front(), co);
    const ReferenceToleranceResult tol = run_reference_tolerance(throws.front(), to);
    Record r = convergence_findings(conv, tol, o.convergence_judgement, o.required_tolerance_drop);
    r.child("reference_tolerance").set("truth_rtol", to.truth_rtol);
    r.child("reference_tolerance").set("atol_ratio", to.atol_ratio);
    r.set("contact_ratio", co.contact_ratio);
    r.set("fixed_kinks", std::string(to_string(co.fixed_kinks)));
    r.set("law", series_name(throws.front(), o.convergence_distributions));
    r.set("distribution", std::string(to_string(throws.front().environment.pressure_distribution)));
    std::vector<std::string> others;
    for (std::size_t k = 1; k < throws.size(); ++k) {
      const std::string law = series_name(throws[k], o.convergence_distributions);
      others.push_back(law);
      Record lr = convergence_series_findings(run_realtime_convergence(throws[k], co), o.convergence_judgement);
      lr.set("distribution", std::string(to_string(throws[k].environment.pressure_distribution)));
      r.child("other_laws").add_child(law, std::move(lr));
    }
    r.set_strings("other_laws_list", others);
    return r;
  });

  run_section(sink, "work_precision", [&] {
    WorkPrecisionOptions wo = o.work_precision;
    wo.workers = o.workers;
    wo.progress = progress;
    wo.laws.clear();  // each throw's law is named with it ("nospin@planing")
    std::vector<ThrowProblem> throws;
    for (const auto& n : o.work_precision_throws) throws.push_back(work_throw(o, n));
    Record r = work_precision_findings(run_work_precision(throws, wo), wo);
    // The restart strategies: CVODE only, on spinning and non-spinning throws, under their laws.
    const RestartStudyOptions& ro = o.restarts;
    WorkPrecisionOptions rs = wo;
    rs.realtime.clear();
    rs.dt_s.clear();
    rs.methods = ro.methods;
    rs.restarts = ro.strategies;
    rs.rtol = ro.rtol;
    rs.repeats = ro.repeats;
    rs.restart_time_tolerance_s = ro.time_tolerance_s;
    rs.restart_error_factor = ro.error_factor;
    std::vector<ThrowProblem> restart_throws;
    for (const auto& n : ro.throws) restart_throws.push_back(work_throw(o, n));
    if (!restart_throws.empty() && !ro.strategies.empty())
      r.add_child("restarts", restart_findings(run_work_precision(restart_throws, rs), rs, ReferenceOptions{}.restart));
    return r;
  });

  if (!o.work_precision_grid_base.file.empty())
    run_section(sink, "work_precision_grid", [&] {
      WorkPrecisionGridOptions g = o.work_precision_grid;
      g.adaptive_rtol = o.work_precision.adaptive_rtol;  // the study's bs32 tolerances and truths
      g.truth_rtol = o.work_precision.truth_rtol;
      g.truth_check_factor = o.work_precision.truth_check_factor;
      g.atol_ratio = o.work_precision.atol_ratio;
      g.workers = o.workers;
      g.progress = progress;
      return work_precision_grid_findings(run_work_precision_grid(o.work_precision_grid_base.problem, g), g);
    });

  run_section(sink, "validation", [&] {
    ValidationOptions vo = o.validation;
    vo.workers = o.workers;
    vo.progress = progress;
    const ValidationResult v =
        run_validation(o.clanet.problem, o.bocquet.problem, o.nospin_throw.problem, o.spin_throw.problem, vo);
    Record r = validation_findings(v, vo);
    // The paper's Fig. 9 histories (shown with the sweeps): the seed's throws with the default law
    // and with the paper's printed equations, both solvers.
    Record& f = r.child("fig9");
    std::vector<std::string> keys;
    for (const auto& run : v.variants) {
      if (run.variant.convention != Convention::paper && (run.variant.law != vo.laws.front() || !run.variant.beside_models()))
        continue;
      for (const ThrowHistory* h : {&run.without_spin, &run.with_spin}) {
        keys.push_back(record_key(h->label));
        f.add_child(keys.back(), history_record(*h));
      }
    }
    f.set_strings("histories", keys);
    return r;
  });

  run_section(sink, "sweeps", [&] {
    std::vector<BounceSweepSpec> specs;
    for (const auto& a : o.sweep_axes)
      for (Convention c : {Convention::physical, Convention::paper})
        for (SolverKind k : {SolverKind::reference, SolverKind::realtime}) {
          BounceSweepSpec s;
          s.base = o.sweep_base.problem;
          s.parameter = a.parameter;
          s.values = a.values;
          s.convention = c;
          s.threshold_tolerance = a.threshold_tolerance;
          s.max_thresholds = o.max_thresholds;
          if (k == SolverKind::realtime) {
            s.solver = realtime_choice(o.sweep_base.problem.realtime);
          } else {
            ReferenceOptions r = o.sweep_base.problem.reference;
            r.rtol = o.sweep_reference_rtol;
            r.atol = o.sweep_reference_atol;
            s.solver = reference_choice(r);
          }
          s.name = std::string(to_string(a.parameter)) + "_" + to_string(c) + "_" +
                   (k == SolverKind::realtime ? "realtime" : "reference");
          specs.push_back(s);
        }
    const auto sweeps = run_bounce_sweeps(specs, ParallelOptions{o.workers, "stones: bounce-count sweeps", progress});
    return sweeps_findings(sweeps);
  });

  if (o.count_ensembles.throws_per_axis > 0)
    run_section(sink, "count_ensembles", [&] {
      std::vector<std::pair<SweepParameter, std::vector<double>>> axes;
      for (const auto& a : o.sweep_axes) axes.emplace_back(a.parameter, a.values);
      ReferenceOptions r = o.sweep_base.problem.reference;
      r.rtol = o.sweep_reference_rtol;
      r.atol = o.sweep_reference_atol;
      const auto throws = run_count_ensembles(o.sweep_base.problem, realtime_choice(o.sweep_base.problem.realtime),
                                              reference_choice(r), axes, o.count_ensembles,
                                              ParallelOptions{o.workers, "stones: bounce counts on ensembles", progress});
      return count_ensembles_findings(throws, o.count_ensembles);
    });

  if (!o.mesh_base.file.empty())
    run_section(sink, "mesh", [&] {
      const SolverChoice solver = realtime_choice(o.mesh_base.problem.realtime);
      const auto runs = run_mesh_study(o.mesh_base.problem, solver, o.mesh,
                                       ParallelOptions{o.workers, "stones: bounce counts against the mesh", progress});
      return mesh_study_findings(runs, o.mesh, solver.label());
    });

  run_section(sink, "hard_cases", [&] {
    HardCaseOptions ho = o.hard_cases;
    ho.workers = o.workers;
    ho.progress = progress;
    StableStepOptions so = o.stable_step;
    so.workers = o.workers;
    so.progress = progress;
    std::vector<std::pair<std::string, ThrowProblem>> problems;
    for (const auto& h : o.hard) problems.emplace_back(h.file, h.problem);
    const auto hard = run_hard_cases(problems, ho);
    const auto stable = run_stable_step(o.stable_step_base.problem, so);
    return hard_cases_findings(hard, stable, ho, so);
  });

  Record root;
  root.set("preset", o.preset);
  return root;
}

}  // namespace stoneskip
