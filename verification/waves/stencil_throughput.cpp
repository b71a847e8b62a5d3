#include "verification/waves/stencil_throughput.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "model/water/disturbance.hpp"
#include "model/water/leapfrog_kernel.hpp"
#include "model/water/thread_team.hpp"
#include "verification/waves/plain_stencil_loop.hpp"

namespace stoneskip {

const char* to_string(ThroughputClock c) { return c == ThroughputClock::wall ? "wall" : "cpu"; }

bool ThroughputOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* what) {
    if (why) *why = what;
    return false;
  };
  if (n < 8) return fail("throughput: n must be >= 8");
  if (threads < 1 || threads > 256) return fail("throughput: threads must be in [1, 256]");
  if (samples < 1) return fail("throughput: samples must be >= 1");
  if (!(sample_s > 0)) return fail("throughput: sample_s must be > 0");
  if (clock == ThroughputClock::cpu && threads != 1) return fail("throughput: the cpu clock needs threads = 1 (use wall)");
  if (temporal_steps < 0 || temporal_steps > 1000) return fail("throughput: temporal_steps must be in [0, 1000]");
  if ((temporal_steps > 0 || plain_loop) && (threads != 1 || precision != Precision::float64))
    return fail("throughput: temporal blocking and the plain loop are timed on one thread in float64");
  if (temporal_two_threads && temporal_steps > 0 && clock != ThroughputClock::wall)
    return fail("throughput: temporal_two_threads is timed on the wall clock");
  return true;
}

std::string ThroughputSummary::brief() const {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "%d² %s %s %d thread%s (%s): %.3g cells/s (%s clock), %.2f of the copy bound %.3g cells/s "
                "(copy %.3g GB/s); medians %.3g cells/s, fraction %.2f",
                options.n, options.stencil.name.c_str(), to_string(options.precision), options.threads,
                options.threads == 1 ? "" : "s", kernel_isa.c_str(), cells_per_s, clock, fraction, bound_cells_per_s,
                copy_bytes_per_s * 1e-9, cells_per_s_median, fraction_median);
  return buf;
}

