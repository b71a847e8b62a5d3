#pragma once
// The scene report's shortcuts (verification/README.md, "scene"): each a cheaper way to run the
// scene, paired with the run it must be compared with. Most are compared with the scene as
// configured (two-way, full field, float64, one thread); the others name their own reference, so
// that a shortcut of the displacement forcing is compared with the displacement forcing, not with
// the base's pressure forcing.
#include <optional>
#include <string>
#include <vector>

#include "solvers/scene/coupled_scene.hpp"
#include "verification/scene/scene_studies.hpp"

namespace stoneskip {

struct ShortcutVariant {
  std::string key, what;
  std::optional<SceneOptions> reference;  // none: the base run (run once for all of them)
  SceneOptions shortcut;
};

// The variants of `base` that SceneShortcutOptions asks for, in the report's order.
std::vector<ShortcutVariant> scene_shortcut_variants(const SceneOptions& base, const SceneShortcutOptions& so);

}  // namespace stoneskip
