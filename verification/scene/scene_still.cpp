#include "verification/scene/scene_still.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

bool StillFrameOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(threshold_fraction > 0 && threshold_fraction < 1)) return fail("threshold_fraction must be in (0, 1)");
  if (top_cells_max < 16 || near_cells_max < 8) return fail("top_cells_max >= 16 and near_cells_max >= 8 needed");
  if (!(near_window_m > 0) || !(margin_m >= 0)) return fail("near_window_m > 0 and margin_m >= 0 needed");
  return true;
}

namespace {

// Block means over [i0, i0 + n b) × [j0, j0 + m b), points beyond the grid left out.
void block_means(const HeightField& f, int i0, int j0, int n, int m, int b, std::vector<double>& out) {
  out.assign(static_cast<std::size_t>(n) * m, 0.0);
  for (int q = 0; q < m; ++q)
    for (int p = 0; p < n; ++p) {
      double s = 0;
      int count = 0;
      for (int dj = 0; dj < b; ++dj)
        for (int di = 0; di < b; ++di) {
          const int i = i0 + p * b + di, j = j0 + q * b + dj;
          if (i < 0 || j < 0 || i >= f.nx() || j >= f.ny()) continue;
          s += f.height(i, j);
          ++count;
        }
      out[static_cast<std::size_t>(q) * n + p] = count ? s / count : 0.0;
    }
}

}  // namespace

StillFrame capture_telling_frame(const SceneOptions& scene, const StillFrameOptions& o) {
  StillFrame r;
  std::string why;
  if (!o.is_valid(&why)) {
    r.problem = why;
    return r;
  }
  if (!scene.water || scene.coupling == Coupling::none) {
    r.problem = "the scene has no field";
    return r;
  }
  // 1. The largest |z| of each frame, and whether the edge is disturbed yet.
  std::vector<double> largest;
  const SceneSummary run = run_scene(scene, [&](const SceneFrame& f) {
    double m = 0;
    for (int j = 0; j < f.field->ny(); ++j)
      for (int i = 0; i < f.field->nx(); ++i) m = std::max(m, std::abs(f.field->height(i, j)));
    largest.push_back(m);
  });
  r.frames = run.frames;
  r.largest_m = largest.empty() ? 0 : *std::max_element(largest.begin(), largest.end());
  if (!(r.largest_m > 0)) {
    r.problem = "the water never moved";
    return r;
  }
  r.threshold_m = o.threshold_fraction * r.largest_m;
  std::vector<double> moving;
  for (double m : largest)
    if (m > 0) moving.push_back(m);
  std::nth_element(moving.begin(), moving.begin() + moving.size() / 2, moving.end());
  r.scale_m = 0.5 * moving[moving.size() / 2];
  // 2. The disturbed cells of each frame until the edge is reached.
  bool edge = false;
  run_scene(scene, [&](const SceneFrame& f) {
    if (edge) return;
    const HeightField& z = *f.field;
    long count = 0;
    for (int j = 0; j < z.ny(); ++j)
      for (int i = 0; i < z.nx(); ++i) {
        if (std::abs(z.height(i, j)) <= r.threshold_m) continue;
        ++count;
        if (i == 0 || j == 0 || i == z.nx() - 1 || j == z.ny() - 1) edge = true;
      }
    if (edge) return;
    ++r.frames_considered;
    if (count > r.disturbed_cells) {
      r.disturbed_cells = count;
      r.frame = f.index;
      r.t_s = f.t_s;
    }
  });
  if (r.frame == 0) {
    r.problem = "no frame has disturbed water before the edge is reached";
    return r;
  }
  // 3. The window: the track and the rings' reach around it, inside the pond.
  const HeightFieldOptions& fo = scene.water->field;
  const FieldPlacement& at = scene.water->placement;
  const double d = fo.cell_m, reach = fo.wave_speed_m_s * r.t_s + o.margin_m;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& p : run.stone.trajectory) {
    if (p.t_s > r.t_s) break;
    x0 = std::min(x0, p.state.position_m.x());
    x1 = std::max(x1, p.state.position_m.x());
    y0 = std::min(y0, p.state.position_m.y());
    y1 = std::max(y1, p.state.position_m.y());
    r.track_x_m.push_back(p.state.position_m.x());
    r.track_y_m.push_back(p.state.position_m.y());
  }
  for (const auto& c : run.stone.contacts)
    if (c.start_s <= r.t_s) {
      r.touch_x_m.push_back(c.first_touch_m.x());
      r.touch_y_m.push_back(c.first_touch_m.y());
    }
  auto cell = [&](double x, double origin) { return static_cast<int>(std::floor((x - origin) / d)); };
  const int i0 = std::clamp(cell(x0 - reach, at.origin_x_m), 0, fo.nx - 1), i1 = std::clamp(cell(x1 + reach, at.origin_x_m) + 1, 0, fo.nx - 1);
  const int j0 = std::clamp(cell(y0 - reach, at.origin_y_m), 0, fo.ny - 1), j1 = std::clamp(cell(y1 + reach, at.origin_y_m) + 1, 0, fo.ny - 1);
  const int span = std::max(i1 - i0 + 1, j1 - j0 + 1);
  const int block = std::max(1, (span + o.top_cells_max - 1) / o.top_cells_max);
  r.top_nx = (i1 - i0 + 1 + block - 1) / block;
  r.top_ny = (j1 - j0 + 1 + block - 1) / block;
  r.top_dx_m = block * d;
  r.top_x0_m = at.origin_x_m + (i0 + 0.5 * (block - 1)) * d;
  r.top_y0_m = at.origin_y_m + (j0 + 0.5 * (block - 1)) * d;
  r.pond_x0_m = at.origin_x_m + (i0 - 0.5) * d;
  r.pond_x1_m = at.origin_x_m + (i0 + r.top_nx * block - 0.5) * d;
  r.pond_y0_m = at.origin_y_m + (j0 - 0.5) * d;
  r.pond_y1_m = at.origin_y_m + (j0 + r.top_ny * block - 0.5) * d;
  // 4. The chosen frame again, captured.
  r.stone_radius_m = scene.stone.disk_radius_m;
  run_scene(scene, [&](const SceneFrame& f) {
    if (f.index != r.frame) return;
    r.stone_status = f.stone_status;
    r.stone_x_m = f.stone.position_m.x();
    r.stone_y_m = f.stone.position_m.y();
    r.stone_z_m = f.stone.position_m.z();
    block_means(*f.field, i0, j0, r.top_nx, r.top_ny, block, r.top_m);
    const int side = std::min({static_cast<int>(std::ceil(o.near_window_m / d)), fo.nx, fo.ny});
    const int nb = std::max(1, (side + o.near_cells_max - 1) / o.near_cells_max);
    r.near_n = std::max(2, side / nb);
    const int w = r.near_n * nb;
    const int ic = static_cast<int>(std::lround((r.stone_x_m - at.origin_x_m) / d));
    const int jc = static_cast<int>(std::lround((r.stone_y_m - at.origin_y_m) / d));
    const int a0 = std::clamp(ic - w / 2, 0, std::max(0, fo.nx - w)), b0 = std::clamp(jc - w / 2, 0, std::max(0, fo.ny - w));
    block_means(*f.field, a0, b0, r.near_n, r.near_n, nb, r.near_m);
    r.near_dx_m = nb * d;
    r.near_x0_m = at.origin_x_m + (a0 + 0.5 * (nb - 1)) * d;
    r.near_y0_m = at.origin_y_m + (b0 + 0.5 * (nb - 1)) * d;
  });
  r.found = true;
  return r;
}

}  // namespace stoneskip
