#include "tools/capture/header_csv.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/csv_columns.hpp"
#include "tools/capture/csv_unit_detection.hpp"
#include "tools/capture/gyro_range.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {

using F = CsvField;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
// WiiYourself! (wiimote.cpp, ParseExtension): MotionPlus.Speed = −(raw − 0x1F7F)·scale, with scale
// 0.05 deg/s per count in slow mode and 0.25 in fast mode.
constexpr double kWyZero = 0x1F7F, kWySlowScale = 0.05, kWyFastScale = 0.25;
constexpr int kMaxMotionPlusWord = 0x3fff;

// Fields split at `sep` (RFC 4180): a field that opens with a double quote (after blanks) runs to
// its closing quote and may hold the separator, "" inside it standing for a quote (kept doubled:
// the readers take numbers and names, never quoted text apart); a quote elsewhere in a field is
// an ordinary character (a header `Size (")`). Empty when a quoted field is left open
// (`unterminated` set).
std::vector<std::string_view> split_row(std::string_view line, char sep, bool* unterminated = nullptr);

// The separator is the most frequent of `,` `;` and tab between fields (not inside quoted ones).
char separator_of(std::string_view line) {
  std::size_t best_count = 0;
  char best = 0;
  for (char sep : {',', ';', '\t'}) {
    bool open = false;
    const std::size_t count = split_row(line, sep, &open).size();
    if (!open && count > 1 && count - 1 > best_count) best_count = count - 1, best = sep;
  }
  return best;
}

std::string_view unquote(std::string_view f) {
  f = trim(f);
  if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = trim(f.substr(1, f.size() - 2));
  return f;
}

std::vector<std::string_view> split_row(std::string_view line, char sep, bool* unterminated) {
  std::vector<std::string_view> out;
  std::size_t begin = 0, i = 0;
  if (unterminated) *unterminated = false;
  while (true) {
    std::size_t j = begin;
    while (j < line.size() && (line[j] == ' ' || (line[j] == '\t' && sep != '\t'))) ++j;
    i = j;
    if (j < line.size() && line[j] == '"') {
      // A quoted field: to the quote not doubled.
      for (i = j + 1;; ++i) {
        if (i >= line.size()) {
          if (unterminated) *unterminated = true;
          return {};
        }
        if (line[i] != '"') continue;
        if (i + 1 < line.size() && line[i + 1] == '"') {
          ++i;  // "" inside: a quote
          continue;
        }
        ++i;
        break;
      }
    }
    while (i < line.size() && line[i] != sep) ++i;
    out.push_back(unquote(line.substr(begin, i - begin)));
    if (i >= line.size()) break;
    begin = i + 1;
  }
  return out;
}

