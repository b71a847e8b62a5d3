#include "verification/stones/hard_cases.hpp"

#include <cmath>
#include <functional>
#include <sstream>

#include "verification/stones/parallel_runs.hpp"

namespace stoneskip {

namespace {

double release_kinetic(const ThrowProblem& p) {
  const Energy e = mechanical_energy(p.stone, p.environment, p.initial);
  return e.translational_J + e.rotational_J;
}

ReferenceOptions tight(const ThrowProblem& p, double rtol, double atol) {
  ReferenceOptions r = p.reference;
  r.rtol = rtol;
  r.atol = atol;
  r.record_trajectory = false;
  return r;
}

std::string verdict_of(const HardRun& run, Convention conv) {
  std::ostringstream s;
  if (!run.finite) return "fails: " + run.result.outcome_detail;
  std::vector<std::string> parts;
  if (run.contacts.missed) parts.push_back("misses " + std::to_string(run.contacts.missed) + " of " +
                                           std::to_string(run.contacts.reference_contacts) + " reference contacts");
  if (run.contacts.spurious) parts.push_back(std::to_string(run.contacts.spurious) + " contacts the reference does not have");
  if (!run.contacts.same_bounces())
    parts.push_back(std::to_string(run.contacts.solver_bounces) + " bounces vs " +
                    std::to_string(run.contacts.reference_bounces));
  if (run.energy_created) {
    std::ostringstream e;
    e << "creates " << run.result.max_energy_gain_J << " J over a contact"
      << (conv == Convention::paper ? " (the paper convention allows it)" : " (must not: physical convention)");
    parts.push_back(e.str());
  }
  if (parts.empty()) return "ok";
  for (std::size_t i = 0; i < parts.size(); ++i) s << (i ? "; " : "") << parts[i];
  return s.str();
}

}  // namespace

std::vector<HardCaseResult> run_hard_cases(const std::vector<std::pair<std::string, ThrowProblem>>& cases,
                                           const HardCaseOptions& o) {
  std::vector<HardCaseResult> out(cases.size());
  std::vector<std::function<void()>> jobs;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const ThrowProblem& p = cases[k].second;
    HardCaseResult& h = out[k];
    h.file = cases[k].first;
    h.title = p.label;
    h.convention = p.environment.convention;
    h.release_kinetic_J = release_kinetic(p);
    h.energy_tolerance_J = o.energy_tolerance_fraction * h.release_kinetic_J;
    h.runs.resize(1 + o.single_steps_s.size());
    {
      std::ostringstream s;
      s << "case settings (" << to_string(p.realtime.scheme);
      if (is_adaptive(p.realtime.scheme))
        s << ", rtol " << p.realtime.rtol << ", atol " << p.realtime.atol_m << " m)";
      else
        s << ", dt " << p.realtime.dt_s << " / " << p.realtime.contact_dt_s << " s)";
      h.runs[0].setting = s.str();
    }
    h.runs[0].dt_s = p.realtime.dt_s;
    h.runs[0].contact_dt_s = p.realtime.contact_dt_s;
    for (std::size_t i = 0; i < o.single_steps_s.size(); ++i) {
      std::ostringstream s;
      s << "single step " << o.single_steps_s[i] << " s (" << to_string(o.single_step_scheme) << ")";
      h.runs[1 + i].setting = s.str();
      h.runs[1 + i].dt_s = h.runs[1 + i].contact_dt_s = o.single_steps_s[i];
    }
    jobs.push_back([&, k] { out[k].reference = solve(cases[k].second, reference_choice(tight(cases[k].second, o.reference_rtol, o.reference_atol))); });
    for (std::size_t i = 0; i < h.runs.size(); ++i)
      jobs.push_back([&, k, i] {
        HardRun& r = out[k].runs[i];
        RealtimeOptions ro = cases[k].second.realtime;
        if (i > 0) {  // the single-step runs
          ro.scheme = o.single_step_scheme;
          ro.dt_s = r.dt_s;
          ro.contact_dt_s = r.contact_dt_s;
        }
        ro.record_trajectory = false;
        r.result = solve(cases[k].second, realtime_choice(ro));
      });
  }
  run_jobs(jobs, ParallelOptions{o.workers, "stones: hard cases", o.progress});
  for (auto& h : out) {
    const ThrowResult& ref = h.reference;
    if (ref.outcome == Outcome::failed) {
      h.reference_verdict = "fails: " + ref.outcome_detail;
    } else {
      std::ostringstream s;
      s << "stable (" << to_string(ref.outcome) << " at " << ref.end_time_s << " s, " << ref.contacts.size()
        << " contacts, " << ref.bounces << " bounces, " << ref.stats.segments << " segments)";
      if (ref.max_energy_gain_J > h.energy_tolerance_J)
        s << "; creates " << ref.max_energy_gain_J << " J over a contact"
          << (h.convention == Convention::paper ? " (the paper convention allows it)" : " (must not!)");
      h.reference_verdict = s.str();
    }
    for (auto& r : h.runs) {
      r.finite = r.result.outcome != Outcome::failed;
      r.contacts = compare_contacts(r.result, ref);
      r.energy_created = r.result.max_energy_gain_J > h.energy_tolerance_J;
      r.verdict = verdict_of(r, h.convention);
    }
  }
  return out;
}

