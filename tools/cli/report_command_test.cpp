// End-to-end tests of the reports: `report waves --quick`, `report stones --quick` and
// `capture validate --out` run the built executable, then `report render` rebuilds the page from
// data.h5 alone.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "tools/cli/hdf5_edit.hpp"
#include "tools/cli/test_support.hpp"
#include "tools/io/folder_manifest.hpp"
#include "tools/io/hdf5_file.hpp"
#include "verification/study/record.hpp"
#include "verification/study/verdict_rules.hpp"

namespace {

using stoneskip::Record;
using stoneskip::test::read_file;
using stoneskip::test::set_attribute;
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

stoneskip::Table stored_table(const stoneskip::Hdf5Reader& data, const std::string& path) {
  std::vector<std::string> parts;
  std::istringstream in(path);
  for (std::string p; std::getline(in, p, '/');)
    if (!p.empty()) parts.push_back(p);
  return read_table_at(data.root(), parts, 0);
}

// The rows a source names, read from data.h5 on their own (not through the report's code).
Points stored_points(const stoneskip::Hdf5Reader& data, const std::vector<std::string>& src) {
  // src: table, data.h5 path, x column, y column, rows, drawn-at height, x power, y scale, where
  // column or -, where value
  const stoneskip::Table t = stored_table(data, src[1]);
  const auto x = t.column(src[2]), y = t.column(src[3]);
  const double at = std::strtod(src[5].c_str(), nullptr), power = std::strtod(src[6].c_str(), nullptr),
               scale = std::strtod(src[7].c_str(), nullptr), value = std::strtod(src[9].c_str(), nullptr);
  const std::vector<double> where = src[8] == "-" ? std::vector<double>{} : t.column(src[8]);
  Points pts;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (src[4] == "y_nonnegative" && !(y[k] >= 0)) continue;
    if (src[4] == "y_negative" && !(y[k] < 0)) continue;
    if (src[4] == "y_positive" && !(y[k] > 0)) continue;
    if (src[4] == "y_nonpositive" && !(y[k] <= 0)) continue;
    if (!where.empty() && where[k] != value) continue;
    const double xx = power == 1 ? x[k] : std::pow(x[k], power), yy = std::isnan(at) ? scale * y[k] : at;
    if (std::isfinite(xx) && std::isfinite(yy)) pts.emplace_back(xx, yy);
  }
  return pts;
}

bool close(double a, double b) { return std::abs(a - b) <= kTenDigits * std::max(std::abs(a), std::abs(b)); }

