#include "verification/scene/scene_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "verification/scene/scene_findings_support.hpp"
#include "verification/scene/scene_probe.hpp"
#include "verification/scene/scene_shortcut_variants.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

using namespace scene_findings;

// ---- shortcuts --------------------------------------------------------------------------------

Record scene_shortcuts_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  const SceneStudyCase& c = find_case(o, o.shortcuts.case_name);
  const SceneShortcutOptions& so = o.shortcuts;
  SceneOptions base = capped(o, c.scene);
  base.coupling = Coupling::two_way;
  base.water->field.mode = StepMode::full;
  base.water->field.precision = Precision::float64;
  base.water->field.threads = 1;
  const std::vector<ShortcutVariant> v = scene_shortcut_variants(base, so);
  Record out;
  out.set("case", c.name);
  out.set("title", c.title);
  out.set("repeats", so.repeats);
  out.set("checkpoint_every", so.checkpoint_every);
  out.set("field_tolerance", so.field_tolerance);
  out.set("time_tolerance_s", so.time_tolerance_s);
  out.set("tile_cells", so.tile_cells);
  std::vector<std::string> keys;
  auto ticker = start_progress(progress, "scene: shortcuts", v.size());
  // The base is the reference of most variants: run it once.
  const ProbedScene base_run = run_probed(base, so.checkpoint_every, so.repeats);
  for (const auto& x : v) {
    const ProbedScene ref = x.reference ? run_probed(*x.reference, so.checkpoint_every, so.repeats) : base_run;
    const ProbedScene cut = run_probed(x.shortcut, so.checkpoint_every, so.repeats);
    const SceneDifference d = compare_scenes(ref, cut);
    Record& r = out.child(x.key);
    keys.push_back(x.key);
    r.set("what", x.what);
    r.set("field_max_change_m", d.field_max_change_m);
    r.set("field_scale_m", d.field_scale_m);
    r.set("field_relative", d.field_relative());
    r.set("start_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    r.set("touch_change_m", d.max_touch_change_m);
    r.set("contacts_reference", d.contacts_a);
    r.set("contacts_shortcut", d.contacts_b);
    r.set("count_change", static_cast<double>(std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b)));
    r.set("reference_cpu_s", ref.min_cpu_s);
    r.set("shortcut_cpu_s", cut.min_cpu_s);
    r.set("saving", ref.min_cpu_s > 0 ? 1 - cut.min_cpu_s / ref.min_cpu_s : kNaN);
    r.set("tile_fraction", cut.summary.tiles.fraction());
    Record in;
    in.set("field_relative", d.field_relative());
    in.set("start_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    in.set("count_change", static_cast<double>(std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b)));
    in.set("field_tolerance", so.field_tolerance);
    in.set("time_tolerance_s", so.time_tolerance_s);
    std::ostringstream reason;
    reason << "largest surface difference " << num(d.field_max_change_m, 2) << " m (" << num(d.field_relative(), 2) << " of the largest surface height), contacts moved by up to "
           << duration(std::max(d.max_start_change_s, d.max_end_change_s)) << ", " << counted(d.contacts_b, "contact") << " against " << d.contacts_a << "; CPU "
           << ms(cut.min_cpu_s) << " against " << ms(ref.min_cpu_s) << " (" << num(100 * (ref.min_cpu_s > 0 ? 1 - cut.min_cpu_s / ref.min_cpu_s : 0), 3)
           << " % saved)";
    decide_verdict(r, "verdict", "shortcut", in, reason.str());
    ticker->tick();
  }
  out.set_strings("shortcuts", keys);
  return out;
}

}  // namespace stoneskip
