#include "reports/common/figure.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/subprocess.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

// Whole figures stored under a group (the sweep page keeps its figures so).
void store_figure(const H5Group& figures_group, const Figure& fig) {
  H5Group g = figures_group.create_group(fig.name);
  g.set_attr("title", fig.title);
  g.set_attr("gnuplot", fig.script);
  g.set_attr("width_px", static_cast<long long>(fig.width_px));
  g.set_attr("height_px", static_cast<long long>(fig.height_px));
  std::vector<std::string> order;
  for (const auto& [name, table] : fig.tables) {
    g.write_table(name, table);
    order.push_back(name);
  }
  g.write_strings("table_order", order);
}

const char* rows_name(TableSource::Rows r) {
  switch (r) {
    case TableSource::Rows::y_nonnegative: return "y_nonnegative";
    case TableSource::Rows::y_negative: return "y_negative";
    case TableSource::Rows::y_positive: return "y_positive";
    case TableSource::Rows::y_nonpositive: return "y_nonpositive";
    case TableSource::Rows::all: break;
  }
  return "all";
}

bool gnuplot_available() { return program_runs({"gnuplot", "--version"}); }

namespace {

void write_dat(const fs::path& path, const Table& t) {
  std::ostringstream s;
  s << "#";
  for (const auto& c : t.columns) s << " " << c;
  s << "\n" << std::setprecision(10);
  const std::size_t nc = t.columns.size();
  for (std::size_t r = 0; r < t.rows(); ++r) {
    // A row of NaN only is a blank line: gnuplot breaks a line there (a NaN it skips, joining the
    // points either side of it — a failed run bridged as if it had a result).
    bool all_nan = nc > 0;
    for (std::size_t c = 0; c < nc; ++c) all_nan = all_nan && std::isnan(t.values[r * nc + c]);
    if (all_nan) {
      s << "\n";
      continue;
    }
    for (std::size_t c = 0; c < nc; ++c) {
      double v = t.values[r * nc + c];
      s << (c ? " " : "");
      if (std::isnan(v))
        s << "NaN";  // gnuplot skips NaN points
      else
        s << v;
    }
    s << "\n";
  }
  write_text_file(path, s.str());
}

// Runs gnuplot on a script in `dir` (its working folder, so the script's relative names resolve
// there) with its output redirected to `output` (a name in `dir`, through the script's variable
// OUT); the script is an argument, never part of a command line. gnuplot's messages on failure.
bool run_gnuplot(const fs::path& dir, const std::string& script_file, const std::string& output, std::string& errors) {
  SubprocessOptions o;
  o.working_dir = dir;
  o.stderr_to = SubprocessOptions::Stderr::merged;
  std::string quoted;  // a gnuplot single-quoted string: a quote is doubled, nothing else is special
  for (char c : output) quoted += c == '\'' ? std::string("''") : std::string(1, c);
  const SubprocessResult r = run_program({"gnuplot", "-e", "OUT='" + quoted + "'", safe_file_argument(script_file)}, o);
  errors = r.started ? r.out : r.error;
  if (r.started && !r.ok() && errors.empty())
    errors = r.signal ? "gnuplot ended by signal " + std::to_string(r.signal) : "gnuplot exited with status " + std::to_string(r.exit_status);
  return r.ok();
}

// The figures folder is made if absent; anything but a plain folder there (a link to somewhere
// else, a file) is refused, since everything below is written inside it.
void require_figures_folder(const fs::path& fig_dir) {
  struct stat st {};
  if (::lstat(fig_dir.c_str(), &st) != 0) {
    fs::create_directory(fig_dir);
    return;
  }
  if (!S_ISDIR(st.st_mode))
    throw_input_error(fig_dir.string(), 0, "", "exists and is " + file_type_words(st.st_mode) + ", not a folder: cannot draw the figures into it");
}

const DerivedSeries* derived_of(const Figure& f, const std::string& table) {
  for (const auto& [name, d] : f.derived)
    if (name == table) return &d;
  return nullptr;
}

void write_sources(const fs::path& path, const Figure& f) {
  std::ostringstream s;
  s << std::setprecision(17);
  for (const auto& [table, list] : f.sources) {
    if (const DerivedSeries* d = derived_of(f, table); list.empty() && d) {
      switch (d->kind) {
        case DerivedSeries::Kind::outline: s << table << "\toutline\t" << d->of_table << "\n"; break;
        case DerivedSeries::Kind::power_law: s << table << "\tpower_law\t" << d->exponent << "\n"; break;
        case DerivedSeries::Kind::line:
          s << table << "\tline\t" << d->record << "\t" << d->intercept_key << "\t" << d->slope_key << "\n";
          break;
      }
      continue;
    }
    if (list.empty()) s << table << "\t-\n";
    for (const auto& src : list)
      s << table << "\t" << src.table << "\t" << src.x_column << "\t" << src.y_column << "\t" << rows_name(src.rows) << "\t"
        << src.y_drawn_at << "\t" << src.x_power << "\t" << src.y_scale << "\t"
        << (src.where_column.empty() ? std::string("-") : src.where_column) << "\t" << src.where_value << "\n";
  }
  for (const auto& [table, c] : f.copies) {
    if (!c.estimates.empty()) {
      s << table << "\testimates\t";
      for (std::size_t i = 0; i < c.estimates.size(); ++i) s << (i ? "," : "") << c.estimates[i];
      s << "\n";
      continue;
    }
    if (c.table.empty()) {  // drawn from numbers of no stored table or estimate, and why
      s << table << "\t-\t" << c.computed << "\n";
      continue;
    }
    s << table << "\tcopy\t" << c.table << "\t" << (c.columns.empty() ? "*" : "");
    for (std::size_t i = 0; i < c.columns.size(); ++i) s << (i ? "," : "") << c.columns[i];
    s << "\n";
  }
  write_text_file(path, s.str());
}

const char* const kKinds[] = {"png", "svg"};

std::string script_name(const Figure& f, const std::string& kind) { return f.name + (kind == "png" ? ".gp" : ".svg.gp"); }

}  // namespace

