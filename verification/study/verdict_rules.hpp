#pragma once
// Every rule that turns numbers into a verdict, in one place. A verdict record (a child of a
// finding) holds the rule's name, its inputs as numbers, the verdict phrase and a computed reason;
// decide() gives the phrase from the inputs alone, so a verdict can be decided again from data.h5
// (the reports' consistency test does, for every verdict stored).
//
// Rules (inputs → phrases):
//   order_fit            valid, order, order_low, order_high, points, expected_order, tolerance,
//                        minimum_order, refinements, growing_refinements (pairwise orders ≤ 0),
//                        failed_points, corrected, shape_tested, curved, local_order_coarse,
//                        local_order_fine (the last six absent from older records) →
//                        verification/convergence/order_fit.hpp judge_order()
//   consistency          constant_term, laplacian_coefficient, tolerance → consistent | inconsistent
//   gci_band             usable, order_does_not_converge, gci_fine, actual_relative_error →
//                        no estimate | misleading | contains the exact value | misses the exact value
//   limit_range          limit_min, limit_max, tolerance → independent of the damping | depends on the damping
//   counterexample       sigma, bound, predicted_growth_per_step, measured_growth_per_step →
//                        not sufficient | not refuted by this example | example outside the bound
//   work_gain            gain, material_gain → not established | no other stencil is materially faster |
//                        another stencil is faster
//   minimum_ratio        ratio, required → not measured | error control works | error control falls short
//   thresholds_near_grid near_grid, bisected, unlocated (changes not bisected or whose bisection
//                        stopped at a failed run, plus grid cells holding more changes than the one
//                        bisected; absent in older data: taken as 0) →
//                        too few thresholds to tell (bisected < 3) | sensitive dependence (half or
//                        more of the bisected within two tolerances of a grid value) | not all
//                        changes located (unlocated > 0) | clean steps
//   attack_change        change_deg, tolerance_deg → no contact (NaN) | nose-down | nose-up | held
//                        (|change| ≤ tolerance)
//   roll_change          change_deg, tolerance_deg → no contact | rolls (roll falls) | rolls (roll grows) | held
//   max_fluid_power      max_fluid_power_W, round_off_W → passive | creates energy
//   contact_energy       contacts, max_residual_ratio, max_gain_ratio (each contact's |ΔE − ∫P dt| and
//                        ΔE over its tolerance, the largest) → no contact | unbalanced (a ratio above 1 or
//                        NaN) | balanced, passive | balanced, creates energy
//   surfing              contacts, bounces, duration_s (the first contact's), plunge_s (ThrowHistory),
//                        surf_plunge_ratio → no contact | leaves the water | never leaves the water (no
//                        bounce, the contact ≥ ratio × plunge) | sinks as it plunges | not decided: no
//                        plunge time (records without duration_s, written before: the count alone)
//   diving               bounces, attack_change_deg, tolerance_deg → bounces | tumbles and dives
//                        (|first contact's attack change| > tolerance) | sinks holding its attitude
//   trout                bounces, entry_attack_deg, min_attack_deg, tolerance_deg → no bounce |
//                        dips and still bounces (entry − min over the first contact > tolerance) |
//                        bounces without a dip
//   error_split          space_converges (0/1), time_at_expected (0/1) → (see verdict_rules.cpp)
//   capture_verdict      the findings of a Wii Remote capture and CaptureVerdictRules' thresholds
//                        (verification/captures/capture_verdict.hpp; inputs: capture_conditions
//                        below) → usable | usable with caveats | unusable
//   bounce_agreement     realtime_bounces, reference_bounces, realtime_failed, reference_failed →
//                        not decided: a run failed | same bounce count | different bounce counts
//   bounce_spread        bounces_low, bounces_high (the ensemble's interval quantiles), failed_runs →
//                        not decided: runs failed | decided by the capture | not decided by the capture
//   ensemble_bounce_agreement  valid, difference_low, difference_high (95 % interval of the two
//                        ensembles' mean bounce counts), count_spread, realtime_failed,
//                        reference_failed (runs without a count) → not measured |
//                        not decided: runs failed | different bounce counts |
//                        no difference established | same bounce count
//   ensemble_count_difference  valid, difference_low, difference_high (95 % interval of two
//                        settings' ensemble mean counts: two meshes, or a throw and its mirror),
//                        count_spread, failed_runs (runs of either ensemble without a count) →
//                        not measured | not decided: runs failed | different bounce counts |
//                        no difference established | same bounce count
//   coupling_change      difference_low, difference_high (95 % interval of the ensembles' mean bounce
//                        counts, verification/study/ensemble_difference.hpp), count_spread (sum of
//                        their standard deviations), max_time_change_s (first contact),
//                        time_tolerance_s, failed_runs (runs without a count) → not decided: runs
//                        failed | changes the bounce count | no difference established |
//                        moves the contacts | no visible change
//                        (all three: where stored, exact_p and alpha: with no spread in either
//                        ensemble the interval is the difference itself, and the exact permutation
//                        test's p ≤ alpha decides; a difference it does not establish is "no
//                        difference established")
//   coupled_limit        growth_below, growth_above, growth_free_above, growth_tolerance →
//                        stable below the limit, unstable above it | the limit is not confirmed
//   ring_speed           valid, speed_low, speed_high, predicted_low, predicted_high → not measured |
//                        within c less the scheme's dispersion | faster than c |
//                        slower than the scheme's dispersion explains
//   shortcut             field_relative, start_change_s, count_change, field_tolerance, time_tolerance_s →
//                        exact | within tolerance | beyond tolerance
//   speed_target         value, target → meets the target | misses the target
//   reference_resolves   reference_error_m, smallest_error_m, margin → the reference resolves the errors
//                        (margin · reference error ≤ smallest error) | the reference's own error is too
//                        large to measure the smallest error
//   power_law_exponent   valid, exponent, exponent_low, exponent_high, points, expected, tolerance
//                        (and curved, where stored) → too few points to fit | not a single power
//                        law | consistent with the expected exponent | excludes the expected
//                        exponent | exponent not established
//                        (the 95 % interval decides, as for order_fit: within expected ± tolerance,
//                        entirely outside it, or neither; fewer than 3 points or no fit: too few;
//                        curved, the series bending in log–log coordinates by the F test of
//                        verification/convergence/power_law_shape.hpp: not a single power law)
//   skips_like_a_stone   a variant's min_speed, best_attack (and, where stored, best_attack_tied_low/
//                        high: the span of grid angles whose minimum speeds tie with the lowest, all
//                        of which must lie within the bound), max_path_angle, contact_time,
//                        contact_exponent_low/high, pitch_change_deg, roll_change_deg, surfing, diving,
//                        trout (0/1: reproduced), max_residual_ratio, max_gain_ratio; the measured
//                        ranges (min_speed_low/high, best_attack_low/high, max_path_angle_low/high,
//                        contact_time_low/high, contact_exponent_measured) and the bounds
//                        (min_speed_fraction, best_attack_bound, max_path_angle_bound,
//                        contact_time_fraction, attitude_bound_deg, contact_exponent_tolerance);
//                        optional min_speed_half_width, max_path_angle_half_width (the bisections'
//                        brackets) → not passive (as contact_energy: unbalanced or creates energy) |
//                        skips like a real stone | "misses R, …[; not decided: R, …]" | "not
//                        decided: R, …" (the rows: U_min within the range ± fraction, argmin α and
//                        β_max within the range ± bound, contact time within the range ± fraction,
//                        the exponent's interval within the measured exponent ± tolerance, |pitch|
//                        and |roll| change ≤ bound, the three regimes; a bracketed value is met
//                        when its whole bracket is within, missed when none of it is, else not
//                        decided, and so is the exponent's interval; without a tolerance (older
//                        records) the interval need only contain the measured exponent; a NaN
//                        misses)
//   cheapest_skipping_variant  per variant V: V.<the variant inputs above>, V.free (1: free attitude),
//                        V.cost_s, V.distance; the ranges and bounds unprefixed →
//                        "V is the cheapest passive law and distribution that skips like a real
//                        stone" (free variants only, every row met; the cheapest by cost_s, ties
//                        to the smaller distance) | "no variant skips like a real stone; no free
//                        variant meets R, …; closest: V (k of 9 rows)" (the rows no free variant
//                        meets: each misses them or leaves them not decided; the most rows met,
//                        then the smaller distance, then the name)
//   restart_strategy     per strategy S: S.failed, S.error_ratio, S.rhs_evaluations →
//                        "S is the cheapest strategy that keeps the contact times" |
//                        no strategy keeps the contact times (S keeps them with no failed run and
//                        error_ratio — its worst contact-time error over its tolerance, the largest
//                        over every method and rtol — at most 1; cheapest by rhs_evaluations, ties
//                        by name)
#include <string>
#include <vector>

