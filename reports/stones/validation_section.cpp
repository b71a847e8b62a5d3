// Section 5 of the stones report: the model beside experiments and analytic models (spec §3), and
// why the two conventions disagree.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/plot_helpers.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string bisected(const BisectedValue& b, const std::string& unit) {
  if (!b.found) return b.note;
  return fmt(b.value(), 3) + " ± " + fmt(0.5 * (b.hi - b.lo), 1) + " " + unit;
}

// The attack angle of the smallest minimum speed (NaN when none bounced).
double best_attack(const std::vector<double>& alpha, const std::vector<BisectedValue>& v) {
  double best = std::nan(""), speed = 1e300;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i].found && v[i].value() < speed) {
      speed = v[i].value();
      best = alpha[i];
    }
  return best;
}

double value_at(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i] - at) < 1e-9) return y[i];
  return std::nan("");
}

// "32.1 ms" at 3.5 m/s, or the first speed above it with a bouncing first contact.
std::string contact_time_text(const std::vector<double>& U, const std::vector<double>& t) {
  const double at = value_at(U, t, 3.5);
  if (std::isfinite(at)) return fmt(1000 * at, 3) + " ms";
  for (std::size_t i = 0; i < U.size(); ++i)
    if (U[i] > 3.5 && std::isfinite(t[i]))
      return "no bounce at 3.5 m/s; " + fmt(1000 * t[i], 3) + " ms at " + fmt(U[i], 2) + " m/s";
  return "no bouncing first contact at the speeds tried";
}

struct AttitudeSummary {
  double min_deg = 0, max_deg = 0, end_of_first_contact_deg = 0, max_roll_deg = 0;
};

AttitudeSummary attitude_summary(const ThrowHistory& h) {
  AttitudeSummary s;
  const auto t = h.table.column("t_s");
  const auto a = h.table.column("attack_deg");
  const auto r = h.table.column("roll_deg");
  if (t.empty()) return s;
  s.min_deg = *std::min_element(a.begin(), a.end());
  s.max_deg = *std::max_element(a.begin(), a.end());
  for (double x : r) s.max_roll_deg = std::max(s.max_roll_deg, std::abs(x));
  const double t_end = h.result.contacts.empty() ? t.back() : h.result.contacts[0].end_s;
  std::size_t i = 0;
  while (i + 1 < t.size() && t[i] < t_end) ++i;
  s.end_of_first_contact_deg = a[i];
  return s;
}

double max_of(const std::vector<double>& v) {
  double m = -1e300;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, x);
  return m;
}

int contacts_gaining_energy(const ThrowHistory& h) {
  int n = 0;
  for (const auto& c : h.result.contacts) n += c.exit_energy_J > c.entry_energy_J ? 1 : 0;
  return n;
}

std::string counts_text(const std::vector<double>& x, const std::vector<int>& n) {
  std::ostringstream s;
  for (std::size_t i = 0; i < x.size(); ++i) s << (i ? ", " : "") << fmt(x[i], 3) << "→" << n[i];
  return s.str();
}

}  // namespace

