#include "verification/stones/validation_scored_value.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "verification/study/words.hpp"

namespace stoneskip {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

ScoredValue scored_value(const Record& g, const std::string& key, const ValidationOptions& o) {
  ScoredValue s;
  s.key = key;
  auto from_bisection = [&](const Record& b) {
    if (b.flag("found")) {
      s.has_value = true;
      s.model = b.number("value");
    } else if (std::isfinite(b.number("bound"))) {
      s.has_value = true;
      s.bound_only = true;
      s.model = b.number("bound");
      s.note = b.text("note") + ": the distance is a lower bound";
    } else {
      s.note = b.text("note");
    }
  };
  auto from_exponent = [&](const Record& e) {
    if (!(e.flag("valid") && e.number("points") >= 3)) {
      s.note = "fewer than 3 points to fit";
    } else if (e.has_number("curved") && e.flag("curved")) {
      // The row's verdict counts no exponent where the points bend (skip_inputs): nor does the
      // distance, which had scored a bent fit's slope as a near hit.
      s.note = "the points bend: no single power law";
    } else {
      s.has_value = true;
      s.model = e.number("exponent");
    }
  };
  if (key == "clanet_min_speed") {
    if (g.has_child("min_speed_at_compared_attack"))
      from_bisection(g.at("min_speed_at_compared_attack"));
    else
      s.note = "the compared attack angle is not on the grid";
  } else if (key == "clanet_best_attack") {
    s.model = g.number("best_attack_deg");
    s.has_value = std::isfinite(s.model);
    // One angle on the grid: its argmin is the angle given, not a result, and was scored as a match.
    const std::size_t angles = g.table("min_speed").rows();
    if (angles < 2) {
      s.has_value = false;
      s.model = kNaN;
      s.note = angles == 0 ? "not measured: the grid holds no attack angle"
                           : "not measured: the grid holds one attack angle (" +
                                 num(g.table("min_speed").column("attack_deg").at(0)) + "°), whose argmin is the angle given";
    } else if (!s.has_value) s.note = "no bounce at any attack angle tried";
    else if (g.has_number("best_attack_tied_low_deg") &&
             g.number("best_attack_tied_low_deg") < g.number("best_attack_tied_high_deg"))
      s.note = "tied: the minimum speeds at " + num(g.number("best_attack_tied_low_deg")) + "–" +
               num(g.number("best_attack_tied_high_deg")) + "° lie within the bisection's bracket of the lowest";
  } else if (key == "clanet_max_path_angle") {
    from_bisection(g.at("largest_path_angle"));
  } else if (key == "clanet_contact_time") {
    const Table& t = g.table("contact_time");
    const std::vector<double>& speeds = t.column("speed_m_s");
    const std::size_t i = static_cast<std::size_t>(std::find(speeds.begin(), speeds.end(), o.contact_time_speed_m_s) - speeds.begin());
    s.model = i < t.rows() ? t.column("contact_s")[i] : kNaN;
    s.has_value = std::isfinite(s.model);
    if (!s.has_value) s.note = "the first contact at " + num(o.contact_time_speed_m_s) + " m/s does not end in a bounce";
  } else if (key == "clanet_contact_exponent") {
    from_exponent(g.at("contact_exponent"));
  } else if (key == "bocquet_speed_exponent" || key == "bocquet_spin_exponent") {
    const std::string fit = key == "bocquet_speed_exponent" ? "speed_exponent" : "spin_exponent";
    if (g.has_child(fit))
      from_exponent(g.at(fit));
    else
      s.note = "Bocquet's stone is not thrown for this variant";
  }
  return s;
}

}  // namespace stoneskip
