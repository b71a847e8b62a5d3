// A measured throw through the coupled scene against both references (capture_scene.hpp), checked
// against closed forms and independent computations: the pose between samples exact for a
// ballistic path (a cubic Hermite curve holds a parabola), the scene without water identical to the
// stepper on still water, the scene's contacts against CVODE within what the stepper's flight step
// explains, and the forced leapfrog driven by the CVODE trajectory's pressure head, gathered with
// the leapfrog's hat weights, converging to the stencil's exact semi-discrete forced solution at
// second order in time (within the fitted order's 95 % interval).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "verification/captures/capture_scene.hpp"
#include "verification/captures/capture_scene_findings.hpp"
#include "verification/convergence/order_fit.hpp"
#include "verification/study/verdict_rules.hpp"

using namespace stoneskip;

namespace {

Stone prism_stone() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
}

// The skipping throw of the shipped capture skip_12ms_14revs.log, as its truth file gives it
// (12 m/s, path 5°, attack 20°, 14 rev/s with the fingers' spin, 0.3 m above the water), onto a
// small periodic pond of 4 cm cells around its first contacts, two-way coupled.
CaptureSceneOptions skipping_options(double duration_s) {
  CaptureSceneOptions o;
  SceneOptions& s = o.scene;
  s.stone = prism_stone();
  ThrowParameters tp;
  tp.speed_m_s = 12;
  tp.path_angle_deg = 5;
  tp.attack_angle_deg = 20;
  tp.spin_rev_s = 14;
  tp.height_m = 0.3;
  s.initial = initial_state(s.stone, tp);
  s.stone_steps.dt_s = 1e-3;
  s.stone_steps.contact_dt_s = 1e-5;
  s.coupling = Coupling::two_way;
  s.draught_samples = 8;
  s.frame_rate_hz = 100;
  s.duration_s = duration_s;
  SceneWater w;
  w.field.nx = 48;
  w.field.ny = 16;
  w.field.cell_m = 0.04;
  w.field.wave_speed_m_s = 0.5;
  w.field.damping_per_s = 0.2;
  w.field.dt_s = 0.01;  // σ = 0.125, below the coupled limit
  w.field.stencil = named_stencil("nine_point_isotropic");
  w.field.boundary = Boundary::periodic;
  w.placement.origin_x_m = 0;
  w.placement.origin_y_m = -0.32;
  s.water = w;
  o.reference.rtol = 1e-10;
  o.quadrature_interval_s = 2.5e-5;  // fine enough that the reference's error lies below the finest leapfrog's
  o.agreement.members = 0;            // the count ensembles cost 2 × 16 throws: only where a test looks at them
  return o;
}

// Order in time: the forced leapfrog with Δt, Δt/2, Δt/4, Δt/8 (same grid), forced by the CVODE
// throw's pressure head gathered with the leapfrog's hat weights on pieces of the scene's contact
// step (as the scene gathers it), against the same semi-discrete solution. The head is
// continuous in time (a face's wetted area grows from zero) with kinks where the rim crosses cell
// edges; the hat weights are the second difference's exact weights, so the order is 2.
void expect_second_order_in_time(const CaptureSceneOptions& o, const CaptureSceneComparison& c) {
  const HeightFieldOptions& f = o.scene.water->field;
  const TrajectoryPose pose(c.reference.trajectory);
  const DraughtField h = trajectory_pressure_head(o.scene.stone, o.scene.environment, f, o.scene.water->placement, pose,
                                                  kPressureSmoothingPasses);
  std::vector<double> errors, steps_s;
  for (int halvings = 0; halvings <= 3; ++halvings) {
    HeightFieldOptions finer = f;
    finer.dt_s = f.dt_s / (1 << halvings);
    const auto z = hat_forced_leapfrog(finer, {}, h, o.scene.stone_steps.contact_dt_s, c.waves.steps << halvings);
    double e = 0;
    for (std::size_t i = 0; i < z.size(); ++i) e = std::max(e, std::abs(z[i] - c.waves.semi_discrete_m[i]));
    errors.push_back(e);
    steps_s.push_back(finer.dt_s);
  }
  BOOST_TEST(errors.front() == c.waves.time_m);  // the study's time error is the coarsest of these
  const OrderFit fit = fit_order(steps_s, errors);
  BOOST_TEST_MESSAGE(to_string(f.boundary) << " pond: hat-weighted forced leapfrog: time errors " << errors[0] << " … "
                                           << errors[3] << " m, " << fit.brief());
  BOOST_REQUIRE(fit.valid);
  BOOST_TEST(fit.order_low <= 2.0, to_string(f.boundary));   // second order inside the fit's 95 % interval …
  BOOST_TEST(fit.order_high >= 2.0, to_string(f.boundary));
  constexpr double kFirstOrderExcluded = 1.5;  // … and first order well outside it
  BOOST_TEST(fit.order_low > kFirstOrderExcluded, to_string(f.boundary));
  // Every error measured lies above the reference's own error (this is what makes them measurable).
  BOOST_TEST(c.waves.quadrature_m * kReferenceMargin < errors.back(), to_string(f.boundary));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capture_scene)

