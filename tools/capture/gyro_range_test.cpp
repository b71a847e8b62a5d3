// The MotionPlus range modes inferred from raw counts alone (gyro_range.hpp), against sequences
// whose modes are known: a rate recorded as the device records it (slow mode 20 counts per deg/s,
// fast mode fast_factor times coarser; fast above 350 deg/s, slow again below 250, the hysteresis of
// synthetic_capture.hpp's sensor).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "tools/capture/gyro_range.hpp"

using namespace stoneskip;

namespace {
constexpr double kCountsPerDegS = 20.0;
constexpr double kFastFactor = 2000.0 / 440.0;

struct Recording {
  std::vector<std::array<double, 3>> counts;  // raw − zero, on axis 0 (the others still)
  std::vector<bool> fast;                     // the device's mode on axis 0
};

Recording record(const std::vector<double>& rate_deg_s, double noise_counts = 0, unsigned seed = 1) {
  Recording r;
  std::mt19937_64 g(seed);
  std::normal_distribution<double> noise(0, noise_counts > 0 ? noise_counts : 1);
  bool fast = false;
  for (double w : rate_deg_s) {
    if (!fast && std::abs(w) > 350) fast = true;
    else if (fast && std::abs(w) < 250) fast = false;
    double c = w * kCountsPerDegS / (fast ? kFastFactor : 1.0);
    if (noise_counts > 0) c += noise(g);
    r.counts.push_back({std::round(c), 0.0, 0.0});
    r.fast.push_back(fast);
  }
  return r;
}

int mismatches(const GyroRangeInference& inferred, const Recording& r) {
  int m = 0;
  for (std::size_t k = 0; k < r.fast.size(); ++k) m += inferred.fast[k][0] != r.fast[k];
  return m;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(gyro_range)

BOOST_AUTO_TEST_CASE(a_swing_that_ends_in_fast_mode_is_read_fast_to_the_end) {
  // A gesture file ends at the release, in the swing's fastest part: here the rate rises by 80 deg/s
  // a sample (8 000 deg/s² at 100 Hz) to 1 600 deg/s, fast from 400 deg/s on, and the file ends there.
  // Judged by the rate's first differences, staying slow is smoother (every later step reads 4.5×
  // smaller, and that outweighs the one jump at the switch); the rate's slope does not jump.
  std::vector<double> rate(20, 0.0);
  for (int k = 1; k <= 20; ++k) rate.push_back(80.0 * k);
  const Recording r = record(rate);
  const GyroRangeInference inferred = infer_gyro_range(r.counts, kFastFactor);
  BOOST_TEST(mismatches(inferred, r) == 0);
  BOOST_TEST(inferred.switches == 1);
}

BOOST_AUTO_TEST_CASE(a_swing_up_and_back_down_switches_twice_on_a_noisy_sensor) {
  // A swing's rate profile, 0 → 900 → 0 deg/s as 900 sin²(π τ) over 0.4 s at 100 Hz, with the
  // synthetic sensor's noise (0.2 deg/s, 4 counts): fast over the middle, slow at both ends.
  std::vector<double> rate(30, 0.0);
  for (int k = 0; k <= 40; ++k) rate.push_back(900.0 * std::pow(std::sin(std::numbers::pi * k / 40.0), 2));
  rate.insert(rate.end(), 30, 0.0);
  const Recording r = record(rate, 4.0, 7);
  const GyroRangeInference inferred = infer_gyro_range(r.counts, kFastFactor);
  BOOST_TEST(mismatches(inferred, r) == 0);
  BOOST_TEST(inferred.switches == 2);
}

BOOST_AUTO_TEST_CASE(a_still_noisy_record_never_switches) {
  // Noise alone, 4 counts (0.2 deg/s) about zero and about a slow 100 deg/s turn: no switch is cheaper.
  std::vector<double> rate(100, 0.0);
  rate.insert(rate.end(), 100, 100.0);
  const Recording r = record(rate, 4.0, 11);
  const GyroRangeInference inferred = infer_gyro_range(r.counts, kFastFactor);
  BOOST_TEST(inferred.switches == 0);
}

BOOST_AUTO_TEST_CASE(irregular_stamps_are_judged_by_the_rate_per_typical_step) {
  // The ramp of the first case, sampled at stamps 10 ms apart with every third report lost (a 20 ms
  // step): per stamp, the rate's slope is the same whatever the gap, and the modes are found.
  std::vector<double> t, rate;
  for (int k = 0; k < 50; ++k) {
    if (k % 3 == 2) continue;
    t.push_back(0.01 * k);
    rate.push_back(k < 30 ? 0.0 : 80.0 * (k - 29));
  }
  const Recording r = record(rate);
  const GyroRangeInference inferred = infer_gyro_range(r.counts, kFastFactor, t);
  BOOST_TEST(mismatches(inferred, r) == 0);
}

BOOST_AUTO_TEST_SUITE_END()
