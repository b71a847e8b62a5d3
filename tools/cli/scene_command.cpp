// stoneskip scene CASE [--set key=value ...] [--json] [--movie FILE.mp4|.gif [--movie-size WxH] [--movie-rate HZ]]
//                      [--out FILE.h5 [--water-frames T1,T2,...]]
//
// Runs a stone case as a scene, frame by frame, for its [scene] duration whether or not the stone
// has sunk: the stone on its [water] (coupled as water.coupling says; still water, no field at
// all, without [water] or with coupling = "none"). Prints the frames per second simulated (no
// drawing), the slowest frame, and what each part cost — thread CPU and wall per frame, the parts
// (stone, draught, water, recording) by the wall clock — and the throw's bounces. With --movie the
// frames are drawn with gnuplot and assembled with ffmpeg (a progress bar while drawing). With
// --out the throw is stored as `run --out` stores it, with the scene's settings in /scene, and
// --water-frames T,... adds the water surface at the first frame at or after each time, as
// float32 (frames × ny × nx) in /water: at most kMaxWaterFrames frames, held to --max-memory-gb.
// A scene running longer than 2 s shows a progress line on stderr (frames done, time left).
//   stoneskip scene cases/scenes/seed_8ms.toml
//   stoneskip scene cases/scenes/seed_8ms.toml --json
//   stoneskip scene cases/scenes/seed_8ms_paper.toml --movie seed_paper.mp4
//   stoneskip scene cases/scenes/seed_8ms.toml --set water.coupling=one_way --set scene.duration_s=1
//   stoneskip scene cases/scenes/seed_8ms.toml --out seed.h5 --water-frames 0.1,0.5,1
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

#include "reports/scene/scene_movie.hpp"
#include "solvers/scene/pond_extent.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/json_output.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/progress.hpp"
#include "tools/io/signal_cleanup.hpp"
#include "tools/io/subprocess.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/scene_throw.hpp"
#include "tools/scene/throw_output.hpp"

