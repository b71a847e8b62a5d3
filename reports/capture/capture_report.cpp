#include "reports/capture/capture_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "verification/captures/mounting.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/hdf5_file.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

std::string interval_text(const Interval& v, int sig = 3) {
  return fmt(v.nominal, sig) + " [" + fmt(v.low, sig) + ", " + fmt(v.high, sig) + "]";
}

// gnuplot commands shading the clipped spans (red), the still part (green) and marking the release.
std::string markers(const CaptureAnalysis& a) {
  std::ostringstream s;
  s.precision(9);
  int id = 1;
  const double half = 0.5 * (a.timing.stats.period_s > 0 ? a.timing.stats.period_s : 0.005);
  for (const auto& sp : a.spans)
    s << "set object " << id++ << " rect from " << sp.t0_s - half << ", graph 0 to " << sp.t1_s + half
      << ", graph 1 fc rgb '#f4a6a6' fs transparent solid 0.45 noborder behind\n";
  if (a.still_found)
    s << "set object " << id++ << " rect from " << a.still_t0_s << ", graph 0 to " << a.still_t1_s
      << ", graph 1 fc rgb '#b9e4b9' fs transparent solid 0.45 noborder behind\n";
  if (a.release_found)
    s << "set arrow from " << a.release_t_s << ", graph 0 to " << a.release_t_s
      << ", graph 1 nohead lw 2 lc rgb '#000000' dt 2\n"
      << "set label 'release' at " << a.release_t_s << ", graph 0.95 offset 0.5,0\n";
  return s.str();
}

Table trace_table(const CaptureAnalysis& a) {
  Table t;
  t.columns = {"t_s", "ax_g", "ay_g", "az_g", "wx_deg_s", "wy_deg_s", "wz_deg_s", "button_down", "clipped_any",
               "world_ax_m_s2", "world_ay_m_s2", "world_az_m_s2", "remote_vx_m_s", "remote_vy_m_s", "remote_vz_m_s",
               "stone_speed_m_s"};
  const ProcessedSeries& s = a.series;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    const bool full = s.world_accel_m_s2.size() == s.t_s.size();
    const Vec3 w = s.rate_deg_s.size() == s.t_s.size() ? s.rate_deg_s[k] : a.trace.samples[a.timing.index[k]].rate_deg_s;
    const Vec3 wa = full ? s.world_accel_m_s2[k] : Vec3::Constant(NAN);
    const Vec3 vr = full ? s.remote_velocity_m_s[k] : Vec3::Constant(NAN);
    t.add_row({s.t_s[k], s.accel_g[k].x(), s.accel_g[k].y(), s.accel_g[k].z(), w.x(), w.y(), w.z(),
               double((s.buttons[k] & a.options.release_button) != 0), double((s.flags[k] & kAccelSaturated) != 0), wa.x(),
               wa.y(), wa.z(), vr.x(), vr.y(), vr.z(), full ? s.stone_speed_m_s[k] : NAN});
  }
  return t;
}

