#pragma once
// The findings of a capture for its report section (`stoneskip capture validate FILE... --out DIR`,
// report kind "captures", reports/capture/capture_report.hpp): every number, verdict and reason the
// page says, computed here from the analysis (capture_analysis.hpp) and the solvers' runs
// (capture_throw.hpp). The renderer only formats them, so `stoneskip report render DIR` rebuilds
// the page from data.h5 alone.
//
// One section per capture (capture_findings), named by capture_section_key, then the section
// "index" (capture_index_findings). A capture's record:
//   file, format                       texts: the file as given, the reader that read it
//   verdict                            rule capture_verdict, its inputs (capture_verdict_inputs) and
//                                      the reasons joined into one sentence
//   reasons, notes, reader_warnings    string lists (the warnings: the first 20; reader_warnings_total)
//   settings                           mounting and thrower ("key=value" lists), the clock model,
//                                      the action button, the ensemble's perturbations, its seed
//   timing                             rate, jitter, gaps, clock (capture_timing.hpp); table
//                                      `intervals`: t_s, interval_ms (as stamped), lost_reports,
//                                      stamp_minus_clock_ms
//   motion                             saturation (levels, counts per axis, spans table), still part
//                                      (times, |a|, the gyro bias, range switches), release (times);
//                                      table `samples`: t_s, ax_g…, wx_deg_s… (bias removed once the
//                                      still part is known), clipped, stone_speed_m_s, lever_speed_m_s
//   throw                              computed (0/1); intervals as children {nominal, low, high}:
//                                      `virtual` (speed_m_s, attack_angle_deg, path_angle_deg,
//                                      spin_rev_s, height_m) and `measured` (speed_m_s,
//                                      accel_speed_m_s, lever_speed_m_s, spin_rev_s, rise_m); the
//                                      accelerometer's bounds; tables `ensemble` (one row a member)
//                                      and `room_path` (the stone in the room, still part → release)
//   simulation                         ran (0/1), case_file, stone_description; `realtime`,
//                                      `reference` (solver, bounces, outcome, distance, CPU and wall
//                                      time, trajectory and contacts tables); `ensemble` (histogram,
//                                      2.5/50/97.5 % bounce counts, CPU and wall time, verdict
//                                      `spread`: rule bounce_spread); verdict `agreement` (rule
//                                      bounce_agreement) when both solvers ran
//   truth                              a synthetic capture with a truth file beside it: each
//                                      quantity's truth against its estimate and interval
//                                      (capture_truth.hpp; added by `capture validate`)
// The place for the coupled scene (not built yet): a child `scene` of this record,
// made by a scene study from the same analysis (the stone against the CVODE reference, the waves
// against the forced spectral reference), and one more part of the capture's section to render it.
#include <string>
#include <utility>
#include <vector>

#include "verification/captures/capture_throw.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct CaptureFindingsContext {
  std::string case_file;          // the stone and water the solvers ran with ("" when they did not run)
  std::string stone_description;
  std::string convention;         // the water model's convention (paper / physical) …
  std::string water_law;          // … and its water law
};

// A section key for a capture file: its file name in lowercase letters, digits and '_' (so it also
// names the figures), made unique among `used` (which receives it).
std::string capture_section_key(const std::string& file, std::vector<std::string>& used);

Record capture_findings(const CaptureAnalysis& a, const CaptureSimulation& sim, const CaptureFindingsContext& c);

// The index section: `captures` (the capture sections' keys, in order), the verdicts counted
// (`usable`, `usable_with_caveats`, `unusable`, `count`), the stone case (`case_file`,
// `stone_description`, `convention`, `water_law`; empty when the solvers did not run) and the
// quantiles of the ensembles' ranges (`low_percent`, `high_percent`).
Record capture_index_findings(const std::vector<std::pair<std::string, Record>>& captures,
                              const CaptureFindingsContext& context);

}  // namespace stoneskip
