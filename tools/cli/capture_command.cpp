// stoneskip capture: Wii Remote captures (tools/capture/README.md, model/README.md §4).
//
//   stoneskip capture validate FILE... [--json] [--out DIR]    verdicts; --out: the captures report
//   stoneskip capture throw FILE --solver realtime|reference|both [--json] [--out FILE.h5]
//   stoneskip capture throw FILE --scene SCENE [--json]          through the coupled scene, both references
//   stoneskip capture convert FILE --out TRACE.csv               any format → stoneskip trace CSV
//   stoneskip capture synthesize --out DIR                       the shipped synthetic captures + truth
//   stoneskip capture columns                                    the csv reader's recognised column names
//
// Examples (regression runs):
//   stoneskip capture validate cases/captures/*.log cases/captures/*.evemu --out out/captures
//   stoneskip capture validate cases/captures/hard_sidearm_clipped.log --json --no-reference
//   stoneskip capture throw cases/captures/gentle_sidearm.log --solver both
//   stoneskip capture throw cases/captures/skip_12ms_14revs.log --scene cases/captures/pond_two_way.toml
// Common options: --format NAME (force a reader), --case FILE (stone and water, default
// cases/paper_8ms_spin.toml), --mount key=value (mounting.hpp), --thrower key=value
// (virtual_thrower.hpp), --clock MODEL, --button A|B, --saturation-g G, --max-accel-g G, --members N,
// --seed S.
// validate --out DIR writes the captures report (reports/capture/capture_report.hpp): DIR/data.h5
// with one findings section per capture and an index, DIR/index.md and DIR/figures/ rendered from
// it alone (`stoneskip report render DIR` rebuilds them), built in DIR.partial and moved into place
// when whole. A file that cannot be read then stops the report before any work.
// --scene SCENE (throw, validate): a stone case with [water] and [scene] (cases/README.md, "A stone on
// live water"; --scene-set key=value overrides its keys): the capture's virtual stone is thrown into that scene and
// compared with the CVODE reference (the stone) and the forced spectral reference driven by the
// CVODE trajectory's draught (the waves; verification/captures/capture_scene.hpp). With validate
// --out, each usable capture's section shows both comparisons.
// Exit status: 0 done (whatever the verdicts, unless --strict and one is unusable), 1 --strict
// with an unusable capture or a failed solve, 2 bad input.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <iostream>
#include <memory>

#include "reports/capture/capture_json.hpp"
#include "reports/common/report_build.hpp"
#include "tools/capture/capture_format.hpp"
#include "tools/capture/capture_truth_file.hpp"
#include "tools/capture/csv_columns.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "tools/capture/trace_csv.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/dotted_key.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/printable_text.hpp"
#include "tools/io/progress.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/stone_case.hpp"
#include "tools/scene/throw_output.hpp"
#include "tools/scene/scene_throw.hpp"
#include "verification/captures/capture_findings.hpp"
#include "verification/captures/capture_truth.hpp"
#include "verification/captures/capture_scene_findings.hpp"
#include "verification/study/study_sink.hpp"