std::vector<Figure> figures(const CaptureAnalysis& a, const CaptureSimulation& sim, const Table& trace) {
  std::vector<Figure> figs;
  const std::string mark = markers(a);
  char thr[400];
  std::snprintf(thr, sizeof thr, "set arrow from graph 0, first %g to graph 1, first %g nohead lc rgb '#aa0000' dt 3\n"
                "set arrow from graph 0, first %g to graph 1, first %g nohead lc rgb '#aa0000' dt 3\n",
                a.options.saturation_g, a.options.saturation_g, -a.options.saturation_g, -a.options.saturation_g);
  {
    Figure f;
    f.name = "acceleration";
    f.title = "Accelerometer per axis (g) as recorded; clipped spans shaded red, the still part green, the release dashed";
    f.tables = {{"trace", trace}};
    f.script = mark + thr +
               "set xlabel 't (s)'\nset ylabel 'a (g)'\nset key outside right\nset grid\n"
               "plot 'trace.dat' u 1:2 w lp pt 7 ps 0.3 t 'a_x', '' u 1:3 w lp pt 7 ps 0.3 t 'a_y', "
               "'' u 1:4 w lp pt 7 ps 0.3 t 'a_z'\n";
    figs.push_back(f);
  }
  {
    Figure f;
    f.name = "angular_rate";
    f.title = "MotionPlus angular rate per axis (deg/s), bias removed; the release dashed";
    f.script = mark + "set xlabel 't (s)'\nset ylabel 'rate (deg/s)'\nset key outside right\nset grid\n"
               "plot 'trace.dat' u 1:5 w lp pt 7 ps 0.3 t 'pitch (x)', '' u 1:6 w lp pt 7 ps 0.3 t 'roll (y)', "
               "'' u 1:7 w lp pt 7 ps 0.3 t 'yaw (z)', '' u 1:($8*100) w steps lc rgb '#888888' t 'button (x100)'\n";
    figs.push_back(f);
  }
  if (a.can_throw()) {
    Figure f;
    f.name = "stone_speed";
    f.title = "The stone's speed from the integrated acceleration (from the end of the still part); the release "
              "estimate with its interval";
    Table est;
    est.columns = {"t_s", "speed_m_s", "low_m_s", "high_m_s", "lever_m_s"};
    est.add_row({a.nominal.t_s, a.speed_m_s.nominal, a.speed_m_s.low, a.speed_m_s.high, a.nominal.lever_speed_m_s});
    f.tables = {{"release_estimate", est}};
    f.script = mark + "set xlabel 't (s)'\nset ylabel 'speed (m/s)'\nset key top left\nset grid\n"
               "plot 'trace.dat' u 1:16 w l lw 2 t 'accelerometer (integrated)', "
               "'release_estimate.dat' u 1:2:3:4 w yerrorbars pt 7 ps 1.5 lc rgb '#000000' t 'release estimate', "
               "'' u 1:5 w p pt 5 ps 1.2 t 'lever arm'\n";
    figs.push_back(f);
  }
  {
    Figure f;
    f.name = "timing";
    f.title = "Interval between kept reports (ms) against time: jitter, and gaps where reports were lost";
    Table dt;
    dt.columns = {"t_s", "interval_ms"};
    const auto& idx = a.timing.index;
    for (std::size_t k = 1; k < idx.size(); ++k)
      dt.add_row({a.series.t_s[k], 1e3 * (a.trace.samples[idx[k]].t_s - a.trace.samples[idx[k - 1]].t_s)});
    f.tables = {{"intervals", dt}};
    f.script = "set xlabel 't (s)'\nset ylabel 'interval (ms)'\nset grid\nset key off\n"
               "plot 'intervals.dat' u 1:2 w p pt 7 ps 0.5\n";
    figs.push_back(f);
  }
  if (!sim.bounce_histogram.empty()) {
    Figure f;
    f.name = "bounce_distribution";
    f.title = "Bounce counts of the ensemble of throws drawn from the capture's uncertainty (real-time model)";
    Table h;
    h.columns = {"bounces", "members"};
    for (const auto& [b, n] : sim.bounce_histogram) h.add_row({double(b), double(n)});
    f.tables = {{"bounce_histogram", h}};
    f.script = "set xlabel 'bounces'\nset ylabel 'members'\nset style fill solid 0.6\nset boxwidth 0.8\nset grid y\n"
               "set key off\nset xtics 1\nset yrange [0:*]\nplot 'bounce_histogram.dat' u 1:2 w boxes\n";
    figs.push_back(f);
  }
  if (sim.realtime || sim.reference) {
    Figure f;
    f.name = "trajectory";
    f.title = "Height of the stone's centre against distance for the nominal throw: real-time model and reference";
    std::string plot = "plot ";
    for (const auto* r : {sim.realtime ? &*sim.realtime : nullptr, sim.reference ? &*sim.reference : nullptr}) {
      if (!r || r->trajectory.empty()) continue;
      const std::string name = r == (sim.realtime ? &*sim.realtime : nullptr) ? "realtime_path" : "reference_path";
      Table t;
      t.columns = {"t_s", "x_m", "y_m", "z_m"};
      for (const auto& p : r->trajectory) t.add_row({p.t_s, p.state.position_m.x(), p.state.position_m.y(), p.state.position_m.z()});
      f.tables.emplace_back(name, t);
      plot += std::string(plot.size() > 5 ? ", " : "") + "'" + name + ".dat' u 2:4 w l lw 2 t '" +
              (name == "realtime_path" ? "real-time model" : "reference (CVODE)") + "'";
    }
    if (!f.tables.empty()) {
      f.script = "set xlabel 'x (m)'\nset ylabel 'z (m)'\nset grid\nset key top right\n"
                 "set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb '#3060c0'\n" + plot + "\n";
      figs.push_back(f);
    }
  }
  return figs;
}