namespace stoneskip::cli {
namespace {

namespace fs = std::filesystem;

struct SceneArgs {
  std::string case_file;
  std::vector<std::string> sets;
  bool json = false;
  std::string movie;
  bool movie_given = false;  // `--movie ""` is refused, not read as "no movie"
  std::string movie_size = "1280x540";
  std::optional<double> movie_rate_hz;  // none given: the format's default (MovieOptions::rate_hz = 0)
  double movie_slow = MovieOptions{}.slow_motion;
  std::string out;
  bool out_given = false;
  std::vector<double> water_frames_s;
  ResourceLimits limits;
};

// A folder for the movie's frames, removed with the object, or by the signal cleanup if a signal
// ends the command (made and registered in one step under the cleanup's lock).
class WorkFolder {
 public:
  WorkFolder() {
    with_registry_lock([&] {
      // TMPDIR naming no folder, or one that cannot be written, is the environment's fault: one line
      // naming it, exit 2 (it was "internal error", exit 3, with no word of TMPDIR).
      std::error_code ec;
      const fs::path dir = fs::temp_directory_path(ec);
      // The variable the library read: the first set of TMPDIR, TMP, TEMP, TEMPDIR (libstdc++), else /tmp.
      std::string named = "/tmp";
      for (const char* v : {"TMPDIR", "TMP", "TEMP", "TEMPDIR"})
        if (const char* value = std::getenv(v)) {
          named = std::string(v) + "=" + value;
          break;
        }
      if (ec) throw InputError(named + ": no folder for the movie's frames (" + ec.message() + "): set TMPDIR to a writable folder");
      std::string tmpl = (dir / "stoneskip-movie-XXXXXX").string();
      if (!mkdtemp(tmpl.data()))
        throw InputError(named + ": cannot make a folder for the movie's frames there (" + std::strerror(errno) +
                         "): set TMPDIR to a writable folder");
      path_ = tmpl;
      registered_ = RegisteredTemporary(path_, TemporaryKind::folder);
    });
  }
  ~WorkFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  RegisteredTemporary registered_;
};

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string general(double v, int significant = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

// A scene file stores at most this many water frames: 100 frames of the seed's 500 × 500 pond
// are 100 MB of float32; more is a movie's job (--movie), not a data file's.
constexpr std::size_t kMaxWaterFrames = 100;

// The water surface at chosen frames, kept as float32 (the field's own precision where it is
// float32; far finer than the stencil's error where it is double) until the file is written.
struct WaterFrames {
  std::set<long> wanted;  // frame indices, 1 … N
  std::vector<double> t_s;
  std::vector<long> index;
  std::vector<float> heights_m;  // frames × ny × nx, row-major, x fastest
  std::vector<double> scratch;
  void record(const SceneFrame& f) {
    if (!f.field || !wanted.count(f.index)) return;
    f.field->heights(scratch);
    heights_m.insert(heights_m.end(), scratch.begin(), scratch.end());
    t_s.push_back(f.t_s);
    index.push_back(f.index);
  }
};

// The frames of --water-frames: each time picks the first frame at or after it (frame k shows
// t = k / rate, k = 1 … N); refused before any work when out of the scene or too many.
std::set<long> chosen_frames(const std::vector<double>& times_s, const SceneOptions& o) {
  if (times_s.size() > kMaxWaterFrames)
    throw_input_error("--water-frames", 0, "", "at most " + std::to_string(kMaxWaterFrames) + " frames (got " +
                                                   std::to_string(times_s.size()) + ")");
  std::set<long> frames;
  for (double t : times_s) {
    // The scene's last frame ends it (it runs whole frames): a time past it has no frame at or after it.
    if (!(t >= 0 && t <= o.end_s() * (1 + 1e-12)))
      throw_input_error("--water-frames", 0, "", "every time must lie in the scene, 0 to " + general(o.end_s()) +
                                                     " s, its last frame (got " + general(t) + ")");
    const long k = std::max(1L, static_cast<long>(std::ceil(t * o.frame_rate_hz - 1e-9)));
    frames.insert(std::min(k, o.frames()));
  }
  return frames;
}

void write_water(const H5Group& root, const SceneOptions& o, const WaterFrames& w) {
  H5Group g = root.create_group("water");
  const HeightFieldOptions& f = o.water->field;
  g.set_attr("nx", static_cast<long long>(f.nx));
  g.set_attr("ny", static_cast<long long>(f.ny));
  g.set_attr("cell_m", f.cell_m);
  // Grid point (i, j) lies at (origin_x_m + i cell_m, origin_y_m + j cell_m) in the throw's frame.
  g.set_attr("origin_x_m", o.water->placement.origin_x_m);
  g.set_attr("origin_y_m", o.water->placement.origin_y_m);
  g.set_attr("stencil", f.stencil.name);
  g.write_vector("t_s", w.t_s, "s");
  g.write_ints("frame", std::vector<long long>(w.index.begin(), w.index.end()));
  g.write_floats_3d("height_m", w.heights_m, {w.t_s.size(), static_cast<std::size_t>(f.ny), static_cast<std::size_t>(f.nx)}, "m");
}

// The contacts (1-based) whose first touch lies outside a walled pond's grid points
// (solvers/scene/pond_extent.hpp): the paper scene's 6th bounce, 4.7 m past the edge, gave the stone
// 0.54 N s and the water 0, and a pond moved 100 m away still read "two_way", with no word of either.
// The text says so in the throw's notes (run_notes), the JSON also here.
PondExtent pond_of(const SceneOptions& o, const SceneSummary& s) {
  return pond_extent(o.water->field, o.water->placement.origin_x_m, o.water->placement.origin_y_m, s.stone.contacts);
}

nlohmann::json json_of(const StoneCase& c, const SceneOptions& o, const SceneSummary& s) {
  nlohmann::json j;
  j["case"] = c.title;
  j["coupling"] = to_string(o.coupling);
  j["frame_rate_hz"] = o.frame_rate_hz;
  j["frames"] = s.frames;
  j["simulated_s"] = s.simulated_s;
  j["frames_per_s_cpu"] = s.frames_per_s_cpu();
  j["frames_per_s_wall"] = s.frames_per_s_wall();
  j["cpu_s"] = s.cpu_s;
  j["wall_s"] = s.wall_s;
  j["slowest_frame"] = {{"index", s.slowest_frame},
                        {"t_s", s.slowest_frame > 0 ? s.frame_costs[s.slowest_frame - 1].t_s : 0.0},
                        {"wall_s", s.slowest_frame_wall_s},
                        {"cpu_s", s.slowest_frame_cpu_s}};
  j["parts_wall_s"] = {{"stone", s.stone_wall_s}, {"draught", s.draught_wall_s}, {"water", s.water_wall_s},
                       {"recording", s.recording_wall_s}, {"energy_budget", s.energy_budget_wall_s}};
  j["clocks"] = "cpu_s: the scene thread's CPU time; wall_s and parts_wall_s: wall clock (steady). cpu_s, wall_s and "
                "frames_per_s include parts_wall_s.energy_budget, the waves' energy budget that --json measures (two "
                "transforms of the grid per water step) and the plain summary, whose speed is the scene's own, does not; "
                "the budget also has every water step taken alone, a cost left in parts_wall_s.water, so "
                "frames_per_s_wall_without_energy_budget is still below the plain summary's speed";
  j["frames_per_s_wall_without_energy_budget"] =
      s.wall_s > s.energy_budget_wall_s ? s.frames / (s.wall_s - s.energy_budget_wall_s) : 0.0;
  j["water_steps"] = s.water_steps;
  j["draught_samples"] = s.draught_samples;
  j["max_draught_volume_m3"] = s.max_draught_volume_m3;
  j["draught_impulse_m3_s"] = s.draught_impulse_m3_s;
  j["water_volume_change_m3"] = s.volume_end_m3 - s.volume_start_m3;
  // The level the stone reads between water steps (model/water/height_field_surface.hpp).
  if (o.water) j["level_in_time"] = to_string(o.level_in_time);
  if (o.coupling == Coupling::two_way) {
    // model/README.md §2.4: what the water received against what the stone received, and the
    // waves' energy budget (solvers/scene/wave_energy.hpp).
    j["forcing"] = to_string(o.forcing);
    j["stone_vertical_impulse_N_s"] = s.stone_vertical_impulse_N_s;
    j["water_vertical_impulse_N_s"] = s.water_vertical_impulse_N_s;
    if (o.forcing == Forcing::pressure) {
      j["heads_on_footprint"] = s.heads_on_footprint;
      // The head's smoothing (solvers/scene/coupled_scene.hpp, pressure_smoothing_passes).
      j["head_width_m"] = o.head_width_m;
      j["head_smoothing_passes"] = pressure_smoothing_passes(o.head_width_m, o.water->field.cell_m);
      // Held for the water steps the scene ended before taking: the contacts' water impulses sum
      // to water_vertical_impulse_N_s plus this.
      j["water_impulse_pending_N_s"] = s.water_impulse_pending_N_s;
    }
    nlohmann::json contacts = nlohmann::json::array();
    for (const ContactImpulse& ci : s.contact_impulses)
      contacts.push_back({{"start_s", ci.start_s}, {"end_s", ci.end_s}, {"stone_N_s", ci.stone_N_s}, {"water_N_s", ci.water_N_s}});
    j["contact_impulses"] = contacts;
    if (s.energy.measured) {
      j["energy_budget_residual"] = s.energy.residual();
      j["grid_scale_energy_fraction"] = s.energy.grid_scale_fraction;
      j["wave_energy"] = {{"start_J", s.energy.start_J}, {"end_J", s.energy.end_J}, {"pressure_work_J", s.energy.pressure_work_J},
                          {"damping_loss_J", s.energy.damping_loss_J}};
    }
  }
  if (o.water) {
    j["grid"] = {o.water->field.nx, o.water->field.ny};
    j["courant"] = o.water->field.courant();
    // A stencil that couples no cell (every weight 0) is stable at every σ: its limit is infinite,
    // which JSON cannot hold, so it is null and the next key says why.
    const double limit = coupled_courant_limit(o.water->field.stencil);
    j["coupled_courant_limit"] = std::isfinite(limit) ? nlohmann::json(limit) : nlohmann::json(nullptr);
    j["coupled_courant_limit_unbounded"] = std::isinf(limit);
    j["tile_steps_fraction"] = s.tiles.fraction();
    j["precision"] = to_string(o.water->field.precision);
    j["threads"] = o.water->field.threads;
    j["mode"] = to_string(o.water->field.mode);
    const PondExtent p = pond_of(o, s);
    j["pond_extent_m"] = {{"x", {p.x0_m, p.x1_m}}, {"y", {p.y0_m, p.y1_m}}};
    j["contacts_off_pond"] = p.off;  // 1-based; the surface there is the edge's, the water takes no push
  }
  j["throw"] = json_summary(c, s.stone);
  j["bounces"] = s.stone.bounces;
  j["outcome"] = to_string(s.stone.outcome);
  return j;
}

std::string text_of(const StoneCase& c, const SceneOptions& o, const SceneSummary& s) {
  std::ostringstream m;
  m << text_summary(c, s.stone);
  m << "scene     " << s.frames << " frames of 1/" << general(o.frame_rate_hz) << " s (" << general(s.simulated_s) << " s simulated), "
    << to_string(o.coupling);
  if (o.water) {
    const HeightFieldOptions& f = o.water->field;
    m << " on " << f.nx << " × " << f.ny << " cells of " << general(f.cell_m) << " m (" << f.stencil.name << ", σ = " << general(f.courant())
      << (o.coupling == Coupling::two_way ? ", coupled limit " + general(coupled_courant_limit(f.stencil)) : std::string()) << ", "
      << to_string(f.precision) << ", " << to_string(f.mode) << ", " << f.threads << (f.threads == 1 ? " thread" : " threads") << ")";
  } else {
    m << ": still water, no field";
  }
  m << "\nspeed     " << general(s.frames_per_s_cpu()) << " frames/s simulated (CPU), " << general(s.frames_per_s_wall())
    << " (wall); real time is " << general(o.frame_rate_hz) << "\n";
  if (s.slowest_frame > 0)
    m << "slowest   frame " << s.slowest_frame << " (t = " << fixed(s.frame_costs[s.slowest_frame - 1].t_s, 3) << " s): "
      << general(1e3 * s.slowest_frame_wall_s, 3) << " ms wall, " << general(1e3 * s.slowest_frame_cpu_s, 3) << " ms CPU\n";
  auto part = [&](const char* name, double w) {
    m << "  " << name << general(1e3 * w, 4) << " ms (" << fixed(s.wall_s > 0 ? 100 * w / s.wall_s : 0, 1) << " %)\n";
  };
  m << "parts     wall clock, over " << general(1e3 * s.wall_s, 4) << " ms wall (" << general(1e3 * s.cpu_s, 4) << " ms CPU):\n";
  part("stone      ", s.stone_wall_s);
  part("draught    ", s.draught_wall_s);
  part("water      ", s.water_wall_s);
  part("recording  ", s.recording_wall_s);
  if (o.water) {
    m << "water     " << s.water_steps << " steps";
    if (o.coupling == Coupling::two_way)
      m << ", " << s.draught_samples << (o.forcing == Forcing::pressure ? " pressure heads (largest " : " draught samples (largest ")
        << general(1e6 * s.max_draught_volume_m3, 3) << " cm³"
        << (o.forcing == Forcing::pressure && o.head_width_m > 0
                ? ", smoothed to " + general(100 * o.head_width_m, 3) + " cm: " +
                      std::to_string(pressure_smoothing_passes(o.head_width_m, o.water->field.cell_m)) + " passes"
                : std::string())
        << "), volume change " << general(s.volume_end_m3 - s.volume_start_m3, 2) << " m³";
    if (o.water->field.mode == StepMode::active_tiles) m << "; active tiles: " << s.tiles.brief();
    m << "; the stone reads the level " << (o.level_in_time == LevelInTime::held ? "held over each step" : "extrapolated between steps");
    m << "\n";
  }
  return m.str();
}

void run(const SceneArgs& a) {
  StoneCase c = load_stone_case(a.case_file, a.sets);
  SceneOptions o = scene_options(c, SceneEnd::at_duration);
  // The energy budget costs two transforms of the grid per water step (in the water's wall time):
  // measured for --json, which reports it; the plain summary is the speed.
  o.energy_budget = a.json;
  std::string why;
  if (!o.valid(&why)) throw_input_error(c.file, 0, "scene", why);
  // Limits before any work (cases/README.md, Limits): the stone and its water over the scene's
  // duration (the stone stops at its t_max_s, the water runs on), and a cost record per frame.
  enforce_limits(estimate_scene(c, o.duration_s, o.frame_rate_hz), a.limits, c.file);
  // The movie's settings and tools are checked before any work.
  std::unique_ptr<MovieRecorder> movie;
  std::unique_ptr<WorkFolder> work;
  MovieOptions mo;
  if (a.movie_given && a.movie.empty()) throw_input_error("--movie", 0, "", "needs a file name (got an empty name)");
  if (!a.movie.empty()) {
    mo.output = a.movie;
    refuse_foreign_output(a.movie, OutputFormat::movie, "--movie");
    int w = 0, h = 0;
    char x = 0;
    std::istringstream size(a.movie_size);
    if (!(size >> w >> x >> h) || x != 'x' || !size.eof()) throw_input_error("--movie-size", 0, "", "must be WIDTHxHEIGHT, e.g. 1280x540");
    mo.width_px = w;
    mo.height_px = h;
    if (a.movie_rate_hz && !(*a.movie_rate_hz > 0))  // 0 is MovieOptions' "the format's default": not a value to type
      throw_input_error("--movie-rate", 0, "", "must be > 0 frames/s (got " + general(*a.movie_rate_hz, 17) + ")");
    mo.rate_hz = a.movie_rate_hz.value_or(0);
    mo.slow_motion = a.movie_slow;
    const std::string problem = mo.problem(o.frame_rate_hz);
    if (!problem.empty()) throw_input_error("--movie", 0, "", problem);
    // Known now, not after the whole scene has run: a scene shorter than one movie frame.
    if (mo.frames(o) < 1)
      throw_input_error("--movie", 0, "", "the scene's " + std::to_string(o.frames()) + " frames make no movie frame (one is drawn every " +
                                              std::to_string(mo.stride(o.frame_rate_hz)) + " scene frames)");
    // The movie's drawing and its temporary frames are held to limits too (1e8 frames were accepted).
    // At most every scene frame drawn once; slow motion's extra pictures (the stone between frames
    // near a contact, known only when the contacts are) are cut to what the limits leave
    // (MovieOptions::max_pictures), and the summary says so.
    const double frames = static_cast<double>(o.frames());
    enforce_limits(estimate_movie(frames, frames, mo.width_px, mo.height_px, mo.top_cells_max, mo.near_cells_max,
                                  MovieOptions::record_bytes(o)),
                   a.limits, "--movie");
    if (!a.limits.allow_large) mo.max_pictures = movie_picture_limit(frames, mo.width_px, mo.height_px, mo.top_cells_max, mo.near_cells_max);
    { AtomicOutput check(mo.output); }  // the folder exists and is writable
    if (!program_runs({"gnuplot", "--version"})) throw_input_error("--movie", 0, "", "gnuplot not found (apt-get install gnuplot-nox)");
    if (!program_runs({"ffmpeg", "-version"})) throw_input_error("--movie", 0, "", "ffmpeg not found (apt-get install ffmpeg)");
    work = std::make_unique<WorkFolder>();
    movie = std::make_unique<MovieRecorder>(mo, o, work->path());
  }
  // The result file and the water frames: checked before any work too.
  if (a.out_given && a.out.empty()) throw_input_error("--out", 0, "", "needs a file name (got an empty one)");
  WaterFrames water;
  if (!a.water_frames_s.empty()) {
    if (a.out.empty()) throw_input_error("--water-frames", 0, "", "needs --out FILE.h5 to store them");
    if (!o.water || o.coupling == Coupling::none) throw_input_error(c.file, 0, "water", "--water-frames needs a water field ([water] with coupling one_way or two_way)");
    water.wanted = chosen_frames(a.water_frames_s, o);
    ResourceEstimate e;
    e.add_memory(4.0 * static_cast<double>(water.wanted.size()) * o.water->field.nx * o.water->field.ny,
                 std::to_string(water.wanted.size()) + " stored water frames");
    enforce_limits(e, a.limits, "--water-frames");
  }
  if (!a.out.empty()) {
    refuse_output_over_inputs(a.out, OutputKind::file, {c.file, c.spec.mesh_file});
    refuse_same_output(a.out, "--out", a.movie, "--movie");
    refuse_foreign_output(a.out, OutputFormat::hdf5);
    AtomicOutput probe(a.out);  // an unwritable place is refused before any work
  }
  // Every input checked (bad input stays one line): a scene runs whole frames (SceneOptions::frames),
  // and a duration between two is said, not cut silently.
  if (std::abs(o.end_s() - o.duration_s) > 1e-9 * o.duration_s)
    std::fprintf(stderr, "note: scene.duration_s = %s s is %s frames of 1/%s s: the scene runs %ld whole frames, to %s s\n",
                 general(o.duration_s, 6).c_str(), general(o.duration_s * o.frame_rate_hz, 4).c_str(),
                 general(o.frame_rate_hz, 6).c_str(), o.frames(), general(o.end_s(), 6).c_str());
  // A progress line on stderr for a scene that runs longer than kQuietScene_s (frames done of all,
  // the time left); a short scene prints nothing. Its tick costs a clock read per frame.
  constexpr double kQuietScene_s = 2.0;
  SceneSummary s;
  {
    Progress progress("scene frames", static_cast<std::size_t>(o.frames()), kQuietScene_s);
    const FrameRecorder recorder = [&](const SceneFrame& f) {
      if (movie) movie->record(f);
      if (!water.wanted.empty()) water.record(f);
      progress.tick();
    };
    StoneStepRecorder stone_steps;  // the stone between frames, for a movie's slow motion only
    if (movie && movie->wants_stone_steps()) stone_steps = [&](double t_s, const RigidState& st) { movie->record_stone_step(t_s, st); };
    s = run_scene(o, recorder, stone_steps);
  }
  if (a.json) {
    nlohmann::json j = json_of(c, o, s);
    if (movie) {
      const MovieSummary m = movie->finish(s.stone.contacts, terminal_progress());
      j["movie"] = {{"file", m.file.string()},     {"frames", m.frames},         {"rate_hz", m.rate_hz},
                    {"bytes", m.bytes},             {"width_px", m.width_px},     {"height_px", m.height_px},
                    {"scale_m", m.scale_m},         {"near_z_m", m.near_z_m},     {"time_warp", m.time_warp},
                    {"drawn", m.drawn},             {"slow_drawn", m.slow_drawn}, {"end_t_s", m.end_t_s},
                    {"left_pond_t_s", m.left_pond_t_s}, {"contacts_beyond", m.contacts_beyond},
                    {"slow_pictures_asked", m.slow_pictures_asked}};
    }
    std::cout << json_text(j) << std::endl;
  } else {
    std::cout << text_of(c, o, s) << std::flush;
    if (movie) {
      std::cout << "movie     drawing the frames with gnuplot (recording the frames' data cost "
                << general(1e3 * s.recording_wall_s, 3) << " ms wall above)\n"
                << std::flush;
      const MovieSummary m = movie->finish(s.stone.contacts, terminal_progress());
      std::cout << "movie     " << m.file.string() << ": " << m.frames << " frames at " << general(m.rate_hz) << " frames/s, "
                << m.width_px << "×" << m.height_px << ", " << general(m.bytes / 1e6, 3) << " MB; drawn in " << general(m.draw_wall_s, 3)
                << " s, assembled in " << general(m.encode_wall_s, 3) << " s (wall); colour scale ±" << general(1e3 * m.scale_m, 2)
                << " mm; " << m.drawn << " scene frames drawn, " << m.slow_drawn << " of them in slow motion (" << general(m.time_warp)
                << "×)";
      if (m.slow_pictures_asked > 0)
        std::cout << "; slow motion cut from " << m.slow_pictures_asked << " to " << m.time_warp / mo.stride(o.frame_rate_hz)
                  << " pictures a frame to stay within the movie limits (--allow-large lifts them)";
      if (m.left_pond_t_s >= 0)
        std::cout << "; the stone left the pond at " << general(m.left_pond_t_s, 4) << " s, the movie ends at " << general(m.end_t_s, 4)
                  << " s, " << m.contacts_beyond << " contacts after that not shown";
      std::cout << "\n";
    }
  }
  if (!a.out.empty()) {
    if (s.stone.outcome == Outcome::failed) {
      std::fprintf(stderr, "stoneskip: %s not written: the stone's solve failed (a failed run writes no result file; one "
                   "already at that name is left as it was)\n",
                   a.out.c_str());
    } else {
      write_throw_file(a.out, c, {{"realtime", &s.stone}}, [&](const H5Group& root) {
        H5Group g = root.create_group("scene");
        g.set_attr("coupling", std::string(to_string(o.coupling)));
        g.set_attr("frame_rate_hz", o.frame_rate_hz);
        g.set_attr("frames", static_cast<long long>(s.frames));
        g.set_attr("duration_s", o.end_s());  // what was simulated: whole frames
        g.set_attr("duration_asked_s", o.duration_s);
        if (!water.t_s.empty()) write_water(root, o, water);
      });
      if (!a.json) std::cout << "wrote     " << a.out << (water.t_s.empty() ? std::string() : " (" + std::to_string(water.t_s.size()) + " water frames)") << "\n";
    }
  }
  if (s.stone.outcome == Outcome::failed) set_exit_code(1);
}

void add_scene(CLI::App& app) {
  auto a = std::make_shared<SceneArgs>();
  auto* cmd = app.add_subcommand("scene", "Run a stone case as a scene, frame by frame: frames/s simulated, cost per part, a movie");
  cmd->add_option("CASE", a->case_file, "Stone case file (TOML; [water] and [scene], see cases/README.md)")->required();
  cmd->add_option("--set", a->sets, "Override a case key: section.key=value (repeatable)");
  cmd->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  cmd->add_option("--movie", a->movie, "Draw the frames (gnuplot) and assemble them (ffmpeg) into FILE.mp4 or FILE.gif");
  cmd->add_option("--movie-size", a->movie_size, "Movie frame size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--movie-rate", a->movie_rate_hz,
                  "Movie frames per second: the scene's frame rate divided by a whole number (default: every frame for MP4, ≤ 30/s for GIF)");
  cmd->add_option("--movie-slow", a->movie_slow,
                  "Slow motion around each contact: the time-warp factor (1: real time throughout)")->capture_default_str();
  cmd->add_option("--out", a->out, "Write the throw (as `run --out`), the scene's settings and any water frames to this HDF5 file");
  cmd->add_option("--water-frames", a->water_frames_s,
                  "Store the water surface at these times, s (comma-separated; the first frame at or after each; at most 100)")
      ->delimiter(',');
  add_limit_options(cmd, a->limits);
  cmd->callback([a, cmd] {
    a->movie_given = cmd->count("--movie") > 0;
    a->out_given = cmd->count("--out") > 0;
    // A movie setting without a movie would be ignored without a word.
    if (!a->movie_given)
      for (const char* option : {"--movie-size", "--movie-rate", "--movie-slow"})
        if (cmd->count(option) > 0) throw_input_error(option, 0, "", "needs --movie FILE (no movie is drawn without it)");
    run(*a);
  });
}

const bool kRegistered = register_command(add_scene);

}  // namespace
}  // namespace stoneskip::cli
