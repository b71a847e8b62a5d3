#include "reports/common/plot.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace stoneskip {

std::string gnuplot_quote(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '\'') out += "''";
    // A line break would end the quoted string and the command: the rest of a title from a data
    // file would run as gnuplot commands (gnuplot's `system` starts programs). Shown as a space.
    else if (c == '\n' || c == '\r') out += ' ';
    // Enhanced text reads these as markup (subscript, overprint, phantom, …); a backslash prints
    // them as written (gnuplot 5.4 "enhanced text": a single backslash inside single quotes).
    // ^ { } stay markup: labels use them for exponents (10^{-3}).
    else if (c == '_' || c == '&' || c == '@' || c == '~') out += std::string("\\") + c;
    else out += c;
  }
  return "'" + out + "'";
}

std::string plot_title(const std::string& caption) {
  // The figure's caption, under the picture, keeps it all; the title over the plot must fit its
  // width (about 110 characters at 1100 pixels): a closing parenthetical goes first, then the words
  // past the limit (cut at a space, so that no UTF-8 character is split).
  constexpr std::size_t kFits = 110;
  std::string t = caption;
  if (t.size() > kFits && t.back() == ')') {
    const auto open = t.rfind(" (");
    if (open != std::string::npos && open > 20) t = t.substr(0, open);
  }
  if (t.size() > kFits) {
    const auto space = t.rfind(' ', kFits - 4);  // " …" is 4 bytes
    t = t.substr(0, space == std::string::npos ? kFits - 4 : space) + " …";
  }
  return t;
}

bool selected(TableSource::Rows rows, double y) {
  switch (rows) {
    case TableSource::Rows::y_nonnegative: return y >= 0;
    case TableSource::Rows::y_negative: return y < 0;
    case TableSource::Rows::y_positive: return y > 0;
    case TableSource::Rows::y_nonpositive: return y <= 0;
    case TableSource::Rows::all: break;
  }
  return true;
}

PlotSeries table_series(const std::string& title, const Record& r, const std::string& table, TableSource how,
                        const std::string& style) {
  PlotSeries p;
  p.title = title;
  p.style = style;
  const Table& t = r.table(table);
  const auto x = t.column(how.x_column), y = t.column(how.y_column);
  const std::vector<double> where = how.where_column.empty() ? std::vector<double>{} : t.column(how.where_column);
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!selected(how.rows, y[k])) {
      if (how.rows == TableSource::Rows::y_positive) {  // a gap in the line, never bridged
        p.x.push_back(std::numeric_limits<double>::quiet_NaN());
        p.y.push_back(std::numeric_limits<double>::quiet_NaN());
      }
      continue;
    }
    if (!where.empty() && where[k] != how.where_value) continue;
    p.x.push_back(how.x_power == 1 ? x[k] : std::pow(x[k], how.x_power));
    p.y.push_back(std::isnan(how.y_drawn_at) ? how.y_scale * y[k] : how.y_drawn_at);
  }
  how.table = r.path() + "/" + table;
  p.sources.push_back(how);
  return p;
}

PlotSeries table_series(const std::string& title, const Record& r, const std::string& table, const std::string& x_column,
                        const std::string& y_column, const std::string& style, TableSource::Rows rows, double y_drawn_at) {
  TableSource how;
  how.x_column = x_column;
  how.y_column = y_column;
  how.rows = rows;
  how.y_drawn_at = y_drawn_at;
  return table_series(title, r, table, how, style);
}

std::string series_colour(int k) {
  static const char* kColours[16] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                     "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#000080", "#800000",
                                     "#008080", "#556b2f", "#c71585", "#00a86b"};
  return std::string(" lc rgb '") + kColours[(k % 16 + 16) % 16] + "'";
}

std::string series_dash(int k) {
  static const int kDashes[3] = {1, 3, 4};  // solid, short dashes, dash-dot (2, long dashes, is left for marking)
  return " dt " + std::to_string(kDashes[((k / 16) % 3 + 3) % 3]);
}

