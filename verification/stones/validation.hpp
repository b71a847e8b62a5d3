#pragma once
// Validation of the stone model against experiments and analytic models (model/README.md §3).
// Nothing here is tuned: each water law runs with its published C_w
// (model/stone/environment.hpp) and its values are set beside the measured ones; the difference
// is model-form error.
//
// The model variants are a list (validation_variants): the CVODE reference in the physical
// convention for every law × pressure distribution × attitude (held, free) of the study, the
// real-time stepper for the first law (uniform, free), the paper's printed equations (their own
// law, uniform, free), and the paper convention's real-time stepper for the seed's Fig. 9 only.
// Each table variant measures on Clanet's disk (Clanet, Hersen & Bocquet 2004; Rosellini et al.
// 2005): U_min against α (bisected), the largest bouncing β, contact time against U with its
// exponent, the spin regimes at α = regime_attack_deg, the surfing throw, the energy balance of
// each contact of the reference throw; and the largest bouncing path angle of a sphere (Johnson &
// Reid 1975). Bocquet's stone and the seed's throws only where the distribution is uniform and
// the attitude free (the variants a model-beside-model comparison needs). The cost of a throw is
// measured per reference variant (thread CPU time, minimum of repeats, both solvers).
#include <optional>
#include <string>
#include <vector>

#include "verification/convergence/order_fit.hpp"
#include "verification/convergence/power_law_shape.hpp"
#include "verification/stones/throw_history.hpp"
#include "verification/stones/throw_problem.hpp"
#include "verification/stones/validation_score.hpp"
#include "verification/study/progress.hpp"

