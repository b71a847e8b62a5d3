#pragma once
// A waves study file (cases/studies/waves.toml, waves_quick.toml; documented in cases/README.md,
// "Study files") resolved into the wave studies' options. Strict: an unknown key is an error; a
// key left out keeps the library's default, and the shipped files state every key.
#include <string>
#include <vector>

#include "tools/io/toml_table.hpp"
#include "verification/waves/wave_studies.hpp"

namespace stoneskip {

struct WaveStudyFile {
  std::string file, text, title;
  WaveStudiesOptions options;
};

WaveStudyFile load_wave_study_file(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace stoneskip
