// The walled-pond reference (solvers/spectral/walled_wave.hpp). Oracles:
//  * the closed form of one damped mode (characteristic roots) on one cosine or sine grid mode;
//  * the periodic reference (SpectralWave, complex FFTs: another code path) on the field's even
//    (reflecting) or odd (fixed) extension to a grid of 2nx × 2ny or 2(nx + 1) × 2(ny + 1) points,
//    read back on the pond's points: the walled problem is that periodic one, mode for mode;
//  * the leapfrog itself (model/water/height_field.hpp), whose ghost cells must make the same
//    walls: its difference from the stencil-symbol reference is its time error alone, second order.
#include "solvers/spectral/walled_wave.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <complex>

#include "model/water/height_field.hpp"
#include "solvers/spectral/spectral_wave.hpp"
#include "solvers/spectral/walled_extension_test_support.hpp"

namespace stoneskip {
namespace {

// Near round-off: an O(1) field through two FFTs of 2-D arrays of ~10³ points, and the closed form
// by another route (complex roots): a few hundred ulps.
constexpr double kNearRoundoff = 1e-12;

// z = A e^{r1 t} + B e^{r2 t}, r1,2 = −μ/2 ± √(μ²/4 − λ), A + B = z0, r1 A + r2 B = v0 (distinct roots).
double by_roots(double lambda, double mu, double z0, double v0, double t) {
  using C = std::complex<double>;
  const C disc = std::sqrt(C(0.25 * mu * mu - lambda, 0));
  const C r1 = -0.5 * mu + disc, r2 = -0.5 * mu - disc;
  const C B = (v0 - r1 * z0) / (r2 - r1), A = z0 - B;
  return (A * std::exp(r1 * t) + B * std::exp(r2 * t)).real();
}

// Grid mode m along an axis of n points: cos(πm(i + ½)/n) between reflecting walls, sin(π(m + 1)(i + 1)/(n + 1))
// between fixed rims.
double grid_mode(Boundary b, int m, int i, int n) {
  return b == Boundary::reflecting ? std::cos(M_PI * m * (i + 0.5) / n) : std::sin(M_PI * (m + 1) * (i + 1.0) / (n + 1));
}

WalledWaveOptions pond(Boundary b, int nx, int ny) {
  WalledWaveOptions o;
  o.nx = nx;
  o.ny = ny;
  o.cell_m = 0.05;
  o.wave_speed_m_s = 0.8;
  o.damping_per_s = 0.3;
  o.boundary = b;
  o.stencil = named_stencil("nine_point_isotropic");
  return o;
}

// A Gaussian off the centre, 2 m·s⁻¹-scale initial velocity of another shape: both non-symmetric.
void fields(int nx, int ny, double d, std::vector<double>& z0, std::vector<double>& v0) {
  z0.assign(static_cast<std::size_t>(nx) * ny, 0);
  v0 = z0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = i * d, y = j * d;
      z0[j * nx + i] = 0.01 * std::exp(-(std::pow(x - 0.3, 2) + std::pow(y - 0.45, 2)) / 0.01);
      v0[j * nx + i] = 0.02 * std::exp(-(std::pow(x - 0.6, 2) + std::pow(y - 0.2, 2)) / 0.02);
    }
}


using test::extended;

}  // namespace

BOOST_AUTO_TEST_SUITE(walled_wave_)

