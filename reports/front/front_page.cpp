#include "reports/front/front_page.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include "reports/common/html_page.hpp"
#include "reports/common/markdown.hpp"
#include "reports/common/section.hpp"
#include "reports/common/summary.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/printable_text.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

// The order a reader meets the reports in: the water, the stone, the two together, the captures.
int kind_rank(const std::string& kind) {
  static const std::map<std::string, int> rank{{"waves", 0}, {"stones", 1}, {"scene", 2}, {"captures", 3}};
  const auto it = rank.find(kind);
  return it == rank.end() ? 9 : it->second;
}

std::string first_heading(const std::string& markdown) {
  for (const Heading& h : headings(markdown))
    if (h.level == 1) return h.text;
  return "";
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(p, ec)) && !ec;
}

std::vector<fs::path> sorted_entries(const fs::path& dir) {
  std::vector<fs::path> v;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

std::string relative_name(const fs::path& p, const fs::path& out) { return p.lexically_relative(out).generic_string(); }

// A relative path as a link target: every byte but the unreserved ones and '/' percent-encoded
// (RFC 3986 §2.1, §2.3), so a folder named "#x", "a b" or "%41" links to itself and a line break
// in a name cannot end the line of Markdown it is in.
std::string link(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char ch : path) {
    if (std::isalnum(ch) || ch == '-' || ch == '.' || ch == '_' || ch == '~' || ch == '/') {
      out += static_cast<char>(ch);
    } else {
      out += '%';
      out += hex[ch >> 4];
      out += hex[ch & 15];
    }
  }
  return out;
}

FrontThrow read_throw(const fs::path& file, const fs::path& out) {
  FrontThrow t;
  t.file = relative_name(file, out);
  Hdf5Reader in(file);
  const H5Group& root = in.root();
  t.title = root.has_attr("title") ? root.attr_string("title") : "";
  t.case_file = root.has_attr("case_file") ? root.attr_string("case_file") : "";
  for (const std::string solver : {"realtime", "reference"}) {
    if (!root.has(solver)) continue;
    const H5Group g = root.open_group(solver);
    FrontThrowRun r;
    r.solver = solver;
    r.outcome = g.has_attr("outcome") ? g.attr_string("outcome") : "";
    r.bounces = g.has_attr("bounces") ? g.attr_double("bounces") : 0;
    r.distance_m = g.has_attr("distance_m") ? g.attr_double("distance_m") : 0;
    t.runs.push_back(r);
  }
  return t;
}

// "**consistent** ×3 · **does not converge** · …": each verdict phrase of the findings once, with
// how often it is said, in the order first said.
std::string verdict_line(const std::vector<std::string>& findings) {
  std::vector<std::string> order;
  std::map<std::string, int> count;
  for (const auto& f : findings)
    for (const auto& v : verdict_phrases(f))
      if (count[v]++ == 0) order.push_back(v);
  std::string line;
  for (const auto& v : order) line += (line.empty() ? "" : " · ") + ("**" + v + "**") + (count[v] > 1 ? " ×" + std::to_string(count[v]) : "");
  // Findings without a bold verdict (the captures' count of verdicts): their first sentence.
  if (line.empty() && !findings.empty()) line = findings.front().substr(0, findings.front().find(". "));
  if (!line.empty() && line.back() == '.') line.pop_back();
  return line;
}

}  // namespace

