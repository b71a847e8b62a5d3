// The scene report's shortcuts are each compared with a run that differs from them in the one
// thing the shortcut changes.
#include <boost/test/unit_test.hpp>

#include "solvers/scene/seed_throw_scene.hpp"
#include "verification/scene/scene_shortcut_variants.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(scene_shortcut_variants_)

BOOST_AUTO_TEST_CASE(each_shortcut_is_compared_with_a_run_of_its_own_forcing) {
  // Oracle: the variants' descriptions. The one-sample shortcut is "displacement forcing: one
  // draught sample per water step against K": its reference is the displacement forcing with K
  // samples. Comparing it with the base (pressure forcing, which ignores the samples) measured
  // the change of forcing instead (the scene report printed 0.97 of the largest height for it).
  SceneOptions base = seed_throw_scene(40, 40, -1.1, -1.5, 1.2);
  base.forcing = Forcing::pressure;
  base.draught_samples = 8;
  const std::vector<ShortcutVariant> v = scene_shortcut_variants(base, SceneShortcutOptions{});
  bool saw_one_sample = false;
  for (const ShortcutVariant& x : v) {
    const SceneOptions& ref = x.reference ? *x.reference : base;
    BOOST_TEST((ref.forcing == x.shortcut.forcing), x.key);
    BOOST_TEST(((ref.coupling == x.shortcut.coupling) || x.key == "no_field"), x.key);
    if (x.key != "one_sample") continue;
    saw_one_sample = true;
    BOOST_TEST((ref.forcing == Forcing::displacement));
    BOOST_TEST(ref.draught_samples == 8);
    BOOST_TEST(x.shortcut.draught_samples == 1);
  }
  BOOST_TEST(saw_one_sample);
}

BOOST_AUTO_TEST_SUITE_END()
