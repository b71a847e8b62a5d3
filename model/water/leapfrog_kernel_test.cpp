#include "model/water/leapfrog_kernel.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "model/water/height_field.hpp"
#include "model/water/thread_team.hpp"

namespace stoneskip {
namespace {

// Three rows of random values around a middle row of length n, stride w = n + 2.
template <class Real>
std::vector<Real> random_rows(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Real> v(static_cast<std::size_t>(3) * (n + 2));
  for (auto& x : v) x = static_cast<Real>(u(rng));
  return v;
}

template <class Real>
void check_segments_round_alike(bool diagonal) {
  // Oracle: the same row computed in one call (vector body + tail) and cell by cell (tail only)
  // must agree to the bit — the property active tiles rely on for ε = 0 (spec §2.6).
  const int n = 77;  // not a multiple of any vector width
  const std::ptrdiff_t w = n + 2;
  const LeapfrogWeights<Real> c{Real(0.3), Real(0.17), Real(diagonal ? 0.05 : 0), Real(0.93)};
  auto z = random_rows<Real>(n, 1);
  auto whole = random_rows<Real>(n, 2), pieces = whole;
  const Real* zm = z.data() + w + 1;
  const double a1 = leapfrog_block_activity(whole.data() + w + 1, zm, n, 1, w, c, diagonal);
  double a2 = 0;
  for (int k = 0; k < n; ++k) a2 = std::max(a2, static_cast<double>(leapfrog_block_activity(pieces.data() + w + 1 + k, zm + k, 1, 1, w, c, diagonal)));
  BOOST_TEST(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(Real)) == 0);
  BOOST_TEST(a1 == a2);
  // And the plain kernel writes the same bits as the activity kernel.
  auto plain = random_rows<Real>(n, 2);
  leapfrog_block(plain.data() + w + 1, zm, n, 1, w, c, diagonal);
  BOOST_TEST(std::memcmp(whole.data(), plain.data(), whole.size() * sizeof(Real)) == 0);
}

BOOST_AUTO_TEST_SUITE(leapfrog_kernel_)

BOOST_AUTO_TEST_CASE(vector_body_and_scalar_tail_round_to_the_same_bits) {
  check_segments_round_alike<double>(true);
  check_segments_round_alike<double>(false);
  check_segments_round_alike<float>(true);
  check_segments_round_alike<float>(false);
}

template <class Real>
void check_aligned_and_unaligned_paths_agree(bool diagonal) {
  // Oracle: the aligned path (shuffled neighbours) and the unaligned one (unaligned loads) evaluate
  // the same expression on the same operands, so a block computed from a 64-byte aligned copy of
  // the data and from a copy one value off alignment must agree to the bit.
  const std::ptrdiff_t lanes = 64 / sizeof(Real), w = 6 * lanes, n = 5 * lanes - 3, rows = 4;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Real, CacheAligned<Real>> a(static_cast<std::size_t>(w) * (rows + 4)), b(a.size() + 1), pa(a.size()), pb(b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    a[k] = b[k + 1] = static_cast<Real>(u(rng));
    pa[k] = pb[k + 1] = static_cast<Real>(u(rng));
  }
  const LeapfrogWeights<Real> c{Real(0.3), Real(0.17), Real(diagonal ? 0.05 : 0), Real(0.93)};
  const std::ptrdiff_t first = 2 * w + lanes;  // aligned in a, one value off in b
  const double act_a = leapfrog_block_activity(pa.data() + first, a.data() + first, n, rows, w, c, diagonal);
  const double act_b = leapfrog_block_activity(pb.data() + first + 1, b.data() + first + 1, n, rows, w, c, diagonal);
  BOOST_TEST(std::memcmp(pa.data(), pb.data() + 1, pa.size() * sizeof(Real)) == 0);
  BOOST_TEST(act_a == act_b);
}

BOOST_AUTO_TEST_CASE(aligned_and_unaligned_paths_round_to_the_same_bits) {
  check_aligned_and_unaligned_paths_agree<double>(true);
  check_aligned_and_unaligned_paths_agree<double>(false);
  check_aligned_and_unaligned_paths_agree<float>(true);
  check_aligned_and_unaligned_paths_agree<float>(false);
}

BOOST_AUTO_TEST_CASE(row_matches_the_update_written_out) {
  // Oracle: the update of spec §2.1 evaluated in long double cell by cell; tolerance a few ulps of
  // the O(1) terms (the kernel rounds each of ~12 operations once).
  const int n = 40;
  const std::ptrdiff_t w = n + 2;
  const LeapfrogWeights<double> c{0.3, 0.17, 0.05, 0.93};
  auto z = random_rows<double>(n, 3);
  auto zp = random_rows<double>(n, 4);
  const auto before = zp;
  leapfrog_block(zp.data() + w + 1, z.data() + w + 1, n, 1, w, c, true);
  for (int i = 1; i <= n; ++i) {
    const std::ptrdiff_t k = w + i;
    long double e = (long double)c.centre * z[k] +
                    (long double)c.orth * ((long double)z[k - 1] + z[k + 1] + z[k - w] + z[k + w]) +
                    (long double)c.diag * ((long double)z[k - w - 1] + z[k - w + 1] + z[k + w - 1] + z[k + w + 1]) -
                    (long double)c.previous * before[k];
    BOOST_TEST(std::abs(static_cast<double>(zp[k] - e)) <= 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(activity_is_the_largest_height_or_change_and_nan_is_never_quiet) {
  // Oracle: max(|z⁺|, |z⁺ − z|) over the row, by direct evaluation; a NaN in z makes it NaN.
  const int n = 33;
  const std::ptrdiff_t w = n + 2;
  const LeapfrogWeights<double> c{0.3, 0.17, 0.05, 0.93};
  auto z = random_rows<double>(n, 5);
  auto zp = random_rows<double>(n, 6);
  const double act = leapfrog_block_activity(zp.data() + w + 1, z.data() + w + 1, n, 1, w, c, true);
  double expect = 0;
  for (int i = 1; i <= n; ++i) expect = std::max({expect, std::abs(zp[w + i]), std::abs(zp[w + i] - z[w + i])});
  BOOST_TEST(act == expect);
  z[w + 9] = NAN;
  BOOST_TEST(std::isnan(leapfrog_block_activity(zp.data() + w + 1, z.data() + w + 1, n, 1, w, c, true)));
  z[w + 9] = INFINITY;
  BOOST_TEST(std::isnan(leapfrog_block_activity(zp.data() + w + 1, z.data() + w + 1, n, 1, w, c, true)));
}

BOOST_AUTO_TEST_CASE(thread_team_runs_every_part_once_per_call) {
  // Oracle: counting. 3 threads, 2000 calls: each part's counter must read 2000.
  ThreadTeam team(3);
  BOOST_TEST(team.size() == 3);
  std::vector<long> count(3, 0);
  auto f = [&](int part) { ++count[part]; };
  for (int r = 0; r < 2000; ++r) team.run(f);
  for (long c : count) BOOST_TEST(c == 2000);
  // part_range tiles [0, count) without gaps or overlap.
  long covered = 0;
  for (int p = 0; p < 7; ++p) {
    const PartRange r = part_range(100, p, 7);
    BOOST_TEST(r.begin == covered);
    covered = r.end;
  }
  BOOST_TEST(covered == 100);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
