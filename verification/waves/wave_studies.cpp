#include "verification/waves/wave_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "solvers/realtime/clocks.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180 / M_PI;

std::vector<Stencil> stencils_of(const WaveStudiesOptions& o) {
  std::vector<Stencil> out;
  for (const auto& n : o.stencils) out.push_back(named_stencil(n));
  return out;
}

Table table(std::vector<std::string> columns) { return Table{std::move(columns), {}}; }

std::vector<double> to_doubles(const std::vector<int>& v) { return {v.begin(), v.end()}; }
std::vector<double> to_doubles(const std::vector<long>& v) { return {v.begin(), v.end()}; }

// The problem's settings, stored where a section needs to say what it solved.
void store_problem(Record& r, const WaveProblem& p) {
  r.set("length_m", p.length_m);
  r.set("wave_speed_m_s", p.wave_speed_m_s);
  r.set("damping_per_s", p.damping_per_s);
  r.set("t_end_s", p.t_end_s);
  r.set("initial", std::string(to_string(p.initial.kind)));
  r.set("amplitude_m", p.initial.amplitude_m);
  r.set("width_m", p.initial.width_m);
  // The rest of the disturbance, so the page can say what was solved (a plane wave was described
  // as a bump of width 0.1 m "in the middle", a Gaussian at (0.1, 0.9) m as "in the middle").
  r.set("x_m", p.initial.x_m);
  r.set("y_m", p.initial.y_m);
  r.set("radius_m", p.initial.radius_m);
  r.set("angle_deg", p.initial.angle_deg);
  r.set("wavelength_m", p.initial.wavelength_m);
}

}  // namespace

bool WaveStudiesOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (stencils.empty()) return fail("no stencils");
  for (const auto& s : stencils)
    if (!is_stencil_name(s)) return fail("unknown stencil '" + s + "'");
  if (!(problem.length_m > 0 && problem.wave_speed_m_s > 0 && problem.damping_per_s >= 0 && problem.t_end_s > 0))
    return fail("the problem needs length, wave speed and end time > 0 and damping >= 0");
  auto grids_ok = [](const std::vector<int>& g) {
    return !g.empty() && std::all_of(g.begin(), g.end(), [](int n) { return n >= 8 && n % 4 == 0 && n <= 4096; });
  };
  if (!grids_ok(convergence.space_grids) || !grids_ok(convergence.both_grids) || convergence.time_grid < 8 ||
      convergence.time_grid % 4 != 0)
    return fail("convergence grids must be multiples of 4 in [8, 4096]");
  if (convergence.time_steps.empty() ||
      std::any_of(convergence.time_steps.begin(), convergence.time_steps.end(), [](long s) { return s < 1; }))
    return fail("convergence time steps must be >= 1");
  if (!(convergence.both_sigma > 0) || convergence.fit_points == 1 || convergence.fit_points < 0)
    return fail("both_sigma > 0 and fit_points = 0 (all) or >= 2 needed");
  if (speed.work.grids.empty() || speed.work.sigma_fractions.empty() || speed.targets_m.empty())
    return fail("speed needs grids, sigma fractions and targets");
  if (std::find(stencils.begin(), stencils.end(), speed.baseline_stencil) == stencils.end())
    return fail("speed.baseline_stencil '" + speed.baseline_stencil + "' is not among the stencils");
  if (std::find(stencils.begin(), stencils.end(), isotropy.baseline_stencil) == stencils.end())
    return fail("isotropy.baseline_stencil '" + isotropy.baseline_stencil + "' is not among the stencils");
  // The isotropy and speed studies leave an inconsistent stencil out: as a baseline it left every
  // ratio "–" and the headline "–× smaller than paper_eq11's –".
  for (const auto& [key, name] : {std::pair<const char*, std::string>{"isotropy", isotropy.baseline_stencil},
                                  std::pair<const char*, std::string>{"speed", speed.baseline_stencil}})
    if (!analyse_consistency(named_stencil(name), consistency).consistent)
      return fail(std::string(key) + ".baseline_stencil '" + name +
                  "' is inconsistent (the consistency study; its weights sum to " + num(named_stencil(name).weight_sum(), 3) +
                  "): the " + key + " study leaves it out, so it cannot be the baseline");
  return true;
}

// ---- settings ---------------------------------------------------------------------------------

