#include "verification/scene/scene_shortcut_variants.hpp"

#include "verification/study/words.hpp"

namespace stoneskip {

std::vector<ShortcutVariant> scene_shortcut_variants(const SceneOptions& base, const SceneShortcutOptions& so) {
  std::vector<ShortcutVariant> v;
  {
    SceneOptions one = base, none = base;
    one.coupling = Coupling::one_way;
    none.coupling = Coupling::none;
    v.push_back({"no_field", "no field at all (coupling none) against one-way on the still pond", one, none});
  }
  {
    SceneOptions t = base;
    t.water->field.mode = StepMode::active_tiles;
    t.water->field.tiles.tile_cells = so.tile_cells;
    t.water->field.tiles.epsilon_m = 0;
    v.push_back({"tiles_eps_0", "active tiles, ε = 0", std::nullopt, t});
    for (std::size_t k = 0; k < so.epsilons_m.size(); ++k) {
      t.water->field.tiles.epsilon_m = so.epsilons_m[k];
      v.push_back({"tiles_eps_" + std::to_string(k + 1), "active tiles, ε = " + num(so.epsilons_m[k], 2) + " m", std::nullopt, t});
    }
  }
  {
    SceneOptions f = base;
    f.water->field.precision = Precision::float32;
    v.push_back({"float32", "float32 heights", std::nullopt, f});
  }
  {
    // The draught's samples matter to the displacement forcing only (the pressure forcing gathers
    // at every stone step): that forcing with one sample against K, both displacement.
    SceneOptions kk = base, k1 = base;
    kk.forcing = k1.forcing = Forcing::displacement;
    k1.draught_samples = 1;
    v.push_back({"one_sample", "displacement forcing: one draught sample per water step (the spec's point sample) against " +
                                   std::to_string(base.draught_samples),
                 kk, k1});
  }
  {
    SceneOptions everywhere = base;
    everywhere.stone_steps.dt_s = everywhere.stone_steps.contact_dt_s;
    v.push_back({"contact_step_near_water", "the contact step only near the water (" + num(base.stone_steps.dt_s, 2) + " s in flight) against " +
                                                num(base.stone_steps.contact_dt_s, 2) + " s everywhere",
                 everywhere, base});
  }
  return v;
}

}  // namespace stoneskip
