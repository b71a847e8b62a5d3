#include "verification/stones/validation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>

#include "model/stone/mass_properties.hpp"
#include "model/stone/rigid_body.hpp"
#include "verification/stones/bounce_sweep.hpp"
#include "verification/stones/parallel_runs.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEarlyLook_s = 0.5;  // solve_until_decided: the early look

SolverChoice reference_of(const ThrowProblem& p, double rtol, bool trajectory) {
  ReferenceOptions r = p.reference;
  r.rtol = rtol;
  r.atol = rtol * 1e-2;
  r.record_trajectory = trajectory;
  return reference_choice(r);
}

SolverChoice realtime_of(const ThrowProblem& p, bool trajectory) {
  RealtimeOptions r = p.realtime;
  r.record_trajectory = trajectory;
  return realtime_choice(r);
}

// The solver of a variant for a problem (the validation's rtol for the reference).
SolverChoice solver_of(const ModelVariant& v, const ThrowProblem& p, double rtol, bool trajectory) {
  return v.solver == SolverKind::reference ? reference_of(p, rtol, trajectory) : realtime_of(p, trajectory);
}

// The problem as a variant sees it: its law with the published C_w, its pressure distribution,
// attitude and convention.
ThrowProblem as_variant(const ThrowProblem& p, const ModelVariant& v) {
  ThrowProblem q = with_convention(p, v.convention);
  set_water_law(q.environment, v.law);
  q.environment.pressure_distribution = v.distribution;
  q.environment.attitude = v.attitude;
  return q;
}

// Clanet's problem with its stone replaced by a sphere of the options (no spin, no attack: a
// sphere has none that matters).
ThrowProblem sphere_problem(const ThrowProblem& clanet, const ValidationOptions& o) {
  ThrowProblem q = clanet;
  const Mesh m = make_icosphere(o.sphere_radius_m, o.sphere_subdivisions);
  const double rho = o.sphere_density_ratio * clanet.environment.water_density_kg_m3;
  char d[160];
  std::snprintf(d, sizeof d, "icosphere R=%g m, %zu triangles, density %g kg/m³ (σ = %g)", o.sphere_radius_m,
                m.triangles.size(), rho, o.sphere_density_ratio);
  q.stone = make_stone(m, mass_properties_from_density(m, rho), o.sphere_radius_m, d);
  q.label = d;
  ThrowParameters tp = q.parameters;
  tp.speed_m_s = o.sphere_speed_m_s;
  tp.spin_rev_s = 0;
  tp.attack_angle_deg = 0;
  tp.height_m = std::max(tp.height_m, 2 * o.sphere_radius_m);
  return with_parameters(q, tp);
}

// Sampling of the energy-balance run: fine enough that the trapezoidal rule's error over a
// contact of tens of ms is far below the integrator's tolerance (checked: the estimate is stored).
constexpr double kEnergySample_s = 2e-5;

// The energy balance of each contact of a throw (ContactEnergy), from a run sampled finely up to
// the early look.
std::vector<ContactEnergy> contact_energy(const ThrowProblem& p, double rtol) {
  ReferenceOptions r = p.reference;
  r.rtol = rtol;
  r.atol = rtol * 1e-2;
  r.record_trajectory = true;
  r.output_dt_s = kEnergySample_s;
  r.t_max_s = std::min(r.t_max_s, kEarlyLook_s);
  const ThrowResult res = solve(p, reference_choice(r));
  std::vector<ContactEnergy> out;
  for (const auto& c : res.contacts) {
    ContactEnergy e;
    e.start_s = c.start_s;
    e.end_s = c.end_s;
    std::vector<double> t, P, E;
    for (const auto& s : res.trajectory)
      if (s.t_s >= c.start_s && s.t_s <= c.end_s) {
        t.push_back(s.t_s);
        P.push_back(fluid_power_W(p.stone, p.environment, s.state));
        E.push_back(s.energy_J);
        e.energy_scale_J = std::max(e.energy_scale_J, std::abs(s.energy_J));
      }
    e.samples = static_cast<int>(t.size());
    if (t.size() < 3) continue;
    auto trapezoid = [&](std::size_t stride) {
      double w = 0;
      std::size_t i = 0;
      for (; i + stride < t.size(); i += stride) w += 0.5 * (P[i] + P[i + stride]) * (t[i + stride] - t[i]);
      if (i + 1 < t.size()) w += 0.5 * (P[i] + P.back()) * (t.back() - t[i]);
      return w;
    };
    e.work_J = trapezoid(1);
    e.quadrature_error_J = std::abs(trapezoid(2) - e.work_J);
    e.energy_change_J = E.back() - E.front();
    out.push_back(e);
  }
  return out;
}