namespace stoneskip::cli {
namespace {

namespace fs = std::filesystem;

struct CaptureArgs {
  std::vector<std::string> files;
  std::string format;
  int remote = 0;
  std::string columns;
  std::string case_file = "cases/paper_8ms_spin.toml";
  std::vector<std::string> sets;
  std::vector<std::string> mounts;
  std::vector<std::string> thrower;
  std::string clock = "automatic";
  std::string button = "B";
  double saturation_g = 3.4;
  double max_accel_g = 20.0;
  double max_rate_deg_s = CaptureOptions{}.max_rate_deg_s;  // the analysis's default, its source cited there
  int members = 64;
  unsigned seed = 20130101;
  bool json = false;
  std::string out;
  std::string solver = "both";
  bool no_reference = false;
  bool no_simulate = false;
  bool strict = false;
  bool progress = false;
  std::string scene;
  std::vector<std::string> scene_sets;
  ResourceLimits limits;
  CLI::Option* validate_case = nullptr;  // validate's --case (given, or the default)
  // throw's ensemble options, registered only to be refused by name (it draws no ensemble).
  std::vector<CLI::Option*> throw_refused;
  std::string refused_value;
};

void add_read(CLI::App* cmd, CaptureArgs& a) {
  cmd->add_option("--format", a.format, "Force a reader: trace_csv, report_log, evemu, gesture, csv (default: recognised from the content)")
      ->check(CLI::IsMember({"auto", "trace_csv", "report_log", "evemu", "gesture", "csv"}));
  cmd->add_option("--remote", a.remote, "csv: the remote to read (the N of a '#WMN' column suffix; default: the first with data)")
      ->check(CLI::Range(1, 999));
  cmd->add_option("--columns", a.columns, "csv: map columns, key[unit]=Column Name,... (keys: t, ax, ay, az, wx, wy, wz, raw_pitch, raw_roll, raw_yaw, speed_pitch, speed_roll, speed_yaw, slow_*, fast_*, buttons, button_a, button_b, pitch, roll, seq)");
}

// A capture is seconds to minutes of reports (a minute at 100 Hz is about 0.5 MB of text), and
// reading one takes about 7 times its size in memory (1.44 GB for a 218 MB, 3-million-row trace):
// a larger file is refused before it is read (cases/README.md, Limits).
constexpr double kMaxCaptureBytes = 64e6;
constexpr double kCaptureReadMemoryPerByte = 7;  // the "about 7 times" above

// The size first (--allow-large lifts it), then the memory the reading takes (--max-memory-gb,
// whether or not the size was lifted): a file over both limits is told of the one to lift first.
void check_capture_size(const std::string& file, const ResourceLimits& limits) {
  std::error_code ec;
  const auto bytes = fs::file_size(file, ec);
  if (ec) return;  // not a regular file: the reader says what it is
  if (!limits.allow_large && static_cast<double>(bytes) > kMaxCaptureBytes)
    throw_input_error(file, 0, "", "is " + human_bytes(static_cast<double>(bytes)) + ", above the " + human_bytes(kMaxCaptureBytes) +
                                       " a capture may be (hours of reports; cases/README.md, Limits); --allow-large lifts it");
  ResourceEstimate e;
  e.add_memory(kCaptureReadMemoryPerByte * static_cast<double>(bytes),
               "reading the capture: about 7 times its " + human_bytes(static_cast<double>(bytes)));
  enforce_limits(e, limits, file);
}

// validate holds every capture it reads at once: their reading together is held to --max-memory-gb.
void check_captures_memory(const std::vector<std::string>& files, const ResourceLimits& limits) {
  double bytes = 0;
  for (const auto& f : files) {
    std::error_code ec;
    const auto b = fs::file_size(f, ec);
    if (!ec) bytes += static_cast<double>(b);
  }
  ResourceEstimate e;
  e.add_memory(kCaptureReadMemoryPerByte * bytes, "reading the " + std::to_string(files.size()) +
                                                      " captures, held together: about 7 times their " + human_bytes(bytes));
  enforce_limits(e, limits, "capture validate");
}

CaptureReadOptions read_options(const CaptureArgs& a) {
  CaptureReadOptions o;
  o.format = a.format;
  o.csv.remote = a.remote;
  o.csv.columns = a.columns;
  return o;
}

// ensemble: the command draws the ensemble (validate); throw runs the nominal throw alone, so the
// options that only shape the ensemble (--max-accel-g, --max-rate-deg-s: what a clipped span may
// hide; --members, --seed) are refused by name there rather than ignored.
void add_common(CLI::App* cmd, CaptureArgs& a, bool ensemble) {
  add_read(cmd, a);
  cmd->add_option("--mount", a.mounts, "Mounting setting key=value (stone_normal, stone_forward, stone_offset_m, lever_arm_m, lever_arm_rel_uncertainty), repeatable");
  cmd->add_option("--clock", a.clock, "automatic (default), regular_reports (the remote's clock fitted through the stamps) or stamps_as_given")
      ->check(CLI::IsMember({"automatic", "regular_reports", "stamps_as_given"}));
  cmd->add_option("--button", a.button, "The action button held through the swing (default B)")->check(CLI::IsMember({"A", "B"}));
  cmd->add_option("--thrower", a.thrower, "Virtual thrower setting key=value (height_mapping, release_height_m, still_height_m, height_uncertainty_m, speed_scale, spin_scale, finger_spin_rev_s), repeatable");
  cmd->add_option("--saturation-g", a.saturation_g, "An axis at or beyond this |a| is clipped, g (default 3.4)");
  if (!ensemble) {
    const char* unused = "Not used: capture throw draws no ensemble (capture validate does)";
    for (const char* name : {"--max-accel-g", "--max-rate-deg-s", "--members", "--seed"})
      a.throw_refused.push_back(cmd->add_option(name, a.refused_value, unused));
    return;
  }
  cmd->add_option("--max-accel-g", a.max_accel_g, "Largest acceleration a clipped span may hide, g (default 20)");
  cmd->add_option("--max-rate-deg-s", a.max_rate_deg_s,
                  "Largest angular rate a span with the MotionPlus at the end of its range may hide, deg/s")
      ->capture_default_str();
  cmd->add_option("--members", a.members, "Ensemble size for the intervals and the bounce distribution (default 64; 0: none, no intervals)");
  cmd->add_option("--seed", a.seed, "Seed of the ensemble's random draws");
}

// where: the command's --case option, so that a command can tell a default from a given one.
void add_case(CLI::App* cmd, CaptureArgs& a, CLI::Option** where = nullptr) {
  CLI::Option* o = cmd->add_option("--case", a.case_file, "Stone case giving the stone, water and solver settings (default cases/paper_8ms_spin.toml)");
  cmd->add_option("--set", a.sets, "Override a case key: section.key=value (repeatable)");
  if (where) *where = o;
}

CaptureOptions capture_options(const CaptureArgs& a, const Trace& t) {
  CaptureOptions o;
  o.mounting = resolve_mounting(t, a.mounts);
  o.thrower = resolve_thrower(t, a.thrower);
  o.timing.clock = a.clock == "regular_reports"   ? ClockModel::regular_reports
                   : a.clock == "stamps_as_given" ? ClockModel::stamps_as_given
                                                  : ClockModel::automatic;
  o.release_button = a.button == "A" ? kButtonA : kButtonB;
  o.saturation_g = a.saturation_g;
  o.max_accel_g = a.max_accel_g;
  o.max_rate_deg_s = a.max_rate_deg_s;
  o.members = a.members;
  o.seed = a.seed;
  std::string why;
  if (!o.is_valid(&why)) {
    // The analysis names its fields; the user gave options: name those.
    for (const auto& [field, option] : std::vector<std::pair<std::string, std::string>>{
             {"max_rate_deg_s", "--max-rate-deg-s"}, {"max_accel_g", "--max-accel-g"}, {"saturation_g", "--saturation-g"},
             {"members", "--members"}})
      for (std::size_t at = why.find(field); at != std::string::npos; at = why.find(field, at + option.size()))
        why.replace(at, field.size(), option);
    throw_input_error("capture options", 0, "", why);
  }
  return o;
}

// What capture_json (reports/capture) does not hold yet: the timing in detail, the throw as
// measured in the room, and the virtual thrower's settings.
void add_details(nlohmann::json& j, const CaptureAnalysis& an) {
  const TimingStats& t = an.timing.stats;
  auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  j["timing"] = {{"clock", to_string(t.clock)},
                 {"mean_rate_hz", number(t.mean_rate_hz)},
                 {"min_interval_ms", number(1e3 * t.min_interval_s)},
                 {"max_interval_ms", number(1e3 * t.max_interval_s)},
                 {"max_jitter_ms", number(1e3 * t.max_jitter_s)},
                 {"equal_stamps", t.equal_stamps},
                 {"clock_residual_max_ms", number(1e3 * t.clock_residual_max_s)},
                 {"longest_gap_ms", number(1e3 * t.longest_gap_s)}};
  const bool ok = an.can_throw();
  const bool drawn = !an.ensemble.empty();  // bounds only where an ensemble drew them (null otherwise)
  auto put = [&](const char* key, const Interval& v) {
    j["measured"][key] = ok ? nlohmann::json{number(v.nominal), drawn ? number(v.low) : nlohmann::json(nullptr),
                                             drawn ? number(v.high) : nlohmann::json(nullptr)}
                            : nlohmann::json(nullptr);
  };
  j["measured"] = nlohmann::json::object();
  put("speed_m_s", an.measured_speed_m_s);
  put("spin_rev_s", an.measured_spin_rev_s);
  put("rise_m", an.rise_m);
  j["thrower"] = thrower_settings(an.options.thrower);
}

// How the command was given (stored with the report).
std::string command_line(const CaptureArgs& a) {
  std::string s = "stoneskip capture validate";
  for (const auto& f : a.files) s += " " + f;
  if (!a.out.empty()) s += " --out " + a.out;
  if (!a.format.empty() && a.format != "auto") s += " --format " + a.format;
  if (a.remote) s += " --remote " + std::to_string(a.remote);
  if (!a.columns.empty()) s += " --columns '" + a.columns + "'";
  if (a.case_file != "cases/paper_8ms_spin.toml") s += " --case " + a.case_file;
  for (const auto& x : a.sets) s += " --set " + x;
  for (const auto& m : a.mounts) s += " --mount " + m;
  for (const auto& t : a.thrower) s += " --thrower " + t;
  if (a.clock != "automatic") s += " --clock " + a.clock;
  if (a.button != "B") s += " --button " + a.button;
  char b[160];
  std::snprintf(b, sizeof b, " --saturation-g %g --max-accel-g %g --max-rate-deg-s %g --members %d --seed %u",
                a.saturation_g, a.max_accel_g, a.max_rate_deg_s, a.members, a.seed);
  s += b;
  if (a.no_reference) s += " --no-reference";
  if (a.no_simulate) s += " --no-simulate";
  if (!a.scene.empty()) s += " --scene " + a.scene;
  for (const auto& x : a.scene_sets) s += " --scene-set " + x;
  return s;
}

// The sections of a captures report are stored as each capture finishes and never resumed: a
// capture takes seconds, and validate prints each one as it goes.
class FreshSections : public StudySink {
 public:
  explicit FreshSections(StudySink& to) : to_(to) {}
  std::optional<Record> resume(const std::string&) override { return std::nullopt; }
  void store(const std::string& section, const Record& r) override { to_.store(section, r); }
  const ProgressFactory& progress() const override { return to_.progress(); }