FrontPageInput read_front_page_input(const fs::path& out, const std::function<RenderedReport(const StoredReport&)>& render) {
  FrontPageInput in;
  std::error_code ec;
  auto linked = [&](const fs::path& p) { return fs::is_symlink(fs::symlink_status(p, ec)); };
  for (const fs::path& dir : sorted_entries(out)) {
    // A report folder is one holding a data.h5 of any kind; what is not a plain file there is said.
    std::error_code e2;
    const fs::path data = dir / "data.h5";
    const bool present = fs::exists(fs::symlink_status(data, e2));
    if (linked(dir)) {
      if (present) in.skipped.push_back({relative_name(dir, out), "a link: not followed"});
      continue;
    }
    if (!present) continue;
    if (linked(data) || !is_file(data)) {
      in.skipped.push_back({relative_name(data, out), linked(data) ? "a link: not followed" : "not a plain file"});
      continue;
    }
    // A sweep page, a damaged file, a report whose stored verdicts contradict their rules or that
    // cannot be rendered: not shown, and said (report render would refuse it too).
    StoredReport stored;
    RenderedReport rendered;
    try {
      stored = load_stored_report(dir / "data.h5");
      std::vector<std::string> contradicted = contradicted_verdicts(stored.report);
      for (auto& c : contradicted_verdicts(stored.sections)) contradicted.push_back(std::move(c));
      if (!contradicted.empty()) throw InputError("a stored verdict contradicts its rule: " + contradicted.front());
      rendered = render(stored);
    } catch (const std::exception& e) {
      std::string why = e.what();
      const std::string file = (dir / "data.h5").string() + ": ";
      if (why.rfind(file, 0) == 0) why = why.substr(file.size());  // the path is the line's own
      in.skipped.push_back({relative_name(dir / "data.h5", out), printable_text(why)});
      continue;
    }
    // The page links the report's own index.md: without it (data written, page not yet rendered)
    // the link would lead nowhere.
    const fs::path page = dir / "index.md";
    if (linked(page) || !is_file(page)) {
      in.skipped.push_back({relative_name(page, out), linked(page) ? "a link: not followed"
                                                                   : "missing or not a plain file (render it: stoneskip report render " +
                                                                         dir.string() + ")"});
      continue;
    }
    FrontReport r;
    r.folder = relative_name(dir, out);
    r.kind = stored.kind;
    r.title = first_heading(rendered.markdown);
    r.code_version = stored.code_version;
    r.created_utc = stored.created_utc;
    r.findings = report_findings(rendered.markdown);
    std::vector<std::string> candidates;
    if (!rendered.headline_figure.empty()) candidates.push_back(rendered.headline_figure);
    for (const auto& f : rendered.figures) candidates.push_back(f.name);
    // Pictures only from the report's own figures/ folder: a linked folder or picture is not followed.
    const bool own_figures = !linked(dir / "figures");
    r.figures = !own_figures ? "link" : fs::is_directory(fs::symlink_status(dir / "figures", ec)) ? "folder" : "";
    for (const auto& name : candidates)
      if (own_figures && !linked(dir / "figures" / (name + ".png")) && is_file(dir / "figures" / (name + ".png"))) {
        r.picture = relative_name(dir / "figures" / (name + ".png"), out);
        break;
      }
    in.reports.push_back(std::move(r));
  }
  if (in.reports.empty()) throw_input_error(out.string(), 0, "", "holds no report (no sub-folder with a report's data.h5): run the main job first");
  std::stable_sort(in.reports.begin(), in.reports.end(),
                   [](const FrontReport& a, const FrontReport& b) { return kind_rank(a.kind) < kind_rank(b.kind); });
  std::string scene_picture;
  for (const auto& r : in.reports)
    if (r.kind == "scene" && scene_picture.empty()) scene_picture = r.picture;
  for (const fs::path& f : sorted_entries(out / "movies")) {
    if (f.extension() != ".mp4") continue;
    if (linked(f) || !is_file(f) || !stoneskip_wrote(f, OutputFormat::movie)) {
      in.skipped.push_back({relative_name(f, out), linked(f) ? "a link: not followed" : "not a movie stoneskip made (no mark)"});
      continue;
    }
    FrontMovie m;
    m.file = relative_name(f, out);
    m.size_mb = static_cast<double>(fs::file_size(f)) / 1e6;
    for (const fs::path& p : sorted_entries(out / "movies"))
      if (p.extension() == ".png" && p.stem().string().rfind(f.stem().string(), 0) == 0 && !linked(p) && is_file(p)) {
        m.picture = relative_name(p, out);
        break;
      }
    if (m.picture.empty()) m.picture = scene_picture;
    in.movies.push_back(m);
  }
  for (const fs::path& f : sorted_entries(out / "throws")) {
    if (f.extension() != ".h5") continue;
    if (linked(f)) {
      in.skipped.push_back({relative_name(f, out), "a link: not followed"});
      continue;
    }
    if (!is_file(f)) {
      in.skipped.push_back({relative_name(f, out), "not a plain file"});
      continue;
    }
    FrontThrow t;
    try {
      t = read_throw(f, out);
    } catch (const std::exception& e) {
      std::string why = e.what();
      if (why.rfind(f.string() + ": ", 0) == 0) why = why.substr(f.string().size() + 2);
      in.skipped.push_back({relative_name(f, out), printable_text(why)});
      continue;
    }
    if (t.runs.empty()) {  // no realtime or reference group: another file (a report's data.h5, say)
      in.skipped.push_back({relative_name(f, out), "holds no realtime or reference run: not a throw's file"});
      continue;
    }
    in.throws.push_back(std::move(t));
  }
  return in;
}