ThrowProblem vary(const ThrowProblem& p, SweepParameter which, double value) {
  ThrowParameters tp = p.parameters;
  parameter_of(tp, which) = value;
  return with_parameters(p, tp);
}

int bounces(const ThrowProblem& p, const SolverChoice& s) { return solve(p, s).bounces; }

// The throw solved up to an early time first (kEarlyLook_s, or t_max if sooner), and again to
// t_max only when `decided` says that early part does not settle the question: the answer is the
// same as from the whole throw, without the seconds-long planing runs after a bounce.
ThrowResult solve_until_decided(const ThrowProblem& p, const SolverChoice& s,
                                const std::function<bool(const ThrowResult&)>& decided) {
  SolverChoice early = s;
  double& t_max = s.kind == SolverKind::realtime ? early.realtime.t_max_s : early.reference.t_max_s;
  if (t_max <= kEarlyLook_s) return solve(p, s);
  t_max = kEarlyLook_s;
  ThrowResult r = solve(p, early);
  return r.outcome != Outcome::time_limit || decided(r) ? r : solve(p, s);
}

// Whether the throw bounces at all: decided once it has bounced (the count never falls).
bool bounces_at_all(const ThrowProblem& p, const SolverChoice& s) {
  return solve_until_decided(p, s, [](const ThrowResult& r) { return r.bounces > 0; }).bounces > 0;
}

std::string fmt_value(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

// The smallest value of the parameter in [lo, hi] at which the throw bounces at least once
// (smallest = true), or the largest at which it still does, by bisection.
BisectedValue bisect_bounce(const ThrowProblem& p, const SolverChoice& s, SweepParameter which, double lo, double hi,
                            double tol, bool smallest, const std::string& unit) {
  BisectedValue b;
  const bool at_lo = bounces_at_all(vary(p, which, lo), s);
  const bool at_hi = bounces_at_all(vary(p, which, hi), s);
  b.runs = 2;
  if (smallest) {
    if (!at_hi) {
      b.note = "no bounce up to " + fmt_value(hi) + " " + unit;
      return b;
    }
    if (at_lo) {
      b.note = "bounces already at " + fmt_value(lo) + " " + unit;
      b.bounces_at_both_ends = true;
      b.lo = b.hi = lo;
      return b;
    }
  } else {
    if (!at_lo) {
      b.note = "no bounce even at " + fmt_value(lo) + " " + unit;
      return b;
    }
    if (at_hi) {
      b.note = "still bounces at " + fmt_value(hi) + " " + unit;
      b.bounces_at_both_ends = true;
      b.lo = b.hi = hi;
      return b;
    }
  }
  // Invariant: the bouncing side and the non-bouncing side bracket the change.
  while (hi - lo > tol) {
    const double mid = 0.5 * (lo + hi);
    const bool bounce = bounces_at_all(vary(p, which, mid), s);
    ++b.runs;
    if (bounce == at_lo)
      lo = mid;
    else
      hi = mid;
  }
  b.found = true;
  b.lo = lo;
  b.hi = hi;
  return b;
}

// Duration of the first contact when it ends in a bounce (Clanet's contact time is that of a
// bounce; a contact that ends in sinking is a planing run of another kind): NaN otherwise.
double first_contact_duration(const ThrowProblem& p, const SolverChoice& s) {
  // Decided once the first contact has ended (a contact still open at the early look is not).
  const ThrowResult r = solve_until_decided(p, s, [](const ThrowResult& e) {
    return e.contacts.size() > 1 || (e.contacts.size() == 1 && e.bounces > 0);
  });
  return r.contacts.empty() || !r.contacts[0].bounced ? kNaN : r.contacts[0].duration_s();
}

std::string history_label(const ThrowProblem& q, const ModelVariant& v) {
  char buf[200];
  const std::string model = v.convention == Convention::paper
                                ? "paper"
                                : std::string("physical ") + to_string(v.law) + ", " + to_string(v.distribution) + ", " +
                                      to_string(v.attitude);
  std::snprintf(buf, sizeof buf, "%g m/s, %g rev/s, %s, %s", q.parameters.speed_m_s, q.parameters.spin_rev_s, model.c_str(),
                v.solver == SolverKind::realtime ? "real-time" : "reference");
  return buf;
}

// Least-squares exponent of y against x over the points with x > 0 and y > 0 (95 % interval).
OrderFit exponent_fit(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> xs, ys;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(y[i])) {
      xs.push_back(x[i]);
      ys.push_back(y[i]);
    }
  OrderFit f = fit_order(xs, ys);
  if (!f.valid) f.problem = std::to_string(xs.size()) + (xs.size() == 1 ? " point" : " points") + " with a positive value";
  return f;
}

