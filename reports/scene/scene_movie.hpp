#pragma once
// A movie of a scene (issue 9, item 6): every frame drawn with gnuplot (reports/scene/
// frame_plot.hpp: the pond from above with the stone and its track, and an oblique 3-D view around
// the stone) and the frames assembled by ffmpeg into an MP4 (H.264) or a GIF. A recorder is handed
// every frame of the scene (solvers/scene/coupled_scene.hpp: FrameRecorder) and writes the data
// the frame will be drawn from into a work folder; finish() draws and assembles, ticking a
// progress bar per frame drawn, and writes the movie atomically (a temporary name, then renamed).
//
// The movie plays in real time: its rate is the scene's frame rate divided by a whole stride
// (every frame for MP4; for a GIF, whose delays are whole hundredths of a second, the smallest
// stride giving ≤ 30 frames/s). It has ⌊N / stride⌋ frames for a scene of N frames, i.e. the
// scene's duration × the movie's rate. The colour scale is fixed for the whole movie: ± half the
// median over the frames of the largest |z| (so a splash saturates and the rings stay visible).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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
  int top_cells_max = 600;          // the top view at most this many points a side (block means)
  // Empty when usable with a scene of this frame rate; else what is wrong (a rate that does not
  // divide the scene's, a size out of range, an unknown format).
  std::string problem(double scene_rate_hz) const;
  // For a usable scene (problem() empty): scene frames per movie frame, and the movie's frames
  // ⌊N / stride⌋ (0 for an unknown format).
  int stride(double scene_rate_hz) const;
  long frames(const SceneOptions& scene) const;
};

struct MovieSummary {
  std::filesystem::path file;
  long frames = 0;
  double rate_hz = 0;
  int width_px = 0, height_px = 0;
  std::uintmax_t bytes = 0;
  double scale_m = 0;
  double draw_wall_s = 0, encode_wall_s = 0;
};

class MovieRecorder {
 public:
  // work_dir: an empty folder of the caller's (removed by the caller).
  MovieRecorder(const MovieOptions& options, const SceneOptions& scene, std::filesystem::path work_dir);
  void record(const SceneFrame& frame);
  // Draws the recorded frames and assembles the movie. `contacts` gives the first-touch points
  // (the throw's contacts, from the scene's summary). Throws std::runtime_error with gnuplot's or
  // ffmpeg's message on failure; no movie file is left then.
  MovieSummary finish(const std::vector<ContactRecord>& contacts, const ProgressFactory& progress);

 private:
  struct FrameData {
    long index;
    double t_s, x_m, y_m, z_m;
    bool sunk;
    double near_x0_m, near_y0_m, near_dx_m;
    int near_nx, near_ny;
  };
  MovieOptions o_;
  MovieFormat format_ = MovieFormat::mp4;
  std::filesystem::path dir_;
  double scene_rate_hz_;
  int stride_ = 1;
  bool has_field_;
  double stone_radius_m_;
  // The pond (or, without a field, a box around the throw's start).
  double x0_m_ = 0, y0_m_ = 0, cell_m_ = 0;
  int nx_ = 0, ny_ = 0, top_block_ = 1, top_nx_ = 0, top_ny_ = 0;
  std::vector<FrameData> frames_;
  std::vector<double> frame_max_m_;
  std::vector<float> buffer_;
};

}  // namespace stoneskip
