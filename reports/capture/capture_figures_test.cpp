// The capture scene's words for the head that forces its water (capture_figures.hpp), from the
// stored settings: the page said "draught" and "b" whatever the scene's forcing, and the shipped
// pond forces its water with the pressure head.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "reports/capture/capture_figures.hpp"

using namespace stoneskip;

namespace {

bool says(const WaveForcingWords& w, const std::string& word) {
  for (const std::string* s : {&w.name, &w.short_name, &w.feedback, &w.gathering})
    if (s->find(word) != std::string::npos) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capture_scene_words)

BOOST_AUTO_TEST_CASE(the_words_follow_the_stored_forcing) {
  // Oracle: solvers/scene/coupled_scene.hpp's two forcings: pressure forces with the faces'
  // pressure head, displacement with the draught b sampled K times a water step.
  Record pressure, displacement, neither;
  pressure.set("forcing", std::string("pressure")).set("draught_samples", 8);
  displacement.set("forcing", std::string("displacement")).set("draught_samples", 8);
  neither.set("draught_samples", 8);  // a record written before the forcing was stored
  const WaveForcingWords p = wave_forcing_words(pressure), d = wave_forcing_words(displacement), n = wave_forcing_words(neither);
  BOOST_TEST(p.name == "the pressure head");
  BOOST_TEST(!says(p, "draught"));
  BOOST_TEST(d.name == "the draught");
  BOOST_TEST(d.gathering == "8 draught samples per water step");
  BOOST_TEST(!says(n, "draught"));
  BOOST_TEST(!says(n, "pressure"));
}

BOOST_AUTO_TEST_CASE(a_far_member_does_not_set_the_bounce_axis) {
  // Oracle: by construction: 59 members make 1 to 31 bounces (central 95 % up to 31) and one makes
  // 102. The axis ends at ⌈1.25 · 31 + 2⌉ = 41 (the 31 shown with room), and a label says that one
  // member lies beyond, up to 102; a spread without such a member keeps its whole range.
  Record c;
  Record& e = c.child("simulation").child("ensemble");
  Table h{{"bounces", "members"}, {}};
  h.add_row({1, 30});
  h.add_row({2, 20});
  h.add_row({31, 9});
  h.add_row({102, 1});
  e.set_table("histogram", h);
  e.set("bounces_high", 31.0);
  const auto f = capture_bounce_figure("k", c);
  BOOST_REQUIRE(f.has_value());
  BOOST_TEST(f->script.find("set xrange [0.4:41.6]") != std::string::npos, f->script);
  BOOST_TEST(f->script.find("1 member beyond the axis, up to 102 bounces") != std::string::npos, f->script);
  e.set("bounces_high", 102.0);  // the far member inside the central 95 %: the whole range
  const auto whole = capture_bounce_figure("k", c);
  BOOST_TEST(whole->script.find("set xrange [0.4:102.6]") != std::string::npos, whole->script);
  BOOST_TEST(whole->script.find("beyond the axis") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_timing_figure_writes_no_nan_or_inf_into_its_script) {
  // Oracle: gnuplot knows NaN but not printf's `nan` or `inf` (an undefined variable: the figure
  // failed), found by rendering a data.h5 edited to a NaN jitter and to 1e308 s. A timing of 10 ms
  // ± 1 ms is drawn with those lines; a jitter of 1e308 s is refused by name; NaN too.
  Record c;
  Record& t = c.child("timing");
  t.set("nominal", false).set("ok", true).set("clock", std::string("host"));
  t.set("period_s", 0.01).set("jitter_s", 0.001).set("max_interval_s", 0.012);
  Table iv{{"t_s", "interval_ms", "lost_reports", "stamp_minus_clock_ms"}, {}};
  for (int k = 1; k <= 5; ++k) iv.add_row({0.01 * k, 10.0, 0.0, 0.0});
  t.set_table("intervals", iv);
  const auto f = capture_timing_figure("k", c);
  BOOST_REQUIRE(f.has_value());
  BOOST_TEST(f->script.find("11 w l dt 2") != std::string::npos, f->script);  // the median + jitter, ms
  BOOST_TEST(f->script.find("nan") == std::string::npos);
  BOOST_TEST(f->script.find("inf") == std::string::npos);
  for (double bad : {1e308, std::nan(""), -1.0}) {
    t.set("jitter_s", bad);
    try {
      capture_timing_figure("k", c);
      BOOST_ERROR("jitter_s = " << bad << " was drawn");
    } catch (const RecordError& e) {
      BOOST_TEST(std::string(e.what()).find("/timing: 'jitter_s' must be a number in [0, 1000000000000]") != std::string::npos,
                 e.what());
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