void write_data(const fs::path& file, const CaptureAnalysis& a, const CaptureSimulation& sim,
                const CaptureReportContext& c, const Table& trace, const std::vector<Figure>& figs) {
  Hdf5Writer w(file);
  H5Group& root = w.root();
  stamp_provenance(root);
  root.set_attr("capture_file", a.source);
  root.set_attr("capture_format", a.format);
  root.set_attr("verdict", std::string(to_string(a.verdict)));
  root.set_attr("case_file", c.case_file);
  root.set_attr("case_text", c.case_text);
  root.set_attr("command_line", c.command_line);
  root.write_strings("reasons", a.reasons.empty() ? std::vector<std::string>{""} : a.reasons);
  root.write_strings("reader_warnings", a.trace.warnings.empty() ? std::vector<std::string>{""} : a.trace.warnings);
  root.write_strings("mounting", mounting_settings(a.options.mounting));
  root.write_table("trace", trace);
  H5Group timing = root.create_group("timing");
  const TimingStats& t = a.timing.stats;
  timing.set_attr("rate_hz", t.rate_hz);
  timing.set_attr("period_s", t.period_s);
  timing.set_attr("jitter_s", t.jitter_s);
  timing.set_attr("max_jitter_s", t.max_jitter_s);
  timing.set_attr("clock_residual_rms_s", t.clock_residual_rms_s);
  timing.set_attr("gaps", (long long)t.gaps);
  timing.set_attr("dropped_reports", (long long)t.dropped_reports);
  timing.set_attr("repeated_reports", (long long)t.repeated);
  timing.set_attr("samples", (long long)t.samples);
  Table spans;
  spans.columns = {"axis", "t0_s", "t1_s", "samples"};
  for (const auto& s : a.spans) spans.add_row({double(s.axis), s.t0_s, s.t1_s, double(s.samples)});
  if (spans.rows()) root.write_table("saturated_spans", spans);
  Table est;
  est.columns = {"nominal", "low", "high"};
  std::vector<std::string> names;
  for (const auto& [name, v] : std::vector<std::pair<std::string, Interval>>{
           {"release_speed_m_s", a.speed_m_s}, {"accelerometer_speed_m_s", a.accel_speed_m_s},
           {"lever_arm_speed_m_s", a.lever_speed_m_s}, {"attack_angle_deg", a.attack_angle_deg},
           {"path_angle_deg", a.path_angle_deg}, {"spin_rev_s", a.spin_rev_s}, {"release_height_m", a.height_m}}) {
    names.push_back(name);
    est.add_row({v.nominal, v.low, v.high});
  }
  root.write_table("estimates", est);
  root.write_strings("estimate_names", names);
  if (!a.ensemble.empty()) {
    Table e;
    e.columns = {"speed_m_s", "attack_angle_deg", "path_angle_deg", "spin_rev_s", "height_m", "bounces_realtime"};
    for (std::size_t k = 0; k < a.ensemble.size(); ++k) {
      const auto& m = a.ensemble[k];
      e.add_row({m.speed_m_s, m.attack_angle_deg, m.path_angle_deg, m.spin_rev_s, m.height_m,
                 k < sim.ensemble_bounces.size() ? double(sim.ensemble_bounces[k]) : NAN});
    }
    root.write_table("ensemble", e);
  }
  H5Group simg = root.create_group("simulation");
  if (sim.realtime) {
    simg.set_attr("realtime_solver", sim.realtime->solver);
    simg.set_attr("realtime_bounces", (long long)sim.realtime->bounces);
    simg.set_attr("realtime_cpu_s", sim.realtime->stats.cpu_s);
  }
  if (sim.reference) {
    simg.set_attr("reference_solver", sim.reference->solver);
    simg.set_attr("reference_bounces", (long long)sim.reference->bounces);
    simg.set_attr("reference_cpu_s", sim.reference->stats.cpu_s);
    simg.set_attr("reference_outcome", std::string(to_string(sim.reference->outcome)));
  }
  simg.set_attr("ensemble_cpu_s", sim.ensemble_cpu_s);
  H5Group fg = root.create_group("figures");
  for (const auto& f : figs) store_figure(fg, f);
  w.commit();
}

