// Oracle: an independent computation, the image sums taken directly over 61 × 61 images (every
// image left out is then more than 29 periods away, e^-(29/3)² ≈ 5e-41 even for the widest bump
// here), against the sampled field, which sums only the images that reach the grid (a Gaussian
// as a product of two 1-D sums, a wide one by Poisson summation). Tolerance 1e-13 of the peak
// sum: round-off of a few dozen terms.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "model/water/disturbance.hpp"

using namespace stoneskip;

namespace {

double brute(const Disturbance& d, double x, double y, double lx, double ly) {
  double s = 0;
  for (int q = -30; q <= 30; ++q)
    for (int p = -30; p <= 30; ++p) {
      const double dx = x - d.x_m + p * lx, dy = y - d.y_m + q * ly;
      const double r = std::sqrt(dx * dx + dy * dy);
      const double u = d.kind == DisturbanceKind::gaussian ? r / d.width_m : (r - d.radius_m) / d.width_m;
      s += std::exp(-u * u);
    }
  return d.amplitude_m * s;
}

// The largest gap between samples z at the points (x0 + i cell, y0 + j cell) and the brute sum on
// the own grid of lx × ly, relative to the sum's peak there.
double gap_to_brute(const std::vector<double>& z, const Disturbance& d, double lx, double ly, double x0, double y0, int nx, int ny,
                    double cell) {
  double gap = 0, peak = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double b = brute(d, x0 + i * cell, y0 + j * cell, lx, ly);
      gap = std::max(gap, std::abs(z[static_cast<std::size_t>(j) * nx + i] - b));
      peak = std::max(peak, std::abs(b));
    }
  return gap / peak;
}

