#include "verification/stones/bounce_baseline.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "tools/io/input_error.hpp"
#include "tools/io/toml_table.hpp"
#include "tools/scene/case_problem.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

std::string num(double v) {
  // The shortest of %.15g / %.17g that reads back exactly.
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::strtod(buf, nullptr) != v) std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep TOML floats floats
  return s;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

template <class T, class F>
std::string array(const std::vector<T>& v, F f) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + f(v[i]);
  return s + "]";
}

std::string unit_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return "rev/s";
    case SweepParameter::speed_m_s: return "m/s";
    default: return "deg";
  }
}

}  // namespace

BounceBaseline read_baseline(const std::string& path) {
  if (!fs::exists(path)) throw_input_error(path, 0, "", "baseline file not found");
  const TomlDocument doc = load_toml(path);
  TomlTable top = doc.top();
  BounceBaseline b;
  b.file = path;
  TomlTable t = top.table("baseline");
  b.name = t.string("name");
  for (char c : b.name)
    if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_'))
      t.fail("name", "use only a-z, 0-9 and _");
  b.description = t.string_or("description", "");
  b.case_file = t.string("case");
  const std::string param = t.string("parameter");
  if (!parse_sweep_parameter(param, b.parameter))
    t.fail("parameter", "'" + param + "' is not one of spin_rev_s, speed_m_s, attack_angle_deg, path_angle_deg");
  b.values = t.numbers("values");
  if (b.values.size() < 2) t.fail("values", "need at least two grid values");
  for (std::size_t i = 1; i < b.values.size(); ++i)
    if (!(b.values[i] > b.values[i - 1])) t.fail("values", "must be strictly ascending");
  const std::string conv = t.string("convention");
  if (!parse_convention(conv, b.convention)) t.fail("convention", "'" + conv + "' is not physical or paper");
  const std::string law = t.string_or("water_law", to_string(b.water_law));
  if (!parse_water_law(law, b.water_law)) t.fail("water_law", "'" + law + "' is not newtonian, planing or lift_drag");
  if (b.convention == Convention::paper && b.water_law != WaterLaw::newtonian)
    t.fail("water_law", "the paper convention has the printed (newtonian) law only");
  const std::string solver = t.string("solver");
  if (solver == "realtime") {
    b.solver = SolverKind::realtime;
    b.scheme = t.string_or("scheme", "");
    Scheme sc;
    if (!b.scheme.empty() && !parse_scheme(b.scheme, sc))
      t.fail("scheme", "'" + b.scheme + "' is not semi_implicit_euler, midpoint or rk4");
    b.dt_s = t.number_or("dt_s", 0);
    b.contact_dt_s = t.number_or("contact_dt_s", 0);
    t.require_non_negative("dt_s", b.dt_s);
    t.require_non_negative("contact_dt_s", b.contact_dt_s);
  } else if (solver == "reference") {
    b.solver = SolverKind::reference;
    b.method = t.string_or("method", "");
    ReferenceMethod m;
    if (!b.method.empty() && !parse_reference_method(b.method, m)) t.fail("method", "'" + b.method + "' is not bdf or adams");
    b.rtol = t.number_or("rtol", 0);
    b.atol = t.number_or("atol", 0);
    t.require_non_negative("rtol", b.rtol);
    t.require_non_negative("atol", b.atol);
    b.restart = t.string_or("restart", "");
    RestartStrategy rs;
    if (!b.restart.empty() && !parse_restart_strategy(b.restart, rs))
      t.fail("restart", "'" + b.restart + "' is not every_event, every_crossing, at_jumps or never");
  } else {
    t.fail("solver", "'" + solver + "' is not realtime or reference");
  }
  b.t_max_s = t.number_or("t_max_s", 0);
  t.require_non_negative("t_max_s", b.t_max_s);
  b.threshold_tolerance = t.number("threshold_tolerance");
  t.require_positive("threshold_tolerance", b.threshold_tolerance);
  b.compare_tolerance = t.number_or("compare_tolerance", 2 * b.threshold_tolerance);
  t.require_positive("compare_tolerance", b.compare_tolerance);
  t.finish();

  if (auto r = top.maybe_table("result")) {
    b.has_result = true;
    b.generated = r->string_or("generated", "");
    for (double c : r->numbers("counts")) {
      if (c != std::floor(c) || c < -1) r->fail("counts", "bounce counts are whole numbers >= -1 (-1: the solver failed)");
      b.counts.push_back(static_cast<int>(c));
    }
    if (b.counts.size() != b.values.size()) r->fail("counts", "needs one count per value of baseline.values");
    const auto lo = r->numbers("threshold_lo"), hi = r->numbers("threshold_hi");
    const auto below = r->numbers("threshold_count_below"), above = r->numbers("threshold_count_above");
    if (hi.size() != lo.size() || below.size() != lo.size() || above.size() != lo.size())
      r->fail("threshold_lo", "threshold_lo, threshold_hi, threshold_count_below and threshold_count_above need equal lengths");
    for (std::size_t i = 0; i < lo.size(); ++i) {
      CountThreshold th;
      th.lo = lo[i];
      th.hi = hi[i];
      th.count_below = static_cast<int>(below[i]);
      th.count_above = static_cast<int>(above[i]);
      th.bisected = true;
      if (!(th.hi >= th.lo)) r->fail("threshold_hi", "each threshold_hi must be >= its threshold_lo");
      b.thresholds.push_back(th);
    }
    r->finish();
  }
  top.finish();
  return b;
}

