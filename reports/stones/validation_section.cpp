// Section 5 of the stones report: each water law beside experiments and analytic models (model/README.md §3),
// and why the two conventions disagree — formatted from the stored record. The measured values
// (and the measured curve) are stored with the findings (they come from the study file), never
// typed in here.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string bisected(const Record& b, const std::string& unit) {
  if (!b.flag("found")) return b.text("note");
  // Two digits of the half-width: one rounded 0.0146 down to 0.01, a third narrower than bisected.
  return fmt(b.number("value"), 3) + " ± " + fmt(b.number("half_width"), 2) + " " + unit;
}

// The contact time at the compared speed, or at the first faster speed with a bouncing first contact.
std::string contact_time_text(const Table& t, double at) {
  const auto U = t.column("speed_m_s"), tau = t.column("contact_s");
  for (std::size_t i = 0; i < U.size(); ++i)
    if (std::abs(U[i] - at) < 1e-9 && std::isfinite(tau[i])) return fmt(1000 * tau[i], 3) + " ms";
  for (std::size_t i = 0; i < U.size(); ++i)
    if (U[i] > at && std::isfinite(tau[i]))
      return "no bounce at " + fmt(at, 3) + " m/s; " + fmt(1000 * tau[i], 3) + " ms at " + fmt(U[i], 3) + " m/s";
  return "no bouncing first contact at the speeds tried";
}