// Every row of a .dat file, each cell as read ("NaN" stays NaN; a blank line, a row of NaN only, is
// an empty row).
std::vector<std::vector<double>> dat_rows(const fs::path& dat) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(read_file(dat));
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') continue;
    std::istringstream cells(line);
    std::vector<double> row;
    for (std::string c; cells >> c;) row.push_back(std::strtod(c.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

// The .dat's rows with both x and y finite, in file order, and a NaN pair where a line breaks.
Points dat_path(const fs::path& dat) {
  Points pts;
  for (const auto& r : dat_rows(dat)) pts.emplace_back(r.size() > 0 ? r[0] : NAN, r.size() > 1 ? r[1] : NAN);
  return pts;
}

// An outline is horizontal pieces, one per point of the series it is drawn through: each piece's
// height is that point's value and its span holds the point's abscissa (a step that ends before the
// last value, or a piece at a height no point has, fails).
void check_outline(const fs::path& figures, const std::string& table, const std::string& of) {
  Points pieces;  // (x0, x1) with its height: drawn as pairs of rows
  std::vector<double> heights;
  const Points path = dat_path(figures / (table + ".dat"));
  for (std::size_t k = 0; k < path.size();) {
    if (!std::isfinite(path[k].first)) {
      ++k;
      continue;
    }
    BOOST_REQUIRE_MESSAGE(k + 1 < path.size() && path[k + 1].second == path[k].second,
                          table << ": row " << k << " does not start a horizontal piece");
    pieces.emplace_back(path[k].first, path[k + 1].first);
    heights.push_back(path[k].second);
    k += 2;
  }
  const Points dots = plotted_points(figures / (of + ".dat"));
  BOOST_TEST(pieces.size() == dots.size(), table << ": " << pieces.size() << " pieces through " << dots.size() << " points");
  for (const auto& [x, y] : dots) {
    bool held = false;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      held = held || (heights[i] == y && pieces[i].first <= x && x <= pieces[i].second);
    BOOST_TEST(held, table << ": no piece at height " << y << " over x = " << x);
  }
}

// Every row of a copied table equals the stored table's named columns, row for row (NaN for NaN).
void check_copy(const stoneskip::Hdf5Reader& data, const fs::path& dat, const std::string& path, const std::string& columns) {
  const stoneskip::Table t = stored_table(data, path);
  std::vector<std::vector<double>> cols;
  std::istringstream in(columns);
  if (columns == "*")
    for (const auto& c : t.columns) cols.push_back(t.column(c));
  else
    for (std::string c; std::getline(in, c, ',');) cols.push_back(t.column(c));
  const auto rows = dat_rows(dat);
  BOOST_REQUIRE_EQUAL(rows.size(), t.rows());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    BOOST_REQUIRE(rows[r].empty() || rows[r].size() == cols.size());
    for (std::size_t c = 0; c < cols.size(); ++c) {
      const double a = rows[r].empty() ? NAN : rows[r][c], b = cols[c][r];
      BOOST_TEST(((std::isnan(a) && std::isnan(b)) || a == b || close(a, b)),
                 dat.filename() << " row " << r << " column " << c << ": drawn " << a << ", stored " << b);
    }
  }
}

// A row per stored estimate: columns 2–4 are the estimate's nominal, low and high, read from data.h5.
void check_estimates(const stoneskip::Hdf5Reader& data, const fs::path& dat, const std::string& paths) {
  std::vector<std::string> records;
  std::istringstream in(paths);
  for (std::string p; std::getline(in, p, ',');) records.push_back(p);
  const auto rows = dat_rows(dat);
  BOOST_REQUIRE_EQUAL(rows.size(), records.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Record v = stoneskip::load_record(data.root().open_group(records[r].substr(1)));
    BOOST_REQUIRE_EQUAL(rows[r].size(), 4u);
    const char* keys[3] = {"nominal", "low", "high"};
    for (int c = 0; c < 3; ++c) {
      const double a = rows[r][c + 1], b = v.number(keys[c]);
      BOOST_TEST(((std::isnan(a) && std::isnan(b)) || close(a, b)), dat.filename() << " row " << r << " " << keys[c] << ": drawn " << a << ", stored " << b);
    }
  }
}

// A guide y = c·x^p: every point gives the same c.
void check_power_law(const fs::path& dat, double p) {
  const Points pts = plotted_points(dat);
  BOOST_TEST(pts.size() >= 2u);
  for (const auto& [x, y] : pts)
    BOOST_TEST(close(y / std::pow(x, p), pts.front().second / std::pow(pts.front().first, p)),
               dat.filename() << ": (" << x << ", " << y << ") is not on y ∝ x^" << p);
}

// The line y = a + b·x, a and b read from the record's attributes in data.h5.
void check_line(const stoneskip::Hdf5Reader& data, const fs::path& dat, const std::vector<std::string>& f) {
  const Record r = stoneskip::load_record(data.root().open_group(f[2].substr(1)));
  const double a = r.number(f[3]), b = r.number(f[4]);
  const Points pts = plotted_points(dat);
  BOOST_TEST(!pts.empty());
  for (const auto& [x, y] : pts)
    BOOST_TEST(std::abs(y - (a + b * x)) <= kTenDigits * (std::abs(a) + std::abs(b * x)),
               dat.filename() << ": (" << x << ", " << y << ") is not on " << a << " + " << b << " x");
}

// Every line figure's plotted points are the stored rows it names: for each set of tables that
// share one list of sources (a curve split where it breaks), the union of their finite rows is the
// union of the rows selected from data.h5, point for point; each such table is plotted `using 1:2`.
// A series drawn from no table is checked against what it says it is (an outline through another
// series, a guide y ∝ x^p, a stored line), a copied table row for row against data.h5. Returns the
// number of figures checked; series that say nothing are counted in `computed`.
int check_figures_match_their_tables(const fs::path& dir, int& computed, std::vector<std::string>& computed_names) {
  stoneskip::Hdf5Reader data(dir / "data.h5");
  const fs::path figures = dir / "figures";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(figures)) {
    if (entry.path().extension() != ".sources") continue;
    const std::string name = entry.path().stem().string();
    const std::string script = read_file(figures / (name + ".gp"));
    std::map<std::string, std::vector<std::vector<std::string>>> by_table;
    const std::string listed = read_file(entry.path());
    // Every table the script draws is accounted for in the .sources, by one of the kinds below.
    const std::regex drawn("'(" + name + "_[a-z0-9_]*)\\.dat'");
    for (std::sregex_iterator it(script.begin(), script.end(), drawn), end; it != end; ++it)
      BOOST_TEST((listed.rfind((*it)[1].str() + "\t", 0) == 0 || listed.find("\n" + (*it)[1].str() + "\t") != std::string::npos),
                 "figure " << name << " draws " << (*it)[1] << ", which its .sources does not account for");
    std::istringstream in(listed);
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> f;
      std::istringstream cells(line);
      for (std::string c; std::getline(cells, c, '\t');) f.push_back(c);
      BOOST_TEST_CONTEXT("figure " << name << ", line '" << line << "'") {
        BOOST_REQUIRE(f.size() >= 2u);
        if (f.size() == 10) {
          by_table[f[0]].push_back(f);
        } else if (f[1] == "-" && f.size() == 3 && !f[2].empty()) {  // computed, and it says from what
          ++computed;
          computed_names.push_back(f[0] + ": " + f[2]);
        } else if (f[1] == "outline" && f.size() == 3) {
          check_outline(figures, f[0], f[2]);
        } else if (f[1] == "power_law" && f.size() == 3) {
          check_power_law(figures / (f[0] + ".dat"), std::strtod(f[2].c_str(), nullptr));
        } else if (f[1] == "line" && f.size() == 5) {
          check_line(data, figures / (f[0] + ".dat"), f);
        } else if (f[1] == "estimates" && f.size() == 3) {
          check_estimates(data, figures / (f[0] + ".dat"), f[2]);
        } else if (f[1] == "copy" && f.size() == 4) {
          check_copy(data, figures / (f[0] + ".dat"), f[2], f[3]);
          BOOST_TEST(script.find("'" + f[0] + ".dat'") != std::string::npos);
        } else {
          BOOST_ERROR("bad line");
        }
      }
    }
    std::map<std::string, std::vector<std::string>> groups;  // the sources, joined → tables
    std::map<std::string, std::vector<std::vector<std::string>>> group_sources;
    for (const auto& [table, srcs] : by_table) {
      std::string key;
      for (const auto& s : srcs)
        for (std::size_t i = 1; i < s.size(); ++i) key += s[i] + (i + 1 < s.size() ? "|" : ";");
      groups[key].push_back(table);
      group_sources[key] = srcs;
    }
    for (const auto& [key, tables] : groups) {
      BOOST_TEST_CONTEXT("figure " << name << ", tables " << tables.front() << " …, from " << key) {
        Points plotted, stored;
        for (const auto& t : tables) {
          BOOST_TEST((script.find("'" + t + ".dat' using 1:2 ") != std::string::npos ||
                      script.find("'" + t + ".dat' u 1:2 ") != std::string::npos));
          const Points p = plotted_points(figures / (t + ".dat"));
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
  std::vector<std::string> computed_names;
  const int line_figures = check_figures_match_their_tables(dir, computed, computed_names);
  std::string list;
  for (const auto& t : computed_names) list += "\n  " + t;
  BOOST_TEST_MESSAGE(dir.filename() << ": " << line_figures << " figures checked against data.h5; " << computed
                                    << " tables computed from stored values, each saying how:" << list);
  // Every figure that draws a table says where it comes from (a figure with no .sources draws none:
  // a still or a map drawn from an image).
  for (const auto& entry : fs::directory_iterator(dir / "figures")) {
    const fs::path p = entry.path();
    if (p.extension() != ".gp" || p.stem().extension() == ".svg") continue;
    if (read_file(p).find(".dat'") != std::string::npos)
      BOOST_TEST(fs::exists(dir / "figures" / (p.stem().string() + ".sources")), p.filename() << " draws tables but has no .sources");
  }
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

  // Rendering in place replaces only what stoneskip wrote (oracle: the folder's manifest, and the
  // user's bytes, which must survive): an edited index.md, or an index.html in a folder without a
  // manifest, is refused with exit 2 and kept; a folder named through a link is refused; a bare
  // folder holding only data.h5 is rendered.
  const auto copy = [&](const std::string& name) {
    const fs::path to = tmp.path() / name;
    fs::copy(dir, to, fs::copy_options::recursive);
    return to;
  };
  const fs::path edited = copy("edited");
  { std::ofstream(edited / "index.md") << "# my notes\n"; }
  const auto e = run_stoneskip("report render " + edited.string());
  BOOST_TEST(e.status == 2, e.out);
  BOOST_TEST(e.out.find("index.md', which changed since stoneskip wrote it") != std::string::npos, e.out);
  BOOST_TEST(read_file(edited / "index.md") == "# my notes\n");
  const fs::path bare = tmp.path() / "bare";
  fs::create_directories(bare);
  fs::copy_file(dir / "data.h5", bare / "data.h5");
  { std::ofstream(bare / "index.html") << "mine\n"; }
  const auto b = run_stoneskip("report render " + bare.string());
  BOOST_TEST(b.status == 2, b.out);
  BOOST_TEST(read_file(bare / "index.html") == "mine\n");
  fs::remove(bare / "index.html");
  BOOST_TEST(run_stoneskip("report render " + bare.string()).status == 0);
  BOOST_TEST(read_file(bare / "index.md") == read_file(dir / "index.md"));
  fs::create_directory_symlink(dir, tmp.path() / "link");
  const auto l = run_stoneskip("report render " + (tmp.path() / "link").string());
  BOOST_TEST(l.status == 2, l.out);
  BOOST_TEST(l.out.find("is a link") != std::string::npos, l.out);
  // A figure an earlier rendering drew (listed in the manifest) that this one does not draw is
  // removed; a file of the user's beside it stays.
  const fs::path stale = copy("stale");
  fs::copy_file(stale / "figures" / "convergence_space.png", stale / "figures" / "old_study.png");
  stoneskip::write_folder_manifest(stale);
  { std::ofstream(stale / "figures" / "mine.txt") << "mine\n"; }
  BOOST_TEST(run_stoneskip("report render " + stale.string()).status == 0);
  BOOST_TEST(!fs::exists(stale / "figures" / "old_study.png"));
  BOOST_TEST(read_file(stale / "figures" / "mine.txt") == "mine\n");
  // Without gnuplot (a PATH that holds none) every figure is named on the page as not drawn, exit 1,
  // and no picture, script or table of the earlier rendering stays beside it (the front page shows a
  // report's picture found on disk); the user's file stays, and with gnuplot back the page is as
  // before, byte for byte.
  const fs::path plain = copy("without_gnuplot");
  { std::ofstream(plain / "figures" / "mine.txt") << "mine\n"; }
  stoneskip::SubprocessOptions merged;
  merged.stderr_to = stoneskip::SubprocessOptions::Stderr::merged;
  const stoneskip::SubprocessResult g =
      stoneskip::run_program({"/usr/bin/env", "PATH=/nonexistent", STONESKIP_EXE, "report", "render", plain.string()}, merged);
  BOOST_TEST(g.exit_status == 1, g.out);
  BOOST_TEST(g.out.find("gnuplot not found") != std::string::npos, g.out);
  std::string left;
  for (const auto& entry : fs::directory_iterator(plain / "figures")) left += entry.path().filename().string() + " ";
  BOOST_TEST(left == "mine.txt ");
  const std::string page = read_file(plain / "index.md");
  BOOST_TEST(page.find("](figures/") == std::string::npos);  // no link to a picture
  std::size_t named = 0;
  for (std::size_t at = page.find("**Figure not drawn:**"); at != std::string::npos; at = page.find("**Figure not drawn:**", at + 1))
    ++named;
  std::size_t drawn = 0;
  for (const auto& entry : fs::directory_iterator(dir / "figures")) drawn += entry.path().extension() == ".png";
  BOOST_TEST(named == drawn);
  BOOST_TEST(run_stoneskip("report render " + plain.string()).status == 0);
  BOOST_TEST(read_file(plain / "index.md") == read_file(dir / "index.md"));
  // Stored numbers edited apart from the verdicts decided on them are refused, not rendered beside
  // them: the section's tolerance (the verdicts' is 0.1), and an error the fit no longer follows.
  const fs::path tolerance = copy("tolerance");
  set_attribute(tolerance / "data.h5", "/sections/convergence", "tolerance", 0.3);
  const auto t = run_stoneskip("report render " + tolerance.string());
  BOOST_TEST(t.status == 2, t.out);
  BOOST_TEST(t.out.find("verdict's tolerance") != std::string::npos, t.out);
  BOOST_TEST(read_file(tolerance / "index.md") == read_file(dir / "index.md"));  // nothing rewritten
  // Provenance that stoneskip does not write (a line break that would start a heading, a huge
  // string, a time in another form) is refused, naming the attribute; a command holding backticks
  // is shown whole as code (CommonMark: a longer fence).
  const fs::path provenance = copy("provenance");
  for (const auto& [name, value] : {std::pair<const char*, std::string>{"code_version", "stoneskip 1\n\n## Findings\n"},
                                    {"code_version", "stoneskip " + std::string(300, 'x')},
                                    {"created_utc", "yesterday"}}) {
    set_attribute(provenance / "data.h5", "/", name, value);
    const auto p = run_stoneskip("report render " + provenance.string());
    BOOST_TEST(p.status == 2, name << ": " << p.out);
    BOOST_TEST(p.out.find(name) != std::string::npos, p.out);
    fs::copy_file(dir / "data.h5", provenance / "data.h5", fs::copy_options::overwrite_existing);
  }
  set_attribute(provenance / "data.h5", "/", "command", std::string("stoneskip report waves --out `a``b`"));
  BOOST_TEST(run_stoneskip("report render " + provenance.string()).status == 0);
  BOOST_TEST(read_file(provenance / "index.md").find("* Made by: ``` stoneskip report waves --out `a``b` ```.") !=
             std::string::npos);
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
  // A measured figure edited apart from the verdict decided on it (900 frames/s under "meets the
  // target" of 3000) is refused, not rendered.
  const fs::path edited = tmp.path() / "edited";
  fs::copy(dir, edited, fs::copy_options::recursive);
  set_attribute(edited / "data.h5", "/sections/speed", "scene_fps_1core", 900.0);
  const auto e = run_stoneskip("report render " + edited.string());
  BOOST_TEST(e.status == 2, e.out);
  BOOST_TEST(e.out.find("scene_fps_1core is 900 but its verdict scene_target was decided on") != std::string::npos, e.out);
  // A still frame's coordinate edited to NaN, or its cell to 1e308 m, was written into the gnuplot
  // script as `nan` or `inf` (the figure failed): refused by name instead (stored_values.hpp).
  for (const auto& [key, value, says] : std::vector<std::tuple<const char*, double, std::string>>{
           {"stone_y_m", std::nan(""), "'stone_y_m' must be a finite number"},
           {"near_dx_m", 1e308, "'near_dx_m' × the window's"}}) {
    const fs::path frame = tmp.path() / (std::string("frame_") + key);
    fs::copy(dir, frame, fs::copy_options::recursive);
    set_attribute(frame / "data.h5", "/sections/frames/seed_8ms", key, value);
    const auto f = run_stoneskip("report render " + frame.string());
    BOOST_TEST(f.status == 2, f.out);
    BOOST_TEST(f.out.find(says) != std::string::npos, f.out);
  }
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