std::string words(const CaptureAnalysis& a, const CaptureSimulation& sim, const CaptureReportContext& c,
                  const std::vector<Figure>& figs) {
  const TimingStats& t = a.timing.stats;
  std::ostringstream md;
  md << "# Capture " << a.source << "\n\n";
  md << "**Verdict: " << to_string(a.verdict) << ".**";
  if (!a.reasons.empty()) {
    md << "\n\n";
    for (const auto& r : a.reasons) md << "* " << r << "\n";
  } else {
    md << " Nothing in this capture limits the estimate beyond the intervals below.\n";
  }
  md << "\nRead as `" << a.format << "`. A Wii Remote stamps nothing itself: the host clock gives the times, the "
        "accelerometer clips near ±3.5 g on every real throw, and the MotionPlus changes range during fast swings "
        "(spec §4). This page says how much of the throw the recording still pins down.\n\n";
  auto find = [&](const std::string& n) {
    for (const auto& f : figs)
      if (f.name == n) return figure_markdown(f);
    return std::string();
  };
  md << "## Timing\n\nThe period is the median interval between kept reports; an interval of 1.5 periods or more "
        "is a gap and round(interval/period) − 1 reports were lost in it; jitter is the standard deviation of the "
        "other intervals. The stamps are then replaced by a straight-line clock fitted through the reports' "
        "positions in the remote's own sequence.\n\n";
  md << MarkdownTable({"quantity", "value"})
            .row({"samples in the file", std::to_string(t.samples)})
            .row({"repeated reports dropped", std::to_string(t.repeated)})
            .row({"rate (Hz)", fmt(t.rate_hz) + (t.nominal ? " (nominal: no timestamps)" : "")})
            .row({"jitter (ms, std / max)", fmt(1e3 * t.jitter_s, 3) + " / " + fmt(1e3 * t.max_jitter_s, 3)})
            .row({"stamp residual from the fitted clock (ms, RMS)", fmt(1e3 * t.clock_residual_rms_s, 3)})
            .row({"gaps / reports lost", std::to_string(t.gaps) + " / " + std::to_string(t.dropped_reports)})
            .row({"longest gap (ms)", fmt(1e3 * t.longest_gap_s, 3)})
            .str()
     << "\n" << find("timing");
  md << "## Saturation, still part, release\n\n";
  md << "An axis reading at or beyond " << fmt(a.options.saturation_g, 3)
     << " g is taken as clipped. The still part (green in the plots) gives the direction of gravity, the check that "
        "|a| is 1 g, and the gyro's bias.\n\n";
  MarkdownTable sat({"quantity", "value"});
  sat.row({"clipped samples (X / Y / Z / any)", std::to_string(a.saturated_samples[0]) + " / " +
                                                  std::to_string(a.saturated_samples[1]) + " / " +
                                                  std::to_string(a.saturated_samples[2]) + " / " + std::to_string(a.saturated_any)})
      .row({"saturated fraction", fmt(a.saturated_fraction, 3)})
      .row({"clipped samples in the swing", std::to_string(a.saturated_in_swing) + " of " + std::to_string(a.swing_samples)})
      .row({"still part (s)", a.still_found ? fmt(a.still_t0_s, 4) + " – " + fmt(a.still_t1_s, 4) : "not found"})
      .row({"still |a| (g)", a.still_found ? fmt(a.still_accel_g, 5) + " (tolerance ±" + fmt(a.options.rules.calibration_caveat_g, 2) + ")" : "–"})
      .row({"gyro bias (deg/s, x y z)", fmt(a.gyro_bias_deg_s.x(), 3) + " " + fmt(a.gyro_bias_deg_s.y(), 3) + " " +
                                            fmt(a.gyro_bias_deg_s.z(), 3)})
      .row({"MotionPlus range switches", std::to_string(a.gyro_range_switches) + (a.trace.gyro_mode_inferred ? " (inferred)" : "")})
      .row({"release (s)", a.release_found ? fmt(a.release_t_s, 5) + " in [" + fmt(a.release_t_low_s, 5) + ", " +
                                                 fmt(a.release_t_high_s, 5) + "]" + (a.release_at_end ? " (file end)" : "")
                                           : "not found"});
  md << sat.str() << "\n" << find("acceleration") << find("angular_rate");
  md << "## The throw\n\nIntervals are the 2.5–97.5 % range of " << a.ensemble.size()
     << " re-runs of the whole chain with perturbed inputs (sensor noise and quantisation, the release time within "
        "its interval, the MotionPlus scale ±"
     << fmt(100 * a.options.gyro_scale_rel_uncertainty, 2) << " %, the lever arm ±"
     << fmt(100 * a.options.mounting.lever_arm_rel_uncertainty, 2) << " %, the start height ±"
     << fmt(a.options.thrower.height_uncertainty_m, 2) << " m"
     << (a.clipped ? ", and the clipped spans filled with random bumps up to " + fmt(a.options.max_accel_g, 3) + " g" : "")
     << ").";
  if (a.clipped)
    md << " **The accelerometer clipped during the swing**, so integrating it gives only a lower bound on the speed; "
          "the speed interval spans from that bound to the integration with every clipped span at "
       << fmt(a.options.max_accel_g, 3)
       << " g, and the throw itself uses the lever-arm velocity (angular rate × lever arm, which the gyro still "
          "measures).";
  md << "\n\n";
  if (a.can_throw()) {
    md << MarkdownTable({"quantity", "estimate [interval]"})
              .row({"release speed (m/s)", interval_text(a.speed_m_s)})
              .row({"… from the accelerometer (m/s)", interval_text(a.accel_speed_m_s) + (a.clipped ? " (clipped: a lower bound, up to the clip-filled bound)" : "")})
              .row({"… from angular rate × lever arm (m/s)", interval_text(a.lever_speed_m_s)})
              .row({"difference accelerometer − lever arm (m/s)", fmt(a.speed_difference_m_s, 3)})
              .row({"attack angle (deg)", interval_text(a.attack_angle_deg)})
              .row({"path angle (deg)", interval_text(a.path_angle_deg)})
              .row({"spin about the stone's normal (rev/s)", interval_text(a.spin_rev_s)})
              .row({"release height (m)", interval_text(a.height_m)})
              .str()
       << "\n" << find("stone_speed");
    md << "The spin is what the remote on the wrist sees: the rotation of the hand. A flick of the fingers at the "
          "release adds spin that no sensor on the wrist can record.\n\n";
  }
  md << "## What the solvers make of it\n\nThe stone and the water come from `" << c.case_file << "` ("
     << c.stone_description << "); its throw is replaced by the capture's release state.\n\n";
  if (sim.realtime || sim.reference) {
    MarkdownTable s({"solver", "bounces", "outcome", "CPU (s)"});
    if (sim.realtime) s.row({sim.realtime->solver, std::to_string(sim.realtime->bounces), to_string(sim.realtime->outcome), fmt(sim.realtime->stats.cpu_s, 3)});
    if (sim.reference) s.row({sim.reference->solver, std::to_string(sim.reference->bounces), to_string(sim.reference->outcome), fmt(sim.reference->stats.cpu_s, 3)});
    md << s.str() << "\n" << find("trajectory");
  } else {
    md << "The solvers did not run (the capture is unusable, or they were switched off).\n\n";
  }
  if (!sim.bounce_histogram.empty()) {
    md << "The ensemble (" << sim.ensemble_bounces.size() << " throws, real-time model, " << fmt(sim.ensemble_cpu_s, 3)
       << " s CPU) gives " << sim.bounces_median << " bounces (median), " << sim.bounces_low << "–" << sim.bounces_high
       << " (2.5–97.5 %): this spread is what the recording cannot decide.\n\n"
       << find("bounce_distribution");
  }
  md << "## Settings\n\nMounting (remote frame): ";
  for (const auto& m : mounting_settings(a.options.mounting)) md << "`" << m << "` ";
  md << "\n\nCommand: `" << c.command_line << "`. Data: `data.h5` (redraw the figures with `stoneskip plot DIR`).\n";
  if (!a.trace.warnings.empty()) {
    md << "\n## Reader warnings\n\n";
    for (std::size_t k = 0; k < a.trace.warnings.size() && k < 20; ++k) md << "* " << a.trace.warnings[k] << "\n";
    if (a.trace.warnings.size() > 20) md << "* … " << a.trace.warnings.size() - 20 << " more\n";
  }
  if (!a.notes.empty()) {
    md << "\n## Notes\n\n";
    for (const auto& n : a.notes) md << "* " << n << "\n";
  }
  return md.str();
}

}  // namespace

