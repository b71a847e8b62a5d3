// Section 5 of the stones report: the model beside experiments and analytic models (spec §3), and
// why the two conventions disagree — formatted from the stored record. The measured values are
// stored with the findings (they come from the study file), never typed in here.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

const char* kVariants[3] = {"reference", "realtime", "paper"};  // model columns of the table

std::string bisected(const Record& b, const std::string& unit) {
  if (!b.flag("found")) return b.text("note");
  return fmt(b.number("value"), 3) + " ± " + fmt(b.number("half_width"), 1) + " " + unit;
}

// The contact time at the compared speed, or at the first faster speed with a bouncing first contact.
std::string contact_time_text(const Table& t, const std::string& column, double at) {
  const auto U = t.column("speed_m_s"), tau = t.column(column);
  for (std::size_t i = 0; i < U.size(); ++i)
    if (std::abs(U[i] - at) < 1e-9 && std::isfinite(tau[i])) return fmt(1000 * tau[i], 3) + " ms";
  for (std::size_t i = 0; i < U.size(); ++i)
    if (U[i] > at && std::isfinite(tau[i]))
      return "no bounce at " + fmt(at, 3) + " m/s; " + fmt(1000 * tau[i], 3) + " ms at " + fmt(U[i], 3) + " m/s";
  return "no bouncing first contact at the speeds tried";
}

std::string regime_text(const Record& g) {
  return "attack " + fmt(g.number("attack_min_deg"), 3) + "…" + fmt(g.number("attack_max_deg"), 3) + "°, " +
         fmt(g.number("attack_after_first_contact_deg"), 3) + "° after 1st contact, |roll| ≤ " +
         fmt(g.number("max_abs_roll_deg"), 3) + "°; " + fmt(g.number("bounces")) + " bounces";
}

std::string counts_text(const Table& t, const std::string& x, const std::string& n) {
  const auto xs = t.column(x), ns = t.column(n);
  std::string s;
  for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? ", " : "") + fmt(xs[i], 3) + "→" + fmt(ns[i], 3);
  return s;
}

// The model's three cells of a validation row (reference physical, real-time physical, paper reference).
std::vector<std::string> model_cells(const Record& v, const std::string& key) {
  const Record& cl = v.at("clanet");
  const Record& bq = v.at("bocquet");
  const Record& seed = v.at("seed");
  std::vector<std::string> out(3, "–");
  const double at = v.number("contact_time_speed_m_s");
  for (int k = 0; k < 3; ++k) {
    const std::string var = kVariants[k];
    const std::string conv = var == "paper" ? "paper" : "physical";
    const std::string seed_key = conv + (var == "realtime" ? "_realtime" : "_reference");
    if (key == "clanet_min_speed" && cl.at("min_speed_" + var).has_child("at_compared_attack"))
      out[k] = bisected(cl.at("min_speed_" + var).at("at_compared_attack"), "m/s");
    else if (key == "clanet_best_attack")
      out[k] = fmt(cl.at("min_speed_" + var).number("best_attack_deg"), 3) + "°";
    else if (key == "clanet_max_path_angle")
      out[k] = bisected(cl.at("largest_path_angle_" + var), "°");
    else if (key == "clanet_contact_time")
      out[k] = contact_time_text(cl.table("contact_time"), "contact_" + var + "_s", at);
    else if (key == "clanet_contact_exponent" && var == "reference")
      out[k] = fmt(cl.number("contact_time_exponent"), 3);
    else if (key.rfind("clanet_regime_", 0) == 0 && var != "realtime") {
      const std::string r = "regime_" + key.substr(14) + "_" + conv;
      if (cl.has_child(r)) out[k] = regime_text(cl.at(r));
    } else if (key == "bocquet_speed_exponent" && var != "realtime")
      out[k] = fmt(bq.number("speed_exponent_" + conv), 3);
    else if (key == "bocquet_spin_exponent" && var != "realtime")
      out[k] = fmt(bq.number("spin_exponent_" + conv), 3);
    else if (key == "bocquet_counts" && var != "realtime")
      out[k] = counts_text(bq.table("spin"), "spin_rev_s", "count_" + conv);
    else if (key == "seed_no_spin" && seed.has_child(seed_key))
      out[k] = fmt(seed.at(seed_key).number("bounces_without_spin")) + " bounces";
    else if (key == "seed_spin" && seed.has_child(seed_key))
      out[k] = fmt(seed.at(seed_key).number("bounces_with_spin")) + " bounces";
    else if (key == "seed_curved" && seed.has_child(seed_key))
      out[k] = "lateral " + fmt(100 * seed.at(seed_key).number("lateral_with_spin_m"), 3) + " cm with spin, " +
               fmt(100 * seed.at(seed_key).number("lateral_without_spin_m"), 3) + " cm without";
  }
  return out;
}