// "−0.98 [−1.1, −0.86]" or "– (1 point with a positive value)".
std::string exponent_text(const Record& e) {
  if (!e.flag("valid")) return "– (" + e.text("problem") + ")";
  if (e.number("points") < 3) return fmt(e.number("exponent"), 3) + " (" + fmt(e.number("points")) + " points, no interval)";
  std::string s = fmt(e.number("exponent"), 3) + " [" + fmt(e.number("exponent_low"), 3) + ", " + fmt(e.number("exponent_high"), 3) + "]";
  if (e.has_number("curved") && e.flag("curved"))
    s += "; bends (F " + fmt(e.number("curvature_f"), 3) + " > " + fmt(e.number("curvature_f_critical"), 3) + "): local " +
         fmt(e.number("local_exponent_min"), 3) + " to " + fmt(e.number("local_exponent_max"), 3);
  return s;
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

std::string attitude_text(const Record& h) {
  const Record& c = h.at("first_contact");
  if (!c.flag("exists")) return "no contact";
  return "pitch " + fmt(c.number("attack_change_deg"), 3) + "° (" + c.at("pitch").text("verdict") + "), roll " +
         fmt(c.number("roll_change_deg"), 3) + "° (" + c.at("roll").text("verdict") + ")";
}

// One variant's cell of a validation row.
std::string model_cell(const Record& g, const std::string& key, const Record& v) {
  if (!g.has_child("seed") && (key.rfind("bocquet_", 0) == 0 || key.rfind("seed_", 0) == 0)) return "not run";
  if (key == "clanet_regime_surfing") return "**" + g.at("regime_verdicts").at("surfing").text("verdict") + "**";
  if (key == "clanet_" + v.text("diving_regime"))
    return "**" + g.at("regime_verdicts").at("diving").text("verdict") + "**: " + regime_text(g.at(v.text("diving_regime")));
  if (key == "clanet_" + v.text("trout_regime"))
    return "**" + g.at("regime_verdicts").at("trout").text("verdict") + "**: " + regime_text(g.at(v.text("trout_regime")));
  if (key == "clanet_" + v.text("held_regime")) return attitude_text(g.at(v.text("held_regime")));
  if (key == "sphere_ricochet") return bisected(g.at("sphere_path_angle"), "°");
  if (key.rfind("seed_", 0) == 0 && !g.has_child("seed")) return "–";
  if (key == "clanet_min_speed")
    return g.has_child("min_speed_at_compared_attack") ? bisected(g.at("min_speed_at_compared_attack"), "m/s") : "–";
  if (key == "clanet_best_attack") {
    // NaN: one angle on the grid, whose argmin is the angle given (validation_findings.cpp).
    const double a = g.number("best_attack_deg");
    if (std::isfinite(a)) return fmt(a, 3) + "°";
    return g.table("min_speed").rows() < 2 ? "not measured (one attack angle on the grid)" : "no bounce at any angle";
  }
  if (key == "clanet_max_path_angle") return bisected(g.at("largest_path_angle"), "°");
  if (key == "clanet_contact_time") return contact_time_text(g.table("contact_time"), v.number("contact_time_speed_m_s"));
  if (key == "clanet_contact_exponent") return exponent_text(g.at("contact_exponent"));
  if (key.rfind("clanet_regime_", 0) == 0) {
    const std::string r = "regime_" + key.substr(14);
    return g.has_child(r) ? regime_text(g.at(r)) : "–";
  }
  if (key == "bocquet_speed_exponent") return exponent_text(g.at("speed_exponent"));
  if (key == "bocquet_spin_exponent") return exponent_text(g.at("spin_exponent"));
  if (key == "bocquet_counts") return counts_text(g.table("bocquet_spin"), "spin_rev_s", "count");
  const Record& seed = g.at("seed");
  if (key == "seed_no_spin") return fmt(seed.number("bounces_without_spin")) + " bounces";
  if (key == "seed_spin") return fmt(seed.number("bounces_with_spin")) + " bounces";
  if (key == "seed_curved")
    return "lateral " + fmt(100 * seed.number("lateral_with_spin_m"), 3) + " cm with spin, " +
           fmt(100 * seed.number("lateral_without_spin_m"), 3) + " cm without";
  return "–";
}

// A curve of every variant: x from `x_column` of table `table`, y from `y_column` (times `scale`).
std::vector<PlotSeries> variant_curves(const Record& vars, const std::string& table, const std::string& x_column,
                                       const std::string& y_column, double scale, bool square_x) {
  std::vector<PlotSeries> ps;
  for (const auto& key : vars.strings("keys")) {
    const Record& g = vars.at(key);
    if (!g.has_table(table)) continue;
    TableSource how;
    how.x_column = x_column;
    how.y_column = y_column;
    how.x_power = square_x ? 2 : 1;
    how.y_scale = scale;
    // Series k in the k-th distinct colour (the min-speed figure's bracket ends match it): 20
    // variants, and gnuplot's 8-colour cycle drew the 1st and 9th alike. The real-time column dashed.
    const int k = static_cast<int>(ps.size());
    ps.push_back(table_series("model: " + g.text("title"), g, table, how,
                              "linespoints" + series_colour(k) + (g.text("solver") == "realtime" ? std::string(" dt 2") : series_dash(k)) +
                                  " pt " + std::to_string(4 + k % 10)));  // squares, circles, triangles, diamonds: not the ends' crosses
  }
  return ps;
}

std::string first_contact_text(const Record& h) {
  const Record& c = h.at("first_contact");
  if (!c.flag("exists")) return "no contact";
  return "first contact " + fmt(1000 * c.number("start_s"), 3) + "–" + fmt(1000 * c.number("end_s"), 3) +
         " ms, pitching the stone " + verdict_markdown(c.at("pitch")) + ", its roll " + verdict_markdown(c.at("roll")) +
         "; speed " + fmt(c.number("entry_speed_m_s"), 3) +
         " → " + fmt(c.number("exit_speed_m_s"), 3) + " m/s; energy " + fmt(c.number("entry_energy_J"), 3) + " → " +
         fmt(c.number("exit_energy_J"), 3) + " J; " + (c.flag("bounced") ? "it takes off again" : "it sinks");
}

}  // namespace

PlotSeries attack_angle_series(const Record& history, const std::string& title, const std::string& style) {
  return table_series(title, history, "history", "t_s", "attack_deg", style);
}