CaptureReportSummary write_capture_report(const fs::path& dir, const CaptureAnalysis& a, const CaptureSimulation& sim,
                                          const CaptureReportContext& c) {
  CaptureReportSummary out;
  fs::create_directories(dir);
  const Table trace = trace_table(a);
  const std::vector<Figure> figs = figures(a, sim, trace);
  write_data(dir / "data.h5", a, sim, c, trace, figs);
  out.gnuplot = gnuplot_available();
  if (out.gnuplot) {
    Hdf5Reader in(dir / "data.h5");  // figures are drawn from the stored data
    out.figures = render_figures(dir, load_figures(in.root().open_group("figures")));
  }
  out.index_md = dir / "index.md";
  write_text_file(out.index_md, words(a, sim, c, figs));
  return out;
}

void write_capture_index(const fs::path& dir, const std::vector<CaptureIndexEntry>& entries, const CaptureReportContext& c) {
  std::ostringstream md;
  md << "# Wii Remote captures\n\nEach capture was read, its timing, clipping and still part checked, its release "
        "state estimated with intervals, and the throw run through the real-time model and the reference "
        "(stone and water from `"
     << c.case_file << "`). Follow a capture's link for its page.\n\n";
  MarkdownTable t({"capture", "verdict", "speed (m/s) [interval]", "attack (deg)", "path (deg)", "spin (rev/s)",
                   "bounces real-time / reference / ensemble"});
  for (const auto& e : entries) {
    const CaptureAnalysis& a = *e.analysis;
    std::string b = "–";
    if (e.simulation && (e.simulation->realtime || e.simulation->reference)) {
      const auto* s = e.simulation;
      b = (s->realtime ? std::to_string(s->realtime->bounces) : "–") + " / " +
          (s->reference ? std::to_string(s->reference->bounces) : "–") + " / " +
          (s->ensemble_bounces.empty() ? "–" : std::to_string(s->bounces_low) + "–" + std::to_string(s->bounces_high));
    }
    const bool ok = a.can_throw();
    t.row({"[" + a.source + "](" + e.folder + "/index.md)",
           std::string(to_string(a.verdict)) + (a.reasons.empty() ? "" : ": " + a.reasons.front()),
           ok ? interval_text(a.speed_m_s) : "–", ok ? fmt(a.attack_angle_deg.nominal, 3) : "–",
           ok ? fmt(a.path_angle_deg.nominal, 3) : "–", ok ? fmt(a.spin_rev_s.nominal, 3) : "–", b});
  }
  md << t.str() << "\nCommand: `" << c.command_line << "`\n";
  write_text_file(dir / "index.md", md.str());
}

}  // namespace stoneskip
