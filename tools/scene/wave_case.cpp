#include "tools/scene/wave_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>

#include "tools/io/number_text.hpp"

namespace stoneskip {

namespace {
std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
}  // namespace

WaterStability water_stability(const HeightFieldOptions& water) {
  WaterStability s;
  s.stencil = water.stencil.name;
  s.sigma = water.courant();
  s.mu_dt = water.damping_per_s * water.dt_s;
  s.limit = leapfrog_courant_limit(water.stencil);
  // The cosines of the wavenumbers each axis holds (stencil.hpp): their range.
  auto range = [&](int n, double& lo, double& hi) {
    switch (water.boundary) {
      case Boundary::periodic:  // k = 2πm/N
        hi = 1;
        lo = n % 2 == 0 ? -1 : -std::cos(M_PI / n);
        break;
      case Boundary::reflecting:  // k = πm/N, m < N
        hi = 1;
        lo = -std::cos(M_PI / n);
        break;
      default:  // fixed: k = πm/(N + 1), 1 ≤ m ≤ N
        hi = std::cos(M_PI / (n + 1));
        lo = -hi;
    }
  };
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  range(water.nx, x0, x1);
  range(water.ny, y0, y1);
  // A growing mode of the plane (limit 0) decides only where the grid holds it: the ranges' ends
  // are modes of the grid (the symbol is bilinear in the cosines), so a 5 × 5 periodic grid, which
  // holds no checkerboard, is stable with a stencil whose only growing mode is the checkerboard.
  s.grid_limit = std::max(s.limit, leapfrog_courant_limit(water.stencil, x0, x1, y0, y1));
  s.grid = std::to_string(water.nx) + " × " + std::to_string(water.ny) + " " + to_string(water.boundary);
  return s;
}

std::string WaterStability::limit_kind() const { return unbounded() ? "unbounded" : no_stable_step() ? "none" : "bounded"; }

std::string WaterStability::limit_text() const {
  if (unbounded()) return "stable at every sigma: the stencil couples no cells";
  char b[160];
  if (no_stable_step()) {
    if (grid_limit == 0) return "no stable step: a mode of the stencil grows at every sigma > 0";
    std::snprintf(b, sizeof b, "stable up to %.6g on this grid's modes (the plane has a mode that grows at every sigma > 0)",
                  grid_limit);
    return b;
  }
  // The grid's own limit is named where it shows in 4 digits (or where it is what keeps sigma stable).
  if (grid_limit > limit * (1 + 1e-4) || (sigma > limit && stable()))
    std::snprintf(b, sizeof b, "stable up to %.6g on this grid's modes, %.6g on the plane", grid_limit, limit);
  else
    std::snprintf(b, sizeof b, "stable up to %.4f", limit);
  return b;
}

std::string WaterStability::reason() const {
  char b[512];
  if (unbounded())
    std::snprintf(b, sizeof b, "the %s stencil couples no cells: stable at every sigma", stencil.c_str());
  else if (no_stable_step() && grid_limit == 0)
    std::snprintf(b, sizeof b, "the %s stencil has no stable step: a mode grows at every sigma > 0 (sigma = %.4f)",
                  stencil.c_str(), sigma);
  else if (no_stable_step()) {
    const auto [s_grid, on_grid] = numbers_apart(sigma, grid_limit, 6);
    std::snprintf(b, sizeof b,
                  "the %s stencil has a mode that grows at every sigma > 0 on the plane, but this %s grid holds none: "
                  "sigma = %s %s %s, the limit over its modes (at every mu dt)",
                  stencil.c_str(), grid.c_str(), s_grid.c_str(), stable() ? "is within" : "exceeds", on_grid.c_str());
  }
  else if (sigma > limit && stable()) {
    const auto [s_plane, plane] = numbers_apart(sigma, limit, 6);
    const auto [s_grid, on_grid] = numbers_apart(sigma, grid_limit, 6);
    std::snprintf(b, sizeof b,
                  "sigma = %s exceeds the von Neumann limit %s of %s on the plane, but is within %s, the limit over "
                  "the modes this %s grid holds (it holds none at the zone's corner; at every mu dt)",
                  (s_plane.size() > s_grid.size() ? s_plane : s_grid).c_str(), plane.c_str(), stencil.c_str(),
                  on_grid.c_str(), grid.c_str());
  } else if (!stable() && grid_limit > limit * (1 + 1e-4)) {
    const auto [s_grid, on_grid] = numbers_apart(sigma, grid_limit, 6);
    std::snprintf(b, sizeof b,
                  "sigma = %s exceeds %s, the limit over the modes this %s grid holds (%.6g on the plane, for %s; at "
                  "every mu dt)",
                  s_grid.c_str(), on_grid.c_str(), grid.c_str(), limit, stencil.c_str());
  }
  else {
    // Four decimals, or as many digits as tell the two apart ("0.7071 exceeds 0.7071" was true).
    char s4[32], l4[32];
    std::snprintf(s4, sizeof s4, "%.4f", sigma);
    std::snprintf(l4, sizeof l4, "%.4f", limit);
    std::pair<std::string, std::string> shown{s4, l4};
    if (shown.first == shown.second && sigma != limit) shown = numbers_apart(sigma, limit, 5);
    std::snprintf(b, sizeof b, "sigma = %s %s the von Neumann limit %s of %s (at every mu dt)", shown.first.c_str(),
                  stable() ? "is within" : "exceeds", shown.second.c_str(), stencil.c_str());
  }
  return b;
}

HeightFieldOptions read_height_field(TomlTable t, TomlTable& top, double* t_end_s) {
  HeightFieldOptions w;
  for (const char* key : {"nx", "ny"}) {
    const long long n = t.integer(key);
    if (n < kMinCells || n > kMaxCells)
      t.fail(key, "must be in [" + std::to_string(kMinCells) + ", " + std::to_string(kMaxCells) + "] (got " + std::to_string(n) + ")");
    (key[1] == 'x' ? w.nx : w.ny) = static_cast<int>(n);
  }
  w.cell_m = t.bounded("cell_m", kCellSize_m.lo, kCellSize_m.hi);
  w.wave_speed_m_s = t.bounded("wave_speed_m_s", kWaveSpeed_m_s.lo, kWaveSpeed_m_s.hi);
  w.damping_per_s = t.bounded_or("damping_per_s", 0.0, 0, kMaxDamping_per_s);
  w.dt_s = t.bounded("dt_s", kWaterStep_s.lo, kWaterStep_s.hi);
  if (t_end_s) {
    *t_end_s = t.bounded("t_end_s", kWaterStep_s.lo, kMaxWaterDuration_s);
    if (*t_end_s / w.dt_s > kMaxWaveSteps)
      t.fail("t_end_s", "t_end_s / dt_s = " + num(*t_end_s / w.dt_s) + " steps exceeds " + num(kMaxWaveSteps));
  }
  const std::string boundary = t.string_or("boundary", "periodic");
  if (!parse_boundary(boundary, w.boundary)) t.fail("boundary", "'" + boundary + "' is not one of periodic, reflecting, fixed");
  const std::string stencil = t.string("stencil");
  if (stencil == "custom") {
    TomlTable s = top.table("stencil");
    w.stencil.name = s.string_or("name", "custom");
    w.stencil.centre = s.bounded("centre", -kMaxStencilWeight, kMaxStencilWeight);
    w.stencil.orth = s.bounded("orth", -kMaxStencilWeight, kMaxStencilWeight);
    w.stencil.diag = s.bounded("diag", -kMaxStencilWeight, kMaxStencilWeight);
    s.finish();
  } else if (is_stencil_name(stencil)) {
    w.stencil = named_stencil(stencil);
    if (top.has("stencil")) top.fail("stencil", "custom weights need water.stencil = \"custom\"");
  } else {
    t.fail("stencil", "'" + stencil + "' is not one of five_point, nine_point_half, nine_point_isotropic, paper_eq11, custom");
  }
  t.finish();
  return w;
}

Disturbance read_disturbance(TomlTable t) {
  Disturbance d;
  const std::string kind = t.string("kind");
  if (!parse_disturbance_kind(kind, d.kind)) t.fail("kind", "'" + kind + "' is not one of gaussian, plane_wave, ring, impulse");
  d.amplitude_m = t.bounded("amplitude_m", -kMaxAmplitude_m, kMaxAmplitude_m);
  switch (d.kind) {
    case DisturbanceKind::gaussian:
    case DisturbanceKind::ring:
      d.width_m = t.bounded("width_m", kDisturbanceLength_m.lo, kDisturbanceLength_m.hi);
      if (d.kind == DisturbanceKind::ring) d.radius_m = t.bounded("radius_m", 0, kDisturbanceLength_m.hi);
      [[fallthrough]];
    case DisturbanceKind::impulse:
      d.x_m = t.bounded("x_m", -kDisturbanceLength_m.hi, kDisturbanceLength_m.hi);
      d.y_m = t.bounded("y_m", -kDisturbanceLength_m.hi, kDisturbanceLength_m.hi);
      break;
    case DisturbanceKind::plane_wave:
      d.wavelength_m = t.bounded("wavelength_m", kDisturbanceLength_m.lo, kDisturbanceLength_m.hi);
      d.angle_deg = t.bounded_or("angle_deg", 0.0, -360, 360);
      break;
  }
  t.finish();  // a key the kind does not use is an error, not silently ignored
  return d;
}

long WaveCase::steps() const { return std::max(1L, static_cast<long>(std::ceil(t_end_s / water.dt_s - 1e-9))); }

std::string WaveCase::resolved_settings() const {
  std::ostringstream s;
  s.precision(17);
  s << "[water]\nstencil = \"" << water.stencil.name << "\"\nnx = " << water.nx << "\nny = " << water.ny
    << "\ncell_m = " << water.cell_m << "\nwave_speed_m_s = " << water.wave_speed_m_s
    << "\ndamping_per_s = " << water.damping_per_s << "\nboundary = \"" << to_string(water.boundary)
    << "\"\ndt_s = " << water.dt_s << "\nt_end_s = " << t_end_s << "\n\n[stencil]  # weights × 1/d²\ncentre = "
    << water.stencil.centre << "\north = " << water.stencil.orth << "\ndiag = " << water.stencil.diag
    << "\n\n[initial]\nkind = \"" << to_string(initial.kind) << "\"\namplitude_m = " << initial.amplitude_m
    << "\nwidth_m = " << initial.width_m << "\nx_m = " << initial.x_m << "\ny_m = " << initial.y_m
    << "\nradius_m = " << initial.radius_m << "\nangle_deg = " << initial.angle_deg
    << "\nwavelength_m = " << initial.wavelength_m << "\n\n[reference]\nsymbol = \""
    << (reference_semi_discrete ? "stencil" : "continuum") << "\"\n";
  return s.str();
}

WaveCase wave_case_from_document(const TomlDocument& doc) {
  WaveCase c;
  c.file = doc.file;
  c.text = doc.text;
  c.overrides = doc.overrides;
  TomlTable top = doc.top();
  c.title = read_case_title(top);
  c.water = read_height_field(top.table("water"), top, &c.t_end_s);
  TomlTable initial = top.table("initial");
  c.initial = read_disturbance(initial);
  if (const std::string why = disturbance_image_problem(c.initial, c.water.nx * c.water.cell_m, c.water.ny * c.water.cell_m, kMaxAmplitude_m);
      !why.empty())
    initial.fail(c.initial.kind == DisturbanceKind::ring ? "radius_m" : "width_m", why);
  if (auto ref = top.maybe_table("reference")) {
    const std::string sym = ref->string_or("symbol", "continuum");
    if (sym != "continuum" && sym != "stencil") ref->fail("symbol", "'" + sym + "' is not one of continuum, stencil");
    c.reference_semi_discrete = sym == "stencil";
    ref->finish();
  }
  top.finish();
  return c;
}

WaveCase load_wave_case(const std::string& path, const std::vector<std::string>& overrides) {
  return wave_case_from_document(load_toml(path, overrides));
}

}  // namespace stoneskip
