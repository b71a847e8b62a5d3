#include "tools/scene/baseline_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"
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


// The bounds of a swept parameter: those of its key in a case's [throw] (stone_case.hpp).
Bounds parameter_bounds(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return {-kMaxSpin_rev_s, kMaxSpin_rev_s};
    case SweepParameter::speed_m_s: return {0, kMaxSpeed_m_s};
    default: return {-90, 90};
  }
}

std::string text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

BounceBaseline read_baseline(const std::string& path) {
  const TomlDocument doc = load_toml(path);
  TomlTable top = doc.top();
  BounceBaseline b;
  b.file = path;
  // A file with no [baseline] (an empty one, a case file named by mistake) says what it lacks.
  if (!top.has("baseline"))
    throw_input_error(path, 0, "baseline",
                      "missing table: a baseline file starts with [baseline] (its case, swept parameter and grid; "
                      "cases/README.md, \"Stone studies, hard cases and golden baselines\")");
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
  const Bounds range = parameter_bounds(b.parameter);
  if (!(b.values.front() >= range.lo && b.values.back() <= range.hi))
    t.fail("values", std::string("the values of ") + to_string(b.parameter) + " must be in [" + text(range.lo) + ", " +
                         text(range.hi) + "] (as the case key)");
  const std::string conv = t.string("convention");
  if (!parse_convention(conv, b.convention)) t.fail("convention", "'" + conv + "' is not physical or paper");
  if (t.has("water_law")) {
    const std::string law = t.string("water_law");
    WaterLaw w;
    if (!parse_water_law(law, w)) t.fail("water_law", "'" + law + "' is not newtonian, planing or nagahiro_hayakawa");
    if (b.convention == Convention::paper && w != WaterLaw::newtonian)
      t.fail("water_law", "the paper convention has the printed (newtonian) law only");
    b.water_law = w;
  }
  if (t.has("pressure_distribution")) {
    const std::string dist = t.string("pressure_distribution");
    PressureDistribution d;
    if (!parse_pressure_distribution(dist, d))
      t.fail("pressure_distribution", "'" + dist + "' is not uniform, savitsky or savitsky_wagner");
    if (b.convention == Convention::paper && d != PressureDistribution::uniform)
      t.fail("pressure_distribution", "the paper convention has the printed (uniform) pressure only");
    b.pressure_distribution = d;
  }
  const std::string solver = t.string("solver");
  if (solver == "realtime") {
    b.solver = SolverKind::realtime;
    b.scheme = t.string_or("scheme", "");
    Scheme sc;
    if (!b.scheme.empty() && !parse_scheme(b.scheme, sc))
      t.fail("scheme", "'" + b.scheme + "' is not bs32, semi_implicit_euler, midpoint or rk4");
    // Absent: the case's (kept as 0); given: positive, and checked with the case's [solver] in
    // sweep_of().
    b.dt_s = t.number_or("dt_s", 0);
    b.contact_dt_s = t.number_or("contact_dt_s", 0);
    if (t.has("dt_s")) t.require_positive("dt_s", b.dt_s);
    if (t.has("contact_dt_s")) t.require_positive("contact_dt_s", b.contact_dt_s);
  } else if (solver == "reference") {
    b.solver = SolverKind::reference;
    b.method = t.string_or("method", "");
    ReferenceMethod m;
    if (!b.method.empty() && !parse_reference_method(b.method, m)) t.fail("method", "'" + b.method + "' is not bdf or adams");
    b.rtol = t.number_or("rtol", 0);
    b.atol = t.number_or("atol", 0);
    if (t.has("rtol")) t.require_in("rtol", b.rtol, 1e-15, 1e-2);  // absent: the case's
    if (t.has("atol")) t.require_in("atol", b.atol, 1e-20, 1);
    b.restart = t.string_or("restart", "");
    RestartStrategy rs;
    if (!b.restart.empty() && !parse_restart_strategy(b.restart, rs))
      t.fail("restart", "'" + b.restart + "' is not every_event, every_crossing, at_jumps or never");
  } else {
    t.fail("solver", "'" + solver + "' is not realtime or reference");
  }
  b.t_max_s = t.number_or("t_max_s", 0);
  if (t.has("t_max_s")) t.require_in("t_max_s", b.t_max_s, kMinDuration_s, kMaxDuration_s);
  // The bisection halves a bracket of at most the grid's span down to threshold_tolerance: at
  // most log2(span / tolerance) ≤ 30 halvings per threshold with this lower bound (a tolerance of
  // 1e-300 would never be reached: the midpoint rounds onto an end).
  const double span = b.values.back() - b.values.front();
  b.threshold_tolerance = t.number("threshold_tolerance");
  t.require_in("threshold_tolerance", b.threshold_tolerance, kMinRelativeThresholdTolerance * span, span);
  b.compare_tolerance = t.number_or("compare_tolerance", 2 * b.threshold_tolerance);
  t.require_in("compare_tolerance", b.compare_tolerance, kMinRelativeThresholdTolerance * span, span);
  // The nudged throws per grid value (verification/stones/bounce_baseline.hpp): a chaotic count is
  // compared on ensembles. 0 compares single runs only.
  const long long members = t.integer_or("ensemble_members", kDefaultEnsembleMembers);
  if (members != 0 && (members < 2 || members > 64 || members % 2 != 0))
    t.fail("ensemble_members", "must be 0 (single runs only) or even, in [2, 64]");
  b.ensemble_members = static_cast<int>(members);
  const bool members_given = t.has("ensemble_members");
  t.finish();

  if (auto r = top.maybe_table("result")) {
    b.has_result = true;
    b.generated = r->string_or("generated", "");
    auto whole = [&](const std::string& key, double c) {
      if (c != std::floor(c) || c < -1 || c > kMaxBounceCount)
        r->fail(key, "bounce counts are whole numbers in [-1, 1000000] (-1: the solver failed)");
      return static_cast<int>(c);
    };
    for (double c : r->numbers("counts")) b.counts.push_back(whole("counts", c));
    if (b.counts.size() != b.values.size()) r->fail("counts", "needs one count per value of baseline.values");
    const auto lo = r->numbers("threshold_lo"), hi = r->numbers("threshold_hi");
    const auto below = r->numbers("threshold_count_below"), above = r->numbers("threshold_count_above");
    if (hi.size() != lo.size() || below.size() != lo.size() || above.size() != lo.size())
      r->fail("threshold_lo", "threshold_lo, threshold_hi, threshold_count_below and threshold_count_above need equal lengths");
    for (std::size_t i = 0; i < lo.size(); ++i) {
      CountThreshold th;
      th.lo = lo[i];
      th.hi = hi[i];
      th.count_below = whole("threshold_count_below", below[i]);
      th.count_above = whole("threshold_count_above", above[i]);
      th.bisected = true;
      if (!(th.hi >= th.lo)) r->fail("threshold_hi", "each threshold_hi must be >= its threshold_lo");
      // A damaged [result] is bad input, not a regression of the code (a threshold at 1400 rev/s
      // on a 0–60 grid was reported as "moved 1386 rev/s", exit 1, after the whole sweep): each
      // lies inside the grid, changes the count, and they come in the order the sweep finds them
      // (one per grid cell, ascending). Its width may pass threshold_tolerance: a bisection that
      // stopped at a failed run keeps its bracket (cases/baselines/spin_paper_realtime.toml).
      if (th.lo < b.values.front() || th.hi > b.values.back())
        r->fail(th.lo < b.values.front() ? "threshold_lo" : "threshold_hi", "threshold " + std::to_string(i + 1) + " [" + text(th.lo) + ", " + text(th.hi) +
                                    "] lies outside the grid [" + text(b.values.front()) + ", " + text(b.values.back()) + "]");
      if (th.count_below == th.count_above)
        r->fail("threshold_count_above", "threshold " + std::to_string(i + 1) + " changes nothing (" +
                                             std::to_string(th.count_below) + " on both sides)");
      if (!b.thresholds.empty() && th.lo < b.thresholds.back().hi)
        r->fail("threshold_lo", "thresholds must be in ascending order without overlap (threshold " + std::to_string(i + 1) +
                                    " starts before threshold " + std::to_string(i) + " ends)");
      b.thresholds.push_back(th);
    }
    // The sweep bisects each grid cell whose two counts differ (neither a failure), once, inside
    // that cell, keeping the left count below (bounce_sweep.cpp): thresholds that do not answer the
    // counts so are a damaged [result], not a regression of the code.
    if (b.counts.size() == b.values.size()) {
      std::size_t next = 0;
      for (std::size_t i = 0; i + 1 < b.values.size(); ++i) {
        const int c0 = b.counts[i], c1 = b.counts[i + 1];
        if (c0 == c1 || c0 < 0 || c1 < 0) continue;
        const std::string cell = "[" + text(b.values[i]) + ", " + text(b.values[i + 1]) + "]";
        if (next >= b.thresholds.size())
          r->fail("threshold_lo", "the counts change from " + std::to_string(c0) + " to " + std::to_string(c1) + " in " +
                                      cell + " but no threshold lies there");
        const CountThreshold& th = b.thresholds[next];
        if (th.lo < b.values[i] || th.hi > b.values[i + 1])
          r->fail("threshold_lo", "threshold " + std::to_string(next + 1) + " [" + text(th.lo) + ", " + text(th.hi) +
                                      "] should lie in " + cell + ", where the counts change from " + std::to_string(c0) +
                                      " to " + std::to_string(c1));
        if (th.count_below != c0)
          r->fail("threshold_count_below", "threshold " + std::to_string(next + 1) + " has " +
                                               std::to_string(th.count_below) + " below it, but counts has " +
                                               std::to_string(c0) + " at " + text(b.values[i]));
        ++next;
      }
      if (next < b.thresholds.size())
        r->fail("threshold_lo", "threshold " + std::to_string(next + 1) + " [" + text(b.thresholds[next].lo) + ", " +
                                    text(b.thresholds[next].hi) + "] lies in no grid cell where counts changes (neither run failing)");
    }
    if (r->has("ensemble_counts")) {
      const auto e = r->numbers("ensemble_counts");
      const std::size_t m = static_cast<std::size_t>(b.ensemble_members);
      if (m == 0 || e.size() != b.values.size() * m)
        r->fail("ensemble_counts", "needs baseline.ensemble_members (" + std::to_string(m) + (members_given ? "" : ", the default") +
                                       ") counts per grid value, " +
                                       std::to_string(b.values.size() * m) + " in all (got " + std::to_string(e.size()) + ")");
      b.ensembles.assign(b.values.size(), {});
      for (std::size_t k = 0; k < e.size(); ++k) b.ensembles[k / m].push_back(whole("ensemble_counts", e[k]));
    }
    r->finish();
  }
  // A baseline written before ensembles (no ensemble_members, a [result] without ensemble_counts)
  // is compared on single runs as it was made: refusing it sent users to `--update`, which would
  // have replaced its golden counts with whatever the code gives now. regress says so.
  if (!members_given && b.has_result && b.ensembles.empty()) b.ensemble_members = 0;
  top.finish();
  return b;
}

