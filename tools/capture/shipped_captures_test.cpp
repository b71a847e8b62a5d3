// Every shipped capture with a truth file (cases/captures/*.truth.toml) recovers its truth within
// its intervals. Oracle: the generator's truth for the throw as the remote can measure it (speed,
// attack and path angles, the spin about the stone's normal, the stone's rise since the still
// part); a capture made without a still part must be unusable. The captures are read as a user
// reads them: the format recognised from the content, the default options.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <toml.hpp>

#include "tools/capture/capture_format.hpp"
#include "verification/captures/capture_analysis.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

double number(const toml::value& t, const char* section, const char* key) {
  const toml::value& v = toml::find(t, section, key);
  return v.is_integer() ? double(v.as_integer()) : v.as_floating();
}

// The capture a truth file belongs to: NAME.truth.toml → NAME, or NAME.* for a gesture file.
fs::path capture_of(const fs::path& truth) {
  const std::string name = truth.filename().string();
  const fs::path direct = truth.parent_path() / name.substr(0, name.size() - std::string(".truth.toml").size());
  if (fs::exists(direct)) return direct;
  for (const auto& e : fs::directory_iterator(truth.parent_path()))
    if (e.path().stem() == direct.filename() && e.path().extension() != ".toml") return e.path();
  return {};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(shipped_captures)

BOOST_AUTO_TEST_CASE(every_shipped_capture_recovers_its_truth_within_its_intervals) {
  CaptureOptions o;  // the defaults a user gets
  int checked = 0;
  for (const auto& e : fs::directory_iterator("cases/captures")) {
    const std::string name = e.path().filename().string();
    if (name.size() < 11 || name.substr(name.size() - 11) != ".truth.toml") continue;
    const fs::path capture = capture_of(e.path());
    BOOST_TEST_CONTEXT(capture.string()) {
      BOOST_REQUIRE(!capture.empty());
      const toml::value truth = toml::parse(e.path().string());
      const Trace trace = read_capture(capture.string());
      CaptureOptions co = o;
      co.mounting = resolve_mounting(trace, {});
      co.thrower = resolve_thrower(trace, {});
      const CaptureAnalysis a = analyse_capture(trace, co);
      ++checked;
      if (number(truth, "recording", "still_s") < o.min_still_s) {
        BOOST_TEST(to_string(a.verdict) == std::string("unusable"));
        BOOST_TEST(!a.still_found);
        continue;
      }
      BOOST_REQUIRE_MESSAGE(a.can_throw(), (a.reasons.empty() ? "" : a.reasons.front()));
      const struct {
        const char* key;
        const Interval& interval;
      } checks[] = {{"speed_m_s", a.measured_speed_m_s},
                    {"attack_angle_deg", a.attack_angle_deg},
                    {"path_angle_deg", a.path_angle_deg},
                    {"spin_rev_s", a.measured_spin_rev_s},
                    {"rise_m", a.rise_m}};
      for (const auto& c : checks) {
        const double x = number(truth, "throw", c.key);
        BOOST_TEST(c.interval.contains(x), c.key << ": truth " << x << " not in [" << c.interval.low << ", "
                                                 << c.interval.high << "] (nominal " << c.interval.nominal << ")");
      }
    }
  }
  BOOST_TEST(checked >= 9);  // the shipped set: six gestures in a room, three skipping throws
}

BOOST_AUTO_TEST_SUITE_END()
