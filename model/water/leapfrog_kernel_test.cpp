#include "model/water/leapfrog_kernel.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <atomic>
#include <cstdlib>
#include <string>
#include <cstring>
#include <random>
#include <vector>

#include "model/water/height_field.hpp"
#include "model/water/thread_team.hpp"

namespace stoneskip {
namespace {

template <class Real>
using Aligned = std::vector<Real, CacheAligned<Real>>;

// Random values in [−1, 1), with `shift` extra leading values so that the same data can be laid
// out on and off a 64-byte boundary.
template <class Real>
Aligned<Real> random_values(std::size_t n, unsigned seed, std::size_t shift = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Aligned<Real> v(n + shift);
  for (std::size_t k = 0; k < n; ++k) v[k + shift] = static_cast<Real>(u(rng));
  return v;
}

template <class Real>
LeapfrogWeights<Real> weights(bool diagonal) {
  return leapfrog_weights<Real>(diagonal ? -10.0 / 3 : -4, diagonal ? 2.0 / 3 : 1, diagonal ? 1.0 / 6 : 0, 0.6, 0.07);
}

template <class Real>
void check_segments_round_alike(bool diagonal) {
  // Oracle: the same row computed in one call (vector body + tail) and cell by cell (tail only)
  // must agree to the bit, and so must the plain block kernel — what active tiles rely on for
  // ε = 0 (model/README.md §2.6).
  const std::ptrdiff_t n = 77, w = 96;  // n not a multiple of any vector width
  const auto c = weights<Real>(diagonal);
  const auto z = random_values<Real>(3 * w, 1);
  auto whole = random_values<Real>(3 * w, 2), pieces = whole, plain = whole;
  const Real* zm = z.data() + w + 16;
  Real a1 = 0, a2 = 0;
  leapfrog_row_chunks(whole.data() + w + 16, zm, n, w, c, diagonal, n, &a1);
  for (std::ptrdiff_t k = 0; k < n; ++k) leapfrog_row_chunks(pieces.data() + w + 16 + k, zm + k, 1, w, c, diagonal, 1, &a2);
  leapfrog_block(plain.data() + w + 16, zm, n, 1, w, c, diagonal);
  BOOST_TEST(std::memcmp(whole.data(), pieces.data(), whole.size() * sizeof(Real)) == 0);
  BOOST_TEST(std::memcmp(whole.data(), plain.data(), whole.size() * sizeof(Real)) == 0);
  BOOST_TEST(a1 == a2);
}

template <class Real>
void check_aligned_and_unaligned_paths_agree(bool diagonal) {
  // Oracle: the aligned path (aligned loads, shuffled ±1 neighbours) and the unaligned one
  // evaluate the same expression on the same operands, so a block computed from a 64-byte aligned
  // copy of the data and from a copy one value off alignment must agree to the bit.
  const std::ptrdiff_t lanes = 64 / sizeof(Real), w = 6 * lanes, n = 5 * lanes - 3, rows = 4;
  const std::size_t size = static_cast<std::size_t>(w) * (rows + 4);
  const auto a = random_values<Real>(size, 3), b = random_values<Real>(size, 3, 1);
  auto pa = random_values<Real>(size, 4), pb = random_values<Real>(size, 4, 1);
  auto qa = pa, qb = pb;
  const auto c = weights<Real>(diagonal);
  const std::ptrdiff_t first = 2 * w + lanes;  // aligned in a, one value off in b
  Real act_a[3] = {}, act_b[3] = {};
  for (std::ptrdiff_t r = 0; r < rows; ++r) {
    leapfrog_row_chunks(pa.data() + first + r * w, a.data() + first + r * w, n, w, c, diagonal, 2 * lanes, act_a);
    leapfrog_row_chunks(pb.data() + first + 1 + r * w, b.data() + first + 1 + r * w, n, w, c, diagonal, 2 * lanes, act_b);
  }
  leapfrog_block(qa.data() + first, a.data() + first, n, rows, w, c, diagonal);
  leapfrog_block(qb.data() + first + 1, b.data() + first + 1, n, rows, w, c, diagonal);
  BOOST_TEST(std::memcmp(pa.data(), pb.data() + 1, size * sizeof(Real)) == 0);
  BOOST_TEST(std::memcmp(qa.data(), qb.data() + 1, size * sizeof(Real)) == 0);
  BOOST_TEST(std::memcmp(pa.data(), qa.data(), size * sizeof(Real)) == 0);
  for (int q = 0; q < 3; ++q) BOOST_TEST(act_a[q] == act_b[q]);
}

// Runs f() on every instruction-set path this CPU supports, the active path restored after.
template <class F>
void on_every_path(F&& f) {
  const SimdPath before = leapfrog_kernel_path();
  for (SimdPath p : supported_simd_paths()) {
    BOOST_TEST_CONTEXT("path " << to_string(p)) {
      BOOST_REQUIRE(set_leapfrog_kernel_path(p));
      f();
    }
  }
  set_leapfrog_kernel_path(before);
}

// One field updated by every kernel entry on one path: blocks (row pairs and, the count being
// odd, a single row) and chunked rows (with activity), on and off vector alignment, so that two
// paths' outputs can be compared byte for byte.
template <class Real>
std::vector<unsigned char> every_entry_on_active_path(bool diagonal, bool defect) {
  const std::ptrdiff_t w = 64 + 16, rows = 7, n = 64 + 5;  // w a multiple of every vector width
  const std::size_t size = static_cast<std::size_t>(w) * (rows + 4);
  const auto z = random_values<Real>(size, 11);
  auto blocks = random_values<Real>(size, 12), chunks = blocks;
  // A consistent stencil (wx = 0) or one whose weights do not sum to zero (wx ≠ 0).
  const auto c = defect ? leapfrog_weights<Real>(-3, 2.0 / 3, diagonal ? 1.0 / 6 : 0, 0.6, 0.07) : weights<Real>(diagonal);
  BOOST_TEST((c.defect != 0) == defect);
  Real act[8] = {};
  for (std::ptrdiff_t off : {std::ptrdiff_t(0), std::ptrdiff_t(1)}) {  // aligned (64 bytes) and not
    const std::ptrdiff_t first = 2 * w + off;
    leapfrog_block(blocks.data() + first, z.data() + first, n - off, rows, w, c, diagonal);
    for (std::ptrdiff_t r = 0; r < rows; ++r)
      leapfrog_row_chunks(chunks.data() + first + r * w, z.data() + first + r * w, n - off, w, c, diagonal, 16, act);
  }
  std::vector<unsigned char> bytes(2 * size * sizeof(Real) + sizeof act);
  std::memcpy(bytes.data(), blocks.data(), size * sizeof(Real));
  std::memcpy(bytes.data() + size * sizeof(Real), chunks.data(), size * sizeof(Real));
  std::memcpy(bytes.data() + 2 * size * sizeof(Real), act, sizeof act);
  return bytes;
}

template <class Real>
void check_paths_against_scalar() {
  for (bool diagonal : {true, false})
    for (bool defect : {true, false}) {
      BOOST_REQUIRE(set_leapfrog_kernel_path(SimdPath::scalar));
      const auto scalar = every_entry_on_active_path<Real>(diagonal, defect);
      on_every_path([&] { BOOST_TEST((every_entry_on_active_path<Real>(diagonal, defect) == scalar)); });
    }
}

BOOST_AUTO_TEST_SUITE(leapfrog_kernel_)

BOOST_AUTO_TEST_CASE(every_supported_instruction_set_computes_the_scalar_paths_bits) {
  // Oracle: the scalar path, cell by cell. Every vector path evaluates the same expression in the
  // same order without FMA contraction, so blocks, chunked rows and their activities must agree
  // with it byte for byte (tolerance 0), in double and float, on and off alignment.
  const SimdPath before = leapfrog_kernel_path();
  check_paths_against_scalar<double>();
  check_paths_against_scalar<float>();
  set_leapfrog_kernel_path(before);
  // A GCC build offers scalar and at least one vector path on x86-64 and aarch64; a clang build
  // (the fuzz build) the scalar path alone (leapfrog_kernel.cpp: GCC's vector extensions).
#if defined(__clang__)
  BOOST_TEST(supported_simd_paths().size() == 1u);
#else
  BOOST_TEST(supported_simd_paths().size() >= 2u);
#endif
  BOOST_TEST((supported_simd_paths().front() == SimdPath::scalar));
}

BOOST_AUTO_TEST_CASE(an_unknown_or_unsupported_path_is_refused) {
  // Oracle: the list of paths. A name that is none of them, or a path of another architecture,
  // is refused with a one-line reason and leaves the active path as it was.
  const SimdPath before = leapfrog_kernel_path();
  const char* old = std::getenv("STONESKIP_ISA");
  const std::string saved = old ? old : "";
  SimdPath p;
  std::string why;
  setenv("STONESKIP_ISA", "avx1024", 1);
  BOOST_TEST(!simd_path_from_environment(p, &why));
  BOOST_TEST(why.find("avx1024") != std::string::npos);
  BOOST_TEST(why.find('\n') == std::string::npos);
  setenv("STONESKIP_ISA", "scalar", 1);
  BOOST_TEST(simd_path_from_environment(p, &why));
  BOOST_TEST((p == SimdPath::scalar));
#if defined(__x86_64__)
  const SimdPath foreign = SimdPath::neon;
#else
  const SimdPath foreign = SimdPath::avx2;
#endif
  setenv("STONESKIP_ISA", to_string(foreign), 1);
  BOOST_TEST(!simd_path_from_environment(p, &why));
  BOOST_TEST(!set_leapfrog_kernel_path(foreign));
  BOOST_TEST((leapfrog_kernel_path() == before));
  if (old) setenv("STONESKIP_ISA", saved.c_str(), 1);
  else unsetenv("STONESKIP_ISA");
}

template <class Real>
void check_wavefront(std::ptrdiff_t n, std::ptrdiff_t rows, int steps, bool diagonal) {
  const std::ptrdiff_t w = (n + 2 + 15) / 16 * 16 + 16;
  const std::size_t size = static_cast<std::size_t>(w) * (rows + 2) + 16;
  auto a = random_values<Real>(size, 21), b = random_values<Real>(size, 22);
  // Ghosts (the rim) at zero, as a fixed boundary holds them.
  for (std::ptrdiff_t j = 0; j < rows + 2; ++j)
    for (std::ptrdiff_t i = 0; i < w; ++i)
      if (j == 0 || j == rows + 1 || i == 0 || i > n) a[j * w + i] = b[j * w + i] = 0;
  auto z1 = a, zp1 = b, z2 = a, zp2 = b;
  const auto c = weights<Real>(diagonal);
  Real* z = z1.data() + w + 1;
  Real* zp = zp1.data() + w + 1;
  for (int s = 0; s < steps; ++s) {
    leapfrog_block(zp, z, n, rows, w, c, diagonal);
    std::swap(z, zp);
  }
  leapfrog_wavefront(z2.data() + w + 1, zp2.data() + w + 1, n, rows, w, c, diagonal, steps);
  // After an odd number of steps the newest level is in the second buffer, as after the swaps.
  BOOST_TEST(std::memcmp(z1.data(), z2.data(), size * sizeof(Real)) == 0);
  BOOST_TEST(std::memcmp(zp1.data(), zp2.data(), size * sizeof(Real)) == 0);
}

BOOST_AUTO_TEST_CASE(wavefront_temporal_blocking_computes_the_one_step_sweeps_bits) {
  // Oracle: `steps` sweeps of the one-step kernel over the whole block with a swap after each.
  // The wavefront reorders the same updates without changing any operand, so both buffers must
  // agree byte for byte (tolerance 0): one step, an even and an odd number within one pass, and
  // more steps than one pass holds (passes of at most 16 levels), on every path.
  on_every_path([] {
    for (int steps : {1, 2, 7, 37}) {
      check_wavefront<double>(61, 23, steps, true);
      check_wavefront<float>(45, 9, steps, false);
    }
    check_wavefront<double>(3, 1, 5, true);  // one row: every level in one front
  });
}

BOOST_AUTO_TEST_CASE(vector_body_and_scalar_tail_round_to_the_same_bits) {
  check_segments_round_alike<double>(true);
  check_segments_round_alike<double>(false);
  check_segments_round_alike<float>(true);
  check_segments_round_alike<float>(false);
}

BOOST_AUTO_TEST_CASE(aligned_and_unaligned_paths_round_to_the_same_bits) {
  check_aligned_and_unaligned_paths_agree<double>(true);
  check_aligned_and_unaligned_paths_agree<double>(false);
  check_aligned_and_unaligned_paths_agree<float>(true);
  check_aligned_and_unaligned_paths_agree<float>(false);
}

template <class Real>
void check_update_written_out(double tolerance) {
  const std::ptrdiff_t n = 40, w = 48;
  const auto c = weights<Real>(true);
  const auto z = random_values<Real>(3 * w, 3);
  auto zp = random_values<Real>(3 * w, 4);
  const auto before = zp;
  leapfrog_block(zp.data() + w + 1, z.data() + w + 1, n, 1, w, c, true);
  const long double sig2 = 0.36L, mdt = 0.07L;
  for (std::ptrdiff_t i = 1; i <= n; ++i) {
    const std::ptrdiff_t k = w + i;
    const long double lap = -10.0L / 3 * z[k] + 2.0L / 3 * ((long double)z[k - 1] + z[k + 1] + z[k - w] + z[k + w]) +
                            1.0L / 6 * ((long double)z[k - w - 1] + z[k - w + 1] + z[k + w - 1] + z[k + w + 1]);
    const long double e = (4 * (long double)z[k] - (2 - mdt) * before[k] + 2 * sig2 * lap) / (2 + mdt);
    BOOST_TEST(std::abs(static_cast<double>(zp[k] - e)) <= tolerance);
  }
}

BOOST_AUTO_TEST_CASE(row_matches_the_update_written_out) {
  check_update_written_out<double>(1e-15);
  check_update_written_out<float>(1e-6);
}

BOOST_AUTO_TEST_CASE(a_uniform_level_stays_exact_in_float_storage) {
  // Oracle: with a consistent stencil (wx = 0) every bracket of the increment form vanishes on a
  // uniform level, whatever the rounding of the weights, so a raised level must stay exactly as it
  // is for any number of steps, in float as in double.
  const std::ptrdiff_t n = 37, w = 64;
  const LeapfrogWeights<float> c = leapfrog_weights<float>(-10.0 / 3, 2.0 / 3, 1.0 / 6, 0.7131, 0.0005);
  Aligned<float> z(3 * w, 0.3171f), zp(3 * w, 0.3171f);
  for (int step = 0; step < 1000; ++step) {
    leapfrog_block(zp.data() + w + 16, z.data() + w + 16, n, 1, w, c, true);
    for (std::ptrdiff_t k = 0; k < 3 * w; ++k) std::swap(z[k], zp[k]);
    for (std::ptrdiff_t k = 0; k < 3 * w; ++k) zp[k] = z[k];  // keep the whole buffer level, ghosts included
  }
  for (std::ptrdiff_t k = w + 16; k < w + 16 + n; ++k) BOOST_TEST(z[k] == 0.3171f);
}

BOOST_AUTO_TEST_CASE(chunk_activity_is_the_largest_height_or_change_and_never_quiet_when_not_finite) {
  // Oracle: max(|z⁺|, |z⁺ − z|) over each chunk by direct evaluation; an inf or NaN in z makes its
  // chunk report a value that no threshold counts as quiet (!(a <= ε)).
  const std::ptrdiff_t n = 40, w = 48, chunk = 16;
  const auto c = weights<double>(true);
  auto z = random_values<double>(3 * w, 5);
  auto zp = random_values<double>(3 * w, 6);
  double act[3] = {};
  leapfrog_row_chunks(zp.data() + w + 4, z.data() + w + 4, n, w, c, true, chunk, act);
  for (int q = 0; q < 3; ++q) {
    double expect = 0;
    for (std::ptrdiff_t k = q * chunk; k < std::min((q + 1) * chunk, n); ++k)
      expect = std::max({expect, std::abs(zp[w + 4 + k]), std::abs(zp[w + 4 + k] - z[w + 4 + k])});
    BOOST_TEST(act[q] == expect);
  }
  for (double bad : {NAN, INFINITY}) {
    z[w + 4 + 20] = bad;  // in chunk 1
    double act2[3] = {};
    leapfrog_row_chunks(zp.data() + w + 4, z.data() + w + 4, n, w, c, true, chunk, act2);
    BOOST_TEST(!(act2[1] <= 1e300));
  }
}

BOOST_AUTO_TEST_CASE(thread_team_runs_every_chunk_once_per_call) {
  // Oracle: counting. 3 threads, 2000 calls of 7 chunks: each chunk's counter must read 2000
  // (atomic counters: chunks of one call may run on different threads at once).
  ThreadTeam team(3);
  BOOST_TEST(team.size() == 3);
  std::vector<std::atomic<long>> count(7);
  auto f = [&](int chunk) { count[chunk].fetch_add(1, std::memory_order_relaxed); };
  for (int r = 0; r < 2000; ++r) team.run(f, 7);
  for (const auto& c : count) BOOST_TEST(c.load() == 2000);
  ThreadTeam alone(1);
  std::vector<int> order;
  auto g = [&](int chunk) { order.push_back(chunk); };
  alone.run(g, 4);
  BOOST_TEST((order == std::vector<int>{0, 1, 2, 3}));
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