fs::path resolve_case_file(const BounceBaseline& b) {
  fs::path c(b.case_file);
  if (c.is_absolute()) return c;
  // The baseline's own tree first: the folder holding the baseline's cases/ (the baseline as
  // found: a shipped "cases/baselines/X.toml" named from another folder is read from the source
  // tree), then beside the baseline. The working directory came first, so a copied tree's changed
  // case was passed over for the shipped one whenever regress ran from the repository (PASS there,
  // FAIL from the copy, with no word of which case ran).
  const fs::path here = fs::absolute(locate_input(b.file)).parent_path();
  const fs::path root = here.parent_path().parent_path();
  // The tree's root only where the baseline lies in <root>/cases/baselines/ (a baseline in a folder
  // of its own names its case beside it, even where two folders up holds a file of that name).
  const bool in_tree = here.filename() == "baselines" && here.parent_path().filename() == "cases";
  if (const fs::path alt = root / c; in_tree && fs::exists(alt)) return alt;
  // A baseline kept in a folder of its own names its case beside it ("mycase.toml").
  if (const fs::path beside = here / c; fs::exists(beside)) return beside;
  if (fs::exists(c)) return fs::absolute(c);
  if (const fs::path shipped = locate_input(c); fs::exists(shipped)) return shipped;
  throw_input_error(b.file, 0, "baseline.case",
                    "case file '" + b.case_file + "' not found " +
                        (in_tree ? "under " + root.string() + " (the folder holding the baseline's cases/), " : std::string()) +
                        "beside the baseline (" + here.string() + "), in the working directory, or among the shipped files");
}

