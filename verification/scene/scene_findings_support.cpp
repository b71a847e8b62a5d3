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

void place_on_pond(SceneOptions& s, const Vec3& first_touch_m, double pond_m, double cell_m, double dt_s) {
  HeightFieldOptions& w = s.water->field;
  w.cell_m = cell_m;
  w.dt_s = dt_s;
  w.nx = w.ny = static_cast<int>(std::ceil(pond_m / cell_m)) + 1;
  s.water->placement.origin_x_m = first_touch_m.x() - 0.25 * pond_m;
  s.water->placement.origin_y_m = first_touch_m.y() - 0.5 * pond_m;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? separator : "") + items[i];
  return s;
}

}  // namespace stoneskip::scene_findings