Record wave_settings_findings(const WaveStudiesOptions& o) {
  Record r;
  r.set("preset", o.preset);
  r.set_strings("stencils", o.stencils);
  store_problem(r.child("problem"), o.problem);
  Table w = table({"centre", "orth", "diag"});
  for (const auto& st : stencils_of(o)) w.add_row({st.centre, st.orth, st.diag});
  r.set_table("stencil_weights", w);
  return r;
}

// ---- consistency ------------------------------------------------------------------------------

Record wave_consistency_findings(const WaveStudiesOptions& o) {
  Record r;
  r.set("max_kd", o.consistency.max_kd);
  r.set("samples", o.consistency.samples);
  r.set("tolerance", o.consistency.tolerance);
  r.set_strings("stencils", o.stencils);
  Table t = table({"centre", "orth", "diag", "weight_sum", "constant_term", "laplacian_coefficient", "leading_error_min",
                   "leading_error_max", "consistent", "isotropic_leading_error"});
  for (const auto& st : stencils_of(o)) {
    const ConsistencyResult c = analyse_consistency(st, o.consistency);
    t.add_row({st.centre, st.orth, st.diag, c.weight_sum, c.constant_term, c.laplacian_coefficient,
               c.consistent ? c.leading_error_min : kNaN, c.consistent ? c.leading_error_max : kNaN,
               c.consistent ? 1.0 : 0.0, c.isotropic_leading_error ? 1.0 : 0.0});
    Record& s = r.child(st.name);
    Table le = table({"theta_deg", "leading_error"});
    for (std::size_t i = 0; i < c.theta_rad.size(); ++i) le.add_row({c.theta_rad[i] * kDeg, c.leading_error[i]});
    s.set_table("leading_error", le);
    s.set("weight_sum", c.weight_sum);
    std::string reason;
    if (c.consistent) {
      reason = "the symbol's constant term is " + num(c.constant_term, 3) + " and its (kd)² coefficient −" +
               num(c.laplacian_coefficient, 7) + "; leading error s₂(θ) from " + num(c.leading_error_min, 4) +
               " to " + num(c.leading_error_max, 4) +
               (c.isotropic_leading_error ? " (the same in every direction)" : " (it depends on the direction)");
    } else {
      reason = "its weights sum to " + num(c.weight_sum, 4) + " instead of 0 (symbol's constant term " +
               num(c.constant_term, 4) + "): a uniformly raised surface feels " + num(c.weight_sum, 4) +
               "·c²h/d², a term that grows without bound as d → 0";
    }
    Record in;
    in.set("constant_term", c.constant_term);
    in.set("laplacian_coefficient", c.laplacian_coefficient);
    in.set("tolerance", o.consistency.tolerance);
    decide_verdict(s, "verdict", "consistency", in, reason);
  }
  r.set_table("summary", t);
  return r;
}

// ---- convergence ------------------------------------------------------------------------------