BounceSweepSpec sweep_of(const BounceBaseline& b) {
  std::vector<std::string> overrides;
  if (b.water_law) overrides.push_back(std::string("environment.water_law=") + to_string(*b.water_law));
  if (b.pressure_distribution)
    overrides.push_back(std::string("environment.pressure_distribution=") + to_string(*b.pressure_distribution));
  // A paper baseline runs the case under the printed law: a case that names another law,
  // distribution or C_w would have had it silently replaced (with_convention). Read in the paper
  // convention, the case is refused where it does, naming its key and this baseline.
  if (b.convention == Convention::paper) overrides.push_back("environment.convention=paper");
  StoneCase c;
  try {
    c = load_stone_case(resolve_case_file(b).string(), overrides);
  } catch (const InputError& e) {
    if (b.convention != Convention::paper) throw;
    throw_input_error(b.file, 0, "baseline.convention", std::string("the case does not run in the paper convention: ") + e.what());
  }
  // A baseline is a bounce-count sweep on still water (the CVODE reference and the sweep's
  // ThrowProblem know no live surface): a case with [water] would be run on still water without a word.
  if (c.water)
    throw_input_error(b.file, 0, "baseline.case",
                      "'" + c.file + "' has [water] (a live surface): a baseline counts bounces on still water; "
                      "sweep a live-water case with `stoneskip sweep`");
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
    o.output_dt_s = std::min(o.output_dt_s, o.t_max_s);
    // The steps as [solver] would check them (a contact_dt_s of 1e-300 must not reach the stepper).
    if (const auto problem = realtime_options_problem(o))
      throw_input_error(b.file, 0, "baseline." + problem->first, problem->second + " (the baseline's settings over the case's [solver])");
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
  s.ensemble_members = b.ensemble_members;
  return s;
}

