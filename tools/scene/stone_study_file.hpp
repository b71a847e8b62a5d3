#pragma once
// A stones study file (cases/studies/stones.toml, stones_quick.toml; documented in
// cases/README.md, "Study files") resolved into the stone studies' options: the throws (case
// files named relative to the study file, loaded here), and each study's settings. Strict: an
// unknown key is an error; a key left out keeps the library's default, and the shipped files
// state every key.
#include <string>
#include <vector>

#include "tools/io/toml_table.hpp"
#include "verification/stones/stone_studies.hpp"

namespace stoneskip {

struct StoneStudyFile {
  std::string file, text, title;
  std::string settings_text;  // the study file and every case file it names: what the findings depend on
  StoneStudiesOptions options;
};

// overrides: "section.key=value" assignments applied after parsing (load_toml), for tests and --set.
StoneStudyFile load_stone_study_file(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace stoneskip
