#pragma once
// Running a scene for a study: the heights at checkpoint frames kept (to compare two runs of the
// same scene field to field), the cost taken as the least of a few repeats (the least disturbed
// measurement on a shared machine), and the differences between two runs — what a shortcut or a
// coupling changes: contacts (matched in order), bounce count, first-touch points, the surface.
#include <vector>

#include "solvers/scene/coupled_scene.hpp"

namespace stoneskip {

struct ProbedScene {
  SceneSummary summary;                          // of the probing run
  std::vector<long> checkpoint_frames;
  std::vector<std::vector<double>> checkpoints;  // heights (nx·ny) at those frames
  double min_cpu_s = 0, min_wall_s = 0;          // least over the repeats (thread CPU, wall)
};

// Runs the scene once keeping the heights every `checkpoint_every` frames (0: none), then
// `repeats` (≥ 1) more times without a recorder for its cost.
ProbedScene run_probed(const SceneOptions& options, long checkpoint_every, int repeats);

struct SceneDifference {
  long contacts_a = 0, contacts_b = 0;
  int bounces_a = 0, bounces_b = 0;
  long common = 0;                    // contacts compared (the shorter list)
  double max_start_change_s = 0;      // over the compared contacts
  double max_end_change_s = 0;
  double max_touch_change_m = 0;      // first-touch points (horizontal)
  double first_contact_exit_speed_change_m_s = 0;
  double field_max_change_m = 0;      // over the common checkpoints
  double field_scale_m = 0;           // max |z| of run a over them
  double field_relative() const { return field_scale_m > 0 ? field_max_change_m / field_scale_m : 0; }
  bool identical() const;             // every number above equal (bit for bit)
};

SceneDifference compare_scenes(const ProbedScene& a, const ProbedScene& b);

}  // namespace stoneskip