SectionOutput validation_section(const Record& v) {
  SectionWriter w(v, "5. Validation against experiments (model/README.md §3)");
  const Record& vars = v.at("variants");
  std::string titles;
  for (const auto& key : vars.strings("keys")) titles += (titles.empty() ? "" : ", ") + code(vars.at(key).text("title"));
  std::string distributions;
  for (const auto& d : v.strings("distributions")) distributions += (distributions.empty() ? "" : ", ") + code(d);
  w.lead("What is compared.",
         "The model's values, nothing tuned, beside measured ones, for each water law with the coefficient its source "
         "publishes (model/stone/water_laws.hpp), each pressure distribution of the study (" + distributions +
             ": model/stone/pressure_distribution.hpp) and both attitudes: `held` (orientation and angular momentum "
             "as thrown, the torques discarded: the high-spin limit in which Clanet et al. and Rosellini et al. analyse "
             "skipping) and `free` (the 6-DOF stone). Columns: " + titles +
             ". Each is the model itself (CVODE, physical convention, rtol " + fmt(v.number("reference_rtol"), 2) +
             ") unless named `real-time`: the real-time stepper at the study's settings on the study's first law, " +
             code(v.text("default_law")) + ", uniform, free" +
             ((!v.has_text("model_default_law") || v.text("default_law") == v.text("model_default_law")) ? std::string()
                                                                    : " (not the model's default in the physical convention, " +
                                                                          code(v.text("model_default_law")) + " with " +
                                                                          code(v.text("model_default_distribution")) +
                                                                          ", which the shipped throws run)") +
             "; the paper convention is the model with the paper's printed equations (their own law, "
             "Eq. 2, uniform, free). To keep the report's run time, Bocquet's stone and the seed's throws are thrown "
             "only for the uniform, free variants and the paper's (\"not run\" elsewhere). The "
             "model is not expected to match: the differences are model-form error (a force law on a triangle mesh, no "
             "splash, no cavity, no added mass). Minimum speeds and the largest path angles are bisected (smallest speed / "
             "largest angle with at least one bounce) to " + fmt(v.number("speed_tolerance_m_s"), 2) + " m/s and " +
             fmt(v.number("angle_tolerance_deg"), 2) + "°; exponents are least-squares fits of the logarithms with their "
             "95 % interval. An attitude change through a contact within ±" + fmt(v.number("attitude_held_deg"), 2) +
             "° is called held (the verdicts `attack_change`, `roll_change`).");
  const Record& m = v.at("measured");
  auto rows_table = [&](const std::string& kind, bool beside_models_only) {
    // A peer simulator's column where the study names one (data written before: none).
    bool peer = false;  // only in a table with a row that has a peer's value
    if (v.has_text("peer_description") && !v.text("peer_description").empty())
      for (const auto& key : m.strings("keys"))
        peer = peer || (m.at(key).text("kind") == kind && m.at(key).has_text("peer") && m.at(key).text("peer") != "–");
    std::vector<std::string> head{"quantity", "measured", "expected: a 2-D newtonian reduction, attitude held (model/README.md §3)"};
    if (peer) head.push_back("peer: " + v.text("peer_description"));
    head.push_back("source");
    std::vector<std::string> cols;
    for (const auto& key : vars.strings("keys"))
      if (!beside_models_only || vars.at(key).flag("beside_models") || vars.at(key).text("convention") == "paper") {
        cols.push_back(key);
        head.push_back("model: " + vars.at(key).text("title"));
      }
    MarkdownTable t(head);
    for (const auto& key : m.strings("keys")) {
      const Record& row = m.at(key);
      if (row.text("kind") != kind) continue;
      std::vector<std::string> cells{row.text("quantity"), row.text("measured"), row.text("expected")};
      if (peer) cells.push_back(row.has_text("peer") ? row.text("peer") : "–");
      cells.push_back(row.text("source"));
      for (const auto& vk : cols) cells.push_back(model_cell(vars.at(vk), key, v));
      t.row(cells);
    }
    w.table(t);
  };
  rows_table("measurement", false);
  {
    const Record& sp = v.at("sphere");
    w.text("Johnson & Reid's sphere: " + sp.text("stone") + ", thrown without spin at " + fmt(sp.number("speed_m_s"), 3) +
           " m/s; their θ_max ≈ 18°/√σ gives " + fmt(sp.number("theta_max_deg"), 3) + "° (a number quoted by Nagahiro & "
           "Hayakawa 2005, not read from Johnson & Reid here). Regimes at " + fmt(v.number("regime_attack_deg"), 3) +
           "° unless stated: diving without spin (" + fmt(v.number("diving_spin_rev_s"), 3) + " rev/s), the trout (" +
           fmt(v.number("trout_spin_rev_s"), 3) + " rev/s), surfing (α " + fmt(v.number("surfing_attack_deg"), 3) +
           "°, β " + fmt(v.number("surfing_path_angle_deg"), 3) + "°); the rules `surfing`, `diving`, `trout` judge them.");
  }

  // The fitted exponent of the contact time and its verdict, per variant.
  {
    const Record& first = vars.at(vars.strings("keys").front());
    w.lead("Fitted exponents.", "Each against the expected value ± " + fmt(v.number("exponent_tolerance"), 2) +
                                    ": the whole 95 % interval must lie within it (rule `power_law_exponent`). First the "
                                    "series must be one power law: a quadratic term in log–log coordinates, tested by "
                                    "the extra-sum-of-squares F test at 95 % (n ≥ 4 points), that is significant means "
                                    "the local exponent drifts across the speeds, and the verdict is then *not a single "
                                    "power law*, with the exponents between neighbouring speeds beside the fit.");
    MarkdownTable e({"model", "contact time against U (expected " +
                                  fmt(first.at("contact_exponent").at("verdict").number("expected"), 3) + ")"});
    for (const auto& key : vars.strings("keys")) {
      const Record& g = vars.at(key);
      e.row({g.text("title"),
             exponent_text(g.at("contact_exponent")) + ": **" + g.at("contact_exponent").at("verdict").text("verdict") + "**"});
    }
    w.table(e);
  }
  // Each contact's energy balance (a check that can fail: the passivity P ≤ 0 is an identity of the laws).
  {
    w.lead("Energy over each contact.",
           "Clanet's reference throw, each reference variant: the stone's mechanical energy change ΔE over each contact "
           "against the time integral of the fluids' power ∫(F·v + τ·ω) dt (trapezoidal, on samples 20 µs apart), "
           "allowed the quadrature's estimated error plus " +
               fmt(vars.at(vars.strings("keys").front()).at("energy").number("integrator_error_factor"), 3) +
               " × rtol of the energy (rule `contact_energy`: balanced, and passive when no contact gains more than that).");
    MarkdownTable e({"model", "contacts", "ΔE (mJ)", "∫P dt (mJ)", "|ΔE − ∫P dt| (µJ)", "tolerance (µJ)", "verdict"});
    for (const auto& key : vars.strings("keys")) {
      const Record& g = vars.at(key);
      if (!g.has_child("energy")) continue;
      const Record& en = g.at("energy");
      const Table& t = en.table("contacts");
      std::string de, wk, res, tol;
      for (std::size_t i = 0; i < t.rows(); ++i) {
        const std::string sep = i ? ", " : "";
        de += sep + fmt(1000 * t.column("energy_change_J")[i], 4);
        wk += sep + fmt(1000 * t.column("work_J")[i], 4);
        res += sep + fmt(1e6 * std::abs(t.column("energy_change_J")[i] - t.column("work_J")[i]), 2);
        tol += sep + fmt(1e6 * t.column("tolerance_J")[i], 2);
      }
      e.row({g.text("title"), fmt(double(t.rows())), de, wk, res, tol, "**" + en.at("verdict").text("verdict") + "**"});
    }
    w.table(e);
  }

  {
    std::vector<PlotSeries> ps = variant_curves(vars, "min_speed", "attack_deg", "min_speed_m_s", 1, false);
    // Each bisection's bracket, its two ends as small crosses in the variant's colour (linetype k:
    // the variants are the figure's first series), so that a point is read with its width.
    // Where every bracket is narrower than a mark (a fiftieth of the speeds' span), the ends are not
    // drawn and the caption gives the widest bracket instead.
    std::vector<PlotSeries> ends;
    double widest = 0, top = 0;
    {
      int k = 0;
      for (const auto& key : vars.strings("keys")) {
        const Record& g = vars.at(key);
        if (!g.has_table("min_speed")) continue;
        ++k;
        if (!g.table("min_speed").has_column("low_m_s")) continue;  // older data: no ends stored
        const auto lo = g.table("min_speed").column("low_m_s"), hi = g.table("min_speed").column("high_m_s");
        for (std::size_t i = 0; i < lo.size(); ++i)
          if (std::isfinite(lo[i]) && std::isfinite(hi[i])) {
            widest = std::max(widest, hi[i] - lo[i]);
            top = std::max(top, hi[i]);
          }
        for (const char* end : {"low_m_s", "high_m_s"})
          ends.push_back(table_series("", g, "min_speed", "attack_deg", end, "points pt 1 ps 1.3" + series_colour(k - 1)));
      }
    }
    const bool ends_visible = !ends.empty() && widest > top / 50;
    if (ends_visible) ps.insert(ps.end(), ends.begin(), ends.end());
    const Record& curves = v.at("curves");
    for (const auto& ck : curves.strings("keys")) {
      const Record& c = curves.at(ck);
      if (c.text("quantity") != "clanet_min_speed") continue;
      // Open black marks drawn last: the two ends sit 0.1 m/s apart, and filled marks hid one another.
      ps.push_back(table_series("measured, low end", c, "points", "x", "low", "points pt 6 ps 2.5 lw 2 lc rgb 'black'"));
      ps.push_back(table_series("measured, high end", c, "points", "x", "high", "points pt 4 ps 2.5 lw 2 lc rgb 'black'"));
    }
    PlotAxes ax;
    ax.x_label = "attack angle α (deg)";
    ax.y_label = "minimum speed for a bounce (m/s)";
    ax.extra = "set yrange [0:*]";
    w.figure(line_figure("clanet_min_speed", std::string("Clanet's disk: minimum bouncing speed against attack angle at β = 20°, measured and each variant") +
                             (ends.empty()   ? std::string()
                              : ends_visible ? std::string(" (crosses: the ends of each bisection's bracket)")
                                             : " (each bisection's bracket, at most " + fmt(widest, 2) +
                                                   " m/s wide, lies within its mark)"),
                         ax, ps, "attack_deg", "speed_m_s"));
    for (const auto& ck : curves.strings("keys")) {
      const Record& c = curves.at(ck);
      if (c.text("quantity") == "clanet_min_speed")
        w.text("Measured points in the figure: " + c.text("label") + " (" + c.text("source") + ").");
    }
  }
  {
    PlotAxes ax;
    ax.x_label = "speed U (m/s)";
    ax.y_label = "duration of the first contact (ms)";
    std::vector<PlotSeries> ps = variant_curves(vars, "contact_time", "speed_m_s", "contact_s", 1000, false);
    // The measured contact time at its speed, and the measured law through it (τ ∝ U^k), over the
    // speeds the variants were thrown at.
    std::string measured_words;
    const Record& meas = v.at("measured");
    if (meas.has_child("clanet_contact_time") && meas.at("clanet_contact_time").flag("scored") && meas.has_child("clanet_contact_exponent") &&
        meas.at("clanet_contact_exponent").flag("scored")) {
      const Record& mt = meas.at("clanet_contact_time");
      const double U0 = v.number("contact_time_speed_m_s"), tau_ms = 1000 * mt.number("score_low");
      const double k = meas.at("clanet_contact_exponent").number("score_low");
      std::vector<double> speeds;
      for (const auto& key : vars.strings("keys"))
        if (vars.at(key).has_table("contact_time")) {
          speeds = vars.at(key).table("contact_time").column("speed_m_s");
          break;
        }
      // The law over the speeds thrown and the measured one (none where they are one speed).
      speeds.push_back(U0);
      const auto [lo, hi] = std::minmax_element(speeds.begin(), speeds.end());
      if (*lo < *hi) {
        std::vector<double> along;  // 40 points: a curve on the figure's linear axes
        for (int i = 0; i <= 40; ++i) along.push_back(*lo + (*hi - *lo) * i / 40.0);
        ps.push_back(power_law_guide("measured law, τ ∝ U^{" + fmt(k, 3) + "} through the measured point", along, U0, tau_ms, k,
                                     "lines dt 2 lw 2 lc rgb 'black'"));
      }
      if (v.has_table("measured_contact_time"))
        ps.push_back(table_series("measured: " + fmt(tau_ms, 3) + " ms at " + fmt(U0, 3) + " m/s", v, "measured_contact_time",
                                  "speed_m_s", "contact_ms", "points pt 7 ps 2.5 lc rgb 'black'"));
      measured_words = "Measured (black): " + mt.text("measured") + " at " + fmt(U0, 3) + " m/s (" + mt.text("source") +
                       "), and the law τ ∝ U^" + fmt(k, 3) + " through it.";
    }
    w.figure(line_figure("clanet_contact_time", "Clanet's disk: contact time against speed, each variant and the measured value", ax,
                         ps, "speed_m_s", "contact_ms"));
    if (!measured_words.empty()) w.text(measured_words);
  }
  // Attitude (pitch and roll) through the first contact at the trout's and the held spin: every
  // free reference variant (a held one keeps both by construction).
  for (const std::string& regime : {v.text("trout_regime"), v.text("held_regime")}) {
    std::vector<PlotSeries> ps;
    double t_zoom = 0;
    std::string spin;
    for (const auto& key : vars.strings("keys")) {
      const Record& g = vars.at(key);
      if (g.text("solver") != "reference" || g.text("attitude") == "held" || !g.has_child(regime)) continue;
      const Record& h = g.at(regime);
      spin = fmt(h.number("spin_rev_s"), 3);
      // One colour per variant: pitch solid, roll dashed.
      const std::string colour = series_colour(static_cast<int>(ps.size() / 2));
      ps.push_back(table_series(g.text("title") + ": pitch (attack)", h, "history", "t_s", "attack_deg", "lines" + colour));
      ps.push_back(table_series(g.text("title") + ": roll", h, "history", "t_s", "roll_deg", "lines dt 2" + colour));
      if (h.at("first_contact").flag("exists")) t_zoom = std::max(t_zoom, 1.3 * h.at("first_contact").number("end_s"));
    }
    if (ps.empty()) continue;
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "angle (deg)";
    if (t_zoom > 0) ax.extra = "set xrange [0:" + fmt(t_zoom, 3) + "]";
    Figure f = line_figure("attitude_" + regime,
                           "Clanet's disk at " + spin + " rev/s, α = " + fmt(v.number("regime_attack_deg"), 3) +
                               "°: pitch and roll through the first contact, each free variant",
                           ax, ps, "t_s", "angle_deg");
    f.data_path = vars.path();
    w.figure(f);
  }
  {
    // Attack angle through the spin regimes: the default law and the paper convention, every spin.
    std::vector<PlotSeries> ps;
    for (const auto& key : vars.strings("keys")) {
      const Record& g = vars.at(key);
      if (g.text("solver") != "reference" ||
          (g.text("convention") != "paper" && (g.text("law") != v.text("default_law") || !g.flag("beside_models"))))
        continue;
      for (const auto& rk : g.strings("regimes")) {
        const Record& h = g.at(rk);
        ps.push_back(attack_angle_series(h, h.text("label"), h.text("convention") == "paper" ? "lines dt 2" : "lines"));
      }
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "attack angle (deg)";
    Figure f = line_figure("clanet_spin_regimes",
                           "Clanet's disk at α = " + fmt(v.number("regime_attack_deg"), 3) + "°: attack angle for each spin",
                           ax, ps, "t_s", "attack_deg");
    f.data_path = vars.path();
    w.figure(f);
  }
  w.subheading("Model beside model (not scored)");
  w.text("Bocquet's counts and trends are his model's estimates (N ≈ RΩ²/g), not measurements, and the seed's claims "
         "are those of a simulation: compared for trends only, never as a gate.");
  rows_table("model", true);
  {
    const Record& bq = v.at("bocquet");
    w.text("Stone for Bocquet's trends: " + bq.text("stone") + ". Bocquet's N_Ω ≈ RΩ²/g gives " +
           counts_text(bq.table("spin"), "spin_rev_s", "bocquet_N_omega") + " bounces at these spins.");
    std::string expected = "–";
    for (const auto& key : vars.strings("keys"))
      if (vars.at(key).has_child("speed_exponent")) {
        expected = fmt(vars.at(key).at("speed_exponent").at("verdict").number("expected"), 3);
        break;
      }
    MarkdownTable e({"model", "N against V² (expected " + expected + ")", "N against Ω² (expected " + expected + ")"});
    for (const auto& key : vars.strings("keys")) {
      const Record& g = vars.at(key);
      if (!g.has_child("speed_exponent")) continue;
      std::vector<std::string> cells{g.text("title")};
      for (const char* fit : {"speed_exponent", "spin_exponent"})
        cells.push_back(exponent_text(g.at(fit)) + ": **" + g.at(fit).at("verdict").text("verdict") + "**");
      e.row(cells);
    }
    w.table(e);
  }
  {
    const Record& bq = v.at("bocquet");
    std::vector<PlotSeries> ps = variant_curves(vars, "bocquet_speed", "speed_m_s", "count", 1, true);
    TableSource squared;
    squared.x_power = 2;
    squared.x_column = "speed_m_s";
    squared.y_column = "bocquet_shape";
    ps.push_back(table_series("Bocquet's V² shape (scaled to N_Ω at the base speed)", bq, "speed", squared, "lines dt 3"));
    PlotAxes ax;
    ax.x_label = "V² (m²/s²)";
    ax.y_label = "bounces";
    w.figure(line_figure("bocquet_speed", "Bounce count against V² (Bocquet's stone)", ax, ps, "V2_m2_s2", "bounces"));
    std::vector<PlotSeries> qs = variant_curves(vars, "bocquet_spin", "spin_rev_s", "count", 1, true);
    squared.x_column = "spin_rev_s";
    squared.y_column = "bocquet_N_omega";
    // The model's counts set the height; Bocquet's N_Ω, which reaches far higher (it bounds the count
    // by the spin alone), is drawn up to the top and leaves the figure there, said in the caption.
    double most = 0, bocquet_most = 0;
    for (std::size_t i = 0; i + 1 < qs.size(); ++i)
      for (double y : qs[i].y)
        if (std::isfinite(y)) most = std::max(most, y);
    qs.push_back(table_series("Bocquet N_Ω = RΩ²/g", bq, "spin", squared, "lines dt 3"));
    for (double y : qs.back().y)
      if (std::isfinite(y)) bocquet_most = std::max(bocquet_most, y);
    const bool clipped = most > 0 && bocquet_most > 1.5 * most;
    ax.x_label = "Ω² (rev²/s²)";
    if (clipped) ax.extra = "set yrange [0:" + fmt(std::ceil(1.5 * most), 4) + "]";
    w.figure(line_figure("bocquet_spin",
                         "Bounce count against Ω² (Bocquet's stone)" +
                             (clipped ? " — Bocquet's N_Ω leaves the figure, reaching " + fmt(bocquet_most, 3) + " at the largest spin"
                                      : std::string()),
                         ax, qs, "spin2_rev2_s2", "bounces"));
  }

  // Why the conventions disagree.
  const Record& why = v.at("conventions");
  const Record& phys = why.at("physical");
  const Record& pap = why.at("paper");
  w.subheading("Why the two conventions disagree");
  w.text("The seed's spinning throw (" + phys.text("label") + "), solved by the reference in both conventions" +
         ((!v.has_text("model_default_law") || v.text("default_law") == v.text("model_default_law"))
              ? std::string(".")
              : std::string("; the physical one with the study's first law, not the model's default, ") +
                    code(v.text("model_default_law")) + " with " + code(v.text("model_default_distribution")) +
                    ", which the shipped case runs (its bounces may differ)."));
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
      e.push_back(table_series(conv + ": total energy", *h, "history", "t_s", "energy_J", "lines"));
      a.push_back(table_series(conv + ": attack angle", *h, "history", "t_s", "attack_deg", "lines"));
      a.push_back(table_series(conv + ": roll angle", *h, "history", "t_s", "roll_deg", "lines dt 2"));
      p.push_back(table_series(conv + ": fluid power F·v + τ·ω", *h, "history", "t_s", "fluid_power_W", "lines"));
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
