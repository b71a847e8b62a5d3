// The report pages in a real browser. Makes a small output as the main job would (the waves
// report's quick preset, one throw, the front page), then opens every HTML page in headless
// Chromium (and one figure's explorable SVG) and checks, for each page:
//   * every src and href in the HTML names a file that exists, and every #fragment an id in its page;
//   * the browser loaded every image (complete, with a width) and logged no console message (a
//     script error or a refused resource);
// and keeps a screenshot of the front page in the folder given. Oracle that the check can fail: a
// page written here with a missing image, a link to nothing, a fragment to nothing and a script
// error must be caught by each of the checks above; if it is not, the check itself is broken.
//
//   stoneskip_browser_check STONESKIP_EXE REPOSITORY SCREENSHOT_DIR
//
// Exit 0 when every page passes, 1 when one fails, 77 (ctest's SKIP_RETURN_CODE) when no Chromium
// is installed: `apt-get install chromium`, or `bash tools/setup/install-deps.sh test`.
// Every program is started with an argument vector (tools/io/subprocess.hpp), never a shell.
#include <stdlib.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tools/io/subprocess.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int kSkip = 77;
constexpr double kCommandTimeout_s = 300;  // the quick report takes seconds; a hang must still end
constexpr double kBrowserTimeout_s = 180;  // Chromium starts in ~15 s on a loaded 2-core machine
const char kVirtualTime_ms[] = "30000";    // time the page may take to load all its images

int failures = 0;

