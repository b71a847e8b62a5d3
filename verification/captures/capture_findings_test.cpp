// Tests of a capture's findings record and of the capture verdict rule it stores.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <unistd.h>

#include "model/stone/mass_properties.hpp"
#include "model/stone/mesh.hpp"
#include "model/stone/stone.hpp"
#include "verification/captures/capture_findings.hpp"
#include "verification/captures/capture_throw.hpp"
#include "verification/study/verdict_rules.hpp"

using namespace stoneskip;

namespace {

// The inputs of a capture that passes every check (each flag 0/1; thresholds as CaptureVerdictRules).
Record clean_inputs() {
  const CaptureVerdictRules r;
  Record in;
  in.set("has_gyro", 1).set("samples", 300).set("min_samples", r.min_samples).set("rate_found", 1).set("rate_hz", 100.0);
  in.set("min_rate_hz", r.min_rate_hz).set("press_found", 1).set("release_found", 1).set("release_gap_s", 0.01);
  in.set("max_release_gap_s", r.max_release_gap_s).set("still_found", 1).set("throw_computed", 1).set("throw_finite", 1);
  in.set("calibration_error_g", 0.01).set("calibration_unusable_g", r.calibration_unusable_g);
  in.set("calibration_caveat_g", r.calibration_caveat_g).set("has_buttons", 1).set("release_at_end", 0);
  in.set("clipped_in_swing", 0).set("gyro_saturated_in_swing", 0).set("stamps_given", 1).set("lost_fraction", 0.0);
  in.set("lost_fraction_caveat", r.lost_fraction_caveat).set("jitter_s", 0.001).set("jitter_caveat_s", r.jitter_caveat_s);
  in.set("nominal_timestamps", 0).set("inferred_range_switches", 0).set("device_calibration", 1);
  in.set("measured_speed_m_s", 10.0).set("lever_speed_m_s", 9.0).set("speed_difference_m_s", 1.0);
  in.set("accel_lever_disagreement", r.accel_lever_disagreement).set("reader_warnings", 0);
  in.set("swing_peak_rate_deg_s", 800.0).set("min_swing_rate_deg_s", r.min_swing_rate_deg_s).set("gyro_held_in_swing", 0);
  return in;
}

// A small analysed capture written by hand: five samples, a release between the fourth and the
// fifth, a throw with a three-member ensemble.
CaptureAnalysis small_analysis() {
  CaptureAnalysis a;
  a.source = "cases/captures/Hand Made.log";
  a.format = "report_log";
  a.trace.source = a.source;
  a.trace.has_gyro = true;
  a.trace.calibration.accel_from_device = true;
  for (int k = 0; k < 5; ++k) {
    TraceSample s;
    s.t_s = 0.01 * k + (k == 2 ? 0.002 : 0.0);
    s.accel_g = Vec3(0, 0, 1 + 0.1 * k);
    s.rate_deg_s = Vec3(0, 0, 100.0 * k);
    s.buttons = k < 4 ? kButtonB : 0u;
    a.trace.samples.push_back(s);
    a.timing.index.push_back(k);
    a.timing.t_s.push_back(0.01 * k);
    a.timing.report_index.push_back(k);
    a.series.t_s.push_back(0.01 * k);
    a.series.accel_g.push_back(s.accel_g);
    a.series.buttons.push_back(s.buttons);
    a.series.flags.push_back(0);
  }
  a.timing.stats.ok = true;
  a.timing.stats.rate_hz = 100;
  a.timing.stats.period_s = 0.01;
  a.timing.stats.clock = ClockModel::regular_reports;
  a.press_found = a.release_found = a.still_found = true;
  a.still_t0_s = 0.0;
  a.still_t1_s = 0.01;
  a.release_sample = 3;
  a.release_t_low_s = 0.03;
  a.release_t_high_s = 0.04;
  a.release_t_s = 0.035;
  a.nominal_computed = true;
  a.still_accel_g = 1.01;
  a.still_accel_error_g = 0.01;
  a.nominal.measured_speed_m_s = a.nominal.lever_speed_m_s = 9.0;
  a.swing_peak_rate_deg_s = 300;  // written by hand, as the rest: a rate a turning wrist passes
  a.speed_m_s = {9.0, 8.5, 9.75};
  a.attack_angle_deg = {20, 19, 21};
  a.path_angle_deg = {5, 4, 6};
  a.spin_rev_s = {2, 1.9, 2.1};
  a.height_m = {0.3, 0.21, 0.39};
  a.measured_speed_m_s = a.speed_m_s;
  a.accel_speed_m_s = a.speed_m_s;
  a.lever_speed_m_s = a.speed_m_s;
  a.measured_spin_rev_s = a.spin_rev_s;
  a.rise_m = {0.1, 0.05, 0.15};
  a.ensemble.resize(3, a.nominal);
  a.options.rules.min_samples = 3;  // five samples are enough here
  a.verdict = Verdict::usable;
  return a;
}

// A nominal throw that makes 1 bounce in both solvers (no ensemble yet).
CaptureSimulation one_bounce_each() {
  CaptureSimulation sim;
  sim.realtime.emplace();
  sim.realtime->bounces = 1;
  sim.reference.emplace();
  sim.reference->bounces = 1;
  return sim;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capture_findings_)

BOOST_AUTO_TEST_CASE(the_capture_verdict_rule_decides_at_its_thresholds) {
  // Oracle: CaptureVerdictRules (capture_verdict.hpp) — a caveat or an unusable reason holds when
  // its finding is beyond the threshold ("more than", "below"), not at it.
  Record in = clean_inputs();
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("jitter_s", in.number("jitter_caveat_s"));
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("jitter_s", in.number("jitter_caveat_s") * (1 + 1e-9));
  BOOST_TEST(decide("capture_verdict", in) == "usable with caveats");
  in.set("stamps_given", 0);  // jitter and lost reports mean nothing without host stamps
  BOOST_TEST(decide("capture_verdict", in) == "usable");

  in = clean_inputs();
  in.set("rate_hz", in.number("min_rate_hz"));
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("rate_hz", 0.99 * in.number("min_rate_hz"));
  BOOST_TEST(decide("capture_verdict", in) == "unusable");

  in = clean_inputs();
  in.set("calibration_error_g", in.number("calibration_caveat_g"));
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("calibration_error_g", in.number("calibration_unusable_g"));
  BOOST_TEST(decide("capture_verdict", in) == "usable with caveats");
  in.set("calibration_error_g", 1.01 * in.number("calibration_unusable_g"));
  BOOST_TEST(decide("capture_verdict", in) == "unusable");

  in = clean_inputs();  // disagreement of the speeds: 25 % of 10 m/s
  in.set("speed_difference_m_s", -2.5);
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("speed_difference_m_s", -2.51);
  BOOST_TEST(decide("capture_verdict", in) == "usable with caveats");
  in.set("clipped_in_swing", 1);  // clipped: the accelerometer is a bound, not a check
  BOOST_TEST(capture_conditions(in).caveats == std::vector<std::string>{"clipped_in_swing"});

  in = clean_inputs();  // a gyro that shows no rotation through the swing: unusable at the threshold's edge
  in.set("swing_peak_rate_deg_s", in.number("min_swing_rate_deg_s"));
  BOOST_TEST(decide("capture_verdict", in) == "usable");
  in.set("swing_peak_rate_deg_s", 0.999 * in.number("min_swing_rate_deg_s"));
  BOOST_TEST(capture_conditions(in).unusable == std::vector<std::string>{"gyro_still"});
  in.set("has_gyro", 0);  // no MotionPlus at all says so, not that it stood still
  BOOST_TEST(capture_conditions(in).unusable == std::vector<std::string>{"no_gyro"});
  in = clean_inputs();  // one swing sample whose rate is held over a MotionPlus silence: unusable
  in.set("gyro_held_in_swing", 1);
  BOOST_TEST(capture_conditions(in).unusable == std::vector<std::string>{"gyro_held_in_swing"});

  in = clean_inputs();
  in.set("samples", in.number("min_samples") - 1).set("still_found", 0).set("reader_warnings", 2);
  const CaptureConditions c = capture_conditions(in);
  BOOST_TEST(c.unusable == (std::vector<std::string>{"too_few_samples", "no_still_part"}));
  BOOST_TEST(c.caveats == std::vector<std::string>{"reader_warnings"});
  BOOST_TEST(decide("capture_verdict", in) == "unusable");
}

BOOST_AUTO_TEST_CASE(judge_capture_gives_one_reason_per_condition_with_its_numbers) {
  // Oracle: the rule's conditions (capture_conditions) on the analysis's own inputs — one reason
  // each, unusable ones first, naming the measured value and the threshold.
  CaptureAnalysis a = small_analysis();
  a.timing.stats.jitter_s = 0.0042;
  a.trace.calibration.accel_from_device = false;
  judge_capture(a, a.options.rules);
  BOOST_TEST(std::string(to_string(a.verdict)) == "usable with caveats");
  BOOST_REQUIRE(a.reasons.size() == 2u);
  BOOST_TEST(a.reasons[0].find("jitter 4.2 ms") != std::string::npos, a.reasons[0]);
  BOOST_TEST(a.reasons[0].find("above 3 ms") != std::string::npos, a.reasons[0]);
  BOOST_TEST(a.reasons[1].find("no device calibration") != std::string::npos, a.reasons[1]);
  a.still_found = false;
  judge_capture(a, a.options.rules);
  BOOST_TEST(std::string(to_string(a.verdict)) == "unusable");
  BOOST_TEST(a.reasons.front().find("no still part of at least 0.2 s") != std::string::npos, a.reasons.front());
}

BOOST_AUTO_TEST_CASE(the_findings_read_back_from_hdf5_unchanged_and_their_verdicts_decide_again) {
  // Oracle: the analysis and the simulation themselves — the stored intervals are theirs bit for
  // bit, the record reads back from HDF5 equal, and every stored verdict is what its rule decides
  // from its stored inputs (both solvers' count ensembles all 1 bounce: the same count, by the exact
  // test; an ensemble from 0 to 2: undecided).
  CaptureAnalysis a = small_analysis();
  judge_capture(a, a.options.rules);
  CaptureSimulation sim = one_bounce_each();
  sim.agreement.factors = {1 - 1e-9, 1 + 1e-9, 1 - 1e-4, 1 + 1e-4};
  sim.agreement.realtime = sim.agreement.reference = {1, 1, 1, 1};
  sim.agreement.difference = welch_difference(sim.agreement.realtime, sim.agreement.reference);
  sim.ensemble_bounces = {0, 1, 2};
  sim.bounce_histogram = {{0, 1}, {1, 1}, {2, 1}};
  sim.bounces_low = 0;
  sim.bounces_median = 1;
  sim.bounces_high = 2;
  const Record r = capture_findings(a, sim, {"cases/x.toml", "prism", "physical", "newtonian"});
  BOOST_TEST(r.at("verdict").text("verdict") == std::string(to_string(a.verdict)));
  BOOST_TEST(r.at("throw").at("virtual").at("speed_m_s").number("high") == a.speed_m_s.high);
  BOOST_TEST(r.at("throw").at("measured").at("rise_m").number("low") == a.rise_m.low);
  BOOST_TEST(r.at("timing").table("intervals").rows() == 4u);
  BOOST_TEST(r.at("timing").table("intervals").column("interval_ms")[1] == 1e3 * (0.022 - 0.01));
  BOOST_TEST(r.at("motion").table("samples").column("button")[4] == 0.0);
  BOOST_TEST(r.at("simulation").at("agreement").text("verdict") == "same bounce count");
  BOOST_TEST(r.at("simulation").at("ensemble").at("spread").text("verdict") == "not decided by the capture");
  BOOST_TEST(r.at("simulation").at("ensemble").at("spread").text("reason").find("0 to 2 bounces") != std::string::npos);

  const auto file = std::filesystem::temp_directory_path() / ("capture-findings-" + std::to_string(::getpid()) + ".h5");
  {
    Hdf5Writer w(file);
    store_record(w.root().create_group("c"), r);
    w.commit();
  }
  Record back;
  {
    Hdf5Reader in(file);
    back = load_record(in.root().open_group("c"));
  }
  std::filesystem::remove(file);
  BOOST_TEST((back == r));
  BOOST_TEST(contradicted_verdicts(back).empty());
  Record forged = back;
  forged.child("verdict").set("jitter_s", 1.0);  // a stored input changed: the stored phrase no longer follows
  BOOST_TEST(contradicted_verdicts(forged).size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_failed_run_decides_no_count) {
  // Oracle: a failed run's bounces until the failure are not its count. The nominal pair (1 and 1
  // bounces, the reference failed), with one of the reference's count ensemble failed, is not "the
  // same count"; the ensemble whose surviving members
  // all make 1 bounce, with one member failed, is not "decided by the capture", and the failed
  // member is NaN in the stored table, not its partial count.
  CaptureAnalysis a = small_analysis();
  judge_capture(a, a.options.rules);
  CaptureSimulation sim = one_bounce_each();
  sim.reference->outcome = Outcome::failed;
  sim.agreement.factors = {1 - 1e-9, 1 + 1e-9, 1 - 1e-4, 1 + 1e-4};
  sim.agreement.realtime = {1, 1, 1, 1};
  sim.agreement.reference = {1, -1, 1, 1};
  sim.agreement.reference_failed = 1;
  sim.agreement.difference = welch_difference({1, 1, 1, 1}, {1, 1, 1});
  sim.ensemble_bounces = {1, -1, 1};
  sim.ensemble_failed = 1;
  sim.bounce_histogram = {{1, 2}};
  sim.bounces_low = sim.bounces_median = sim.bounces_high = 1;
  const Record r = capture_findings(a, sim, {"cases/x.toml", "prism", "physical", "newtonian"});
  const Record& m = r.at("simulation");
  BOOST_TEST(m.at("agreement").text("verdict") == "not decided: runs failed");
  BOOST_TEST(m.at("agreement").text("reason").find("(CVODE) fails after 1 bounce") != std::string::npos,
             m.at("agreement").text("reason"));
  BOOST_TEST(m.at("ensemble").at("spread").text("verdict") == "not decided: runs failed");
  BOOST_TEST(m.at("ensemble").number("failed") == 1.0);
  const auto counts = r.at("throw").table("ensemble").column("bounces_realtime");
  BOOST_REQUIRE(counts.size() == 3u);
  BOOST_TEST(std::isnan(counts[1]));
  BOOST_TEST(counts[0] == 1.0);
  BOOST_TEST(contradicted_verdicts(r).empty());
}

BOOST_AUTO_TEST_CASE(simulate_capture_marks_a_failed_member_and_keeps_it_out_of_the_spread) {
  // Oracle: each member run alone by run_realtime with the same options. A budget of 4 right-hand
  // sides per 0.5 s frame runs the state away, which fails the run (stone_stepper.hpp); such a
  // member is −1, counted in ensemble_failed, and in neither the histogram nor the quantiles.
  CaptureAnalysis a = small_analysis();
  a.nominal.velocity_m_s = Vec3(8, 0, -1.4);
  a.nominal.height_m = 0.1;
  a.ensemble.assign(2, a.nominal);
  const Mesh mesh = make_prism(0.03, 0.008, 11);
  const Stone stone = make_stone(mesh, mass_properties_from_density(mesh, 2500), 0.03, "test prism");
  const Environment env;
  CaptureSimulationOptions o;
  o.reference = false;
  o.realtime_options.rhs_per_frame = 4;
  o.realtime_options.frame_dt_s = 0.5;
  const CaptureSimulation sim = simulate_capture(stone, env, a, o);
  RealtimeOptions alone = o.realtime_options;
  alone.record_trajectory = false;
  const ThrowResult r = run_realtime(stone, env, capture_initial_state(stone, a.nominal), alone);
  BOOST_REQUIRE(r.outcome == Outcome::failed);  // the premise: the budget fails the throw
  BOOST_TEST(sim.ensemble_bounces == (std::vector<int>{-1, -1}), boost::test_tools::per_element());
  BOOST_TEST(sim.ensemble_failed == 2);
  BOOST_TEST(sim.bounce_histogram.empty());
  BOOST_TEST(sim.bounces_low == -1);
  BOOST_TEST(sim.bounces_high == -1);
}

BOOST_AUTO_TEST_CASE(a_count_that_the_clipped_bounds_allow_undecides_the_capture) {
  // Oracle: the rule bounce_spread — a clipped accelerometer only bounds the speed and the rise, so
  // the members (which need not reach the bounds) decide nothing the bounds' corners contradict.
  // Every member makes 0 bounces: decided when the corners make 0 too, not decided when one corner
  // makes 1, and not decided when a corner's run failed.
  CaptureAnalysis a = small_analysis();
  a.clipped = true;
  judge_capture(a, a.options.rules);
  CaptureSimulation sim = one_bounce_each();
  sim.ensemble_bounces = {0, 0, 0};
  sim.bounce_histogram = {{0, 3}};
  sim.bounces_low = sim.bounces_median = sim.bounces_high = 0;
  sim.corners = {{8.5, 0.21, 0}, {8.5, 0.39, 0}, {9.75, 0.21, 0}, {9.75, 0.39, 0}};
  auto spread = [&](const CaptureSimulation& s) {
    const Record r = capture_findings(a, s, {"cases/x.toml", "prism", "physical", "newtonian"});
    BOOST_TEST(contradicted_verdicts(r).empty());
    return r.at("simulation").at("ensemble");
  };
  const Record decided = spread(sim);
  BOOST_TEST(decided.at("spread").text("verdict") == "decided by the capture");
  BOOST_TEST(decided.table("bound_corners").column("speed_m_s") == (std::vector<double>{8.5, 8.5, 9.75, 9.75}),
             boost::test_tools::per_element());
  BOOST_TEST(decided.at("spread").text("reason").find("(8.5 to 9.75 m/s)") != std::string::npos, decided.at("spread").text("reason"));
  sim.corners[3].bounces = 1;
  const Record undecided = spread(sim);
  BOOST_TEST(undecided.at("spread").text("verdict") == "not decided by the capture");
  BOOST_TEST(undecided.at("spread").text("reason").find("makes 0 to 1 bounce") != std::string::npos,
             undecided.at("spread").text("reason"));
  sim.corners[3].bounces = -1;
  BOOST_TEST(spread(sim).at("spread").text("verdict") == "not decided: runs failed");
}

BOOST_AUTO_TEST_CASE(simulate_capture_runs_a_clipped_captures_nominal_throw_at_its_bounds_corners) {
  // Oracle: the nominal release scaled to each speed bound (same direction) at each height bound,
  // run alone by run_realtime with the same options. An unclipped capture has no corners.
  CaptureAnalysis a = small_analysis();
  a.nominal.velocity_m_s = Vec3(8, 0, -1.4);
  a.nominal.height_m = 0.1;
  a.ensemble.assign(1, a.nominal);
  a.speed_m_s = {a.nominal.velocity_m_s.norm(), 5.0, 14.0};
  a.height_m = {0.1, 0.05, 0.3};
  const Mesh mesh = make_prism(0.03, 0.008, 11);
  const Stone stone = make_stone(mesh, mass_properties_from_density(mesh, 2500), 0.03, "test prism");
  const Environment env;
  CaptureSimulationOptions o;
  o.reference = false;
  BOOST_TEST(simulate_capture(stone, env, a, o).corners.empty());
  a.clipped = true;
  const CaptureSimulation sim = simulate_capture(stone, env, a, o);
  BOOST_REQUIRE(sim.corners.size() == 4u);
  RealtimeOptions alone = o.realtime_options;
  alone.record_trajectory = false;
  std::size_t k = 0;
  for (const double speed : {5.0, 14.0})
    for (const double height : {0.05, 0.3}) {
      ReleaseKinematics r = a.nominal;
      r.velocity_m_s *= speed / r.velocity_m_s.norm();  // as simulate_capture scales it
      r.height_m = height;
      const ThrowResult t = run_realtime(stone, env, capture_initial_state(stone, r), alone);
      BOOST_TEST(sim.corners[k].speed_m_s == speed);
      BOOST_TEST(sim.corners[k].height_m == height);
      BOOST_TEST(sim.corners[k].bounces == (t.outcome == Outcome::failed ? -1 : t.bounces), "corner " << k);
      ++k;
    }
  // A nominal throw of zero speed has no direction to scale: its corners count as failed, so the
  // rule decides nothing from the members alone.
  a.nominal.velocity_m_s = Vec3::Zero();
  const CaptureSimulation still = simulate_capture(stone, env, a, o);
  BOOST_REQUIRE(still.corners.size() == 4u);
  for (const auto& c : still.corners) BOOST_TEST(c.bounces == -1);
}

BOOST_AUTO_TEST_CASE(section_keys_name_figures_and_never_collide) {
  // Oracle: the key rules (capture_findings.hpp) — lowercase letters, digits and '_', unique, never
  // the index section's name, never starting with '_'.
  std::vector<std::string> used;
  BOOST_TEST(capture_section_key("cases/captures/Gentle Sidearm.LOG", used) == "gentle_sidearm_log");
  BOOST_TEST(capture_section_key("other/gentle-sidearm.log", used) == "gentle_sidearm_log_2");
  BOOST_TEST(capture_section_key("index", used) == "index_2");
  BOOST_TEST(capture_section_key(".hidden", used) == "capture_hidden");
  BOOST_TEST(used.size() == 4u);
}

BOOST_AUTO_TEST_SUITE_END()