double worst_gap(const Disturbance& d, int nx, int ny, double cell) {
  std::vector<double> z;
  sample_disturbance(d, nx, ny, cell, z);
  return gap_to_brute(z, d, nx * cell, ny * cell, 0, 0, nx, ny, cell);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(disturbance)

BOOST_AUTO_TEST_CASE(a_gaussian_is_its_whole_periodic_image_sum_at_any_width_and_centre) {
  // 3 × 3 images only: a Gaussian half as wide as its 1 m × 0.75 m grid missed images of 2 % of
  // its peak (a seam), and one centred off the grid (x_m = −0.9 m) missed the image nearest to
  // the grid's far edge.
  Disturbance d;
  d.kind = DisturbanceKind::gaussian;
  d.amplitude_m = 0.01;
  for (double width : {0.05, 0.5, 0.6, 3.0})
    for (double x0 : {0.3, -0.9, 2.7}) {
      d.width_m = width;
      d.x_m = x0;
      d.y_m = 0.2;
      BOOST_TEST(worst_gap(d, 20, 15, 0.05) < 1e-13, "width " << width << ", x " << x0);
    }
}

BOOST_AUTO_TEST_CASE(a_ring_is_its_whole_periodic_image_sum_within_its_reach) {
  Disturbance d;
  d.kind = DisturbanceKind::ring;
  d.amplitude_m = 0.01;
  d.width_m = 0.08;
  for (double radius : {0.2, 0.9, 1.7})
    for (double x0 : {0.4, -0.6}) {
      d.radius_m = radius;
      d.x_m = x0;
      d.y_m = 0.35;
      BOOST_TEST(disturbance_image_problem(d, 1.0, 0.75, 1e3) == "");
      BOOST_TEST(worst_gap(d, 20, 15, 0.05) < 1e-13, "radius " << radius << ", x " << x0);
    }
}

BOOST_AUTO_TEST_CASE(a_ring_reaching_past_its_image_limit_is_named) {
  // radius + 6.5 width = 2.52 m on a 0.75 m side: ⌈2.52/0.75⌉ + 1 = 5 images each side, past 4.
  Disturbance d;
  d.kind = DisturbanceKind::ring;
  d.radius_m = 2.0;
  d.width_m = 0.08;
  BOOST_TEST(disturbance_image_problem(d, 1.0, 0.75, 1e3).find("reaches past 3 periods") != std::string::npos);
  BOOST_TEST(disturbance_image_problem(d, 1.0, 1.0, 1e3) == "");  // ⌈2.52⌉ + 1 = 4: within
  // A Gaussian's sum is exact at any width, but it peaks near A π w² / (Lx Ly): 0.01 π 1e6 / 0.75
  // = 4.19e4 m for w = 1e3 m, above a 1e3 m bound; w = 100 m gives 419 m, below it.
  d.kind = DisturbanceKind::gaussian;
  d.amplitude_m = 0.01;
  d.width_m = 1e3;
  BOOST_TEST(disturbance_image_problem(d, 1.0, 0.75, 1e3).find("41887.9") != std::string::npos,
             disturbance_image_problem(d, 1.0, 0.75, 1e3));
  d.width_m = 100;
  BOOST_TEST(disturbance_image_problem(d, 1.0, 0.75, 1e3) == "");
  // At the bound itself: A = 1000 m a fifth of the grid wide, whose images add 3e-11 of it.
  d.amplitude_m = 1e3;
  d.width_m = 0.2;
  BOOST_TEST(disturbance_image_problem(d, 1.0, 1.0, 1e3) == "");
}

BOOST_AUTO_TEST_CASE(another_grid_samples_the_same_surface_at_its_own_points) {
  // Oracle: the same brute-force image sum (61 × 61 images, the own grid's period) read at the
  // other grid's points, x0 + i d′: a finer grid, shifted by a non-whole number of cells and
  // reaching past the own grid's edge (there the surface is the own grid's periodic function); for
  // a plane wave, A cos(k·x) at the point. Tolerance 1e-13 of the peak, as above.
  const double lx = 20 * 0.05, ly = 15 * 0.05, x0 = -0.137, y0 = 0.2113, cell = 0.0173;
  const int nx = 71, ny = 40;  // reaches x ∈ [−0.137, 1.074], past the own grid's 1 m
  Disturbance g;
  g.kind = DisturbanceKind::gaussian;
  g.amplitude_m = 0.01;
  g.width_m = 0.12;
  g.x_m = 0.93;  // near the own grid's edge: its image across the edge is on the other grid
  g.y_m = 0.4;
  Disturbance r = g;
  r.kind = DisturbanceKind::ring;
  r.radius_m = 0.3;
  r.width_m = 0.05;
  for (const Disturbance& d : {g, r}) {
    std::vector<double> z;
    sample_disturbance_at(d, lx, ly, x0, y0, nx, ny, cell, z);
    BOOST_TEST(gap_to_brute(z, d, lx, ly, x0, y0, nx, ny, cell) < 1e-13, to_string(d.kind));
  }
  Disturbance w;
  w.kind = DisturbanceKind::plane_wave;
  w.amplitude_m = 0.02;
  w.wavelength_m = 0.37;
  w.angle_deg = 23;
  std::vector<double> z;
  sample_disturbance_at(w, lx, ly, x0, y0, nx, ny, cell, z);
  const double k = 2 * M_PI / w.wavelength_m, th = w.angle_deg * M_PI / 180;
  double gap = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = x0 + i * cell, y = y0 + j * cell;
      gap = std::max(gap, std::abs(z[static_cast<std::size_t>(j) * nx + i] - w.amplitude_m * std::cos(k * (x * std::cos(th) + y * std::sin(th)))));
    }
  BOOST_TEST(gap / w.amplitude_m < 1e-13);
}

BOOST_AUTO_TEST_CASE(on_its_own_grid_the_resampled_surface_is_the_sampled_one_bit_for_bit) {
  // Oracle: sample_disturbance, which every scene and wave case uses: a scene's initial surface
  // must not move when the grid section learns to resample it.
  Disturbance d;
  d.amplitude_m = 0.013;
  d.x_m = 0.71;
  d.y_m = 0.05;
  d.width_m = 0.09;
  d.radius_m = 0.25;
  d.wavelength_m = 0.31;
  d.angle_deg = 17;
  for (auto kind : {DisturbanceKind::gaussian, DisturbanceKind::ring, DisturbanceKind::plane_wave}) {
    d.kind = kind;
    std::vector<double> a, b;
    sample_disturbance(d, 37, 29, 0.031, a);
    sample_disturbance_at(d, 37 * 0.031, 29 * 0.031, 0.0, 0.0, 37, 29, 0.031, b);
    BOOST_TEST((a == b), to_string(kind));
  }
  // An impulse is one cell's height: refused, by name.
  d.kind = DisturbanceKind::impulse;
  BOOST_TEST(resample_problem(d).find("impulse") != std::string::npos);
  std::vector<double> z;
  BOOST_CHECK_THROW(sample_disturbance_at(d, 1.0, 1.0, 0.0, 0.0, 10, 10, 0.1, z), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
