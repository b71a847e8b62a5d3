#include "reports/scene/scene_movie.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "reports/common/colour_scale.hpp"
#include "reports/scene/frame_plot.hpp"
#include "solvers/realtime/clocks.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/subprocess.hpp"
#include "verification/scene/scene_still.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

bool movie_format_of(const fs::path& file, MovieFormat& out) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".mp4") out = MovieFormat::mp4;
  else if (ext == ".gif") out = MovieFormat::gif;
  else return false;
  return true;
}

namespace {

constexpr int kMaxStride = 1000000;

// The stride of scene frames between movie frames.
int movie_stride(MovieFormat f, double scene_rate_hz, double rate_hz) {
  if (rate_hz > 0) return static_cast<int>(std::lround(scene_rate_hz / rate_hz));
  if (f == MovieFormat::mp4) return 1;
  return std::max(1, static_cast<int>(std::ceil(scene_rate_hz / 30.0 - 1e-9)));
}

std::string frame_name(const char* stem, long k, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s_%05ld.%s", stem, k, ext);
  return buf;
}

void write_floats(const fs::path& p, const std::vector<float>& v) {
  std::ofstream f(p, std::ios::binary);
  f.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(float)));
  if (!f) throw std::runtime_error("movie: cannot write " + p.string());
}

// Block means of the field (verification/scene/scene_still.hpp), zeros without a field.
double means(const HeightField* field, int i0, int j0, int n, int m, int b, std::vector<float>& out) {
  if (field) return block_means(*field, i0, j0, n, m, b, out);
  out.assign(static_cast<std::size_t>(n) * m, 0.0f);
  return 0;
}

// Runs a program (argument vector, no shell) in `dir`, calling on_line for every line it prints
// (stdout and stderr); its exit status, or -1 if it could not start or was killed.
int run_lines(const std::vector<std::string>& argv, const fs::path& dir, const std::function<void(const std::string&)>& on_line) {
  SubprocessOptions o;
  o.working_dir = dir;
  o.stderr_to = SubprocessOptions::Stderr::merged;
  o.on_line = on_line;
  const SubprocessResult r = run_program(argv, o);
  if (!r.started) on_line(r.error);
  return r.started ? r.exit_status : -1;
}

// ffmpeg reads a name with "proto:" as a protocol and one with a leading '-' as an option; a
// "file:" URL with an absolute path is always the plain file.
std::string ffmpeg_file(const fs::path& p) { return "file:" + fs::absolute(p).string(); }

// Inserts a GIF89a comment extension (0x21 0xFE, data sub-blocks, 0x00; GIF89a specification §24)
// after the logical screen descriptor and the global colour table, if any (§18, §19). A file that
// is not GIF89a is left as it is.
void add_gif_comment(const fs::path& p, const std::string& text) {
  std::string g;
  {
    std::ifstream in(p, std::ios::binary);
    g.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (g.size() < 13 || g.compare(0, 6, "GIF89a") != 0) return;
  const auto packed = static_cast<unsigned char>(g[10]);
  std::size_t at = 13;
  if (packed & 0x80) at += 3 * (std::size_t{1} << ((packed & 7) + 1));
  if (at > g.size()) return;
  std::string block = "\x21\xFE";
  block += static_cast<char>(std::min<std::size_t>(text.size(), 255));
  block += text.substr(0, 255);
  block += '\0';
  g.insert(at, block);
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f.write(g.data(), static_cast<std::streamsize>(g.size()));
  f.close();
  if (!f) throw std::runtime_error("movie: cannot write the GIF's comment into " + p.string());
}

}  // namespace

std::string MovieOptions::problem(double scene_rate_hz) const {
  MovieFormat f;
  if (!movie_format_of(output, f)) return "the movie must be a .mp4 or .gif file (got '" + output.string() + "')";
  if (width_px < 320 || width_px > 7680 || height_px < 160 || height_px > 4320)
    return "the movie size must be within 320×160 … 7680×4320";
  if (rate_hz < 0 || !std::isfinite(rate_hz)) return "the movie rate must be > 0";
  if (rate_hz > 0) {
    const double stride = scene_rate_hz / rate_hz;
    // A stride beyond a million frames would not fit the frame counter (1e-300 frames/s: SIGFPE).
    if (!(stride <= kMaxStride)) {
      char got[64];
      std::snprintf(got, sizeof got, "%g", rate_hz);
      return "the movie rate must be at least the scene's frame rate / " + std::to_string(kMaxStride) + " (got " + got + ")";
    }
    if (stride < 1 - 1e-9 || std::abs(stride - std::round(stride)) > 1e-6)
      return "the movie rate must be the scene's frame rate divided by a whole number";
    if (f == MovieFormat::gif && rate_hz > 50) return "a GIF plays at most 50 frames/s (delays are whole hundredths of a second)";
  }
  if (!(near_window_m > 0) || near_cells_max < 8 || top_cells_max < 16 || !(view_width_m > 0)) return "bad movie window sizes";
  if (!(slow_motion >= 1 && slow_motion <= 100)) return "the movie's slow motion must be a factor within 1 … 100";
  if (!(slow_margin_s >= 0) || !(after_leaving_s >= 0)) return "the movie's slow-motion margin and its time after the stone leaves must be ≥ 0";
  return "";
}