std::vector<double> squares(const std::vector<double>& v) {
  std::vector<double> out;
  for (double x : v) out.push_back(x * x);
  return out;
}

std::vector<double> as_doubles(const std::vector<int>& v) { return {v.begin(), v.end()}; }

}  // namespace

const std::vector<std::string>& scorable_quantities() {
  static const std::vector<std::string> k{"clanet_min_speed",        "clanet_best_attack",     "clanet_max_path_angle",
                                          "clanet_contact_time",     "clanet_contact_exponent", "bocquet_speed_exponent",
                                          "bocquet_spin_exponent"};
  return k;
}

const std::vector<std::string>& cost_throw_names() {
  static const std::vector<std::string> k{"clanet", "seed_spin", "seed_nospin"};
  return k;
}

bool ValidationOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (laws.empty()) return fail("validation needs at least one water law");
  if (std::set<WaterLaw>(laws.begin(), laws.end()).size() != laws.size()) return fail("validation laws repeat");
  if (distributions.empty()) return fail("validation needs at least one pressure distribution");
  if (std::set<PressureDistribution>(distributions.begin(), distributions.end()).size() != distributions.size())
    return fail("validation distributions repeat");
  // The model-beside-model rows, the conventions' comparison and Fig. 9 use the uniform free variant.
  if (std::find(distributions.begin(), distributions.end(), PressureDistribution::uniform) == distributions.end())
    return fail("validation distributions must include uniform (the model-beside-model rows and Fig. 9 use it)");
  for (double w : {diving_spin_rev_s, trout_spin_rev_s})
    if (std::find(regime_spins_rev_s.begin(), regime_spins_rev_s.end(), w) == regime_spins_rev_s.end())
      return fail("validation diving_spin_rev_s and trout_spin_rev_s must be among regime_spins_rev_s");
  if (!(sphere_radius_m > 0) || !(sphere_density_ratio > 0) || !(sphere_speed_m_s > 0) || sphere_subdivisions < 0 ||
      sphere_subdivisions > 5)
    return fail("validation sphere: radius, density ratio and speed positive, subdivisions 0-5");
  if (clanet_attack_deg.empty() || clanet_contact_speeds_m_s.empty() || bocquet_speeds_m_s.empty() ||
      bocquet_spins_rev_s.empty() || regime_spins_rev_s.empty())
    return fail("validation grids must not be empty");
  if (std::find(regime_spins_rev_s.begin(), regime_spins_rev_s.end(), ranking.held_spin_rev_s) == regime_spins_rev_s.end())
    return fail("validation ranking held_spin_rev_s must be one of regime_spins_rev_s");
  const SkipBounds& b = ranking.bounds;
  if (!(ranking.miss_distance > 0) || !(b.min_speed_fraction >= 0) || !(b.best_attack_deg >= 0) ||
      !(b.max_path_angle_deg >= 0) || !(b.contact_time_fraction >= 0) || !(b.attitude_deg >= 0) || ranking.cost_repeats < 1)
    return fail("validation ranking bounds must be non-negative and cost_repeats >= 1");
  for (const auto& m : measured)
    if (m.kind != "measurement" && m.kind != "model")
      return fail("validation measured '" + m.key + "': kind must be measurement or model");
  if (ranking.cost_throws.empty()) return fail("validation ranking needs at least one cost throw");
  for (const auto& n : ranking.cost_throws)
    if (std::find(cost_throw_names().begin(), cost_throw_names().end(), n) == cost_throw_names().end())
      return fail("validation ranking cost throw '" + n + "' is not one of clanet, seed_spin, seed_nospin");
  std::set<std::string> keys;
  for (const auto& m : measured) {
    if (!keys.insert(m.key).second) return fail("validation measured key '" + m.key + "' repeats");
    if (!m.score) continue;
    const auto& s = scorable_quantities();
    if (std::find(s.begin(), s.end(), m.key) == s.end())
      return fail("validation measured '" + m.key + "' has a score range but is not a scorable quantity");
    if (!(m.score->low <= m.score->high) || !(m.score->low * m.score->high > 0))
      return fail("validation measured '" + m.key + "': score_low <= score_high, both non-zero and of one sign");
  }
  for (const auto& c : curves) {
    if (c.key != "clanet_min_speed") return fail("validation curve '" + c.key + "' is not clanet_min_speed");
    if (c.x.empty() || c.x.size() != c.low.size() || c.x.size() != c.high.size())
      return fail("validation curve '" + c.label + "': x, low and high need one value per point");
    for (std::size_t i = 0; i < c.x.size(); ++i)
      if (!(c.low[i] <= c.high[i])) return fail("validation curve '" + c.label + "': low > high");
  }
  return true;
}