namespace {

void store_sequence(Record& parent, const ConvergenceSequence& seq, const OrderJudgement& j) {
  Record& r = parent.child(seq.kind);
  Table t = table({"n", "steps", "h", "sigma", "l2_error_m", "max_error_m", "cpu_s", "point_m"});
  t.units = {"1", "1", seq.kind == "time" ? "s" : "m", "1", "m", "m", "s", "m"};  // h: Δt (time) or d (space, both)
  double cpu = 0;
  std::vector<double> h, e;
  for (const auto& p : seq.points) {
    t.add_row({double(p.n), double(p.steps), p.h, p.sigma, p.l2_m, p.max_m, p.cpu_s, p.point_m});
    cpu += p.cpu_s;
    h.push_back(p.h);
    e.push_back(p.l2_m);
  }
  r.set_table("points", t);
  r.set("cpu_s", cpu);
  store_order_fit(r, "fit", seq.fit, j);
  store_order_fit(r, "fit_max", seq.fit_max, j);
  r.set_table("pairwise_all", value_list(fit_order(h, e).pairwise, "order"));  // every neighbouring pair
  if (seq.kind == "both" && seq.points.size() >= 3) {
    Record& g = r.child("gci");
    const double fine = seq.points.back().point_m;
    const bool usable = seq.gci.kind == ConvergenceKind::monotone || seq.gci.kind == ConvergenceKind::oscillatory;
    g.set("kind", std::string(to_string(seq.gci.kind)));
    g.set("usable", usable);
    g.set("order", usable ? seq.gci.order : kNaN);
    g.set("extrapolated_m", usable ? seq.gci.extrapolated : kNaN);
    g.set("gci_fine", usable ? seq.gci.gci_fine : kNaN);
    // Where the apparent order was not reasonable: the expected order and Fs = 3 used (gci.hpp).
    g.set("reverted", usable && seq.gci.reverted);
    g.set("order_used", usable ? seq.gci.order_used : kNaN);
    g.set("safety_factor", usable ? seq.gci.safety_factor : kNaN);
    g.set("point_fine_m", fine);
    g.set("point_exact_m", seq.point_exact_m);
    const double actual = std::abs(seq.point_exact_m - fine) / std::abs(fine);
    g.set("actual_relative_error", actual);
    // Does the GCI band (a relative uncertainty of the fine value) contain the exact value?
    const bool order_says_no = judge_order(seq.fit, j).verdict == OrderVerdict::does_not_converge;
    std::string reason;
    if (!usable) {
      reason = "the three finest values are " + std::string(to_string(seq.gci.kind)) + ", so Celik's procedure gives no GCI";
    } else if (order_says_no) {
      reason = "the three finest values look " + std::string(to_string(seq.gci.kind)) + " (GCI " +
               num(100 * seq.gci.gci_fine, 3) + " %), but the order test of the whole error says the sequence does not converge; the actual error is " +
               num(100 * actual, 3) + " %";
    } else {
      reason = "GCI " + num(100 * seq.gci.gci_fine, 3) + " % against an actual error of " + num(100 * actual, 3) + " %";
      if (seq.gci.reverted)
        reason += " (the apparent order " + num(seq.gci.order, 3) + " is not within " + num(j.tolerance, 3) + " of " +
                  num(j.expected_order, 3) + ": the GCI uses " + num(seq.gci.order_used, 3) + " and Fs = " +
                  num(seq.gci.safety_factor, 3) + ", Roache 2011)";
    }
    Record in;
    in.set("usable", usable);
    in.set("order_does_not_converge", order_says_no);
    in.set("gci_fine", usable ? seq.gci.gci_fine : kNaN);
    in.set("actual_relative_error", actual);
    decide_verdict(g, "verdict", "gci_band", in, reason);
  }
}

}  // namespace

Record wave_convergence_findings(const WaveStudiesOptions& o, const ProgressFactory& progress) {
  ConvergenceStudyOptions co = o.convergence;
  co.problem = o.problem;
  Record r;
  store_problem(r.child("problem"), co.problem);
  r.set_table("space_grids", value_list(to_doubles(co.space_grids)));
  r.set("time_grid", co.time_grid);
  r.set_table("time_steps", value_list(to_doubles(co.time_steps)));
  r.set_table("both_grids", value_list(to_doubles(co.both_grids)));
  r.set("both_sigma", co.both_sigma);
  std::vector<std::string> walls;
  for (const Boundary b : co.walls) walls.push_back(to_string(b));
  r.set_strings("walls", walls);
  r.set("walls_t_end_s", co.walls_t_end_s);
  r.set("fit_points", co.fit_points);
  r.set("expected_order", co.judgement.expected_order);
  r.set("tolerance", co.judgement.tolerance);
  r.set("minimum_order", co.judgement.minimum_order);
  r.set_strings("stencils", o.stencils);
  auto ticker = start_progress(progress, "waves: convergence", convergence_study_work(co) * o.stencils.size());
  for (const auto& st : stencils_of(o)) {
    const ConvergenceStudy c = run_convergence_study(st, co, ticker.get());
    Record& s = r.child(st.name);
    for (const ConvergenceSequence* seq : {&c.space, &c.time, &c.both}) store_sequence(s, *seq, co.judgement);
    for (const ConvergenceSequence& seq : c.walls) store_sequence(s, seq, co.judgement);
    // What the split says about where an error comes from (computed from the verdicts above).
    const OrderVerdict vs = judge_order(c.space.fit, co.judgement).verdict, vt = judge_order(c.time.fit, co.judgement).verdict;
    if (vs == OrderVerdict::does_not_converge) {
      const auto& sp = c.space.points;
      std::string reason = "its space error is " + num(sp.back().l2_m, 3) + " m RMS on the finest grid against " +
                           num(sp.front().l2_m, 3) + " m on the coarsest (space order " + c.space.fit.brief() +
                           "), while its time error falls at order " + c.time.fit.brief();
      Record in;
      in.set("space_converges", false);
      in.set("time_at_expected", vt == OrderVerdict::converges_at_expected_order);
      decide_verdict(s, "diagnosis", "error_split", in, reason);
    }
  }
  return r;
}