int MovieOptions::stride(double scene_rate_hz) const {
  MovieFormat f;
  return movie_format_of(output, f) ? movie_stride(f, scene_rate_hz, rate_hz) : 1;
}

namespace {

// The surface along the side view is recorded every R / 5 over ±(4 R + |v| / rate): the view of the
// stone (at most 3.4 R from it while the level shows) anywhere up to the next frame. At most 4001
// points (a stone the paper's air law runs away with).
int side_water_points(double radius_m, double speed_m_s, double rate_hz) {
  const double reach = 4 * radius_m + speed_m_s / rate_hz, ds = radius_m / 5;
  if (!(reach / ds < 2000)) return 4001;
  return 2 * static_cast<int>(std::ceil(reach / ds)) + 1;
}

}  // namespace

double MovieOptions::record_bytes(const SceneOptions& scene) {
  const double speed = scene.initial.velocity_m_s.norm();
  return 320.0 + 4.0 * side_water_points(scene.stone.bounding_radius_m, speed, scene.frame_rate_hz);
}

int MovieOptions::slow_pictures(double scene_rate_hz) const {
  return std::max(1, static_cast<int>(std::lround(slow_motion / stride(scene_rate_hz))));
}

long MovieOptions::frames(const SceneOptions& scene) const {
  MovieFormat f;
  return movie_format_of(output, f) ? scene.frames() / stride(scene.frame_rate_hz) : 0;
}

MovieRecorder::MovieRecorder(const MovieOptions& options, const SceneOptions& scene, fs::path work_dir)
    : o_(options), dir_(std::move(work_dir)), scene_rate_hz_(scene.frame_rate_hz),
      has_field_(scene.coupling != Coupling::none && scene.water.has_value()), stone_radius_m_(scene.stone.disk_radius_m),
      stone_(scene.stone), side_direction_(side_view_direction(scene.initial.velocity_m_s)) {
  const std::string why = o_.problem(scene.frame_rate_hz);
  if (!why.empty()) throw std::invalid_argument("movie: " + why);
  movie_format_of(o_.output, format_);
  stride_ = movie_stride(format_, scene.frame_rate_hz, o_.rate_hz);
  if (has_field_) {
    const HeightFieldOptions& f = scene.water->field;
    x0_m_ = scene.water->placement.origin_x_m;
    y0_m_ = scene.water->placement.origin_y_m;
    cell_m_ = f.cell_m;
    nx_ = f.nx;
    ny_ = f.ny;
  } else {  // still water: a flat 10 m pond around the throw's start
    cell_m_ = 0.05;
    nx_ = ny_ = 200;
    x0_m_ = scene.initial.position_m.x() - 1;
    y0_m_ = scene.initial.position_m.y() - 5;
  }
  view_nx_ = std::clamp(static_cast<int>(std::lround(o_.view_width_m / cell_m_)), 2, nx_);
  view_ny_ = std::clamp(view_nx_ / 2, 2, ny_);
  top_block_ = std::max(2, (std::max(view_nx_, view_ny_) + o_.top_cells_max - 1) / o_.top_cells_max);
  top_nx_ = std::max(1, view_nx_ / top_block_);
  top_ny_ = std::max(1, view_ny_ / top_block_);
}