BOOST_AUTO_TEST_CASE(pose_between_samples_is_exact_for_a_parabola) {
  // Oracle: closed form — a ballistic path x = x0 + v t, z = z0 + w t − g t²/2 is a cubic, which
  // Hermite interpolation from positions and velocities reproduces exactly; a constant rotation
  // rate is reproduced by slerp.
  constexpr double kRoundoff = 1e-13;  // a few hundred ulps of a unit quantity
  const double g = 9.81;
  std::vector<TrajectorySample> samples;
  for (int k = 0; k <= 10; ++k) {
    TrajectorySample s;
    s.t_s = 0.01 * k * k;  // uneven spacing
    s.state.position_m = Vec3(1 + 3 * s.t_s, 0.5, 2 + 4 * s.t_s - 0.5 * g * s.t_s * s.t_s);
    s.state.velocity_m_s = Vec3(3, 0, 4 - g * s.t_s);
    s.state.orientation = Quat(Eigen::AngleAxisd(2.0 * s.t_s, Vec3::UnitZ()));
    samples.push_back(s);
  }
  const TrajectoryPose pose(samples);
  for (double t : {0.003, 0.137, 0.5, 0.999}) {
    const auto s = pose.at(t);
    BOOST_REQUIRE(s);
    BOOST_TEST(std::abs(s->position_m.x() - (1 + 3 * t)) < kRoundoff);
    BOOST_TEST(std::abs(s->position_m.z() - (2 + 4 * t - 0.5 * g * t * t)) < kRoundoff);
    BOOST_TEST(s->orientation.angularDistance(Quat(Eigen::AngleAxisd(2.0 * t, Vec3::UnitZ()))) < kRoundoff);
  }
  BOOST_TEST(!pose.at(1.0001));  // after the last sample the stone has left
}

BOOST_AUTO_TEST_CASE(scene_without_water_is_the_still_water_stepper) {
  // Oracle: model/README.md §2.4 — coupling none is the still-water throw bit for bit, so the scene's and the
  // still-water stepper's contacts are the same numbers.
  CaptureSceneOptions o = skipping_options(0.5);
  o.scene.coupling = Coupling::none;
  const CaptureSceneComparison c = compare_capture_scene(o);
  BOOST_TEST(!c.waves_compared);
  BOOST_REQUIRE(!c.contacts.empty());
  for (const auto& k : c.contacts) {
    BOOST_TEST(k.scene_start_s == k.still_start_s);
    BOOST_TEST(k.scene_end_s == k.still_end_s);
  }
}