std::string baseline_text(const BounceBaseline& b, const BounceSweepResult& r, const std::string& generated) {
  std::ostringstream s;
  s << "# Golden baseline: bounce count against " << to_string(b.parameter) << " (" << unit_of(b.parameter) << ").\n"
    << "# Checked by `stoneskip regress`; rewritten (the [result] part) by `stoneskip regress --update --baseline "
       "THIS_FILE`.\n"
    << "# Counts must match exactly except within compare_tolerance of a threshold; thresholds must match\n"
    << "# (same counts on both sides) within compare_tolerance. Where a grid value's ensemble of nudged throws\n"
    << "# (speed x (1 +- eps), eps 1e-9 ... 1e-6) has spread, the count is chaotic there: the ensembles decide.\n\n";
  s << "[baseline]\n";
  s << "name = " << quoted(b.name) << "\n";
  if (!b.description.empty()) s << "description = " << quoted(b.description) << "\n";
  s << "case = " << quoted(b.case_file) << "\n";
  s << "parameter = " << quoted(to_string(b.parameter)) << "\n";
  s << "values = " << array(b.values, num) << "\n";
  s << "convention = " << quoted(to_string(b.convention)) << "\n";
  if (b.water_law) s << "water_law = " << quoted(to_string(*b.water_law)) << "\n";
  if (b.pressure_distribution) s << "pressure_distribution = " << quoted(to_string(*b.pressure_distribution)) << "\n";
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
  s << "compare_tolerance = " << num(b.compare_tolerance) << "\n";
  s << "ensemble_members = " << b.ensemble_members << "\n\n";
  return s.str() + result_section_text(r, generated);
}