fs::path resolve_case_file(const BounceBaseline& b) {
  fs::path c(b.case_file);
  if (c.is_absolute() || fs::exists(c)) return c;
  fs::path root = fs::path(b.file).parent_path().parent_path().parent_path();
  fs::path alt = root / c;
  if (fs::exists(alt)) return alt;
  throw_input_error(b.file, 0, "baseline.case", "case file '" + b.case_file + "' not found (relative to the working directory or to " +
                                                     (root.empty() ? std::string(".") : root.string()) + ")");
}

BounceSweepSpec sweep_of(const BounceBaseline& b) {
  std::vector<std::string> overrides;
  if (b.water_law != WaterLaw::newtonian) overrides.push_back(std::string("environment.water_law=") + to_string(b.water_law));
  const StoneCase c = load_stone_case(resolve_case_file(b).string(), overrides);
  BounceSweepSpec s;
  s.name = b.name;
  s.base = problem_from_case(c);
  if (!s.base.from_parameters)
    throw_input_error(b.file, 0, "baseline.case", "the case gives a full [throw.state]; a sweep needs [throw] parameters");
  s.parameter = b.parameter;
  s.values = b.values;
  s.convention = b.convention;
  if (b.solver == SolverKind::realtime) {
    RealtimeOptions o = c.realtime;
    if (!b.scheme.empty()) parse_scheme(b.scheme, o.scheme);
    if (b.dt_s > 0) o.dt_s = b.dt_s;
    if (b.contact_dt_s > 0) o.contact_dt_s = b.contact_dt_s;
    if (b.t_max_s > 0) o.t_max_s = b.t_max_s;
    s.solver = realtime_choice(o);
  } else {
    ReferenceOptions o = c.reference;
    if (!b.method.empty()) parse_reference_method(b.method, o.method);
    if (b.rtol > 0) o.rtol = b.rtol;
    if (b.atol > 0) o.atol = b.atol;
    if (!b.restart.empty()) parse_restart_strategy(b.restart, o.restart);
    if (b.t_max_s > 0) o.t_max_s = b.t_max_s;
    s.solver = reference_choice(o);
  }
  s.threshold_tolerance = b.threshold_tolerance;
  s.max_thresholds = 1000;  // a baseline bisects every change
  return s;
}

std::string baseline_text(const BounceBaseline& b, const BounceSweepResult& r, const std::string& generated) {
  std::ostringstream s;
  s << "# Golden baseline: bounce count against " << to_string(b.parameter) << " (" << unit_of(b.parameter) << ").\n"
    << "# Checked by `stoneskip regress`; rewritten (the [result] part) by `stoneskip regress --update --baseline "
       "THIS_FILE`.\n"
    << "# Counts must match exactly except within compare_tolerance of a threshold; thresholds must match\n"
    << "# (same counts on both sides) within compare_tolerance.\n\n";
  s << "[baseline]\n";
  s << "name = " << quoted(b.name) << "\n";
  if (!b.description.empty()) s << "description = " << quoted(b.description) << "\n";
  s << "case = " << quoted(b.case_file) << "\n";
  s << "parameter = " << quoted(to_string(b.parameter)) << "\n";
  s << "values = " << array(b.values, num) << "\n";
  s << "convention = " << quoted(to_string(b.convention)) << "\n";
  if (b.water_law != WaterLaw::newtonian) s << "water_law = " << quoted(to_string(b.water_law)) << "\n";
  if (b.solver == SolverKind::realtime) {
    s << "solver = \"realtime\"\n";
    if (!b.scheme.empty()) s << "scheme = " << quoted(b.scheme) << "\n";
    if (b.dt_s > 0) s << "dt_s = " << num(b.dt_s) << "\n";
    if (b.contact_dt_s > 0) s << "contact_dt_s = " << num(b.contact_dt_s) << "\n";
  } else {
    s << "solver = \"reference\"\n";
    if (!b.method.empty()) s << "method = " << quoted(b.method) << "\n";
    if (b.rtol > 0) s << "rtol = " << num(b.rtol) << "\n";
    if (b.atol > 0) s << "atol = " << num(b.atol) << "\n";
    if (!b.restart.empty()) s << "restart = " << quoted(b.restart) << "\n";
  }
  if (b.t_max_s > 0) s << "t_max_s = " << num(b.t_max_s) << "\n";
  s << "threshold_tolerance = " << num(b.threshold_tolerance) << "\n";
  s << "compare_tolerance = " << num(b.compare_tolerance) << "\n\n";
  s << "[result]\n";
  s << "generated = " << quoted(generated) << "\n";
  s << "counts = " << array(r.counts, [](int c) { return std::to_string(c); }) << "\n";
  std::vector<double> lo, hi, below, above;
  for (const auto& t : r.thresholds) {
    lo.push_back(t.lo);
    hi.push_back(t.hi);
    below.push_back(t.count_below);
    above.push_back(t.count_above);
  }
  s << "threshold_lo = " << array(lo, num) << "\n";
  s << "threshold_hi = " << array(hi, num) << "\n";
  s << "threshold_count_below = " << array(below, [](double c) { return std::to_string(static_cast<int>(c)); }) << "\n";
  s << "threshold_count_above = " << array(above, [](double c) { return std::to_string(static_cast<int>(c)); }) << "\n";
  return s.str();
}

