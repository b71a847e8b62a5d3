#include "model/water/height_field.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <algorithm>
#include <cstring>
#include <functional>

#include "model/water/disturbance.hpp"
#include "model/water/height_field_surface.hpp"
#include "model/water/leapfrog_kernel.hpp"
#include "model/water/stencil.hpp"

namespace stoneskip {
namespace {

// A single eigenmode of the discrete operator under undamped leapfrog, started with the Taylor
// level z⁻ = (1 + σ² s/2) z0, is exactly z_n = cos(nθ) z0 with cos θ = 1 + σ² s/2 (s the
// mode's symbol). Tolerance: n steps of round-off growth, ~1e-13 after a few hundred steps.
constexpr double kStepRoundoff = 1e-12;

HeightFieldOptions options_for(const std::string& stencil, Boundary b, int n, double sigma) {
  HeightFieldOptions o;
  o.nx = o.ny = n;
  o.cell_m = 1.0 / n;
  o.wave_speed_m_s = 1;
  o.dt_s = sigma * o.cell_m;
  o.stencil = named_stencil(stencil);
  o.boundary = b;
  return o;
}

// Runs a separable mode f(i) g(j) and compares with cos(nθ) at every cell.
double mode_error(const std::string& stencil, Boundary b, double a, double bb,
                  const std::function<double(int)>& fx, const std::function<double(int)>& fy, long steps) {
  const int n = 24;
  const double sigma = 0.5;
  HeightField f(options_for(stencil, b, n, sigma));
  std::vector<double> z0(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) z0[j * n + i] = fx(i) * fy(j);
  f.set_state(z0);
  f.advance(steps);
  const double s = named_stencil(stencil).symbol(a, bb);
  const double theta = std::acos(1 + sigma * sigma * s / 2);
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(f.height(i, j) - std::cos(steps * theta) * z0[j * n + i]));
  return worst;
}

// The heights and previous heights of a field, cell by cell, as bits.
std::vector<double> both_levels(const HeightField& f) {
  std::vector<double> v;
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i) {
      v.push_back(f.height(i, j));
      v.push_back(f.previous_height(i, j));
    }
  return v;
}

BOOST_AUTO_TEST_SUITE(height_field_)

BOOST_AUTO_TEST_CASE(advance_along_the_wavefront_gives_the_bits_of_single_steps) {
  // Oracle: n calls of step(), which apply the boundary to a whole level before each sweep. The
  // temporal-blocked advance applies it row by row (periodic: recomputed image rows) and evaluates
  // the same updates on the same operands, so both levels must agree byte for byte (tolerance 0):
  // every boundary, both storages, with and without corner weights and damping, n odd and even,
  // within one pass and over several (a pass advances at most 16 levels).
  struct Case {
    const char* stencil;
    Precision precision;
    int nx, ny;  // two levels over 1 MB, so advance takes the wavefront
  };
  const Case cases[] = {{"nine_point_isotropic", Precision::float64, 251, 262}, {"five_point", Precision::float32, 301, 419},
                        {"paper_eq11", Precision::float64, 259, 257}};
  for (const Case& c : cases)
    for (Boundary b : {Boundary::periodic, Boundary::reflecting, Boundary::fixed})
      for (long n : {2L, 7L, 37L}) {
        BOOST_TEST_CONTEXT(c.stencil << " " << to_string(c.precision) << " " << to_string(b) << " n = " << n) {
          HeightFieldOptions o = options_for(c.stencil, b, c.nx, 0.5);
          o.ny = c.ny;
          o.precision = c.precision;
          o.damping_per_s = 3;
          HeightField stepped(o), blocked(o);
          BOOST_REQUIRE(blocked.advance_is_blocked());
          // A Gaussian off centre, already nonzero at two edges (e^−1 at the right one).
          Disturbance d;
          d.x_m = 0.9 * o.nx * o.cell_m;
          d.y_m = 0.15 * o.ny * o.cell_m;
          d.width_m = 0.1;
          std::vector<double> z0;
          sample_disturbance(d, o.nx, o.ny, o.cell_m, z0);
          stepped.set_state(z0);
          blocked.set_state(z0);
          for (long s = 0; s < n; ++s) stepped.step();
          blocked.advance(n);
          const auto a = both_levels(stepped), e = both_levels(blocked);
          BOOST_TEST(std::memcmp(a.data(), e.data(), a.size() * sizeof(double)) == 0);
          BOOST_TEST(blocked.steps() == n);
          BOOST_TEST(blocked.time_s() == stepped.time_s());
          // And stepping on from there still agrees (the ghosts are refilled as step() needs).
          stepped.step();
          blocked.step();
          BOOST_TEST(stepped.height(0, 0) == blocked.height(0, 0));
          BOOST_TEST(stepped.height(o.nx - 1, o.ny - 1) == blocked.height(o.nx - 1, o.ny - 1));
        }
      }
}