// ---- isotropy ---------------------------------------------------------------------------------

Record wave_isotropy_findings(const WaveStudiesOptions& o, const ProgressFactory& progress) {
  const WaveIsotropyOptions& io = o.isotropy;
  Record r;
  r.set("table_kd", io.table_kd);
  r.set_table("polar_kd", value_list(io.polar_kd, "kd"));
  r.set_table("measured_kd", value_list(io.measured_kd, "kd"));
  r.set("measured_grid", io.measured_grid);
  r.set("measured_sigma", io.measured_sigma);
  r.set("measured_steps", io.measured_steps);
  r.set("ring_n", io.ring.n);
  r.set("ring_width_m", io.ring.width_m);
  r.set("ring_t_s", io.ring.t_s);
  r.set("ring_sigma", io.ring.sigma);
  r.set("baseline_stencil", io.baseline_stencil);

  // Only consistent stencils have a phase speed to speak of.
  std::vector<Stencil> used;
  std::vector<std::string> skipped;
  for (const auto& st : stencils_of(o)) {
    if (analyse_consistency(st, o.consistency).consistent)
      used.push_back(st);
    else
      skipped.push_back(st.name);
  }
  std::vector<std::string> names;
  for (const auto& st : used) names.push_back(st.name);
  r.set_strings("stencils", names);
  r.set_strings("skipped_inconsistent", skipped);

  auto ticker = start_progress(progress, "waves: isotropy", used.size() * (io.measured_kd.size() * io.measured_angles + 1));
  double worst_semi = 0, worst_fully = 0;
  double baseline_spread = kNaN;
  for (const auto& st : used)
    if (st.name == io.baseline_stencil) baseline_spread = phase_error_spread(st, io.table_kd);
  for (const auto& st : used) {
    Record& s = r.child(st.name);
    // From the symbol: polar curves and the spread over direction against kd.
    for (std::size_t k = 0; k < io.polar_kd.size(); ++k) {
      Table t = table({"theta_deg", "speed_ratio"});
      for (int a = 0; a < io.polar_angles; ++a) {
        const double th = 2 * M_PI * a / (io.polar_angles - 1);
        t.add_row({th * kDeg, 1 + phase_speed_error(st, io.polar_kd[k], th)});
      }
      s.set_table("polar_" + std::to_string(k), t);
    }
    Table sp = table({"kd", "spread"});
    for (int i = 0; i < io.spread_points; ++i) {
      const double kd = io.spread_kd_min * std::pow(io.spread_kd_max / io.spread_kd_min, i / double(io.spread_points - 1));
      sp.add_row({kd, phase_error_spread(st, kd)});
    }
    s.set_table("spread", sp);
    Table at = table({"kd", "spread", "mean_error"});
    for (double kd : io.polar_kd) {
      double mean = 0;
      for (int a = 0; a < 91; ++a) mean += phase_speed_error(st, kd, M_PI / 2 * a / 90) / 91;
      at.add_row({kd, phase_error_spread(st, kd), mean});
    }
    s.set_table("spread_at_polar_kd", at);
    const double spread = phase_error_spread(st, io.table_kd);
    double mean = 0;
    for (int a = 0; a < 91; ++a) mean += phase_speed_error(st, io.table_kd, M_PI / 2 * a / 90) / 91;
    s.set("spread_at_table_kd", spread);
    s.set("mean_error_at_table_kd", mean);
    s.set("spread_ratio_to_baseline", spread / baseline_spread);

    // Measured from simulations of single Fourier modes.
    Table m = table({"kd_target", "m", "n", "kd", "theta_deg", "measured_error", "semi_discrete_error",
                     "fully_discrete_error"});
    for (std::size_t ik = 0; ik < io.measured_kd.size(); ++ik) {
      const double kd = io.measured_kd[ik];
      for (int a = 0; a < io.measured_angles; ++a) {
        const MeasuredPhaseSpeed q = measure_phase_speed(st, kd, M_PI / 4 * a / (io.measured_angles - 1),
                                                         io.measured_grid, io.measured_sigma, io.measured_steps);
        m.add_row({kd, double(q.m), double(q.n), q.kd, q.theta_rad * kDeg, q.measured_error, q.semi_discrete_error,
                   q.fully_discrete_error});
        worst_semi = std::max(worst_semi, std::abs(q.measured_error - q.semi_discrete_error));
        worst_fully = std::max(worst_fully, std::abs(q.measured_error - q.fully_discrete_error));
        ticker->tick();
      }
      Table line = table({"theta_deg", "symbol_error_per_kd2"});
      for (int a = 0; a <= 90; ++a) {
        const double th = M_PI / 4 * a / 90;
        line.add_row({th * kDeg, phase_speed_error(st, kd, th) / (kd * kd)});
      }
      s.set_table("symbol_line_" + std::to_string(ik), line);
    }
    s.set_table("measured", m);

    // Ring test.
    const RingTest ring = ring_test(st, io.ring);
    Table rt = table({"theta_deg", "front_radius_m", "reference_front_radius_m", "difference_cells"});
    double lag = 0;
    for (std::size_t i = 0; i < ring.theta_rad.size(); ++i) {
      const double diff = (ring.front_radius_m[i] - ring.reference_front_radius_m[i]) / ring.cell_m;
      rt.add_row({ring.theta_rad[i] * kDeg, ring.front_radius_m[i], ring.reference_front_radius_m[i], diff});
      lag -= diff / ring.theta_rad.size();
    }
    s.set_table("ring", rt);
    s.set("ring_spread_cells", ring.spread_m / ring.cell_m);
    s.set("ring_mean_lag_cells", lag);
    s.set("ring_cpu_s", ring.cpu_s);
    ticker->tick();
  }
  r.set("worst_measured_vs_semi_discrete", worst_semi);
  r.set("worst_measured_vs_fully_discrete", worst_fully);

  // The roundest stencil at the table's kd, and by how much.
  if (!used.empty()) {
    const Stencil* best = &used[0];
    for (const auto& st : used)
      if (phase_error_spread(st, io.table_kd) < phase_error_spread(*best, io.table_kd)) best = &st;
    const double ratio = baseline_spread / phase_error_spread(*best, io.table_kd);
    Record& v = r.child("roundest");
    v.set("stencil", best->name);
    v.set("ratio_to_baseline", ratio);
    v.set("why", "its phase-speed spread over direction at kd = " + num(io.table_kd / M_PI, 4) + "π is " +
                                num(phase_error_spread(*best, io.table_kd), 3) + ", " + num(ratio, 3) +
                                "× smaller than " + io.baseline_stencil + "'s " + num(baseline_spread, 3));
  }
  return r;
}

