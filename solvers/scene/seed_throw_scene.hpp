#pragma once
// The seed's throw as a scene built in code, for tests and studies that need a small, fast copy of
// cases/scenes/seed_8ms.toml: the 44-triangle stone (an 11-gon prism, R = 3 cm, 8 mm thick,
// 2500 kg/m³) thrown at 8 m/s, path and attack angles 10°, 10 rev/s, from 0.1 m (physical
// convention: it lands at x ≈ 0.4 m and sinks in its first contact), stone steps 1 ms in flight and
// 10 µs in contact, over a pond of nx × ny cells of 2 cm (γ = 1/3 stencil, μ = 0.2 /s, reflecting
// walls, one water step per 1/90 s frame), its grid point (0, 0) at (origin_x_m, origin_y_m).
#include "solvers/scene/coupled_scene.hpp"

namespace stoneskip {

SceneOptions seed_throw_scene(int nx, int ny, double origin_x_m, double origin_y_m, double duration_s,
                              Coupling coupling = Coupling::two_way, double wave_speed_m_s = 0.5);

}  // namespace stoneskip