std::string front_page_markdown(const FrontPageInput& in) {
  std::ostringstream md;
  md << "# stoneskip: what the main job found\n\n"
     << "stoneskip verifies and validates Lee & Baek's (2013) real-time stone-skipping model: the water surface against "
        "its exact solution, the stone against a high-accuracy reference (SUNDIALS CVODE) and against experiments, and "
        "Wii Remote captures as inputs. This page links everything the main job wrote into this folder. Each line below is "
        "read from the reports' `data.h5`; each report opens with its findings and links to its sections.\n\n";
  // The reports, each with its verdicts in one line and a picture.
  md << "## The reports\n\n";
  // A title two reports share (the captures and the capture through the scene) is told apart by folder.
  std::map<std::string, int> titles;
  for (const auto& r : in.reports) ++titles[r.title];
  auto name = [&](const FrontReport& r) {
    return (r.title.empty() ? code(r.folder) : r.title) + (titles[r.title] > 1 ? " (" + code(r.folder + "/") + ")" : "");
  };
  for (const auto& r : in.reports) {
    md << "### [" << name(r) << "](" << link(r.folder) << "/index.md)\n\n";
    const std::string verdicts = verdict_line(r.findings);
    // The bold verdicts of the report's opening findings, each counted once per finding that states it
    // (×2: two findings say it), not a tally of every verdict in the report.
    md << "**Its findings' verdicts:** " << (verdicts.empty() ? std::string("none stated") : verdicts) << ". "
       << "Folder " << code(r.folder + "/") << " (`" << r.kind << "` report, data written " << r.created_utc << "): "
       << "[page](" << link(r.folder) << "/index.md), `data.h5`"
       << (r.figures == "folder" ? ", `figures/`"
           : r.figures == "link" ? " (its `figures/` is a link, not followed)"
                                 : " (no `figures/`)")
       << ".\n\n";
    if (!r.picture.empty()) md << "![" << r.title << "](" << link(r.picture) << ")\n\n";
  }
  if (!in.movies.empty()) {
    md << "## The movie\n\n";
    for (const auto& m : in.movies) {
      // Each movie named by its scene: the shipped throw of the same name (throws/NAME.h5), if there is one.
      std::string what = "the scene as a movie";
      for (const auto& th : in.throws)
        if (fs::path(th.file).stem() == fs::path(m.file).stem()) what = "the scene of " + code(fs::path(th.file).filename().string()) + " (" + printable_text(th.title) + ") as a movie";
      md << "* [" << code(m.file) << "](" << link(m.file) << ") (" << fmt(m.size_mb, 3) << " MB): " << what << ".\n";
    }
    md << "\n";
    if (!in.movies.front().picture.empty()) md << "![A still of the scene](" << link(in.movies.front().picture) << ")\n\n";
  }
  if (!in.throws.empty()) {
    md << "## The shipped throws\n\n"
       << "Each shipped case thrown by the real-time model and, where the case asks, the CVODE reference; the `.h5` holds "
          "the trajectory and every contact (reports/README.md describes it).\n\n";
    MarkdownTable t({"file", "throw", "case", "real-time: bounces, distance (m), outcome", "reference: bounces, distance (m), outcome"});
    for (const auto& th : in.throws) {
      std::map<std::string, std::string> cell{{"realtime", "–"}, {"reference", "–"}};
      for (const auto& r : th.runs) cell[r.solver] = fmt(r.bounces) + ", " + fmt(r.distance_m, 3) + ", " + r.outcome;
      const std::string title = printable_text(th.title);  // a case's own words: one line in a cell
      t.row({"[" + code(fs::path(th.file).filename().string()) + "](" + link(th.file) + ")", title,
             th.case_file.empty() ? "–" : code(th.case_file),
             cell["realtime"], cell["reference"]});
    }
    md << t.str() << "\n";
  }
  // What we found: each report's findings as it states them.
  md << "## What we found\n\n";
  for (const auto& r : in.reports) {
    md << "### " << name(r) << "\n\n";
    if (r.findings.empty()) {
      md << "The report states no findings list; [read it](" << link(r.folder) << "/index.md).\n\n";
      continue;
    }
    for (std::string f : r.findings) {
      // A link into the report's own page ("(#2-…)") points into that page from here.
      for (std::size_t at = f.find("](#"); at != std::string::npos; at = f.find("](#", at + 2))
        f.insert(at + 2, link(r.folder) + "/index.md");
      md << "* " << f << "\n";
    }
    md << "\n[The whole report](" << link(r.folder) << "/index.md).\n\n";
  }
  if (!in.skipped.empty()) {
    md << "## Not shown\n\n"
       << "Found in this folder and left off this page, each with the reason:\n\n";
    for (const auto& s : in.skipped) md << "* " << code(s.path) << ": " << code(s.reason) << "\n";
    md << "\n";
  }
  md << "## Provenance\n\n";
  std::set<std::string> versions;
  for (const auto& r : in.reports) versions.insert(r.code_version);
  md << "* Reports made by: ";
  bool first = true;
  for (const auto& v : versions) md << (first ? "" : "; ") << v, first = false;
  md << ".\n* This page is made by `stoneskip report front DIR` from the files in DIR alone; run it again after "
        "any report is rebuilt.\n";
  return md.str();
}

namespace {
// An existing page is replaced only if it is a front page (stoneskip's own title within its first
// 4 KB); someone's index.md in that folder is refused, naming it.
void refuse_unless_front_page(const fs::path& path, const std::string& signature) {
  check_output_destination(path);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec))) return;
  const std::string head = read_text_file(path).substr(0, 4096);
  if (head.find(signature) == std::string::npos)
    throw_input_error(path.string(), 0, "", "exists and is not a stoneskip front page: not replaced");
}
}  // namespace

void write_front_page(const fs::path& out, const std::string& markdown) {
  constexpr const char* kTitle = "stoneskip: what the main job found";
  refuse_unless_front_page(out / "index.md", std::string("# ") + kTitle);
  refuse_unless_front_page(out / "index.html", std::string("<title>") + kTitle + "</title>");
  const std::string page = with_contents(markdown);
  write_text_file(out / "index.md", page);
  write_text_file(out / "index.html", html_page(page));
}

}  // namespace stoneskip
