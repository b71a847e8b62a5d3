// The two-way model of model/README.md §2.4 run end to end: a stone's draught computed from the field each
// step (model/coupling/draught.hpp) drives the forced leapfrog (model/water/height_field.hpp).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>

#include "model/coupling/draught.hpp"
#include "model/coupling/test_support.hpp"
#include "model/stone/portable_uniform.hpp"
#include "model/water/disturbance.hpp"

namespace stoneskip {
namespace {

// A 44-triangle prism (R = 8 cm, 1.5 cm thick) moved along a prescribed path through the water:
// drifting at (0.3, 0.1) m/s, bobbing ±3 mm about 2 mm under, tilted 10° and spinning.
struct MovingStone {
  StoneDraught draught{make_prism(0.08, 0.015, 11)};
  void pose(double t, Vec3& x, Mat3& R) const {
    x = Vec3(0.3 + 0.3 * t, 0.4 + 0.1 * t, -0.002 + 0.003 * std::sin(5 * t));
    R = (Eigen::AngleAxisd(0.17, Vec3::UnitY()) * Eigen::AngleAxisd(4 * t, Vec3::UnitZ())).toRotationMatrix();
  }
  // One two-way step: b from the stone's pose and the field at the start of the step.
  DraughtSummary step(HeightField& f, DraughtPatch& p) {
    Vec3 x;
    Mat3 R;
    pose(f.time_s(), x, R);
    const DraughtSummary s = draught.compute(x, R, f, FieldPlacement{}, p);
    f.step(p);
    return s;
  }
};

HeightFieldOptions pond(const std::string& stencil, Boundary b, double sigma, double mu = 0.5) {
  HeightFieldOptions o;
  o.nx = o.ny = 64;
  o.cell_m = 1.0 / 64;
  o.wave_speed_m_s = 1;
  o.damping_per_s = mu;
  o.dt_s = sigma * o.cell_m;
  o.stencil = named_stencil(stencil);
  o.boundary = b;
  return o;
}

double abs_volume(const HeightField& f) {
  double s = 0;
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i) s += std::abs(f.height(i, j));
  return s * f.options().cell_m * f.options().cell_m;
}

BOOST_AUTO_TEST_SUITE(two_way_)

BOOST_AUTO_TEST_CASE(a_moving_stone_adds_no_water_with_a_consistent_stencil) {
  // Oracle: model/README.md §2.4 — a consistent stencil's weights sum to 0, so Σ L[z + b] = 0 on a periodic or
  // reflecting grid and Σ z d² keeps its start value (0, still water) to round-off: 1e-12 of the
  // displaced volume Σ|z| d² (a few ulps per cell per step, 4096 cells, 300 steps).
  constexpr double kVolumeRoundoff = 1e-12;
  for (const char* st : {"five_point", "nine_point_half", "nine_point_isotropic"})
    for (auto b : {Boundary::periodic, Boundary::reflecting}) {
      HeightField f(pond(st, b, 0.4));
      MovingStone stone;
      DraughtPatch p;
      double worst = 0, scale = 0;
      int wet_steps = 0;
      for (int s = 0; s < 300; ++s) {
        wet_steps += stone.step(f, p).wet;
        worst = std::max(worst, std::abs(f.volume_m3()));
        scale = std::max(scale, abs_volume(f));
      }
      BOOST_TEST(wet_steps > 250);
      BOOST_TEST(scale > 1e-5);  // the stone did move water: ~ its draught over its footprint
      BOOST_TEST(worst <= kVolumeRoundoff * scale, st << " " << to_string(b) << ": |ΔV| " << worst << " of " << scale);
      BOOST_TEST_MESSAGE(st << " " << to_string(b) << ": largest |ΔV| " << worst << " m³, displaced " << scale << " m³");
    }
}

BOOST_AUTO_TEST_CASE(paper_eq11_does_not_conserve_the_water) {
  // Oracle: paper_eq11's weights sum to −1/3 (model/README.md §2.2), so each step changes Σ z by
  // −(2σ²/3)/(2 + μΔt) Σ (z + b): the volume drifts by a visible fraction of what the stone displaces.
  HeightField f(pond("paper_eq11", Boundary::periodic, 0.4));
  MovingStone stone;
  DraughtPatch p;
  for (int s = 0; s < 300; ++s) stone.step(f, p);
  BOOST_TEST(std::abs(f.volume_m3()) > 0.01 * abs_volume(f), f.volume_m3() << " vs " << abs_volume(f));
  BOOST_TEST_MESSAGE("paper_eq11: volume " << f.volume_m3() << " m³ after 300 steps, displaced " << abs_volume(f) << " m³");
}

BOOST_AUTO_TEST_CASE(a_plate_held_still_settles_to_the_closed_form) {
  // Oracle: model/README.md §2.4 — a flat-bottomed plate held with its bottom at s < 0 over K grid points of
  // an N-point periodic grid settles (μ > 0) to z + b = C everywhere: z = C off the plate,
  // (C + s)/2 under it, b = (C − s)/2, C = −K s/(2N − K). μ = 12/s makes every mode decay at
  // least as e^{−μt/2} (all modes underdamped: μ²/4 = 36 < λ_min ≈ 4π²); after 8 s the transient
  // is ~0.01 m · e^{−48}, nothing, and the tolerance 1e-12 m is round-off of O(1 cm) values summed
  // over the run. b is recomputed from the field every step.
  const int n = 32;
  HeightFieldOptions o = pond("five_point", Boundary::periodic, 0.45, 12.0);
  o.nx = o.ny = n;
  o.cell_m = 1.0 / n;
  o.dt_s = 0.45 * o.cell_m;  // below the coupled limit 0.5
  HeightField f(o);
  const double d = o.cell_m, h = 0.02, s = -0.01;
  // An 8 × 8-cell plate whose edges lie between grid points: K = 64 points under it.
  StoneDraught plate(test::voxel_mesh({{0, 0, 0}}, Vec3(8 * d, 8 * d, h), Vec3(4 * d, 4 * d, 0.5 * h)));
  const Vec3 at(0.5 + 0.5 * d, 0.5 + 0.5 * d, s + 0.5 * h);
  DraughtPatch p;
  int k_points = 0;
  while (f.time_s() < 8.0) {
    k_points = plate.compute(at, Mat3::Identity(), f, FieldPlacement{}, p).points;
    f.step(p);
  }
  const double N = n * n, K = k_points, C = -K * s / (2 * N - K);
  BOOST_TEST(k_points == 64);
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i * d - at.x(), y = j * d - at.y();
      const bool under = std::abs(x) < 4 * d && std::abs(y) < 4 * d;
      worst = std::max(worst, std::abs(f.height(i, j) - (under ? 0.5 * (C + s) : C)));
    }
  BOOST_TEST(worst <= 1e-12, "largest departure " << worst << " m, C = " << C);
  BOOST_TEST_MESSAGE("held plate: largest departure from the closed form " << worst << " m (C = " << C << " m)");
  plate.compute(at, Mat3::Identity(), f, FieldPlacement{}, p);
  BOOST_TEST(std::abs(p.at(p.ni / 2, p.nj / 2) - 0.5 * (C - s)) <= 1e-12);
}