// The same for a line of the file: an open quote is an error naming the line.
std::vector<std::string_view> split_row(const TextLine& line, char sep, const std::string& file) {
  bool open = false;
  auto fields = split_row(line.text, sep, &open);
  if (open) throw_input_error(file, line.number, "", "a quoted field is not closed (no matching '\"' on the line)");
  return fields;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_motion_field(F f) {
  return (f >= F::ax && f <= F::wz) || (f >= F::speed_pitch && f <= F::raw_yaw);
}

// A used column.
struct Column {
  std::size_t index = 0;     // position in the row
  std::string header;        // as written
  RecognisedColumn rc;
  CsvUnit unit = CsvUnit::none;  // resolved (the field's default when none was given)
};

// --columns key[unit]=Header,… against the header fields.
std::vector<Column> mapped_columns(const std::string& spec, const std::vector<std::string_view>& headers,
                                  const std::string& file) {
  std::vector<Column> out;
  if (trim(spec).empty()) return out;
  std::string known;
  for (const auto& f : csv_fields()) known += std::string(known.empty() ? "" : ", ") + f.key;
  std::string available;
  for (const auto h : headers) available += std::string(available.empty() ? "'" : ", '") + std::string(h) + "'";
  for (const auto item : split_fields(spec, true)) {
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) throw_input_error("--columns", 0, std::string(item), "expected key=Column Name");
    std::string_view key = trim(item.substr(0, eq));
    const std::string_view name = trim(item.substr(eq + 1));
    CsvUnit unit = CsvUnit::none;
    if (const auto b = key.find('['); b != std::string_view::npos && key.back() == ']') {
      const auto u = parse_csv_unit(key.substr(b + 1, key.size() - b - 2));
      if (!u) throw_input_error("--columns", 0, std::string(key), "unknown unit");
      unit = *u;
      key = trim(key.substr(0, b));
    }
    const auto field = csv_field_from_key(key);
    if (!field) throw_input_error("--columns", 0, std::string(key), "unknown key (known: " + known + ")");
    std::size_t found = headers.size();
    for (std::size_t i = 0; i < headers.size(); ++i)
      if (lower(headers[i]) == lower(name)) found = i;
    if (found == headers.size())
      throw_input_error("--columns", 0, std::string(key),
                        "no column '" + std::string(name) + "' in " + file + " (columns: " + available + ")");
    const HeaderParts parts = split_header(headers[found]);
    if (unit == CsvUnit::none && parts.has_bracket_unit) {
      const auto u = parse_csv_unit(parts.unit_text);
      if (u) unit = *u;
    }
    for (const Column& other : out)
      if (other.index == found)
        throw_input_error("--columns", 0, std::string(key),
                          "column '" + std::string(headers[found]) + "' is already mapped to " +
                              csv_field_info(other.rc.field).key + " (a column holds one quantity)");
    Column c;
    c.index = found;
    c.header = std::string(headers[found]);
    c.rc.field = *field;
    c.rc.remote = parts.remote;
    c.rc.unit = unit;
    if (!unit_allowed(c.rc))
      throw_input_error("--columns", 0, std::string(key), std::string("unit '") + to_string(unit) + "' not allowed for " +
                                                            csv_field_info(*field).meaning);
    out.push_back(c);
  }
  return out;
}

// One parsed cell: NaN when the field is empty.
constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();
bool empty(double x) { return std::isnan(x); }

// Parses a cell of column c; returns false with `what` on bad input.
bool parse_cell(const Column& c, std::string_view text, double& out, std::string& what) {
  if (text.empty()) {
    out = kEmpty;
    return true;
  }
  const F f = c.rc.field;
  const bool hex_word = (f >= F::raw_pitch && f <= F::raw_yaw) || f == F::buttons;
  if (hex_word) {
    std::string_view digits = text;
    const bool hex = c.unit != CsvUnit::dec;
    if (hex && digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) digits.remove_prefix(2);
    const auto v = digits.size() <= 8 ? parse_integer(digits, hex ? 16 : 10) : std::nullopt;
    const long long max = f == F::buttons ? 0xffff : kMaxMotionPlusWord;
    if (!v || *v < 0 || *v > max) {
      char b[160];
      std::snprintf(b, sizeof b, "expected a %s word 0..0x%llx, got '", f == F::buttons ? "button" : "14-bit MotionPlus",
                    max);
      what = b + std::string(text) + "'" + (hex ? " (hexadecimal)" : " (decimal)");
      return false;
    }
    out = double(*v);
    return true;
  }
  const bool flag = (f >= F::slow_pitch && f <= F::fast_yaw) || f == F::button_a || f == F::button_b;
  if (flag) {
    const std::string v = lower(text);
    if (v == "1" || v == "true") out = 1.0;
    else if (v == "0" || v == "false") out = 0.0;
    else {
      what = "expected 0 or 1, got '" + std::string(text) + "'";
      return false;
    }
    return true;
  }
  const auto v = parse_real(text);
  if (!v) {
    what = "not a number: '" + std::string(text) + "'";
    return false;
  }
  out = *v;
  return true;
}