#include "verification/study/record.hpp"

namespace stoneskip {

// The verdict phrase of `rule` for the inputs in `inputs` (its numbers). RecordError for an
// unknown rule or a missing input.
std::string decide(const std::string& rule, const Record& inputs);

// Child `key` of `parent`: the inputs' numbers, `rule`, `verdict` = decide(rule, inputs) and
// `reason`. Returns the child.
Record& decide_verdict(Record& parent, const std::string& key, const std::string& rule, const Record& inputs,
                       const std::string& reason);

// capture_verdict: which of its conditions hold, by name, in the order a capture's reasons list
// them (unusable ones, then caveats). Inputs (numbers; flags 0/1): has_gyro, samples, min_samples,
// rate_found, rate_hz, min_rate_hz, press_found, release_found, release_gap_s, max_release_gap_s,
// still_found, throw_computed, throw_finite, calibration_error_g, calibration_unusable_g,
// calibration_caveat_g, has_buttons, release_at_end, clipped_in_swing, gyro_saturated_in_swing,
// stamps_given, lost_fraction, lost_fraction_caveat, jitter_s, jitter_caveat_s,
// nominal_timestamps, inferred_range_switches, device_calibration, measured_speed_m_s,
// lever_speed_m_s, speed_difference_m_s, accel_lever_disagreement, reader_warnings, and (when
// stored) release_speed_m_s, min/max_release_speed_m_s, hand_displacement_m, max_hand_displacement_m,
// release_tilt_deg, max_tilt_deg, swing_peak_rate_deg_s, min_swing_rate_deg_s, gyro_held_in_swing.
// Unusable: no_gyro, too_few_samples, no_rate, rate_too_low, no_press, release_in_gap,
// no_still_part, gyro_held_in_swing, gyro_still, state_not_finite, calibration_wrong, release_speed_implausible,
// hand_displacement_implausible. Caveats: no_release_signal, button_held_at_end,
// clipped_in_swing, gyro_saturated, reports_lost, jitter, calibration_off, no_timestamps,
// range_switches_inferred, nominal_calibration, accel_lever_disagree, reader_warnings,
// attitude_implausible.
struct CaptureConditions {
  std::vector<std::string> unusable, caveats;
};
CaptureConditions capture_conditions(const Record& inputs);

// Every verdict record under `r` (at any depth) whose stored phrase differs from what its rule
// decides from its stored inputs, as "path: stored 'x', rule says 'y'" lines. Empty: consistent.
std::vector<std::string> contradicted_verdicts(const Record& r);

}  // namespace stoneskip
