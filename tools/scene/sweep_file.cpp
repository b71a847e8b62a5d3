#include "tools/scene/sweep_file.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "tools/io/atomic_file.hpp"
#include "tools/io/dotted_key.hpp"
#include "tools/io/input_error.hpp"
#include "tools/scene/resource_estimate.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

const std::set<std::string> kTopKeys = {"base", "set", "solvers", "title", "description", "design", "vary"};

long line_of(const toml::value& v) { return static_cast<long>(v.location().line()); }

// A top-level array of strings (`solvers`, `set`) with the line of the array.
std::vector<std::string> strings(TomlTable& top, const toml::value& root, const std::string& key, long& line,
                                 std::vector<long>* lines = nullptr) {
  std::vector<std::string> out;
  if (!top.has(key)) return out;
  const toml::value& v = root.as_table().at(key);
  line = line_of(v);
  if (!v.is_array()) top.fail(key, "expected an array of strings");
  for (const auto& e : v.as_array()) {
    if (!e.is_string()) top.fail(key, "expected an array of strings");
    out.push_back(e.as_string().str);
    if (lines) lines->push_back(line_of(e));
  }
  return out;
}

SweepSolvers read_solvers(TomlTable& top, const toml::value& root, long& line) {
  if (!top.has("solvers")) return SweepSolvers::realtime;
  bool realtime = false, reference = false;
  for (const auto& s : strings(top, root, "solvers", line)) {
    bool& flag = s == "realtime" ? realtime : reference;
    if (s != "realtime" && s != "reference")
      top.fail("solvers", "each must be \"realtime\" or \"reference\" (got \"" + s + "\")");
    if (flag) top.fail("solvers", "\"" + s + "\" is listed twice");
    flag = true;
  }
  if (!realtime && !reference) top.fail("solvers", "name at least one solver: \"realtime\" and/or \"reference\"");
  return realtime && reference ? SweepSolvers::both : realtime ? SweepSolvers::realtime : SweepSolvers::reference;
}

}  // namespace

namespace {
// Whole values (not −0) become TOML integers, as their literal would parse under --set.
bool as_integer(double v) { return v == std::floor(v) && std::abs(v) < 9.0e15 && !(v == 0 && std::signbit(v)); }
}  // namespace

std::string sweep_override(const std::string& key, double value) {
  char b[64];
  if (as_integer(value))
    std::snprintf(b, sizeof b, "%.0f", value);
  else
    std::snprintf(b, sizeof b, "%.17g", value);  // 17 significant digits: the same double back
  std::string literal = b;
  if (!as_integer(value) && literal.find_first_of(".eEn") == std::string::npos) literal += ".0";  // -0 → -0.0
  return key + "=" + literal;
}

SweepFile sweep_file_from_text(const std::string& text, const std::string& name) {
  const TomlDocument doc = parse_toml_text(text, name);
  SweepFile s;
  s.file = name;
  s.text = text;
  TomlTable top = doc.top();
  for (const auto& k : top.keys())
    if (!kTopKeys.count(k)) top.fail(k, "unknown key (a sweep file has base, set, solvers, title, description, [design], [[vary]])");
  s.title = top.string_or("title", fs::path(name).stem().string());
  top.string_or("description", "");
  const std::string base = top.string("base");
  s.base_line = line_of(doc.root.as_table().at("base"));
  fs::path bp(base);
  if (bp.is_relative()) bp = fs::path(name).parent_path() / bp;
  s.base_file = bp.lexically_normal().string();
  s.base_sets = strings(top, doc.root, "set", s.set_line, &s.set_lines);
  s.solvers = read_solvers(top, doc.root, s.solvers_line);

  // [design]
  TomlTable design = top.table("design");
  const std::string kind = design.string("kind");
  if (!parse_design_kind(kind, s.design.kind))
    design.fail("kind", "must be \"grid\", \"random\" or \"latin_hypercube\" (got \"" + kind + "\")");
  const bool grid = s.design.kind == DesignKind::grid;
  if (grid) {
    for (const char* k : {"samples", "seed"})
      if (design.has(k)) design.fail(k, "is for random designs; a grid's throws are the product of the [[vary]] counts");
  } else {
    s.design.samples = design.integer("samples");
    const long long seed = design.integer("seed");
    if (seed < 0) design.fail("seed", "must be an integer >= 0");
    s.design.seed = static_cast<std::uint64_t>(seed);
  }
  design.finish();

  // [[vary]]
  if (!top.has("vary")) top.fail("vary", "missing: give one [[vary]] table per parameter to vary");
  const toml::value& vary = doc.root.as_table().at("vary");
  if (!vary.is_array()) top.fail("vary", "expected [[vary]] tables (an array of tables)");
  std::vector<TomlTable> tables;
  for (std::size_t i = 0; i < vary.as_array().size(); ++i) {
    const toml::value& e = vary.as_array()[i];
    if (!e.is_table()) top.fail("vary", "expected [[vary]] tables (an array of tables)");
    tables.emplace_back(&e, name, "vary[" + std::to_string(i + 1) + "]");
    TomlTable& v = tables.back();
    SweepAxis a;
    a.key = canonical_dotted_key(v.string("key"));  // "throw . speed_m_s" is throw.speed_m_s (twice is refused)
    s.axis_lines.push_back(line_of(e.as_table().at("key")));
    a.from = v.number("from");
    a.to = v.number("to");
    const std::string scale = v.string_or("scale", "linear");
    if (!parse_axis_scale(scale, a.scale)) v.fail("scale", "must be \"linear\" or \"log\" (got \"" + scale + "\")");
    if (grid)
      a.count = v.integer("count");
    else if (v.has("count"))
      v.fail("count", "is for grids; a " + kind + " design draws [design] samples");
    v.finish();
    s.design.axes.push_back(a);
  }
  DesignProblem problem;
  if (!s.design.is_valid(&problem)) {
    if (problem.axis >= 0) tables[static_cast<std::size_t>(problem.axis)].fail(problem.key, problem.what);
    if (problem.key == "vary") top.fail("vary", problem.what);
    design.fail(problem.key, problem.what);
  }
  return s;
}