// RMS departure of the field from a reference state.
double rms_departure(const HeightField& f, const std::vector<double>& ref) {
  double s = 0;
  for (int j = 0; j < f.ny(); ++j)
    for (int i = 0; i < f.nx(); ++i) {
      const double e = f.height(i, j) - ref[static_cast<std::size_t>(j) * f.nx() + i];
      s += e * e;
    }
  return std::sqrt(s / (f.nx() * f.ny()));
}

struct PlateGrowth {
  double rate = 0;           // per-step growth of the departure from equilibrium, from step 10 to the last
  double final_departure = 0;
};

// A 24 × 24-cell plate held on a 48² periodic grid, started in its equilibrium (the closed form
// above) plus 1e-12 m of noise; the departure's growth rate per step over `steps` − 10 steps. Plate 4 cm thick, bottom at
// −2 cm, so b stays in its linear range (0 < z − s < h) while the departure is below ~1 cm.
PlateGrowth plate_growth(const std::string& stencil, double sigma, bool with_plate, int steps) {
  const int n = 48;
  HeightFieldOptions o = pond(stencil, Boundary::periodic, sigma, 0.2);
  o.nx = o.ny = n;
  o.cell_m = 1.0 / n;
  o.dt_s = sigma * o.cell_m;
  HeightField f(o);
  const double d = o.cell_m, h = 0.04, s = -0.02;
  StoneDraught plate(test::voxel_mesh({{0, 0, 0}}, Vec3(24 * d, 24 * d, h), Vec3(12 * d, 12 * d, 0.5 * h)));
  const Vec3 at(0.5 + 0.5 * d, 0.5 + 0.5 * d, s + 0.5 * h);
  const double N = n * n, K = 24 * 24, C = with_plate ? -K * s / (2 * N - K) : 0;
  std::vector<double> eq(n * n), z(n * n);
  PortableUniform rng{5};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool under = with_plate && std::abs(i * d - at.x()) < 12 * d && std::abs(j * d - at.y()) < 12 * d;
      eq[j * n + i] = under ? 0.5 * (C + s) : C;
      z[j * n + i] = eq[j * n + i] + rng(-1e-12, 1e-12);
    }
  f.set_levels(z, z);
  DraughtPatch p;
  double r10 = 0;
  for (int step = 0; step < steps; ++step) {
    if (with_plate)
      plate.compute(at, Mat3::Identity(), f, FieldPlacement{}, p);
    else
      p.clear();
    f.step(p);
    if (step + 1 == 10) r10 = rms_departure(f, eq);
  }
  PlateGrowth g;
  g.final_departure = rms_departure(f, eq);
  g.rate = std::pow(g.final_departure / r10, 1.0 / (steps - 10));
  return g;
}

