#include "solvers/spectral/spectral_wave.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>
#include <functional>

#include "solvers/spectral/damped_mode.hpp"

namespace stoneskip {
namespace {

// Near round-off: the FFT round trip of an O(1) field on 32² points costs ~log2(1024)·ulp per
// value, and the closed forms are evaluated by a different route (complex roots); 1e-12 allows
// a few hundred ulps.
constexpr double kNearRoundoff = 1e-12;

// Independent closed form by the characteristic roots r1,2 = −μ/2 ± √(μ²/4 − λ) (complex when
// underdamped): z = A e^{r1 t} + B e^{r2 t} with A + B = z0, r1 A + r2 B = v0. Distinct roots only.
double by_roots(double lambda, double mu, double z0, double v0, double t) {
  using C = std::complex<double>;
  C disc = std::sqrt(C(0.25 * mu * mu - lambda, 0));
  C r1 = -0.5 * mu + disc, r2 = -0.5 * mu - disc;
  C B = (v0 - r1 * z0) / (r2 - r1), A = z0 - B;
  return (A * std::exp(r1 * t) + B * std::exp(r2 * t)).real();
}
// Critical damping (λ = μ²/4): z = (z0 + (v0 + μ z0/2) t) e^{−μt/2}.
double critical(double mu, double z0, double v0, double t) { return (z0 + (v0 + 0.5 * mu * z0) * t) * std::exp(-0.5 * mu * t); }

// Runs the spectral reference on the single grid mode cos(2π(m x + n y)/L) with z0 = a, v0 = b
// times the mode, and returns the largest difference from `exact(t)` times the mode.
double single_mode_error(double mu, int m, int n, double a, double b, double t, const std::function<double(double)>& exact) {
  const int N = 32;
  SpectralWaveOptions o;
  o.nx = o.ny = N;
  o.cell_m = 1.0 / N;
  o.wave_speed_m_s = 1;
  o.damping_per_s = mu;
  SpectralWave w(o);
  std::vector<double> z0(N * N), v0(N * N), z;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      double mode = std::cos(2 * M_PI * (m * i + n * j) / N);
      z0[j * N + i] = a * mode;
      v0[j * N + i] = b * mode;
    }
  w.set_initial(z0, v0);
  w.evaluate(t, z);
  const double zt = exact(t);
  double worst = 0;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i)
      worst = std::max(worst, std::abs(z[j * N + i] - zt * std::cos(2 * M_PI * (m * i + n * j) / N)));
  return worst;
}

BOOST_AUTO_TEST_SUITE(spectral_wave_)

BOOST_AUTO_TEST_CASE(underdamped_mode_matches_the_closed_form) {
  // Oracle: by_roots with complex roots; λ = (2π)²·5 ≈ 197, μ = 1 (D > 0).
  const double lambda = 4 * M_PI * M_PI * 5, mu = 1;
  for (double t : {0.1, 0.77, 3.0})
    BOOST_TEST(single_mode_error(mu, 2, 1, 0.7, -0.3, t, [&](double tt) { return by_roots(lambda, mu, 0.7, -0.3, tt); }) <= kNearRoundoff);
}

BOOST_AUTO_TEST_CASE(overdamped_mode_matches_the_closed_form) {
  // Oracle: by_roots with real roots; μ = 3√λ (D < 0), including a long time (no overflow).
  const double lambda = 4 * M_PI * M_PI * 5, mu = 3 * std::sqrt(lambda);
  const auto exact = [&](double tt) { return by_roots(lambda, mu, 0.7, -0.3, tt); };
  for (double t : {0.01, 0.5}) BOOST_TEST(single_mode_error(mu, 2, 1, 0.7, -0.3, t, exact) <= kNearRoundoff);
  // At t = 40 the mode is e^{r t} ≈ 5e-104 (r ≈ −5.9): an absolute tolerance would pass a zero, and
  // the grid's FFT round trip leaves ~1e-17 in the mean mode, which does not decay. So the mode's own
  // exact factors, relatively: both sides' slow root r = −μ/2 + √(μ²/4 − λ) carries a rounding of
  // about ε μ/|r|, which the exponent r t multiplies to ~1e-12; 1e-10 of the value.
  const DampedModeFactors f = damped_mode(lambda, mu, 40.0);
  BOOST_TEST(std::abs(0.7 * f.gz - 0.3 * f.gv - exact(40.0)) <= 1e-10 * std::abs(exact(40.0)));
}

BOOST_AUTO_TEST_CASE(critically_damped_mode_matches_the_closed_form) {
  // Oracle: the critical form; μ = 2√λ so D is zero up to round-off of λ (the series branch).
  const double lambda = 4 * M_PI * M_PI * 5, mu = 2 * std::sqrt(lambda);
  for (double t : {0.01, 0.3, 2.0})
    BOOST_TEST(single_mode_error(mu, 2, 1, 0.7, -0.3, t, [&](double tt) { return critical(mu, 0.7, -0.3, tt); }) <= kNearRoundoff);
}

BOOST_AUTO_TEST_CASE(nearly_critical_modes_are_continuous_across_the_series_switch) {
  // Oracle: by_roots is well conditioned for D = ±1e-3 λ away from critical; the series
  // (|D t²| < 0.5) and the trigonometric/hyperbolic branches must both agree with it.
  const double lambda = 50;
  for (double rel : {-1e-3, 1e-3})
    for (double t : {0.05, 5.0, 30.0}) {
      const double mu = 2 * std::sqrt(lambda * (1 - rel));  // D = rel·λ
      DampedModeFactors f = damped_mode(lambda, mu, t);
      const double z = 0.7 * f.gz - 0.3 * f.gv, ref = by_roots(lambda, mu, 0.7, -0.3, t);
      // Relative: at t = 30 the mode is e^{−μt/2} ≈ 1e-92, which an absolute 1e-10 would let a zero
      // pass. by_roots loses about μ/|r1 − r2| ≈ 60 ulps, the exponent μt/2 ≈ 212 times ε more.
      BOOST_TEST(std::abs(z - ref) <= 1e-10 * std::abs(ref), "t " << t << ": " << z << " vs " << ref);
    }
}

