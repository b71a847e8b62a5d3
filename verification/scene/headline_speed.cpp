#include "verification/scene/headline_speed.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "model/water/leapfrog_kernel.hpp"
#include "solvers/realtime/clocks.hpp"
#include "verification/stones/parallel_runs.hpp"
#include "tools/io/usable_cores.hpp"

namespace stoneskip {

bool HeadlineSpeedOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  std::string w;
  if (!scene.valid(&w)) return fail("scene: " + w);
  if (scene_repeats < 1 || sweep.repeats < 1) return fail("repeats must be >= 1");
  if (many_threads < 1) return fail("many_threads must be >= 1");
  if (stencil_small_n < 8 || stencil_large_n < 8) return fail("stencil grids must be >= 8");
  if (sweep.spins_rev_s.empty() || sweep.attack_angles_deg.empty()) return fail("the sweep needs spins and attack angles");
  if (sweep.workers < 1) return fail("sweep workers must be >= 1");
  return true;
}

namespace {

double load_average() {
  double l[1];
  return getloadavg(l, 1) == 1 ? l[0] : -1;
}

// The first processor's "model name", with its "cpu family", "model" and "stepping" where given: a
// virtual machine may say only "AMD EPYC", which the numbers tell apart (family 25: Zen 3/4, 26: Zen 5).
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, name, family, model, stepping;
  auto value = [&] {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) return std::string();
    const std::size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? std::string() : line.substr(start);
  };
  auto key = [&](const char* k) {
    const std::size_t colon = line.find(':');
    std::string head = line.substr(0, colon == std::string::npos ? line.size() : colon);
    while (!head.empty() && (head.back() == ' ' || head.back() == '\t')) head.pop_back();
    return head == k;
  };
  while (std::getline(in, line)) {
    if (line.empty() && !name.empty()) break;  // the first processor only
    if (key("model name")) name = value();
    else if (key("cpu family")) family = value();
    else if (key("model")) model = value();
    else if (key("stepping")) stepping = value();
  }
  if (name.empty()) return "unknown";
  if (!family.empty() && !model.empty())
    name += " (family " + family + ", model " + model + (stepping.empty() ? "" : ", stepping " + stepping) + ")";
  return name;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

SceneSpeed measure_scene(const SceneOptions& base, int threads, int repeats, ProgressTicker& ticker) {
  SceneSpeed s;
  s.threads = threads;
  SceneOptions o = base;
  if (o.water) o.water->field.threads = threads;
  for (int k = 0; k < repeats; ++k) {
    SceneSummary r = run_scene(o);
    s.frames = r.frames;
    s.wall_s.push_back(r.wall_s);
    if (k == 0 || r.cpu_s < s.best_cpu_s) s.best_cpu_s = r.cpu_s;
    if (k == 0 || r.wall_s < s.best_wall_s) {
      s.best_wall_s = r.wall_s;
      s.best = std::move(r);
    }
    ticker.tick();
  }
  s.median_wall_s = median(s.wall_s);
  return s;
}

