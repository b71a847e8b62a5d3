#pragma once
// The verdict on a capture: unusable, usable with caveats, or usable, with the reasons — decided
// from the analysis's findings alone by the thresholds below, each with why it is where it is.
// The decision is the verdict rule `capture_verdict` (verification/study/verdict_rules.hpp): the
// findings and thresholds go in as numbers (capture_verdict_inputs), so a stored verdict can be
// decided again from data.h5; this file words the reasons.
#include <cstddef>
#include <string>
#include <vector>

#include "verification/study/record.hpp"

namespace stoneskip {

enum class Verdict { usable, usable_with_caveats, unusable };
const char* to_string(Verdict v);

struct CaptureVerdictRules {
  // --- unusable ---
  // A swing of ≈ 0.2 s at 100 Hz and a still part of min_still_s need more than this many samples.
  std::size_t min_samples = 10;
  // A throw's swing lasts ≈ 0.1–0.2 s (model/README.md §4: 7–20 g over 0.1–0.15 s); below 20 Hz it holds 2–4
  // samples and the rate integration cannot follow it.
  double min_rate_hz = 20.0;
  // The release falling in a longer gap is interpolated over half a swing: its state is unknown.
  double max_release_gap_s = 0.1;
  // Still-part |a| off 1 g by more: the calibration is wrong (3× the caveat level; an ADXL330
  // zero-g offset alone stays within ≈ 0.05 g after the factory calibration).
  double calibration_unusable_g = 0.15;
  // Plausible for a human throw. The hand moves no faster than a ball it releases, and the fastest
  // human throws, elite baseball pitches, release the ball at ≈ 40–45 m/s (Fleisig et al. 1999,
  // J. Biomech. 32, 1371): above max_release_speed_m_s the capture is not a hand's. Below
  // min_release_speed_m_s it is no throw (a gentle underhand toss ≈ 3–5 m/s; skimming needs
  // ≥ 5 m/s, Clanet, Hersen & Bocquet 2004).
  double max_release_speed_m_s = 45.0;
  double min_release_speed_m_s = 1.0;
  // From the end of the still part to the release the hand stays within an arm's reach (≈ 1–2 m
  // for an adult, shoulder to fingertip about 0.75 m, swung about a turning body) plus a stride:
  // a stone further than this from where it was held still is integration drift, not a throw.
  double max_hand_displacement_m = 3.0;
  // A swing whose angular rate never departs from the still part's by this much did not reach the
  // gyro: a throwing wrist turns at hundreds of deg/s (the MotionPlus's fast range, to ≈ 2000 deg/s,
  // exists for it), its noise is ≈ 1 deg/s. A stuck or missing MotionPlus stream (its first report
  // repeated, a gesture file's centred counts) reads 0 here, and the orientation and the lever
  // arm's velocity are then nothing but the accelerometer's guesses.
  double min_swing_rate_deg_s = 20.0;
  // --- caveats ---
  // Still-part |a| off 1 g by more: check the calibration (a 0.05 g offset tilts gravity by 3°).
  double calibration_caveat_g = 0.05;
  // More reports lost than this fraction: the integration bridges gaps by straight lines.
  double lost_fraction_caveat = 0.02;
  // Interval jitter above 3 ms (30 % of a 100 Hz period): the clock is poorly known.
  double jitter_caveat_s = 0.003;
  // Accelerometer and lever-arm speeds differing by more than this fraction of the speed, without
  // clipping: the mounting's lever arm is probably wrong (the lever model ignores the pivot's own
  // motion, typically 10–20 % of a side-arm throw's speed).
  double accel_lever_disagreement = 0.25;
  // The stone's normal further than this from the vertical at release: skipping throws release the
  // stone near flat (attack angles 0–45°, Clanet, Hersen & Bocquet 2004, and a few degrees of
  // roll), so a larger tilt says the mounting (stone_normal, stone_forward) does not describe how
  // the remote was strapped on (upside down, a stone symmetric top to bottom skips the same with
  // its spin reversed, but the attack angle reads as 180° minus it).
  double max_tilt_deg = 60.0;

  bool is_valid(std::string* why) const;
};

struct CaptureAnalysis;
struct Trace;

// The inputs of the rule `capture_verdict`: a's findings and the rules' thresholds, as numbers.
Record capture_verdict_inputs(const CaptureAnalysis& a, const CaptureVerdictRules& rules);
// The verdict phrase as the enum ("usable", …); unusable for an unknown phrase.
Verdict verdict_from_phrase(const std::string& phrase);

// The verdict and its reasons (unusable reasons first, then caveats), from a's findings; notes
// (information that does not change the verdict) are appended to a.notes. Fills a.verdict,
// a.reasons.
void judge_capture(CaptureAnalysis& a, const CaptureVerdictRules& rules);

}  // namespace stoneskip