BOOST_AUTO_TEST_CASE(the_coupled_step_is_stable_below_the_coupled_limit_and_grows_above_it) {
  // Oracle: model/README.md §2.4 — under the plate the Courant number is √2 σ, so the limit is the free
  // limit / √2 (coupled_courant_limit). 3 % below it the departure from equilibrium does not grow
  // over 400 steps (rate ≤ 1 + 1e-3: a bounded transient, as leapfrog modes near the limit have,
  // spread over the steps); 3 % above it grows geometrically from the first steps (rate > 1.05
  // over 30 steps) while staying well inside b's linear range (departure < 1 mm; b is linear in z
  // up to 1 cm); and without the plate the same σ is stable, so the limit is the coupling's.
  for (const char* st : {"five_point", "nine_point_isotropic"}) {
    const double limit = coupled_courant_limit(named_stencil(st));
    const PlateGrowth below = plate_growth(st, 0.97 * limit, true, 400);
    const PlateGrowth above = plate_growth(st, 1.03 * limit, true, 40);
    const PlateGrowth free = plate_growth(st, 1.03 * limit, false, 400);
    BOOST_TEST(below.rate <= 1 + 1e-3, st << " below: " << below.rate);
    BOOST_TEST(above.rate > 1.05, st << " above: " << above.rate);
    BOOST_TEST(above.final_departure < 1e-3, st << " above left the linear range: " << above.final_departure);
    BOOST_TEST_MESSAGE(st << ": coupled limit " << limit << ", growth per step 3 % below " << below.rate << ", 3 % above "
                          << above.rate << ", free at 3 % above " << free.rate);
    BOOST_TEST(free.rate <= 1 + 1e-3, st << " free: " << free.rate);
  }
}

BOOST_AUTO_TEST_CASE(with_no_wave_speed_two_way_is_one_way_bit_for_bit) {
  // Oracle: model/README.md §2.4 — with c = 0 the forcing 2c²Δt² L[b] is zero and the field never moves, so
  // a two-way run equals a run without draught to the bit; on still water z stays exactly 0, and
  // with μ = 0 a disturbed field stays exactly as it started.
  for (double mu : {0.0, 0.7}) {
    HeightFieldOptions o = pond("nine_point_isotropic", Boundary::reflecting, 0.4, mu);
    o.wave_speed_m_s = 0;
    HeightField two(o), one(o);
    Disturbance dist;
    dist.amplitude_m = 0.003;
    dist.x_m = dist.y_m = 0.6;
    std::vector<double> z0;
    sample_disturbance(dist, o.nx, o.ny, o.cell_m, z0);
    two.set_state(z0);
    one.set_state(z0);
    MovingStone stone;
    DraughtPatch p;
    int wet = 0;
    for (int s = 0; s < 200; ++s) {
      wet += stone.step(two, p).wet;
      one.step();
    }
    BOOST_TEST(wet > 150);
    std::vector<double> a, b;
    two.heights(a);
    one.heights(b);
    BOOST_TEST(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
    if (mu == 0) BOOST_TEST(std::memcmp(a.data(), z0.data(), a.size() * sizeof(double)) == 0);
    HeightField still(o);
    for (int s = 0; s < 200; ++s) stone.step(still, p);
    double worst = 0;
    for (int j = 0; j < o.ny; ++j)
      for (int i = 0; i < o.nx; ++i) worst = std::max(worst, std::abs(still.height(i, j)));
    BOOST_TEST(worst == 0);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
