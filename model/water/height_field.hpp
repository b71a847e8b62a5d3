#pragma once
// The water surface as a height field (spec §2.1, Lee & Baek 2013 Eq. 8–11):
//   z_tt = c² ∇²z − μ z_t  on nx × ny cells of size d,
// stepped with the leapfrog of Lengyel's height field with centred damping
//   z⁺ = (4 z − (2 − μΔt) z⁻ + 2 c²Δt² L[z]) / (2 + μΔt),
// L any 3×3 stencil (model/water/stencil.hpp). Storage: two padded (nx+2)×(ny+2) arrays with a
// ghost layer that the boundary condition fills before each step, so the interior update has no
// branches and a step allocates nothing. z⁺ overwrites z⁻ in place (each cell reads only its own
// z⁻), then the two buffers swap.
#include <string>
#include <vector>

#include "model/water/stencil.hpp"

namespace stoneskip {

enum class Boundary {
  periodic,    // the grid tiles the plane (verification against the spectral reference)
  reflecting,  // zero normal slope: ghost cells mirror the edge cells (a wall)
  fixed,       // z = 0 in the ghost cells, half a cell outside the edge (a clamped rim)
};
const char* to_string(Boundary b);
bool parse_boundary(const std::string& s, Boundary& out);

struct HeightFieldOptions {
  int nx = 64, ny = 64;
  double cell_m = 1.0 / 64;
  double wave_speed_m_s = 1;  // c
  double damping_per_s = 0;   // μ
  double dt_s = 0.5 / 64;
  Stencil stencil;
  Boundary boundary = Boundary::periodic;

  double courant() const { return wave_speed_m_s * dt_s / cell_m; }  // σ = cΔt/d
};

class HeightField {
 public:
  explicit HeightField(const HeightFieldOptions& options);

  // Sets z(0) = z0 and z_t(0) = v0 (row-major, x fastest, size nx·ny) and the leapfrog's
  // previous level by Taylor expansion with the scheme's own acceleration:
  // z(−Δt) = z0 − Δt v0 + (Δt²/2)(c² L[z0] − μ v0), a local error O(Δt³) that keeps the
  // global error O(Δt²). An empty v0 means zero velocity.
  void set_state(const std::vector<double>& z0, const std::vector<double>& v0 = {});

  void step();            // one leapfrog step; no allocation
  void advance(long n);   // n steps

  const HeightFieldOptions& options() const { return options_; }
  int nx() const { return options_.nx; }
  int ny() const { return options_.ny; }
  double time_s() const { return time_s_; }
  long steps() const { return steps_; }

  double height(int i, int j) const { return cur_[index(i, j)]; }
  void set_height(int i, int j, double z) { cur_[index(i, j)] = z; }
  // Copies the current heights (row-major, x fastest) into out (resized to nx·ny).
  void heights(std::vector<double>& out) const;
  // Height at a point x = i d, y = j d in grid units (bilinear between cells); outside the grid,
  // periodic fields wrap, others take the nearest edge value.
  double interpolate(double x_m, double y_m) const;

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j + 1) * stride_ + (i + 1); }
  void fill_ghosts(std::vector<double>& z) const;
  void apply_laplacian(const std::vector<double>& z, std::vector<double>& out) const;  // L[z] (no ghosts in out)

  HeightFieldOptions options_;
  std::size_t stride_;
  std::vector<double> cur_, prev_;
  double time_s_ = 0;
  long steps_ = 0;
};

}  // namespace stoneskip