SectionOutput validation_section(const ValidationResult& v, const H5Group& data) {
  SectionOutput out;
  H5Group g = data.create_group("validation");
  const ClanetResult& C = v.clanet;
  const BocquetResult& B = v.bocquet;
  // Data.
  {
    Table t;
    t.columns = {"attack_deg", "min_speed_reference_m_s", "min_speed_realtime_m_s", "min_speed_paper_m_s"};
    for (std::size_t i = 0; i < C.attack_deg.size(); ++i)
      t.add_row({C.attack_deg[i], C.min_speed_reference[i].found ? C.min_speed_reference[i].value() : std::nan(""),
                 C.min_speed_realtime[i].found ? C.min_speed_realtime[i].value() : std::nan(""),
                 C.min_speed_paper[i].found ? C.min_speed_paper[i].value() : std::nan("")});
    g.write_table("clanet_min_speed", t);
    Table c;
    c.columns = {"speed_m_s", "contact_reference_s", "contact_realtime_s", "contact_paper_s"};
    for (std::size_t i = 0; i < C.contact_speeds_m_s.size(); ++i)
      c.add_row({C.contact_speeds_m_s[i], C.contact_time_reference_s[i], C.contact_time_realtime_s[i], C.contact_time_paper_s[i]});
    g.write_table("clanet_contact_time", c);
    Table bs;
    bs.columns = {"speed_m_s", "count_physical", "count_paper", "bocquet_shape"};
    for (std::size_t i = 0; i < B.speeds_m_s.size(); ++i)
      bs.add_row({B.speeds_m_s[i], static_cast<double>(B.count_vs_speed_physical[i]),
                  static_cast<double>(B.count_vs_speed_paper[i]), B.bocquet_speed_prediction[i]});
    g.write_table("bocquet_speed", bs);
    Table bw;
    bw.columns = {"spin_rev_s", "count_physical", "count_paper", "bocquet_N_omega"};
    for (std::size_t i = 0; i < B.spins_rev_s.size(); ++i)
      bw.add_row({B.spins_rev_s[i], static_cast<double>(B.count_vs_spin_physical[i]),
                  static_cast<double>(B.count_vs_spin_paper[i]), B.bocquet_spin_prediction[i]});
    g.write_table("bocquet_spin", bw);
    H5Group sr = g.create_group("spin_regimes");
    for (const auto& h : C.spin_regimes) write_history(sr, history_group_name(h.label), h);
  }

  std::ostringstream md;
  md << "## 5. Validation against experiments (spec §3)\n\n"
     << "**What is compared.** The model's values — computed with the spec's force law, nothing tuned — beside "
        "measured ones. The model is not expected to match: the differences are model-form error (a Newtonian "
        "impact law on a triangle mesh, no splash, no cavity, no added mass). The `reference` column is the model "
        "itself (CVODE, rtol " << "1e-7" << "); the `real-time` column adds the stepper's discretisation error; "
        "`paper` is the model with the paper's printed equations. Minimum speeds and the largest path angle are "
        "bisected (smallest speed / largest angle with at least one bounce).\n\n";
  const std::size_t i20 = std::find(C.attack_deg.begin(), C.attack_deg.end(), 20.0) - C.attack_deg.begin();
  const auto at20 = [&](const std::vector<BisectedValue>& x) {
    return i20 < x.size() ? bisected(x[i20], "m/s") : std::string("–");
  };
  const ThrowHistory* regime[3][2] = {};
  for (std::size_t k = 0; k < C.spin_regimes.size() && k < 6; ++k) regime[k / 2][k % 2] = &C.spin_regimes[k];
  auto regime_text = [&](int k, int c) {
    if (!regime[k][c]) return std::string("–");
    const AttitudeSummary s = attitude_summary(*regime[k][c]);
    return "attack " + fmt(s.min_deg, 3) + "…" + fmt(s.max_deg, 3) + "°, " + fmt(s.end_of_first_contact_deg, 3) +
           "° after 1st contact, |roll| ≤ " + fmt(s.max_roll_deg, 3) + "°; " + std::to_string(regime[k][c]->result.bounces) +
           " bounces";
  };
  MarkdownTable t({"quantity", "measured", "expected (2-D reduction, spec §3)", "model: reference (physical)",
                   "model: real-time (physical)", "model: paper convention (reference)"});
  t.row({"Clanet: min. bouncing speed at α = 20°, β = 20°, 65 rev/s", "≈ 2.5–2.6 m/s", "≈ 2.9–3.0 m/s",
         at20(C.min_speed_reference), at20(C.min_speed_realtime), at20(C.min_speed_paper)});
  t.row({"Clanet: attack angle of the lowest minimum speed", "≈ 20°", "≈ 25–30°",
         fmt_or_dash(best_attack(C.attack_deg, C.min_speed_reference), 3) + "°",
         fmt_or_dash(best_attack(C.attack_deg, C.min_speed_realtime), 3) + "°",
         fmt_or_dash(best_attack(C.attack_deg, C.min_speed_paper), 3) + "°"});
  t.row({"Clanet: largest bouncing path angle β (3.5 m/s, α = 20°)", "≈ 45°", "≈ 32°",
         bisected(C.largest_path_angle_reference, "°"), bisected(C.largest_path_angle_realtime, "°"),
         bisected(C.largest_path_angle_paper, "°")});
  t.row({"Clanet: contact time at 3.5 m/s (bouncing contacts only)", "≈ 32 ms", "≈ 49 ms",
         contact_time_text(C.contact_speeds_m_s, C.contact_time_reference_s),
         contact_time_text(C.contact_speeds_m_s, C.contact_time_realtime_s),
         contact_time_text(C.contact_speeds_m_s, C.contact_time_paper_s)});
  t.row({"Clanet: contact time ∝ U^k, k = (fit over the bouncing speeds)", "≈ −1", "–", fmt_or_dash(C.contact_time_exponent, 3),
         "–", "–"});
  t.row({"Clanet: no spin (α = 35°)", "tumbles", "–", regime_text(0, 0), "–", regime_text(0, 1)});
  t.row({"Clanet: 10 rev/s (α = 35°)", "attack dips and recovers", "–", regime_text(1, 0), "–", regime_text(1, 1)});
  t.row({"Clanet: 65 rev/s (α = 35°)", "attack held", "–", regime_text(2, 0), "–", regime_text(2, 1)});
  t.row({"Bocquet: N against V (exponent of N ∝ V^k where N > 0)", "k = 2", "–", fmt_or_dash(B.speed_exponent_physical, 3),
         "–", fmt_or_dash(B.speed_exponent_paper, 3)});
  t.row({"Bocquet: N against Ω (exponent of N ∝ Ω^k where N > 0)", "k = 2", "–", fmt_or_dash(B.spin_exponent_physical, 3),
         "–", fmt_or_dash(B.spin_exponent_paper, 3)});
  t.row({"Bocquet: counts at 12 m/s, 5 / 9 / 14 rev/s", "5 / ≈15 / 38–40", "–",
         counts_text(B.spins_rev_s, B.count_vs_spin_physical), "–", counts_text(B.spins_rev_s, B.count_vs_spin_paper)});
  const SeedClaim* seed[2][2] = {};
  for (const auto& s : v.seed) seed[s.convention == "paper"][s.solver == "real-time"] = &s;
  auto seed_cell = [&](int c, int s, int what) {
    const SeedClaim* k = seed[c][s];
    if (!k) return std::string("–");
    switch (what) {
      case 0: return std::to_string(k->bounces_without_spin) + " bounces";
      case 1: return std::to_string(k->bounces_with_spin) + " bounces";
      default:
        return "lateral " + fmt(100 * k->lateral_with_spin_m, 3) + " cm with spin, " + fmt(100 * k->lateral_without_spin_m, 3) +
               " cm without";
    }
  };
  t.row({"Lee & Baek: 8 m/s without spin", "3 bounces", "–", seed_cell(0, 0, 0), seed_cell(0, 1, 0), seed_cell(1, 0, 0)});
  t.row({"Lee & Baek: 8 m/s with spin" +
             (v.fig9.size() > 4 ? " (" + v.fig9[4].label.substr(0, v.fig9[4].label.find(", ", v.fig9[4].label.find(", ") + 2)) + ")"
                                : std::string()),
         "more bounces than without", "–", seed_cell(0, 0, 1), seed_cell(0, 1, 1), seed_cell(1, 0, 1)});
  t.row({"Lee & Baek: curved path with spin", "visibly curved", "–", seed_cell(0, 0, 2), seed_cell(0, 1, 2), seed_cell(1, 0, 2)});
  md << t.str() << "\n";
  md << "Stone for Bocquet's trends: " << B.stone << " (his example: 0.1 kg, 10 cm, 12 m/s, 14 rev/s, θ = 10°). "
     << "Bocquet's N_Ω ≈ RΩ²/g gives " << counts_text(B.spins_rev_s, [&] {
          std::vector<int> n;
          for (double x : B.bocquet_spin_prediction) n.push_back(static_cast<int>(std::lround(x)));
          return n;
        }())
     << " bounces at these spins.\n\n";

  // Figures.
  {
    PlotSeries a, b, c, m;
    a.title = "model, reference (physical)";
    b.title = "model, real-time (physical)";
    c.title = "model, paper convention";
    m.title = "measured near α = 20° (Clanet et al. 2004)";
    m.style = "points pt 7 ps 1.5";
    for (std::size_t i = 0; i < C.attack_deg.size(); ++i) {
      a.x.push_back(C.attack_deg[i]);
      b.x.push_back(C.attack_deg[i]);
      c.x.push_back(C.attack_deg[i]);
      a.y.push_back(C.min_speed_reference[i].found ? C.min_speed_reference[i].value() : std::nan(""));
      b.y.push_back(C.min_speed_realtime[i].found ? C.min_speed_realtime[i].value() : std::nan(""));
      c.y.push_back(C.min_speed_paper[i].found ? C.min_speed_paper[i].value() : std::nan(""));
    }
    m.x = {20.0};
    m.y = {2.55};
    PlotAxes ax;
    ax.x_label = "attack angle α (deg)";
    ax.y_label = "minimum speed for a bounce (m/s)";
    ax.extra = "set yrange [0:*]";
    Figure f = line_figure("clanet_min_speed", "Clanet's disk: minimum bouncing speed against attack angle (β = 20°, 65 rev/s)",
                           ax, {a, b, c, m}, "attack_deg", "speed_m_s");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  {
    PlotSeries a, b, c, m;
    a.title = "model, reference (physical)";
    b.title = "model, real-time (physical)";
    c.title = "model, paper convention";
    m.title = "measured: 32 ms at 3.5 m/s, ∝ 1/U";
    m.style = "lines dt 3";
    a.x = b.x = c.x = C.contact_speeds_m_s;
    for (std::size_t i = 0; i < C.contact_speeds_m_s.size(); ++i) {
      a.y.push_back(1000 * C.contact_time_reference_s[i]);
      b.y.push_back(1000 * C.contact_time_realtime_s[i]);
      c.y.push_back(1000 * C.contact_time_paper_s[i]);
      m.x.push_back(C.contact_speeds_m_s[i]);
      m.y.push_back(32.0 * 3.5 / C.contact_speeds_m_s[i]);
    }
    PlotAxes ax;
    ax.x_label = "speed U (m/s)";
    ax.y_label = "duration of the first contact (ms)";
    Figure f = line_figure("clanet_contact_time", "Clanet's disk: contact time against speed", ax, {a, b, c, m}, "speed_m_s",
                           "contact_ms");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  {
    std::vector<PlotSeries> ps;
    for (const auto& h : C.spin_regimes) {
      PlotSeries p;
      p.title = h.label;
      p.style = h.convention == Convention::paper ? "lines dt 2" : "lines";
      p.x = h.table.column("t_s");
      p.y = h.table.column("attack_deg");
      ps.push_back(p);
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "attack angle (deg)";
    Figure f = line_figure("clanet_spin_regimes", "Clanet's disk at α = 35°, β = 20°: attack angle for 0, 10, 65 rev/s",
                           ax, ps, "t_s", "attack_deg");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  {
    std::vector<PlotSeries> ps(3);
    ps[0].title = "model, physical";
    ps[1].title = "model, paper convention";
    ps[2].title = "Bocquet's V² shape (scaled to N_Ω at 12 m/s)";
    ps[2].style = "lines dt 3";
    for (std::size_t i = 0; i < B.speeds_m_s.size(); ++i) {
      const double x = B.speeds_m_s[i] * B.speeds_m_s[i];
      for (auto& p : ps) p.x.push_back(x);
      ps[0].y.push_back(B.count_vs_speed_physical[i]);
      ps[1].y.push_back(B.count_vs_speed_paper[i]);
      ps[2].y.push_back(B.bocquet_speed_prediction[i]);
    }
    PlotAxes ax;
    ax.x_label = "V² (m²/s²)";
    ax.y_label = "bounces";
    Figure f = line_figure("bocquet_speed", "Bounce count against V² (Bocquet's stone, 14 rev/s)", ax, ps, "V2_m2_s2", "bounces");
    md << figure_markdown(f);
    out.figures.push_back(f);
    std::vector<PlotSeries> qs(3);
    qs[0].title = "model, physical";
    qs[1].title = "model, paper convention";
    qs[2].title = "Bocquet N_Ω = RΩ²/g";
    qs[2].style = "lines dt 3";
    for (std::size_t i = 0; i < B.spins_rev_s.size(); ++i) {
      const double x = B.spins_rev_s[i] * B.spins_rev_s[i];
      for (auto& p : qs) p.x.push_back(x);
      qs[0].y.push_back(B.count_vs_spin_physical[i]);
      qs[1].y.push_back(B.count_vs_spin_paper[i]);
      qs[2].y.push_back(B.bocquet_spin_prediction[i]);
    }
    ax.x_label = "Ω² (rev²/s²)";
    Figure f2 = line_figure("bocquet_spin", "Bounce count against Ω² (Bocquet's stone, 12 m/s)", ax, qs, "spin2_rev2_s2", "bounces");
    md << figure_markdown(f2);
    out.figures.push_back(f2);
  }

  // Why the conventions disagree.
  if (v.fig9.size() >= 8) {
    const ThrowHistory& phys = v.fig9[4];
    const ThrowHistory& pap = v.fig9[6];
    const AttitudeSummary sp = attitude_summary(phys), sq = attitude_summary(pap);
    auto first = [](const ThrowHistory& h) -> const ContactRecord* {
      return h.result.contacts.empty() ? nullptr : &h.result.contacts.front();
    };
    auto contact_text = [&](const ThrowHistory& h) {
      const ContactRecord* c = first(h);
      if (!c) return std::string("no contact");
      std::ostringstream s;
      s << "first contact " << fmt(1000 * c->start_s, 3) << "–" << fmt(1000 * c->end_s, 3) << " ms: attack angle "
        << fmt(c->entry_attack_angle_deg, 3) << "° at entry, " << fmt(c->exit_attack_angle_deg, 3) << "° at the end; speed "
        << fmt(c->entry_speed_m_s, 3) << " → " << fmt(c->exit_speed_m_s, 3) << " m/s; energy " << fmt(c->entry_energy_J, 3)
        << " → " << fmt(c->exit_energy_J, 3) << " J; " << (c->bounced ? "it takes off again" : "it sinks");
      return s.str();
    };
    md << "### Why the two conventions disagree\n\n"
       << "The seed's spinning 8 m/s throw (" << phys.label.substr(0, phys.label.find(',', phys.label.find(',') + 1))
       << "), solved by the reference in both conventions.\n\n"
       << "* **physical**: " << contact_text(phys) << ". " << phys.result.bounces << " bounces in all; the largest "
       << "rate of work of water and air on the stone is " << fmt(max_of(phys.table.column("fluid_power_W")), 3)
       << " W — never positive, as spec §1.6 requires; |roll| stays below " << fmt(sp.max_roll_deg, 3) << "°.\n"
       << "* **paper**: " << contact_text(pap) << ". " << pap.result.bounces << " bounces in all; the fluids' rate of "
       << "work reaches +" << fmt(max_of(pap.table.column("fluid_power_W")), 3) << " W, " << contacts_gaining_energy(pap)
       << " of " << pap.result.contacts.size() << " contacts end with more energy than they began with (largest gain "
       << fmt(pap.result.max_energy_gain_J, 3) << " J), and in flight the attack angle swings between "
       << fmt(sq.min_deg, 3) << "° and " << fmt(sq.max_deg, 3) << "° with |roll| up to " << fmt(sq.max_roll_deg, 3)
       << "°: the stone wobbles and, after later contacts, flips over.\n\n"
       << "Why. In the physical convention only faces advancing into the water are pushed, so the lift acts on the "
          "wetted trailing part of the stone, behind and below its centre of mass: its torque r × F pitches the nose "
          "down (the attack angle falls during the contact, see the zoomed figure), the stone meets the water ever "
          "flatter and deeper, and the contact becomes a planing run that ends in sinking. The paper's printed Eq. 3 "
          "(τ = F × r) reverses every torque, so the same lift pitches the nose *up* instead; its Eq. 1 reverses the "
          "spin's contribution to the face velocities and its Eq. 2 lets submerged faces that retreat from the water "
          "push as well, so the water can do positive work on the stone — it leaves the first contact with more "
          "energy than it brought, which no passive fluid can give. More bounces in the paper convention, and their "
          "growth with spin, are therefore a property of the misprinted equations, not evidence of the stabilising "
          "effect of spin.\n\n";
    std::vector<PlotSeries> e, a, p;
    for (const ThrowHistory* h : {&phys, &pap}) {
      const std::string conv = to_string(h->convention);
      PlotSeries x;
      x.title = conv + ": total energy";
      x.style = "lines";
      x.x = h->table.column("t_s");
      x.y = h->table.column("energy_J");
      e.push_back(x);
      PlotSeries y1, y2;
      y1.title = conv + ": attack angle";
      y2.title = conv + ": roll angle";
      y1.style = "lines";
      y2.style = "lines dt 2";
      y1.x = y2.x = h->table.column("t_s");
      y1.y = h->table.column("attack_deg");
      y2.y = h->table.column("roll_deg");
      a.push_back(y1);
      a.push_back(y2);
      PlotSeries z;
      z.title = conv + ": fluid power F·v + τ·ω";
      z.style = "lines";
      z.x = h->table.column("t_s");
      z.y = h->table.column("fluid_power_W");
      p.push_back(z);
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "mechanical energy (J)";
    Figure f1 = line_figure("conventions_energy", "Energy of the seed's spinning 8 m/s throw in both conventions", ax, e, "t_s", "energy_J");
    ax.y_label = "angle (deg)";
    Figure f2 = line_figure("conventions_attitude", "Attitude of the seed's spinning 8 m/s throw in both conventions", ax, a, "t_s", "angle_deg");
    ax.y_label = "rate of work of water and air on the stone (W)";
    Figure f3 = line_figure("conventions_power", "Rate of work of the fluids (positive: energy created)", ax, p, "t_s", "power_W");
    ax.y_label = "angle (deg)";
    const ContactRecord* c0 = first(pap);
    const ContactRecord* c1 = first(phys);
    const double t_zoom = 1.5 * std::max(c0 ? c0->end_s : 0.1, c1 ? c1->end_s : 0.1);
    ax.extra = "set xrange [0:" + fmt(t_zoom, 3) + "]";
    Figure f4 = line_figure("conventions_first_contact", "Attitude through the first contact, both conventions", ax, a, "t_s",
                            "angle_deg");
    md << figure_markdown(f4) << figure_markdown(f1) << figure_markdown(f2) << figure_markdown(f3);
    out.figures.push_back(f4);
    out.figures.push_back(f1);
    out.figures.push_back(f2);
    out.figures.push_back(f3);
  }
  out.markdown = md.str();
  return out;
}

}  // namespace stoneskip
