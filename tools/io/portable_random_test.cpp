// PortableDraws (portable_random.hpp). Oracles: the engines' outputs the C++ standard fixes
// ([rand.predef]: the 10 000th of a default-seeded mt19937_64 is 9981545732273789042, of mt19937
// 4123659995) turned into [0, 1) by exact arithmetic (Python's fractions, correctly rounded); and,
// where the library is libstdc++, std::uniform_real_distribution and std::normal_distribution
// themselves, drawn from the same seed in the same order, bit for bit (the captures and ensembles
// that a seed gave before must not change).
#include "tools/io/portable_random.hpp"

#include <boost/test/unit_test.hpp>

#include <random>

namespace stoneskip {
namespace {

// The draws a capture and an ensemble member interleave: a normal, a uniform on [0, 1), a
// symmetric one, another normal (so that the kept second value of a pair is used between uniforms).
template <class Engine>
void expect_libstdcxx_draws(typename Engine::result_type seed) {
  Engine rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1e-12, 1e-12);
  PortableDraws<Engine> draws(seed);
  int differ = 0;
  for (int k = 0; k < 20000; ++k) {
    differ += gauss(rng) != draws.gauss();
    differ += unit(rng) != draws.unit();
    differ += sym(rng) != draws.uniform(-1e-12, 1e-12);
    differ += gauss(rng) != draws.gauss();
  }
  BOOST_TEST(differ == 0);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(portable_random)

BOOST_AUTO_TEST_CASE(a_unit_draw_is_the_standard_engine_output_over_its_range) {
  // A 64-bit engine: one output a draw, so the 10 000th draw is the 10 000th output over 2^64,
  // correctly rounded (0.5411006783847329, exact to the last bit).
  PortableDraws<std::mt19937_64> wide(5489u);  // the engines' default seed
  double u = 0;
  for (int k = 0; k < 10000; ++k) u = wide.unit();
  BOOST_TEST(u == 0.5411006783847329);
  // A 32-bit engine: two outputs a draw, the second the high half, so the 5 000th draw is the
  // 10 000th output over 2^32 plus less than 2^-32 from the 9 999th.
  PortableDraws<std::mt19937> narrow(5489u);
  for (int k = 0; k < 5000; ++k) u = narrow.unit();
  BOOST_TEST(u >= 0.9601144108455628 - 0x1p-52);
  BOOST_TEST(u < 0.9601144108455628 + 0x1p-32);
}

BOOST_AUTO_TEST_CASE(normal_draws_have_the_moments_of_a_standard_normal) {
  // 200 000 draws: the mean's standard error is 1/√n = 0.0022 and the variance's √(2/n) = 0.0032;
  // 5 standard errors is a bound a correct generator passes but for about 1 in 1.7 million seeds,
  // and a wrong scale (σ = √2, from a lost factor) or a biased pair fails by tens of them.
  PortableDraws<std::mt19937_64> draws(12345u);
  const int n = 200000;
  double sum = 0, sum2 = 0, sum4 = 0;
  for (int k = 0; k < n; ++k) {
    const double g = draws.gauss();
    sum += g;
    sum2 += g * g;
    sum4 += g * g * g * g;
  }
  BOOST_TEST(std::abs(sum / n) < 5 / std::sqrt(double(n)));
  BOOST_TEST(std::abs(sum2 / n - 1) < 5 * std::sqrt(2.0 / n));
  // The fourth moment is 3 for a normal (its standard error √(96/n) = 0.022): a uniform or a
  // triangular shape of the right variance gives 1.8 or 2.4.
  BOOST_TEST(std::abs(sum4 / n - 3) < 5 * std::sqrt(96.0 / n));
}

BOOST_AUTO_TEST_CASE(draws_equal_libstdcxx_distributions_bit_for_bit) {
#if defined(__GLIBCXX__)
  expect_libstdcxx_draws<std::mt19937_64>(7u);
  expect_libstdcxx_draws<std::mt19937_64>(0x9e3779b97f4a7c15ULL);
  expect_libstdcxx_draws<std::mt19937>(5u);
#else
  BOOST_TEST_MESSAGE("not libstdc++: its distributions are not this library's; the other cases stand");
#endif
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace stoneskip
