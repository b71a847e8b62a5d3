// The capture scene's words for the head that forces its water (capture_figures.hpp), from the
// stored settings: the page said "draught" and "b" whatever the scene's forcing, and the shipped
// pond forces its water with the pressure head.
#include <boost/test/unit_test.hpp>

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

BOOST_AUTO_TEST_SUITE_END()
