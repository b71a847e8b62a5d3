#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "model/water/height_field.hpp"

namespace stoneskip {
namespace {

// The forced update differs from the free one only by 2c²Δt² L[b]/(2 + μΔt), so a forced step of
// (z, z⁻) equals a free step of (z + b, z⁻ + 4b/(2 − μΔt)) with b spread densely over the grid
// (its ghosts made by the boundary rule like z's). That free step is an independent route to
// the same numbers (no patch, no scatter, no images); the tolerance is round-off of O(1) values.
constexpr double kRoundoff = 1e-13;

HeightFieldOptions small_field(Boundary b, const std::string& stencil) {
  HeightFieldOptions o;
  o.nx = 23;
  o.ny = 17;
  o.cell_m = 0.05;
  o.wave_speed_m_s = 1.3;
  o.damping_per_s = 2.0;
  o.dt_s = 0.4 * o.cell_m / o.wave_speed_m_s;
  o.stencil = named_stencil(stencil);
  o.boundary = b;
  return o;
}

std::vector<double> noise(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> v(n);
  for (auto& x : v) x = u(rng);
  return v;
}

void check_forced_step(Boundary boundary, const std::string& stencil, int i0, int j0, int ni, int nj) {
  const auto o = small_field(boundary, stencil);
  const std::size_t n = static_cast<std::size_t>(o.nx) * o.ny;
  const auto z = noise(n, 1), zm = noise(n, 2);
  DraughtPatch p;
  p.reset(i0, j0, ni, nj);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (double& b : p.b_m) b = u(rng);
  // Dense b on the grid: wrapped (periodic) or the part inside the grid (others).
  std::vector<double> dense(n, 0.0);
  for (int c = 0; c < nj; ++c)
    for (int a = 0; a < ni; ++a) {
      int i = i0 + a, j = j0 + c;
      if (boundary == Boundary::periodic) {
        i = ((i % o.nx) + o.nx) % o.nx;
        j = ((j % o.ny) + o.ny) % o.ny;
      } else if (i < 0 || i >= o.nx || j < 0 || j >= o.ny) {
        continue;
      }
      dense[static_cast<std::size_t>(j) * o.nx + i] += p.at(a, c);
    }
  HeightField forced(o), free(o);
  forced.set_levels(z, zm);
  const double mdt = o.damping_per_s * o.dt_s;
  std::vector<double> z2(n), zm2(n);
  for (std::size_t k = 0; k < n; ++k) {
    z2[k] = z[k] + dense[k];
    zm2[k] = zm[k] + 4 * dense[k] / (2 - mdt);
  }
  free.set_levels(z2, zm2);
  forced.step(p);
  free.step();
  double worst = 0;
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i) worst = std::max(worst, std::abs(forced.height(i, j) - free.height(i, j)));
  BOOST_TEST(worst <= kRoundoff, to_string(boundary) << " " << stencil << " box (" << i0 << "," << j0 << ") " << ni
                                                      << "x" << nj << ": " << worst);
}

BOOST_AUTO_TEST_SUITE(forced_step_)

BOOST_AUTO_TEST_CASE(forced_step_equals_a_free_step_of_the_shifted_levels_on_every_boundary) {
  // Oracle: see kRoundoff. Boxes inside, across an edge, across a corner, and (periodic) as wide
  // as the grid, for a 5-point and a 9-point stencil.
  for (auto b : {Boundary::periodic, Boundary::reflecting, Boundary::fixed})
    for (const char* s : {"five_point", "nine_point_isotropic"}) {
      check_forced_step(b, s, 5, 4, 6, 5);
      check_forced_step(b, s, -2, 3, 5, 4);
      check_forced_step(b, s, 19, 14, 6, 6);
      check_forced_step(b, s, -1, -1, 3, 3);
    }
  check_forced_step(Boundary::periodic, "nine_point_half", -7, 2, 23, 17);
}

BOOST_AUTO_TEST_CASE(empty_draught_is_the_free_step_to_the_bit) {
  // Oracle: an empty patch adds nothing, so the field must equal a free run bit for bit.
  const auto o = small_field(Boundary::reflecting, "nine_point_isotropic");
  const std::size_t n = static_cast<std::size_t>(o.nx) * o.ny;
  HeightField a(o), b(o);
  a.set_state(noise(n, 7));
  b.set_state(noise(n, 7));
  DraughtPatch empty;
  for (int s = 0; s < 50; ++s) {
    a.step(empty);
    b.step();
  }
  std::vector<double> za, zb;
  a.heights(za);
  b.heights(zb);
  BOOST_TEST(std::memcmp(za.data(), zb.data(), n * sizeof(double)) == 0);
}

BOOST_AUTO_TEST_CASE(threads_and_float32_storage_give_the_same_field) {
  // Oracle: the update of a cell does not depend on which thread computes it, so two or three
  // threads give the one-thread field bit for bit. float32 storage rounds each level to 24 bits:
  // against float64 after 200 steps of an O(1) field the difference stays ~1e-6 (a few hundred
  // float ulps of accumulated, bounded round-off; the scheme is neutrally stable).
  auto o = small_field(Boundary::periodic, "nine_point_isotropic");
  o.nx = 70;  // several vector widths and a tail per row
  o.ny = 41;
  const std::size_t n = static_cast<std::size_t>(o.nx) * o.ny;
  const auto z0 = noise(n, 11);
  HeightField one(o);
  one.set_state(z0);
  one.advance(200);
  std::vector<double> z1, zt;
  one.heights(z1);
  for (int threads : {2, 3}) {
    auto ot = o;
    ot.threads = threads;
    HeightField many(ot);
    many.set_state(z0);
    many.advance(200);
    many.heights(zt);
    BOOST_TEST(std::memcmp(z1.data(), zt.data(), n * sizeof(double)) == 0, threads << " threads");
  }
  auto of = o;
  of.precision = Precision::float32;
  HeightField single(of);
  single.set_state(z0);
  single.advance(200);
  single.heights(zt);
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k) worst = std::max(worst, std::abs(zt[k] - z1[k]));
  BOOST_TEST(worst <= 1e-5);
  BOOST_TEST(worst > 0);  // it is float storage
}

BOOST_AUTO_TEST_CASE(invalid_options_are_refused_with_the_option_named) {
  // Oracle: HeightFieldOptions::is_valid names the offending option.
  HeightFieldOptions o;
  std::string why;
  o.threads = 0;
  BOOST_TEST(!o.is_valid(&why));
  BOOST_TEST(why.find("threads") != std::string::npos);
  o = HeightFieldOptions{};
  o.tiles.epsilon_m = -1;
  BOOST_TEST(!o.is_valid(&why));
  BOOST_TEST(why.find("epsilon") != std::string::npos);
  BOOST_CHECK_THROW(HeightField{o}, std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
