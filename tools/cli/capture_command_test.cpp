// End-to-end tests of `stoneskip capture validate` on the shipped synthetic captures. Oracle: the
// truth sidecar written by the generator with each capture (cases/captures/*.truth.toml): the
// release speed and angles that produced the recording, and what the recorder dropped.
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <toml.hpp>

namespace fs = std::filesystem;

namespace {

struct Run {
  int status = -1;
  std::string out;
};

Run run(const std::string& args) {
  const fs::path o = fs::temp_directory_path() / ("stoneskip_capture_cli_" + std::to_string(::getpid()));
  const std::string cmd = std::string(STONESKIP_EXE) + " " + args + " >" + o.string() + " 2>/dev/null";
  Run r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream f(o);
  r.out.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  fs::remove(o);
  return r;
}

nlohmann::json validate(const std::string& capture) {
  const Run r = run("capture validate " + capture + " --json --no-reference --members 16");
  BOOST_REQUIRE_MESSAGE(r.status == 0, capture << ": exit " << r.status);
  return nlohmann::json::parse(r.out);
}

// A number of the truth file, written as an integer or a float.
double truth_number(const toml::value& truth, const char* section, const char* key) {
  const toml::value& v = toml::find(truth, section, key);
  return v.is_integer() ? static_cast<double>(v.as_integer()) : v.as_floating();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capture_command)

BOOST_AUTO_TEST_CASE(the_clipped_capture_is_flagged_and_its_speed_interval_holds_the_truth) {
  // Oracle: the generator's true release speed (truth sidecar). A clipped accelerometer gives a
  // lower bound only: the verdict must name the clipping and the interval must contain the truth.
  const auto truth = toml::parse("cases/captures/hard_sidearm_clipped.log.truth.toml");
  const double speed = truth_number(truth, "throw", "speed_m_s");
  const auto j = validate("cases/captures/hard_sidearm_clipped.log");
  BOOST_TEST(j["verdict"].get<std::string>() != "usable");
  BOOST_TEST(j["reasons"][0].get<std::string>().find("clipped") != std::string::npos);
  BOOST_TEST(j["saturated_fraction"].get<double>() > 0.0);
  BOOST_TEST(j["release_speed_m_s_low"].get<double>() <= speed);
  BOOST_TEST(j["release_speed_m_s_high"].get<double>() >= speed);
  BOOST_TEST(j["dropped_reports"].get<int>() == toml::find<int>(truth, "recording", "dropped_reports"));
}

BOOST_AUTO_TEST_CASE(the_gentle_capture_recovers_the_throw_in_every_format) {
  // Oracle: the truth sidecar; the acceptance bands (speed 5 %, angles 3°) for an
  // unclipped throw, through the raw report log, the evemu recording and the gesture file.
  const std::pair<const char*, const char*> captures[] = {
      {"gentle_sidearm.log", "gentle_sidearm.log.truth.toml"},
      {"gentle_sidearm.evemu", "gentle_sidearm.evemu.truth.toml"},
      {"gentle_sidearm_gesture.txt", "gentle_sidearm_gesture.truth.toml"}};
  for (const auto& [f, truth_file] : captures) {
    const std::string path = std::string("cases/captures/") + f;
    const auto truth = toml::parse(std::string("cases/captures/") + truth_file);
    const auto j = validate(path);
    BOOST_TEST_CONTEXT(f) {
      BOOST_TEST(j["verdict"].get<std::string>() != "unusable");
      BOOST_TEST(j["saturated_fraction"].get<double>() == 0.0);
      const double speed = truth_number(truth, "throw", "speed_m_s");
      BOOST_TEST(std::abs(j["release_speed_m_s"].get<double>() - speed) <= 0.05 * speed);
      BOOST_TEST(std::abs(j["attack_angle_deg"].get<double>() - truth_number(truth, "throw", "attack_angle_deg")) <= 3.0);
      BOOST_TEST(std::abs(j["path_angle_deg"].get<double>() - truth_number(truth, "throw", "path_angle_deg")) <= 3.0);
      BOOST_TEST(j["rate_hz"].get<double>() > 90.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_capture_without_a_still_part_is_unusable) {
  // Oracle: the generator made this capture with no still part (truth sidecar): gravity and the
  // gyro bias cannot be found, so the verdict must be unusable with that reason.
  const auto j = validate("cases/captures/no_still_part.log");
  BOOST_TEST(j["verdict"].get<std::string>() == "unusable");
  BOOST_TEST(j["reasons"][0].get<std::string>().find("still") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