BOOST_AUTO_TEST_CASE(skipping_capture_through_the_scene_against_both_references) {
  // Oracles: CVODE (rtol 1e-10) for the stone; the stencil's exact semi-discrete forced solution
  // (model/README.md §2.5) for the forced leapfrog driven by the CVODE trajectory's pressure head.
  // The comparison ends at 0.3 s, after the first bounces.
  CaptureSceneOptions o = skipping_options(0.3);
  o.agreement.members = 8;
  const CaptureSceneComparison c = compare_capture_scene(o);
  BOOST_REQUIRE(c.waves_compared);
  BOOST_TEST_MESSAGE("bounces scene " << c.scene.stone.bounces << " still " << c.still_water.bounces << " reference "
                                      << c.reference.bounces << "; contacts compared " << c.contacts.size()
                                      << ", start differences scene " << c.max_start_difference_s << " s, still "
                                      << c.still_max_start_difference_s << " s");
  BOOST_TEST_MESSAGE("waves at " << c.waves.t_s << " s: amplitude " << c.waves.amplitude_m << " m, total "
                                 << c.waves.total_m << ", model " << c.waves.model_m << " (path " << c.waves.path_m
                                 << ", feedback " << c.waves.feedback_m << "), time " << c.waves.time_m
                                 << ", space " << c.waves.space_m << ", quadrature " << c.waves.quadrature_m);
  // The stone: the stepper (bs32, error-controlled at its default tolerance, which locates each
  // crossing on its dense output) on still water against CVODE at rtol 1e-10: the same equations
  // on the same water. Its contact starts differ by its own error, bounded here by a run at a
  // hundredth of the tolerance: the tolerance ladder's difference, times 10 (the error of the
  // default run is that difference to about 1 %, the ladder's step being a factor 100 in rtol and
  // the scheme's error about proportional to it).
  BOOST_REQUIRE(c.contacts.size() >= 2u);
  BOOST_TEST(c.reference.bounces >= 1);
  RealtimeOptions tight = o.scene.stone_steps;
  tight.t_max_s = std::min(tight.t_max_s, o.scene.end_s());
  tight.rtol /= 100;
  tight.atol_m /= 100;
  const ThrowResult fine = run_realtime(o.scene.stone, o.scene.environment, o.scene.initial, tight);
  BOOST_REQUIRE(!fine.contacts.empty());
  const double ladder_s = std::abs(fine.contacts.front().start_s - c.still_water.contacts.front().start_s);
  constexpr double kTimeRoundoff_s = 1e-9;  // where both runs agree to the located crossing's own tolerance
  BOOST_TEST_MESSAGE("first contact: tolerance ladder " << ladder_s << " s");
  BOOST_TEST(std::abs(c.still_water.contacts.front().start_s - c.reference.contacts.front().start_s) <=
             10 * ladder_s + kTimeRoundoff_s);
  // The live water moves later contacts (the scene's stone meets its own waves): only the first
  // contact, on water still undisturbed, is held to the same bound.
  BOOST_TEST(c.contacts.front().index == 1);
  BOOST_TEST(std::abs(c.contacts.front().scene_start_s - c.contacts.front().reference_start_s) <= 10 * ladder_s + kTimeRoundoff_s);
  // The count ensembles on still water (the stepper and CVODE: the same equations): no difference
  // established between them (the stones report's ensembles find the same on the physical throws).
  BOOST_TEST(c.agreement.factors.size() == 8u);
  BOOST_TEST(!c.agreement.difference.established(), "stepper " << c.agreement.difference.mean_a << ", CVODE "
                                                           << c.agreement.difference.mean_b);
  BOOST_TEST(c.waves.amplitude_m > 0);
  // Order in time: the forced leapfrog with Δt, Δt/2, Δt/4, Δt/8 (same grid), forced by the CVODE
  // throw's pressure head gathered with the leapfrog's hat weights on pieces of the scene's contact
  // step (as the scene gathers it), against the same semi-discrete solution. The head is
  // continuous in time (a face's wetted area grows from zero) with kinks where the rim crosses cell
  // edges; the hat weights are the second difference's exact weights, so the order is 2.
  const HeightFieldOptions& f = o.scene.water->field;
  expect_second_order_in_time(o, c);
  // The findings: every verdict agrees with its rule.
  const Record r = capture_scene_findings(c, o, "test");
  BOOST_TEST(contradicted_verdicts(r).empty());
  BOOST_TEST(r.at("waves").table("profile").rows() == std::size_t(f.nx));
  // The row of the largest difference holds total_m, the max over the whole grid (oracle: the
  // definition of total_m, max |scene − continuum|): its own largest difference is that value.
  const Table& worst = r.at("waves").table("worst_profile");
  const auto scene = worst.column("scene_m"), continuum = worst.column("continuum_m");
  double largest = 0;
  for (std::size_t i = 0; i < scene.size(); ++i) largest = std::max(largest, std::abs(scene[i] - continuum[i]));
  BOOST_TEST(largest == c.waves.total_m);
}