 private:
  StudySink& to_;
};

void print_verdict(const CaptureAnalysis& an, const CaptureSimulation* sim) {
  std::printf("%s: %s\n", printable_text(an.source).c_str(), to_string(an.verdict));
  for (const auto& r : an.reasons) std::printf("  - %s\n", printable_text(r).c_str());
  for (const auto& n : an.notes) std::printf("  note: %s\n", printable_text(n).c_str());
  if (!an.can_throw()) return;
  // Without an ensemble (capture throw; validate --members 0) there is no interval to print.
  const bool intervals = !an.ensemble.empty();
  const auto show = [intervals](const char* name, const Interval& v, const std::string& unit) {
    if (intervals) std::printf("    %-24s %8.3f  [%.3f, %.3f] %s\n", name, v.nominal, v.low, v.high, unit.c_str());
    else std::printf("    %-24s %8.3f  %s\n", name, v.nominal, unit.c_str());
  };
  const TimingStats& t = an.timing.stats;
  std::printf("  timing: rate %.1f Hz (median interval; mean %.1f Hz), jitter %.2f ms, intervals %.1f-%.1f ms, %d gaps "
              "(about %ld reports lost), %zu repeats; clock %s",
              t.rate_hz, t.mean_rate_hz, 1e3 * t.jitter_s, 1e3 * t.min_interval_s, 1e3 * t.max_interval_s, t.gaps,
              t.dropped_reports, t.repeated, to_string(t.clock));
  if (t.clock == ClockModel::regular_reports) std::printf(" at %.4g Hz", t.clock_rate_hz);
  std::printf("\n");
  std::printf("  saturated fraction %.3f\n", an.saturated_fraction);
  const bool rough = intervals && static_cast<int>(an.ensemble.size()) < kMembersResolvingInterval;
  std::printf("  as measured (the stone at the remote's mounting, in the room)%s:\n",
              !intervals ? "; no intervals (no ensemble: capture validate --members N gives them)"
              : rough    ? "; rough intervals: too few members to resolve the 2.5-97.5 % range (about 41 do)"
                         : "");
  const std::string used = an.nominal.speed_floored ? "the accelerometer's lower bound, which the lever-arm value is below"
                                                    : "the lever-arm value";
  show("speed", an.measured_speed_m_s,
       !an.clipped ? std::string("m/s")
       : intervals ? "m/s (accelerometer clipped: " + used + "; the interval is the accelerometer's bounds and the re-runs)"
                   : "m/s (accelerometer clipped: " + used + ")");
  show("  accelerometer", an.accel_speed_m_s, "m/s");
  show("  angular rate x lever", an.lever_speed_m_s, "m/s");
  show("attack angle", an.attack_angle_deg, "deg");
  show("path angle", an.path_angle_deg, "deg");
  show("spin about the normal", an.measured_spin_rev_s, "rev/s");
  show("rise since still part", an.rise_m, "m");
  const VirtualThrowerOptions& th = an.options.thrower;
  std::printf("  as mapped (the virtual stone: %s, speed x%g, spin x%g + %g rev/s):\n", to_string(th.height_mapping),
              th.speed_scale, th.spin_scale, th.finger_spin_rev_s);
  show("speed", an.speed_m_s, "m/s");
  show("spin", an.spin_rev_s, "rev/s");
  show("height above the water", an.height_m, "m");
  if (sim) {
    auto run = [](const ThrowResult& r) { return (r.outcome == Outcome::failed ? "failed after " : "") + std::to_string(r.bounces); };
    if (sim->realtime) std::printf("  bounces: real-time %s", run(*sim->realtime).c_str());
    if (sim->reference) std::printf(", reference %s", run(*sim->reference).c_str());
    if (sim->every_member_failed())
      std::printf(", ensemble: all %zu runs failed", sim->ensemble_bounces.size());
    else if (!sim->ensemble_bounces.empty())
      std::printf(", ensemble median %d [%d, %d] of %zu%s", sim->bounces_median, sim->bounces_low, sim->bounces_high,
                  sim->ensemble_bounces.size(),
                  sim->ensemble_failed > 0 ? (" (" + std::to_string(sim->ensemble_failed) + " failed)").c_str() : "");
    if (!sim->corners.empty()) {
      // Clipped: the nominal throw at the corners of the speed and height intervals.
      const auto [least, most, failed] = sim->corner_range();
      if (most >= 0) std::printf("; at the intervals' corners %d to %d", least, most);
      if (failed > 0) std::printf("%s%d of %zu corner runs failed", most >= 0 ? ", " : "; ", failed, sim->corners.size());
    }
    std::printf("\n");
  }
}

// The throw is the capture's: a --set (or --scene-set) of the case's [throw] (however its key is written: "throw",
// '"throw"', " throw ") would be ignored without a word. A malformed key is left to the case loader.
void refuse_throw_sets(const std::string& command, const std::vector<std::string>& sets, const std::string& flag = "--set") {
  for (const std::string& set : sets) {
    const auto eq = assignment_equals(set);
    std::vector<std::string> parts;
    if (eq == std::string::npos || !parse_dotted_key(set.substr(0, eq), parts, nullptr) || parts.front() != "throw")
      continue;
    throw_input_error(flag + " " + join_dotted_key(parts), 0, "",
                      command + " takes the throw from the capture; [throw] keys of the case are not used");
  }
}

// The scene case of --scene, checked before any work: it must have a water field.
std::optional<StoneCase> load_scene_case(const CaptureArgs& a) {
  if (a.scene.empty()) return std::nullopt;
  refuse_throw_sets("capture --scene", a.scene_sets, "--scene-set");
  StoneCase c;
  try {
    c = load_stone_case(a.scene, a.scene_sets);
  } catch (const InputError& e) {
    // The case reader names an override "--set KEY"; here the user wrote --scene-set.
    std::string m = e.what();
    if (const auto at = m.find("--set "); at != std::string::npos) m.replace(at, 6, "--scene-set ");
    throw InputError(m);
  }
  if (!c.water || c.water->coupling == Coupling::none)
    throw_input_error(a.scene, 0, "water", "--scene needs a case with [water] and a coupling other than none");
  return c;
}

// The capture's virtual stone thrown into the scene case, against both references.
Record scene_comparison(const StoneCase& scene, const CaptureAnalysis& an) {
  StoneCase c = scene;
  c.initial = capture_initial_state(c.stone, an.nominal);
  CaptureSceneOptions o;
  o.scene = scene_options(c, SceneEnd::at_duration);
  o.reference = c.reference;
  std::string why;
  if (!o.valid(&why)) throw_input_error(scene.file, 0, "", why);
  return capture_scene_findings(compare_capture_scene(o), o, scene.file);
}

std::string verdict_line(const Record& v) { return v.text("verdict") + " — " + v.text("reason"); }

void print_scene(const Record& r) {
  const Record& st = r.at("stone");
  const Record& w = r.at("waves");
  std::printf("scene %s: stone %s\n", r.at("settings").text("case_file").c_str(), verdict_line(st.at("agreement")).c_str());
  if (!st.text("off_pond").empty()) std::printf("scene off the pond: the scene's %s\n", st.text("off_pond").c_str());
  if (!w.flag("compared")) {
    std::printf("waves not compared: %s\n", w.text("not_compared").c_str());
    return;
  }
  std::printf("waves at %.4g s, largest reference height %.3g mm; max differences (mm): total %.3g, model %.3g "
              "(path %.3g, feedback %.3g), time %.3g, space %.3g, reference quadrature %.3g\nreference: %s\n",
              w.number("t_s"), 1e3 * w.number("amplitude_m"), 1e3 * w.number("total_m"), 1e3 * w.number("model_m"),
              1e3 * w.number("path_m"), 1e3 * w.number("feedback_m"),
              1e3 * w.number("time_m"), 1e3 * w.number("space_m"), 1e3 * w.number("quadrature_m"),
              verdict_line(w.at("reference")).c_str());
}

nlohmann::json scene_json(const Record& r) {
  const Record& st = r.at("stone");
  const Record& w = r.at("waves");
  nlohmann::json j;
  j["case_file"] = r.at("settings").text("case_file");
  j["coupling"] = r.at("settings").text("coupling");
  j["forcing"] = r.at("settings").text("forcing");
  nlohmann::json s;
  for (const char* k : {"scene_bounces", "still_bounces", "reference_bounces", "max_start_difference_s",
                        "max_end_difference_s", "still_max_start_difference_s"})
    s[k] = st.number(k);
  s["verdict"] = st.at("agreement").text("verdict");
  s["reason"] = st.at("agreement").text("reason");
  s["contacts_off_pond"] = st.number("contacts_off_pond");  // begun off a walled pond: the edge's height, no push taken
  s["off_pond"] = st.text("off_pond");
  s["ensemble_members"] = st.number("count_ensemble_members");  // the verdict's: stepper against CVODE on still water
  const Table& t = st.table("contacts");
  for (std::size_t i = 0; i < t.rows(); ++i) {
    nlohmann::json c;
    for (const auto& col : t.columns) c[col] = t.column(col)[i];
    s["contacts"].push_back(c);
  }
  j["stone"] = s;
  nlohmann::json wj{{"compared", w.flag("compared")}};
  if (!w.flag("compared")) {
    wj["not_compared"] = w.text("not_compared");
  } else {
    for (const char* k : {"t_s", "amplitude_m", "total_m", "model_m", "path_m", "feedback_m", "time_m", "space_m", "quadrature_m"}) wj[k] = w.number(k);
    wj["verdict"] = w.at("reference").text("verdict");
    wj["reason"] = w.at("reference").text("reason");
  }
  j["waves"] = wj;
  return j;
}

// Every file a capture command reads: the captures, and the case and scene files (with their mesh).
std::vector<fs::path> inputs_of(const CaptureArgs& a, const StoneCase* c, const StoneCase* scene) {
  std::vector<fs::path> in(a.files.begin(), a.files.end());
  for (const auto& f : a.files)
    if (const fs::path t = capture_truth_file(f); !t.empty()) in.push_back(t);
  for (const StoneCase* k : {c, scene})
    if (k) {
      in.push_back(k->file);
      in.push_back(k->spec.mesh_file);
    }
  return in;
}

void validate(const CaptureArgs& a) {
  refuse_throw_sets("capture validate", a.sets);
  std::optional<StoneCase> c;
  if (!a.no_simulate) c = load_stone_case(a.case_file, a.sets);
  const std::optional<StoneCase> scene = load_scene_case(a);
  if (scene && a.no_simulate) throw InputError("capture validate: --scene and --no-simulate cannot be given together");
  if (a.members < 0 || a.members == 1)
    throw_input_error("--members", 0, "",
                      "must be 0 (no ensemble, no intervals) or at least 2 (got " + std::to_string(a.members) + ")");
  if (a.no_simulate && (!a.sets.empty() || (a.validate_case && a.validate_case->count() > 0)))
    throw InputError("capture validate: --case and --set are not used with --no-simulate (no solver runs)");
  if (a.scene.empty() && !a.scene_sets.empty()) throw InputError("capture validate: --scene-set needs --scene");
  if (!a.out.empty() && a.members == 0)
    throw InputError("capture validate: --members 0 with --out: the report's intervals and bounce spread need an ensemble");
  refuse_output_over_inputs(a.out, OutputKind::folder, inputs_of(a, c ? &*c : nullptr, scene ? &*scene : nullptr));
  if (c) {
    // Limits before any work (cases/README.md, Limits): every capture's ensemble is a throw per member.
    ResourceEstimate e = estimate_run(*c, RunSolvers{true, !a.no_reference, false});
    const double members = static_cast<double>(a.members) * static_cast<double>(a.files.size());
    e.add_work(members * e.work.front().count, kMaxRegressTriangleEvaluations,
               "triangle evaluations in the ensembles (" + std::to_string(a.files.size()) + " captures × " +
                   std::to_string(a.members) + " members, each a throw of the case)");
    enforce_limits(e, a.limits, "--members");
  }
  if (a.files.size() > 1) check_captures_memory(a.files, a.limits);
  // 1. Every file read first: a report holds every capture asked for, or there is none. Without
  //    --out one bad file does not stop the others; it is reported and the exit status says so.
  std::vector<std::optional<Trace>> traces;
  std::vector<std::optional<CaptureTruth>> truths;  // a synthetic capture's truth file, when beside it
  bool unreadable = false;
  for (const auto& file : a.files) {
    try {
      check_capture_size(file, a.limits);
      traces.emplace_back(read_capture(file, read_options(a)));
      truths.emplace_back(read_capture_truth(file));
    } catch (const InputError& e) {
      if (traces.size() > truths.size()) traces.pop_back();
      truths.emplace_back(std::nullopt);
      // One bad file does not stop the others; it is reported and the exit status says so. A
      // single capture's error is the command's one line.
      if (a.files.size() == 1 && !a.json) throw;
      unreadable = true;
      traces.emplace_back(std::nullopt);
      if (a.json) {
        nlohmann::json j{{"file", file}, {"verdict", "unusable"}, {"reasons", {e.what()}}, {"error", e.what()}};
        std::cout << json_text(j, -1) << std::endl;
      } else {
        std::fprintf(stderr, "stoneskip: %s\n", printable_text(e.what()).c_str());
      }
    }
  }
  if (unreadable && !a.out.empty())
    throw InputError("capture validate: at least one capture could not be read (see above); no report written to " + a.out);
  // 2. The report folder (made whole at the end, kind "captures"): checked before any work.
  const std::string command = command_line(a);
  std::optional<ReportBuild> build;
  if (!a.out.empty())
    build.emplace(ReportBuildOptions{a.out, "captures",
                                     "# " + command + "\n" + (c ? "# case " + c->file + "\n" + c->text : std::string()),
                                     command, terminal_progress(), /*keep_sections_on_signal=*/false});
  std::optional<FreshSections> sections;
  if (build) sections.emplace(*build);
  CaptureFindingsContext ctx;
  if (c) {
    ctx.case_file = a.case_file;
    ctx.stone_description = c->stone.description;
    ctx.convention = to_string(c->environment.convention);
    ctx.water_law = to_string(c->environment.water_law);
  }
  // 3. Each capture: analysis, the solvers, the verdict printed, its section stored.
  std::vector<std::pair<std::string, Record>> stored;
  std::vector<std::string> used;
  bool unusable = false;
  for (std::size_t i = 0; i < traces.size(); ++i) {
    const std::optional<Trace>& trace = traces[i];
    if (!trace) continue;
    auto run = [&] {
      const CaptureAnalysis an = analyse_capture(*trace, capture_options(a, *trace));
      CaptureSimulation sim;
      if (c && an.can_throw()) {
        CaptureSimulationOptions so;
        so.reference = !a.no_reference;
        so.realtime_options = c->realtime;
        so.reference_options = c->reference;
        // Shown at once with --progress, otherwise once the ensemble has run 2 s.
        Progress progress("capture ensemble " + an.source, an.ensemble.size(), a.progress ? 0.0 : 2.0);
        so.progress = [&progress](std::size_t, std::size_t) { progress.tick(); };
        sim = simulate_capture(c->stone, c->environment, an, so);
        progress.done();
      }
      unusable = unusable || !an.can_throw();
      if (a.json) {
        nlohmann::json j = capture_json(an, c ? &sim : nullptr);
        add_details(j, an);
        std::cout << json_text(j, -1) << std::endl;
      } else {
        print_verdict(an, c ? &sim : nullptr);
      }
      Record r = capture_findings(an, sim, ctx);
      if (truths[i] && an.can_throw()) r.add_child("truth", truth_comparison(an, *truths[i]));
      if (scene && an.can_throw()) {
        r.add_child("scene", scene_comparison(*scene, an));
        if (!a.json) print_scene(r.at("scene"));
      }
      return r;
    };
    if (!build) {
      run();
      continue;
    }
    const std::string key = capture_section_key(trace->source, used);
    stored.emplace_back(key, run_section(*sections, key, run));
  }
  // 4. The index, data.h5, the page and its figures from it alone; the folder moved into place.
  if (build) {
    build->store("index", capture_index_findings(stored, ctx));
    if (!a.json) {
      finish_report(*build, Record(), a.out);
    } else {  // stdout holds one JSON object per capture, nothing else
      render_folder(build->assemble(Record()));
      build->commit();
    }
  }
  if (unreadable) throw InputError("capture validate: at least one capture could not be read (see above)");
  if (a.strict && unusable) set_exit_code(1);
}

void throw_capture(const CaptureArgs& a) {
  if (a.scene.empty() && !a.scene_sets.empty()) throw InputError("capture throw: --scene-set needs --scene");
  for (const CLI::Option* o : a.throw_refused)
    if (o->count() > 0)
      throw InputError("capture throw: " + o->get_name() +
                       " is not used: the throw is the nominal one, with no ensemble (capture validate draws it)");
  const std::optional<StoneCase> scene = load_scene_case(a);
  if (scene && !a.out.empty()) throw InputError("capture throw: --out is not written with --scene (use capture validate --scene --out DIR for the report)");
  refuse_throw_sets("capture throw", a.sets);
  StoneCase c = load_stone_case(a.case_file, a.sets);
  // The solves are held to the limits of `run` (cases/README.md, Limits) before the capture is read.
  enforce_limits(estimate_run(c, RunSolvers{a.solver != "reference", a.solver != "realtime", !a.out.empty()}), a.limits,
                 c.file);
  refuse_output_over_inputs(a.out, OutputKind::file, inputs_of(a, &c, nullptr));
  refuse_foreign_output(a.out, OutputFormat::hdf5);
  if (!a.out.empty()) AtomicOutput check(a.out);
  check_capture_size(a.files.front(), a.limits);
  const Trace trace = read_capture(a.files.front(), read_options(a));
  CaptureOptions o = capture_options(a, trace);
  o.members = 0;  // the intervals are validate's business; the throw is the nominal one
  const CaptureAnalysis an = analyse_capture(trace, o);
  if (!an.can_throw())
    throw_input_error(a.files.front(), 0, "", std::string("unusable capture: ") + (an.reasons.empty() ? "" : an.reasons.front()));
  if (scene) {
    const Record r = scene_comparison(*scene, an);
    if (a.json) {
      nlohmann::json j = capture_json(an, nullptr);
      add_details(j, an);
      j["scene"] = scene_json(r);
      std::cout << json_text(j) << std::endl;
    } else {
      print_verdict(an, nullptr);
      print_scene(r);
    }
    return;
  }
  c.initial = capture_initial_state(c.stone, an.nominal);
  c.throw_from_parameters = false;
  c.title = "capture " + a.files.front();
  std::vector<std::pair<std::string, ThrowResult>> results;
  const Heartbeat alive("capture throw");  // a line on stderr once the solves take more than 2 s
  if (a.solver == "realtime" || a.solver == "both")
    results.emplace_back("realtime", run_realtime(c.stone, c.environment, c.initial, c.realtime));
  if (a.solver == "reference" || a.solver == "both")
    results.emplace_back("reference", run_reference(c.stone, c.environment, c.initial, c.reference));
  if (a.json) {
    nlohmann::json j = capture_json(an, nullptr);
    add_details(j, an);
    for (const auto& [name, r] : results) j[name] = json_summary(c, r);
    std::cout << json_text(j) << std::endl;
  } else {
    print_verdict(an, nullptr);
    for (const auto& [name, r] : results) std::cout << text_summary(c, r) << "\n";
  }
  bool failed = false;
  for (const auto& [name, r] : results) failed = failed || r.outcome == Outcome::failed;
  if (failed) set_exit_code(1);
  if (!a.out.empty() && failed) {
    std::fprintf(stderr, "stoneskip: %s not written: the solve failed (a failed run writes no result file; one already at "
                 "that name is left as it was)\n",
                 a.out.c_str());
  } else if (!a.out.empty()) {
    std::vector<std::pair<std::string, const ThrowResult*>> refs;
    for (const auto& [name, r] : results) refs.emplace_back(name, &r);
    write_throw_file(a.out, c, refs);
  }
}

void convert(const CaptureArgs& a) {
  refuse_output_over_inputs(a.out, OutputKind::file, inputs_of(a, nullptr, nullptr));
  refuse_foreign_output(a.out, OutputFormat::trace_csv);
  check_capture_size(a.files.front(), a.limits);
  std::optional<Heartbeat> alive(std::in_place, "capture convert");  // a line once reading takes more than 2 s
  Trace t = read_capture(a.files.front(), read_options(a));
  alive.reset();
  for (const auto& w : t.warnings) std::fprintf(stderr, "warning: %s\n", printable_text(w).c_str());
  write_text_file(a.out, trace_csv_text(t));
  std::printf("wrote %s (%zu samples from %s)\n", a.out.c_str(), t.samples.size(), t.format.c_str());
}

// The shipped synthetic captures (cases/captures/): each with its .truth.toml.
enum class CaptureKind { report_log, evemu, gesture, wiiyourself_csv };

// Writes one synthetic file into the output folder: a new file, or one that holds exactly these
// bytes already (the shipped set regenerated by the same code: left alone). Anything else there is
// not known to be stoneskip's and is refused, naming it; nothing is written through a link.
// Whether synthesize must write `text` to `path`: false where the file already holds it; an
// InputError where something else is there (not replaced).
bool synthetic_needs_writing(const fs::path& path, const std::string& text) {
  std::error_code ec;
  const auto st = fs::symlink_status(path, ec);
  if (!ec && fs::exists(st)) {
    if (!fs::is_regular_file(st)) throw_input_error(path.string(), 0, "", "exists and is not a regular file: not replaced");
    if (read_text_file(path) == text) return false;
    throw_input_error(path.string(), 0, "",
                      "exists and differs from what synthesize writes: not replaced (remove it to regenerate it, "
                      "or choose another --out)");
  }
  return true;
}

void synthesize(const CaptureArgs& a) {
  // The folder: made if missing (with its parents); never a link (its files would land elsewhere).
  {
    std::error_code ec;
    const auto st = fs::symlink_status(a.out, ec);
    if (!ec && fs::is_symlink(st)) throw_input_error(a.out, 0, "--out", "is a symbolic link: not written through");
    if (!ec && fs::exists(st) && !fs::is_directory(st)) throw_input_error(a.out, 0, "--out", "exists and is not a folder");
  }
  fs::create_directories(a.out);
  struct Item {
    std::string name;
    SyntheticThrow th;
    SyntheticSensor s;
    CaptureKind kind;
  };
  // Gestures (a remote swung in a room): release 0.9 m up, 5–10 m/s, 1–2 rev/s.
  SyntheticThrow gentle;
  gentle.swing_rate_rad_s = 7.0;
  gentle.pivot_speed_m_s = 1.0;
  SyntheticThrow hard;  // Ω = 14 rad/s: clips a real remote
  SyntheticSensor lossy;
  lossy.drop_probability = 0.06;
  lossy.jitter_s = 0.0045;
  lossy.seed = 7;
  SyntheticThrow no_still = gentle;
  no_still.still_s = 0.1;
  no_still.press_at_s = 0.0;
  SyntheticSensor s37;
  s37.report_id = 0x37;
  s37.seed = 3;
  // Skipping throws as published (synthetic_capture.hpp, skipping_throw).
  SkippingThrowSpec bocquet;  // Bocquet 2003's example: 12 m/s, 14 rev/s; Clanet's α = 20°
  // Near the physical convention's threshold for the measured throw: 14 m/s at α ≈ 31°, β ≈ 2°
  // separates 0 from 1 bounce there (this model's optimum is α ≈ 25–30°, model/README.md §3). A thrower whose
  // trunk barely turns (pivot share 5 %), so the lever-arm estimate stays close to the speed.
  SkippingThrowSpec threshold;
  threshold.speed_m_s = 14.5;
  threshold.spin_rev_s = 12.0;
  threshold.attack_angle_deg = 31.0;
  threshold.path_angle_deg = 2.0;
  threshold.pivot_share = 0.05;
  SkippingThrowSpec two_remotes;
  two_remotes.speed_m_s = 10.0;
  two_remotes.spin_rev_s = 12.0;
  two_remotes.path_angle_deg = 8.0;
  SyntheticSensor s_skip;
  s_skip.report_id = 0x37;
  s_skip.seed = 11;
  SyntheticSensor s_threshold;
  s_threshold.seed = 13;
  SyntheticSensor s_wm1;  // a Windows host: larger jitter
  s_wm1.jitter_s = 0.004;
  s_wm1.seed = 17;
  const std::vector<Item> items{{"gentle_sidearm.log", gentle, {}, CaptureKind::report_log},
                                {"hard_sidearm_clipped.log", hard, s37, CaptureKind::report_log},
                                {"gentle_sidearm.evemu", gentle, {}, CaptureKind::evemu},
                                {"gentle_sidearm_gesture.txt", gentle, {}, CaptureKind::gesture},
                                {"lossy_sidearm.log", gentle, lossy, CaptureKind::report_log},
                                {"no_still_part.log", no_still, {}, CaptureKind::report_log},
                                {"skip_12ms_14revs.log", skipping_throw(bocquet), s_skip, CaptureKind::report_log},
                                {"skip_threshold_14ms.log", skipping_throw(threshold), s_threshold, CaptureKind::report_log},
                                {"skip_two_remotes_wiiyourself.csv", skipping_throw(two_remotes), s_wm1,
                                 CaptureKind::wiiyourself_csv}};
  SyntheticSensor idle;  // the second remote, on the table
  idle.rate_hz = 99.6;
  idle.jitter_s = 0.004;
  idle.accel_zero_counts = {511, 509, 515};
  idle.accel_one_g_counts = {615, 613, 618};
  idle.gyro_zero_counts = {8101, 8033, 8150};
  idle.seed = 19;
  // Every file made and every destination checked before the first is written: a refusal (a
  // file of the user's under one of the names) once came after 17 files had been written.
  struct Out {
    fs::path path;
    std::string text;
  };
  std::vector<Out> outs;
  std::vector<std::string> lines;
  for (const auto& it : items) {
    SyntheticTruth truth;
    std::string text;
    switch (it.kind) {
      case CaptureKind::report_log: text = synthetic_report_log(it.th, it.s, truth); break;
      case CaptureKind::evemu: text = synthetic_evemu(it.th, it.s, truth); break;
      case CaptureKind::gesture: text = synthetic_gesture(it.th, it.s, truth); break;
      case CaptureKind::wiiyourself_csv: text = synthetic_wiiyourself_csv(it.th, it.s, idle, truth); break;
    }
    outs.push_back({fs::path(a.out) / it.name, text});
    // gesture: name_gesture.truth.toml (the recorder's own extension is dropped); others: name.ext.truth.toml.
    const fs::path p(it.name);
    const std::string truth_name = it.kind == CaptureKind::gesture ? p.stem().string() : it.name;
    outs.push_back({fs::path(a.out) / (truth_name + ".truth.toml"), truth.toml()});
    char line[400];
    std::snprintf(line, sizeof line, "wrote %s (truth: %.3f m/s, attack %.2f deg, path %.2f deg, spin %.2f rev/s seen, %.2f in all)\n",
                  it.name.c_str(), truth.speed_m_s, truth.attack_angle_deg, truth.path_angle_deg, truth.spin_rev_s,
                  truth.total_spin_rev_s);
    lines.push_back(line);
  }
  std::vector<bool> needed;
  for (const Out& o : outs) needed.push_back(synthetic_needs_writing(o.path, o.text));
  for (std::size_t k = 0; k < outs.size(); ++k)
    if (needed[k]) write_text_file(outs[k].path, outs[k].text);
  for (const std::string& l : lines) std::fputs(l.c_str(), stdout);
}

// The header-driven CSV reader's table of recognised column names (from the code, so it cannot
// drift from what the reader does).
void print_columns() {
  std::printf("key           meaning                                                        units (first: default)\n");
  for (const auto& f : csv_fields()) {
    std::string units;
    for (CsvUnit u : f.units) units += std::string(units.empty() ? "" : ", ") + (u == CsvUnit::none ? "none" : to_string(u));
    std::printf("%-13s %-62s %s\n", f.key, f.meaning, units.c_str());
    std::string names;
    for (const auto& n : csv_field_names(f.field)) names += std::string(names.empty() ? "" : ", ") + n;
    std::printf("              names: %s\n", names.c_str());
  }
  std::printf("Names are compared in lowercase words (split at spaces, _ . - / : and camelCase); a unit in [ ] or ( )\n"
              "or as trailing words (t_s, wx_deg_s), and a device suffix #WMn, may follow.\n");
}

void add_capture(CLI::App& app) {
  auto* cmd = app.add_subcommand("capture", "Wii Remote captures: validate them, convert them, throw them");
  cmd->require_subcommand(1);
  auto a = std::make_shared<CaptureArgs>();

  auto* v = cmd->add_subcommand("validate", "Judge captures (verdict, timing, clipping, still part, release, throw with intervals, bounce counts)");
  v->add_option("FILE", a->files, "Capture files (any format)")->required();
  v->add_flag("--json", a->json, "One JSON object per capture (one per line)");
  v->add_option("--out", a->out, "Write the captures report into DIR (index.md, figures/, data.h5; an existing report folder is replaced)")
      ->check([](const std::string& d) { return d.empty() ? std::string("needs a folder name (got an empty one)") : std::string(); });
  v->add_flag("--no-reference", a->no_reference, "Skip the CVODE reference run of the nominal throw");
  v->add_flag("--no-simulate", a->no_simulate, "Skip the solvers (no case file needed)");
  v->add_flag("--strict", a->strict, "Exit with status 1 if a capture is unusable");
  v->add_flag("--progress", a->progress, "Show the ensemble's progress on stderr at once (otherwise after 2 s)");
  v->add_option("--scene", a->scene, "Also throw each usable capture into this scene case against both references (its report section shows them)");
  v->add_option("--scene-set", a->scene_sets, "Override a key of the scene case: section.key=value (repeatable)");
  add_common(v, *a, true);
  add_case(v, *a, &a->validate_case);
  add_limit_options(v, a->limits);
  v->get_option("--allow-large")->description("Run even when the estimated work (the ensembles' throws) exceeds the documented "
                                               "limits, and read captures larger than 64 MB (cases/README.md, Limits)");
  v->callback([a] { validate(*a); });

  auto* t = cmd->add_subcommand("throw", "Run the throw a capture records through the solvers");
  t->add_option("FILE", a->files, "Capture file")->required()->expected(1);
  t->add_option("--solver", a->solver, "realtime, reference or both (default)")->check(CLI::IsMember({"realtime", "reference", "both"}));
  t->add_flag("--json", a->json, "Print one JSON object");
  t->add_option("--out", a->out, "Write the trajectories and the case to this HDF5 file")
      ->check([](const std::string& f) { return f.empty() ? std::string("needs a file name (got an empty one)") : std::string(); });
  t->add_option("--scene", a->scene, "Throw it into this scene case ([water], [scene]) against the CVODE and the forced spectral references");
  t->add_option("--scene-set", a->scene_sets, "Override a key of the scene case: section.key=value (repeatable)");
  add_common(t, *a, false);
  add_case(t, *a);
  add_limit_options(t, a->limits);
  t->get_option("--allow-large")->description("Run even when the estimated work (steps, triangle evaluations) exceeds the "
                                               "documented limits, and read a capture larger than 64 MB (cases/README.md, Limits)");
  t->callback([a] { throw_capture(*a); });

  auto* c = cmd->add_subcommand("convert", "Write any capture as a stoneskip trace CSV");
  c->add_option("FILE", a->files, "Capture file")->required()->expected(1);
  c->add_option("--out", a->out, "Trace CSV to write")->required();
  add_read(c, *a);
  add_limit_options(c, a->limits);
  // Here the only work is reading: --allow-large lifts the size a capture may be.
  c->get_option("--allow-large")->description("Read a capture larger than the 64 MB limit (cases/README.md, Limits)");
  c->callback([a] { convert(*a); });

  auto* cols = cmd->add_subcommand("columns", "List the column names the csv reader recognises, with their units");
  cols->callback([] { print_columns(); });

  auto* s = cmd->add_subcommand("synthesize", "Write the shipped synthetic captures and their truth files");
  s->add_option("--out", a->out, "Folder (e.g. cases/captures)")
      ->required()
      ->check([](const std::string& d) { return d.empty() ? std::string("needs a folder name (got an empty one)") : std::string(); });
  s->callback([a] { synthesize(*a); });
}

const bool kRegistered = register_command(add_capture);

}  // namespace
}  // namespace stoneskip::cli
