#pragma once
// A scene study file (cases/studies/scene.toml, scene_quick.toml; documented in cases/README.md,
// "Study files") resolved into the scene studies' options (verification/scene/scene_studies.hpp):
// the scene cases it names (paths relative to the study file) are loaded here, never by the
// studies. Strict: an unknown key is an error; a key left out keeps the library's default.
#include <string>
#include <vector>

#include "verification/scene/scene_studies.hpp"

namespace stoneskip {

struct SceneStudyFile {
  std::string file, text, title;
  std::string settings_text;  // the study file and every case file it names
  SceneStudiesOptions options;
};

SceneStudyFile load_scene_study_file(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace stoneskip