void MovieRecorder::record(const SceneFrame& f) {
  // Every scene frame is kept (slow motion draws them all near a contact, known only at the end),
  // until after_leaving_s after the stone has left the pond.
  const double x = f.stone.position_m.x(), y = f.stone.position_m.y(), z = f.stone.position_m.z();
  const bool in_pond = x >= x0_m_ - 0.5 * cell_m_ && x <= x0_m_ + (nx_ - 0.5) * cell_m_ && y >= y0_m_ - 0.5 * cell_m_ &&
                       y <= y0_m_ + (ny_ - 0.5) * cell_m_;
  if (!in_pond && left_t_s_ < 0 && f.stone_status == StoneStatus::in_play) left_t_s_ = f.t_s;
  if (left_t_s_ >= 0 && f.t_s > left_t_s_ + o_.after_leaving_s + 1e-9) return;
  const long k = static_cast<long>(frames_.size()) + 1;
  const HeightField* field = has_field_ ? f.field : nullptr;
  auto cell_of = [&](double v, double origin) { return static_cast<int>(std::lround((v - origin) / cell_m_)); };
  // The top window: the stone two thirds of the way across, inside the pond.
  const int ti0 = std::clamp(cell_of(x, x0_m_) - 2 * view_nx_ / 3, 0, nx_ - view_nx_);
  const int tj0 = std::clamp(cell_of(y, y0_m_) - view_ny_ / 2, 0, ny_ - view_ny_);
  means(field, ti0, tj0, top_nx_, top_ny_, top_block_, buffer_);
  write_floats(dir_ / frame_name("top", k, "bin"), buffer_);
  const double top_scale = robust_scale(std::vector<double>(buffer_.begin(), buffer_.end())).scale;
  // The 3-D window: near_window_m around the stone, or where it was last low while it flies.
  if (z <= stone_radius_m_ && in_pond) {
    low_seen_ = true;
    low_x_m_ = x;
    low_y_m_ = y;
  }
  const double cx = (z > stone_radius_m_ && low_seen_) || !in_pond ? low_x_m_ : x;
  const double cy = (z > stone_radius_m_ && low_seen_) || !in_pond ? low_y_m_ : y;
  const int side = std::min({static_cast<int>(std::ceil(o_.near_window_m / cell_m_)), nx_, ny_});
  const int block = std::max(1, (side + o_.near_cells_max - 1) / o_.near_cells_max);
  const int n = std::max(2, side / block);
  const int span = n * block;
  const int i0 = std::clamp(cell_of(cx, x0_m_) - span / 2, 0, std::max(0, nx_ - span));
  const int j0 = std::clamp(cell_of(cy, y0_m_) - span / 2, 0, std::max(0, ny_ - span));
  means(field, i0, j0, n, n, block, buffer_);
  write_floats(dir_ / frame_name("near", k, "bin"), buffer_);
  FrameData d;
  d.index = f.index;
  d.t_s = f.t_s;
  d.sunk = f.stone_status == StoneStatus::sank;
  d.in_pond = in_pond;
  d.top_x0_m = x0_m_ + (ti0 + 0.5 * (top_block_ - 1)) * cell_m_;
  d.top_y0_m = y0_m_ + (tj0 + 0.5 * (top_block_ - 1)) * cell_m_;
  d.near_dx_m = block * cell_m_;
  d.near_x0_m = x0_m_ + (i0 + 0.5 * (block - 1)) * cell_m_;
  d.near_y0_m = y0_m_ + (j0 + 0.5 * (block - 1)) * cell_m_;
  d.near_nx = d.near_ny = n;
  d.top_scale_m = top_scale;
  d.near_scale_m = robust_scale(std::vector<double>(buffer_.begin(), buffer_.end())).scale;
  // The side view: the surface along the throw's direction through the stone's centre, across
  // any window of the view of the stone up to the next frame (side_water_points).
  d.stone = f.stone;
  {
    d.water_ds_cm = 100 * stone_.bounding_radius_m / 5;
    const int points = side_water_points(stone_.bounding_radius_m, f.stone.velocity_m_s.norm(), scene_rate_hz_);
    d.water_s0_cm = -0.5 * (points - 1) * d.water_ds_cm;
    d.water_cm.resize(static_cast<std::size_t>(points));
    for (int q = 0; q < points; ++q) {
      const Vec3 at = f.stone.position_m + 0.01 * (d.water_s0_cm + q * d.water_ds_cm) * side_direction_;
      d.water_cm[static_cast<std::size_t>(q)] = field ? static_cast<float>(100 * field->interpolate(at.x() - x0_m_, at.y() - y0_m_)) : 0.0f;
    }
  }
  frames_.push_back(std::move(d));
}

void MovieRecorder::record_stone_step(double t_s, const RigidState& stone) {
  if (!poses_.empty() && !(t_s > poses_.back().t_s)) return;  // a repeated time (the throw's end)
  poses_.push_back({t_s, stone.position_m, stone.orientation});
}