BOOST_AUTO_TEST_CASE(periodic_fourier_mode_follows_the_exact_leapfrog_recurrence) {
  // Oracle: z_n = cos(nθ) z0 for the mode cos(2π(3i + 5j)/24) (see kStepRoundoff).
  const int n = 24;
  const double a = 2 * M_PI * 3 / n, b = 2 * M_PI * 5 / n;
  for (const auto& name : stencil_names()) {
    double e = mode_error(name, Boundary::periodic, a, b, [&](int i) { return std::cos(a * i); },
                          [&](int j) { return std::cos(b * j); }, 300);
    BOOST_TEST(e <= kStepRoundoff, name << ": " << e);
  }
}

BOOST_AUTO_TEST_CASE(fixed_boundary_sine_mode_follows_the_exact_leapfrog_recurrence) {
  // Oracle: sin(πm(i+1)/(n+1)) vanishes at the ghost cells i = −1 and i = n, so the product of two
  // such modes is an eigenmode of every 3×3 stencil with z = 0 ghosts; z_n = cos(nθ) z0.
  const int n = 24;
  const double a = M_PI * 2 / (n + 1), b = M_PI * 7 / (n + 1);
  for (const auto& name : stencil_names()) {
    double e = mode_error(name, Boundary::fixed, a, b, [&](int i) { return std::sin(a * (i + 1)); },
                          [&](int j) { return std::sin(b * (j + 1)); }, 300);
    BOOST_TEST(e <= kStepRoundoff, name << ": " << e);
  }
}

BOOST_AUTO_TEST_CASE(reflecting_boundary_cosine_mode_follows_the_exact_leapfrog_recurrence) {
  // Oracle: cos(πm(i + ½)/n) is even about i = −½ and i = n − ½, so mirrored ghosts make the
  // product of two such modes an eigenmode of every 3×3 stencil; z_n = cos(nθ) z0.
  const int n = 24;
  const double a = M_PI * 3 / n, b = M_PI * 4 / n;
  for (const auto& name : stencil_names()) {
    double e = mode_error(name, Boundary::reflecting, a, b, [&](int i) { return std::cos(a * (i + 0.5)); },
                          [&](int j) { return std::cos(b * (j + 0.5)); }, 300);
    BOOST_TEST(e <= kStepRoundoff, name << ": " << e);
  }
}

BOOST_AUTO_TEST_CASE(damped_uniform_raise_decays_at_the_exact_leapfrog_rate) {
  // Oracle: for a uniform field L[z] = 0 for a consistent stencil, and the centred-damping leapfrog
  // gives z⁺ = (4z − (2 − μΔt) z⁻)/(2 + μΔt), whose roots are 1 and (2 − μΔt)/(2 + μΔt); the Taylor
  // start with zero velocity puts all weight on the root 1, so the raise stays constant in exact
  // arithmetic. In floating point each step's rounding is at most γ₁₁ S |z| (the update's eleven
  // rounded operations, S = |wc| + 4|wo| + 4|wd| + |wp| the sum of its weights' sizes), and the mean
  // mode sums those errors with gain at most 1/(1 − wp) (the recurrence's roots are 1 and wp), so
  // after N steps the raise is within N γ₁₁ S |z| / (1 − wp): 9.6e-13 here (measured 2.3e-14 with
  // the column form of leapfrog_kernel.hpp; the direct form happened to keep 0.25 exactly). Weights
  // that miss consistency by δ move it by about N δ |z| / (1 − wp): 2.8e-7 at δ = 1e-9.
  auto o = options_for("nine_point_half", Boundary::reflecting, 16, 0.5);
  o.damping_per_s = 3;
  HeightField f(o);
  f.set_state(std::vector<double>(16 * 16, 0.25));
  const int steps = 100;
  f.advance(steps);
  const Stencil st = named_stencil("nine_point_half");
  const auto w = leapfrog_weights<double>(st.centre, st.orth, st.diag, o.courant(), o.damping_per_s * o.dt_s);
  const double size = std::abs(w.centre) + 4 * std::abs(w.orth) + 4 * std::abs(w.diag) + std::abs(w.previous);
  const double u = 0x1p-53, gamma11 = 11 * u / (1 - 11 * u);
  const double bound = steps * gamma11 * size * 0.25 / (1 - w.previous);
  BOOST_TEST(bound < 1e-12);  // the bound itself is tight enough to mean something
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) BOOST_TEST(std::abs(f.height(i, j) - 0.25) <= bound);
}

