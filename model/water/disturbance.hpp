#pragma once
// Initial disturbances of a water surface, sampled at the cell points x_i = i d, y_j = j d
// (i < nx, j < ny) of a grid whose periodic copies tile the plane with period nx d × ny d.
// A Gaussian and a ring are summed over every periodic image that reaches the grid (each image
// left out is below e^-42 of the peak at every cell), so on a periodic grid they are smooth and
// periodic whatever their width and wherever their centre; on other boundaries the images are
// negligible when the bump is well inside the domain. A Gaussian's sum separates in x and y and
// is exact at any width (a wide one by Poisson summation); a ring's does not, and a ring reaching
// past kMostRingImages periods is refused (disturbance_image_problem).
#include <string>
#include <vector>

namespace stoneskip {

enum class DisturbanceKind { gaussian, plane_wave, ring, impulse };
const char* to_string(DisturbanceKind k);
bool parse_disturbance_kind(const std::string& s, DisturbanceKind& out);

struct Disturbance {
  DisturbanceKind kind = DisturbanceKind::gaussian;
  double amplitude_m = 0.01;
  double width_m = 0.1;        // gaussian: e-folding radius, z = A exp(−r²/w²); ring: half-width
  double x_m = 0, y_m = 0;     // centre (gaussian, ring, impulse)
  double radius_m = 0.2;       // ring: z = A exp(−(r − R)²/w²)
  double angle_deg = 0;        // plane_wave: direction of k from the x axis
  double wavelength_m = 0.25;  // plane_wave: z = A cos(k·x), |k| = 2π/λ
};

// Fills z (size nx·ny, row-major with x fastest) with the disturbance. The initial velocity of
// every kind is zero (a plane wave therefore starts as a standing wave).
void sample_disturbance(const Disturbance& d, int nx, int ny, double cell_m, std::vector<double>& z);

// The same surface on another grid: the surface `d` makes on its own grid (period lx_m × ly_m, the
// shape's coordinates measured from that grid's first cell point), sampled at the cell points
// x0_m + i cell_m, y0_m + j cell_m (i < nx, j < ny) of another grid, x0_m and y0_m measured from the
// first grid's first point. A Gaussian or a ring is the own grid's periodic function (its images
// summed with that period), read at each point wrapped into the own grid; a plane wave is its
// cosine at the point. With x0_m = y0_m = 0, cell_m = lx_m / nx and the own grid's size, this is
// sample_disturbance bit for bit. An impulse is one cell's value, not a function of position:
// refused (std::invalid_argument); resample_problem says so before.
void sample_disturbance_at(const Disturbance& d, double lx_m, double ly_m, double x0_m, double y0_m, int nx, int ny, double cell_m,
                           std::vector<double>& z);

// "" or why `d` cannot be resampled onto another grid (an impulse).
std::string resample_problem(const Disturbance& d);

// A ring is summed over images up to this many periods from the grid on each side.
constexpr int kMostRingImages = 4;

// "" or why `d` cannot be summed over its images on a grid of lx × ly metres: a ring whose radius
// + 6.5 widths reaches past kMostRingImages − 1 periods (its images would be (2·4 + 1)² and more per
// cell), or a Gaussian whose sum peaks above max_height_m (a width of 1e6 m on a 1 m grid: 3e10 m).
std::string disturbance_image_problem(const Disturbance& d, double lx_m, double ly_m, double max_height_m);

// A Gaussian's height at its centre with its periodic images summed, |A| Sx(0) Sy(0) (0 for other
// kinds): |A| for a bump narrow against the grid, about |A| π w² / (Lx Ly) once it is wider.
double gaussian_image_peak_m(const Disturbance& d, double lx_m, double ly_m);

}  // namespace stoneskip