namespace {

// The median of the positive values (0 if none).
double median_positive(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double a) { return !(a > 0); }), v.end());
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

FramePlot MovieRecorder::picture(long m, const FrameData& f, std::size_t j, const RigidState& stone, double t_s, long slow_contact,
                                 const std::vector<ContactRecord>& contacts, const MovieSummary& s) const {
  const double dx = cell_m_ * top_block_;
  FramePlot p;
  std::ostringstream top, near;
  top.precision(9);
  near.precision(9);
  top << "'" << frame_name("top", static_cast<long>(j) + 1, "bin") << "' binary array=(" << top_nx_ << "," << top_ny_
      << ") format='%float32' origin=(" << f.top_x0_m << "," << f.top_y0_m << ") dx=" << dx << " dy=" << dx;
  near << "'" << frame_name("near", static_cast<long>(j) + 1, "bin") << "' binary array=(" << f.near_nx << "," << f.near_ny
       << ") format='%float32' origin=(" << f.near_x0_m << "," << f.near_y0_m << ",0) dx=" << f.near_dx_m << " dy=" << f.near_dx_m;
  p.top = top.str();
  p.near = near.str();
  if (j > 0) p.track = "'track.dat' every ::0::" + std::to_string(j);
  long touched = 0;
  for (const auto& c : contacts) touched += c.start_s <= t_s;
  if (touched > 0) p.touches = "'touches.dat' every ::0::" + std::to_string(touched - 1);
  p.stone_x_m = stone.position_m.x();
  p.stone_y_m = stone.position_m.y();
  p.stone_z_m = stone.position_m.z();
  p.stone_radius_m = stone_radius_m_;
  p.stone_sunk = f.sunk;
  p.pond_x0_m = f.top_x0_m - 0.5 * dx;
  p.pond_x1_m = f.top_x0_m + (top_nx_ - 0.5) * dx;
  p.pond_y0_m = f.top_y0_m - 0.5 * dx;
  p.pond_y1_m = f.top_y0_m + (top_ny_ - 0.5) * dx;
  p.near_x0_m = f.near_x0_m;
  p.near_x1_m = f.near_x0_m + (f.near_nx - 1) * f.near_dx_m;
  p.near_y0_m = f.near_y0_m;
  p.near_y1_m = f.near_y0_m + (f.near_ny - 1) * f.near_dx_m;
  p.scale_m = s.scale_m;
  p.near_z_m = s.near_z_m;
  char speed[96], left[200];
  if (slow_contact > 0)
    std::snprintf(speed, sizeof speed, "SLOW MOTION %g× (contact %ld)", s.time_warp, slow_contact);
  else
    std::snprintf(speed, sizeof speed, "real time");
  left[0] = 0;
  if (left_t_s_ >= 0 && f.t_s >= left_t_s_)
    std::snprintf(left, sizeof left, " — LEFT THE POND at %.3f s; the movie ends at %.3f s, %ld later contacts not shown", left_t_s_,
                  s.end_t_s, s.contacts_beyond);
  // Whether the stone is in a contact now: its centre can be a centimetre above the still level
  // while a rim is wet (on its edge), and the dot alone read as a stone in flight.
  char touching[48] = "";
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (t_s >= contacts[c].start_s && t_s <= contacts[c].end_s) std::snprintf(touching, sizeof touching, ", IN CONTACT %zu", c + 1);
  char title[520], foot[240];
  // In slow motion the time to 0.1 ms: the pictures between two frames are 1/(rate × repeats) apart.
  std::snprintf(title, sizeof title, slow_contact > 0 ? "t = %.4f s   %s%s%s%s" : "t = %.3f s   %s%s%s%s", t_s, speed, touching,
                f.sunk ? ", the stone has sunk" : "", left);
  const int n = std::snprintf(foot, sizeof foot, "colour ±%.2g mm, 3-D box ±%.2g mm; means of %d×%d cells", 1e3 * s.scale_m,
                              1e3 * s.near_z_m, top_block_, top_block_);
  if (slow_contact > 0 && n > 0 && n < static_cast<int>(sizeof foot))
    std::snprintf(foot + n, sizeof foot - static_cast<std::size_t>(n), "; the water as at its frame, t = %.3f s", f.t_s);
  p.title = title;
  p.footnote = foot;
  // The side view: the stone as drawn, the surface recorded along the view's line at the frame,
  // shifted by how far the stone has moved along it since.
  const SideWindow w = side_window(stone.position_m.z(), stone_.bounding_radius_m);
  const double shift_cm = 100 * (stone.position_m - f.stone.position_m).dot(side_direction_);
  const std::string faces = frame_name("side", m, "dat"), water = frame_name("water", m, "dat");
  std::ofstream sf(dir_ / faces), wf(dir_ / water);
  write_side_faces(sf, stone_, stone, side_direction_);
  wf.precision(6);
  const int nw = static_cast<int>(f.water_cm.size());
  for (const double at : side_samples_cm(w, kSideSamples)) {
    const double u = std::clamp((at + shift_cm - f.water_s0_cm) / f.water_ds_cm, 0.0, double(nw - 1));
    const int k = std::min(static_cast<int>(u), nw - 2);
    const double eta = nw < 2 ? 0.0 : f.water_cm[k] + (u - k) * (f.water_cm[k + 1] - f.water_cm[k]);
    wf << at << " " << eta << "\n";
  }
  sf.close();
  wf.close();
  if (!sf || !wf) throw std::runtime_error("movie: cannot write the side view's data into " + dir_.string());
  p.side_faces = "'" + faces + "'";
  p.side_water = "'" + water + "'";
  p.side_s0_cm = w.s0_cm;
  p.side_s1_cm = w.s1_cm;
  p.side_z0_cm = w.z0_cm;
  p.side_z1_cm = w.z1_cm;
  p.side_note = w.level_note;
  return p;
}