std::vector<fs::path> figure_files(const std::vector<Figure>& figs) {
  std::vector<fs::path> out;
  const fs::path d = "figures";
  for (const auto& f : figs) {
    for (const auto& [name, table] : f.tables) out.push_back(d / (name + ".dat"));
    if (!f.sources.empty() || !f.copies.empty()) out.push_back(d / (f.name + ".sources"));
    for (const std::string kind : kKinds) {
      out.push_back(d / (f.name + "." + kind));
      out.push_back(d / script_name(f, kind));
    }
  }
  return out;
}

void remove_figure_files(const fs::path& dir, const std::vector<Figure>& figs) {
  const std::vector<fs::path> files = figure_files(figs);
  for (const auto& f : files) check_output_destination(dir / f);
  for (const auto& f : files) {
    std::error_code ec;  // absent: nothing to remove
    fs::remove(dir / f, ec);
  }
}

RenderSummary render_figures(const fs::path& dir, const std::vector<Figure>& figs) {
  RenderSummary summary;
  const fs::path fig_dir = dir / "figures";
  require_figures_folder(fig_dir);
  // Every file the figures will write, checked before the first is written (a link, a FIFO or a
  // device among them is refused with nothing changed).
  for (const auto& f : figure_files(figs)) check_output_destination(dir / f);
  for (const auto& f : figs) {
    for (const auto& [name, table] : f.tables) write_dat(fig_dir / (name + ".dat"), table);
    if (!f.sources.empty() || !f.copies.empty()) write_sources(fig_dir / (f.name + ".sources"), f);
    for (const std::string kind : kKinds) {
      // gnuplot draws into a temporary beside the final name, renamed over it when whole: never
      // through a link or into a FIFO put there (AtomicOutput checks the name again on commit).
      AtomicOutput image(fig_dir / (f.name + "." + kind));
      std::ostringstream gp;
      if (kind == "png")
        gp << "set terminal pngcairo size " << f.width_px << "," << f.height_px << " enhanced font 'Sans,10'\n";
      else
        // `mouse standalone`: the SVG, opened on its own, shows the coordinates under the pointer
        // and hides or shows a series on a click on its legend entry (gnuplot's own script, inline).
        gp << "set terminal svg size " << f.width_px << "," << f.height_px
           << " enhanced font 'Sans,10' background '#ffffff' mouse standalone\n";
      // The kept script draws <name>.<kind> when a reader runs it; render sets OUT to the temporary.
      gp << "set output (exists('OUT') ? OUT : '" << f.name << "." << kind << "')\n";
      gp << "set encoding utf8\nset datafile missing 'NaN'\n";
      gp << f.script << "\nset output\n";
      write_text_file(fig_dir / script_name(f, kind), gp.str());
      std::string errors;
      if (!run_gnuplot(fig_dir, script_name(f, kind), image.temporary_path().filename().string(), errors)) {
        const std::string said = kind + ": " + errors.substr(0, errors.find('\n', 200));
        summary.failures.push_back(f.name + "." + said);
        if (summary.not_drawn.empty() || summary.not_drawn.back().first != f.name) summary.not_drawn.emplace_back(f.name, said);
        // No picture rather than an older one beside this data (the page says which failed). The
        // name was checked above to be a plain file or absent, and render replaces only its own.
        std::error_code ec;
        fs::remove(fig_dir / (f.name + "." + kind), ec);
        continue;
      }
      image.commit();
      if (kind == "png") ++summary.rendered;
    }
  }
  return summary;
}

std::string figure_markdown(const Figure& fig) {
  std::string data = fig.data_path.empty() ? "" : ", data: `data.h5:" + fig.data_path + "`";
  return "![" + fig.title + "](figures/" + fig.name + ".png)\n\n*Figure: " + fig.title + "* ([SVG to explore](figures/" +
         fig.name + ".svg): coordinates under the pointer, a click on a legend entry hides its series" + data + ")\n\n";
}

std::string figure_not_drawn_markdown(const Figure& fig, const std::string& why, bool script_written) {
  // One line of a Markdown paragraph inside a code span: gnuplot's newlines and runs of blanks (its
  // caret line) as one space, a backquote as a quote.
  std::string words;
  for (char c : why) {
    if (c == '`') c = '\'';
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!words.empty() && words.back() != ' ') words += ' ';
    } else {
      words += c;
    }
  }
  if (!words.empty() && words.back() == ' ') words.pop_back();
  const std::string data = fig.data_path.empty() ? "" : " Its data: `data.h5:" + fig.data_path + "`.";
  const std::string script = script_written ? " Its script: `figures/" + script_name(fig, "png") + "`." : "";
  return "**Figure not drawn:** *" + fig.title + "* (`figures/" + fig.name + "`: `" + words + "`)." + data + script +
         "\n\n";
}

std::string mark_figures_not_drawn(std::string markdown, const std::vector<Figure>& figs, const RenderSummary& s) {
  for (const auto& [name, why] : s.not_drawn)
    for (const Figure& f : figs) {
      if (f.name != name) continue;
      const std::string image = figure_markdown(f);
      const std::size_t at = markdown.find(image);
      if (at != std::string::npos)
        markdown.replace(at, image.size(), figure_not_drawn_markdown(f, why, s.scripts_written));
    }
  return markdown;
}

}  // namespace stoneskip
