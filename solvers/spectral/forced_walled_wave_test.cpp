// The forced walled reference (solvers/spectral/forced_walled_wave.hpp). Oracles:
//  * the periodic forced reference (ForcedSpectralWave: complex FFTs, another code path) on the
//    even (reflecting) or odd (fixed) extension of the field and of the draught;
//  * the forced leapfrog (model/water/height_field.hpp, step(DraughtPatch)) with the same walls:
//    its difference from the stencil-symbol reference is its time error alone, O(Δt²), also while
//    the draught runs into a wall — where the leapfrog's ghost cells mirror b (reflecting) or hold 0
//    (fixed), as the reference's extension does.
#include "solvers/spectral/forced_walled_wave.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/water/draught_patch.hpp"
#include "model/water/height_field.hpp"
#include "solvers/spectral/forced_wave.hpp"
#include "solvers/spectral/walled_extension_test_support.hpp"

namespace stoneskip {
namespace {

// A 5 mm Gaussian draught (e-folding 3 cells) on the points x = i d, y = j d, starting smoothly
// (MovingGaussianDraught's envelope) at (0.35, 0.3) m and running at (−0.5, 0.1) m/s: toward the wall at
// x = 0, which it reaches at about 0.7 s and runs into.
struct RunningDraught {
  int nx = 0, ny = 0;
  double d = 0;
  void operator()(double t, std::vector<double>& b) const {
    MovingGaussianDraught shape;
    shape.rise_s = 0.1;
    const double e = shape.envelope(t), xc = 0.35 - 0.5 * t, yc = 0.3 + 0.1 * t, w = 3 * d;
    b.assign(static_cast<std::size_t>(nx) * ny, 0.0);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double u = (i * d - xc) / w, v = (j * d - yc) / w;
        b[static_cast<std::size_t>(j) * nx + i] = 0.005 * e * std::exp(-u * u - v * v);
      }
  }
};

WalledWaveOptions pond(Boundary b, int nx, int ny, double d) {
  WalledWaveOptions o;
  o.nx = nx;
  o.ny = ny;
  o.cell_m = d;
  o.wave_speed_m_s = 0.8;
  o.damping_per_s = 0.3;
  o.boundary = b;
  o.stencil = named_stencil("nine_point_isotropic");
  return o;
}


using test::extended;

}  // namespace

BOOST_AUTO_TEST_SUITE(forced_walled_wave_)

BOOST_AUTO_TEST_CASE(the_forced_walled_pond_is_the_periodic_forced_reference_on_its_extension) {
  // The same quadrature nodes on both sides, so the two integrals are the same sums mode for mode:
  // agreement to round-off (1e-12 of the 5 mm draught's response), both symbols, both walls, at a
  // time when the draught has run into the wall at x = 0.
  const int nx = 20, ny = 14;
  const double d = 0.04;
  const DuhamelQuadrature q{8, 6};
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed})
    for (const SpectralSymbol symbol : {SpectralSymbol::continuum, SpectralSymbol::stencil}) {
      WalledWaveOptions o = pond(b, nx, ny, d);
      o.symbol = symbol;
      const RunningDraught draught{nx, ny, d};
      ForcedWalledWave w(o, draught, q);
      std::vector<double> z, ez;
      w.evaluate(0.9, z);
      int px = 0, py = 0;
      extended(b, z, nx, ny, px, py);  // the periodic grid's size
      SpectralWaveOptions so;
      so.nx = px;
      so.ny = py;
      so.cell_m = d;
      so.wave_speed_m_s = o.wave_speed_m_s;
      so.damping_per_s = o.damping_per_s;
      so.symbol = symbol;
      so.stencil = o.stencil;
      ForcedSpectralWave periodic(
          so,
          [&](double t, std::vector<double>& eb) {
            std::vector<double> wb;
            draught(t, wb);
            int ex = 0, ey = 0;
            eb = extended(b, wb, nx, ny, ex, ey);
          },
          q);
      periodic.evaluate(0.9, ez);
      double worst = 0, scale = 0;
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          worst = std::max(worst, std::abs(z[j * nx + i] - ez[static_cast<std::size_t>(j) * px + i]));
          scale = std::max(scale, std::abs(ez[static_cast<std::size_t>(j) * px + i]));
        }
      BOOST_TEST(scale > 1e-4);  // the draught has made waves of a millimetre or more
      BOOST_TEST(worst <= 1e-12 * scale, to_string(b) << ": " << worst << " of " << scale);
      BOOST_TEST(w.draught_transforms() == 8 * 6);
    }
}

