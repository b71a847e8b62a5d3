// The distributed pressure's switches (load_switches.hpp) against the loads themselves
// (fluid_forces.cpp): along a path through the water, every jump of the loads lies where a switch
// changes sign, and holding the loaded region (LoadMode) removes the jumps of the region's changes.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "model/stone/load_switches.hpp"
#include "model/stone/portable_uniform.hpp"
#include "model/stone/throw.hpp"

using namespace stoneskip;

namespace {

Stone test_stone() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "test prism");
}

// A rigid motion through the water with a fixed velocity and a fixed world angular velocity (a
// kinematic path: no integrator in the way): attack 5° nose up, skimming forward and down at 4 m/s
// and 0.4 m/s, 30 rev/s about the disk's axis, the trailing rim 4 mm under water at t = 0: deep
// enough that the rim's flanks are wet, where the spin turns a face's normal through the direction
// of motion and the face joins or leaves the loaded region (the Wagner rise no longer wets the rim
// above the surface, where a shallower path found those changes).
constexpr double kAttackDeg = 5, kDepth = 0.004;
struct Path {
  Stone stone = test_stone();
  Vec3 v = Vec3(4, 0, -0.4);
  Vec3 omega;
  Quat q0;
  Vec3 x0;
  Path() {
    q0 = Quat(Eigen::AngleAxisd(-kAttackDeg * std::numbers::pi / 180, Vec3::UnitY()));
    omega = 2 * std::numbers::pi * 30 * (q0 * Vec3::UnitZ());
    x0 = Vec3(0, 0, 0.03 * std::sin(kAttackDeg * std::numbers::pi / 180) - kDepth);
  }
  RigidState at(double t) const {
    RigidState s;
    s.position_m = x0 + t * v;
    s.velocity_m_s = v;
    s.orientation = Quat(Eigen::AngleAxisd(omega.norm() * t, omega.normalized())) * q0;
    const Mat3 R = s.orientation.toRotationMatrix();
    s.angular_momentum_kg_m2_s = R * stone.inertia_body_kg_m2 * R.transpose() * omega;
    return s;
  }
};

Environment savitsky_wagner() {
  Environment env;
  set_default_water_model(env);  // planing, savitsky_wagner
  return env;
}

struct Sample {
  Vec3 force, torque;
};

