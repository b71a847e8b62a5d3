#include "tools/scene/wave_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace stoneskip {

HeightFieldOptions read_height_field(TomlTable t, TomlTable& top, double* t_end_s) {
  HeightFieldOptions w;
  const long long nx = t.integer("nx"), ny = t.integer("ny");
  if (nx < 4 || nx > 16384) t.fail("nx", "must be in [4, 16384]");
  if (ny < 4 || ny > 16384) t.fail("ny", "must be in [4, 16384]");
  w.nx = static_cast<int>(nx);
  w.ny = static_cast<int>(ny);
  w.cell_m = t.number("cell_m");
  t.require_positive("cell_m", w.cell_m);
  w.wave_speed_m_s = t.number("wave_speed_m_s");
  t.require_positive("wave_speed_m_s", w.wave_speed_m_s);
  w.damping_per_s = t.number_or("damping_per_s", 0.0);
  t.require_non_negative("damping_per_s", w.damping_per_s);
  w.dt_s = t.number("dt_s");
  t.require_positive("dt_s", w.dt_s);
  if (t_end_s) {
    *t_end_s = t.number("t_end_s");
    t.require_positive("t_end_s", *t_end_s);
    if (*t_end_s / w.dt_s > 1e8) t.fail("t_end_s", "more than 1e8 steps of dt_s");
  }
  const std::string boundary = t.string_or("boundary", "periodic");
  if (!parse_boundary(boundary, w.boundary)) t.fail("boundary", "'" + boundary + "' is not one of periodic, reflecting, fixed");
  const std::string stencil = t.string("stencil");
  if (stencil == "custom") {
    TomlTable s = top.table("stencil");
    w.stencil.name = s.string_or("name", "custom");
    w.stencil.centre = s.number("centre");
    w.stencil.orth = s.number("orth");
    w.stencil.diag = s.number("diag");
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
  d.amplitude_m = t.number("amplitude_m");
  switch (d.kind) {
    case DisturbanceKind::gaussian:
    case DisturbanceKind::ring:
      d.width_m = t.number("width_m");
      t.require_positive("width_m", d.width_m);
      if (d.kind == DisturbanceKind::ring) {
        d.radius_m = t.number("radius_m");
        t.require_non_negative("radius_m", d.radius_m);
      }
      [[fallthrough]];
    case DisturbanceKind::impulse:
      d.x_m = t.number("x_m");
      d.y_m = t.number("y_m");
      break;
    case DisturbanceKind::plane_wave:
      d.wavelength_m = t.number("wavelength_m");
      t.require_positive("wavelength_m", d.wavelength_m);
      d.angle_deg = t.number_or("angle_deg", 0.0);
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
  c.initial = read_disturbance(top.table("initial"));
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