std::string first_contact_text(const Record& h) {
  const Record& c = h.at("first_contact");
  if (!c.flag("exists")) return "no contact";
  return "first contact " + fmt(1000 * c.number("start_s"), 3) + "–" + fmt(1000 * c.number("end_s"), 3) +
         " ms, pitching the stone " + verdict_markdown(c.at("pitch")) + "; speed " + fmt(c.number("entry_speed_m_s"), 3) +
         " → " + fmt(c.number("exit_speed_m_s"), 3) + " m/s; energy " + fmt(c.number("entry_energy_J"), 3) + " → " +
         fmt(c.number("exit_energy_J"), 3) + " J; " + (c.flag("bounced") ? "it takes off again" : "it sinks");
}

}  // namespace

SectionOutput validation_section(const Record& v) {
  SectionWriter w(v, "5. Validation against experiments (spec §3)");
  w.lead("What is compared.",
         "The model's values — computed with the spec's force law, nothing tuned — beside measured ones. The model is not "
         "expected to match: the differences are model-form error (a Newtonian impact law on a triangle mesh, no splash, "
         "no cavity, no added mass). The `reference` column is the model itself (CVODE, rtol " +
             fmt(v.number("reference_rtol"), 2) +
             "); the `real-time` column adds the stepper's discretisation error; `paper` is the model with the paper's "
             "printed equations. Minimum speeds and the largest path angle are bisected (smallest speed / largest angle "
             "with at least one bounce) to " + fmt(v.number("speed_tolerance_m_s"), 2) + " m/s and " +
             fmt(v.number("angle_tolerance_deg"), 2) + "°.");
  const Record& m = v.at("measured");
  MarkdownTable t({"quantity", "measured", "expected (spec §3)", "source", "model: reference (physical)",
                   "model: real-time (physical)", "model: paper convention (reference)"});
  for (const auto& key : m.strings("keys")) {
    const Record& row = m.at(key);
    const auto cells = model_cells(v, key);
    t.row({row.text("quantity"), row.text("measured"), row.text("expected"), row.text("source"), cells[0], cells[1], cells[2]});
  }
  w.table(t);
  const Record& bq = v.at("bocquet");
  w.text("Stone for Bocquet's trends: " + bq.text("stone") + ". Bocquet's N_Ω ≈ RΩ²/g gives " +
         counts_text(bq.table("spin"), "spin_rev_s", "bocquet_N_omega") + " bounces at these spins.");

  const Record& cl = v.at("clanet");
  {
    const Table& ms = cl.table("min_speed");
    PlotSeries a, b, c;
    a.title = "model, reference (physical)";
    b.title = "model, real-time (physical)";
    c.title = "model, paper convention";
    a.x = b.x = c.x = ms.column("attack_deg");
    a.y = ms.column("min_speed_reference_m_s");
    b.y = ms.column("min_speed_realtime_m_s");
    c.y = ms.column("min_speed_paper_m_s");
    PlotAxes ax;
    ax.x_label = "attack angle α (deg)";
    ax.y_label = "minimum speed for a bounce (m/s)";
    ax.extra = "set yrange [0:*]";
    w.figure(line_figure("clanet_min_speed", "Clanet's disk: minimum bouncing speed against attack angle", ax, {a, b, c},
                         "attack_deg", "speed_m_s"));
  }
  {
    const Table& ct = cl.table("contact_time");
    PlotSeries a, b, c;
    a.title = "model, reference (physical)";
    b.title = "model, real-time (physical)";
    c.title = "model, paper convention";
    a.x = b.x = c.x = ct.column("speed_m_s");
    for (auto [p, col] : {std::pair{&a, "contact_reference_s"}, {&b, "contact_realtime_s"}, {&c, "contact_paper_s"}})
      for (double x : ct.column(col)) p->y.push_back(1000 * x);
    PlotAxes ax;
    ax.x_label = "speed U (m/s)";
    ax.y_label = "duration of the first contact (ms)";
    w.figure(line_figure("clanet_contact_time", "Clanet's disk: contact time against speed", ax, {a, b, c}, "speed_m_s",
                         "contact_ms"));
  }
  {
    std::vector<PlotSeries> ps;
    for (const auto& key : cl.strings("regimes")) {
      const Record& h = cl.at(key);
      PlotSeries p;
      p.title = h.text("label");
      p.style = h.text("convention") == "paper" ? "lines dt 2" : "lines";
      p.x = h.table("history").column("t_s");
      p.y = h.table("history").column("attack_deg");
      ps.push_back(p);
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "attack angle (deg)";
    w.figure(line_figure("clanet_spin_regimes",
                         "Clanet's disk at α = " + fmt(cl.number("regime_attack_deg"), 3) + "°: attack angle for each spin",
                         ax, ps, "t_s", "attack_deg"));
  }
  {
    const Table& s = bq.table("speed");
    std::vector<PlotSeries> ps(3);
    ps[0].title = "model, physical";
    ps[1].title = "model, paper convention";
    ps[2].title = "Bocquet's V² shape (scaled to N_Ω at the base speed)";
    ps[2].style = "lines dt 3";
    for (double V : s.column("speed_m_s"))
      for (auto& p : ps) p.x.push_back(V * V);
    ps[0].y = s.column("count_physical");
    ps[1].y = s.column("count_paper");
    ps[2].y = s.column("bocquet_shape");
    PlotAxes ax;
    ax.x_label = "V² (m²/s²)";
    ax.y_label = "bounces";
    w.figure(line_figure("bocquet_speed", "Bounce count against V² (Bocquet's stone)", ax, ps, "V2_m2_s2", "bounces"));
    const Table& o = bq.table("spin");
    std::vector<PlotSeries> qs(3);
    qs[0].title = "model, physical";
    qs[1].title = "model, paper convention";
    qs[2].title = "Bocquet N_Ω = RΩ²/g";
    qs[2].style = "lines dt 3";
    for (double W : o.column("spin_rev_s"))
      for (auto& p : qs) p.x.push_back(W * W);
    qs[0].y = o.column("count_physical");
    qs[1].y = o.column("count_paper");
    qs[2].y = o.column("bocquet_N_omega");
    ax.x_label = "Ω² (rev²/s²)";
    w.figure(line_figure("bocquet_spin", "Bounce count against Ω² (Bocquet's stone)", ax, qs, "spin2_rev2_s2", "bounces"));
  }

  // Why the conventions disagree.
  const Record& why = v.at("conventions");
  const Record& phys = why.at("physical");
  const Record& pap = why.at("paper");
  w.subheading("Why the two conventions disagree");
  w.text("The seed's spinning throw (" + phys.text("label") + "), solved by the reference in both conventions.");
  w.bullet("**physical**: " + first_contact_text(phys) + ". " + fmt(phys.number("bounces")) + " bounces in all; " +
           verdict_markdown(why.at("physical_energy")) + "; |roll| stays below " + fmt(phys.number("max_abs_roll_deg"), 3) + "°.");
  w.bullet("**paper**: " + first_contact_text(pap) + ". " + fmt(pap.number("bounces")) + " bounces in all; " +
           verdict_markdown(why.at("paper_energy")) + "; in flight the attack angle ranges over " +
           fmt(pap.number("attack_min_deg"), 3) + "° … " + fmt(pap.number("attack_max_deg"), 3) + "° with |roll| up to " +
           fmt(pap.number("max_abs_roll_deg"), 3) + "°.");
  w.end_list();
  w.lead("How to read it.",
         "In the physical convention only faces advancing into the water are pushed, so the lift acts on the wetted "
         "trailing part of the stone, behind and below its centre of mass, and its torque r × F turns the stone about its "
         "centre of mass. The paper's printed Eq. 3 (τ = F × r) reverses every torque, so the same lift turns the stone "
         "the other way; its Eq. 1 reverses the spin's contribution to the face velocities and its Eq. 2 lets submerged "
         "faces that retreat from the water push as well, so the water can do positive work on the stone, which no "
         "passive fluid can. The pitch and energy verdicts above say which of these the runs show; where the paper "
         "convention creates energy, its extra bounces are a property of the misprinted equations, not evidence for "
         "them.");
  {
    std::vector<PlotSeries> e, a, p;
    for (const Record* h : {&phys, &pap}) {
      const std::string conv = h->text("convention");
      const Table& hist = h->table("history");
      PlotSeries x;
      x.title = conv + ": total energy";
      x.style = "lines";
      x.x = hist.column("t_s");
      x.y = hist.column("energy_J");
      e.push_back(x);
      PlotSeries y1, y2;
      y1.title = conv + ": attack angle";
      y2.title = conv + ": roll angle";
      y1.style = "lines";
      y2.style = "lines dt 2";
      y1.x = y2.x = hist.column("t_s");
      y1.y = hist.column("attack_deg");
      y2.y = hist.column("roll_deg");
      a.push_back(y1);
      a.push_back(y2);
      PlotSeries z;
      z.title = conv + ": fluid power F·v + τ·ω";
      z.style = "lines";
      z.x = hist.column("t_s");
      z.y = hist.column("fluid_power_W");
      p.push_back(z);
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    double t_zoom = 0.1;
    for (const Record* h : {&phys, &pap})
      if (h->at("first_contact").flag("exists")) t_zoom = std::max(t_zoom, 1.5 * h->at("first_contact").number("end_s"));
    ax.y_label = "angle (deg)";
    ax.extra = "set xrange [0:" + fmt(t_zoom, 3) + "]";
    Figure f4 = line_figure("conventions_first_contact", "Attitude through the first contact, both conventions", ax, a, "t_s",
                            "angle_deg");
    f4.data_path = why.path();
    w.figure(f4);
    ax.extra.clear();
    ax.y_label = "mechanical energy (J)";
    Figure f1 = line_figure("conventions_energy", "Energy of the seed's spinning throw in both conventions", ax, e, "t_s", "energy_J");
    f1.data_path = why.path();
    w.figure(f1);
    ax.y_label = "angle (deg)";
    Figure f2 = line_figure("conventions_attitude", "Attitude of the seed's spinning throw in both conventions", ax, a, "t_s", "angle_deg");
    f2.data_path = why.path();
    w.figure(f2);
    ax.y_label = "rate of work of water and air on the stone (W)";
    Figure f3 = line_figure("conventions_power", "Rate of work of the fluids (positive: energy created)", ax, p, "t_s", "power_W");
    f3.data_path = why.path();
    w.figure(f3);
  }
  return w.finish();
}

}  // namespace stoneskip