// |Δ| of the loads between two samples, torque at the stone's radius.
double change(const Sample& a, const Sample& b) {
  return std::max((b.force - a.force).norm(), (b.torque - a.torque).norm() / 0.03);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(load_switches)

BOOST_AUTO_TEST_CASE(every_jump_of_the_distributed_loads_lies_where_a_switch_changes_sign) {
  // Oracle: the loads themselves, sampled every 20 ns over 3 ms of the path. A jump is a change
  // between two samples 20 times both neighbouring changes (a kink only bends the changes; on this
  // path the loads change by ~5e-6 N a sample, and the region's jumps are 8e-3 and 2e-2 N). Each must lie in
  // an interval where a vertex crosses the surface or the raised waterline (the polygons change)
  // or a face's loaded-region switch changes sign; and the path must hold such a jump.
  const Path p;
  const Environment env = savitsky_wagner();
  LoadSwitches switches(p.stone, env);
  BOOST_TEST_REQUIRE(switches.active());
  const double dt = 2e-8;
  const int n = 150000;
  std::vector<Sample> loads(n + 1);
  for (int i = 0; i <= n; ++i) {
    const WaterLoads w = water_loads(p.stone, env, p.at(i * dt));
    loads[i] = {w.force_N, w.torque_N_m};
  }
  int jumps = 0, region_jumps = 0;
  std::vector<double> g0, g1;
  for (int i = 1; i + 1 < n; ++i) {
    const double d = change(loads[i], loads[i + 1]);
    if (!(d > 20 * std::max(change(loads[i - 1], loads[i]), change(loads[i + 1], loads[i + 2])))) continue;
    ++jumps;
    switches.reset(p.at(i * dt), g0);
    switches.evaluate(p.at((i + 1) * dt), g1);
    bool polygons_change = false, region_changes = false;
    for (int k = 0; k < static_cast<int>(g0.size()); ++k) {
      const auto kind = switches.kind(k);
      if (kind == LoadSwitches::Kind::raised_crossing && (g0[k] >= 0) != (g1[k] >= 0)) polygons_change = true;
      if (kind == LoadSwitches::Kind::loaded_face && g0[k] * g1[k] < 0) region_changes = true;
    }
    for (const Vec3& vb : p.stone.body_mesh.vertices) {
      const double z0 = p.at(i * dt).position_m.z() + (p.at(i * dt).orientation * vb).z();
      const double z1 = p.at((i + 1) * dt).position_m.z() + (p.at((i + 1) * dt).orientation * vb).z();
      if ((z0 < 0) != (z1 < 0)) polygons_change = true;
    }
    BOOST_TEST((polygons_change || region_changes), "a jump of " << d << " N at t = " << i * dt << " s with no switch");
    if (region_changes && !polygons_change) ++region_jumps;
  }
  BOOST_TEST_MESSAGE(jumps << " jumps, " << region_jumps << " of the loaded region alone");
  BOOST_TEST(region_jumps >= 1);
}

BOOST_AUTO_TEST_CASE(holding_the_loaded_region_keeps_the_loads_smooth_where_it_changes) {
  // Oracle: the free loads' own jump where a face leaves or joins the loaded region (found as in
  // the test above). Held from the sample before, the loads change across it by no more than twice
  // their neighbouring changes: the held branch continues smoothly. And at the state the mode is
  // taken from, the held loads are the free ones bit for bit (the mode is the loads' own choice).
  const Path p;
  const Environment env = savitsky_wagner();
  LoadSwitches switches(p.stone, env);
  const double dt = 2e-8;
  const int n = 150000;
  std::vector<double> g0, g1;
  int checked = 0;
  for (int i = 1; i + 2 < n && checked < 5; ++i) {
    switches.reset(p.at(i * dt), g0);
    switches.evaluate(p.at((i + 1) * dt), g1);
    bool region_changes = false;
    for (int k = 0; k < static_cast<int>(g0.size()); ++k)
      if (switches.kind(k) == LoadSwitches::Kind::loaded_face && g0[k] * g1[k] < 0) region_changes = true;
    if (!region_changes) continue;
    const LoadMode mode = switches.load_mode();
    auto free_at = [&](int j) {
      const WaterLoads w = water_loads(p.stone, env, p.at(j * dt));
      return Sample{w.force_N, w.torque_N_m};
    };
    auto held_at = [&](int j) {
      const WaterLoads w = water_loads(p.stone, env, p.at(j * dt), nullptr, nullptr, &mode);
      return Sample{w.force_N, w.torque_N_m};
    };
    const Sample f0 = free_at(i), f1 = free_at(i + 1), h0 = held_at(i), h1 = held_at(i + 1);
    BOOST_TEST(h0.force == f0.force);
    BOOST_TEST(h0.torque == f0.torque);
    const double neighbours = std::max(change(held_at(i - 1), h0), change(h1, held_at(i + 2)));
    const double free_jump = change(f0, f1);
    if (!(free_jump > 20 * neighbours)) continue;  // a switch of a face that carries no load
    BOOST_TEST_MESSAGE("t = " << i * dt << " s: free jump " << free_jump << " N, held " << change(h0, h1)
                              << " N, neighbouring changes " << neighbours << " N");
    BOOST_TEST(change(h0, h1) <= 2 * neighbours, "held " << change(h0, h1) << " N against " << free_jump << " N free");
    ++checked;
  }
  BOOST_TEST(checked >= 1);
}

BOOST_AUTO_TEST_CASE(a_stone_turning_over_in_contact_flips_the_wetted_side_where_its_switch_changes_sign) {
  // Oracle: the loads themselves. The prism stands on its rim (body z axis horizontal, turned by
  // 90° ∓ ε about the x axis), 3 mm in the water, moving forward, down and towards +y: the disk face
  // towards +y advances into the water. Which face is the underside that the Wagner rise wets
  // flips with the sign of R₂₂ (pressure_distribution.hpp): the free loads jump between ε = ±1e-9,
  // by far more than between ε = 1e-9 and 3e-9 (a smooth branch: 1e3 times), the underside_flip
  // switch changes sign there, and the loads held in the mode taken at +ε continue that branch at
  // −ε (a change no larger than twice the smooth one).
  const Stone stone = test_stone();
  const Environment env = savitsky_wagner();
  LoadSwitches switches(stone, env);
  auto state = [&](double eps) {
    RigidState s;
    s.orientation = Quat(Eigen::AngleAxisd(std::numbers::pi / 2 - eps, Vec3::UnitX()));
    s.position_m = Vec3(0, 0, 0.03 - 0.003);
    s.velocity_m_s = Vec3(4, 1, -0.5);
    return s;
  };
  auto loads = [&](double eps, const LoadMode* mode) {
    const WaterLoads w = water_loads(stone, env, state(eps), nullptr, nullptr, mode);
    return Sample{w.force_N, w.torque_N_m};
  };
  const double smooth = change(loads(3e-9, nullptr), loads(1e-9, nullptr));
  const double jump = change(loads(1e-9, nullptr), loads(-1e-9, nullptr));
  BOOST_TEST_MESSAGE("turning over: free jump " << jump << " N, smooth change " << smooth << " N");
  BOOST_TEST(jump > 1e3 * smooth);
  std::vector<double> g0, g1;
  switches.reset(state(1e-9), g0);
  switches.evaluate(state(-1e-9), g1);
  int flips = 0;
  for (int k = 0; k < static_cast<int>(g0.size()); ++k)
    if (switches.kind(k) == LoadSwitches::Kind::underside_flip) flips += g0[k] > 0 && g1[k] < 0;
  BOOST_TEST(flips == 1);
  const LoadMode mode = switches.load_mode();
  BOOST_TEST(change(loads(1e-9, &mode), loads(-1e-9, &mode)) <= 2 * smooth);
}

BOOST_AUTO_TEST_CASE(one_switch_alone_is_the_value_of_them_all_bit_for_bit) {
  // Oracle: evaluate, which computes every switch at once. value(s, k) computes only what switch k
  // needs (the real-time stepper's root search on one switch), through the same functions, so it
  // must give the same double, bit for bit, or NaN where evaluate's is NaN: any difference would
  // move a located kink. States: the path through the water (modes recorded at 8 times, values
  // 0–2 ms later, past several switches) and 300 random states near the water (attitudes, speeds
  // to 8 m/s, spins to 100 rev/s), each recorded and then moved by up to 2 mm, 0.02 rad and 0.2 m/s,
  // under savitsky_wagner and savitsky. Every kind of switch must be compared finite somewhere,
  // or the check would be empty.
  const Path path;
  const Stone& s = path.stone;
  PortableUniform u{2024};
  // One draw a statement (a call's arguments are evaluated in an unspecified order: GCC right to
  // left, clang left to right), last argument first, as GCC drew them: the same states everywhere.
  auto draw = [&](double lo_xy, double hi_xy, double lo_z, double hi_z) {
    const double z = u(lo_z, hi_z), y = u(lo_xy, hi_xy), x = u(lo_xy, hi_xy);
    return Vec3(x, y, z);
  };
  auto random_state = [&] {
    RigidState st;
    st.position_m = Vec3(0, 0, u(-0.01, 0.01));
    const double qz = u(-1, 1), qy = u(-1, 1), qx = u(-1, 1), qw = u(-1, 1);
    st.orientation = Quat(qw, qx, qy, qz).normalized();
    st.velocity_m_s = draw(-8, 8, -3, 3);
    const Vec3 w = draw(-60, 60, -630, 630);
    const Mat3 R = st.orientation.toRotationMatrix();
    st.angular_momentum_kg_m2_s = R * s.inertia_body_kg_m2 * w;
    return st;
  };
  auto moved = [&](RigidState st) {
    st.position_m += draw(-2e-3, 2e-3, -2e-3, 2e-3);
    const Vec3 axis = draw(-1, 1, -1, 1).normalized();
    const double angle = u(0, 0.02);
    st.orientation = (Quat(Eigen::AngleAxisd(angle, axis)) * st.orientation).normalized();
    st.velocity_m_s += draw(-0.2, 0.2, -0.2, 0.2);
    return st;
  };
  std::vector<std::pair<RigidState, RigidState>> pairs;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 5; ++j) pairs.push_back({path.at(0.004 * i), path.at(0.004 * i + 0.0005 * j)});
  for (int i = 0; i < 300; ++i) {
    const RigidState a = random_state();
    pairs.push_back({a, moved(a)});
  }
  int finite[8] = {};
  long compared = 0, mismatches = 0;
  for (const PressureDistribution d : {PressureDistribution::savitsky_wagner, PressureDistribution::savitsky}) {
    Environment env = savitsky_wagner();
    env.pressure_distribution = d;
    LoadSwitches sw(s, env);
    std::vector<double> g0, g;
    for (const auto& [a, b] : pairs) {
      sw.reset(a, g0);
      sw.evaluate(b, g);
      for (int k = 0; k < static_cast<int>(g.size()); ++k) {
        const double v = sw.value(b, k);
        ++compared;
        const bool same = std::isnan(g[k]) ? std::isnan(v) : v == g[k];
        if (!same) {
          ++mismatches;
          BOOST_TEST_MESSAGE("switch " << k << ": value " << v << " against evaluate's " << g[k]);
        }
        if (std::isfinite(g[k])) ++finite[static_cast<int>(sw.kind(k))];
      }
      BOOST_TEST(std::isnan(sw.value(b, static_cast<int>(g.size()))));  // past the last switch
    }
  }
  BOOST_TEST(mismatches == 0);
  BOOST_TEST(compared > 10000);
  for (const LoadSwitches::Kind k :
       {LoadSwitches::Kind::raised_crossing, LoadSwitches::Kind::deepest_vertex, LoadSwitches::Kind::loaded_face,
        LoadSwitches::Kind::centre_of_pressure, LoadSwitches::Kind::planing_share, LoadSwitches::Kind::underside_flip,
        LoadSwitches::Kind::span_start, LoadSwitches::Kind::span_end})
    BOOST_TEST(finite[static_cast<int>(k)] > 0, "switch kind " << static_cast<int>(k) << " never finite");
}

BOOST_AUTO_TEST_SUITE_END()