// ---- stability --------------------------------------------------------------------------------

Record wave_stability_findings(const WaveStudiesOptions& o, const ProgressFactory& progress) {
  const WaveStabilityOptions& so = o.stability;
  Record r;
  r.set("mu_dt_max", so.mu_dt_max);
  r.set("check_factor", so.check_factor);
  r.set("measured_tolerance", so.measured_tolerance);
  r.set("measured_steps", so.measured_steps);
  r.set("damping_independence_tolerance", so.damping_independence_tolerance);
  StabilityLimitOptions lo;
  r.set("wavenumbers", lo.wavenumbers);
  r.set_strings("stencils", o.stencils);
  auto ticker = start_progress(progress, "waves: stability", o.stencils.size() * (1 + so.check_mu_dt.size()));
  for (const auto& st : stencils_of(o)) {
    Record& s = r.child(st.name);
    Table c = table({"mu_dt", "sigma_limit"});
    double lo_lim = 1e300, hi_lim = -1e300;
    for (int i = 0; i < so.mu_dt_points; ++i) {
      const double mu_dt = so.mu_dt_max * i / (so.mu_dt_points - 1);
      const double lim = stability_limit(st, mu_dt, lo);
      c.add_row({mu_dt, lim});
      lo_lim = std::min(lo_lim, lim);
      hi_lim = std::max(hi_lim, lim);
    }
    s.set_table("limit_curve", c);
    s.set("limit_min", lo_lim);
    s.set("limit_max", hi_lim);
    s.set("limit_at_zero_damping", stability_limit(st, 0.0, lo));
    ticker->tick();
    Record in;
    in.set("limit_min", lo_lim);
    in.set("limit_max", hi_lim);
    in.set("tolerance", so.damping_independence_tolerance);
    decide_verdict(s, "damping", "limit_range", in,
                            "σ limit " + num(lo_lim, 7) + " … " + num(hi_lim, 7) + " over μΔt = 0 … " +
                                num(so.mu_dt_max, 3) + " (range " + num(hi_lim - lo_lim, 2) + ", tolerance " +
                                num(so.damping_independence_tolerance, 2) + ")");

    Table k = table({"mu_dt", "computed_limit", "measured_limit", "lengyel_bound", "growth_below", "ratio_below",
                     "growth_above", "ratio_above", "predicted_growth_above"});
    for (double mu_dt : so.check_mu_dt) {
      const double lim = stability_limit(st, mu_dt, lo);
      const GrowthRun below = run_growth(st, (1 - so.check_factor) * lim, mu_dt);
      const GrowthRun above = run_growth(st, (1 + so.check_factor) * lim, mu_dt);
      const double measured = measured_stability_limit(st, mu_dt, 0.9 * lim, 1.1 * lim, so.measured_tolerance,
                                                       so.measured_steps);
      k.add_row({mu_dt, lim, measured, lengyel_bound(mu_dt), below.growth_per_step, below.norm_ratio,
                 above.growth_per_step, above.norm_ratio,
                 max_amplification(st, (1 + so.check_factor) * lim, mu_dt)});
      ticker->tick();
    }
    s.set_table("checks", k);
  }
  // Lengyel's printed bound and its counter-example (model/README.md §2.2).
  const Stencil five = named_stencil("five_point");
  Record& l = r.child("lengyel");
  l.set("stencil", std::string("five_point"));
  l.set("sigma", so.lengyel_sigma);
  l.set("mu_dt", so.lengyel_mu_dt);
  l.set("bound", lengyel_bound(so.lengyel_mu_dt));
  const GrowthRun g = run_growth(five, so.lengyel_sigma, so.lengyel_mu_dt, 16, so.lengyel_steps);
  const double predicted = max_amplification(five, so.lengyel_sigma, so.lengyel_mu_dt);
  l.set("predicted_growth_per_step", predicted);
  l.set("measured_growth_per_step", g.growth_per_step);
  l.set("norm_ratio", g.norm_ratio);
  l.set("steps", g.steps);
  l.set("steps_run", g.steps_run);  // the run stops once its RMS passes 1e100: the prose's count
  Table bound = table({"mu_dt", "lengyel_bound"});
  for (int i = 0; i < so.mu_dt_points; ++i) {
    const double mu_dt = so.mu_dt_max * i / (so.mu_dt_points - 1);
    bound.add_row({mu_dt, lengyel_bound(mu_dt)});
  }
  l.set_table("bound_curve", bound);
  const bool inside = so.lengyel_sigma < lengyel_bound(so.lengyel_mu_dt);
  Record in;
  in.set("sigma", so.lengyel_sigma);
  in.set("bound", lengyel_bound(so.lengyel_mu_dt));
  in.set("predicted_growth_per_step", predicted);
  in.set("measured_growth_per_step", g.growth_per_step);
  decide_verdict(
      l, "verdict", "counterexample", in,
      "five-point at μΔt = " + num(so.lengyel_mu_dt, 3) + ", σ = " + num(so.lengyel_sigma, 3) +
          (inside ? " < " : " ≥ ") + num(lengyel_bound(so.lengyel_mu_dt), 4) + " (the bound); the worst mode grows ×" +
          num(predicted, 4) + " per step by its amplification factor and ×" + num(g.growth_per_step, 4) +
          " in a run from random noise");
  return r;
}