BOOST_AUTO_TEST_CASE(surface_adapter_interpolates_bilinear_fields_exactly) {
  // Oracle: bilinear interpolation reproduces z = 1 + 2x − 3y + 0.5xy exactly between cell points,
  // and a periodic field repeats with period n d.
  auto o = options_for("five_point", Boundary::periodic, 8, 0.5);
  HeightField f(o);
  auto g = [](double x, double y) { return 1 + 2 * x - 3 * y + 0.5 * x * y; };
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) f.set_height(i, j, g(i * o.cell_m, j * o.cell_m));
  HeightFieldSurface surface(f, 10.0, -2.0);
  const double x = 0.33, y = 0.61;  // inside [0, 7d]
  BOOST_TEST(std::abs(surface.height_m(x + 10.0, y - 2.0) - g(x, y)) <= 1e-14);
  BOOST_TEST(std::abs(surface.height_m(x + 10.0 + 1.0, y - 2.0 - 3.0) - g(x, y)) <= 1e-13);
}

// The largest error of the level a stone reads between water steps (HeightFieldSurface at
// θ = 0.1 … 0.9 of each step over one wave period), against the exact mode's smooth continuation
// cos(θ t/Δt) z0 (the recurrence above, z_n = cos(nθ) z0, read between its steps).
double level_between_steps_error(LevelInTime in_time, double sigma) {
  const int n = 16;
  HeightField f(options_for("five_point", Boundary::periodic, n, sigma));
  std::vector<double> z0(n * n);
  const double a = 2 * M_PI / n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) z0[j * n + i] = std::cos(a * i);
  f.set_state(z0);
  const double theta = std::acos(1 + sigma * sigma * named_stencil("five_point").symbol(a, 0) / 2);
  const double dt = f.options().dt_s;
  HeightFieldSurface surface(f, 0, 0, in_time);
  double worst = 0;
  const long steps = std::lround(2 * M_PI / theta);  // one period of the mode
  for (long k = 0; k < steps; ++k, f.step())
    for (double phi : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      surface.set_time((k + phi) * dt);
      worst = std::max(worst, std::abs(surface.height_m(0, 0) - std::cos((k + phi) * theta)));  // at cell (0, 0): z0 = 1
    }
  return worst;
}

BOOST_AUTO_TEST_CASE(level_between_steps_is_first_order_held_and_second_order_extrapolated) {
  // Oracle: the exact mode above. Held over a step, the level is off by up to ω Δt (first order);
  // the line through the last two levels by θ(1 + θ) (ω Δt)²/2 (second order: model/water/
  // height_field_surface.hpp). Observed orders from Δt and Δt/2 (σ = 0.2, 0.1: ω Δt = 0.078 and
  // 0.039); tolerance 0.15 on the order: the next term of each error's expansion is O(ω Δt), under
  // 10 % of the leading one here, which moves a log2 ratio by less than 0.15.
  const double held = std::log2(level_between_steps_error(LevelInTime::held, 0.2) / level_between_steps_error(LevelInTime::held, 0.1));
  const double extrapolated = std::log2(level_between_steps_error(LevelInTime::extrapolated, 0.2) /
                                        level_between_steps_error(LevelInTime::extrapolated, 0.1));
  BOOST_TEST_MESSAGE("observed orders: held " << held << ", extrapolated " << extrapolated);
  BOOST_TEST(std::abs(held - 1) <= 0.15);
  BOOST_TEST(std::abs(extrapolated - 2) <= 0.15);
  // And the size: at ω Δt = 0.039 the held level is off by about 0.9 ω Δt, the extrapolated one
  // by about 0.9 · 1.9 (ω Δt)²/2 (within 10 %, the next term).
  const double w_dt = std::acos(1 + 0.01 * named_stencil("five_point").symbol(2 * M_PI / 16, 0) / 2);
  BOOST_TEST(std::abs(level_between_steps_error(LevelInTime::held, 0.1) / (0.9 * w_dt) - 1) <= 0.1);
  BOOST_TEST(std::abs(level_between_steps_error(LevelInTime::extrapolated, 0.1) / (0.9 * 1.9 * w_dt * w_dt / 2) - 1) <= 0.1);
}

BOOST_AUTO_TEST_CASE(gaussian_disturbance_peaks_at_its_centre_with_its_amplitude) {
  // Oracle: A exp(0) at the centre cell; the periodic images add A·exp(−(L/w)²) ≈ 1e-43, nothing.
  Disturbance d;
  d.amplitude_m = 0.02;
  d.width_m = 0.1;
  d.x_m = 0.5;
  d.y_m = 0.25;
  std::vector<double> z;
  sample_disturbance(d, 32, 32, 1.0 / 32, z);
  BOOST_TEST(std::abs(z[8 * 32 + 16] - 0.02) <= 1e-16);
  BOOST_TEST(*std::max_element(z.begin(), z.end()) == z[8 * 32 + 16]);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