PlotSeries power_law_guide(const std::string& title, const std::vector<double>& x, double x0, double y0, double p,
                           const std::string& style) {
  PlotSeries s;
  s.title = title;
  s.style = style;
  for (double v : x) {
    s.x.push_back(v);
    s.y.push_back(y0 * std::pow(v / x0, p));
  }
  DerivedSeries d;
  d.kind = DerivedSeries::Kind::power_law;
  d.exponent = p;
  s.derived = d;
  return s;
}

PlotSeries record_line(const std::string& title, const Record& r, const std::string& intercept_key, const std::string& slope_key,
                       const std::vector<double>& x, const std::string& style) {
  PlotSeries s;
  s.title = title;
  s.style = style;
  const double a = r.number(intercept_key), b = r.number(slope_key);
  for (double v : x) {
    s.x.push_back(v);
    s.y.push_back(a + b * v);
  }
  DerivedSeries d;
  d.kind = DerivedSeries::Kind::line;
  d.record = r.path();
  d.intercept_key = intercept_key;
  d.slope_key = slope_key;
  s.derived = d;
  return s;
}

void add_stored_table(Figure& f, const std::string& name, const Record& r, const std::string& table,
                      const std::vector<std::string>& columns) {
  const Table& stored = r.table(table);
  if (columns.empty()) {
    f.tables.emplace_back(name, stored);
  } else {
    Table out;
    out.columns = columns;
    std::vector<std::vector<double>> cols;
    for (const auto& c : columns) cols.push_back(stored.column(c));
    for (std::size_t row = 0; row < stored.rows(); ++row) {
      std::vector<double> values;
      for (const auto& c : cols) values.push_back(c[row]);
      out.add_row(values);
    }
    f.tables.emplace_back(name, out);
  }
  f.copies.emplace_back(name, TableCopy{r.path() + "/" + table, columns, {}, ""});
}

void add_computed_table(Figure& f, const std::string& name, Table t, const std::string& how) {
  f.tables.emplace_back(name, std::move(t));
  TableCopy c;
  c.computed = how;
  f.copies.emplace_back(name, c);
}

Figure line_figure(const std::string& name, const std::string& title, const PlotAxes& axes,
                   const std::vector<PlotSeries>& series, const std::string& x_column, const std::string& y_column) {
  Figure f;
  f.name = name;
  f.title = title;
  std::ostringstream s;
  s << "set title " << gnuplot_quote(plot_title(title)) << "\n";
  s << "set xlabel " << gnuplot_quote(axes.x_label) << "\nset ylabel " << gnuplot_quote(axes.y_label) << "\n";
  if (axes.log_x) s << "set logscale x\nset format x '10^{%L}'\n";
  if (axes.log_y) s << "set logscale y\nset format y '10^{%L}'\n";
  s << "set grid\nset key below maxrows 4 width -2 height 1.5\n";
  s << axes.extra << "\n";
  std::vector<std::string> clauses;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& p = series[i];
    Table t;
    t.columns = {x_column, y_column};
    bool any = false;
    for (std::size_t k = 0; k < p.x.size() && k < p.y.size(); ++k) {
      t.add_row({p.x[k], p.y[k]});
      any = true;
    }
    if (!any) t.add_row({std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()});  // an empty series still has a legend entry
    const std::string tname = name + "_" + std::to_string(i);
    f.tables.emplace_back(tname, t);
    f.sources.emplace_back(tname, p.sources);
    if (p.sources.empty() && p.derived) {
      DerivedSeries d = *p.derived;
      if (d.kind == DerivedSeries::Kind::outline) d.of_table = name + "_" + std::to_string(i + d.of_offset);
      f.derived.emplace_back(tname, d);
    }
    clauses.push_back("'" + tname + ".dat' using 1:2 with " + p.style + " title " + gnuplot_quote(p.title));
  }
  s << "plot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) s << (i ? ", \\\n     " : "") << clauses[i];
  s << "\n";
  f.script = s.str();
  f.width_px = 1000;
  f.height_px = 560;
  return f;
}

}  // namespace stoneskip