BOOST_AUTO_TEST_CASE(one_grid_mode_follows_the_damped_modes_closed_form) {
  // Reflecting and fixed, several modes (the reflecting (0, 0) one is the level: λ = 0), under- and
  // overdamped (μ = 0.3 and 40 /s against ω ≈ 5–90 /s), the continuum symbol λ = c²|k|².
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed})
    for (const double mu : {0.3, 40.0})
      for (const auto& [m, n] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{3, 5}, std::pair{11, 2}}) {
        WalledWaveOptions o = pond(b, 16, 12);
        o.damping_per_s = mu;
        WalledWave w(o);
        const double kx = b == Boundary::reflecting ? M_PI * m / (16 * o.cell_m) : M_PI * (m + 1) / (17 * o.cell_m);
        const double ky = b == Boundary::reflecting ? M_PI * n / (12 * o.cell_m) : M_PI * (n + 1) / (13 * o.cell_m);
        const double lambda = 0.64 * (kx * kx + ky * ky);
        BOOST_TEST(std::abs(w.lambda(m, n) - lambda) <= 1e-12 * lambda, to_string(b) << " mode " << m << "," << n);
        std::vector<double> z0(16 * 12), v0(16 * 12), z;
        for (int j = 0; j < 12; ++j)
          for (int i = 0; i < 16; ++i) {
            const double mode = grid_mode(b, m, i, 16) * grid_mode(b, n, j, 12);
            z0[j * 16 + i] = 0.7 * mode;
            v0[j * 16 + i] = -1.3 * mode;
          }
        w.set_initial(z0, v0);
        for (const double t : {0.01, 0.37, 2.5}) {
          w.evaluate(t, z);
          const double zt = lambda == 0 ? 0.7 - 1.3 * (1 - std::exp(-mu * t)) / mu : by_roots(lambda, mu, 0.7, -1.3, t);
          double worst = 0;
          for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 16; ++i)
              worst = std::max(worst, std::abs(z[j * 16 + i] - zt * grid_mode(b, m, i, 16) * grid_mode(b, n, j, 12)));
          BOOST_TEST(worst <= kNearRoundoff, to_string(b) << " mu " << mu << " mode " << m << "," << n << " t " << t << ": " << worst);
        }
      }
}

BOOST_AUTO_TEST_CASE(the_walled_pond_is_the_periodic_reference_on_its_extension) {
  // Odd sizes too (the extension's period is then even but the pond's modes are not a power of 2),
  // both symbols: the continuum one and the stencil's own.
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed})
    for (const SpectralSymbol symbol : {SpectralSymbol::continuum, SpectralSymbol::stencil})
      for (const auto& [nx, ny] : {std::pair{24, 18}, std::pair{17, 9}}) {
        WalledWaveOptions o = pond(b, nx, ny);
        o.symbol = symbol;
        WalledWave w(o);
        std::vector<double> z0, v0, z;
        fields(nx, ny, o.cell_m, z0, v0);
        w.set_initial(z0, v0);
        int px = 0, py = 0;
        const std::vector<double> ez0 = extended(b, z0, nx, ny, px, py), ev0 = extended(b, v0, nx, ny, px, py);
        SpectralWaveOptions so;
        so.nx = px;
        so.ny = py;
        so.cell_m = o.cell_m;
        so.wave_speed_m_s = o.wave_speed_m_s;
        so.damping_per_s = o.damping_per_s;
        so.symbol = symbol;
        so.stencil = o.stencil;
        SpectralWave periodic(so);
        periodic.set_initial(ez0, ev0);
        std::vector<double> ez;
        for (const double t : {0.2, 1.7}) {
          w.evaluate(t, z);
          periodic.evaluate(t, ez);
          double worst = 0, scale = 0;
          for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
              worst = std::max(worst, std::abs(z[j * nx + i] - ez[static_cast<std::size_t>(j) * px + i]));
              scale = std::max(scale, std::abs(ez[static_cast<std::size_t>(j) * px + i]));
            }
          BOOST_TEST(scale > 1e-4);  // the comparison is of a field, not of zeros
          BOOST_TEST(worst <= kNearRoundoff * 0.01, to_string(b) << " " << nx << "x" << ny << " t " << t << ": " << worst);
        }
      }
}

