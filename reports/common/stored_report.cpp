#include "reports/common/stored_report.hpp"

#include "reports/common/html_page.hpp"
#include "reports/common/summary.hpp"
#include <algorithm>

#include "reports/common/section.hpp"
#include "stoneskip_version.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/isolated_read.hpp"

namespace stoneskip {

namespace {

StoredReport load_in_process(const std::filesystem::path& data_h5) {
  Hdf5Reader in(data_h5);
  const H5Group& root = in.root();
  if (!root.has_attr("report") || !root.has("sections") || !root.has("report")) {
    // A sweep-plot folder's data.h5 (its figures and the sweep it came from, sweep_page.cpp) is
    // redrawn from that sweep, not rendered.
    if (root.has("figures") && root.has_attr("source"))
      throw_input_error(data_h5.string(), 0, "",
                        "the data file of a `sweep-plot` folder, not of a report: redraw it with `stoneskip sweep-plot " +
                            root.attr_string("source") + " --out DIR`");
    throw_input_error(data_h5.string(), 0, "", "not the data file of a stoneskip report (no /report and /sections)");
  }
  StoredReport s;
  s.file = data_h5;
  try {
    s.kind = root.attr_string("report");
    s.code_version = root.attr_string("code_version");
    s.created_utc = root.attr_string("created_utc");
    s.settings = root.has_attr("settings") ? root.attr_string("settings") : "";
    s.command = root.has_attr("command") ? root.attr_string("command") : "";
    s.report = load_record(root.open_group("report"));
    s.sections = load_record(root.open_group("sections"));
  } catch (const std::exception& e) {
    throw_input_error(data_h5.string(), 0, "", std::string("unreadable report data: ") + e.what());
  }
  // The provenance strings go into the page as they are: each is what stoneskip writes there (one
  // line of plausible length; the time as stamp_provenance writes it), or the file is refused.
  // A 50 MB or many-line code_version made a 50 MB page, or a second "Findings" heading.
  const auto one_line = [&](const std::string& key, const std::string& v, std::size_t most) {
    if (v.size() > most || v.find_first_of("\n\r") != std::string::npos)
      throw_input_error(data_h5.string(), 0, key,
                        v.size() > most ? "is " + std::to_string(v.size()) + " characters long (at most " + std::to_string(most) + ")"
                                        : std::string("holds a line break; stoneskip writes one line there"));
  };
  one_line("code_version", s.code_version, 200);
  if (s.code_version.rfind("stoneskip ", 0) != 0)
    throw_input_error(data_h5.string(), 0, "code_version", "does not start with 'stoneskip ' (not written by stoneskip)");
  one_line("created_utc", s.created_utc, 20);
  const bool utc = s.created_utc.size() == 20 && std::all_of(s.created_utc.begin(), s.created_utc.end(), [i = 0](char ch) mutable {
                     const int k = i++;
                     if (k == 4 || k == 7) return ch == '-';
                     if (k == 10) return ch == 'T';
                     if (k == 13 || k == 16) return ch == ':';
                     if (k == 19) return ch == 'Z';
                     return ch >= '0' && ch <= '9';
                   });
  if (!utc) throw_input_error(data_h5.string(), 0, "created_utc", "is not a time as YYYY-MM-DDThh:mm:ssZ");
  // The command holds the file names as given, line breaks included: only its size is bounded
  // (the page shows it as code, a line break written \n).
  if (s.command.size() > (1u << 20))
    throw_input_error(data_h5.string(), 0, "command", "is " + std::to_string(s.command.size()) + " characters long (at most 1048576)");
  return s;
}

}  // namespace

StoredReport load_stored_report(const std::filesystem::path& data_h5) {
  // A damaged file can crash or hang the HDF5 library before any check of ours: read it in a
  // child first (tools/io/isolated_read.hpp).
  read_in_child_first(data_h5, [&] { load_in_process(data_h5); });
  return load_in_process(data_h5);
}

void append(RenderedReport& r, const SectionOutput& s) {
  r.markdown += s.markdown;
  r.figures.insert(r.figures.end(), s.figures.begin(), s.figures.end());
}

std::string provenance_markdown(const StoredReport& s) {
  std::string md = "## Provenance\n\n";
  md += "* Code: " + s.code_version + "; data written " + s.created_utc + ".\n";
  // The page may be rendered later, by other code, from the same data.h5 (`report render`).
  md += std::string("* This page rendered by: stoneskip ") + kVersion + " (git " + kGitDescribe + ").\n";
  if (!s.command.empty()) md += "* Made by: " + code(s.command) + ".\n";
  md += "* Everything above is formatted from `data.h5` (settings under its root attribute `settings`, findings "
        "under `/sections`); `stoneskip report render DIR` rebuilds this page and the figures from it.\n";
  return md;
}

std::vector<std::filesystem::path> rendered_files(const RenderedReport& r) {
  std::vector<std::filesystem::path> out{"index.md", "index.html"};
  for (auto& f : figure_files(r.figures)) out.push_back(std::move(f));
  return out;
}

RenderSummary write_rendered_report(const std::filesystem::path& dir, const RenderedReport& r) {
  RenderSummary summary;
  if (gnuplot_available()) {
    summary = render_figures(dir, r.figures);
  } else {
    for (const auto& f : r.figures) {
      summary.failures.push_back(f.name + ": gnuplot not found (apt-get install gnuplot-nox)");
      summary.not_drawn.emplace_back(f.name, "gnuplot not found (apt-get install gnuplot-nox)");
    }
    summary.scripts_written = false;
    remove_figure_files(dir, r.figures);  // no picture of an earlier rendering beside "not drawn"
  }
  // A figure not drawn is said so on the page, in its place (no link to a picture that is not there).
  const std::string markdown = with_contents(mark_figures_not_drawn(r.markdown, r.figures, summary));
  write_text_file(dir / "index.md", markdown);
  write_text_file(dir / "index.html", html_page(markdown));
  return summary;
}

}  // namespace stoneskip
