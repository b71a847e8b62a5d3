#include "solvers/scene/seed_throw_scene.hpp"

#include "model/stone/throw.hpp"

namespace stoneskip {

SceneOptions seed_throw_scene(int nx, int ny, double origin_x_m, double origin_y_m, double duration_s, Coupling coupling,
                              double wave_speed_m_s) {
  SceneOptions o;
  const Mesh m = make_prism(0.03, 0.008, 11);
  o.stone = make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
  ThrowParameters tp;
  tp.speed_m_s = 8;
  tp.path_angle_deg = 10;
  tp.attack_angle_deg = 10;
  tp.spin_rev_s = 10;
  tp.height_m = 0.1;
  o.initial = initial_state(o.stone, tp);
  o.stone_steps.scheme = Scheme::semi_implicit_euler;  // the game-engine stepper, fixed steps
  o.stone_steps.dt_s = 1e-3;
  o.stone_steps.contact_dt_s = 1e-5;
  o.coupling = coupling;
  SceneWater w;
  w.field.nx = nx;
  w.field.ny = ny;
  w.field.cell_m = 0.02;
  w.field.wave_speed_m_s = wave_speed_m_s;
  w.field.damping_per_s = 0.2;
  w.field.dt_s = 1.0 / 90;
  w.field.stencil = named_stencil("nine_point_isotropic");
  w.field.boundary = Boundary::reflecting;
  w.placement.origin_x_m = origin_x_m;
  w.placement.origin_y_m = origin_y_m;
  o.water = w;
  o.frame_rate_hz = 90;
  o.duration_s = duration_s;
  return o;
}

}  // namespace stoneskip
