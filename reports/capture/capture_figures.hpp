#pragma once
// The figures of one capture's section, each built from its stored record (verification/captures/
// capture_findings.hpp says what it holds) and named "<key>_<figure>" so that the captures of one
// report do not collide. Every figure marks the same phases in the same colours: the still part
// green, the swing blue, clipped spans red, the release interval grey with the release dashed.
#include <optional>
#include <string>

#include "reports/common/figure.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

// Acceleration and angular rate against time over the whole capture, phases marked.
Figure capture_motion_figure(const std::string& key, const Record& capture);
// The same zoomed on the swing, with the stone's speed (integrated accelerometer, ω × lever arm)
// and the release estimates with their intervals. Needs the throw (throw.computed).
std::optional<Figure> capture_swing_figure(const std::string& key, const Record& capture);
// Intervals between reports against time (period, jitter, gaps), the stamps' distance from the
// clock used, and the distribution of the intervals. None without host timestamps.
std::optional<Figure> capture_timing_figure(const std::string& key, const Record& capture);
// The release state with its intervals and the ensemble, the throw in the room beside the virtual
// stone for each quantity.
std::optional<Figure> capture_release_figure(const std::string& key, const Record& capture);
// The stone's path in the room (from above, from the side) beside the virtual stone's flight over
// the water.
std::optional<Figure> capture_room_and_water_figure(const std::string& key, const Record& capture);
// Height against distance of the nominal throw, real-time model and reference, contacts marked.
std::optional<Figure> capture_trajectory_figure(const std::string& key, const Record& capture);
// Bounce counts of the ensemble, the nominal throw's counts marked.
std::optional<Figure> capture_bounce_figure(const std::string& key, const Record& capture);
// The throw through the coupled scene (child `scene`, verification/captures/capture_scene_findings.hpp):
// height against distance of the scene's stone, the stepper on still water and CVODE, contacts
// marked; and the surface along the grid row through the first contact at the scene's last frame:
// the scene, the leapfrog driven by CVODE's draught, the semi-discrete and the continuum references.
std::optional<Figure> capture_scene_stone_figure(const std::string& key, const Record& capture);
std::optional<Figure> capture_scene_wave_figure(const std::string& key, const Record& capture);

// The words for the head that forces the capture scene's water, from its settings' `forcing`
// (solvers/scene/coupled_scene.hpp): the faces' pressure head, or the draught b. Records written
// before `forcing` was stored get words that name neither.
struct WaveForcingWords {
  std::string name;        // "the pressure head"
  std::string short_name;  // "pressure head"
  std::string feedback;    // what the scene's own forcing adds to the stone's path
  std::string gathering;   // how the scene gathers the head over a water step
};
WaveForcingWords wave_forcing_words(const Record& settings);

}  // namespace stoneskip
