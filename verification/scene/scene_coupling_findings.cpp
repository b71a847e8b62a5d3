#include "verification/scene/scene_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

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


}  // namespace

// ---- coupling ---------------------------------------------------------------------------------

Record scene_coupling_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  Record out;
  std::vector<std::string> names;
  auto ticker = start_progress(progress, "scene: coupling", 3 * o.cases.size());
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
    } else {
      why = "the stone never touched the water";
    }
    r.set("why", why);
    const long count_change = std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b);
    std::ostringstream reason;
    reason << "two-way: " << counted(d.contacts_a, "contact") << " (" << counted(d.bounces_a, "bounce") << ") in " << num(two.end_s(), 3)
           << " s against one-way's " << d.contacts_b << " (" << d.bounces_b << "); over " << (d.common == 1 ? "the first contact" : "the first " + counted(d.common, "contact"))
           << " the times differ by up to "
           << duration(std::max(d.max_start_change_s, d.max_end_change_s)) << " and the first touches by up to " << length(d.max_touch_change_m);
    Record in;
    in.set("count_change", static_cast<double>(count_change));
    in.set("max_time_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    in.set("time_tolerance_s", o.coupling.time_tolerance_s);
    decide_verdict(r, "verdict", "coupling_change", in, reason.str());
  }
  out.set_strings("cases", names);
  out.set("time_tolerance_s", o.coupling.time_tolerance_s);
  return out;
}

}  // namespace stoneskip
