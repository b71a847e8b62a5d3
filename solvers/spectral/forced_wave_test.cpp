#include "solvers/spectral/forced_wave.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>

#include "solvers/spectral/gauss_legendre.hpp"

namespace stoneskip {
namespace {

// Independent closed form of ẑ'' + μ ẑ' + λ ẑ = F e^{βt}, ẑ(0) = ẑ'(0) = 0, by the residues of
// its Laplace transform F / ((p − β)(p − r1)(p − r2)), r1,2 = −μ/2 ± √(μ²/4 − λ) (distinct, ≠ β):
//   ẑ(t) = F [e^{βt}/((β − r1)(β − r2)) + e^{r1 t}/((r1 − β)(r1 − r2)) + e^{r2 t}/((r2 − β)(r2 − r1))].
std::complex<double> forced_mode(double lambda, double mu, std::complex<double> F, std::complex<double> beta, double t) {
  using C = std::complex<double>;
  const C disc = std::sqrt(C(0.25 * mu * mu - lambda, 0));
  const C r1 = -0.5 * mu + disc, r2 = -0.5 * mu - disc;
  return F * (std::exp(beta * t) / ((beta - r1) * (beta - r2)) + std::exp(r1 * t) / ((r1 - beta) * (r1 - r2)) +
              std::exp(r2 * t) / ((r2 - beta) * (r2 - r1)));
}

BOOST_AUTO_TEST_SUITE(forced_wave_)

BOOST_AUTO_TEST_CASE(gauss_legendre_integrates_polynomials_of_degree_2n_minus_1_exactly) {
  // Oracle: ∫_{−1}^{1} x^k dx = 2/(k + 1) for even k, 0 for odd k, k ≤ 2n − 1; round-off 1e-14.
  for (int n : {1, 2, 5, 8, 12}) {
    const GaussLegendreRule r = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double s = 0;
      for (int q = 0; q < n; ++q) s += r.weights[q] * std::pow(r.nodes[q], k);
      BOOST_TEST(std::abs(s - (k % 2 ? 0.0 : 2.0 / (k + 1))) <= 1e-14, "n " << n << " k " << k);
    }
  }
}

BOOST_AUTO_TEST_CASE(duhamel_quadrature_converges_to_round_off_for_a_single_forced_mode) {
  // Oracle: b = B cos(2π(2x + y)) sin(ωt) on a periodic unit square, z(0) = z'(0) = 0: one Fourier
  // mode forced by −λ B sin ωt = Im(−λ B e^{iωt}), whose exact response is forced_mode (residues,
  // an independent route). The quadrature error must fall as the sub-intervals are refined and
  // end at round-off: 1e-12 of the response (the terms summed, λB·G ~ 0.1 m, exceed the 0.013 m
  // response, and both routes sum ~100 of them; 1e-12 is a few hundred ulps of those terms).
  const int N = 16;
  const double B = 0.01, omega = 9.0, mu = 0.8, t = 1.7;
  SpectralWaveOptions o;
  o.nx = o.ny = N;
  o.cell_m = 1.0 / N;
  o.wave_speed_m_s = 1;
  o.damping_per_s = mu;
  auto b = [&](double s, std::vector<double>& out) {
    out.resize(N * N);
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) out[j * N + i] = B * std::cos(2 * M_PI * (2 * i + j) / N) * std::sin(omega * s);
  };
  const double lambda = 4 * M_PI * M_PI * 5;
  const double amp = forced_mode(lambda, mu, -lambda * B, std::complex<double>(0, omega), t).imag();
  double previous = 1e300, last = 0;
  for (int intervals : {1, 2, 4, 8, 16}) {
    ForcedSpectralWave w(o, b, DuhamelQuadrature{intervals, 6});
    std::vector<double> z;
    w.evaluate(t, z);
    BOOST_TEST(w.draught_transforms() == intervals * 6);
    double err = 0;
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) err = std::max(err, std::abs(z[j * N + i] - amp * std::cos(2 * M_PI * (2 * i + j) / N)));
    BOOST_TEST_MESSAGE(intervals << " sub-intervals × 6 nodes: error " << err << " (response " << std::abs(amp) << ")");
    BOOST_TEST((err < previous || err <= 1e-12 * std::abs(amp)), intervals << ": " << err << " after " << previous);
    previous = err;
    last = err;
  }
  BOOST_TEST(last <= 1e-12 * std::abs(amp));
  BOOST_TEST(std::abs(amp) > 1e-3);  // a real response, not a vanishing one
}

BOOST_AUTO_TEST_CASE(forced_and_free_parts_add) {
  // Oracle: linearity — with a free initial state and a draught, the reference equals the free
  // reference plus the forced one from rest (same quadrature), to round-off.
  const int N = 16;
  SpectralWaveOptions o;
  o.nx = o.ny = N;
  o.cell_m = 1.0 / N;
  o.damping_per_s = 0.3;
  o.symbol = SpectralSymbol::stencil;
  o.stencil = named_stencil("nine_point_isotropic");
  MovingGaussianDraught g;
  std::vector<double> z0(N * N), zf, zb, zsum;
  for (int k = 0; k < N * N; ++k) z0[k] = 0.001 * std::sin(0.37 * k);
  ForcedSpectralWave both(o, g.on_grid(N, N, o.cell_m), {4, 6}), forced(o, g.on_grid(N, N, o.cell_m), {4, 6});
  both.set_initial(z0);
  SpectralWave free(o);
  free.set_initial(z0);
  both.evaluate(0.4, zb);
  forced.evaluate(0.4, zf);
  free.evaluate(0.4, zsum);
  double worst = 0;
  for (int k = 0; k < N * N; ++k) worst = std::max(worst, std::abs(zb[k] - (zf[k] + zsum[k])));
  BOOST_TEST(worst <= 1e-16);
}

BOOST_AUTO_TEST_CASE(moving_gaussian_is_smooth_periodic_and_starts_at_zero) {
  // Oracle: the definition — e(0) = 0, e(t) → 1; the peak at the moved centre, wrapped.
  MovingGaussianDraught g;
  g.x0_m = 0.9;
  g.y0_m = 0.5;
  g.vx_m_s = 0.5;
  g.vy_m_s = 0;
  std::vector<double> b;
  g.sample(0, 32, 32, 1.0 / 32, b);
  for (double v : b) BOOST_TEST(v == 0);
  g.sample(0.2, 32, 32, 1.0 / 32, b);  // centre at x = 1.0 ≡ 0: cell (0, 16)
  BOOST_TEST(std::abs(b[16 * 32 + 0] - g.depth_m * g.envelope(0.2)) <= 1e-17);  // images add e^{−100}
  BOOST_TEST(std::abs(g.envelope(2.0) - 1) <= 1e-15);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
