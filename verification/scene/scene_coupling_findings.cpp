#include "verification/scene/scene_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "verification/study/ensemble_difference.hpp"
#include "verification/scene/scene_findings_support.hpp"
#include "verification/scene/scene_probe.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

using namespace scene_findings;

namespace {

Table contacts_table(const ThrowResult& r) {
  Table t = table({"start_s", "end_s", "touch_x_m", "touch_y_m", "exit_speed_m_s", "bounced"});
  for (const auto& c : r.contacts)
    t.add_row({c.start_s, c.end_s, c.first_touch_m.x(), c.first_touch_m.y(), c.exit_speed_m_s, c.bounced ? 1.0 : 0.0});
  return t;
}


// What the water received against what the stone received, and the waves' energy budget, for one
// forcing of the two-way scene (model/README.md §2.4; solvers/scene/wave_energy.hpp).
void store_forcing(Record& k, const SceneSummary& s) {
  k.set("stone_vertical_impulse_N_s", s.stone_vertical_impulse_N_s);
  k.set("water_vertical_impulse_N_s", s.water_vertical_impulse_N_s);
  k.set("water_impulse_pending_N_s", s.water_impulse_pending_N_s);  // pressure: held for steps past the end
  k.set("impulse_ratio", s.stone_vertical_impulse_N_s != 0 ? s.water_vertical_impulse_N_s / s.stone_vertical_impulse_N_s : kNaN);
  k.set("energy_measured", s.energy.measured);
  k.set("wave_energy_start_J", s.energy.start_J);
  k.set("wave_energy_end_J", s.energy.end_J);
  k.set("pressure_work_J", s.energy.pressure_work_J);
  k.set("damping_loss_J", s.energy.damping_loss_J);
  k.set("energy_budget_residual", s.energy.measured ? s.energy.residual() : kNaN);
  k.set("grid_scale_energy_fraction", s.energy.measured ? s.energy.grid_scale_fraction : kNaN);
  Table t = table({"start_s", "end_s", "stone_N_s", "water_N_s"});
  for (const auto& c : s.contact_impulses) t.add_row({c.start_s, c.end_s, c.stone_N_s, c.water_N_s});
  k.set_table("contact_impulses", t);
  k.set("bounces", s.stone.bounces);
}

// The bounce counts of an ensemble of throws of one setting, each run only as long as its throw
// and no longer than the scene (the contacts table beside it stops there: a quick report's 0.6 s
// scene once had members counted over the throw's own 3 s); a throw whose solve failed has no
// count: NaN (its bounces until the failure are not its count).
std::vector<double> ensemble_bounces(SceneOptions s, const std::vector<double>& factors) {
  s.stone_steps.t_max_s = std::min(s.stone_steps.t_max_s, s.end_s());
  s.end = SceneEnd::with_the_throw;
  std::vector<double> out;
  for (double f : factors) {
    SceneOptions t = s;
    t.initial.velocity_m_s *= f;  // the speed, relatively; direction and spin kept
    const ThrowResult r = run_scene(t).stone;
    out.push_back(r.outcome == Outcome::failed ? std::nan("") : static_cast<double>(r.bounces));
  }
  return out;
}

// The counts that exist (NaN: a failed run), and how many did not.
std::vector<double> counted_runs(const std::vector<double>& counts, long& failed) {
  std::vector<double> out;
  failed = 0;
  for (double c : counts) {
    if (std::isnan(c)) ++failed;
    else out.push_back(c);
  }
  return out;
}

}  // namespace

// ---- coupling ---------------------------------------------------------------------------------

