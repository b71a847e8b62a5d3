#pragma once
// A wave case file (TOML, documented in cases/README.md, section "Wave cases") resolved into the
// height field's options, the initial disturbance and the end time: [water], [initial], and
// optionally [case], [stencil] (custom weights, with water.stencil = "custom") and [reference].
// Every error is a one-line InputError naming the file and the line or key.
#include <string>
#include <vector>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "tools/io/toml_table.hpp"

namespace stoneskip {

struct WaveCase {
  std::string file;
  std::string text;
  std::vector<std::string> overrides;
  std::string title;
  HeightFieldOptions water;
  double t_end_s = 0;
  Disturbance initial;
  bool reference_semi_discrete = false;  // [reference] symbol = "stencil": compare with the
                                         // stencil's exact semi-discrete solution (time error only)
  long steps() const;                    // ⌈t_end/Δt⌉ (the run ends at steps·Δt)
  std::string resolved_settings() const; // every setting as TOML, after defaults and overrides
};

// The pieces, shared with stone cases that put the stone on a live water surface:
// [water] (t_end_s read only when t_end_s != nullptr; [stencil] from `top` for custom weights)
// and a disturbance table ([initial] here, [water.initial] in a stone case).
HeightFieldOptions read_height_field(TomlTable t, TomlTable& top, double* t_end_s);
Disturbance read_disturbance(TomlTable t);

WaveCase load_wave_case(const std::string& path, const std::vector<std::string>& overrides = {});
WaveCase wave_case_from_document(const TomlDocument& doc);

}  // namespace stoneskip