std::string ModelVariant::key() const {
  if (convention == Convention::paper) return solver == SolverKind::realtime ? "paper_realtime" : "paper_reference";
  return std::string(to_string(law)) + "_" + to_string(distribution) + "_" + to_string(attitude) +
         (solver == SolverKind::realtime ? "_realtime" : "");
}

std::string ModelVariant::title() const {
  if (convention == Convention::paper) return solver == SolverKind::realtime ? "paper convention, real-time" : "paper convention, reference";
  return std::string(to_string(law)) + ", " + to_string(distribution) + ", " + to_string(attitude) +
         (solver == SolverKind::realtime ? ", real-time" : "");
}

bool ModelVariant::beside_models() const {
  return distribution == PressureDistribution::uniform && attitude == Attitude::free;
}

bool ModelVariant::ranked() const { return convention == Convention::physical && solver == SolverKind::reference; }

std::vector<ModelVariant> validation_variants(const std::vector<WaterLaw>& laws,
                                              const std::vector<PressureDistribution>& distributions) {
  std::vector<ModelVariant> v;
  for (WaterLaw law : laws)
    for (PressureDistribution d : distributions)
      for (Attitude a : {Attitude::held, Attitude::free})
        v.push_back({law, d, a, Convention::physical, SolverKind::reference, VariantUse::table});
  if (!laws.empty())
    v.push_back({laws.front(), PressureDistribution::uniform, Attitude::free, Convention::physical, SolverKind::realtime,
                 VariantUse::table});
  // The paper's printed equations have one law, their Eq. 2, uniform (environment_problem refuses others).
  v.push_back({WaterLaw::newtonian, PressureDistribution::uniform, Attitude::free, Convention::paper, SolverKind::reference,
               VariantUse::table});
  v.push_back({WaterLaw::newtonian, PressureDistribution::uniform, Attitude::free, Convention::paper, SolverKind::realtime,
               VariantUse::seed_only});
  return v;
}

const VariantResult* ValidationResult::find(WaterLaw law, Convention c, SolverKind s) const {
  for (const auto& v : variants)
    if ((c == Convention::paper || (v.variant.law == law && v.variant.beside_models())) && v.variant.convention == c &&
        v.variant.solver == s)
      return &v;
  return nullptr;
}