namespace {

double now_s(ThroughputClock clock) {
  if (clock == ThroughputClock::wall)
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// Runs `kernel` repeatedly for at least `sample_s` on the clock; returns seconds per call.
template <class F>
double time_sample(F&& kernel, double sample_s, ThroughputClock clock) {
  const double t0 = now_s(clock);
  long calls = 0;
  double elapsed = 0;
  do {
    kernel();
    ++calls;
    elapsed = now_s(clock) - t0;
  } while (elapsed < sample_s);
  return elapsed / static_cast<double>(calls);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

template <class Real>
void measure_copy(std::size_t elements, ThreadTeam& team, const ThroughputOptions& o, std::vector<double>& seconds,
                  const std::function<void()>& between) {
  std::vector<Real> a(elements, Real(1)), b(elements, Real(0));
  const int parts = 4 * team.size();  // chunks, as the field's step cuts its rows
  auto copy = [&](int part) {
    const PartRange r = part_range(static_cast<long>(elements), part, parts);
    std::memcpy(b.data() + r.begin, a.data() + r.begin, static_cast<std::size_t>(r.end - r.begin) * sizeof(Real));
  };
  for (int s = 0; s < o.samples; ++s) {
    seconds.push_back(time_sample([&] { team.run(copy, parts); }, o.sample_s, o.clock));
    a.swap(b);
    between();
  }
}

}  // namespace

ThroughputSummary measure_stencil_throughput(const ThroughputOptions& o) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument(why);
  // The field: a Gaussian on an n × n periodic grid at σ = 0.5 (stable for every named stencil).
  HeightFieldOptions fo;
  fo.nx = fo.ny = o.n;
  fo.cell_m = 1.0 / o.n;
  fo.dt_s = 0.5 * fo.cell_m;
  fo.damping_per_s = 0.5;
  fo.stencil = o.stencil;
  fo.precision = o.precision;
  fo.threads = o.threads;
  HeightField field(fo);
  Disturbance d;
  d.x_m = d.y_m = 0.5;
  std::vector<double> z0;
  sample_disturbance(d, o.n, o.n, fo.cell_m, z0);
  field.set_state(z0);
  // The copy: arrays of one field level's size, split over a team of the same size.
  ThreadTeam team(o.threads);
  const std::size_t elements = static_cast<std::size_t>(o.n + 2) * (o.n + 2);
  std::vector<double> step_s, copy_s, temporal_s, plain_s;
  // The raw levels for the wavefront and the plain loop: z0 on a fixed (zero) rim, rows padded to
  // 64 bytes with the first cell of each row aligned, as the field lays them out.
  const std::ptrdiff_t w = (o.n + 2 + 15) / 8 * 8, first = w + 8;
  std::vector<double, CacheAligned<double>> raw_z, raw_zp;
  if (o.plain_loop) {
    raw_z.assign(static_cast<std::size_t>(w) * (o.n + 2) + 16, 0.0);
    for (int j = 0; j < o.n; ++j)
      for (int i = 0; i < o.n; ++i) raw_z[first + j * w + i] = z0[static_cast<std::size_t>(j) * o.n + i];
    raw_zp = raw_z;
  }
  const Stencil& st = o.stencil;
  const LeapfrogWeights<double> wts = leapfrog_weights<double>(st.centre, st.orth, st.diag, fo.courant(), fo.damping_per_s * fo.dt_s);
  // Two threads' halves: each its own two levels of n/2 rows on a zero rim, filled by its thread.
  std::vector<double> two_s;
  const std::ptrdiff_t half_rows = o.n / 2;
  std::vector<std::vector<double, CacheAligned<double>>> halves(4);
  std::unique_ptr<ThreadTeam> pair;
  if (o.temporal_steps > 0 && o.temporal_two_threads) {
    pair = std::make_unique<ThreadTeam>(2);
    auto fill = [&](int part) {
      for (int level = 0; level < 2; ++level) {
        auto& v = halves[2 * part + level];
        v.assign(static_cast<std::size_t>(w) * (half_rows + 2) + 16, 0.0);
        for (std::ptrdiff_t j = 0; j < half_rows; ++j)
          for (int i = 0; i < o.n; ++i) v[first + j * w + i] = z0[static_cast<std::size_t>(j + part * half_rows) * o.n + i];
      }
    };
    pair->run(fill, 2);
  }
  auto advance_halves = [&](int part) {
    auto& a = halves[2 * part];
    auto& b = halves[2 * part + 1];
    leapfrog_wavefront(a.data() + first, b.data() + first, o.n, half_rows, w, wts, wts.diag != 0, o.temporal_steps);
    if (o.temporal_steps % 2) a.swap(b);
  };
  auto one_step_sample = [&] {
    step_s.push_back(time_sample([&] { field.step(); }, o.sample_s, o.clock));
    if (o.temporal_steps > 0)
      temporal_s.push_back(time_sample([&] { field.advance(o.temporal_steps); }, o.sample_s, o.clock));
    if (pair)
      two_s.push_back(time_sample([&] { pair->run(advance_halves, 2); }, o.sample_s, o.clock));
    if (o.plain_loop)
      plain_s.push_back(time_sample([&] {
        plain_leapfrog_block(raw_zp.data() + first, raw_z.data() + first, o.n, o.n, w, wts);
        raw_z.swap(raw_zp);
      }, o.sample_s, o.clock));
  };
  field.step();  // warm the caches and the team
  if (o.precision == Precision::float64)
    measure_copy<double>(elements, team, o, copy_s, one_step_sample);
  else
    measure_copy<float>(elements, team, o, copy_s, one_step_sample);

  ThroughputSummary s;
  s.options = o;
  s.kernel_isa = leapfrog_kernel_isa();
  s.clock = to_string(o.clock);
  const double cells = static_cast<double>(o.n) * o.n;
  const double bytes = static_cast<double>(elements) * (o.precision == Precision::float64 ? sizeof(double) : sizeof(float));
  const double value_bytes = o.precision == Precision::float64 ? sizeof(double) : sizeof(float);
  s.cells_per_s = cells / *std::min_element(step_s.begin(), step_s.end());
  s.cells_per_s_median = cells / median(step_s);
  s.copy_bytes_per_s = 2 * bytes / *std::min_element(copy_s.begin(), copy_s.end());
  s.copy_bytes_per_s_median = 2 * bytes / median(copy_s);
  s.bound_cells_per_s = s.copy_bytes_per_s / (3 * value_bytes);
  s.fraction = s.cells_per_s / s.bound_cells_per_s;
  s.fraction_median = s.cells_per_s_median / (s.copy_bytes_per_s_median / (3 * value_bytes));
  if (!temporal_s.empty()) {
    s.temporal_cells_per_s = cells * o.temporal_steps / *std::min_element(temporal_s.begin(), temporal_s.end());
    s.temporal_fraction = s.temporal_cells_per_s / s.bound_cells_per_s;
  }
  if (!two_s.empty()) {
    s.temporal_two_threads_cells_per_s = static_cast<double>(o.n) * (2 * half_rows) * o.temporal_steps /
                                         *std::min_element(two_s.begin(), two_s.end());
    s.temporal_two_threads_fraction = s.temporal_two_threads_cells_per_s / s.bound_cells_per_s;
  }
  if (!plain_s.empty()) s.plain_cells_per_s = cells / *std::min_element(plain_s.begin(), plain_s.end());
  return s;
}

}  // namespace stoneskip