namespace stoneskip {

// A measured (or otherwise expected) value the model is set beside (model/README.md §3), as its source states
// it; from the study file, stored with the findings, never typed into a report.
struct MeasuredValue {
  std::string key;        // the validation row: "clanet_min_speed", "bocquet_speed_exponent", ...
  std::string quantity;   // the row's words
  std::string measured;   // "≈ 2.5–2.6 m/s"
  std::string expected;   // the spec's independent 2-D reduction, or "–"
  std::string source;     // "Clanet, Hersen & Bocquet 2004"
  // The measured range in SI units (m/s, deg, s, or the bare exponent) when the row is scored in
  // the ranking; only the quantities of scorable_quantities() can be.
  std::optional<MeasuredRange> score;
  std::string score_unit;  // of the range, as a reader would say it ("m/s", "s", "deg", "" for exponents)
  // "measurement" (an experiment, read from its text, a figure or a secondary account: the quantity
  // or source says which) or "model" (another model's estimate: shown "model beside model", never scored).
  std::string kind = "measurement";
  // The peer simulator's value of the same quantity (ValidationOptions::peer_description), as its
  // source reports it; empty: none given.
  std::string peer;
};

// The rows whose model value is a number the ranking can score (validation_findings.cpp computes
// each): clanet_min_speed (m/s, at min_speed_attack_deg), clanet_best_attack (deg),
// clanet_max_path_angle (deg), clanet_contact_time (s, at contact_time_speed_m_s),
// clanet_contact_exponent, bocquet_speed_exponent (of N against V²), bocquet_spin_exponent (of N
// against Ω²).
const std::vector<std::string>& scorable_quantities();

// A measured curve set beside the model's, as data: the model curve it belongs with (only
// "clanet_min_speed": U_min against α at β = 20°), and per point x with the measured range.
struct MeasuredCurve {
  std::string key;
  std::string label;      // the legend: what the points are, honestly
  std::string source;
  std::vector<double> x, low, high;
};

// The bounds within which a variant "skips like a real stone": each row's
// measured value (the study file's [[validation.measured]] score range) widened by these.
struct SkipBounds {
  double min_speed_fraction = 0.10;     // U_min within 10 % of the measured range
  double best_attack_deg = 5;           // argmin α within 5°
  double max_path_angle_deg = 5;        // β_max within 5°
  double contact_time_fraction = 0.20;  // contact time within 20 %; its exponent's interval must contain the measured
  double attitude_deg = 5;              // pitch and roll change per contact at held_spin_rev_s
};

struct RankingOptions {
  double miss_distance = 2.302585092994046;  // ln 10: what a quantity the model cannot produce costs
  double held_spin_rev_s = 65;     // the regime in which Clanet et al. see the attack angle held
  SkipBounds bounds;
  int cost_repeats = 3;            // CPU time per throw: minimum over this many runs
  std::vector<std::string> cost_throws{"clanet", "seed_spin", "seed_nospin"};  // of cost_throw_names()
};

// The throws a law's cost can be measured on: Clanet's reference throw, the seed's two.
const std::vector<std::string>& cost_throw_names();

struct ValidationOptions {
  std::vector<WaterLaw> laws{WaterLaw::newtonian};  // the first is the default: real-time column, Fig. 9
  std::vector<PressureDistribution> distributions{PressureDistribution::uniform};  // of every physical law
  double reference_rtol = 1e-7;     // the model's value: accurate to far better than it matters here
  double speed_tolerance_m_s = 0.05;
  double angle_tolerance_deg = 0.5;
  std::vector<double> clanet_attack_deg{10, 15, 20, 25, 30, 35, 40};
  double clanet_speed_low_m_s = 0.5, clanet_speed_high_m_s = 8.0;
  std::vector<double> clanet_contact_speeds_m_s{2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0};
  std::vector<double> bocquet_speeds_m_s{4, 6, 8, 10, 12, 14, 16, 18};
  std::vector<double> bocquet_spins_rev_s{0, 5, 9, 14, 20, 30};
  std::vector<double> regime_spins_rev_s{0, 10, 65};  // Clanet's three spin regimes, at α = regime_attack_deg
  double regime_attack_deg = 35;
  double diving_spin_rev_s = 0;   // Rosellini et al.'s diving regime: no spin (one of regime_spins_rev_s)
  double trout_spin_rev_s = 10;   // ... the "trout": dips and still bounces (one of regime_spins_rev_s)
  double surfing_attack_deg = 30, surfing_path_angle_deg = 35;  // ... surfing: never leaves the water
  // Johnson & Reid 1975 (quoted by Nagahiro & Hayakawa 2005): a sphere of σ = ρ_s/ρ_w ricochets
  // below θ_max ≈ 18°/√σ, a limit of high Froude numbers.
  double sphere_radius_m = 0.01, sphere_density_ratio = 2.65, sphere_speed_m_s = 10;
  int sphere_subdivisions = 2;
  double sphere_theta_coefficient_deg = 18;  // Johnson & Reid's 18° (θ_max √σ)
  double contact_time_speed_m_s = 3.5;                // where a contact time is compared
  double min_speed_attack_deg = 20;                   // where a minimum speed is compared
  double contact_exponent_expected = -1;              // Rosellini et al.: τ ∝ 1/U
  double count_exponent_expected = 1;                 // Bocquet: N ∝ V², N ∝ Ω²
  double exponent_tolerance = 0.25;                   // the fitted exponents' interval must lie within this
  double history_dt_s = 1e-3;                         // stored histories: rows at least this far apart
  std::vector<MeasuredValue> measured;
  // Another simulator of the same experiments, whose reported values (MeasuredValue::peer) stand in
  // a column of their own beside the measured ones; empty: no peer column.
  std::string peer_description;
  std::vector<MeasuredCurve> curves;
  RankingOptions ranking;
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
  bool valid(std::string* why) const;
};

// table: measures everything above; seed_only: only the seed's two throws (for the paper's Fig. 9).
enum class VariantUse { table, seed_only };

struct ModelVariant {
  WaterLaw law = WaterLaw::newtonian;
  PressureDistribution distribution = PressureDistribution::uniform;
  Attitude attitude = Attitude::free;
  Convention convention = Convention::physical;
  SolverKind solver = SolverKind::reference;
  VariantUse use = VariantUse::table;
  // "planing_savitsky_wagner_held", "newtonian_uniform_free_realtime", "paper_reference", ...
  std::string key() const;
  // "planing, savitsky_wagner, held", "newtonian, uniform, free, real-time", "paper convention, reference"
  std::string title() const;
  // Bocquet's stone and the seed's throws: measured for uniform free variants only (cost).
  bool beside_models() const;
  bool ranked() const;  // the reference in the physical convention
};

// The variants of a study with these laws and distributions, in the order of the validation table.
std::vector<ModelVariant> validation_variants(const std::vector<WaterLaw>& laws,
                                              const std::vector<PressureDistribution>& distributions);

// The energy balance of one contact: the stone's mechanical energy change
// against the time integral of the fluids' power (trapezoidal, on samples `sample_dt_s` apart and
// the located events), and that integral's quadrature error estimated from every other sample.
struct ContactEnergy {
  double start_s = 0, end_s = 0;
  double energy_change_J = 0, work_J = 0, quadrature_error_J = 0;
  double energy_scale_J = 0;  // the largest |E| over the contact (what the integrator's rtol is relative to)
  int samples = 0;
};

// A value found by bisection on one throw parameter, for one variant.
struct BisectedValue {
  bool found = false;
  std::string note;     // why not found: "no bounce up to 8 m/s", ...
  bool bounces_at_both_ends = false;  // not found because it bounced at both ends of the bracket
  double lo = 0, hi = 0;
  double value() const { return 0.5 * (lo + hi); }
  int runs = 0;
};

struct VariantResult {
  ModelVariant variant;
  // Clanet's disk (table variants).
  std::vector<BisectedValue> min_speed;   // per attack angle of the options
  BisectedValue largest_path_angle;
  std::vector<double> contact_time_s;     // per contact speed: the first contact's, if it bounced (else NaN)
  OrderFit contact_time_fit;              // log τ against log U over the bouncing first contacts
  PowerLawShape contact_time_shape;       // whether one power law describes them at all
  std::vector<ThrowHistory> regimes;      // per regime spin, at α = regime_attack_deg
  ThrowHistory surfing;                   // α = surfing_attack_deg, β = surfing_path_angle_deg
  std::vector<ContactEnergy> energy;      // per contact of Clanet's reference throw (reference variants)
  double energy_rtol = 0;                 // the integrator's tolerance of that run
  BisectedValue sphere_path_angle;        // largest bouncing β of the sphere
  // Bocquet's stone (table variants).
  std::vector<int> count_vs_speed, count_vs_spin;
  OrderFit speed_fit, spin_fit;           // log N against log V², log Ω² (N > 0, V, Ω > 0)
  PowerLawShape speed_shape, spin_shape;
  // The seed's 8 m/s throws (every variant).
  ThrowHistory without_spin, with_spin;
  // Per contact of the seed's spinning throw (reference variants beside the models): the energy
  // balance the conventions' comparison judges on that throw, not on Clanet's.
  std::vector<ContactEnergy> with_spin_energy;
};

// The cost of a throw with one law (physical convention): thread CPU time, minimum over repeats.
struct ThrowCost {
  std::string throw_name;   // "clanet", "seed_spin", "seed_nospin"
  double reference_cpu_s = 0, realtime_cpu_s = 0;
  long reference_rhs_evaluations = 0, realtime_steps = 0;
};
struct LawCost {
  ModelVariant variant;
  std::vector<ThrowCost> throws;
  double mean_reference_cpu_s = 0, mean_realtime_cpu_s = 0;  // per throw
  // The law's own cost, apart from how long its throws last: per real-time step, per CVODE
  // right-hand side (means over the throws).
  double mean_realtime_cpu_per_step_s = 0, mean_reference_cpu_per_rhs_s = 0;
};

struct ValidationResult {
  std::vector<VariantResult> variants;   // in the order of validation_variants
  std::vector<LawCost> costs;            // per ranked variant, in the variants' order
  std::string sphere_stone;              // description of the sphere
  std::string bocquet_stone;             // description of the stone used
  std::vector<double> bocquet_speed_prediction, bocquet_spin_prediction;  // N_V shape and N_Ω (model/README.md §3)
  const VariantResult* find(WaterLaw law, Convention c, SolverKind s) const;  // nullptr if not run
};

// clanet: the aluminium-disk case; bocquet: a stone for Bocquet's example; without/with_spin:
// the seed's 8 m/s throws.
ValidationResult run_validation(const ThrowProblem& clanet, const ThrowProblem& bocquet, const ThrowProblem& without_spin,
                                const ThrowProblem& with_spin, const ValidationOptions& o);

}  // namespace stoneskip