SweepSpeed measure_sweep(const SweepSpeedOptions& o, ProgressTicker& ticker) {
  const std::vector<ThrowProblem> throws = sweep_throws(o);
  SolverChoice solver = realtime_choice(o.base.realtime);
  solver.realtime.record_trajectory = false;  // a sweep needs the counts, not the paths
  SweepSpeed s;
  s.throws = static_cast<long>(throws.size());
  s.workers = o.workers;
  std::vector<int> bounces(throws.size());
  std::vector<double> cpu(throws.size()), simulated(throws.size()), gain(throws.size());
  std::vector<long> steps(throws.size()), contact_steps(throws.size()), rhs(throws.size());
  for (int k = 0; k < o.repeats; ++k) {
    ParallelOptions po;
    po.workers = o.workers;
    const WallTimer wall;
    parallel_for(
        throws.size(),
        [&](std::size_t i) {
          const ThrowResult r = solve(throws[i], solver);
          bounces[i] = r.outcome == Outcome::failed ? -1 : r.bounces;
          gain[i] = r.max_energy_gain_J;
          cpu[i] = r.stats.cpu_s;
          steps[i] = r.stats.steps;
          contact_steps[i] = r.stats.contact_steps;
          rhs[i] = r.stats.rhs_evaluations;
          simulated[i] = r.end_time_s;
        },
        po);
    const double w = wall.seconds();
    s.wall_s.push_back(w);
    if (k == 0 || w < s.best_wall_s) {
      s.best_wall_s = w;
      s.cpu_s = 0;
      for (double c : cpu) s.cpu_s += c;
      s.steps = s.contact_steps = s.rhs_evaluations = 0;
      s.simulated_s = 0;
      for (std::size_t i = 0; i < throws.size(); ++i) {
        s.steps += steps[i];
        s.contact_steps += contact_steps[i];
        s.rhs_evaluations += rhs[i];
        s.simulated_s += simulated[i];
      }
    }
    ticker.tick();
  }
  s.bounces = bounces;
  for (double g : gain) {
    s.max_energy_gain_J = std::max(s.max_energy_gain_J, g);
    if (g > 0) ++s.throws_gaining_energy;
  }
  for (int b : bounces) {
    if (b < 0) continue;
    if (static_cast<std::size_t>(b) >= s.bounce_histogram.size()) s.bounce_histogram.resize(b + 1, 0);
    ++s.bounce_histogram[b];
  }
  return s;
}

}  // namespace

std::vector<ThrowProblem> sweep_throws(const SweepSpeedOptions& o) {
  std::vector<ThrowProblem> throws;
  for (double spin : o.spins_rev_s)
    for (double attack : o.attack_angles_deg) {
      ThrowParameters tp = o.base.parameters;
      tp.spin_rev_s = spin;
      tp.attack_angle_deg = attack;
      throws.push_back(with_parameters(o.base, tp));
    }
  return throws;
}

HeadlineSpeed measure_headline_speed(const HeadlineSpeedOptions& o, const ProgressFactory& progress) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument("headline speed: " + why);
  HeadlineSpeed h;
  h.cores = usable_cores();  // the affinity mask's: a run pinned to one core says so
  h.load_before = load_average();
  h.cpu_model = cpu_model();
  for (SimdPath p : supported_simd_paths()) h.supported_isas.push_back(to_string(p));
  auto ticker = start_progress(progress, "bench", static_cast<std::size_t>(2 * o.scene_repeats + 2 + o.sweep.repeats));
  if (o.sweep_only) {
    h.sweep = measure_sweep(o.sweep, *ticker);
    h.load_after = load_average();
    return h;
  }
  h.scene_one = measure_scene(o.scene, 1, o.scene_repeats, *ticker);
  h.scene_many = measure_scene(o.scene, o.many_threads, o.scene_repeats, *ticker);
  ThroughputOptions t = o.stencil;
  t.threads = 1;
  t.n = o.stencil_small_n;
  t.plain_loop = t.precision == Precision::float64;
  h.stencil_small = measure_stencil_throughput(t);
  ticker->tick();
  t.plain_loop = false;
  t.n = o.stencil_large_n;
  t.temporal_steps = t.precision == Precision::float64 ? o.temporal_steps : 0;
  h.stencil_large = measure_stencil_throughput(t);
  ticker->tick();
  if (o.every_isa) {
    const SimdPath chosen = leapfrog_kernel_path();
    for (SimdPath p : supported_simd_paths()) {
      set_leapfrog_kernel_path(p);
      IsaStencilSpeed s;
      s.isa = to_string(p);
      t.n = o.stencil_small_n;
      t.temporal_steps = 0;
      s.small = measure_stencil_throughput(t);
      t.n = o.stencil_large_n;
      t.temporal_steps = t.precision == Precision::float64 ? o.temporal_steps : 0;
      s.large = measure_stencil_throughput(t);
      h.by_isa.push_back(std::move(s));
    }
    set_leapfrog_kernel_path(chosen);
  }
  h.per_cell_ratio = h.stencil_large.cells_per_s > 0 ? h.stencil_small.cells_per_s / h.stencil_large.cells_per_s : 0;
  h.sweep = measure_sweep(o.sweep, *ticker);
  h.load_after = load_average();
  return h;
}

}  // namespace stoneskip
