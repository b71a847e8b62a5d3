#pragma once
// The still of a scene that goes into the report: the most telling frame,
// chosen by a stated rule — the frame with the most disturbed water (cells with |z| above
// `threshold_fraction` of the largest |z| of the whole scene) among the frames before any
// disturbance reaches the pond's edge (after that, reflections muddle the rings) — and what it
// is drawn from: the surface in a window around the track (block means), the water around the
// stone (while the stone is in the air — its centre higher than its radius above z = 0 — around
// its latest first touch instead, where its newest ring is), the track and the first touches so far.
#include <string>
#include <vector>

#include "solvers/scene/coupled_scene.hpp"

namespace stoneskip {

struct StillFrameOptions {
  double threshold_fraction = 0.05;
  int top_cells_max = 200;     // the top view at most this many block means a side
  int near_cells_max = 80;     // the 3-D view's
  double near_window_m = 2.4;
  double margin_m = 0.5;       // around the track and the rings' reach (c × duration)
  bool is_valid(std::string* why = nullptr) const;
};

struct StillFrame {
  bool found = false;
  std::string problem;
  long frame = 0, frames = 0;
  double t_s = 0;
  long disturbed_cells = 0;      // at the chosen frame
  long frames_considered = 0;    // before the edge was reached
  double threshold_m = 0, largest_m = 0;
  double scale_m = 0;            // colour scale: half the median over frames of the largest |z|
  StoneStatus stone_status = StoneStatus::in_play;
  double stone_x_m = 0, stone_y_m = 0, stone_z_m = 0, stone_radius_m = 0;
  double pond_x0_m = 0, pond_x1_m = 0, pond_y0_m = 0, pond_y1_m = 0;  // the top view's window
  double top_x0_m = 0, top_y0_m = 0, top_dx_m = 0;                   // first block centre, block size
  int top_nx = 0, top_ny = 0;
  std::vector<double> top_m;     // top_ny rows of top_nx
  bool near_on_touch = false;    // the 3-D window is around the latest touch (the stone was in the air), not the stone
  double near_x0_m = 0, near_y0_m = 0, near_dx_m = 0;
  int near_n = 0;
  std::vector<double> near_m;
  std::vector<double> track_x_m, track_y_m, touch_x_m, touch_y_m;
};

// Block means of the field's heights over [i0, i0 + n b) × [j0, j0 + m b) (b × b points each,
// points beyond the grid left out), row-major n × m into out; returns the largest |mean|.
// Defined for float and double (the movie's frames and the report's stills).
template <class T>
double block_means(const HeightField& f, int i0, int j0, int n, int m, int b, std::vector<T>& out);

StillFrame capture_telling_frame(const SceneOptions& scene, const StillFrameOptions& options);

}  // namespace stoneskip
