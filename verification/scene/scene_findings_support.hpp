#pragma once
// What the scene studies' sections share (verification/scene/scene_studies.hpp): the scene as a
// preset runs it, the case a section names, a case's settings as a record, and numbers as words in
// the unit that reads best. Internal to verification/scene.
#include <limits>
#include <string>
#include <vector>

#include "verification/scene/scene_studies.hpp"

namespace stoneskip::scene_findings {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Table table(std::vector<std::string> columns);
// The scene as the study runs it: cut to the preset's duration cap.
SceneOptions capped(const SceneStudiesOptions& o, SceneOptions s);
// The case named (the first if the name is empty); throws std::invalid_argument if none is.
const SceneStudyCase& find_case(const SceneStudiesOptions& o, const std::string& name);
std::string us(double s);
std::string ms(double s);
std::string mm(double m);
// A time or a length in the unit that reads best (a contact moved by 0.97 s, not 9.7e5 µs).
std::string duration(double s);
std::string length(double m);
// "1 contact", "2 contacts".
std::string counted(long n, const std::string& noun);
// The case's settings as the report states them (title, convention, coupling, frames, grid, σ …).
void store_scene_settings(Record& r, const SceneStudyCase& c, const SceneOptions& s);

}  // namespace stoneskip::scene_findings
