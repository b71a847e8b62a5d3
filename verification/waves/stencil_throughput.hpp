#pragma once
// How fast the height field steps, against what the memory of the same machine allows:
// cell updates per second of HeightField::step, and the copy kernel's bytes per second
// measured in the same binary, in the same run, with the same threads and array size. A step reads
// z and z⁻ and writes z⁺ over z⁻: 3 values per cell; a copy reads and writes 2 values per element.
// The bound is (copy bytes/s) / (3 · sizeof(value)) cells/s; the fraction is the step's rate over it.
//
// With temporal_steps, HeightField::advance is timed too: on one thread and levels over L2 it takes
// the wavefront of model/water/leapfrog_kernel.hpp, with the field's own (periodic) boundary, several
// steps per pass over memory, so its rate may exceed the copy bound. With temporal_two_threads,
// also two threads each running the wavefront on its own half of the field (fixed rims, no rows
// exchanged: an upper bound on a split field, which would recompute P halo rows a pass). With
// plain_loop, a loop of the same update without SIMD (verification/waves/plain_stencil_loop.hpp).
//
// Clock: wall (steady_clock) by default, the only meaningful one when a step is split over
// threads; cpu (the calling thread's CPU time) for one thread on a loaded machine, where it leaves
// out the time other processes held the core (not what they did to the caches and the memory
// bus). The two kernels are sampled alternately, `samples` times each, every sample long enough to
// be timed (sample_s), and both the best sample (least disturbed) and the median are reported. The
// best/best fraction is the headline; the median/median fraction says how much load there was.
#include <string>

#include "model/water/height_field.hpp"
#include "model/water/stencil.hpp"

namespace stoneskip {

enum class ThroughputClock { wall, cpu };
const char* to_string(ThroughputClock c);

struct ThroughputOptions {
  int n = 500;                            // n × n cells
  Stencil stencil = named_stencil("five_point");
  int threads = 1;
  Precision precision = Precision::float64;
  ThroughputClock clock = ThroughputClock::wall;  // cpu requires threads = 1
  int samples = 30;                       // timed samples of each kernel, interleaved
  double sample_s = 0.005;                // time a sample repeats its kernel for (at least once)
  // Also timed, interleaved with the step (one thread, float64 only; 0/false: not measured):
  int temporal_steps = 0;                 // HeightField::advance over this many steps per call
  bool temporal_two_threads = false;      // and the wavefront on two halves on two threads
  bool plain_loop = false;                // the plain loop of plain_stencil_loop.hpp
  bool is_valid(std::string* why = nullptr) const;
};

struct ThroughputSummary {
  ThroughputOptions options;
  std::string kernel_isa;                 // the SIMD variant chosen at run time (leapfrog_kernel_isa)
  const char* clock = "wall";            // "wall" or "cpu" (thread CPU time)
  double cells_per_s = 0;                 // best sample of the step
  double cells_per_s_median = 0;
  double copy_bytes_per_s = 0;            // best sample of the copy (bytes read + written per second)
  double copy_bytes_per_s_median = 0;
  double bound_cells_per_s = 0;           // copy_bytes_per_s / (3 · sizeof(value)), best
  double fraction = 0;                    // cells_per_s / bound_cells_per_s (best / best)
  double fraction_median = 0;             // the same from the medians
  // Temporal blocking (HeightField::advance, the field's boundary): cell
  // updates per second over its steps, and over the same copy bound (best / best).
  double temporal_cells_per_s = 0, temporal_fraction = 0;
  // The same on two threads (halves of the field), over the one-thread copy bound.
  double temporal_two_threads_cells_per_s = 0, temporal_two_threads_fraction = 0;
  double plain_cells_per_s = 0;           // the plain loop, best sample
  std::string brief() const;  // "500² five_point float64 1 thread: 2.1e9 cells/s (wall), 0.62 of copy bound 3.4e9"
};

// Throws std::invalid_argument for invalid options.
ThroughputSummary measure_stencil_throughput(const ThroughputOptions& options);

}  // namespace stoneskip