BOOST_AUTO_TEST_CASE(mean_mode_matches_the_closed_form) {
  // Oracle: k = 0: z = z0 + v0 (1 − e^{−μt})/μ, and z0 + v0 t when μ = 0.
  BOOST_TEST(single_mode_error(2.0, 0, 0, 0.4, 0.5, 1.3, [](double t) { return 0.4 + 0.5 * (1 - std::exp(-2 * t)) / 2; }) <= kNearRoundoff);
  BOOST_TEST(single_mode_error(0.0, 0, 0, 0.4, 0.5, 1.3, [](double t) { return 0.4 + 0.5 * t; }) <= kNearRoundoff);
}

BOOST_AUTO_TEST_CASE(nyquist_mode_matches_the_closed_form) {
  // Oracle: by_roots for the checkerboard mode (m = n = N/2), the mode that limits stability.
  const double lambda = 2 * std::pow(M_PI * 32, 2), mu = 1;
  BOOST_TEST(single_mode_error(mu, 16, 16, 1.0, 0.0, 0.013, [&](double tt) { return by_roots(lambda, mu, 1.0, 0.0, tt); }) <= kNearRoundoff);
}

BOOST_AUTO_TEST_CASE(stencil_symbol_gives_the_semi_discrete_mode_frequency) {
  // Oracle: by_roots with λ = −c² symbol(a, b)/d² of the five-point stencil (its exact eigenvalue
  // on the grid mode), i.e. the exact solution of the method-of-lines system.
  const int N = 32;
  SpectralWaveOptions o;
  o.nx = o.ny = N;
  o.cell_m = 1.0 / N;
  o.damping_per_s = 0.5;
  o.symbol = SpectralSymbol::stencil;
  o.stencil = named_stencil("five_point");
  SpectralWave w(o);
  const double a = 2 * M_PI * 5 / N, b = 2 * M_PI * 3 / N;
  const double lambda = -o.stencil.symbol(a, b) * N * N;
  BOOST_TEST(std::abs(w.lambda(5, 3) - lambda) <= 1e-12 * lambda);
  std::vector<double> z0(N * N), z;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) z0[j * N + i] = std::cos(a * i + b * j);
  w.set_initial(z0);
  w.evaluate(0.9, z);
  const double zt = by_roots(lambda, 0.5, 1, 0, 0.9);
  double worst = 0;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) worst = std::max(worst, std::abs(z[j * N + i] - zt * z0[j * N + i]));
  BOOST_TEST(worst <= kNearRoundoff);
}

BOOST_AUTO_TEST_CASE(a_uniform_field_stays_uniform_under_every_named_stencils_symbol) {
  // Oracle: a uniform field at rest is a stationary solution of the damped wave equation and of
  // every consistent stencil (the coefficients sum to 0; paper_eq11's sum to −1/3, so it is not
  // one of them): its mean mode has λ = 0 exactly.
  // nine_point_isotropic's symbol(0, 0) evaluates to +1.1e-16; read as λ < 0 it grew as
  // cosh(√1.1e-16 · ct/d): 28 m on a 314 m field at ct/d = 4e7 (the time checked here).
  for (const char* name : {"five_point", "nine_point_half", "nine_point_isotropic"}) {
    const int N = 8;
    SpectralWaveOptions o;
    o.nx = o.ny = N;
    o.cell_m = 0.025;
    o.symbol = SpectralSymbol::stencil;
    o.stencil = named_stencil(name);
    SpectralWave w(o);
    BOOST_TEST(w.lambda(0, 0) == 0.0, name);
    std::vector<double> z0(N * N, 314.159), z;
    w.set_initial(z0);
    w.evaluate(1e6, z);
    double worst = 0;
    for (double v : z) worst = std::max(worst, std::abs(v - 314.159));
    BOOST_TEST(worst <= kNearRoundoff * 314.159, name << ": " << worst);
  }
}

BOOST_AUTO_TEST_CASE(a_slow_overdamped_mode_keeps_its_decay) {
  // Oracle: the slow root r = −μ/2 + √(μ²/4 − λ) by its series in ε = λ/μ² (independent of the
  // code's closed form): r = −μ(ε + ε² + 2ε³ + 5ε⁴ + …) (Catalan numbers); from z0 = 1 at rest the
  // fast mode is gone by t = 1e-3 (e^{−1e3}), leaving z = (μ + r)/(μ + 2r) e^{rt}. With λ = 1.5e-7,
  // μ = 1e6, t = 1e6 the decay is 1 − 1.5e-7: computing a − μ/2 as a difference lost all of it.
  const double lambda = 1.5e-7, mu = 1e6, t = 1e6;
  const double e = lambda / (mu * mu);
  const double r = -mu * (e + e * e + 2 * e * e * e);
  const double exact = (mu + r) / (mu + 2 * r) * std::exp(r * t);
  const DampedModeFactors f = damped_mode(lambda, mu, t);
  BOOST_TEST(std::abs(f.gz - exact) <= 1e-15, f.gz << " against " << exact);
  BOOST_TEST(1 - f.gz > 1e-7);  // the decay is there at all
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
