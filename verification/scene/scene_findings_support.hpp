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
// A quantity a section's tables and reasons carry.
struct SectionQuantity {
  const char* key;    // its column in the section's tables (and the suffix of its verdict inputs)
  const char* words;  // as the reasons name it
  double scale;       // to the unit it is said in
  const char* unit;
};
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
// The items joined by `separator`.
std::string joined(const std::vector<std::string>& items, const std::string& separator);
// "1 contact", "2 contacts".
std::string counted(long n, const std::string& noun);
// The scene on a pond of pond_m × pond_m around a first touch (a quarter of the pond behind it, in
// the middle across), cells of cell_m, the water step dt_s: what the grid section runs. A case
// starting from a disturbed surface has it sampled afresh at the pond's cell points
// (sample_disturbance_at, the case's own grid as the shape's frame); grid_case_problem has
// refused a surface that cannot be.
void place_on_pond(SceneOptions& s, const SceneStudyCase& c, const Vec3& first_touch_m, double pond_m, double cell_m, double dt_s);
// Where the walls of that pond stand against a case's first contact (its track on still water, the
// stone's disk around it): the nearest wall's distance and when a wave from it, at c, first
// reaches the track.
struct PondWalls {
  double nearest_m = 0;     // the nearest wall to the track, less the disk's radius
  double reach_s = 0;       // nearest_m / c
  bool inside_case = true;  // the pond lies within the case's own field (or the case's is periodic)
};
// The case starts from a disturbed surface with a shape (some initial height is not 0).
bool starts_disturbed(const SceneStudyCase& c);
// A shape in words: "a plane wave 2 cm high and 1 m long, its crests across x" …
std::string initial_surface_words(const Disturbance& d);
PondWalls pond_walls(const SceneStudyCase& c, const ContactRecord& first, double pond_m, double cell_m);
// The same pond, placed around `touch` (the first touch on still water, as place_on_pond places
// it), against another contact's track: a grid's own first contact, which on live water may run
// longer and elsewhere than on still water.
PondWalls pond_walls(const SceneStudyCase& c, const Vec3& touch, const ContactRecord& track, double pond_m, double cell_m);
// The case's settings as the report states them (title, convention, coupling, frames, grid, σ …).
void store_scene_settings(Record& r, const SceneStudyCase& c, const SceneOptions& s);

}  // namespace stoneskip::scene_findings
