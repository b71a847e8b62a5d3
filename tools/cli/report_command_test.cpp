// End-to-end tests of the reports: `report waves --quick`, `report stones --quick` and
// `capture validate --out` run the built executable, then `report render` rebuilds the page from
// data.h5 alone.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <set>

#include "tools/cli/test_support.hpp"
#include "tools/io/hdf5_file.hpp"
#include "verification/study/record.hpp"
#include "verification/study/verdict_rules.hpp"

namespace {

using stoneskip::Record;
using stoneskip::test::read_file;
using stoneskip::test::run_stoneskip;
using stoneskip::test::TempDir;
namespace fs = std::filesystem;

// Every verdict stored under r: (phrase, reason).
void stored_verdicts(const Record& r, std::set<std::pair<std::string, std::string>>& out) {
  if (r.has_text("rule") && r.has_text("verdict") && r.has_text("reason")) out.emplace(r.text("verdict"), r.text("reason"));
  for (const auto& c : r.child_names()) stored_verdicts(r.at(c), out);
}

// ---- figures against their tables ---------------------------------------------------------------

// A .dat file is written with 10 significant digits (reports/common/figure.cpp): a plotted value
// and its stored double agree to half a unit in the 10th digit, 5e-10 relative; 1e-9 leaves room.
constexpr double kTenDigits = 1e-9;

using Points = std::vector<std::pair<double, double>>;

// The rows of a figure's .dat with both x and y finite (gnuplot draws no other).
Points plotted_points(const fs::path& dat) {
  Points pts;
  std::istringstream in(read_file(dat));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string a, b;
    row >> a >> b;
    const double x = std::strtod(a.c_str(), nullptr), y = std::strtod(b.c_str(), nullptr);
    if (std::isfinite(x) && std::isfinite(y)) pts.emplace_back(x, y);
  }
  return pts;
}

stoneskip::Table read_table_at(const stoneskip::H5Group& g, const std::vector<std::string>& parts, std::size_t i) {
  if (i + 1 == parts.size()) return g.read_table(parts[i]);
  return read_table_at(g.open_group(parts[i]), parts, i + 1);
}

// The rows a source names, read from data.h5 on their own (not through the report's code).
Points stored_points(const stoneskip::Hdf5Reader& data, const std::vector<std::string>& src) {
  // src: table, data.h5 path, x column, y column, rows, drawn-at height
  std::vector<std::string> parts;
  std::istringstream path(src[1]);
  for (std::string p; std::getline(path, p, '/');)
    if (!p.empty()) parts.push_back(p);
  const stoneskip::Table t = read_table_at(data.root(), parts, 0);
  const auto x = t.column(src[2]), y = t.column(src[3]);
  const double at = std::strtod(src[5].c_str(), nullptr);
  Points pts;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (src[4] == "y_nonnegative" && !(y[k] >= 0)) continue;
    if (src[4] == "y_negative" && !(y[k] < 0)) continue;
    const double yy = std::isnan(at) ? y[k] : at;
    if (std::isfinite(x[k]) && std::isfinite(yy)) pts.emplace_back(x[k], yy);
  }
  return pts;
}

bool close(double a, double b) { return std::abs(a - b) <= kTenDigits * std::max(std::abs(a), std::abs(b)); }

// Every line figure's plotted points are the stored rows it names: for each set of tables that
// share one list of sources (a curve split where it breaks), the union of their finite rows is the
// union of the rows selected from data.h5, point for point; each such table is plotted `using 1:2`.
// Returns the number of figures checked; series drawn from no stored table are counted in `computed`.
int check_figures_match_their_tables(const fs::path& dir, int& computed) {
  stoneskip::Hdf5Reader data(dir / "data.h5");
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(dir / "figures")) {
    if (entry.path().extension() != ".sources") continue;
    const std::string name = entry.path().stem().string();
    const std::string script = read_file(dir / "figures" / (name + ".gp"));
    std::map<std::string, std::vector<std::vector<std::string>>> by_table;
    std::istringstream in(read_file(entry.path()));
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> f;
      std::istringstream cells(line);
      for (std::string c; std::getline(cells, c, '\t');) f.push_back(c);
      BOOST_REQUIRE_MESSAGE(f.size() == 6 || (f.size() == 2 && f[1] == "-"), name << ".sources: bad line '" << line << "'");
      if (f.size() == 2) {
        ++computed;
        by_table[f[0]];
      } else {
        by_table[f[0]].push_back(f);
      }
    }
    std::map<std::string, std::vector<std::string>> groups;  // the sources, joined → tables
    std::map<std::string, std::vector<std::vector<std::string>>> group_sources;
    for (const auto& [table, srcs] : by_table) {
      if (srcs.empty()) continue;
      std::string key;
      for (const auto& s : srcs) key += s[1] + "|" + s[2] + "|" + s[3] + "|" + s[4] + "|" + s[5] + ";";
      groups[key].push_back(table);
      group_sources[key] = srcs;
    }
    for (const auto& [key, tables] : groups) {
      BOOST_TEST_CONTEXT("figure " << name << ", tables " << tables.front() << " …, from " << key) {
        Points plotted, stored;
        for (const auto& t : tables) {
          BOOST_TEST((script.find("'" + t + ".dat' using 1:2 ") != std::string::npos ||
                      script.find("'" + t + ".dat' u 1:2 ") != std::string::npos));
          const Points p = plotted_points(dir / "figures" / (t + ".dat"));
          plotted.insert(plotted.end(), p.begin(), p.end());
        }
        for (const auto& s : group_sources[key]) {
          const Points p = stored_points(data, s);
          stored.insert(stored.end(), p.begin(), p.end());
        }
        std::sort(plotted.begin(), plotted.end());
        std::sort(stored.begin(), stored.end());
        BOOST_REQUIRE_EQUAL(plotted.size(), stored.size());
        for (std::size_t k = 0; k < plotted.size(); ++k)
          BOOST_TEST((close(plotted[k].first, stored[k].first) && close(plotted[k].second, stored[k].second)),
                     "point " << k << ": plotted (" << plotted[k].first << ", " << plotted[k].second << "), stored ("
                              << stored[k].first << ", " << stored[k].second << ")");
      }
    }
    ++checked;
  }
  return checked;
}