struct Row {
  long line = 0;
  std::vector<double> cells;  // per used column
};

std::string remote_name(int r) { return "#WM" + std::to_string(r); }

}  // namespace

bool is_header_csv_column_line(const std::string& line) {
  const char sep = separator_of(line);
  if (!sep) return false;
  int recognised = 0;
  bool motion = false;
  for (const auto h : split_row(line, sep)) {
    const auto rc = recognise_column(h);
    if (!rc) continue;
    ++recognised;
    motion = motion || is_motion_field(rc->field);
  }
  return recognised >= 2 && motion;
}

Trace read_header_csv(const std::string& text, const std::string& file, const HeaderCsvOptions& options) {
  Trace t;
  t.source = file;
  t.format = "csv";
  t.calibration.accel_from_device = true;  // the logger wrote calibrated accelerations
  const std::vector<TextLine> lines = split_capture_lines(text, file);
  // 1. Header comments, then the column line.
  std::size_t k = 0;
  for (; k < lines.size(); ++k)
    if (!skip_blank_or_header(t, trim(lines[k].text), file, lines[k].number)) break;
  if (k == lines.size()) throw_input_error(file, 0, "", "no column line: not a CSV capture");
  const TextLine& column_line = lines[k];
  const char sep = separator_of(column_line.text);
  if (!sep) throw_input_error(file, column_line.number, "", "the column line has no ',', ';' or tab separator");
  const std::vector<std::string_view> headers = split_row(column_line, sep, file);
  // 2. The columns used: --columns first, then the recognised names.
  std::vector<Column> columns = mapped_columns(options.columns, headers, file);
  std::vector<std::string> unused, unrecognised;
  for (std::size_t i = 0; i < headers.size(); ++i) {
    if (std::any_of(columns.begin(), columns.end(), [&](const Column& c) { return c.index == i; })) continue;
    const auto rc = recognise_column(headers[i]);
    if (!rc) {
      // A known name with a bracketed unit we cannot read ("Acc X [mg]"): say so, naming the unit.
      const HeaderParts parts = split_header(headers[i]);
      if (parts.has_bracket_unit && !parse_csv_unit(parts.unit_text))
        if (const auto named = recognise_column(parts.name)) {
          std::string allowed;
          for (CsvUnit u : csv_field_info(named->field).units)
            if (u != CsvUnit::none) allowed += std::string(allowed.empty() ? "" : ", ") + to_string(u);
          throw_input_error(file, column_line.number, std::string(headers[i]),
                            "unit '" + parts.unit_text + "' is not supported for " + csv_field_info(named->field).meaning +
                                " (" + (allowed.empty() ? "no unit" : allowed) + ")");
        }
      if (!headers[i].empty()) unrecognised.push_back("'" + std::string(headers[i]) + "'");
      continue;
    }
    if (!unit_allowed(*rc)) {
      std::string allowed;
      for (CsvUnit u : csv_field_info(rc->field).units)
        if (u != CsvUnit::none) allowed += std::string(allowed.empty() ? "" : ", ") + to_string(u);
      throw_input_error(file, column_line.number, std::string(headers[i]),
                        std::string("unit '") + to_string(rc->unit) + "' is not one of " + csv_field_info(rc->field).meaning +
                            " (" + (allowed.empty() ? "no unit" : allowed) + ")");
    }
    if (rc->field == F::orientation_pitch || rc->field == F::orientation_roll || rc->field == F::sequence) {
      unused.push_back("'" + std::string(headers[i]) + "'");
    }
    Column c;
    c.index = i;
    c.header = std::string(headers[i]);
    c.rc = *rc;
    columns.push_back(c);
  }
  for (Column& c : columns) c.unit = c.rc.unit != CsvUnit::none ? c.rc.unit : csv_field_info(c.rc.field).units.front();
  // Two columns for the same quantity of the same remote.
  for (std::size_t i = 0; i < columns.size(); ++i)
    for (std::size_t j = i + 1; j < columns.size(); ++j)
      if (columns[i].rc.field == columns[j].rc.field && columns[i].rc.remote == columns[j].rc.remote)
        throw_input_error(file, column_line.number, "",
                          "columns '" + columns[i].header + "' and '" + columns[j].header + "' both give " +
                              csv_field_info(columns[i].rc.field).key);
  // 3. The rows, every used cell parsed strictly.
  std::vector<Row> rows;
  for (std::size_t i = k + 1; i < lines.size(); ++i) {
    const TextLine& line = lines[i];
    const std::string_view s = trim(line.text);
    if (s.empty() || s.front() == '#') continue;
    bool open = false;
    const auto fields = split_row(line.text, sep, &open);
    if (open) {
      malformed_line(file, line, "a quoted field is not closed (no matching '\"' on the line)", t.warnings);
      continue;
    }
    if (fields.size() != headers.size()) {
      malformed_line(file, line,
                     "expected " + std::to_string(headers.size()) + " fields (as the column line), found " +
                         std::to_string(fields.size()),
                     t.warnings);
      continue;
    }
    Row r;
    r.line = line.number;
    r.cells.resize(columns.size());
    bool ok = true;
    for (std::size_t c = 0; c < columns.size() && ok; ++c) {
      std::string what;
      if (!parse_cell(columns[c], fields[columns[c].index], r.cells[c], what)) {
        malformed_line(file, line, columns[c].header + ": " + what, t.warnings);
        ok = false;
      }
    }
    if (ok) rows.push_back(std::move(r));
  }
  if (rows.empty()) throw_input_error(file, 0, "", "no data rows");
  // 4. The remotes, and the one read.
  std::set<int> remotes;
  for (const Column& c : columns)
    if (c.rc.remote > 0) remotes.insert(c.rc.remote);
  const bool several = remotes.size() > 1;
  if (remotes.empty()) remotes.insert(1);
  auto columns_of = [&](int remote) {  // field → column position, own suffix before shared
    std::map<F, std::size_t> m;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c].rc.remote == 0 || columns[c].rc.remote == remote)
        if (!m.count(columns[c].rc.field) || columns[c].rc.remote != 0) m[columns[c].rc.field] = c;
    return m;
  };
  auto has_data = [&](int remote) {
    const auto m = columns_of(remote);
    for (const Row& r : rows)
      for (const auto& [field, c] : m)
        if (is_motion_field(field) && !(field >= F::raw_pitch && field <= F::raw_yaw) && !empty(r.cells[c]) &&
            r.cells[c] != 0.0)
          return true;
    return false;
  };
  std::string remote_list;
  for (int r : remotes) remote_list += std::string(remote_list.empty() ? "" : ", ") + remote_name(r);
  int remote = options.remote;
  if (remote > 0) {
    if (!remotes.count(remote))
      throw_input_error(file, 0, "--remote", "no remote " + remote_name(remote) + " in the file (remotes: " + remote_list + ")");
    if (!has_data(remote))
      throw_input_error(file, 0, "--remote", "remote " + remote_name(remote) + " has no data (its accelerations and rates are empty or zero)");
  } else {
    for (int r : remotes)
      if (has_data(r)) {
        remote = r;
        break;
      }
    if (remote == 0) throw_input_error(file, 0, "", "no remote with data (accelerations and rates all empty or zero)");
  }
  const std::map<F, std::size_t> col = columns_of(remote);
  auto have = [&](F f) { return col.count(f) > 0; };
  auto axes_complete = [&](F first, const char* what) {
    const int n = int(have(first)) + int(have(F(int(first) + 1))) + int(have(F(int(first) + 2)));
    if (n != 0 && n != 3)
      throw_input_error(file, column_line.number, "",
                        std::string(what) + " needs all three of " + csv_field_info(first).key + ", " +
                            csv_field_info(F(int(first) + 1)).key + ", " + csv_field_info(F(int(first) + 2)).key +
                            " for " + remote_name(remote) + " (found " + std::to_string(n) + ")");
    return n == 3;
  };
  if (!axes_complete(F::ax, "the acceleration"))
    throw_input_error(file, column_line.number, "",
                      "no acceleration columns for " + remote_name(remote) + " (e.g. 'Acc X', 'acc_x [g]'; or --columns ax=...)");
  const bool raw = axes_complete(F::raw_pitch, "the MotionPlus raw words");
  const bool rates = axes_complete(F::wx, "the angular rate");
  const bool speeds = axes_complete(F::speed_pitch, "the WiiYourself! speeds");
  t.has_gyro = raw || rates || speeds;
  t.has_buttons = have(F::buttons) || have(F::button_a) || have(F::button_b);
  // 5. The samples of that remote.
  std::vector<F> data_fields{F::ax, F::ay, F::az};
  const F rate_first = raw ? F::raw_pitch : rates ? F::wx : F::speed_pitch;
  if (t.has_gyro)
    for (int i = 0; i < 3; ++i) data_fields.push_back(F(int(rate_first) + i));
  if (raw && speeds)
    for (int i = 0; i < 3; ++i) data_fields.push_back(F(int(F::speed_pitch) + i));
  for (F f : {F::buttons, F::button_a, F::button_b, F::slow_pitch, F::slow_roll, F::slow_yaw, F::fast_pitch, F::fast_roll,
              F::fast_yaw})
    if (have(f)) data_fields.push_back(f);
  std::vector<const Row*> kept;
  std::size_t skipped_empty = 0, skipped_unchanged = 0;
  std::vector<bool> repeated;
  for (const Row& r : rows) {
    int empties = 0;
    for (F f : data_fields) empties += empty(r.cells[col.at(f)]);
    if (empties == int(data_fields.size())) {
      ++skipped_empty;
      continue;
    }
    if (empties > 0) {
      for (F f : data_fields)
        if (empty(r.cells[col.at(f)]))
          throw_input_error(file, r.line, columns[col.at(f)].header,
                            "empty field while other fields of " + remote_name(remote) + " are given");
    }
    if (have(F::time) && empty(r.cells[col.at(F::time)])) throw_input_error(file, r.line, columns[col.at(F::time)].header, "empty time");
    bool same = !kept.empty();
    for (F f : data_fields)
      if (same && r.cells[col.at(f)] != kept.back()->cells[col.at(f)]) same = false;
    if (same && several) {
      ++skipped_unchanged;
      continue;
    }
    const bool same_time = !have(F::time) || (!kept.empty() && r.cells[col.at(F::time)] == kept.back()->cells[col.at(F::time)]);
    repeated.push_back(same && same_time);
    kept.push_back(&r);
  }
  if (kept.empty()) throw_input_error(file, 0, "", "no samples for " + remote_name(remote));
  // 6. Times.
  std::vector<double> times(kept.size());
  if (have(F::time)) {
    const Column& tc = columns[col.at(F::time)];
    // A 32-bit tick counter (WiiYourself! stamps rows with timeGetTime, in milliseconds) wraps
    // every 2^32 ticks, 49.7 days: a whole-number time that falls back by more than half the
    // counter's range, from below 2^32, to a step under a minute past the wrap, is unwrapped.
    constexpr double kTicks = 4294967296.0, kMaxWrapStep = 60000;
    double offset = 0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const double stamp = kept[i]->cells[col.at(F::time)];
      times[i] = stamp + offset;
      if (i > 0 && times[i] < times[i - 1]) {
        const double previous_stamp = times[i - 1] - offset;
        const bool whole = stamp == std::floor(stamp) && previous_stamp == std::floor(previous_stamp);
        if (whole && stamp >= 0 && previous_stamp < kTicks && previous_stamp - stamp > kTicks / 2 &&
            stamp + kTicks - previous_stamp <= kMaxWrapStep) {
          offset += kTicks;
          times[i] = stamp + offset;
          t.notes.push_back(input_location(file, kept[i]->line, tc.header) +
                            ": the 32-bit tick counter wrapped; later times unwrapped (+2^32)");
          continue;
        }
        char what[200];  // both lines: an absurd stamp on the earlier one shows here as the later's fault
        std::snprintf(what, sizeof what, "time goes backwards (%.15g after %.15g on line %ld)", stamp, previous_stamp,
                      long(kept[i - 1]->line));
        throw_input_error(file, kept[i]->line, tc.header, what);
      }
    }
    // The rows skipped for this remote (another's, or unchanged) are stamped by the same logger's
    // clock: time going backwards on one of them is as wrong as on a kept row (it passed unseen).
    // A fall of more than half the tick counter's range is its wrap, judged above on the kept rows.
    const Row* before = nullptr;
    for (const Row& r : rows) {
      const double stamp = r.cells[col.at(F::time)];
      if (empty(stamp)) continue;
      const double previous = before ? before->cells[col.at(F::time)] : stamp;
      if (stamp < previous && !(previous - stamp > kTicks / 2)) {
        char what[200];
        std::snprintf(what, sizeof what, "time goes backwards (%.15g after %.15g on line %ld)", stamp, previous,
                      long(before->line));
        throw_input_error(file, r.line, tc.header, what);
      }
      before = &r;
    }
    CsvUnit unit = tc.rc.unit;
    std::string how = "from the header";
    if (unit == CsvUnit::none) {
      std::vector<double> dt;
      for (std::size_t i = 1; i < times.size(); ++i)
        if (times[i] > times[i - 1]) dt.push_back(times[i] - times[i - 1]);
      double median = 0;
      if (!dt.empty()) {
        std::nth_element(dt.begin(), dt.begin() + std::ptrdiff_t(dt.size() / 2), dt.end());
        median = dt[dt.size() / 2];
      }
      unit = median < 0.5 ? CsvUnit::s : median < 500 ? CsvUnit::ms : CsvUnit::us;
      char b[120];
      std::snprintf(b, sizeof b, "no unit in the header: detected from the median interval %.6g", median);
      how = b;
    }
    const double scale = unit == CsvUnit::ms ? 1e-3 : unit == CsvUnit::us ? 1e-6 : 1.0;
    const double t0 = times.front();
    for (double& x : times) x = (x - t0) * scale;
    t.notes.push_back("time column '" + tc.header + "' in " + to_string(unit) + " (" + how + ")");
  } else {
    t.nominal_timestamps = true;
    for (std::size_t i = 0; i < kept.size(); ++i) times[i] = double(i) / t.nominal_rate_hz;
    t.notes.push_back("no time column: samples placed at the nominal rate");
  }
  // 7. Angular rates and MotionPlus range modes.
  std::vector<std::array<double, 3>> counts(kept.size());
  std::array<bool, 3> infer{false, false, false};
  std::vector<std::array<bool, 3>> fast(kept.size(), {false, false, false});
  const char* axis_name[3] = {"pitch", "roll", "yaw"};
  // Range modes from slow/fast columns, whatever else the file holds (raw words or rates).
  std::array<bool, 3> mode_columns{false, false, false};
  for (int a = 0; a < 3; ++a) {
    const F slow_f = F(int(F::slow_pitch) + a), fast_f = F(int(F::fast_pitch) + a);
    mode_columns[a] = have(slow_f) || have(fast_f);
    if (mode_columns[a])
      for (std::size_t i = 0; i < kept.size(); ++i)
        fast[i][a] = have(fast_f) ? kept[i]->cells[col.at(fast_f)] == 1.0 : kept[i]->cells[col.at(slow_f)] == 0.0;
  }
  if (raw) {
    for (int a = 0; a < 3; ++a) {
      const F speed_f = F(int(F::speed_pitch) + a);
      if (mode_columns[a]) continue;
      if (!speeds) {
        infer[a] = true;
        continue;
      }
      // WiiYourself!'s conversion tells the mode where raw is off its zero.
      const double to_deg = columns[col.at(speed_f)].unit == CsvUnit::rad_s ? kRadToDeg : 1.0;
      bool previous = false;
      for (std::size_t i = 0; i < kept.size() && !infer[a]; ++i) {
        const double d = kept[i]->cells[col.at(F(int(F::raw_pitch) + a))] - kWyZero;
        const double speed = to_deg * kept[i]->cells[col.at(speed_f)];
        const double tol = 0.002 + 1e-5 * std::abs(speed);  // printing and single precision
        const bool slow_ok = std::abs(speed + d * kWySlowScale) <= tol, fast_ok = std::abs(speed + d * kWyFastScale) <= tol;
        if (!slow_ok && !fast_ok) {
          infer[a] = true;
          t.warnings.push_back(input_location(file, kept[i]->line, columns[col.at(speed_f)].header) +
                               ": the speed does not follow WiiYourself!'s conversion of the raw word; the " +
                               axis_name[a] + " range mode is inferred from jumps instead");
          break;
        }
        if (slow_ok != fast_ok) previous = fast_ok;
        fast[i][a] = previous;
      }
    }
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (int a = 0; a < 3; ++a)
        counts[i][a] = kept[i]->cells[col.at(F(int(F::raw_pitch) + a))] - t.calibration.gyro_zero_counts[a];
    if (infer[0] || infer[1] || infer[2]) {
      const auto range = infer_gyro_range(counts, t.calibration.gyro_fast_factor, times);
      for (std::size_t i = 0; i < kept.size(); ++i)
        for (int a = 0; a < 3; ++a)
          if (infer[a]) fast[i][a] = range.fast[i][a];
      t.gyro_mode_inferred = true;
    }
  }
  // 8. The trace. A unit the header does not give is read from the data, as the time's is
  // (csv_unit_detection.hpp), and a note says which and why.
  auto values_of = [&](F first) {
    std::vector<std::array<double, 3>> v(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (int a = 0; a < 3; ++a) v[i][a] = kept[i]->cells[col.at(F(int(first) + a))];
    return v;
  };
  CsvUnit accel_unit = columns[col.at(F::ax)].unit;
  if (columns[col.at(F::ax)].rc.unit == CsvUnit::none) {
    const DetectedCsvUnit d = detect_acceleration_unit(values_of(F::ax));
    accel_unit = d.unit;
    t.notes.push_back(std::string("accelerations in ") + to_string(d.unit) + " (" + d.how + ")");
  }
  CsvUnit rate_unit = rates ? columns[col.at(F::wx)].unit : speeds ? columns[col.at(F::speed_pitch)].unit : CsvUnit::deg_s;
  if (!raw && rates && columns[col.at(F::wx)].rc.unit == CsvUnit::none) {
    const DetectedCsvUnit d = detect_rate_unit(values_of(F::wx));
    rate_unit = d.unit;
    t.notes.push_back(std::string("angular rates in ") + to_string(d.unit) + " (" + d.how + ")");
  }
  const double accel_scale = accel_unit == CsvUnit::m_s2 ? 1.0 / kStandardGravity : 1.0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const Row& r = *kept[i];
    TraceSample x;
    x.line = r.line;
    x.t_s = times[i];
    for (int a = 0; a < 3; ++a) x.accel_g[a] = accel_scale * r.cells[col.at(F(int(F::ax) + a))];
    if (raw) {
      for (int a = 0; a < 3; ++a) {
        const double word = r.cells[col.at(F(int(F::raw_pitch) + a))];
        x.gyro_fast[a] = fast[i][a];
        x.rate_deg_s[a] = t.calibration.gyro_deg_s(a, word, fast[i][a]);
        if (word == 0 || word == kMaxMotionPlusWord) x.flags |= kGyroSaturated;
      }
    } else if (rates || speeds) {
      const F first = rates ? F::wx : F::speed_pitch;
      const double to_deg = rate_unit == CsvUnit::rad_s ? kRadToDeg : 1.0;
      for (int a = 0; a < 3; ++a) {
        const double w = to_deg * r.cells[col.at(F(int(first) + a))];
        x.rate_deg_s[a] = rates ? w : -w;
        if (rates) {
          // The range mode sets how the zero-rate bias scales: from the mode columns, else from the
          // rate's size (beyond the slow range the MotionPlus was in fast mode; within it, slow is
          // assumed, and the trace says the modes were inferred).
          x.gyro_fast[a] = mode_columns[a] ? fast[i][a] : std::abs(w) > t.calibration.gyro_range_deg_s(false);
        } else {
          // WiiYourself!'s slow range is ±8192·0.05 deg/s: beyond it the MotionPlus was in fast mode.
          x.gyro_fast[a] = std::abs(w) > 8192 * kWySlowScale;
          if (std::abs(w) >= 0.99 * 8192 * kWyFastScale) x.flags |= kGyroSaturated;
        }
      }
      if (speeds && !rates) t.gyro_mode_inferred = true;
      if (rates && !(mode_columns[0] && mode_columns[1] && mode_columns[2])) t.gyro_mode_inferred = true;
    }
    if (have(F::buttons)) {
      const unsigned bits = unsigned(r.cells[col.at(F::buttons)]);
      x.buttons = ((bits & 0xffu) << 8) | (bits >> 8);  // WiiYourself! reads the two bytes little-endian
    }
    if (have(F::button_a) && r.cells[col.at(F::button_a)] == 1.0) x.buttons |= kButtonA;
    if (have(F::button_b) && r.cells[col.at(F::button_b)] == 1.0) x.buttons |= kButtonB;
    if (repeated[i]) x.flags |= kRepeated;
    t.samples.push_back(x);
  }
  // 9. What was chosen, for the notes.
  t.notes.push_back("remote " + remote_name(remote) + (remotes.size() > 1 ? " of " + remote_list : std::string()) +
                    (options.remote > 0 ? " (--remote)" : remotes.size() > 1 ? " (the first with data)" : ""));
  if (raw)
    t.notes.push_back(std::string("angular rate from the MotionPlus raw words; range modes ") +
                      (have(F::slow_pitch) || have(F::fast_pitch) ? "from the slow/fast columns"
                       : speeds && !t.gyro_mode_inferred ? "from WiiYourself!'s Speed columns"
                                                         : "inferred from jumps"));
  else if (rates)
    t.notes.push_back(std::string("angular rate from the rate columns (right-handed about X, Y, Z); range modes ") +
                      (t.gyro_mode_inferred ? "from the rates' size where no slow/fast column gives them"
                                            : "from the slow/fast columns"));
  else if (speeds)
    t.notes.push_back("angular rate from WiiYourself!'s Speed columns (sign reversed; range modes from their size)");
  if (skipped_unchanged > 0)
    t.notes.push_back(std::to_string(skipped_unchanged) + " rows with no new data for " + remote_name(remote) +
                      " (written for another remote) skipped");
  if (skipped_empty > 0) t.notes.push_back(std::to_string(skipped_empty) + " rows without data for " + remote_name(remote) + " skipped");
  if (!t.has_buttons) t.notes.push_back("no button column: the release is taken at the file's end");
  auto list = [&](const char* what, const std::vector<std::string>& names) {
    if (names.empty()) return;
    std::string s = what;
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : " ") + names[i];
    t.notes.push_back(s);
  };
  list("columns read and checked, not used (sample numbers, the accelerometer's orientation):", unused);
  list("columns not recognised (ignored; map them with --columns):", unrecognised);
  return t;
}

}  // namespace stoneskip