MovieSummary MovieRecorder::finish(const std::vector<ContactRecord>& contacts, const ProgressFactory& progress) {
  MovieSummary s;
  s.file = o_.output;
  s.rate_hz = scene_rate_hz_ / stride_;
  s.width_px = o_.width_px;
  s.height_px = o_.height_px;
  if (frames_.empty()) throw std::runtime_error("movie: no frames to draw (the scene is shorter than one movie frame)");
  // 1. The scales, fixed for the movie: medians over the frames of each view's robust largest |z|.
  {
    std::vector<double> top, near;
    for (const auto& f : frames_) {
      top.push_back(f.top_scale_m);
      near.push_back(f.near_scale_m);
    }
    s.scale_m = median_positive(top);
    s.near_z_m = 1.2 * median_positive(near);
  }
  if (!(s.scale_m > 0)) s.scale_m = 1e-4;
  if (!(s.near_z_m > 0)) s.near_z_m = 2 * s.scale_m;
  // 2. Which frames are drawn, and as how many movie frames each: every stride-th in real time,
  //    every one near a contact as `repeats` pictures, the stone at even times from the frame to
  //    the next (the time warp repeats × stride).
  int repeats = o_.slow_pictures(scene_rate_hz_);
  auto slow_at = [&](double t) {
    if (!(o_.slow_motion > 1)) return 0L;
    for (std::size_t c = 0; c < contacts.size(); ++c)
      if (t >= contacts[c].start_s - o_.slow_margin_s - 1e-9 && t <= contacts[c].end_s + o_.slow_margin_s + 1e-9)
        return static_cast<long>(c) + 1;
    return 0L;
  };
  struct Drawn {
    std::size_t frame;
    long contact;  // 0: real time
  };
  std::vector<Drawn> drawn;
  for (std::size_t j = 0; j < frames_.size(); ++j) {
    const long c = slow_at(frames_[j].t_s);
    if (c > 0 || frames_[j].index % stride_ == 0) drawn.push_back({j, c});
  }
  if (drawn.empty()) throw std::runtime_error("movie: no frames to draw (the scene is shorter than one movie frame)");
  // The pictures within the movie limits (MovieOptions::max_pictures): slow motion's extra
  // pictures, known only now, are cut to fit, and the summary says so.
  {
    long slow = 0;
    for (const auto& d : drawn) slow += d.contact > 0;
    const double real = static_cast<double>(drawn.size() - static_cast<std::size_t>(slow));
    if (slow > 0 && real + double(slow) * repeats > o_.max_pictures) {
      s.slow_pictures_asked = repeats;
      repeats = std::max(1, static_cast<int>(std::floor((o_.max_pictures - real) / double(slow))));
    }
  }
  s.time_warp = o_.slow_motion > 1 ? double(repeats * stride_) : 1.0;
  s.drawn = static_cast<long>(drawn.size());
  s.left_pond_t_s = left_t_s_;
  s.end_t_s = frames_[drawn.back().frame].t_s;
  for (const auto& c : contacts) s.contacts_beyond += c.start_s > s.end_t_s;
  // 3. The track and the first touches, one point a line.
  {
    std::ofstream t(dir_ / "track.dat");
    t.precision(9);
    for (const auto& f : frames_) t << f.stone.position_m.x() << " " << f.stone.position_m.y() << "\n";
    std::ofstream c(dir_ / "touches.dat");
    c.precision(9);
    for (const auto& k : contacts) c << k.first_touch_m.x() << " " << k.first_touch_m.y() << "\n";
  }
  // 4. The gnuplot script: one block per drawn frame.
  std::ostringstream gp;
  gp.precision(9);
  // 10 points at 1280 px wide, in proportion at other widths (7 at least): the three panels'
  // labels keep their room on a 640 px movie.
  const int font_pt = std::clamp(static_cast<int>(std::lround(10.0 * o_.width_px / 1280)), 7, 30);
  gp << "set terminal pngcairo size " << o_.width_px << "," << o_.height_px << " font 'Sans," << font_pt << "'\n";
  long m = 0;  // pictures, in the movie's order
  for (std::size_t q = 0; q < drawn.size(); ++q) {
    const std::size_t j = drawn[q].frame;
    const FrameData& f = frames_[j];
    const bool slow = drawn[q].contact > 0;
    s.slow_drawn += slow;
    for (int r = 0; r < (slow ? repeats : 1); ++r) {
      // The stone: at the frame, or in slow motion between the stepper's states at an even time
      // from the frame to the next (the water stays as at the frame).
      const double t = f.t_s + double(r) / (repeats * scene_rate_hz_);
      RigidState stone = f.stone;
      if (slow && !poses_.empty()) {
        const StonePose pose = pose_at(poses_, t);
        stone.position_m = pose.position_m;
        stone.orientation = pose.orientation;
      }
      ++m;
      gp << "set output '" << frame_name("seq", m, "png") << "'\n"
         << frame_plot_commands(picture(m, f, j, stone, t, slow ? drawn[q].contact : 0, contacts, s)) << "set output\nprint 'frame "
         << m << "'\n";
    }
  }
  s.frames = m;
  {
    std::ofstream f(dir_ / "movie.gp");
    f << gp.str();
  }
  // 5. Draw, one tick per picture.
  const WallTimer draw;
  {
    auto ticker = start_progress(progress, "movie: drawing frames", static_cast<std::size_t>(m));
    std::string errors;
    const int rc = run_lines({"gnuplot", "movie.gp"}, dir_, [&](const std::string& line) {
      if (line.rfind("frame ", 0) == 0) ticker->tick();
      else if (errors.size() < 2000) errors += line + "\n";
    });
    if (rc != 0) throw std::runtime_error("movie: gnuplot failed (status " + std::to_string(rc) + "): " + errors);
  }
  s.draw_wall_s = draw.seconds();
  // 6. Assemble.
  const WallTimer encode;
  AtomicOutput out(o_.output);
  std::ostringstream rate;
  rate.precision(12);
  rate << s.rate_hz;
  // The frames' pattern: image2 reads '%' as a conversion, so one in the folder's name (a TMPDIR
  // with '%' in it) is written "%%"; the folder is absolute, so no "proto:" prefix is read either.
  std::string folder;
  for (char c : fs::absolute(dir_).string()) folder += c == '%' ? std::string("%%") : std::string(1, c);
  std::vector<std::string> ffmpeg = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", rate.str(),
                                     "-f", "image2", "-i", folder + "/seq_%05d.png"};
  // The MP4 carries kMovieMarker in its metadata (the GIF in a comment, below): a later --movie to
  // this name knows the file is stoneskip's to replace (tools/io/foreign_output.hpp).
  if (format_ == MovieFormat::mp4)
    ffmpeg.insert(ffmpeg.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                 "-metadata", std::string("comment=") + kMovieMarker, "-f", "mp4"});
  else
    ffmpeg.insert(ffmpeg.end(), {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-f", "gif"});
  ffmpeg.push_back(ffmpeg_file(out.temporary_path()));
  std::string errors;
  const int rc = run_lines(ffmpeg, dir_, [&](const std::string& line) {
    if (errors.size() < 2000) errors += line + "\n";
  });
  if (rc != 0) throw std::runtime_error("movie: ffmpeg failed (status " + std::to_string(rc) + "): " + errors);
  if (format_ == MovieFormat::gif) add_gif_comment(out.temporary_path(), kMovieMarker);
  out.commit();
  s.encode_wall_s = encode.seconds();
  s.bytes = fs::file_size(o_.output);
  return s;
}

}  // namespace stoneskip