ValidationResult run_validation(const ThrowProblem& clanet, const ThrowProblem& bocquet, const ThrowProblem& without_spin,
                                const ThrowProblem& with_spin, const ValidationOptions& o) {
  ValidationResult res;
  const std::vector<ModelVariant> variants = validation_variants(o.laws, o.distributions);
  const ThrowProblem sphere = sphere_problem(clanet, o);
  res.sphere_stone = sphere.stone.description;
  res.variants.resize(variants.size());
  std::vector<std::function<void()>> jobs;
  const double rtol = o.reference_rtol;

  for (std::size_t k = 0; k < variants.size(); ++k) {
    const ModelVariant& v = variants[k];
    VariantResult& R = res.variants[k];
    R.variant = v;
    // The seed's 8 m/s throws, with their histories (uniform free variants and the paper's).
    for (const auto* seed : {&without_spin, &with_spin}) {
      if (!v.beside_models()) continue;
      ThrowHistory& out = seed == &without_spin ? R.without_spin : R.with_spin;
      jobs.push_back([&, seed, &out = out] {
        const ThrowProblem q = as_variant(*seed, v);
        out = make_history(q, solve(q, solver_of(v, q, rtol, true)), history_label(q, v));
      });
    }
    if (v.beside_models() && v.solver == SolverKind::reference)
      jobs.push_back([&] { R.with_spin_energy = contact_energy(as_variant(with_spin, v), rtol); });
    if (v.use != VariantUse::table) continue;

    // Clanet: minimum bouncing speed against attack angle (β from the case), largest β.
    const ThrowProblem C = as_variant(clanet, v);
    const SolverChoice Cs = solver_of(v, C, rtol, false);
    R.min_speed.resize(o.clanet_attack_deg.size());
    for (std::size_t i = 0; i < o.clanet_attack_deg.size(); ++i)
      jobs.push_back([&, C, Cs, i] {
        R.min_speed[i] = bisect_bounce(vary(C, SweepParameter::attack_angle_deg, o.clanet_attack_deg[i]), Cs,
                                       SweepParameter::speed_m_s, o.clanet_speed_low_m_s, o.clanet_speed_high_m_s,
                                       o.speed_tolerance_m_s, true, "m/s");
      });
    jobs.push_back([&, C, Cs] {
      R.largest_path_angle = bisect_bounce(C, Cs, SweepParameter::path_angle_deg, 5.0, 80.0, o.angle_tolerance_deg, false, "deg");
    });
    // Contact time against speed.
    R.contact_time_s.assign(o.clanet_contact_speeds_m_s.size(), kNaN);
    for (std::size_t i = 0; i < o.clanet_contact_speeds_m_s.size(); ++i)
      jobs.push_back([&, C, Cs, i] {
        R.contact_time_s[i] = first_contact_duration(vary(C, SweepParameter::speed_m_s, o.clanet_contact_speeds_m_s[i]), Cs);
      });
    // The spin regimes at α = regime_attack_deg (Clanet et al.: tumbles / dips and recovers / held).
    R.regimes.resize(o.regime_spins_rev_s.size());
    for (std::size_t i = 0; i < o.regime_spins_rev_s.size(); ++i)
      jobs.push_back([&, C, i] {
        const ThrowProblem q = vary(vary(C, SweepParameter::attack_angle_deg, o.regime_attack_deg), SweepParameter::spin_rev_s,
                                    o.regime_spins_rev_s[i]);
        R.regimes[i] = make_history(q, solve(q, solver_of(v, q, rtol, true)), history_label(q, v));
      });
    // Rosellini et al.'s surfing throw (the case's spin).
    jobs.push_back([&, C] {
      const ThrowProblem q =
          vary(vary(C, SweepParameter::attack_angle_deg, o.surfing_attack_deg), SweepParameter::path_angle_deg, o.surfing_path_angle_deg);
      R.surfing = make_history(q, solve(q, solver_of(v, q, rtol, true)), history_label(q, v));
    });
    // The energy balance of each contact of the reference throw (the reference's own run).
    if (v.solver == SolverKind::reference)
      jobs.push_back([&, C] {
        R.energy = contact_energy(C, rtol);
        R.energy_rtol = rtol;
      });
    // Johnson & Reid's sphere: the largest path angle that still bounces.
    {
      const ThrowProblem S = as_variant(sphere, v);
      const SolverChoice Ss = solver_of(v, S, rtol, false);
      jobs.push_back([&, S, Ss] {
        R.sphere_path_angle = bisect_bounce(S, Ss, SweepParameter::path_angle_deg, 1.0, 60.0, o.angle_tolerance_deg, false, "deg");
      });
    }
    if (!v.beside_models()) continue;

    // Bocquet: count against V and Ω.
    const ThrowProblem B = as_variant(bocquet, v);
    const SolverChoice Bs = solver_of(v, B, rtol, false);
    R.count_vs_speed.assign(o.bocquet_speeds_m_s.size(), 0);
    R.count_vs_spin.assign(o.bocquet_spins_rev_s.size(), 0);
    for (std::size_t i = 0; i < o.bocquet_speeds_m_s.size(); ++i)
      jobs.push_back([&, B, Bs, i] { R.count_vs_speed[i] = bounces(vary(B, SweepParameter::speed_m_s, o.bocquet_speeds_m_s[i]), Bs); });
    for (std::size_t i = 0; i < o.bocquet_spins_rev_s.size(); ++i)
      jobs.push_back([&, B, Bs, i] { R.count_vs_spin[i] = bounces(vary(B, SweepParameter::spin_rev_s, o.bocquet_spins_rev_s[i]), Bs); });
  }

  // The cost of a throw with each law, both solvers (thread CPU time: the other worker's runs do
  // not count, though they share the caches).
  struct CostThrowSpec {
    const char* name;
    const ThrowProblem* problem;
  };
  const CostThrowSpec known[] = {{"clanet", &clanet}, {"seed_spin", &with_spin}, {"seed_nospin", &without_spin}};
  std::vector<CostThrowSpec> cost_throws;
  for (const auto& name : o.ranking.cost_throws)
    for (const auto& k : known)
      if (name == k.name) cost_throws.push_back(k);
  std::vector<ModelVariant> ranked;
  for (const auto& v : variants)
    if (v.use == VariantUse::table && v.ranked()) ranked.push_back(v);
  res.costs.resize(ranked.size());
  for (std::size_t l = 0; l < ranked.size(); ++l) {
    LawCost& L = res.costs[l];
    L.variant = ranked[l];
    L.throws.resize(cost_throws.size());
    for (std::size_t t = 0; t < cost_throws.size(); ++t) {
      L.throws[t].throw_name = cost_throws[t].name;
      jobs.push_back([&, l, t] {
        const ModelVariant& ref = res.costs[l].variant;
        const ThrowProblem q = as_variant(*cost_throws[t].problem, ref);
        const ThrowResult r = solve_min_cpu(q, reference_of(q, rtol, false), o.ranking.cost_repeats);
        res.costs[l].throws[t].reference_cpu_s = r.stats.cpu_s;
        res.costs[l].throws[t].reference_rhs_evaluations = r.stats.rhs_evaluations;
        const ThrowResult s = solve_min_cpu(q, realtime_of(q, false), o.ranking.cost_repeats);
        res.costs[l].throws[t].realtime_cpu_s = s.stats.cpu_s;
        res.costs[l].throws[t].realtime_steps = s.stats.steps;
      });
    }
  }

  run_jobs(jobs, ParallelOptions{o.workers, "stones: validation", o.progress});

  // Fits, predictions, means.
  for (auto& R : res.variants) {
    if (R.variant.use != VariantUse::table) continue;
    R.contact_time_fit = exponent_fit(o.clanet_contact_speeds_m_s, R.contact_time_s);
    R.contact_time_shape = test_power_law_shape(o.clanet_contact_speeds_m_s, R.contact_time_s);
    if (!R.variant.beside_models()) continue;
    R.speed_fit = exponent_fit(squares(o.bocquet_speeds_m_s), as_doubles(R.count_vs_speed));
    R.spin_fit = exponent_fit(squares(o.bocquet_spins_rev_s), as_doubles(R.count_vs_spin));
    R.speed_shape = test_power_law_shape(squares(o.bocquet_speeds_m_s), as_doubles(R.count_vs_speed));
    R.spin_shape = test_power_law_shape(squares(o.bocquet_spins_rev_s), as_doubles(R.count_vs_spin));
  }
  for (auto& L : res.costs) {
    for (const auto& t : L.throws) {
      L.mean_reference_cpu_s += t.reference_cpu_s / double(L.throws.size());
      L.mean_realtime_cpu_s += t.realtime_cpu_s / double(L.throws.size());
      L.mean_realtime_cpu_per_step_s += t.realtime_cpu_s / double(std::max(1L, t.realtime_steps)) / double(L.throws.size());
      L.mean_reference_cpu_per_rhs_s +=
          t.reference_cpu_s / double(std::max(1L, t.reference_rhs_evaluations)) / double(L.throws.size());
    }
  }
  {
    // Bocquet 2003: N_V = V² / (2 μ g ℓ) needs his friction μ; we show the shape V² scaled to
    // N_Ω at the base speed instead, and N_Ω ≈ R Ω² / g in absolute terms.
    res.bocquet_stone = bocquet.stone.description;
    const double R = bocquet.stone.disk_radius_m, g = bocquet.environment.gravity_m_s2;
    for (double w : o.bocquet_spins_rev_s) {
      const double omega = 2 * std::numbers::pi * w;
      res.bocquet_spin_prediction.push_back(R * omega * omega / g);
    }
    const double V0 = bocquet.parameters.speed_m_s;
    const double N_ref = R * std::pow(2 * std::numbers::pi * bocquet.parameters.spin_rev_s, 2) / g;
    for (double V : o.bocquet_speeds_m_s) res.bocquet_speed_prediction.push_back(N_ref * (V * V) / (V0 * V0));
  }
  return res;
}

}  // namespace stoneskip