// ---- speed against error ----------------------------------------------------------------------

Record wave_speed_findings(const WaveStudiesOptions& o, const ProgressFactory& progress) {
  const WaveSpeedOptions& so = o.speed;
  WaveWorkPrecisionOptions wo = so.work;
  Record r;
  store_problem(r.child("problem"), wo.problem);
  r.set_table("grids", value_list(to_doubles(wo.grids)));
  r.set_table("sigma_fractions", value_list(wo.sigma_fractions));
  r.set("min_cpu_s", wo.min_cpu_s);
  r.set_table("targets_m", value_list(so.targets_m, "target_m"));
  r.set("baseline_stencil", so.baseline_stencil);
  r.set("material_gain", so.material_gain);
  r.set("clock", std::string("CPU time of the stepping thread"));
  r.set_strings("stencils", o.stencils);
  std::size_t total = 0;
  for (const auto& st : stencils_of(o)) {
    wo.stability_limit = stability_limit(st, 0.0);
    total += work_precision_work(wo);
  }
  auto ticker = start_progress(progress, "waves: speed against error", total);
  std::vector<std::pair<std::string, std::vector<WaveWorkPoint>>> all;
  std::vector<bool> consistent;
  for (const auto& st : stencils_of(o)) {
    wo.stability_limit = stability_limit(st, 0.0);
    const std::vector<WaveWorkPoint> pts = run_work_precision(st, wo, ticker.get());
    all.emplace_back(st.name, pts);
    consistent.push_back(analyse_consistency(st, o.consistency).consistent);
    Record& s = r.child(st.name);
    s.set("sigma_limit", wo.stability_limit);
    Table t = table({"n", "sigma", "steps", "l2_error_m", "max_error_m", "cpu_s"});
    double best = 1e300, rate = kNaN;
    int nmax = 0;
    for (const auto& w : pts) {
      t.add_row({double(w.n), w.sigma, double(w.steps), w.l2_m, w.max_m, w.cpu_s});
      best = std::min(best, w.l2_m);
      if (w.n >= nmax && w.cpu_s > 0) {
        nmax = w.n;
        rate = double(w.n) * w.n * w.steps / w.cpu_s;
      }
    }
    s.set_table("points", t);
    s.set("best_error_m", best);
    s.set("cell_updates_per_cpu_s_largest_grid", rate);
    Table reach = table({"target_m", "cpu_s"});
    for (double e : so.targets_m) reach.add_row({e, cpu_to_reach(pts, e)});
    s.set_table("cpu_to_reach", reach);
  }
  // Which stencil reaches each target first, and how much the best 8-neighbour consistent stencil
  // gains over the baseline at any target.
  Table winners = table({"target_m", "winner_index", "winner_cpu_s", "baseline_cpu_s"});
  double gain = kNaN;
  std::string gain_stencil;
  for (double e : so.targets_m) {
    int win = -1;
    double best = kNaN, base = kNaN;
    for (std::size_t i = 0; i < all.size(); ++i) {
      const double c = cpu_to_reach(all[i].second, e);
      if (all[i].first == so.baseline_stencil) base = c;
      if (!std::isnan(c) && (std::isnan(best) || c < best)) best = c, win = static_cast<int>(i);
    }
    winners.add_row({e, double(win), best, base});
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i].first == so.baseline_stencil || !consistent[i]) continue;
      const double c = cpu_to_reach(all[i].second, e);
      if (std::isnan(c) || std::isnan(base)) continue;
      if (std::isnan(gain) || base / c > gain) gain = base / c, gain_stencil = all[i].first;
    }
  }
  r.set_table("winners", winners);
  std::string reason;
  if (std::isnan(gain)) {
    reason = "no target error was reached both by " + so.baseline_stencil + " and by another consistent stencil";
  } else if (gain < so.material_gain) {
    reason = "the best of the others (" + gain_stencil + ") is at most " + num(gain, 3) + "× as fast as " +
             so.baseline_stencil + " at any target; below " + num(so.material_gain, 3) + "× counts as timing noise here";
  } else {
    reason = gain_stencil + " reaches a target " + num(gain, 3) + "× faster than " + so.baseline_stencil +
             " (threshold " + num(so.material_gain, 3) + "×)";
  }
  Record in;
  in.set("gain", gain);
  in.set("material_gain", so.material_gain);
  decide_verdict(r, "answer", "work_gain", in, reason);
  return r;
}

// ---- all --------------------------------------------------------------------------------------

Record run_wave_studies(const WaveStudiesOptions& o, StudySink& sink) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("wave study settings: " + why);
  const ProgressFactory& p = sink.progress();
  run_section(sink, "settings", [&] { return wave_settings_findings(o); });
  run_section(sink, "consistency", [&] { return wave_consistency_findings(o); });
  run_section(sink, "convergence", [&] { return wave_convergence_findings(o, p); });
  run_section(sink, "isotropy", [&] { return wave_isotropy_findings(o, p); });
  run_section(sink, "stability", [&] { return wave_stability_findings(o, p); });
  run_section(sink, "speed", [&] { return wave_speed_findings(o, p); });
  Record root;
  root.set("preset", o.preset);
  return root;
}

}  // namespace stoneskip
