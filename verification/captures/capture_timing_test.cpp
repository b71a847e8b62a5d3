// Timing of a capture against stamps whose generating clock is known: the oracle is that clock
// (its rate, the reports it dropped) and independent computations of the statistics.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "tools/io/portable_random.hpp"
#include "verification/captures/capture_timing.hpp"

using namespace stoneskip;

namespace {
Trace stamped(const std::vector<double>& stamps) {
  Trace t;
  for (double s : stamps) {
    TraceSample x;
    x.t_s = s;
    t.samples.push_back(x);
  }
  return t;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(capture_timing)

BOOST_AUTO_TEST_CASE(a_regular_clock_under_host_jitter_is_recovered_and_its_losses_counted) {
  // Oracle: a 100 Hz clock (slot n at 2.5 + n/100 s) stamped with uniform ±j jitter, with 6 % of
  // the slots lost at random. The slots must be found exactly, and the fitted clock must match the
  // true one to a few σ/√N (σ = j/√3). j = 4.5 ms is the hard case: two stamps can be 1 ms or 29 ms
  // apart, so counting slots interval by interval fails, yet every stamp is within half a period of
  // its slot.
  for (const double j : {0.003, 0.0045}) {
    BOOST_TEST_CONTEXT("jitter ±" << 1e3 * j << " ms") {
      PortableDraws<std::mt19937_64> rng(5);  // the same stamps from every standard library
      std::vector<double> stamps, truth;
      std::vector<long> slots;
      long lost = 0;
      for (long n = 0; n < 200; ++n) {
        if (n > 0 && n < 199 && rng.unit() < 0.06) {
          ++lost;
          continue;
        }
        truth.push_back(2.5 + n / 100.0);
        stamps.push_back(truth.back() + rng.uniform(-j, j));
        slots.push_back(n);
      }
      const TimedSamples t = analyse_timing(stamped(stamps));
      BOOST_TEST(to_string(t.stats.clock) == std::string("regular_reports"));
      BOOST_TEST(t.stats.dropped_reports == lost);
      bool all = true;
      for (std::size_t k = 0; k < slots.size(); ++k) all = all && t.report_index[k] == slots[k];
      BOOST_TEST(all);
      const double tolerance = 5 * (j / std::sqrt(3.0)) / std::sqrt(double(stamps.size()));  // the line's own error
      double worst = 0;
      for (std::size_t k = 0; k < truth.size(); ++k) worst = std::max(worst, std::abs(t.t_s[k] - truth[k]));
      BOOST_TEST(worst < 2 * tolerance);
      // The rate the times use is the fitted clock's: within 5 σ of its slope (σ_b = σ / √Σ(n − n̄)²,
      // Σ ≈ N³/12 over 200 slots) of 100 Hz, whatever the median interval says.
      const double sigma_b = (j / std::sqrt(3.0)) / std::sqrt(200.0 * 200.0 * 200.0 / 12.0);
      BOOST_TEST(std::abs(t.stats.clock_rate_hz - 100.0) < 5 * sigma_b * 100.0 * 100.0, t.stats.clock_rate_hz);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_minute_long_capture_keeps_every_slot) {
  // Oracle: as above, for 6000 reports (a minute at 100 Hz) with ±4 ms jitter and 3 % lost: the
  // period found from the first stamps must carry the slot count through to the last report.
  PortableDraws<std::mt19937_64> rng(11);
  std::vector<double> stamps;
  std::vector<long> slots;
  for (long n = 0; n < 6000; ++n) {
    if (n > 0 && n < 5999 && rng.unit() < 0.03) continue;
    stamps.push_back(100.0 + n * 0.0099 + rng.uniform(-0.004, 0.004));  // a remote whose clock runs 1 % fast
    slots.push_back(n);
  }
  const TimedSamples t = analyse_timing(stamped(stamps));
  BOOST_TEST(to_string(t.stats.clock) == std::string("regular_reports"));
  bool all = true;
  for (std::size_t k = 0; k < slots.size(); ++k) all = all && t.report_index[k] == slots[k];
  BOOST_TEST(all);
  BOOST_TEST(t.stats.dropped_reports == long(6000 - stamps.size()));
}

BOOST_AUTO_TEST_CASE(stamps_without_a_regular_clock_are_kept_as_given) {
  // Oracle: a sampler whose rate drifts from 200 Hz to 50 Hz has no regular clock within half an
  // interval of its stamps: the stamps must be used unchanged, and the reported statistics must
  // equal the ones computed here from the intervals.
  std::vector<double> stamps{0.0};
  for (int k = 0; k < 120; ++k) stamps.push_back(stamps.back() + 0.005 + 0.015 * k / 119.0);
  stamps.push_back(stamps.back());  // two samples stamped alike
  stamps.push_back(stamps.back() + 0.02);
  const TimedSamples t = analyse_timing(stamped(stamps));
  BOOST_TEST(to_string(t.stats.clock) == std::string("stamps_as_given"));
  BOOST_TEST(t.t_s == stamps, boost::test_tools::per_element());
  BOOST_TEST(t.stats.equal_stamps == 1u);
  BOOST_TEST(t.stats.min_interval_s == 0.0);
  const double duration = stamps.back() - stamps.front();
  BOOST_TEST(std::abs(t.stats.mean_rate_hz - double(stamps.size() - 1) / duration) < 1e-12);
  // Forcing the regular model replaces them anyway (the user's choice).
  TimingOptions o;
  o.clock = ClockModel::regular_reports;
  BOOST_TEST(to_string(analyse_timing(stamped(stamps), o).stats.clock) == std::string("regular_reports"));
}

BOOST_AUTO_TEST_CASE(jitter_is_the_standard_deviation_of_the_intervals_that_are_not_gaps) {
  // Oracle: the sample standard deviation computed here over the intervals below 1.5 periods.
  std::vector<double> stamps;
  double s = 0;
  for (int k = 0; k < 50; ++k) {
    stamps.push_back(s);
    s += (k % 3 == 0 ? 0.012 : 0.009) + (k == 20 ? 0.03 : 0.0);
  }
  const TimedSamples t = analyse_timing(stamped(stamps));
  std::vector<double> ok;
  for (std::size_t k = 1; k < stamps.size(); ++k)
    if (stamps[k] - stamps[k - 1] < 1.5 * 0.009) ok.push_back(stamps[k] - stamps[k - 1]);
  double mean = 0, var = 0;
  for (double d : ok) mean += d / double(ok.size());
  for (double d : ok) var += (d - mean) * (d - mean) / double(ok.size() - 1);
  BOOST_TEST(std::abs(t.stats.jitter_s - std::sqrt(var)) < 1e-15);
  BOOST_TEST(t.stats.gaps == 1);
  BOOST_TEST(std::abs(t.stats.longest_gap_s - 0.039) < 1e-15);
}

BOOST_AUTO_TEST_CASE(reports_reaching_the_host_in_bursts_keep_their_rate_and_losses) {
  // Oracle: a 100 Hz clock whose reports a logger reads in bursts of b: all b are stamped 0.2 ms
  // apart when the last of them is sent (slots n at n/100 s). Counted interval by interval they
  // look like a 100/b Hz stream with a report lost in every long interval; the rate is 100 Hz,
  // and what is lost is only the 3 slots removed (each a whole burst's worth of time later).
  for (const int b : {2, 3, 4}) {
    BOOST_TEST_CONTEXT("bursts of " << b) {
      std::vector<double> stamps;
      for (long n = 0; n < 396; ++n) {  // 396: whole bursts of 2, 3 and 4
        if (n == 101 || n == 202 || n == 303) continue;  // lost: their slots are skipped
        const long last = (n / b) * b + b - 1;            // the burst's last report
        stamps.push_back(1.0 + 0.01 * double(last) + 0.0002 * double(n % b));
      }
      const TimedSamples t = analyse_timing(stamped(stamps));
      BOOST_TEST(t.stats.bursts);
      BOOST_TEST(t.stats.rate_hz == 100.0, boost::test_tools::tolerance(1e-6));
      BOOST_TEST(t.stats.dropped_reports == 3);
      BOOST_TEST(t.stats.jitter_s > 0.003);  // stamps up to b − 1 periods from their slots: a caveat
      // The slots: increasing, and the last report in the last of the 396 slots.
      BOOST_TEST(std::is_sorted(t.report_index.begin(), t.report_index.end()));
      BOOST_TEST((std::adjacent_find(t.report_index.begin(), t.report_index.end()) == t.report_index.end()));
      BOOST_TEST(t.report_index.back() == 395);
    }
  }
  // A logger polling every 25 ms reads bursts of 2 and 3 in turn (2.5 periods a poll): the rate
  // is still 100 Hz (to the 8-report runs' rounding), and no loss is counted where none happened.
  std::vector<double> polled;
  for (long n = 0; n < 400; ++n) {
    const double sent = 1.0 + 0.01 * double(n);
    const double poll = 1.0 + 0.025 * std::ceil((sent - 1.0) / 0.025 + 1e-9);  // the next poll after it
    polled.push_back(poll + 0.0002 * double(n % 3));
  }
  std::sort(polled.begin(), polled.end());
  const TimedSamples p = analyse_timing(stamped(polled));
  BOOST_TEST(p.stats.bursts);
  BOOST_TEST(std::abs(p.stats.rate_hz - 100.0) <= 2.0, p.stats.rate_hz);
  BOOST_TEST(p.stats.dropped_reports == 0);
  // A regular stream with host jitter is no burst (the windowed and single medians agree).
  std::vector<double> steady;
  for (long n = 0; n < 400; ++n) steady.push_back(1.0 + 0.01 * double(n) + 0.002 * ((n * 7919) % 3 - 1));
  BOOST_TEST(!analyse_timing(stamped(steady)).stats.bursts);
}

BOOST_AUTO_TEST_SUITE_END()
