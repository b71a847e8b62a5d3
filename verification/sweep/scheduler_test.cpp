// The master's scheduling on threads (no MPI job): every throw handed out comes back exactly once
// whatever order the threads finish in (oracle: the list handed out, rows that encode their own
// index), the sink sees every row on the calling thread, and guided chunks follow their closed
// form ceil(remaining / (2 · consumers)) clamped to [1, max_chunk].
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <set>
#include <thread>

#include "verification/sweep/scheduler.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(sweep_scheduler)

BOOST_AUTO_TEST_CASE(guided_chunks_shrink_to_one_towards_the_end) {
  // Oracle: the formula, by hand.
  BOOST_TEST(guided_chunk(100, 2, 32) == 25u);
  BOOST_TEST(guided_chunk(1000, 2, 32) == 32u);
  BOOST_TEST(guided_chunk(101, 2, 64) == 26u);
  BOOST_TEST(guided_chunk(3, 2, 32) == 1u);
  BOOST_TEST(guided_chunk(1, 8, 32) == 1u);
  BOOST_TEST(guided_chunk(0, 2, 32) == 0u);
}

BOOST_AUTO_TEST_CASE(every_pending_throw_comes_back_once_whatever_order_threads_finish_in) {
  // Oracle: the pending list (with gaps, as after a resume); row = (index, index²).
  std::vector<std::uint64_t> pending;
  for (std::uint64_t i = 0; i < 300; ++i)
    if (i % 7 != 3) pending.push_back(i);
  const auto caller = std::this_thread::get_id();
  const ThrowEvaluator evaluate = [](std::uint64_t i, const ThrowSite& site, RowBatch& out) {
    std::this_thread::sleep_for(std::chrono::microseconds((i * 37) % 200));  // uneven costs
    out.add_row({static_cast<double>(i), static_cast<double>(i * i), static_cast<double>(site.thread)});
  };
  std::multiset<std::uint64_t> seen;
  bool on_caller = true;
  const BatchSink sink = [&](const RowBatch& b) {
    on_caller = on_caller && std::this_thread::get_id() == caller;
    for (std::size_t r = 0; r < b.rows(); ++r) {
      const std::uint64_t i = b.throw_index(r);
      BOOST_TEST(b.values[r * 3 + 1] == static_cast<double>(i * i));
      seen.insert(i);
    }
  };
  MpiSession alone;  // not launched by MPI: a job of one
  ScheduleOptions o;
  o.master_threads = 3;
  o.max_chunk = 8;
  const ScheduleStats s = run_master(pending, 3, evaluate, sink, o, alone);
  BOOST_TEST(on_caller);
  BOOST_TEST(s.throws == pending.size());
  BOOST_TEST(seen == std::multiset<std::uint64_t>(pending.begin(), pending.end()));
  BOOST_TEST(s.remote_throws == 0u);
  BOOST_TEST(s.master_threads == 3);
}

BOOST_AUTO_TEST_CASE(nothing_pending_returns_at_once) {
  // Oracle: an empty list (a resume that found every throw in the journal).
  MpiSession alone;
  const ScheduleStats s = run_master({}, 1, [](std::uint64_t, const ThrowSite&, RowBatch&) {}, [](const RowBatch&) {}, {}, alone);
  BOOST_TEST(s.throws == 0u);
  BOOST_TEST(s.chunks == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
