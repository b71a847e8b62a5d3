#pragma once
// The headline speed figures, measured in one run of one binary:
//   1. the seed's scene (a stone on a 500 × 500 two-way field, 90 frames per simulated second)
//      in simulated frames per second, the field on one thread and on two;
//   2. the stencil's cell updates per second at 500² (in cache) and 2048² (in memory), against
//      the copy bound measured by the same binary (verification/waves/stencil_throughput.hpp);
//      and, beside it, the temporal-blocked kernel at 2048² (several steps per pass over memory)
//      and a plain loop of the same update at 500² (no SIMD: the stand-in for "written plainly");
//      optionally the stencil on every instruction-set path the CPU supports, side by side;
//   3. real-time throws per second in a bounce-count sweep (a grid of spins × attack angles of
//      one throw) spread over two workers (verification/stones/parallel_runs.hpp).
// Clocks: the scene is run `repeats` times; frames/s are given from the best (least disturbed)
// wall time and from the median, and from the scene thread's CPU time (one thread only). The
// stencil's figures are wall unless asked otherwise (best samples; see stencil_throughput.hpp).
// The sweep's figure is throws over the wall time of the whole sweep (best of its repeats), with
// the summed thread CPU time of the throws beside it. The machine's load average (1 minute) is
// read before and after, and the CPU's model name and core count kept, so a reader can judge
// what and where the wall figures were measured.
#include <string>
#include <vector>

#include "solvers/scene/coupled_scene.hpp"
#include "verification/stones/throw_problem.hpp"
#include "verification/study/progress.hpp"
#include "verification/waves/stencil_throughput.hpp"

namespace stoneskip {

struct SweepSpeedOptions {
  ThrowProblem base;                  // the thrown stone; its realtime options are the sweep's solver
  std::vector<double> spins_rev_s;    // × attack angles: the grid of throws
  std::vector<double> attack_angles_deg;
  int workers = 2;
  int repeats = 3;                    // best of
};

// The sweep's throws in its order: spins outer, attack angles inner.
std::vector<ThrowProblem> sweep_throws(const SweepSpeedOptions& o);

struct HeadlineSpeedOptions {
  SceneOptions scene;                 // the seed's scene (threads are set per measurement)
  int scene_repeats = 3;
  int many_threads = 2;               // "two cores"
  int stencil_small_n = 500, stencil_large_n = 2048;
  ThroughputOptions stencil;          // stencil, precision, clock, samples (n and threads set per run)
  int temporal_steps = 16;            // steps per wavefront call at the large grid (0: not measured)
  bool every_isa = false;             // the stencil on every supported path too
  bool sweep_only = false;            // only the sweep (no scene, no stencil): its keys alone are meaningful
  SweepSpeedOptions sweep;
  bool is_valid(std::string* why = nullptr) const;
};

struct SceneSpeed {
  int threads = 1;
  long frames = 0;
  std::vector<double> wall_s;         // per repeat
  double best_wall_s = 0, median_wall_s = 0, best_cpu_s = 0;
  double fps_best_wall() const { return best_wall_s > 0 ? frames / best_wall_s : 0; }
  double fps_median_wall() const { return median_wall_s > 0 ? frames / median_wall_s : 0; }
  double fps_cpu() const { return best_cpu_s > 0 ? frames / best_cpu_s : 0; }
  SceneSummary best;                  // the repeat with the best wall time (its parts and slowest frame)
};

struct SweepSpeed {
  long throws = 0;
  int workers = 0;
  std::vector<double> wall_s;         // per repeat
  double best_wall_s = 0;
  double cpu_s = 0;                   // summed thread CPU of the throws, best repeat
  // What a throw costs (the profile of the sweep's time): summed over the throws of one repeat.
  long steps = 0, contact_steps = 0;  // all stone steps; those with the contact step size
  long rhs_evaluations = 0;           // right-hand sides
  double simulated_s = 0;             // Σ of each throw's end time
  std::vector<int> bounce_histogram;  // throws with 0, 1, 2, … bounces
  std::vector<int> bounces;           // per throw, spins outer, attack angles inner (−1: failed)
  // Passivity: the largest rise of total energy over any contact of any throw (J; > 0: the stepper
  // created energy), and the throws where it is above zero (ThrowResult::max_energy_gain_J).
  double max_energy_gain_J = 0;
  long throws_gaining_energy = 0;
  double throws_per_s() const { return best_wall_s > 0 ? throws / best_wall_s : 0; }
};

struct IsaStencilSpeed {
  std::string isa;                    // to_string(SimdPath)
  ThroughputSummary small, large;
};

struct HeadlineSpeed {
  SceneSpeed scene_one, scene_many;
  ThroughputSummary stencil_small, stencil_large;
  double per_cell_ratio = 0;          // small-grid rate / large-grid rate
  SweepSpeed sweep;
  double load_before = -1, load_after = -1;  // 1-minute load average (−1: unknown)
  int cores = 0;                      // std::thread::hardware_concurrency()
  std::string cpu_model;              // /proc/cpuinfo "model name" ("unknown" where absent)
  std::vector<std::string> supported_isas;  // the kernel paths this CPU runs, scalar first
  std::vector<IsaStencilSpeed> by_isa;      // with every_isa: each supported path's stencil figures
};

// Throws std::invalid_argument for invalid options.
HeadlineSpeed measure_headline_speed(const HeadlineSpeedOptions& options, const ProgressFactory& progress = {});

}  // namespace stoneskip