Record scene_coupling_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  Record out;
  std::vector<std::string> names;
  const std::vector<double> factors =
      perturbation_factors(o.coupling.ensemble_members, o.coupling.perturbation_smallest, o.coupling.perturbation_largest);
  auto ticker = start_progress(progress, "scene: coupling", (4 + 2 * factors.size()) * o.cases.size());
  for (const auto& c : o.cases) {
    names.push_back(c.name);
    SceneOptions two = capped(o, c.scene), one = two, none = two;
    two.coupling = Coupling::two_way;
    one.coupling = Coupling::one_way;
    none.coupling = Coupling::none;
    const ProbedScene a = run_probed(two, 0, 1);
    ticker->tick();
    const ProbedScene b = run_probed(one, 0, 1);
    ticker->tick();
    const ProbedScene n = run_probed(none, 0, 1);
    ticker->tick();
    // The two forcings side by side, with the energy budget (model/README.md §2.4).
    SceneOptions pressed = two, displaced = two;
    pressed.forcing = Forcing::pressure;
    displaced.forcing = Forcing::displacement;
    pressed.energy_budget = displaced.energy_budget = true;
    const SceneSummary fp = run_scene(pressed);
    const SceneSummary fd = run_scene(displaced);
    ticker->tick();
    Record& r = out.child(c.name);
    store_scene_settings(r.child("settings"), c, two);
    const double radius = two.stone.disk_radius_m, cw = two.water->field.wave_speed_m_s;
    r.set("footprint_time_s", 2 * radius / cw);
    for (const auto& [key, p] : {std::pair<const char*, const ProbedScene*>{"two_way", &a}, {"one_way", &b}, {"none", &n}}) {
      Record& k = r.child(key);
      k.set_table("contacts", contacts_table(p->summary.stone));
      k.set("contact_count", static_cast<long>(p->summary.stone.contacts.size()));
      k.set("bounces", p->summary.stone.bounces);
      k.set("outcome", std::string(to_string(p->summary.stone.outcome)));
      k.set("end_time_s", p->summary.stone.end_time_s);
      k.set("distance_m", p->summary.stone.distance_m);
    }
    store_forcing(r.child("forcing").child("pressure"), fp);
    store_forcing(r.child("forcing").child("displacement"), fd);
    r.child("forcing").set("scene_forcing", std::string(to_string(two.forcing)));
    const SceneDifference d = compare_scenes(a, b);
    const SceneDifference still = compare_scenes(b, n);
    r.set("one_way_equals_still", still.identical());
    r.set("max_start_change_s", d.max_start_change_s);
    r.set("max_end_change_s", d.max_end_change_s);
    r.set("max_touch_change_m", d.max_touch_change_m);
    r.set("first_exit_speed_change_m_s", d.first_contact_exit_speed_change_m_s);
    // Why they differ: the draught and the water under the stone, contact by contact.
    Table e = table({"start_s", "end_s", "max_volume_m3", "volume_time_m3_s", "surface_at_start_m", "lowest_surface_m"});
    for (const auto& x : a.summary.episodes)
      e.add_row({x.start_s, x.end_s, x.max_volume_m3, x.volume_time_m3_s, x.surface_at_start_m, x.lowest_surface_m});
    r.set_table("draught_episodes", e);
    r.set("max_draught_volume_m3", a.summary.max_draught_volume_m3);
    r.set("water_volume_change_m3", a.summary.volume_end_m3 - a.summary.volume_start_m3);
    const auto& ca = a.summary.stone.contacts;
    std::string why;
    if (!ca.empty() && !a.summary.episodes.empty()) {
      const DraughtEpisode& first = a.summary.episodes.front();
      const double duration = ca.front().end_s - ca.front().start_s;
      const double depression = first.surface_at_start_m - first.lowest_surface_m;
      const double mean_draught = first.max_volume_m3 / (M_PI * radius * radius);
      r.set("first_contact_duration_s", duration);
      r.set("first_depression_m", depression);
      r.set("first_mean_draught_m", mean_draught);
      why = "the first contact lasts " + ms(duration) + ", " + num(duration / (2 * radius / cw), 2) +
            " of the time footprint/c = " + num(2 * radius / cw, 3) + " s in which the water under the stone can answer it (model/README.md §2.4): the stone's draught (up to " +
            num(1e6 * first.max_volume_m3, 3) + " cm³, " + mm(mean_draught) + " deep over its disk) lowered the water under its centre by " +
            mm(depression) + " before it left";
      double worst = 0;
      std::size_t at = 0;
      for (std::size_t k = 0; k < a.summary.episodes.size(); ++k) {
        const auto& x = a.summary.episodes[k];
        if (x.surface_at_start_m - x.lowest_surface_m > worst) {
          worst = x.surface_at_start_m - x.lowest_surface_m;
          at = k;
        }
      }
      if (a.summary.episodes.size() > 1)
        why += "; the deepest depression under the stone in any contact was " + mm(worst) + " (contact " + std::to_string(at + 1) + " of " +
               std::to_string(a.summary.episodes.size()) + ")";
      if (d.common > 0)
        why += "; after the first contact the two runs leave at speeds " + num(d.first_contact_exit_speed_change_m_s, 2) + " m/s apart";
    } else if (!ca.empty() && !a.summary.contact_impulses.empty()) {
      const ContactImpulse& first = a.summary.contact_impulses.front();
      const double duration = ca.front().end_s - ca.front().start_s;
      r.set("first_contact_duration_s", duration);
      why = "the first contact lasts " + ms(duration) + ", " + num(duration / (2 * radius / cw), 2) +
            " of the time footprint/c = " + num(2 * radius / cw, 3) + " s in which the water under the stone can answer it (model/README.md §2.4); "
            "the stone pressed on the water with " + num(first.stone_N_s, 3) + " N s of vertical impulse over " + ms(first.end_s - first.start_s) +
            " (" + counted(static_cast<long>(a.summary.contact_impulses.size()), "pressing") + " in all)";
    } else {
      why = "the stone never touched the water";
    }
    r.set("why", why);
    // The bounce counts on ensembles of perturbed throws (a chaotic count is not compared run
    // against run); the first contact, which precedes any decorrelation, run against run.
    const std::vector<double> counts_two = ensemble_bounces(two, factors);
    for (std::size_t k = 0; k < factors.size(); ++k) ticker->tick();
    const std::vector<double> counts_one = ensemble_bounces(one, factors);
    for (std::size_t k = 0; k < factors.size(); ++k) ticker->tick();
    long failed_two = 0, failed_one = 0;
    const MeanDifference md = welch_difference(counted_runs(counts_two, failed_two), counted_runs(counts_one, failed_one));
    Table ens = table({"speed_factor", "two_way_bounces", "one_way_bounces"});
    for (std::size_t k = 0; k < factors.size(); ++k) ens.add_row({factors[k], counts_two[k], counts_one[k]});
    Record& er = r.child("ensemble");
    er.set_table("members", ens);
    er.set("members_per_setting", static_cast<long>(factors.size()));
    er.set("horizon_s", std::min(two.stone_steps.t_max_s, two.end_s()));
    er.set("perturbation_smallest", o.coupling.perturbation_smallest);
    er.set("perturbation_largest", o.coupling.perturbation_largest);
    er.set("mean_two_way", md.mean_a);
    er.set("mean_one_way", md.mean_b);
    er.set("sd_two_way", md.sd_a);
    er.set("sd_one_way", md.sd_b);
    er.set("difference", md.difference);
    er.set("difference_low", md.low);
    er.set("difference_high", md.high);
    er.set("failed_two_way", failed_two);
    er.set("failed_one_way", failed_one);
    const auto& cb = b.summary.stone.contacts;
    double first_change = 0;
    if (!ca.empty() && !cb.empty())
      first_change = std::max(std::abs(ca.front().start_s - cb.front().start_s), std::abs(ca.front().end_s - cb.front().end_s));
    else if (ca.empty() != cb.empty())
      first_change = std::numeric_limits<double>::infinity();
    std::ostringstream reason;
    reason << "bounces over " << factors.size() << " throws each, each counted up to the scene's end at "
           << duration(std::min(two.stone_steps.t_max_s, two.end_s())) << " (speed × 1 ± 1e" << num(std::log10(o.coupling.perturbation_smallest), 2)
           << " … 1e" << num(std::log10(o.coupling.perturbation_largest), 2) << "): two-way " << num(md.mean_a, 3) << " ± " << num(md.sd_a, 2)
           << ", one-way " << num(md.mean_b, 3) << " ± " << num(md.sd_b, 2) << " (mean ± sd); difference " << num(md.difference, 3)
           << ", 95 % interval [" << num(md.low, 3) << ", " << num(md.high, 3) << "] (Welch; " << failed_two << " and "
           << failed_one << " runs failed); the first contact's times differ by "
           << duration(first_change);
    Record in;
    in.set("difference_low", md.low);
    in.set("difference_high", md.high);
    in.set("count_spread", md.sd_a + md.sd_b);
    in.set("exact_p", md.exact_p);  // no spread: the exact permutation test (ensemble_difference.hpp)
    in.set("alpha", md.alpha);
    in.set("failed_runs", failed_two + failed_one);
    in.set("max_time_change_s", first_change);
    in.set("time_tolerance_s", o.coupling.time_tolerance_s);
    decide_verdict(r, "verdict", "coupling_change", in, reason.str());
  }
  out.set_strings("cases", names);
  out.set("time_tolerance_s", o.coupling.time_tolerance_s);
  return out;
}

}  // namespace stoneskip