BOOST_AUTO_TEST_CASE(the_forced_leapfrogs_walls_are_the_forced_references_walls) {
  // The forced leapfrog on a walled 30 × 24 pond, b given at each step's start, to t = 1 s (the
  // draught at the wall x = 0 from about 0.7 s), against the stencil-symbol forced reference: its
  // time error, O(Δt²). As in walled_wave_test.cpp: from σ = 0.4, four halvings of Δt, the
  // observed order closing in on 2 at each and within 0.02 of it at the last. A forcing that treated
  // the draught at the wall otherwise than the reference's extension (b not mirrored, or mirrored
  // into a fixed rim) would leave a difference that does not fall with Δt. The reference's own
  // quadrature error (32 × 8 nodes) is far below the smallest difference measured (checked below).
  const int nx = 30, ny = 24;
  const double d = 0.04, t_end = 1.0;
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed}) {
    WalledWaveOptions o = pond(b, nx, ny, d);
    o.symbol = SpectralSymbol::stencil;
    const RunningDraught draught{nx, ny, d};
    ForcedWalledWave ref(o, draught, DuhamelQuadrature{32, 8});
    ForcedWalledWave finer(o, draught, DuhamelQuadrature{64, 8});
    std::vector<double> zr, zr2, z;
    ref.evaluate(t_end, zr);
    finer.evaluate(t_end, zr2);
    double quadrature = 0;
    for (std::size_t k = 0; k < zr.size(); ++k) quadrature = std::max(quadrature, std::abs(zr[k] - zr2[k]));
    std::vector<double> errors;
    for (const int steps : {50, 100, 200, 400, 800}) {  // σ = 0.8 · (1 s/steps) / 0.04 m = 0.4 … 0.025
      HeightFieldOptions h;
      h.nx = nx;
      h.ny = ny;
      h.cell_m = d;
      h.wave_speed_m_s = o.wave_speed_m_s;
      h.damping_per_s = o.damping_per_s;
      h.dt_s = t_end / steps;
      h.stencil = o.stencil;
      h.boundary = b;
      HeightField f(h);
      f.set_state(std::vector<double>(static_cast<std::size_t>(nx) * ny, 0.0));
      DraughtPatch patch;
      for (int k = 0; k < steps; ++k) {
        patch.reset(0, 0, nx, ny);
        draught(k * h.dt_s, patch.b_m);  // b at the start of the step (model/README.md §2.4)
        f.step(patch);
      }
      f.heights(z);
      double worst = 0;
      for (std::size_t k = 0; k < z.size(); ++k) worst = std::max(worst, std::abs(z[k] - zr[k]));
      errors.push_back(worst);
    }
    BOOST_TEST(quadrature <= 1e-3 * errors.back(), to_string(b) << ": quadrature " << quadrature);
    double last_gap = INFINITY;
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double order = std::log2(errors[k - 1] / errors[k]), gap = std::abs(order - 2);
      BOOST_TEST_MESSAGE(to_string(b) << " " << errors[k - 1] << " -> " << errors[k] << " order " << order);
      BOOST_TEST(gap <= last_gap + 1e-3, to_string(b) << ": errors " << errors[k - 1] << " → " << errors[k] << ", order " << order);
      last_gap = gap;
    }
    BOOST_TEST(last_gap <= 0.02, to_string(b) << ": the last order is 2 ± " << last_gap);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace stoneskip