// The checks every report must pass, on a report folder just written.
void check_report(const fs::path& dir) {
  const std::string index = read_file(dir / "index.md");
  const std::string page = read_file(dir / "index.html");
  BOOST_REQUIRE(!index.empty());
  BOOST_TEST(page.rfind("<!DOCTYPE html>", 0) == 0);  // the same page for the browser, beside it
  // 1. Every figure the page names exists (PNG and SVG), and nothing is left of the build.
  const std::regex figure(R"(\]\(figures/([a-z0-9_]+)\.png\))");
  int figures = 0;
  for (std::sregex_iterator it(index.begin(), index.end(), figure), end; it != end; ++it, ++figures) {
    const std::string name = (*it)[1];
    BOOST_TEST_CONTEXT("figure " << name) {
      BOOST_TEST(fs::file_size(dir / "figures" / (name + ".png")) > 0u);
      BOOST_TEST(fs::file_size(dir / "figures" / (name + ".svg")) > 0u);
    }
  }
  BOOST_TEST(figures > 0);
  BOOST_TEST(!fs::exists(fs::path(dir.string() + ".partial")));
  BOOST_TEST(!fs::exists(dir / "sections"));

  // 2. No stored verdict contradicts its own rule applied to its stored inputs, and every verdict
  //    the page states ("**phrase** — reason") is one of the stored ones, word for word.
  stoneskip::Hdf5Reader data(dir / "data.h5");
  const Record sections = stoneskip::load_record(data.root().open_group("sections"));
  const auto contradictions = stoneskip::contradicted_verdicts(sections);
  for (const auto& c : contradictions) BOOST_ERROR(c);
  std::set<std::pair<std::string, std::string>> stored;
  stored_verdicts(sections, stored);
  BOOST_TEST(stored.size() > 5u);
  std::set<std::string> phrases;
  for (const auto& [v, r] : stored) phrases.insert(v);
  const std::regex stated(R"(\*\*([^*]+)\*\* — ([^|\n]+?)(?= \||\.? *\n|$))");
  int checked = 0;
  for (std::sregex_iterator it(index.begin(), index.end(), stated), end; it != end; ++it) {
    const std::string phrase = (*it)[1];
    if (!phrases.count(phrase)) continue;  // bold text that is not a verdict
    std::string reason = (*it)[2];
    bool found = false;
    for (const auto& [v, r] : stored)
      if (v == phrase && (reason == r || reason + "." == r || reason.rfind(r, 0) == 0)) found = true;
    BOOST_TEST(found, "the page states '" << phrase << " — " << reason << "', which no stored verdict says");
    ++checked;
  }
  BOOST_TEST(checked > 5);

  // 3. The page is a function of data.h5: rendering it again gives the same bytes, in both forms.
  const auto r = run_stoneskip("report render " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(read_file(dir / "index.md") == index);

  // 4. Every line figure draws the stored rows it names (above), no other.
  int computed = 0;
  const int line_figures = check_figures_match_their_tables(dir, computed);
  BOOST_TEST_MESSAGE(dir.filename() << ": " << line_figures << " line figures checked against data.h5; " << computed
                                    << " series computed from no stored table");
  BOOST_TEST(read_file(dir / "index.html") == page);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_command_)

BOOST_AUTO_TEST_CASE(waves_quick_report_is_a_function_of_its_data) {
  // Oracle: the report's own data — every figure it names is drawn, every verdict it states is
  // stored and agrees with its rule, and rendering data.h5 again reproduces index.md byte for byte.
  TempDir tmp("stoneskip-report-waves");
  const fs::path dir = tmp.path() / "waves";
  const auto r = run_stoneskip("report waves --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
}

BOOST_AUTO_TEST_CASE(stones_quick_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report; and the validation's rows of the quick preset are there: a
  // column per law × distribution × attitude, the regimes, the sphere, each contact's energy
  // balance, the attitude figures at 10 and 65 rev/s, Bocquet's rows beside the model, the answer.
  TempDir tmp("stoneskip-report-stones");
  const fs::path dir = tmp.path() / "stones";
  const auto r = run_stoneskip("report stones --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  const std::string index = read_file(dir / "index.md");
  for (const char* text : {"model: planing, uniform, held", "model: planing, savitsky_wagner, free", "Rosellini: surfing",
                           "Johnson & Reid: largest ricochet path angle of a sphere", "**Energy over each contact.**",
                           "### Model beside model (not scored)", "figures/attitude_regime_10.png",
                           "figures/attitude_regime_65.png", "* The answer: **"})
    BOOST_TEST(index.find(text) != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(scene_quick_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report; and the still frames the page promises are drawn.
  TempDir tmp("stoneskip-report-scene");
  const fs::path dir = tmp.path() / "scene";
  const auto r = run_stoneskip("report scene --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  BOOST_TEST(fs::file_size(dir / "figures" / "still_seed_8ms.png") > 0u);
}

BOOST_AUTO_TEST_CASE(captures_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report — on three shipped captures (a WiiYourself! log with jitter and
  // clipping, a throw at the physical convention's first bounce, an unusable one) and a small
  // ensemble, each usable one also thrown into a small coupled scene: every capture has its
  // section and anchor, every figure is drawn (the scene's two among them), every verdict agrees
  // with its rule, and rendering data.h5 again reproduces index.md byte for byte.
  TempDir tmp("stoneskip-report-captures");
  const fs::path dir = tmp.path() / "captures";
  const auto r = run_stoneskip("capture validate cases/captures/skip_two_remotes_wiiyourself.csv "
                               "cases/captures/skip_threshold_14ms.log cases/captures/no_still_part.log --members 12 "
                               "--scene cases/captures/pond_two_way.toml --scene-set scene.duration_s=0.3 "
                               "--scene-set solver.t_max_s=0.3 --scene-set water.nx=80 --scene-set water.ny=40 "
                               "--scene-set water.cell_m=0.04 --out " +
                               dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  const std::string index = read_file(dir / "index.md");
  for (const char* key : {"skip_two_remotes_wiiyourself_csv", "skip_threshold_14ms_log", "no_still_part_log"}) {
    BOOST_TEST(index.find("<a id=\"" + std::string(key) + "\"></a>") != std::string::npos, key);
    BOOST_TEST(index.find("](#" + std::string(key) + ")") != std::string::npos, key);
  }
  BOOST_TEST(index.find("**unusable** — no still part") != std::string::npos);
  for (const char* key : {"skip_two_remotes_wiiyourself_csv", "skip_threshold_14ms_log"}) {
    BOOST_TEST(index.find("](figures/" + std::string(key) + "_scene_stone.png)") != std::string::npos, key);
    BOOST_TEST(index.find("](figures/" + std::string(key) + "_scene_waves.png)") != std::string::npos, key);
  }
  // A folder that is not a report is refused before any work (exit 2, nothing written into it).
  const fs::path other = tmp.path() / "other";
  fs::create_directories(other);
  { std::ofstream(other / "notes.txt") << "mine\n"; }
  const auto refused = run_stoneskip("capture validate cases/captures/gentle_sidearm.log --no-simulate --out " + other.string());
  BOOST_TEST(refused.status == 2, refused.out);
  BOOST_TEST(!fs::exists(other / "index.md"));
}

BOOST_AUTO_TEST_CASE(a_bad_study_file_fails_before_any_work_and_leaves_nothing) {
  // Oracle: the input rules — one line naming the file and key, exit 2, no folder.
  TempDir tmp("stoneskip-report-bad");
  const fs::path study = tmp.path() / "bad.toml";
  {
    std::ofstream f(study);
    f << "[study]\nkind = \"waves\"\npreset = \"x\"\n[convergence]\nspace_grid = [32, 64]\n";
  }
  const fs::path dir = tmp.path() / "out";
  const auto r = run_stoneskip("report waves --study " + study.string() + " --out " + dir.string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("convergence.space_grid") != std::string::npos, r.out);
  BOOST_TEST(!fs::exists(dir));
  BOOST_TEST(!fs::exists(fs::path(dir.string() + ".partial")));
}

BOOST_AUTO_TEST_CASE(render_refuses_a_folder_that_is_not_a_report) {
  // Oracle: the input rules — exit 2 and a line naming the file.
  TempDir tmp("stoneskip-render-bad");
  const auto r = run_stoneskip("report render " + tmp.path().string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("data.h5") != std::string::npos, r.out);
}

BOOST_AUTO_TEST_SUITE_END()
