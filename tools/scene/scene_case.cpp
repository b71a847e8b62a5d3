#include "tools/scene/scene_case.hpp"

#include <optional>
#include <sstream>

#include "model/coupling/draught.hpp"
#include "tools/io/number_text.hpp"
#include "tools/scene/stone_case.hpp"
#include "tools/scene/wave_case.hpp"

namespace stoneskip {

namespace {

WaterScene read_water(TomlTable w, TomlTable& top) {
  WaterScene scene;
  scene.origin_x_m = w.bounded_or("origin_x_m", 0.0, -kMaxWaterOrigin_m, kMaxWaterOrigin_m);
  scene.origin_y_m = w.bounded_or("origin_y_m", 0.0, -kMaxWaterOrigin_m, kMaxWaterOrigin_m);
  std::optional<TomlTable> initial_table = w.maybe_table("initial");
  if (initial_table) scene.initial = read_disturbance(*initial_table);
  const std::string coupling = w.string_or("coupling", to_string(scene.coupling));
  if (!parse_coupling(coupling, scene.coupling)) w.fail("coupling", "'" + coupling + "' is not one of none, one_way, two_way");
  const std::string forcing = w.string_or("forcing", to_string(scene.forcing));
  if (!parse_forcing(forcing, scene.forcing)) w.fail("forcing", "'" + forcing + "' is not one of pressure, displacement");
  const long long samples = w.integer_or("draught_samples", scene.draught_samples);
  if (samples < 1 || samples > 4096) w.fail("draught_samples", "must be in [1, 4096]");
  // The draught is sampled only under the displacement forcing: under pressure the head of each
  // stone step is applied, and draught_samples = 1, 8 and 4096 gave bit-identical scenes.
  if (w.has("draught_samples") && scene.forcing == Forcing::pressure)
    w.fail("draught_samples", "is used only with forcing = \"displacement\" (the pressure forcing applies the head of every "
                              "stone step, no draught samples)");
  scene.draught_samples = static_cast<int>(samples);
  // A head of fixed width in metres (solvers/scene/coupled_scene.hpp, pressure_smoothing_passes).
  scene.head_width_m = w.bounded_or("head_width_m", scene.head_width_m, 0.0, 1.0);
  const bool width_given = w.has("head_width_m");
  if (width_given && (scene.coupling != Coupling::two_way || scene.forcing != Forcing::pressure))
    w.fail("head_width_m", "is used only with coupling = \"two_way\" and forcing = \"pressure\" (it widens the head the "
                           "stone presses on the water with)");
  // The level the stone reads between water steps (model/water/height_field_surface.hpp).
  const std::string in_time = w.string_or("level_in_time", to_string(scene.level_in_time));
  if (!parse_level_in_time(in_time, scene.level_in_time))
    w.fail("level_in_time", "'" + in_time + "' is not one of held, extrapolated");
  if (w.has("level_in_time") && scene.coupling == Coupling::none)
    w.fail("level_in_time", "is used only with coupling = \"one_way\" or \"two_way\" (with none the stone reads still water)");
  // How the field is computed (model/water/height_field.hpp); read before read_height_field,
  // which finishes the table (the keys read here count as known there).
  HeightFieldOptions how;
  const std::string precision = w.string_or("precision", to_string(how.precision));
  if (!parse_precision(precision, how.precision)) w.fail("precision", "'" + precision + "' is not one of float64, float32");
  const long long threads = w.integer_or("threads", how.threads);
  if (threads < 1 || threads > 64) w.fail("threads", "must be in [1, 64]");
  const std::string mode = w.string_or("mode", to_string(how.mode));
  if (!parse_step_mode(mode, how.mode)) w.fail("mode", "'" + mode + "' is not one of full, active_tiles");
  const long long tile = w.integer_or("tile_cells", how.tiles.tile_cells);
  if (tile < 1 || tile > 4096) w.fail("tile_cells", "must be in [1, 4096]");
  how.tiles.epsilon_m = w.number_or("epsilon_m", how.tiles.epsilon_m);
  w.require_non_negative("epsilon_m", how.tiles.epsilon_m);
  TomlTable checked = w;  // for errors naming keys after read_height_field has finished w
  scene.field = read_height_field(w, top, nullptr);
  if (scene.initial) {
    const std::string why = disturbance_image_problem(*scene.initial, scene.field.nx * scene.field.cell_m,
                                                      scene.field.ny * scene.field.cell_m, kMaxAmplitude_m);
    if (!why.empty()) initial_table->fail(scene.initial->kind == DisturbanceKind::ring ? "radius_m" : "width_m", why);
  }
  if (width_given && scene.coupling == Coupling::two_way && scene.forcing == Forcing::pressure &&
      pressure_smoothing_passes(scene.head_width_m, scene.field.cell_m) == 0) {
    std::ostringstream m;
    m.precision(6);
    m << scene.head_width_m << " m is " << scene.head_width_m / scene.field.cell_m << " cells of " << scene.field.cell_m
      << " m; at most " << kMaxHeadWidthCells << " cells (the head takes 2 (w/d)^2 binomial passes a water step, at most "
      << kMaxPressureSmoothingPasses << "): take head_width_m <= " << at_most(kMaxHeadWidthCells * scene.field.cell_m, 6)
      << " or a larger cell_m";
    checked.fail("head_width_m", m.str());
  }
  scene.field.precision = how.precision;
  scene.field.threads = static_cast<int>(threads);
  scene.field.mode = how.mode;
  scene.field.tiles.tile_cells = static_cast<int>(tile);
  scene.field.tiles.epsilon_m = how.tiles.epsilon_m;
  // A scene's water must be stable (a wave case may be unstable on purpose; a scene's water that
  // blows up would be blamed on the stone): the exact free limit over the grid's modes (wave_case.hpp).
  {
    const WaterStability st = water_stability(scene.field);
    if (!st.stable()) {
      std::ostringstream m;
      m.precision(6);
      const auto [shown_sigma, shown_limit] = numbers_apart(st.sigma, st.grid_limit, 6);
      m << "the water would be unstable: sigma = c dt_s / cell_m = " << shown_sigma;
      if (st.no_stable_step() && st.grid_limit == 0)
        m << ", but the " << st.stencil << " stencil has no stable step (a mode grows at every sigma > 0): change its weights";
      else {
        // The step it advises must pass the two-way check below too: under the stone the limit is lower.
        const double coupled = coupled_courant_limit(scene.field.stencil);
        const bool lowered = scene.coupling == Coupling::two_way && coupled < st.limit;
        m << " exceeds the " << st.stencil << " stencil's limit " << shown_limit
          << " over this grid's modes (at every mu dt)";
        if (lowered) m << ", and a two-way stone lowers it to " << coupled << " under the stone (model/README.md §2.4)";
        // Rounded down: the step advised must pass when taken as printed.
        m << "; take dt_s <= " << at_most((lowered ? coupled : st.grid_limit) * scene.field.cell_m / scene.field.wave_speed_m_s, 6);
      }
      checked.fail("dt_s", m.str());
    }
  }
  if (scene.coupling == Coupling::two_way) {
    // Spec §2.4: under the stone the Courant number is √2 σ; refused rather than run unstable.
    const double sigma = scene.field.courant(), limit = coupled_courant_limit(scene.field.stencil);
    if (sigma > limit) {
      std::ostringstream m;
      m.precision(4);
      const auto [shown_sigma, shown_limit] = numbers_apart(sigma, limit, 4);
      m << "σ = cΔt/d = " << shown_sigma << " is above the coupled stability limit " << shown_limit << " of "
        << scene.field.stencil.name << " under the stone (model/README.md §2.4: free limit/√2): take dt_s ≤ "
        << at_most(limit * scene.field.cell_m / scene.field.wave_speed_m_s, 4) << " s, or coupling = \"one_way\"";
      checked.fail("dt_s", m.str());
    }
  }
  return scene;
}

}  // namespace

void read_scene_keys(TomlTable& top, std::optional<WaterScene>& water, SceneFrames& frames) {
  if (auto w = top.maybe_table("water")) water = read_water(*w, top);
  if (auto s = top.maybe_table("scene")) {
    frames.frame_rate_hz = s->number_or("frame_rate_hz", frames.frame_rate_hz);
    s->require_in("frame_rate_hz", frames.frame_rate_hz, 1e-3, 1e5);
    if (auto d = s->maybe_number("duration_s")) {
      s->require_positive("duration_s", *d);
      if (*d * frames.frame_rate_hz < 1) s->fail("duration_s", "shorter than one frame (1/frame_rate_hz)");
      if (*d * frames.frame_rate_hz > 1e8) s->fail("duration_s", "more than 1e8 frames");
      frames.duration_s = *d;
    }
    const std::string free = s->string_or("free_water", to_string(frames.free_water));
    if (!parse_free_water(free, frames.free_water))
      s->fail("free_water", "'" + free + "' is not one of one_at_a_time, to_the_next_frame, to_the_next_look");
    s->finish();
  }
}

std::string scene_settings_toml(const std::optional<WaterScene>& water, const SceneFrames& frames) {
  std::ostringstream s;
  s.precision(12);
  if (water) {
    const HeightFieldOptions& f = water->field;
    s << "\n[water]\ncoupling = \"" << to_string(water->coupling) << "\"\nforcing = \"" << to_string(water->forcing)
      << "\"\ndraught_samples = " << water->draught_samples;
    if (water->head_width_m > 0) s << "\nhead_width_m = " << water->head_width_m;
    s << "\nlevel_in_time = \"" << to_string(water->level_in_time) << "\"";
    s << "\nstencil = \"" << f.stencil.name << "\"  # weights × 1/d²: " << f.stencil.centre << ", " << f.stencil.orth << ", "
      << f.stencil.diag << "\nnx = " << f.nx << "\nny = " << f.ny << "\ncell_m = " << f.cell_m
      << "\nwave_speed_m_s = " << f.wave_speed_m_s << "\ndamping_per_s = " << f.damping_per_s << "\nboundary = \""
      << to_string(f.boundary) << "\"\ndt_s = " << f.dt_s << "  # σ = " << f.courant() << "\nprecision = \""
      << to_string(f.precision) << "\"\nthreads = " << f.threads << "\nmode = \"" << to_string(f.mode)
      << "\"\ntile_cells = " << f.tiles.tile_cells << "\nepsilon_m = " << f.tiles.epsilon_m << "\norigin_x_m = " << water->origin_x_m
      << "\norigin_y_m = " << water->origin_y_m << "\n";
    if (water->initial) {
      const Disturbance& d = *water->initial;
      s << "\n[water.initial]\nkind = \"" << to_string(d.kind) << "\"\namplitude_m = " << d.amplitude_m << "\nwidth_m = " << d.width_m
        << "\nx_m = " << d.x_m << "\ny_m = " << d.y_m << "\nradius_m = " << d.radius_m << "\nangle_deg = " << d.angle_deg
        << "\nwavelength_m = " << d.wavelength_m << "\n";
    }
  }
  s << "\n[scene]\nframe_rate_hz = " << frames.frame_rate_hz << "\nfree_water = \"" << to_string(frames.free_water) << "\"\n";
  if (frames.duration_s) s << "duration_s = " << *frames.duration_s << "\n";
  else s << "# duration_s: the stone's t_max_s\n";
  return s.str();
}

}  // namespace stoneskip