std::string result_section_text(const BounceSweepResult& r, const std::string& generated) {
  std::ostringstream s;
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
  if (!r.ensembles.empty()) {
    // One row of ensemble_members counts per grid value (−1: the solver failed).
    s << "ensemble_counts = [\n";
    for (const auto& row : r.ensembles) {
      s << " ";
      for (int c : row) s << " " << c << ",";
      s << "\n";
    }
    s << "]\n";
  }
  // A change whose bisection stopped at a failed run is held like the others (its bracket's middle
  // within compare_tolerance), but it was not located: said here, where a reader of the file looks.
  for (std::size_t i = 0; i < r.thresholds.size(); ++i)
    if (const CountThreshold& t = r.thresholds[i]; !t.bisected && !std::isnan(t.failed_at))
      s << "# threshold " << i + 1 << " (" << t.count_below << " -> " << t.count_above
        << "): not located, its bisection stopped at a failed run at " << num(t.failed_at) << "\n";
  return s.str();
}

namespace {

// Where a line opens the [result] table ("[result]", "[ result ]", a comment after it), outside a
// multi-line string; npos if no line does.
std::size_t result_header_at(const std::string& text) {
  bool in_basic = false, in_literal = false;  // inside """...""" or '''...'''
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    if (!in_basic && !in_literal) {
      std::string bare;  // the line without blanks, up to a comment
      for (char c : line) {
        if (c == '#') break;
        if (!std::isspace(static_cast<unsigned char>(c))) bare += c;
      }
      if (bare == "[result]") return at;
    }
    for (std::size_t i = 0; i + 3 <= line.size(); ++i) {
      if (!in_literal && line.compare(i, 3, "\"\"\"") == 0) {
        in_basic = !in_basic;
        i += 2;
      } else if (!in_basic && line.compare(i, 3, "'''") == 0) {
        in_literal = !in_literal;
        i += 2;
      }
    }
    at = end + 1;
  }
  return std::string::npos;
}

}  // namespace

std::string updated_baseline_text(const std::string& old_text, const BounceSweepResult& r, const std::string& generated) {
  const std::size_t at = result_header_at(old_text);
  std::string kept = old_text.substr(0, at == std::string::npos ? old_text.size() : at);
  // A file written with CRLF line ends keeps them in the new [result] too (it got LF).
  const bool crlf = kept.find("\r\n") != std::string::npos;
  if (at == std::string::npos) {  // no [result] yet: it follows the file, after one blank line
    while (!kept.empty() && (kept.back() == '\n' || kept.back() == '\r' || kept.back() == ' ' || kept.back() == '\t'))
      kept.pop_back();
    if (!kept.empty()) kept += crlf ? "\r\n\r\n" : "\n\n";
  }
  std::string result = result_section_text(r, generated);
  if (crlf) {
    std::string with_cr;
    for (char ch : result) {
      if (ch == '\n') with_cr += '\r';
      with_cr += ch;
    }
    result = std::move(with_cr);
  }
  return kept + result;
}

}  // namespace stoneskip
