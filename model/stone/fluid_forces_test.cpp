// Water and air forces (model/README.md §1.4–1.6): closed-form loads in both conventions. The sign of the
// fluid power over random states, per law and convention, is in water_laws_test.cpp.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include <algorithm>

#include "model/stone/portable_uniform.hpp"
#include "model/stone/pressure_distribution.hpp"
#include "model/stone/rigid_body.hpp"
#include "model/stone/triangle_clip.hpp"
#include "model/stone/throw.hpp"
#include "model/stone/water_laws.hpp"
#include "model/stone/water_surface.hpp"

using namespace stoneskip;

namespace {

Stone test_stone(int n = 11) {
  const Mesh m = make_prism(0.03, 0.008, n);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "test prism");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fluid_forces)

BOOST_AUTO_TEST_CASE(a_flat_plate_sinking_flat_feels_cw_rho_s_w_squared) {
  // Oracle: Newtonian impact law (Eq. 2) on a fully wetted bottom face moving straight down:
  // F = C_w ρ_w S w² upward, no torque; rim faces move tangentially (u = 0) and carry no load.
  const Stone s = test_stone();
  Environment env;
  env.water_coefficient = 0.7;
  RigidState st;
  st.position_m = Vec3(0, 0, 0.004 - 1e-4);  // bottom face 0.1 mm under water, top face dry
  st.velocity_m_s = Vec3(0, 0, -3.0);
  const WaterLoads w = water_loads(s, env, st);
  const double S = 0.5 * 11 * 0.03 * 0.03 * std::sin(2 * std::numbers::pi / 11);
  const double expected = 0.7 * 1000 * S * 9.0;
  BOOST_TEST(std::abs(w.force_N.z() - expected) <= 1e-12 * expected);
  BOOST_TEST(std::abs(w.force_N.x()) + std::abs(w.force_N.y()) <= 1e-12 * expected);
  BOOST_TEST(w.torque_N_m.norm() <= 1e-12 * expected * 0.03);
  BOOST_TEST(std::abs(w.wetted_area_m2 - S - 11 * 0.03 * std::sin(std::numbers::pi / 11) * 2 * 1e-4) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(air_drag_opposes_the_normal_velocity_in_the_physical_convention_only) {
  // Oracle: Eq. 6 closed form. Moving up along the normal (u > 0): physical F = −C ρ u² S n
  // (down), paper F = −C ρ u² S n too; moving down (u < 0): physical pushes up, paper still down.
  const Stone s = test_stone();
  Environment phys, paper;
  paper.convention = Convention::paper;
  RigidState st;
  st.position_m = Vec3(0, 0, 1);
  st.velocity_m_s = Vec3(0, 0, -2);
  const double mag = 1.2 * s.disk_area_m2 * 4.0;
  BOOST_TEST(std::abs(air_loads(s, phys, st).force_N.z() - mag) <= 1e-14);
  BOOST_TEST(std::abs(air_loads(s, paper, st).force_N.z() + mag) <= 1e-14);
}

BOOST_AUTO_TEST_CASE(the_printed_torque_is_the_negative_of_the_physical_one_without_spin) {
  // Oracle: Eq. 3 as printed is F × r = −(r × F). With no spin, v_i is the same in both
  // conventions, and for a face that advances into the water the forces agree: a tilted plate
  // falling straight down has every wet face advancing, so τ_paper = −τ_physical exactly.
  const Stone s = test_stone();
  Environment phys, paper;
  paper.convention = Convention::paper;
  // The plate is tilted by 0.2 rad and only its low edge is under water: the wet faces are the
  // bottom and the low side of the rim, whose outward normals point down, so with no spin every
  // wet face advances (u ≥ 0) while the plate falls straight down.
  RigidState st;
  st.orientation = Quat(Eigen::AngleAxisd(-0.2, Vec3::UnitY()));
  st.velocity_m_s = Vec3(0, 0, -2);
  st.position_m = Vec3(0, 0, 0.03 * std::sin(0.2) - 1e-3);
  const WaterLoads c = water_loads(s, phys, st), d = water_loads(s, paper, st);
  BOOST_TEST(c.torque_N_m.norm() > 0);
  BOOST_TEST((c.torque_N_m + d.torque_N_m).norm() <= 1e-9 * c.torque_N_m.norm() + 1e-15);
}

BOOST_AUTO_TEST_CASE(the_printed_eq1_reverses_the_spin_term_of_a_flat_face) {
  // Oracle: closed form of spec §1.6's printed Eq. 1–3 on the N = 11 prism's bottom face (n = −z),
  // centre of mass at the origin, the face 1e-9 m under, v = (0, 0, −1) m/s, ω = (100, 0, 0) rad/s.
  // Printed Eq. 1: v_i = v + r_i × ω = (0, z ω, −1 − y_i ω), so u_i = v_i · n = 1 + y_i ω; Eq. 2
  // gives F_i = ρ u_i² S_i upward; Eq. 3 as printed, τ = Σ F_i × r_i, has τ_x = −Σ F_i y_i. The fan's
  // mirror symmetry in y (Σ S y = Σ S y³ = 0) leaves F_z = ρ (S + ω² Σ S y²) and τ_x = −2 ρ ω Σ S y²,
  // with each triangle's S_t = R² sin(2π/N)/2 and centroid at (2/3) R cos(π/N) from the axis:
  // Σ S y² = S_t d² N/2 = 4.9275e-7 m⁴, so F_z = 7.6037 N and τ_x = −0.098550 N m. A repaired Eq. 1
  // (v + ω × r, u_i = 1 − y_i ω) keeps F_z but turns τ_x to +0.098550: this test tells them apart.
  // Tolerance 1e-6 relative: the rim's 1e-9 m wet strips carry about 1e-7 N.
  const Stone s = test_stone();
  Environment paper;
  paper.convention = Convention::paper;
  RigidState st;
  st.position_m = Vec3(0, 0, 0.004 - 1e-9);
  st.velocity_m_s = Vec3(0, 0, -1);
  set_body_angular_velocity(s, st, Vec3(100, 0, 0));  // body = world: the identity orientation
  const double R = 0.03, N = 11, w = 100, rho = 1000;
  const double St = 0.5 * R * R * std::sin(2 * std::numbers::pi / N);
  const double d = 2.0 / 3.0 * R * std::cos(std::numbers::pi / N);
  const double Sy2 = St * d * d * N / 2;
  const WaterLoads l = water_loads(s, paper, st);
  BOOST_TEST(l.force_N.z() == rho * (N * St + w * w * Sy2), boost::test_tools::tolerance(1e-6));
  BOOST_TEST(l.torque_N_m.x() == -2 * rho * w * Sy2, boost::test_tools::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(a_nan_state_or_surface_gives_nan_loads_not_dry_ones) {
  // Oracle: IEEE: a NaN in the state or the surface must reach the loads, so that the solvers fail
  // saying where. The law's `!(u > 0)` read a NaN normal speed as "no water", and std::max skipped a
  // NaN depth: a stone over a NaN field flew on as if over none.
  const Stone s = test_stone();
  RigidState st;
  st.position_m = Vec3(0, 0, 0.002);  // half under
  st.velocity_m_s = Vec3(3, 0, -1);
  for (WaterLaw law : {WaterLaw::newtonian, WaterLaw::planing, WaterLaw::nagahiro_hayakawa})
    for (PressureDistribution dist : {PressureDistribution::uniform, PressureDistribution::savitsky_wagner}) {
      Environment env;
      env.water_law = law;
      env.pressure_distribution = dist;
      BOOST_TEST_CONTEXT(to_string(law) << ", " << to_string(dist)) {
        BOOST_TEST(std::isnan(law_pressure_Pa(env, std::numeric_limits<double>::quiet_NaN(), 3.0)));
        RigidState spin = st;
        spin.angular_momentum_kg_m2_s = Vec3(0, 0, std::numeric_limits<double>::quiet_NaN());
        BOOST_TEST(!water_loads(s, env, spin).force_N.allFinite());
        struct NanSurface : WaterSurface {
          double height_m(double, double) const override { return std::numeric_limits<double>::quiet_NaN(); }
        } nan_surface;
        BOOST_TEST(!water_loads(s, env, st, &nan_surface).force_N.allFinite());
        BOOST_TEST(water_loads(s, env, st).force_N.allFinite());  // the same state over still water
      }
    }
}

namespace {

// The N = 11 prism pitched nose up by α (leading edge +x up) moving at `speed` along a path β below
// the horizontal, its lowest vertex `depth` under still water.
RigidState pitched_in_contact(const Stone& s, double alpha_deg, double beta_deg, double speed, double depth) {
  RigidState st;
  st.orientation = Quat(Eigen::AngleAxisd(-alpha_deg * std::numbers::pi / 180, Vec3::UnitY()));
  double lowest = 1e300;
  for (const Vec3& v : s.body_mesh.vertices) lowest = std::min(lowest, (st.orientation * v).z());
  st.position_m = Vec3(0, 0, -depth - lowest);
  const double b = beta_deg * std::numbers::pi / 180;
  st.velocity_m_s = speed * Vec3(std::cos(b), 0, -std::sin(b));
  return st;
}

Environment planing(PressureDistribution d) {
  Environment env;
  set_water_law(env, WaterLaw::planing);
  env.pressure_distribution = d;
  return env;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_wagner_rise_wets_the_underside_only) {
  // Oracle: the rule itself, computed independently of the loads (pressure_distribution.hpp,
  // on_underside): each face's push acts on its polygon below the raised waterline (π/2 − 1) d_max
  // on the underside and below the surface elsewhere; the pushes add up to the force; and the
  // pushes' magnitudes add up to the law's total Σ p_i S_i on the geometric wetted area (K's
  // normalisation), which the uniform distribution's pushes give. Tolerance 1e-12: sums of ≤ 44
  // faces. States: the N = 11 prism, pitched 10° nose up at 8 m/s, 10° path, contacts 1–10 mm deep,
  // deep enough that the raised waterline cuts the rim (the faces the rise used to wet).
  const Stone s = test_stone();
  for (double depth_mm : {1.0, 4.0, 6.0, 8.0, 10.0}) {
    BOOST_TEST_CONTEXT("depth " << depth_mm << " mm") {
      const RigidState st = pitched_in_contact(s, 10, 10, 8, depth_mm * 1e-3);
      std::vector<FacePush> wagner, uniform;
      const WaterLoads l = water_loads(s, planing(PressureDistribution::savitsky_wagner), st, nullptr, &wagner);
      water_loads(s, planing(PressureDistribution::uniform), st, nullptr, &uniform);
      const Mat3 R = st.orientation.toRotationMatrix();
      const double rise = (std::numbers::pi / 2 - 1) * depth_mm * 1e-3;
      double total_uniform = 0, total_wagner = 0;
      for (const FacePush& p : uniform) total_uniform += p.force_N.norm();
      Vec3 sum = Vec3::Zero();
      int rim_faces_cut = 0;
      for (const FacePush& p : wagner) {
        total_wagner += p.force_N.norm();
        sum += p.force_N;
        // Its face: one whose polygon, clipped by the rule, is the push's (the bottom's 11 triangles
        // share a plane, so the polygon decides).
        bool found = false;
        for (int i = 0; i < static_cast<int>(s.body_mesh.triangles.size()) && !found; ++i) {
          const auto& t = s.body_mesh.triangles[i];
          Vec3 w[3];
          double d[3];
          const bool under = s.face_normals_body[i].z() < -1e-9;  // body z up: the underside faces down
          for (int k = 0; k < 3; ++k) {
            w[k] = st.position_m + R * s.body_mesh.vertices[t[k]];
            d[k] = -w[k].z() + (under ? rise : 0);
          }
          const ClippedPolygon expected = clip_submerged_polygon(w[0], w[1], w[2], d[0], d[1], d[2]);
          bool same = expected.count == p.wetted.count && (R * s.face_normals_body[i]).dot(p.force_N) < 0;
          for (int k = 0; same && k < expected.count; ++k)
            same = (p.wetted.vertices[k] - expected.vertices[k]).norm() <= 1e-12;
          found = same;
        }
        BOOST_TEST(found);
      }
      // The faces off the underside that the raised waterline cuts: the case the rule is about.
      for (int i = 0; i < static_cast<int>(s.body_mesh.triangles.size()); ++i) {
        if (s.face_normals_body[i].z() < -1e-9) continue;
        bool cut = false;
        for (int k : s.body_mesh.triangles[i]) {
          const double d = -(st.position_m + R * s.body_mesh.vertices[k]).z();
          cut = cut || (d < 0 && d + rise >= 0);
        }
        rim_faces_cut += cut;
      }
      if (depth_mm >= 4) BOOST_TEST(rim_faces_cut > 0);  // the case the rule is about is exercised
      BOOST_TEST((sum - l.force_N).norm() <= 1e-12 * l.force_N.norm());
      BOOST_TEST(std::abs(total_wagner - total_uniform) <= 1e-12 * total_uniform);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_distribution_moves_the_law_s_total_and_never_amplifies_it) {
  // Oracle: the uniform pressure's pushes. K = Σ p_i S_i / Σ p_i W_i (fluid_forces.cpp) grows without
  // bound as the faces' pressures at their centres of pressure vanish, but it scales those same
  // pressures: Σ |F_i| is the law's total Σ p_i S_i on the geometric wetted area whatever K is. Over
  // 2 000 random states near the water (attitudes, speeds to 8 m/s, spins to 100 rev/s) under both
  // distributions and two laws, the pushes' magnitudes add up to the uniform pushes' to 1e-12
  // relative (sums of ≤ 44 faces), so no state gets more push from the water than the law gives.
  const Stone s = test_stone();
  PortableUniform u{12345};  // the same states on every platform
  int wet = 0;
  for (int k = 0; k < 2000; ++k) {
    RigidState st;
    // One draw a statement (a call's arguments are evaluated in an unspecified order: GCC right
    // to left, clang left to right), last component first, as GCC drew them.
    st.position_m = Vec3(0, 0, u(-0.02, 0.02));
    const double qz = u(-1, 1), qy = u(-1, 1), qx = u(-1, 1), qw = u(-1, 1);
    st.orientation = Quat(qw, qx, qy, qz).normalized();
    const double vz = u(-3, 3), vy = u(-8, 8), vx = u(-8, 8);
    st.velocity_m_s = Vec3(vx, vy, vz);
    const double wz = u(-630, 630), wy = u(-60, 60), wx = u(-60, 60);
    set_body_angular_velocity(s, st, Vec3(wx, wy, wz));
    for (WaterLaw law : {WaterLaw::planing, WaterLaw::newtonian}) {
      Environment uniform;
      set_water_law(uniform, law);
      std::vector<FacePush> base;
      water_loads(s, uniform, st, nullptr, &base);
      double total = 0;
      for (const FacePush& p : base) total += p.force_N.norm();
      if (total > 0) ++wet;
      for (PressureDistribution d : {PressureDistribution::savitsky, PressureDistribution::savitsky_wagner}) {
        Environment env = uniform;
        env.pressure_distribution = d;
        std::vector<FacePush> pushes;
        water_loads(s, env, st, nullptr, &pushes);
        double sum = 0;
        for (const FacePush& p : pushes) sum += p.force_N.norm();
        BOOST_TEST(std::abs(sum - total) <= 1e-12 * total, "state " << k << ", " << to_string(d) << ": " << sum << " N against " << total << " N");
      }
    }
  }
  BOOST_TEST_MESSAGE(wet << " of 4000 state-law pairs wet");
  BOOST_TEST(wet >= 3600);  // nearly every pair wet (3956 when written): the property is exercised
}

BOOST_AUTO_TEST_CASE(a_deeper_planing_contact_lifts_more_under_every_distribution) {
  // Oracle: planing physics (Savitsky 1964: at a fixed trim and speed the lift grows with the wetted
  // length): the N = 11 prism pitched 10° nose up at 8 m/s on a 10° path, its lowest vertex 2, 4, 6,
  // 8 and 10 mm deep, must be lifted more at each depth. When the Wagner rise wetted the rim, the
  // leading-edge peak of the distribution loaded the leading flank, and lift fell with depth past
  // 6 mm (16.7, 15.2, 13.2 N at 6, 8, 10 mm, against the uniform pressure's 18.0, 24.6, 28.6 N).
  // Margin: each step at least 5 % more lift (the wetted area grows by more than that).
  const Stone s = test_stone();
  for (PressureDistribution d :
       {PressureDistribution::uniform, PressureDistribution::savitsky, PressureDistribution::savitsky_wagner}) {
    double previous = 0;
    for (double depth_mm : {2.0, 4.0, 6.0, 8.0, 10.0}) {
      const double lift = water_loads(s, planing(d), pitched_in_contact(s, 10, 10, 8, depth_mm * 1e-3)).force_N.z();
      BOOST_TEST_MESSAGE(to_string(d) << " " << depth_mm << " mm: lift " << lift << " N");
      BOOST_TEST(lift >= 1.05 * previous, to_string(d) << " at " << depth_mm << " mm: " << lift << " N after " << previous << " N");
      previous = lift;
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
