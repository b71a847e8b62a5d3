// The captures report, formatted from the stored records (capture_findings.hpp says what each
// holds): the verdicts first, then one section per capture.
#include "reports/capture/capture_report.hpp"

#include <algorithm>
#include <cmath>

#include "reports/capture/capture_figures.hpp"
#include "reports/common/markdown.hpp"
#include "verification/study/stored_values.hpp"

namespace stoneskip {

namespace {

// The most contacts a stored run may claim when read back (data.h5 may be edited by hand): a
// throw's runs have tens; the count bounds the "contacts gaining energy" read beside it.
constexpr std::size_t kMostStoredContacts = 1'000'000;

// "nominal [low, high]" of a stored interval.
std::string iv(const Record& v, int significant = 3) {
  return fmt(v.number("nominal"), significant) + " [" + fmt(v.number("low"), significant) + ", " +
         fmt(v.number("high"), significant) + "]";
}

std::string yes_no(bool b) { return b ? "yes" : "no"; }

std::string code_list(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + code(x);
  return s;
}

void add_figure(SectionWriter& w, const std::optional<Figure>& f) {
  if (f) w.figure(*f);
}

// ---- the index ----

std::string bounces_cell(const Record& c) {
  const Record& sim = c.at("simulation");
  if (!sim.flag("ran")) return "–";
  auto count = [&](const char* solver) { return sim.has_child(solver) ? fmt(sim.at(solver).number("bounces")) : "–"; };
  std::string ens = "–";
  if (sim.has_child("ensemble")) {
    const Record& e = sim.at("ensemble");
    ens = std::isnan(e.number("bounces_low")) ? std::string("none finished")
                                               : fmt(e.number("bounces_low")) + "–" + fmt(e.number("bounces_high"));
    if (e.has_number("failed") && e.number("failed") > 0) ens += " (" + fmt(e.number("failed")) + " failed)";
  }
  return count("realtime") + " / " + count("reference") + " / " + ens;
}

SectionOutput index_section(const Record& index, const Record& sections) {
  SectionWriter w(index, "Verdicts");
  w.text(fmt(index.number("count")) + " capture(s): " + fmt(index.number("usable")) + " usable, " +
         fmt(index.number("usable_with_caveats")) + " usable with caveats, " + fmt(index.number("unusable")) +
         " unusable. A capture's name leads to its part of this page: the reasons for its verdict, its timing, its "
         "motion, its release state and what the solvers make of it.");
  MarkdownTable t({"capture", "read as", "verdict", "speed (m/s) [interval]", "attack (deg)", "path (deg)", "spin (rev/s)",
                   "height (m)",
                   "bounces: real-time / reference / ensemble (" + fmt(index.number("low_percent"), 3) + "–" +
                       fmt(index.number("high_percent"), 3) + " %)"});
  for (const auto& key : index.strings("captures")) {
    const Record& c = sections.at(key);
    const Record& th = c.at("throw");
    const bool ok = th.flag("computed");
    auto value = [&](const char* name) { return ok ? iv(th.at("virtual").at(name)) : std::string("–"); };
    auto nominal = [&](const char* name) {
      return ok ? fmt(th.at("virtual").at(name).number("nominal"), 3) : std::string("–");
    };
    t.row({"[" + code(c.text("file")) + "](#" + key + ")", code(c.text("format")), "**" + c.at("verdict").text("verdict") + "**",
           value("speed_m_s"), nominal("attack_angle_deg"), nominal("path_angle_deg"), nominal("spin_rev_s"),
           nominal("height_m"), bounces_cell(c)});
  }
  w.table(t);
  w.text("Speed, angles, spin and height are the virtual stone's, the throw the solvers get; each capture's section "
         "shows them beside the throw as measured in the room.");
  return w.finish();
}

// ---- one capture ----

void timing_part(SectionWriter& w, const std::string& key, const Record& c) {
  const Record& t = c.at("timing");
  w.subheading("Timing");
  if (t.flag("nominal")) {
    w.text("The file has no timestamps: the times are those of the nominal rate, and nothing can be said of jitter, gaps "
           "or lost reports.");
    return;
  }
  std::string clock;
  if (t.text("clock") == "regular_reports")
    clock = "Every stamp lies within " + fmt(t.number("regular_max_residual_intervals"), 3) +
            " median intervals of a regular clock fitted through the reports' slots, so that clock, the remote's own, "
            "replaced the stamps (`regular_reports`).";
  else
    clock = "The stamps were used as given (`stamps_as_given`" +
            std::string(c.at("settings").text("clock_option") == "automatic"
                            ? ": no regular clock lies within " + fmt(t.number("regular_max_residual_intervals"), 3) +
                                  " median intervals of every stamp"
                            : ", as asked") +
            ").";
  // How gaps were counted (verification/captures/capture_timing.cpp): by the fitted clock's slots
  // where that clock replaced the stamps, by bursts where the host polled, else by the intervals.
  std::string counting;
  if (t.text("clock") == "regular_reports")
    counting = "Each stamp takes the slot of that clock nearest to it, and slots skipped between neighbouring reports "
               "are reports lost (a gap): an interval is judged by where its two stamps fall on the clock, not by its "
               "length alone (a late stamp then an early one make one long and one short interval over single slots). "
               "The jitter is the standard deviation of the intervals that skip no slot.";
  else if (t.has_number("bursts") && t.flag("bursts"))
    counting = "The reports reached the host in bursts (several stamped together, as a host that polls delivers them): "
               "the rate is from the median interval per report, each burst's last report is as many slots after the "
               "previous burst's last as the burst has reports, more where the time between them exceeds that by three "
               "quarters of a period or more, and those extra slots are reports lost. The jitter is the standard "
               "deviation of the intervals inside bursts and into bursts that skip no slot.";
  else
    counting = "An interval of " + fmt(t.number("gap_factor"), 3) +
               " median intervals or more is a gap, and about round(interval / median) − 1 reports were lost in it; the "
               "jitter is the standard deviation of the other intervals.";
  w.text("The rate is the inverse of the median interval between kept reports. " + clock + " " + counting);
  MarkdownTable m({"quantity", "value"});
  m.row({"samples in the file", fmt(t.number("samples"))})
      .row({"repeated reports dropped", fmt(t.number("repeated"))})
      .row({"rate (Hz): from the median interval / mean over the capture",
            fmt(t.number("rate_hz"), 5) + " / " + fmt(t.number("mean_rate_hz"), 5)})
      .row({"jitter (ms): standard deviation / largest deviation",
            fmt(1e3 * t.number("jitter_s"), 3) + " / " + fmt(1e3 * t.number("max_jitter_s"), 3)})
      .row({"shortest / longest interval (ms)",
            fmt(1e3 * t.number("min_interval_s"), 3) + " / " + fmt(1e3 * t.number("max_interval_s"), 3)})
      .row({"pairs of equal stamps", fmt(t.number("equal_stamps"))})
      .row({"rate of the regular clock that replaced the stamps (Hz)",
            t.text("clock") == "regular_reports" && t.has_number("clock_rate_hz") ? fmt(t.number("clock_rate_hz"), 5)
                                                                                  : std::string("– (stamps used as given)")})
      .row({"stamp − regular clock (ms): RMS / largest",
            fmt(1e3 * t.number("clock_residual_rms_s"), 3) + " / " + fmt(1e3 * t.number("clock_residual_max_s"), 3)})
      .row({"gaps / reports lost in them", fmt(t.number("gaps")) + " / " + fmt(t.number("dropped_reports"))})
      .row({"longest gap (ms)", fmt(1e3 * t.number("longest_gap_s"), 3)});
  w.table(m);
  add_figure(w, capture_timing_figure(key, c));
}

void motion_part(SectionWriter& w, const std::string& key, const Record& c) {
  const Record& m = c.at("motion");
  const Record& sat = m.at("saturation");
  const Record& still = m.at("still");
  const Record& rel = m.at("release");
  w.subheading("The motion: still part, swing, clipping, release");
  w.text("An accelerometer axis at or beyond " + fmt(sat.number("saturation_g"), 3) +
         " g is taken as clipped. The still part is the latest stretch of at least " + fmt(still.number("min_still_s"), 3) +
         " s before the release where the acceleration stays within " + fmt(still.number("accel_tol_g"), 3) +
         " g and the rate within " + fmt(still.number("rate_tol_deg_s"), 3) +
         " deg/s of their means: it gives the direction of gravity, the check that the remote at rest reads 1 g, and the "
         "gyro's bias. " +
         (rel.flag("has_buttons") ? "The release lies between the last sample with " + rel.text("button") +
                                        " held and the first without it; the swing runs from the end of the still part "
                                        "to the release."
                                  : std::string("The file records no buttons: the release is taken at its end.")));
  auto span = [](double a, double b, int sig) { return fmt(a, sig) + " – " + fmt(b, sig); };
  MarkdownTable t({"quantity", "value"});
  t.row({"clipped samples: X / Y / Z / any", fmt(sat.number("samples_x")) + " / " + fmt(sat.number("samples_y")) + " / " +
                                                 fmt(sat.number("samples_z")) + " / " + fmt(sat.number("samples_any"))})
      .row({"fraction of the samples clipped", fmt(sat.number("fraction"), 3)})
      .row({"clipped samples in the swing", fmt(sat.number("in_swing")) + " of " + fmt(sat.number("swing_samples")) +
                                                (sat.text("clipped_axes").empty() ? "" : " (" + sat.text("clipped_axes") + ")")})
      .row({"MotionPlus at the end of its range in the swing", yes_no(sat.flag("gyro_saturated_in_swing"))});
  // The MotionPlus in the swing, from the verdict's stored inputs (records stored before them lack them).
  const Record& v = c.at("verdict");
  if (v.has_number("swing_peak_rate_deg_s") && v.has_number("min_swing_rate_deg_s"))
    t.row({"largest rate off the still part's in the swing (deg/s)",
           !still.flag("found") ? std::string("not measured (no still part to measure from)")
                                : fmt(v.number("swing_peak_rate_deg_s"), 4) + " (unusable below " +
                                      fmt(v.number("min_swing_rate_deg_s"), 3) + ": a gyro that did not record the throw)"});
  if (v.has_number("gyro_held_in_swing"))
    t.row({"swing samples whose rate is held over a MotionPlus silence",
           fmt(v.number("gyro_held_in_swing")) + " (unusable above 0)"});
  t.row({"still part (s)", still.flag("found") ? span(still.number("t0_s"), still.number("t1_s"), 4) : "not found"})
      .row({"acceleration in the still part (g)",
            fmt(still.number("accel_g"), 5) + " (a caveat beyond 1 ± " + fmt(still.number("caveat_g"), 3) +
                ", unusable beyond 1 ± " + fmt(still.number("unusable_g"), 3) + ")"})
      .row({"gyro bias (deg/s, x y z)", fmt(still.number("gyro_bias_x_deg_s"), 3) + " " +
                                            fmt(still.number("gyro_bias_y_deg_s"), 3) + " " +
                                            fmt(still.number("gyro_bias_z_deg_s"), 3)})
      .row({"MotionPlus range switches", fmt(still.number("range_switches")) +
                                             (still.flag("range_inferred") ? " (inferred from jumps: no range flags)" : "")})
      .row({"release (s)", rel.flag("found") ? fmt(rel.number("t_s"), 5) + " in [" + fmt(rel.number("t_low_s"), 5) + ", " +
                                                   fmt(rel.number("t_high_s"), 5) + "]" +
                                                   (rel.flag("at_end") ? " (the file's end)" : "")
                                             : (rel.flag("press_found") ? "not found" : "no press of " + rel.text("button"))});
  w.table(t);
  w.figure(capture_motion_figure(key, c));
  add_figure(w, capture_swing_figure(key, c));
}

void release_part(SectionWriter& w, const std::string& key, const Record& c) {
  const Record& th = c.at("throw");
  const Record& s = c.at("settings");
  // Records stored before the MotionPlus fill existed lack its bound: their intervals had none.
  const bool gyro_saturated =
      c.at("motion").at("saturation").flag("gyro_saturated_in_swing") && s.has_number("max_rate_deg_s");
  w.subheading("The release state, as measured in the room and as mapped to the virtual stone");
  if (!th.flag("computed")) {
    w.text("No release state: the capture's verdict is " + c.at("verdict").text("verdict") + " (its reasons are above).");
    return;
  }
  std::vector<std::string> perturbed{
      "noise of " + fmt(s.number("accel_noise_g"), 3) + " g and " + fmt(s.number("gyro_noise_deg_s"), 3) +
          " deg/s per sample",
      "half a quantisation step", "a calibration offset of ±" + fmt(s.number("accel_bias_g"), 3) + " g per axis",
      "the release time within its interval",
      "the MotionPlus scale ±" + fmt(100 * s.number("gyro_scale_rel_uncertainty"), 3) + " %",
      "the lever arm ±" + fmt(100 * s.number("lever_arm_rel_uncertainty"), 3) + " %",
      "the thrower's release height ±" + fmt(s.number("height_uncertainty_m"), 3) + " m"};
  if (th.flag("clipped"))
    perturbed.push_back("the clipped spans filled with random bumps up to " + fmt(s.number("max_accel_g"), 3) + " g");
  if (gyro_saturated)
    perturbed.push_back("the spans where the MotionPlus reached the end of its range filled with random bumps up to " +
                        fmt(s.number("max_rate_deg_s"), 4) + " deg/s (a saturated rate is a lower bound)");
  std::string listed;
  for (std::size_t k = 0; k < perturbed.size(); ++k)
    listed += (k == 0 ? "" : k + 1 == perturbed.size() ? ", and " : ", ") + perturbed[k];
  w.text("The intervals join the nominal estimate with the " + fmt(s.number("interval_low_percent"), 3) + "–" +
         fmt(s.number("interval_high_percent"), 3) + " % range of " + fmt(th.number("members")) +
         " re-runs of the whole chain on perturbed inputs: " + listed + "." +
         // With few re-runs the quantiles are read off the extreme draws (0.025 (n − 1) < 1).
         (s.number("interval_low_percent") / 100 * (th.number("members") - 1) < 1
              ? " With " + fmt(th.number("members")) + " re-runs the quantiles are interpolated between the extreme draws: "
                "**too few re-runs to resolve a " + fmt(s.number("interval_low_percent"), 3) + "–" +
                fmt(s.number("interval_high_percent"), 3) + " % range**; these intervals are rough (about " +
                fmt(std::ceil(100 / s.number("interval_low_percent")) + 1) + " re-runs resolve it)."
              : std::string()));
  if (th.flag("clipped") && !th.has_number("lever_raised_to_bound"))  // written before the speeds were raised
    w.text("The accelerometer clipped during the swing, so integrating it gives only a lower bound on the speed (" +
           fmt(th.number("accel_lower_speed_m_s"), 3) + " m/s; " + fmt(th.number("accel_upper_speed_m_s"), 3) +
           " m/s with every clipped span at " + fmt(s.number("max_accel_g"), 3) +
           " g). The throw takes the lever-arm velocity (angular rate × lever arm, which the gyro still measures), and "
           "the speed's interval spans both.");
  else if (th.flag("clipped")) {
    const Record& ms = th.at("measured");
    const double lever = ms.at("lever_speed_m_s").number("nominal");
    const bool raised = th.flag("lever_raised_to_bound");
    w.text("The accelerometer clipped during the swing, so integrating it gives only a lower bound on the speed (" +
           fmt(th.number("accel_lower_speed_m_s"), 3) + " m/s; " + fmt(th.number("accel_upper_speed_m_s"), 3) +
           " m/s with every clipped span at " + fmt(s.number("max_accel_g"), 3) +
           " g). The throw takes the lever-arm velocity (angular rate × lever arm, which the gyro still measures)" +
           (raised ? ", here raised to that lower bound, since its speed (" + fmt(lever, 3) + " m/s) falls below it"
                   : std::string()) +
           ". The speed's interval spans the accelerometer's bounds and the re-runs, each re-run's speed raised the "
           "same way to its own bound where slower. The lever arm's velocity misses the pivot's own motion, which the "
           "accelerometer sees, so the path and attack angles' intervals also span the directions of the "
           "accelerometer's velocity (at both bounds and in each re-run), and the rise's interval spans the rise "
           "integrated at both bounds: these intervals can reach far beyond the re-runs' spread.");
  }
  const bool fixed = s.text("height_mapping") == "fixed_release_height";
  const double finger = s.number("finger_spin_rev_s");
  w.text("The virtual thrower (" + code(s.text("height_mapping")) + "): " +
         (fixed ? "the stone's centre " + fmt(s.number("release_height_m"), 3) +
                      " m above the water at the release, whatever the hand did in the room"
                : "the still part " + fmt(s.number("still_height_m"), 3) +
                      " m above the water, plus the rise measured since") +
         "; the measured velocity × " + fmt(s.number("speed_scale"), 3) + "; the spin about the stone's normal × " +
         fmt(s.number("spin_scale"), 3) +
         (finger != 0 ? " plus " + fmt(finger, 3) + " rev/s from the fingers" : std::string(", with no finger spin added")) +
         ". The attack, path and roll angles are not changed.");
  const Record& m = th.at("measured");
  const Record& v = th.at("virtual");
  MarkdownTable t({"quantity", "as measured in the room", "the virtual stone (what the solvers get)"});
  t.row({"speed (m/s)", iv(m.at("speed_m_s")), iv(v.at("speed_m_s"))})
      .row({"… from the accelerometer (m/s)",
            iv(m.at("accel_speed_m_s")) + (th.flag("clipped") ? " (clipped: from the lower bound to the clip-filled one)" : ""),
            ""})
      .row({"… from angular rate × lever arm (m/s)", iv(m.at("lever_speed_m_s")), ""})
      .row({"accelerometer − lever arm, nominal (m/s)", fmt(th.number("speed_difference_m_s"), 3), ""})
      .row({"attack angle (deg)", iv(v.at("attack_angle_deg")), "the same"})
      .row({"path angle (deg)", iv(v.at("path_angle_deg")), "the same"})
      .row({"roll angle, nominal (deg)", fmt(th.number("roll_angle_deg"), 3), "the same"})
      .row({"spin about the stone's normal (rev/s)", iv(m.at("spin_rev_s")), iv(v.at("spin_rev_s"))})
      .row({"height (m)", "rise since the still part: " + iv(m.at("rise_m")),
            "above the water: " + iv(v.at("height_m"))});
  w.table(t);
  w.text("The spin in the room is what the remote on the forearm sees: the turn of the arm. A flick of the fingers at the "
         "release adds spin that no sensor on the forearm can record; the thrower's `finger_spin_rev_s` adds it when "
         "asked.");
  add_figure(w, capture_release_figure(key, c));
  add_figure(w, capture_room_and_water_figure(key, c));
}

// A synthetic capture's recovered values against its generator's truth (capture_truth.hpp).
void truth_part(SectionWriter& w, const Record& c) {
  if (!c.has_child("truth")) return;
  const Record& t = c.at("truth");
  w.subheading("Against the truth");
  w.text("This capture is synthetic: its generator wrote the throw it recorded in " + code(t.text("file")) + ". " +
         fmt(t.number("inside_count")) + " of the " + fmt(t.number("compared")) +
         " intervals below hold the truth (the room's values, before the virtual thrower).");
  MarkdownTable tab({"quantity", "truth", "recovered [interval]", "recovered / truth", "interval holds the truth"});
  const struct {
    const char* key;
    const char* label;
  } rows[] = {{"speed_m_s", "speed used (m/s)"},
              {"accel_speed_m_s", "… from the accelerometer (m/s)"},
              {"lever_speed_m_s", "… from angular rate × lever arm (m/s)"},
              {"lever_arm_part_m_s", "angular rate × lever arm against the arm's part of the truth (m/s)"},
              {"attack_angle_deg", "attack angle (deg)"},
              {"path_angle_deg", "path angle (deg)"},
              {"spin_rev_s", "spin about the stone's normal (rev/s)"},
              {"rise_m", "rise since the still part (m)"}};
  for (const auto& r : rows) {
    if (!t.has_child(r.key)) continue;
    const Record& q = t.at(r.key);
    tab.row({r.label, fmt(q.number("truth"), 4), iv(q), fmt(q.number("ratio"), 3), yes_no(q.flag("inside"))});
  }
  w.table(tab);
  if (t.has_child("lever_arm_part_m_s")) {
    const Record& lever = t.at("lever_speed_m_s");
    const Record& arm = t.at("lever_arm_part_m_s");
    w.text("Angular rate × lever arm sees the arm's turn about its pivot and nothing else: its nominal " +
           fmt(lever.number("nominal"), 3) + " m/s is " + fmt(arm.number("ratio"), 3) + " of the truth's arm part (" +
           fmt(arm.number("truth"), 4) + " m/s) but " + fmt(lever.number("ratio"), 3) + " of the whole speed (" +
           fmt(lever.number("truth"), 4) + " m/s). The rest is the pivot's own motion (the trunk's turn, " +
           fmt(t.number("pivot_speed_m_s"), 3) +
           " m/s at the release), which no sensor on the forearm measures: where the accelerometer clips and the throw "
           "takes the lever-arm estimate, its nominal speed is low by up to that much (less where it is raised to "
           "the accelerometer's lower bound), and only the accelerometer's bounds in the speed's interval cover it.");
  }
}

void solvers_part(SectionWriter& w, const std::string& key, const Record& c) {
  const Record& sim = c.at("simulation");
  w.subheading("What the solvers make of it");
  if (!sim.flag("ran")) {
    w.text(c.at("throw").flag("computed") ? "The solvers did not run (switched off)."
                                          : "The solvers did not run: the capture's verdict is " +
                                                c.at("verdict").text("verdict") + ".");
    return;
  }
  w.text("The stone and the water come from " + code(sim.text("case_file")) + " (" + sim.text("stone_description") + "; " +
         sim.text("convention") + " convention, " + sim.text("water_law") +
         " water law); the throw is the capture's virtual stone.");
  // Records written before the energy was stored have no such column.
  const bool energy = (!sim.has_child("realtime") || sim.at("realtime").has_number("max_energy_gain_J")) &&
                      (!sim.has_child("reference") || sim.at("reference").has_number("max_energy_gain_J"));
  std::vector<std::string> head{"solver", "bounces", "contacts", "distance (m)", "outcome", "CPU (s)", "wall (s)"};
  if (energy) head.insert(head.begin() + 3, "contacts gaining energy; largest gain (J)");
  MarkdownTable t(head);
  int gaining = 0;
  for (const char* solver : {"realtime", "reference"}) {
    if (!sim.has_child(solver)) continue;
    const Record& r = sim.at(solver);
    std::vector<std::string> row{r.text("solver"), fmt(r.number("bounces")), fmt(r.number("contacts")),
                                 fmt(r.number("distance_m"), 3), r.text("outcome"), fmt(r.number("cpu_s"), 3),
                                 fmt(r.number("wall_s"), 3)};
    if (energy) {
      gaining = std::max(gaining, static_cast<int>(stored_count(r, "contacts_gaining_energy",
                                                                stored_count(r, "contacts", kMostStoredContacts))));
      row.insert(row.begin() + 3, fmt(r.number("contacts_gaining_energy")) + "; " +
                                      (r.number("max_energy_gain_J") > 0 ? fmt(r.number("max_energy_gain_J"), 3) : "none"));
    }
    t.row(row);
  }
  w.table(t);
  if (energy && gaining > 0)
    w.text("The stone leaves " + std::string(gaining == 1 ? "a contact" : "contacts") +
           " with more energy than it entered " + (gaining == 1 ? "it" : "them") + ": the water created energy, as the " +
           sim.text("convention") + " convention's equations " +
           (sim.text("convention") == "paper" ? "as printed can (model/README.md §1.6); its bounces are not a physical "
                                                "stone's"
                                              : "should not (a solver's error: see its tolerance)") +
           ".");
  // Records written before the ensembles judged the nominal throw's single runs.
  if (sim.has_child("agreement"))
    w.verdict(sim.has_table("count_ensemble") ? "Real-time model against the reference, on ensembles of the nominal throw"
                                        : "Real-time model against the reference",
              sim.at("agreement"));
  if (sim.has_number("count_ensemble_members") && sim.number("count_ensemble_members") > 0)
    w.text("Cost of those ensembles (" + fmt(sim.number("count_ensemble_members")) + " throws through each solver): " +
           fmt(sim.number("count_ensemble_cpu_s"), 3) + " s CPU, " + fmt(sim.number("count_ensemble_wall_s"), 3) + " s wall.");
  add_figure(w, capture_trajectory_figure(key, c));
  if (sim.has_child("ensemble")) {
    const Record& e = sim.at("ensemble");
    // Clipped captures since the bounds' corners were run: the corners too (older data has none).
    const bool corners = e.has_table("bound_corners");
    w.text("The ensemble: the " + fmt(e.number("members")) +
           " releases of the capture's ensemble (each re-estimated with random noise, biases, gyro scale, lever arm, height "
           "and release time, clipped spans filled at random)" +
           (corners ? std::string(" and the nominal throw at the four corners of the speed and height intervals (the clipped "
                                  "accelerometer's bounds joined with the members' range, which the members need not reach)")
                    : std::string()) +
           ", through the real-time model (" + fmt(e.number("cpu_s"), 3) + " s CPU, " + fmt(e.number("wall_s"), 3) +
           " s wall). Their spread is what the recording cannot decide.");
    w.verdict("Bounce count", e.at("spread"));
    add_figure(w, capture_bounce_figure(key, c));
  }
}

void scene_part(SectionWriter& w, const std::string& key, const Record& c) {
  if (!c.has_child("scene")) return;
  const Record& sc = c.at("scene");
  const Record& s = sc.at("settings");
  const Record& st = sc.at("stone");
  const Record& wv = sc.at("waves");
  w.subheading("Through the coupled scene, against both references");
  const WaveForcingWords head = wave_forcing_words(s);
  std::string water = "no water field";
  if (s.flag("has_water"))
    water = fmt(s.number("nx")) + " × " + fmt(s.number("ny")) + " grid of " + fmt(100 * s.number("cell_m"), 3) + " cm cells (" +
            s.text("stencil") + ", " + (s.has_text("boundary") ? s.text("boundary") : s.flag("periodic") ? "periodic" : "not periodic") +
            (s.has_text("boundary") && s.text("boundary") != "periodic" ? " walls" : "") + "), c = " +
            fmt(s.number("wave_speed_m_s"), 3) + " m/s, μ = " + fmt(s.number("damping_per_s"), 3) + " /s, Δt = " +
            fmt(1e3 * s.number("dt_s"), 3) + " ms (σ = " + fmt(s.number("courant"), 3) + "), " + head.gathering;
  w.text("The capture's virtual stone thrown into the scene of " + code(s.text("case_file")) + " (" +
         s.text("stone_description") + "; " + s.text("convention") + " convention; coupling " + code(s.text("coupling")) +
         "; " + water + "; " + fmt(s.number("frame_rate_hz"), 4) + " frames/s for " +
         fmt(s.number("duration_s"), 4) + " s). The stone is compared with the CVODE reference on still water (rtol " +
         fmt(s.number("reference_rtol"), 3) + ") contact by contact, beside the same real-time model on still water: "
         "the scene against still water is what the live surface changes, still water against CVODE is the model's "
         "own step error (" +
         (s.has_number("stone_adaptive") && s.flag("stone_adaptive")
              ? code(s.text("stone_scheme")) + " at rtol " + fmt(s.number("stone_rtol"), 3)
              : "flight step " + fmt(1e3 * s.number("stone_dt_s"), 3) + " ms, contact step " +
                    fmt(1e3 * s.number("stone_contact_dt_s"), 3) + " ms") +
         ").");
  MarkdownTable t({"CVODE contact", "start (s): scene / still water / CVODE", "end (s): scene / still water / CVODE",
                   "exit x (m): scene / CVODE", "bounced: scene / CVODE"});
  const Table& k = st.table("contacts");
  for (std::size_t i = 0; i < k.rows(); ++i) {
    auto v = [&](const char* col, int sig) { return fmt_or_dash(k.column(col)[i], sig); };
    t.row({v("index", 3), v("scene_start_s", 6) + " / " + v("still_start_s", 6) + " / " + v("reference_start_s", 6),
           v("scene_end_s", 6) + " / " + v("still_end_s", 6) + " / " + v("reference_end_s", 6),
           v("scene_exit_x_m", 4) + " / " + v("reference_exit_x_m", 4),
           yes_no(k.column("scene_bounced")[i] != 0) + " / " + yes_no(k.column("reference_bounced")[i] != 0)});
  }
  w.table(t);
  // Records written before the ensembles judged the scene's one run against CVODE's.
  w.verdict(st.has_table("count_ensemble") ? "The stepper against CVODE on still water, on ensembles (the scene's live water is "
                                       "one run, shown and not judged)"
                                     : "The scene's stone against CVODE",
            st.at("agreement"));
  w.end_list();
  add_figure(w, capture_scene_stone_figure(key, c));
  if (st.has_number("count_ensemble_members") && st.number("count_ensemble_members") > 0)
    w.text("Cost of the still-water ensembles (" + fmt(st.number("count_ensemble_members")) + " throws through each solver): " +
           fmt(st.number("count_ensemble_cpu_s"), 3) + " s CPU, " + fmt(st.number("count_ensemble_wall_s"), 3) + " s wall.");
  if (!wv.flag("compared")) {
    w.text("The waves are not compared: " + wv.text("not_compared") + ".");
  } else {
    w.text("The waves at " + fmt(wv.number("t_s"), 4) + " s (" + fmt(wv.number("steps")) +
           " water steps) against the forced spectral reference (model/README.md §2.5) driven by " + head.name + " of the CVODE "
           "trajectory against the flat surface, evaluated on " + fmt(wv.number("quadrature_intervals"), 9) +
           " sub-intervals of " + fmt(s.number("quadrature_nodes")) + " Gauss–Legendre nodes each. Largest differences over the grid (the largest "
           "height of the reference is " + fmt(1e3 * wv.number("amplitude_m"), 3) + " mm):");
    MarkdownTable e({"part", "compares", "max difference (mm)"});
    e.row({"total", "scene − continuum reference", fmt(1e3 * wv.number("total_m"), 3)})
        .row({"model", "scene − leapfrog driven by CVODE's " + head.short_name + " (the stone's own path, " + head.feedback + ")",
              fmt(1e3 * wv.number("model_m"), 3)})
        .row({"… path", "leapfrog driven by the scene stone's own " + head.short_name + " − the one driven by CVODE's",
              fmt(1e3 * wv.number("path_m"), 3)})
        .row({"… feedback", "scene − leapfrog driven by the scene stone's own " + head.short_name + " (" + head.feedback + ")",
              fmt(1e3 * wv.number("feedback_m"), 3)})
        .row({"time", "that leapfrog − the stencil's exact semi-discrete solution", fmt(1e3 * wv.number("time_m"), 3)})
        .row({"space", "semi-discrete − continuum solution", fmt(1e3 * wv.number("space_m"), 3)})
        .row({"reference", "continuum reference − itself with half as many sub-intervals",
              fmt(1e3 * wv.number("quadrature_m"), 3)});
    w.table(e);
    w.verdict("The reference", wv.at("reference"));
    w.end_list();
    add_figure(w, capture_scene_wave_figure(key, c));
    w.text("Cost: the scene " + fmt(st.number("frames")) + " frames in " + fmt(st.number("scene_cpu_s"), 3) + " s CPU, " +
           fmt(st.number("scene_wall_s"), 3) + " s wall; CVODE " + fmt(st.number("reference_cpu_s"), 3) + " s CPU, " +
           fmt(st.number("reference_wall_s"), 3) + " s wall; the wave references (" + fmt(wv.number("transforms"), 12) +
           " transforms of the " + head.short_name + ") " + fmt(wv.number("cpu_s"), 3) + " s CPU, " + fmt(wv.number("wall_s"), 3) + " s wall.");
  }
}

void settings_part(SectionWriter& w, const Record& c) {
  const Record& s = c.at("settings");
  const Record& t = c.at("timing");
  w.subheading("Settings");
  w.bullet("Mounting (remote frame): " + code_list(s.strings("mounting")))
      .bullet("Virtual thrower: " + code_list(s.strings("thrower")))
      .bullet("Clock: " + code(s.text("clock_option")) + (t.flag("ok") ? ", used: " + code(t.text("clock")) : std::string()))
      .bullet("Action button: " + s.text("release_button"))
      .bullet("Ensemble: " + fmt(s.number("members_requested")) + " members asked for, seed " + fmt(s.number("seed"), 12));
  w.end_list();
  const auto& warnings = c.strings("reader_warnings");
  const double total = c.number("reader_warnings_total");
  if (total > 0) {
    w.subheading("Reader warnings");
    for (const auto& x : warnings) w.bullet(x);
    if (total > double(warnings.size())) w.bullet("… and " + fmt(total - double(warnings.size())) + " more");
    w.end_list();
  }
  if (!c.strings("notes").empty()) {
    w.subheading("Notes");
    for (const auto& x : c.strings("notes")) w.bullet(x);
    w.end_list();
  }
}

SectionOutput capture_section(const std::string& key, const Record& c) {
  SectionWriter w(c, "Capture " + code(c.text("file")));
  w.verdict("Verdict", c.at("verdict"));
  w.end_list();
  w.text("Read as " + code(c.text("format")) + ".");
  timing_part(w, key, c);
  motion_part(w, key, c);
  release_part(w, key, c);
  truth_part(w, c);
  solvers_part(w, key, c);
  scene_part(w, key, c);
  settings_part(w, c);
  return w.finish();
}

}  // namespace

RenderedReport render_captures_report(const StoredReport& s) {
  const Record& secs = s.sections;
  const Record& index = secs.at("index");
  RenderedReport out;
  const bool simulated = !index.text("case_file").empty();
  out.markdown =
      "# Wii Remote captures\n\n"
      "Each capture was read, its timing, clipping and still part checked, the release state it records estimated with "
      "intervals, mapped by the virtual thrower to a stone over water, and " +
      (simulated ? "thrown through the real-time model and the reference (the stone and the water of " +
                       code(index.text("case_file")) + ": " + index.text("stone_description") + ", " +
                       index.text("convention") + " convention)."
                 : std::string("not thrown (the solvers were switched off).")) +
      " A Wii Remote stamps nothing itself: the host stamps its reports, its accelerometer clips on real throws and its "
      "MotionPlus changes range during fast swings (model/README.md §4). Each section says how much of the throw its recording "
      "still pins down.\n\n";
  append(out, index_section(index, secs));
  for (const auto& key : index.strings("captures")) {
    out.markdown += "<a id=\"" + key + "\"></a>\n\n";
    append(out, capture_section(key, secs.at(key)));
  }
  out.markdown += provenance_markdown(s);
  return out;
}

}  // namespace stoneskip