BaselineComparison compare_with_baseline(const BounceBaseline& stored, const BounceSweepResult& now) {
  BaselineComparison c;
  c.name = stored.name;
  c.grid_points = static_cast<int>(stored.values.size());
  c.thresholds = static_cast<int>(stored.thresholds.size());
  const std::string unit = " " + unit_of(stored.parameter);
  const std::string pname = to_string(stored.parameter);
  auto fmt = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return std::string(buf);
  };
  if (!stored.has_result) {
    c.passed = false;
    c.regressions.push_back("the baseline has no [result] (run `stoneskip regress --update --baseline " + stored.file + "`)");
    return c;
  }
  for (std::size_t i = 0; i < stored.values.size() && i < now.counts.size(); ++i) {
    if (stored.counts[i] == now.counts[i]) continue;
    const double v = stored.values[i];
    bool near = false;
    for (const auto& t : stored.thresholds) near = near || std::abs(v - t.value()) <= stored.compare_tolerance;
    std::string line = "count at " + pname + " = " + fmt(v) + unit + ": stored " + std::to_string(stored.counts[i]) +
                       ", now " + std::to_string(now.counts[i]);
    if (now.counts[i] < 0 && !now.failures[i].empty()) line += " (solver failed: " + now.failures[i] + ")";
    if (near)
      c.tolerated.push_back(line + " (within " + fmt(stored.compare_tolerance) + unit + " of a stored threshold)");
    else
      c.regressions.push_back(line);
  }
  std::vector<bool> used(now.thresholds.size(), false);
  for (const auto& t : stored.thresholds) {
    int best = -1;
    double best_d = 0;
    for (std::size_t j = 0; j < now.thresholds.size(); ++j) {
      const auto& n = now.thresholds[j];
      if (used[j] || n.count_below != t.count_below || n.count_above != t.count_above) continue;
      const double d = std::abs(n.value() - t.value());
      if (best < 0 || d < best_d) {
        best = static_cast<int>(j);
        best_d = d;
      }
    }
    const std::string what = "threshold " + std::to_string(t.count_below) + " -> " + std::to_string(t.count_above) +
                             " bounces stored at " + pname + " = " + fmt(t.value()) + unit;
    if (best >= 0 && best_d <= stored.compare_tolerance) {
      used[best] = true;
      continue;
    }
    if (best >= 0)
      c.regressions.push_back(what + ": now at " + fmt(now.thresholds[best].value()) + unit + " (moved " + fmt(best_d) +
                              unit + ", tolerance " + fmt(stored.compare_tolerance) + unit + ")");
    else
      c.regressions.push_back(what + ": gone");
    if (best >= 0) used[best] = true;
  }
  for (std::size_t j = 0; j < now.thresholds.size(); ++j) {
    if (used[j]) continue;
    const auto& n = now.thresholds[j];
    c.regressions.push_back("new threshold " + std::to_string(n.count_below) + " -> " + std::to_string(n.count_above) +
                            " bounces at " + pname + " = " + fmt(n.value()) + unit + " (not in the baseline)");
  }
  c.passed = c.regressions.empty();
  return c;
}

}  // namespace stoneskip
