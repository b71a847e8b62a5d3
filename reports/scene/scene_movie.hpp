#pragma once
// A movie of a scene: every frame drawn with gnuplot (reports/scene/frame_plot.hpp: the pond from
// above with the stone and its track, an oblique 3-D view around the stone, and the stone from the
// side at true scale) and the frames assembled by ffmpeg into an MP4 (H.264) or a GIF. A recorder
// is handed every frame of the scene (solvers/scene/coupled_scene.hpp: FrameRecorder) and writes the data
// the frame will be drawn from into a work folder; finish() draws and assembles, ticking a
// progress bar per frame drawn, and writes the movie atomically (a temporary name, then renamed).
//
// Time: away from contacts the movie plays in real time: its rate is the scene's frame rate divided
// by a whole stride (every frame for MP4; for a GIF, whose delays are whole hundredths of a second,
// the smallest stride giving ≤ 30 frames/s), one movie frame per stride scene frames. Within
// slow_margin_s of a contact (before its start, after its end) every scene frame is drawn as
// round(slow_motion / stride) movie frames: slow motion, its factor written on the frame. Those
// pictures show the stone at even times from the frame to the next, between the stepper's states
// (reports/scene/stone_poses.hpp), and the water as at the frame: the field is recorded once a
// frame, and the seed's water steps once a frame. The
// movie ends after_leaving_s after the stone leaves the pond (said on the frames from then on).
// Space: the top view is a window view_width_m wide (half as high) that follows the stone, the
// stone two thirds of the way across, so that its latest rings stay in view; its heights are means
// of blocks of at least 2 × 2 cells (a grid-scale pattern would otherwise beat with the pixels:
// moiré). The 3-D view is the water around the stone, or while it is in the air around where it
// was last low (its centre within its radius of the still level): where its newest ring is.
// Scales are fixed for the whole movie, from the drawn data (reports/common/colour_scale.hpp): the
// colour ± the median over the frames of each top view's robust largest |z|; the 3-D box ± 1.2
// times the same median for the 3-D windows. The side view is at true scale: the stone's faces seen
// along the throw, and the surface along the same plane (reports/scene/side_view.hpp).
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "reports/scene/frame_plot.hpp"
#include "reports/scene/side_view.hpp"
#include "reports/scene/stone_poses.hpp"
#include "solvers/scene/coupled_scene.hpp"
#include "verification/study/progress.hpp"

