#pragma once
// The level between water steps (model/README.md §2.4; model/water/height_field_surface.hpp): the
// scene's first contact at its own cell on water steps of step_fractions of its own, the stone
// reading the level held over each step and extrapolated from the last two, each against the same
// scene on a step reference_step_fraction of its own (extrapolated; held there beside it, whose
// gap bounds what the reference resolves). Part of the grid section (scene_grid_findings.cpp),
// into its child "water_step". Internal to verification/scene.
#include "verification/scene/scene_studies.hpp"

namespace stoneskip::scene_findings {

// `base`: the grid section's scene (two-way, full steps, one thread) of case `c` (whose initial
// surface, if any, each pond samples afresh); `touch`: its first contact on still water, around
// which the pond is put; `end_s`: when the runs stop.
void water_step_study(const SceneOptions& base, const SceneStudyCase& c, const ContactRecord& touch, double end_s,
                      const SceneGridOptions& g, const ProgressFactory& progress, Record& out);

}  // namespace stoneskip::scene_findings
