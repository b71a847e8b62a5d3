#include "tools/scene/wave_case.hpp"

#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>
#include <cmath>

#include "tools/io/input_error.hpp"

namespace stoneskip {
namespace {

const char* kBase = R"(
[water]
stencil = "custom"
nx = 40
ny = 30
cell_m = 0.02
wave_speed_m_s = 0.8
dt_s = 0.01
t_end_s = 0.105
[stencil]
centre = -3.5
orth = 0.75
diag = 0.125
[initial]
kind = "ring"
amplitude_m = 0.01
width_m = 0.05
radius_m = 0.2
x_m = 0.4
y_m = 0.3
)";

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    wave_case_from_document(parse_toml_text(text, "case.toml", sets));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

BOOST_AUTO_TEST_SUITE(wave_case_)

BOOST_AUTO_TEST_CASE(custom_stencil_and_ring_are_read_as_written) {
  // Oracle: the values in kBase; steps = ⌈0.105/0.01⌉ = 11; defaults periodic, μ = 0.
  WaveCase c = wave_case_from_document(parse_toml_text(kBase, "case.toml"));
  BOOST_TEST(c.water.stencil.name == "custom");
  BOOST_TEST(c.water.stencil.centre == -3.5);
  BOOST_TEST(c.water.stencil.orth == 0.75);
  BOOST_TEST(c.water.stencil.diag == 0.125);
  BOOST_TEST(c.water.nx == 40);
  BOOST_TEST(c.water.ny == 30);
  BOOST_TEST(c.steps() == 11);
  BOOST_TEST(c.water.damping_per_s == 0.0);
  BOOST_TEST((c.water.boundary == Boundary::periodic));
  BOOST_TEST((c.initial.kind == DisturbanceKind::ring));
  BOOST_TEST(c.initial.radius_m == 0.2);
}

BOOST_AUTO_TEST_CASE(named_stencil_replaces_the_custom_weights_only_without_a_stencil_table) {
  // Oracle: cases/README.md — [stencil] is allowed only with stencil = "custom".
  const std::string e = error_of(kBase, {"water.stencil=five_point"});
  BOOST_TEST(e.find("stencil") != std::string::npos, e);
}

BOOST_AUTO_TEST_CASE(keys_the_kind_does_not_use_and_bad_values_are_rejected_by_name) {
  // Oracle: cases/README.md — only the keys a kind uses are allowed; ranges as documented.
  BOOST_TEST(error_of(kBase, {"initial.wavelength_m=0.1"}).find("initial.wavelength_m") != std::string::npos);
  BOOST_TEST(error_of(kBase, {"water.nx=2"}).find("water.nx") != std::string::npos);
  BOOST_TEST(error_of(kBase, {"water.boundary=open"}).find("water.boundary") != std::string::npos);
  BOOST_TEST(error_of(kBase, {"initial.kind=square"}).find("initial.kind") != std::string::npos);
  BOOST_TEST(error_of(kBase, {"water.dt_s=-1"}).find("water.dt_s") != std::string::npos);
  BOOST_TEST(error_of(kBase, {"reference.symbol=exact"}).find("reference.symbol") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_stability_limit_is_taken_over_the_modes_the_grid_holds) {
  // Oracle: the operator itself. The stencil's matrix on an N × M grid with the boundary's ghost
  // rule (periodic: wrapped; reflecting: the edge cell mirrored, ghost(−1) = cell 0; fixed: 0),
  // its most negative eigenvalue λ (Eigen, symmetric), and the leapfrog's limit 2/√(−λ) (stencil.hpp).
  // A 5 × 5 periodic five-point grid holds no checkerboard: 0.7435 there, not 1/√2 (σ = 0.74 was
  // called unstable while its RMS stayed bounded); a 6 × 6 one holds it: 1/√2.
  struct Grid {
    int nx, ny;
    Boundary b;
    const char* stencil;
  };
  for (const Grid g : {Grid{5, 5, Boundary::periodic, "five_point"}, Grid{6, 6, Boundary::periodic, "five_point"},
                       Grid{7, 7, Boundary::periodic, "nine_point_isotropic"}, Grid{5, 6, Boundary::periodic, "paper_eq11"},
                       Grid{6, 5, Boundary::reflecting, "five_point"}, Grid{5, 5, Boundary::fixed, "nine_point_isotropic"},
                       Grid{4, 7, Boundary::fixed, "nine_point_half"}}) {
    const Stencil st = named_stencil(g.stencil);
    const int n = g.nx * g.ny;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    auto add = [&](int i, int j, int di, int dj, double w) {
      int p = i + di, q = j + dj;
      auto fold = [&](int& k, int size) {
        if (k >= 0 && k < size) return true;
        if (g.b == Boundary::periodic) k = (k + size) % size;
        else if (g.b == Boundary::reflecting) k = k < 0 ? -1 - k : 2 * size - 1 - k;
        else return false;
        return true;
      };
      if (!fold(p, g.nx) || !fold(q, g.ny)) return;
      a(j * g.nx + i, q * g.nx + p) += w;
    };
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            add(i, j, di, dj, di == 0 && dj == 0 ? st.centre : (di == 0 || dj == 0 ? st.orth : st.diag));
    const double lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues().minCoeff();
    HeightFieldOptions w;
    w.nx = g.nx;
    w.ny = g.ny;
    w.boundary = g.b;
    w.stencil = st;
    const WaterStability s = water_stability(w);
    BOOST_TEST(std::abs(s.grid_limit - 2 / std::sqrt(-lambda)) <= 1e-12, g.nx << "×" << g.ny << " " << to_string(g.b) << " " << g.stencil);
    BOOST_TEST(s.grid_limit >= s.limit);
  }
}

BOOST_AUTO_TEST_CASE(a_growing_mode_the_grid_does_not_hold_does_not_make_it_unstable) {
  // Oracle: the periodic operator's eigenvalues (Eigen). The stencil centre −0.9, orth −0.25 grows
  // only at the checkerboard (symbol +0.1 at (π, π)): a 5 × 5 periodic grid holds no checkerboard,
  // its eigenvalues all lie below 0 and its limit is 2/√(−λ_min); a 6 × 6 one holds it (λ_max > 0):
  // no stable step. The 5 × 5 run was called UNSTABLE (exit 1) while its RMS did not grow.
  const Stencil st{"anti", -0.9, -0.25, 0};
  for (int n : {5, 6}) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n * n, n * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        a(j * n + i, j * n + i) += st.centre;
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
          a(j * n + i, ((j + dj + n) % n) * n + (i + di + n) % n) += st.orth;
      }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues();
    HeightFieldOptions w;
    w.nx = w.ny = n;
    w.boundary = Boundary::periodic;
    w.stencil = st;
    w.wave_speed_m_s = 1;
    w.cell_m = 0.1;
    w.dt_s = 0.05;  // σ = 0.5
    const WaterStability s = water_stability(w);
    BOOST_TEST(s.no_stable_step());  // on the plane
    if (ev.maxCoeff() < 0) {
      BOOST_TEST(std::abs(s.grid_limit - 2 / std::sqrt(-ev.minCoeff())) <= 1e-12, n);
      BOOST_TEST(s.stable(), n);
      BOOST_TEST(s.reason().find("this " + s.grid + " grid holds none") != std::string::npos, s.reason());
    } else {
      BOOST_TEST(s.grid_limit == 0.0, n);
      BOOST_TEST(!s.stable(), n);
    }
    BOOST_TEST((n == 5) == (ev.maxCoeff() < 0));
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