namespace stoneskip {

enum class MovieFormat { mp4, gif };
// From the file's extension (.mp4, .gif); false for any other.
bool movie_format_of(const std::filesystem::path& file, MovieFormat& out);

struct MovieOptions {
  std::filesystem::path output;
  int width_px = 1280, height_px = 540;
  double rate_hz = 0;               // 0: the default of the format (see above)
  double near_window_m = 2.4;       // the 3-D view's side
  int near_cells_max = 100;         // the 3-D view's grid at most this many points a side (block means)
  int top_cells_max = 300;          // the top view at most this many points a side (block means)
  double view_width_m = 6;          // the top view's width (at most the pond's)
  double slow_motion = 8;           // time-warp factor around contacts (1: real time throughout)
  double slow_margin_s = 0.03;      // slow motion from this long before a contact to this long after
  double after_leaving_s = 0.4;     // the movie ends this long after the stone leaves the pond
  // At most this many pictures (the movie limits, tools/scene/resource_estimate.hpp): slow motion
  // draws fewer pictures per frame where the contacts' frames would pass it.
  double max_pictures = std::numeric_limits<double>::infinity();
  // Empty when usable with a scene of this frame rate; else what is wrong (a rate that does not
  // divide the scene's, a size out of range, an unknown format).
  std::string problem(double scene_rate_hz) const;
  // For a usable scene (problem() empty): scene frames per movie frame, and the movie's frames
  // ⌊N / stride⌋ (0 for an unknown format).
  int stride(double scene_rate_hz) const;
  long frames(const SceneOptions& scene) const;
  // Pictures drawn per scene frame in slow motion, each shown once: round(slow_motion / stride),
  // at least 1. They show the stone between the frame and the next (the water as at the frame).
  int slow_pictures(double scene_rate_hz) const;
  // The bytes a recorder holds per scene frame for this scene at the throw's speed (its windows,
  // the stone, the surface along the side view: more where the stone moves further in a frame).
  static double record_bytes(const SceneOptions& scene);
};

struct MovieSummary {
  std::filesystem::path file;
  long frames = 0;
  double rate_hz = 0;
  int width_px = 0, height_px = 0;
  std::uintmax_t bytes = 0;
  double scale_m = 0, near_z_m = 0;
  double time_warp = 1;            // the slow motion's factor (1: none)
  int slow_pictures_asked = 0;     // > 0: the pictures per slow frame asked for, cut to fit max_pictures
  long drawn = 0, slow_drawn = 0;  // scene frames drawn; of them, in slow motion (slow_pictures each)
  double left_pond_t_s = -1;       // when the stone left the pond (-1: it did not)
  long contacts_beyond = 0;        // contacts that began after the movie's end
  double end_t_s = 0;              // the last frame drawn
  double draw_wall_s = 0, encode_wall_s = 0;
};

class MovieRecorder {
 public:
  // work_dir: an empty folder of the caller's (removed by the caller).
  MovieRecorder(const MovieOptions& options, const SceneOptions& scene, std::filesystem::path work_dir);
  void record(const SceneFrame& frame);
  // The stone between frames (solvers/scene/coupled_scene.hpp, StoneStepRecorder): slow motion
  // draws it at the times between two frames (reports/scene/stone_poses.hpp). Wanted only with
  // slow motion.
  bool wants_stone_steps() const { return o_.slow_motion > 1; }
  void record_stone_step(double t_s, const RigidState& stone);
  // Draws the recorded frames and assembles the movie. `contacts` gives the first-touch points
  // (the throw's contacts, from the scene's summary). Throws std::runtime_error with gnuplot's or
  // ffmpeg's message on failure; no movie file is left then.
  MovieSummary finish(const std::vector<ContactRecord>& contacts, const ProgressFactory& progress);

 private:
  struct FrameData {
    long index;
    double t_s;
    bool sunk, in_pond;
    double top_x0_m, top_y0_m;   // the top window's first block centre
    double near_x0_m, near_y0_m, near_dx_m;
    int near_nx, near_ny;
    double top_scale_m, near_scale_m;  // robust largest |z| of each view
    RigidState stone;                   // where it is drawn, its track, the side view (side_view.hpp)
    // The surface along the side view's direction through the stone's centre, at s = s0 + k ds
    // (cm): wide enough for the view of the stone anywhere up to the next frame.
    double water_s0_cm = 0, water_ds_cm = 1;
    std::vector<float> water_cm;
  };
  static constexpr int kSideSamples = 121;  // points of the surface drawn across the side view
  // Picture m: frame f (frames_[j]) with the stone drawn as `stone` at time t (slow_contact: the
  // contact whose slow motion it is in, 0 in real time); writes its side view's data files.
  FramePlot picture(long m, const FrameData& f, std::size_t j, const RigidState& stone, double t_s, long slow_contact,
                    const std::vector<ContactRecord>& contacts, const MovieSummary& s) const;
  MovieOptions o_;
  MovieFormat format_ = MovieFormat::mp4;
  std::filesystem::path dir_;
  double scene_rate_hz_;
  int stride_ = 1;
  bool has_field_;
  double stone_radius_m_;
  Stone stone_;                           // its faces, for the side view
  Vec3 side_direction_;                   // the side view's horizontal direction (the throw's)
  // The pond (or, without a field, a box around the throw's start).
  double x0_m_ = 0, y0_m_ = 0, cell_m_ = 0;
  int nx_ = 0, ny_ = 0;
  int view_nx_ = 0, view_ny_ = 0;         // the top window, in cells
  int top_block_ = 2, top_nx_ = 0, top_ny_ = 0;  // its block means
  bool low_seen_ = false;
  double low_x_m_ = 0, low_y_m_ = 0;      // where the stone was last low
  double left_t_s_ = -1;
  std::vector<FrameData> frames_;
  std::vector<StonePose> poses_;          // the stone at its steps' starts (slow motion)
  std::vector<float> buffer_;
};

}  // namespace stoneskip