BOOST_AUTO_TEST_CASE(the_leapfrogs_walls_are_the_references_walls) {
  // The leapfrog on a walled 40 × 30 pond against the stencil-symbol reference: what is left is the
  // time error, c₂Δt² + O(Δt⁴). From σ = 0.4, four halvings of Δt: the observed order must close in on
  // 2 at every halving (its distance from 2 shrinks, as the Δt⁴ term's share falls by 4 a halving)
  // and be within 0.02 of 2 at the last (σ = 0.05 → 0.025: 1/64 of the share at the first, where
  // measured it moved the order by 0.17). A ghost treatment that made other walls (a wall half a
  // cell off, a corner ghost not mirrored) would leave a difference that does not fall with Δt:
  // an order going to 0.
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed}) {
    const int nx = 40, ny = 30;
    WalledWaveOptions o = pond(b, nx, ny);
    o.symbol = SpectralSymbol::stencil;
    std::vector<double> z0, v0, z, zr;
    fields(nx, ny, o.cell_m, z0, v0);
    WalledWave w(o);
    w.set_initial(z0);  // from rest: HeightField's start from rest is second order (set_state)
    const double t_end = 1.0;
    w.evaluate(t_end, zr);
    std::vector<double> errors;
    for (const int steps : {40, 80, 160, 320, 640}) {  // σ = 0.8 · (1 s/steps) / 0.05 m = 0.4 … 0.025
      HeightFieldOptions h;
      h.nx = nx;
      h.ny = ny;
      h.cell_m = o.cell_m;
      h.wave_speed_m_s = o.wave_speed_m_s;
      h.damping_per_s = o.damping_per_s;
      h.dt_s = t_end / steps;
      h.stencil = o.stencil;
      h.boundary = b;
      HeightField f(h);
      f.set_state(z0);
      f.advance(steps);
      f.heights(z);
      double worst = 0;
      for (std::size_t k = 0; k < z.size(); ++k) worst = std::max(worst, std::abs(z[k] - zr[k]));
      errors.push_back(worst);
    }
    double last_gap = INFINITY;
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double order = std::log2(errors[k - 1] / errors[k]), gap = std::abs(order - 2);
      BOOST_TEST(gap <= last_gap + 1e-3, to_string(b) << ": errors " << errors[k - 1] << " → " << errors[k] << ", order " << order);
      last_gap = gap;
    }
    BOOST_TEST(last_gap <= 0.02, to_string(b) << ": the last order is 2 ± " << last_gap);
  }
}

BOOST_AUTO_TEST_CASE(the_short_wave_share_is_that_of_the_surfaces_rms) {
  // Oracle: two orthogonal grid modes, a low one (all of it in the lower half) and one past half the
  // modes along x: the share is the RMS of the second part over the RMS of the sum, computed on the
  // grid points. The level (0, 0) mode too, whose DCT weight differs.
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed})
    for (const auto& [low_m, low_n] : {std::pair{1, 1}, std::pair{0, 0}}) {
      if (b == Boundary::fixed && low_m == 0) continue;  // fixed: mode index 0 is already a sine
      const int nx = 16, ny = 12;
      std::vector<double> z0(nx * ny), high(nx * ny);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          high[j * nx + i] = -0.4 * grid_mode(b, 12, i, nx) * grid_mode(b, 1, j, ny);
          z0[j * nx + i] = 1.3 * grid_mode(b, low_m, i, nx) * grid_mode(b, low_n, j, ny) + high[j * nx + i];
        }
      auto rms = [](const std::vector<double>& f) {
        double s = 0;
        for (const double v : f) s += v * v;
        return std::sqrt(s / f.size());
      };
      WalledWave w(pond(b, nx, ny));
      w.set_initial(z0);
      BOOST_TEST(std::abs(w.upper_half_fraction() - rms(high) / rms(z0)) <= 1e-12, to_string(b) << " low " << low_m);
      w.set_initial(high);
      BOOST_TEST(std::abs(w.upper_half_fraction() - 1) <= 1e-12);
    }
}

BOOST_AUTO_TEST_CASE(a_periodic_grid_is_refused) {
  WalledWaveOptions o = pond(Boundary::periodic, 8, 8);
  BOOST_CHECK_THROW(WalledWave{o}, std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace stoneskip