void fail(const std::string& what) {
  std::printf("FAIL: %s\n", what.c_str());
  ++failures;
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

std::string find_browser() {
  if (const char* b = std::getenv("STONESKIP_BROWSER")) return b;
  for (const std::string b : {"chromium", "chromium-browser", "google-chrome"})
    if (stoneskip::program_runs({b, "--version"})) return b;
  return "";
}

bool run(const std::vector<std::string>& argv, const fs::path& cwd, std::string* out = nullptr) {
  stoneskip::SubprocessOptions o;
  o.working_dir = cwd;
  o.stderr_to = stoneskip::SubprocessOptions::Stderr::merged;
  o.timeout_s = kCommandTimeout_s;
  const auto r = stoneskip::run_program(argv, o);
  if (out) *out = r.out;
  if (!r.ok()) std::printf("command failed (%s): %s\n%s\n", r.error.c_str(), argv[1].c_str(), r.out.substr(0, 2000).c_str());
  return r.ok();
}

std::vector<std::string> browser_argv(const std::string& browser, const fs::path& profile) {
  return {browser,           "--headless",       "--no-sandbox",           "--disable-gpu", "--user-data-dir=" + profile.string(),
          "--enable-logging=stderr", "--v=0", "--allow-file-access-from-files", "--no-first-run", "--hide-scrollbars"};
}

// Every value of an attribute (src, href, id) in a page of ours (quoted with '"', no entities
// but &amp;, &quot;, &lt;, &gt;).
std::vector<std::string> attribute_values(const std::string& html, const std::string& attr) {
  std::vector<std::string> v;
  const std::regex re("\\s" + attr + "=\"([^\"]*)\"");
  for (std::sregex_iterator it(html.begin(), html.end(), re), end; it != end; ++it) {
    std::string s = (*it)[1];
    for (const auto& [e, c] : std::map<std::string, std::string>{{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
      for (std::size_t at; (at = s.find(e)) != std::string::npos;) s.replace(at, e.size(), c);
    v.push_back(s);
  }
  return v;
}

// The links and images of one page that resolve to nothing, as "page: target (why)".
std::vector<std::string> unresolved(const fs::path& page) {
  std::vector<std::string> bad;
  const std::string html = read_file(page);
  std::vector<std::string> targets = attribute_values(html, "src");
  for (auto& h : attribute_values(html, "href")) targets.push_back(h);
  for (const auto& t : targets) {
    if (t.find("://") != std::string::npos || t.rfind("mailto:", 0) == 0) {
      bad.push_back(page.string() + ": " + t + " (leaves the folder: a page must read offline)");
      continue;
    }
    const std::size_t hash = t.find('#');
    const fs::path file = hash == 0 ? page : page.parent_path() / t.substr(0, hash);
    if (!fs::is_regular_file(file)) {
      bad.push_back(page.string() + ": " + t + " (no such file)");
      continue;
    }
    if (hash != std::string::npos && file.extension() == ".html") {
      const auto ids = attribute_values(read_file(file), "id");
      if (std::find(ids.begin(), ids.end(), t.substr(hash + 1)) == ids.end()) bad.push_back(page.string() + ": " + t + " (no such id)");
    }
  }
  return bad;
}

// A page with one of each fault the checks must catch.
const char kBrokenPage[] = R"(<!DOCTYPE html><html><head><meta charset="utf-8"><title>broken</title></head><body>
<p id="here">A page with faults.</p><img src="missing.png" alt="missing"><a href="nothere.html">nothing</a><a href="#nowhere">no id</a>
<script>notDefinedAnywhere();</script></body></html>
)";

// The probe: every page in an iframe; when all have loaded, one line per page saying which
// images loaded and which did not. (File pages may read each other only with
// --allow-file-access-from-files.)
std::string probe_page(const std::vector<std::string>& pages) {
  std::string frames;
  for (const auto& p : pages) frames += "<iframe src=\"" + p + "\" width=\"1200\" height=\"800\"></iframe>\n";
  return "<!DOCTYPE html><html><head><meta charset=\"utf-8\"></head><body>\n" + frames +
         R"(<script>
addEventListener('load', () => {
  let out = '';
  for (const f of document.querySelectorAll('iframe')) {
    const d = f.contentDocument;
    if (!d) { out += 'page=' + f.getAttribute('src') + ' unreadable\n'; continue; }
    const ok = [], bad = [];
    for (const i of d.images) (i.complete && i.naturalWidth > 0 ? ok : bad).push(i.getAttribute('src'));
    out += 'page=' + f.getAttribute('src') + ' images=' + d.images.length + ' loaded=' + ok.length + ' broken=' + bad.join(',') + '\n';
  }
  const pre = document.createElement('pre');
  pre.id = 'probe';
  pre.textContent = out;
  document.body.appendChild(pre);
});
</script></body></html>
)";
}

// The width and height in a PNG's header (0, 0 when it is not a PNG).
std::pair<int, int> png_size(const fs::path& p) {
  const std::string s = read_file(p);
  if (s.size() < 24 || s.compare(1, 3, "PNG") != 0) return {0, 0};
  auto be = [&](std::size_t at) {
    return (static_cast<unsigned char>(s[at]) << 24) | (static_cast<unsigned char>(s[at + 1]) << 16) |
           (static_cast<unsigned char>(s[at + 2]) << 8) | static_cast<unsigned char>(s[at + 3]);
  };
  return {be(16), be(20)};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s STONESKIP_EXE REPOSITORY SCREENSHOT_DIR\n", argv[0]);
    return 2;
  }
  const std::string exe = argv[1];
  const fs::path repo = argv[2], shots = argv[3];
  const std::string browser = find_browser();
  if (browser.empty()) {
    std::printf("SKIPPED: no Chromium found (chromium, chromium-browser or google-chrome on PATH, or STONESKIP_BROWSER); "
                "install it with `apt-get install chromium` or `bash tools/setup/install-deps.sh test`\n");
    return kSkip;
  }
  char templ[] = "/tmp/stoneskip-browser-XXXXXX";
  if (!::mkdtemp(templ)) return 2;
  const fs::path work = templ;
  const fs::path out = work / "out";
  fs::create_directories(out / "throws");

  // 1. A small output, as the main job writes it.
  bool made = run({exe, "report", "waves", "--quick", "--out", (out / "waves").string()}, repo) &&
              run({exe, "run", "cases/paper_8ms_spin.toml", "--solver", "both", "--out", (out / "throws" / "paper_8ms_spin.h5").string()}, repo) &&
              run({exe, "report", "front", out.string()}, repo);
  if (!made) {
    fs::remove_all(work);
    std::printf("FAIL: could not make the output to check\n");
    return 1;
  }
  fs::create_directories(work / "broken");
  write_file(work / "broken" / "index.html", kBrokenPage);

  // 2. The pages, and what the HTML itself names.
  std::vector<fs::path> pages;
  for (const auto& e : fs::recursive_directory_iterator(out))
    if (e.is_regular_file() && e.path().extension() == ".html") pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  if (pages.size() < 2) fail("expected the front page and the waves report's page, found " + std::to_string(pages.size()) + " pages");
  for (const auto& p : pages)
    for (const auto& b : unresolved(p)) fail(b);
  // One figure's SVG as well, opened on its own as a reader who explores it would: gnuplot's inline
  // script (coordinates, legend clicks) must run without a console message.
  for (const auto& e : fs::directory_iterator(out / "waves" / "figures"))
    if (e.path().extension() == ".svg" && read_file(e.path()).find("gnuplot_svg") != std::string::npos) {
      pages.push_back(e.path());
      break;
    }
  if (pages.back().extension() != ".svg") fail("no figure of the waves report is an explorable SVG (gnuplot's mouse script)");
  const auto broken_static = unresolved(work / "broken" / "index.html");
  for (const std::string fault : {"missing.png (no such file)", "nothere.html (no such file)", "#nowhere (no such id)"}) {
    bool caught = false;
    for (const auto& b : broken_static) caught = caught || b.find(fault) != std::string::npos;
    if (!caught) fail("the check of links did not catch the broken page's " + fault);
  }

  // 3. Every page in the browser, at once, through the probe.
  std::vector<std::string> rel;
  for (const auto& p : pages) rel.push_back(p.lexically_relative(work).generic_string());
  rel.push_back("broken/index.html");
  write_file(work / "probe.html", probe_page(rel));
  auto args = browser_argv(browser, work / "profile");
  args.insert(args.end(), {std::string("--virtual-time-budget=") + kVirtualTime_ms, "--dump-dom", "file://" + (work / "probe.html").string()});
  stoneskip::SubprocessOptions o;
  o.timeout_s = kBrowserTimeout_s;
  const auto r = stoneskip::run_program(args, o);
  if (!r.ok()) fail("the browser did not run: " + r.error + " " + r.err.substr(0, 2000));
  const std::size_t at = r.out.find("<pre id=\"probe\">");
  if (at == std::string::npos) fail("the probe found no pages (the browser's output holds no probe)");
  const std::string probe = at == std::string::npos ? "" : r.out.substr(at, r.out.find("</pre>", at) - at);
  for (std::size_t i = 0; i < rel.size(); ++i) {
    const std::string line_start = "page=" + rel[i] + " ";
    const std::size_t l = probe.find(line_start);
    if (l == std::string::npos) {
      fail(rel[i] + ": not seen by the probe");
      continue;
    }
    const std::string line = probe.substr(l, probe.find('\n', l) - l);
    const bool is_broken_page = rel[i] == "broken/index.html";
    const bool all_loaded = line.size() >= 8 && line.compare(line.size() - 8, 8, " broken=") == 0;
    if (is_broken_page && line.find("broken=missing.png") == std::string::npos) fail("the probe did not catch the broken page's missing image: " + line);
    if (!is_broken_page && !all_loaded) fail(rel[i] + ": images the browser could not load: " + line);
    if (!is_broken_page && i < pages.size() && pages[i].extension() == ".html") {
      const std::size_t imgs = attribute_values(read_file(pages[i]), "src").size();
      if (line.find(" images=" + std::to_string(imgs) + " ") == std::string::npos)
        fail(rel[i] + ": the browser saw another number of images than the page names (" + std::to_string(imgs) + "): " + line);
    }
    std::printf("%s\n", line.c_str());
  }
  // Console messages (script errors, refused loads), which Chromium logs as "CONSOLE".
  std::istringstream log(r.err);
  bool control_seen = false;
  for (std::string line; std::getline(log, line);) {
    if (line.find("CONSOLE") == std::string::npos) continue;
    if (line.find("broken/index.html") != std::string::npos && line.find("notDefinedAnywhere") != std::string::npos)
      control_seen = true;
    else
      fail("console: " + line);
  }
  if (!control_seen) fail("the browser's log did not show the broken page's script error: console errors would go unseen");

  // 4. A screenshot of the front page, kept.
  fs::create_directories(shots);
  const fs::path shot = shots / "front_page.png";
  fs::remove(shot);
  auto sargs = browser_argv(browser, work / "profile");
  sargs.insert(sargs.end(), {std::string("--virtual-time-budget=") + kVirtualTime_ms, "--window-size=1280,1600",
                             "--screenshot=" + shot.string(), "file://" + (out / "index.html").string()});
  const auto s = stoneskip::run_program(sargs, o);
  const auto [w, h] = png_size(shot);
  if (!s.ok() || w != 1280 || h != 1600) fail("no 1280 × 1600 screenshot of the front page at " + shot.string() + " (" + s.error + ")");

  fs::remove_all(work);
  std::printf("%zu pages checked in %s; screenshot: %s; %d failure(s)\n", pages.size(), browser.c_str(), shot.c_str(), failures);
  return failures == 0 ? 0 : 1;
}