BOOST_AUTO_TEST_CASE(a_walled_pond_is_compared_with_the_walled_forced_reference) {
  // Oracle: the walled forced reference (solvers/spectral/forced_walled_wave.hpp), whose walls are
  // the leapfrog's (forced_walled_wave_test.cpp). The fixture's pond walled in, reflecting or fixed,
  // and moved under the first two contacts (x = 1.99 and 2.58 m, y = 0 and −0.07 m) with its wall at
  // y = −0.1 m (half a cell more for the reflecting one): the 3 cm stone lands 3 to 10 cm from it, its
  // smoothed head reaches the wall, and its waves (0.5 m/s) meet it. The waves are compared, and the
  // time part of the gap is second order as on the periodic pond.
  for (const Boundary b : {Boundary::reflecting, Boundary::fixed}) {
    CaptureSceneOptions o = skipping_options(0.3);
    o.scene.water->field.boundary = b;
    o.scene.water->placement.origin_x_m = 1.5;
    o.scene.water->placement.origin_y_m = -0.1;
    const CaptureSceneComparison c = compare_capture_scene(o);
    BOOST_REQUIRE_MESSAGE(c.waves_compared, to_string(b) << ": " << c.waves_not_compared);
    for (const auto& k : c.scene.stone.contacts)  // on the pond, within 10 cm of the wall
      BOOST_TEST((k.entry_position_m.y() > -0.1 && k.entry_position_m.y() < 0.0 && k.entry_position_m.x() > 1.5),
                 to_string(b) << ": a contact at " << k.entry_position_m.transpose());
    BOOST_TEST(c.waves.amplitude_m > 0);
    expect_second_order_in_time(o, c);
    const Record r = capture_scene_findings(c, o, "test");
    BOOST_TEST(contradicted_verdicts(r).empty());
    BOOST_TEST(r.at("settings").text("boundary") == to_string(b));
  }
}

BOOST_AUTO_TEST_CASE(contacts_begun_off_a_walled_pond_are_counted_and_said) {
  // Oracle: the geometry. The fixture's pond, walled and moved 100 m down the throw, lies under
  // none of the stone's contacts (its grid points span x in [100, 101.88] m; the throw stays within
  // a few metres of its release): every contact of the scene is off it, and the stone's record
  // says so in a sentence. The periodic pond in place tiles the plane: none is.
  CaptureSceneOptions o = skipping_options(0.3);
  const Record in_place = capture_scene_findings(compare_capture_scene(o), o, "test");
  BOOST_TEST(in_place.at("stone").number("contacts_off_pond") == 0);
  BOOST_TEST(in_place.at("stone").text("off_pond").empty());
  o.scene.water->field.boundary = Boundary::reflecting;
  o.scene.water->placement.origin_x_m = 100;
  const CaptureSceneComparison c = compare_capture_scene(o);
  BOOST_REQUIRE(!c.scene.stone.contacts.empty());
  const Record moved = capture_scene_findings(c, o, "test");
  BOOST_TEST(moved.at("stone").number("contacts_off_pond") == double(c.scene.stone.contacts.size()));
  const std::string off = moved.at("stone").text("off_pond");
  BOOST_TEST(off.find("outside the pond, x in [100, 101.9] m") != std::string::npos, off);
  BOOST_TEST(off.find("the water takes none of the push") != std::string::npos, off);  // two-way
}

BOOST_AUTO_TEST_CASE(waves_too_costly_to_reference_are_not_compared_and_say_why) {
  // Oracle: the work estimate's definition — 2.5 · intervals · nodes · cells: 0.3 s in 1e-4 s
  // sub-intervals of 4 nodes on 48 × 16 cells is 2.5 · 3000 · 4 · 768 = 2.304e7 cell-transforms.
  CaptureSceneOptions o = skipping_options(0.3);
  o.quadrature_interval_s = 1e-4;
  o.max_reference_cell_transforms = 2.3e7;
  const CaptureSceneComparison c = compare_capture_scene(o);
  BOOST_TEST(!c.waves_compared);
  BOOST_TEST(c.waves_not_compared.find("2.3e+07 cell-transforms") != std::string::npos, c.waves_not_compared);
  BOOST_TEST(!c.contacts.empty());  // the stone is still compared
  o.max_reference_cell_transforms = 2.31e7;
  BOOST_TEST(compare_capture_scene(o).waves_compared);
}

BOOST_AUTO_TEST_CASE(invalid_options_are_refused) {
  // Oracle: the input rules — invalid options name the option.
  CaptureSceneOptions o = skipping_options(0.3);
  o.quadrature_nodes = 0;
  std::string why;
  BOOST_TEST(!o.valid(&why));
  BOOST_TEST(why.find("quadrature_nodes") != std::string::npos);
  BOOST_CHECK_THROW(compare_capture_scene(o), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
