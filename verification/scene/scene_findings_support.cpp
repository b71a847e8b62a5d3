#include "verification/scene/scene_findings_support.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "verification/study/words.hpp"

namespace stoneskip::scene_findings {

Table table(std::vector<std::string> columns) { return Table{std::move(columns), {}}; }

SceneOptions capped(const SceneStudiesOptions& o, SceneOptions s) {
  if (o.duration_cap_s > 0) s.duration_s = std::min(s.duration_s, o.duration_cap_s);
  return s;
}

const SceneStudyCase& find_case(const SceneStudiesOptions& o, const std::string& name) {
  if (name.empty()) return o.cases.front();
  for (const auto& c : o.cases)
    if (c.name == name) return c;
  throw std::invalid_argument("scene study: no case named '" + name + "'");
}

std::string us(double s) { return num(1e6 * s, 3) + " µs"; }
std::string ms(double s) { return num(1e3 * s, 3) + " ms"; }
std::string mm(double m) { return num(1e3 * m, 3) + " mm"; }
std::string duration(double s) { return std::abs(s) >= 0.1 ? num(s, 3) + " s" : std::abs(s) >= 1e-3 ? ms(s) : us(s); }
std::string length(double m) { return std::abs(m) >= 1 ? num(m, 3) + " m" : mm(m); }
std::string counted(long n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

void store_scene_settings(Record& r, const SceneStudyCase& c, const SceneOptions& s) {
  r.set("title", c.title);
  r.set("file", c.file);
  r.set("convention", std::string(to_string(s.environment.convention)));
  r.set("coupling", std::string(to_string(s.coupling)));
  r.set("frame_rate_hz", s.frame_rate_hz);
  r.set("duration_s", s.end_s());
  r.set("frames", s.frames());
  r.set("stone", s.stone.description);
  r.set("stone_radius_m", s.stone.disk_radius_m);
  r.set("speed_m_s", s.initial.velocity_m_s.norm());
  r.set("contact_dt_s", s.stone_steps.contact_dt_s);
  r.set("draught_samples", s.draught_samples);
  r.set("scene_forcing", std::string(to_string(s.forcing)));  // draught samples count under displacement only
  if (s.water) {
    const HeightFieldOptions& f = s.water->field;
    r.set("nx", f.nx);
    r.set("ny", f.ny);
    r.set("cell_m", f.cell_m);
    r.set("origin_x_m", s.water->placement.origin_x_m);  // the centre of cell (0, 0)
    r.set("origin_y_m", s.water->placement.origin_y_m);
    r.set("wave_speed_m_s", f.wave_speed_m_s);
    r.set("damping_per_s", f.damping_per_s);
    r.set("water_dt_s", f.dt_s);
    r.set("courant", f.courant());
    r.set("coupled_limit", coupled_courant_limit(f.stencil));
    r.set("stencil", f.stencil.name);
    r.set("precision", std::string(to_string(f.precision)));
    r.set("mode", std::string(to_string(f.mode)));
  }
}

void place_on_pond(SceneOptions& s, const SceneStudyCase& c, const Vec3& first_touch_m, double pond_m, double cell_m, double dt_s) {
  HeightFieldOptions& w = s.water->field;
  w.cell_m = cell_m;
  w.dt_s = dt_s;
  w.nx = w.ny = static_cast<int>(std::ceil(pond_m / cell_m)) + 1;
  s.water->placement.origin_x_m = first_touch_m.x() - 0.25 * pond_m;
  s.water->placement.origin_y_m = first_touch_m.y() - 0.5 * pond_m;
  // The case's initial surface at the pond's own points: the shape's frame is the case's grid.
  const SceneWater& own = *c.scene.water;
  if (c.initial) {
    sample_disturbance_at(*c.initial, own.field.nx * own.field.cell_m, own.field.ny * own.field.cell_m,
                          s.water->placement.origin_x_m - own.placement.origin_x_m,
                          s.water->placement.origin_y_m - own.placement.origin_y_m, w.nx, w.ny, w.cell_m, s.water->initial_m);
  } else {
    if (!std::all_of(own.initial_m.begin(), own.initial_m.end(), [](double z) { return z == 0; }))
      throw std::logic_error("place_on_pond: a disturbed surface without a shape (grid_case_problem refuses it)");
    s.water->initial_m.clear();  // still water (heights all 0 on the case's grid: none on this one)
  }
}

bool starts_disturbed(const SceneStudyCase& c) {
  const auto& z = c.scene.water->initial_m;
  return c.initial && std::any_of(z.begin(), z.end(), [](double v) { return v != 0; });
}

std::string initial_surface_words(const Disturbance& d) {
  const std::string high = length(std::abs(d.amplitude_m)) + (d.amplitude_m < 0 ? " deep" : " high");
  const std::string at = " centred at (" + num(d.x_m, 4) + ", " + num(d.y_m, 4) + ") m of the case's grid";
  switch (d.kind) {
    case DisturbanceKind::plane_wave:
      return "a standing plane wave " + high + " and " + length(d.wavelength_m) + " long, its wave vector " + num(d.angle_deg, 4) +
             "° from x";
    case DisturbanceKind::gaussian: return "a Gaussian hump " + high + " and " + length(d.width_m) + " wide (e-folding)" + at;
    case DisturbanceKind::ring:
      return "a ring " + high + ", " + length(d.radius_m) + " in radius and " + length(d.width_m) + " wide" + at;
    case DisturbanceKind::impulse: return "an impulse of " + length(d.amplitude_m) + at;
  }
  return "?";
}

PondWalls pond_walls(const SceneStudyCase& c, const ContactRecord& first, double pond_m, double cell_m) {
  return pond_walls(c, first.first_touch_m, first, pond_m, cell_m);
}

PondWalls pond_walls(const SceneStudyCase& c, const Vec3& touch, const ContactRecord& first, double pond_m, double cell_m) {
  const SceneWater& own = *c.scene.water;
  const int n = static_cast<int>(std::ceil(pond_m / cell_m)) + 1;
  const double x0 = touch.x() - 0.25 * pond_m, y0 = touch.y() - 0.5 * pond_m;
  const double x1 = x0 + (n - 1) * cell_m, y1 = y0 + (n - 1) * cell_m;
  // The track: the centre of mass from entry to exit, its extent in x and y.
  const double tx0 = std::min(first.entry_position_m.x(), first.exit_position_m.x());
  const double tx1 = std::max(first.entry_position_m.x(), first.exit_position_m.x());
  const double ty0 = std::min(first.entry_position_m.y(), first.exit_position_m.y());
  const double ty1 = std::max(first.entry_position_m.y(), first.exit_position_m.y());
  PondWalls p;
  p.nearest_m = std::min({tx0 - x0, x1 - tx1, ty0 - y0, y1 - ty1}) - c.scene.stone.disk_radius_m;
  p.reach_s = std::max(0.0, p.nearest_m) / own.field.wave_speed_m_s;
  const double ox = own.placement.origin_x_m, oy = own.placement.origin_y_m;
  const double ex = ox + (own.field.nx - 1) * own.field.cell_m, ey = oy + (own.field.ny - 1) * own.field.cell_m;
  p.inside_case = own.field.boundary == Boundary::periodic || (x0 >= ox && y0 >= oy && x1 <= ex && y1 <= ey);
  return p;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? separator : "") + items[i];
  return s;
}

}  // namespace stoneskip::scene_findings