std::vector<StableStepRow> run_stable_step(const ThrowProblem& base, const StableStepOptions& o) {
  std::vector<double> steps = o.steps_s;
  if (steps.empty())
    for (int k = 0; k <= 11; ++k) steps.push_back(1e-5 * std::pow(2.0, k));
  std::vector<StableStepRow> rows(o.speeds_m_s.size());
  std::vector<ThrowProblem> problems;
  std::vector<ThrowResult> refs(o.speeds_m_s.size());
  std::vector<std::vector<ThrowResult>> runs(o.speeds_m_s.size(), std::vector<ThrowResult>(steps.size()));
  for (double U : o.speeds_m_s) {
    ThrowParameters tp = base.parameters;
    tp.speed_m_s = U;
    problems.push_back(with_parameters(base, tp));
  }
  std::vector<std::function<void()>> jobs;
  for (std::size_t k = 0; k < problems.size(); ++k) {
    jobs.push_back([&, k] { refs[k] = solve(problems[k], reference_choice(tight(problems[k], o.reference_rtol, o.reference_rtol * 1e-2))); });
    for (std::size_t i = 0; i < steps.size(); ++i)
      jobs.push_back([&, k, i] {
        RealtimeOptions ro = problems[k].realtime;
        ro.scheme = o.scheme;
        ro.dt_s = ro.contact_dt_s = steps[i];
        ro.record_trajectory = false;
        runs[k][i] = solve(problems[k], realtime_choice(ro));
      });
  }
  run_jobs(jobs, ParallelOptions{o.workers, "stones: largest stable step", o.progress});
  for (std::size_t k = 0; k < problems.size(); ++k) {
    StableStepRow& row = rows[k];
    row.speed_m_s = o.speeds_m_s[k];
    row.reference_bounces = refs[k].bounces;
    row.reference_contacts = static_cast<int>(refs[k].contacts.size());
    row.steps_s = steps;
    const double tol = o.energy_tolerance_fraction * release_kinetic(problems[k]);
    bool finite = true, no_gain = true, same = true;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const ThrowResult& r = runs[k][i];
      const bool f = r.outcome != Outcome::failed;
      row.bounces.push_back(f ? r.bounces : -1);
      row.energy_gain_J.push_back(r.max_energy_gain_J);
      finite = finite && f;
      no_gain = no_gain && finite && r.max_energy_gain_J <= tol;
      same = same && no_gain && r.contacts.size() == refs[k].contacts.size() && r.bounces == refs[k].bounces;
      if (finite) row.largest_finite_s = steps[i];
      if (no_gain) row.largest_no_energy_gain_s = steps[i];
      if (same) row.largest_same_contacts_s = steps[i];
    }
  }
  return rows;
}

}  // namespace stoneskip
