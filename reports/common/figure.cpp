#include "reports/common/figure.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "tools/io/atomic_file.hpp"

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

bool gnuplot_available() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

namespace {

void write_dat(const fs::path& path, const Table& t) {
  std::ostringstream s;
  s << "#";
  for (const auto& c : t.columns) s << " " << c;
  s << "\n" << std::setprecision(10);
  const std::size_t nc = t.columns.size();
  for (std::size_t r = 0; r < t.rows(); ++r) {
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

int run_gnuplot(const fs::path& dir, const std::string& script_file, std::string& errors) {
  fs::path err = dir / (script_file + ".err");
  std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + script_file + "' 2>'" + err.filename().string() + "'";
  int rc = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  errors = ss.str();
  std::error_code ec;
  fs::remove(err, ec);
  return rc;
}

}  // namespace

RenderSummary render_figures(const fs::path& dir, const std::vector<Figure>& figs) {
  RenderSummary summary;
  fs::path fig_dir = dir / "figures";
  fs::create_directories(fig_dir);
  for (const auto& f : figs) {
    for (const auto& [name, table] : f.tables) write_dat(fig_dir / (name + ".dat"), table);
    for (const char* kind : {"png", "svg"}) {
      std::ostringstream gp;
      if (std::string(kind) == "png")
        gp << "set terminal pngcairo size " << f.width_px << "," << f.height_px << " enhanced font 'Sans,10'\n";
      else
        gp << "set terminal svg size " << f.width_px << "," << f.height_px << " enhanced font 'Sans,10' background '#ffffff'\n";
      gp << "set output '" << f.name << "." << kind << "'\n";
      gp << "set encoding utf8\nset datafile missing 'NaN'\n";
      gp << f.script << "\n";
      std::string script_name = f.name + (std::string(kind) == "png" ? ".gp" : ".svg.gp");
      write_text_file(fig_dir / script_name, gp.str());
      std::string errors;
      int rc = run_gnuplot(fig_dir, script_name, errors);
      if (rc != 0) {
        summary.failures.push_back(f.name + "." + kind + ": " + errors.substr(0, errors.find('\n', 200)));
      } else if (std::string(kind) == "png") {
        ++summary.rendered;
      }
    }
  }
  return summary;
}

std::string figure_markdown(const Figure& fig) {
  std::string data = fig.data_path.empty() ? "" : ", data: `data.h5:" + fig.data_path + "`";
  return "![" + fig.title + "](figures/" + fig.name + ".png)\n\n*Figure: " + fig.title + "* ([SVG](figures/" +
         fig.name + ".svg)" + data + ")\n\n";
}

}  // namespace stoneskip