SweepFile load_sweep_file(const std::string& path) { return sweep_file_from_text(read_text_file(path), path); }

SweepCases::SweepCases(const SweepFile& sweep) : sweep_(sweep) {
  // 1. The base case, with the sweep's fixed overrides.
  std::string base_text;
  try {
    base_text = read_text_file(sweep.base_file);
    base_doc_ = parse_toml_text(base_text, sweep.base_file, sweep.base_sets);
    base_ = stone_case_from_document(base_doc_);
  } catch (const InputError& e) {
    // Blame the `set` line where the base alone loads (an override that does not apply), else the base.
    bool base_alone_loads = !base_text.empty();
    if (base_alone_loads && !sweep.base_sets.empty()) {
      try {
        stone_case_from_document(parse_toml_text(base_text, sweep.base_file, {}));
      } catch (const InputError&) {
        base_alone_loads = false;
      }
    }
    if (base_alone_loads && !sweep.base_sets.empty()) {
      // The first entry that does not apply, on its own line (an array may span lines).
      std::size_t bad = sweep.base_sets.size() - 1;
      std::string why = e.what();
      for (std::size_t k = 0; k + 1 < sweep.base_sets.size(); ++k) {
        try {
          stone_case_from_document(parse_toml_text(
              base_text, sweep.base_file, std::vector<std::string>(sweep.base_sets.begin(), sweep.base_sets.begin() + k + 1)));
        } catch (const InputError& first) {
          bad = k;
          why = first.what();
          break;
        }
      }
      // The message of the reader names a command-line override ("--set key"): here it is an entry.
      if (const auto at = why.find("--set "); at != std::string::npos) why.replace(at, 6, "entry ");
      const long line = bad < sweep.set_lines.size() ? sweep.set_lines[bad] : sweep.set_line;
      throw_input_error(sweep.file, line, "set", "an override does not apply to the base case: " + why);
    }
    throw_input_error(sweep.file, sweep.base_line, "base", std::string("the base case does not load: ") + e.what());
  }
  if (base_.water && runs_reference(sweep.solvers))
    throw_input_error(sweep.file, sweep.solvers_line, "solvers",
                      "the base case has [water]; the CVODE reference supports still water only");

  // 2. Every varied key must hold a number where the base case has it.
  for (std::size_t k = 0; k < sweep.design.axes.size(); ++k) {
    const std::string& key = sweep.design.axes[k].key;
    const toml::value* node = &base_doc_.root;
    std::size_t start = 0;
    while (node && node->is_table()) {
      const std::size_t dot = key.find('.', start);
      const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      const auto& t = node->as_table();
      node = t.count(part) ? &t.at(part) : nullptr;
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    if (node && !node->is_integer() && !node->is_floating())
      throw_input_error(sweep.file, sweep.axis_lines[k], "vary[" + std::to_string(k + 1) + "].key",
                        "\"" + key + "\" is not a numeric key (the base case gives it a " +
                            (node->is_string() ? "string" : node->is_table() ? "table" : "non-number") + ")");
  }

  // 3. The case at the design's extreme points and first throws.
  const SweepDesign& d = sweep.design;
  const std::size_t n = d.axes.size();
  const RunSolvers solvers{runs_realtime(sweep.solvers), runs_reference(sweep.solvers), false};
  // Each probe's estimate raises heaviest_throw_; a case the reader refuses refuses the sweep.
  auto probe = [&](const std::vector<double>& p) {
    try {
      const ResourceEstimate e = estimate_run(at(p), solvers);
      if (e.work.size() > heaviest_throw_.work.size()) heaviest_throw_.work = e.work;
      for (std::size_t i = 0; i < e.work.size(); ++i)
        if (e.work[i].count > heaviest_throw_.work[i].count || std::isnan(e.work[i].count)) heaviest_throw_.work[i] = e.work[i];
      if (!(e.memory_bytes <= heaviest_throw_.memory_bytes)) {
        heaviest_throw_.memory_bytes = e.memory_bytes;
        heaviest_throw_.memory_detail = e.memory_detail;
      }
      return e;
    } catch (const InputError& e) {
      // Blame the varied key the case reader named, or the first one.
      std::string what = e.what();
      std::size_t k = 0;
      for (std::size_t j = 0; j < n; ++j)
        if (what.find(d.axes[j].key) != std::string::npos) k = j;
      // The reader refused the override itself ("--set thrw: unknown key", a command line's words):
      // here it is the varied key, the axis whose key it begins.
      std::string label = "vary[" + std::to_string(k + 1) + "]";
      if (const auto at = what.find("--set "); at != std::string::npos) {
        const std::string named = what.substr(at + 6, what.find(':', at) - at - 6);
        for (std::size_t j = 0; j < n; ++j)
          if (d.axes[j].key.rfind(named, 0) == 0) k = j;
        what.replace(at, 6, "the varied key ");
        label = "vary[" + std::to_string(k + 1) + "].key";
      }
      if (what.find("unknown key") != std::string::npos) label = "vary[" + std::to_string(k + 1) + "].key";
      std::string values;
      for (std::size_t j = 0; j < n; ++j) values += (j ? ", " : "") + sweep_override(d.axes[j].key, p[j]);
      throw_input_error(sweep.file, sweep.axis_lines[k], label, "the base case refuses the throw at " + values + ": " + what);
    }
  };
  // How heavy a probe is against the limits: the largest fraction of any limit it uses.
  auto load = [](const ResourceEstimate& e) {
    double f = e.memory_bytes / kDefaultMaxMemoryBytes;
    for (const auto& w : e.work) f = std::max(f, std::isnan(w.count) ? HUGE_VAL : w.count / w.limit);
    return std::isnan(f) ? HUGE_VAL : f;
  };
  if (n <= 10) {
    for (std::size_t mask = 0; mask < (std::size_t{1} << n); ++mask) {
      std::vector<double> p(n);
      for (std::size_t k = 0; k < n; ++k) p[k] = (mask >> k & 1) ? d.axes[k].to : d.axes[k].from;
      probe(p);
    }
  } else {
    // 2ⁿ corners are too many: each axis alone at either end, then the corner that takes every
    // axis at its heavier end (the heaviest corner when each axis's effect is monotone).
    std::vector<double> low(n), heaviest(n);
    for (std::size_t j = 0; j < n; ++j) low[j] = d.axes[j].from;
    const double base_load = load(probe(low));
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<double> p = low;
      p[k] = d.axes[k].to;
      heaviest[k] = load(probe(p)) > base_load ? d.axes[k].to : d.axes[k].from;
    }
    probe(heaviest);
  }
  for (std::size_t i = 0; i < std::min<std::size_t>(d.size(), 4); ++i) probe(d.point(i));
  if (d.kind == DesignKind::grid)
    for (std::size_t k = 0; k < n; ++k) {
      // An interior grid value, the first that is not whole if any (an integer key refuses a fraction).
      const std::vector<double> values = d.grid_values(k);
      if (values.size() <= 2) continue;
      std::size_t at_value = 1;
      for (std::size_t i = 1; i + 1 < values.size(); ++i)
        if (values[i] != std::floor(values[i])) {
          at_value = i;
          break;
        }
      std::vector<double> p = d.point(0);
      p[k] = values[at_value];
      probe(p);
    }
}

StoneCase SweepCases::at(const std::vector<double>& point) const {
  TomlDocument doc = base_doc_;  // a copy of the parsed base: ~20× cheaper than parsing its text
  for (std::size_t k = 0; k < point.size(); ++k) {
    const double v = point[k];
    set_value(doc.root, doc.file, sweep_.design.axes[k].key,
              as_integer(v) ? toml::value(static_cast<toml::integer>(v)) : toml::value(v));
  }
  return stone_case_from_document(doc);
}

}  // namespace stoneskip
