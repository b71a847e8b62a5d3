#pragma once
// Estimates, from a validated case, of the memory a command will hold and the work it will do, and
// the documented limits they are held to (cases/README.md, "Limits"; tools/io/resource_limits.hpp
// refuses what exceeds them). Estimates are worst cases known before any work:
//  * a real-time throw takes at most t_max_s / contact_dt_s steps (every step in contact), each of
//    (1, 2 or 4 right-hand sides by scheme) × the stone's triangles; a reference throw at most
//    [reference] max_steps steps of one right-hand side each;
//  * its trajectory holds a sample per output_dt_s (every step with output_dt_s = 0);
//  * a height field holds about 5 arrays of its cells, 10.5 with the spectral reference (FFTW
//    buffers, transforms, the reference surface); a wave case steps cells × ⌈t_end/Δt⌉.
#include <string>
#include <vector>

#include "tools/io/resource_limits.hpp"
#include "tools/scene/stone_case.hpp"
#include "tools/scene/wave_case.hpp"
#include "verification/stones/bounce_baseline.hpp"

namespace stoneskip {

// Worst-case triangle evaluations (right-hand sides × triangles) of one throw: about 80 ns each
// (measured, one core), so 2e9 is under three minutes even if every step were in contact.
constexpr double kMaxTriangleEvaluations = 2e9;
// Height-field cell updates of a wave run or of a scene's water (0.6–0.9 G/s measured: about a minute).
constexpr double kMaxCellUpdates = 5e10;
// Worst-case triangle evaluations of a whole `stoneskip regress` (every throw of every baseline).
constexpr double kMaxRegressTriangleEvaluations = 1e11;

struct RunSolvers {
  bool realtime = true;
  bool reference = false;
  bool writes_file = false;  // --out: the trajectory is also held as a table
};

ResourceEstimate estimate_run(const StoneCase& c, const RunSolvers& solvers);
ResourceEstimate estimate_wave(const WaveCase& c);
// A coupled scene of duration_s at frame_rate_hz: the stone and its water over the whole duration
// (the stone stops at its t_max_s, the water runs on), and a cost record per frame.
ResourceEstimate estimate_scene(const StoneCase& c, double duration_s, double frame_rate_hz);
// A scene's movie recording `frames` scene frames and drawing at most `images` pictures of
// width × height pixels (slow motion draws the stone between frames: up to its factor per frame):
// the pictures drawn (pixels, against kMaxMoviePixels) and the temporary disk filled before ffmpeg
// assembles them — per frame its data (top view ≤ top_cells² and 3-D view ≤ near_cells² floats),
// per picture a PNG (≤ 3 bytes a pixel) — against kMaxMovieTemporaryBytes; the per-frame records
// of record_bytes each held in memory (reports/scene/scene_movie.hpp, MovieOptions::record_bytes).
// 5e10 pixels: 72 000 frames of 1280×540 (13 minutes of a 90 frames/s movie; gnuplot draws about
// 10–20 such frames a second on one core, so about an hour), 1500 frames at 7680×4320.
constexpr double kMaxMoviePixels = 5e10;
constexpr double kMaxMovieTemporaryBytes = 2e10;  // 20 GB of the temporary folder's disk
ResourceEstimate estimate_movie(double frames, double images, double width_px, double height_px, double top_cells, double near_cells,
                                double record_bytes);
// The most pictures a movie of `frames` scene frames may draw within kMaxMoviePixels and
// kMaxMovieTemporaryBytes (each frame's data counted once): what slow motion is cut to.
double movie_picture_limit(double frames, double width_px, double height_px, double top_cells, double near_cells);
// A sweep: every throw held to the one-throw limits at the heaviest case the design's corners give
// (SweepCases::heaviest_throw), all throws together to kSweepWorkFactor times them; its table in
// memory (throws × row_bytes) beside one throw's memory per compute thread.
constexpr double kSweepWorkFactor = 5000;
ResourceEstimate estimate_sweep(const ResourceEstimate& heaviest_throw, double throws, double row_bytes, double threads);

ResourceEstimate estimate_regress(const std::vector<BounceSweepSpec>& sweeps);

}  // namespace stoneskip
