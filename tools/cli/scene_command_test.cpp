// End-to-end tests of `stoneskip scene`: the JSON solvers/README.md promises, the movie (ffprobe reads it
// and counts the frames), and bad input (one line naming the key, exit 2, no movie left behind).
// The seed's case is shrunk with --set (a 60 × 60 pond, a fraction of a second, small frames) so
// that each test runs in a second or two.
#include <boost/test/unit_test.hpp>

#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tools/cli/test_support.hpp"
#include "tools/io/foreign_output.hpp"
#include "tools/io/hdf5_file.hpp"

namespace {

using stoneskip::test::read_file;
using stoneskip::test::run_stoneskip;
using stoneskip::test::TempDir;
namespace fs = std::filesystem;

// The seed's scene on a 1.2 m pond around the landing point, for `seconds`.
std::string small_seed(double seconds) {
  return "cases/scenes/seed_8ms.toml --set water.nx=60 --set water.ny=60 --set water.origin_x_m=-0.1 "
         "--set water.origin_y_m=-0.6 --set scene.duration_s=" +
         std::to_string(seconds);
}

// ffprobe's count of the video frames in a file (−1 if it cannot read it). The name is passed as a
// "file:" URL so that ffprobe reads no option or protocol in it.
long probed_frames(const fs::path& movie) {
  stoneskip::SubprocessOptions o;
  o.stderr_to = stoneskip::SubprocessOptions::Stderr::discarded;
  const stoneskip::SubprocessResult p =
      stoneskip::run_program({"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                              "stream=nb_read_frames", "-of", "csv=p=0", "file:" + fs::absolute(movie).string()},
                             o);
  if (!p.ok() || p.out.empty()) return -1;
  try {
    return std::stol(p.out);
  } catch (...) {
    return -1;
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_command_)

BOOST_AUTO_TEST_CASE(json_reports_frames_speed_and_parts) {
  // Oracle: solvers/README.md's schema and the scene's definitions — N = duration · rate frames, the
  // frame rate per CPU and wall second equal to frames over the summed times, the parts (wall)
  // within the wall time, and the throw the same as `stoneskip run` gives on the same water
  // (the scene runs the same stepper; it only goes on after the stone has sunk, and stops at its
  // duration: its contacts are the run's first ones, the last possibly cut at the scene's end).
  const auto r = run_stoneskip("scene " + small_seed(0.2) + " --json", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j["frames"].get<long>() == 18);
  BOOST_TEST(j["coupling"].get<std::string>() == "two_way");
  const double cpu = j["cpu_s"], wall = j["wall_s"];
  BOOST_TEST(std::abs(j["frames_per_s_cpu"].get<double>() - 18 / cpu) <= 1e-9 * (18 / cpu));
  BOOST_TEST(std::abs(j["frames_per_s_wall"].get<double>() - 18 / wall) <= 1e-9 * (18 / wall));
  double parts = 0;
  for (const char* k : {"stone", "draught", "water", "recording", "energy_budget"}) parts += j["parts_wall_s"][k].get<double>();
  BOOST_TEST(parts <= wall * (1 + 1e-9));
  // The energy budget that --json measures is a part of its own (it was booked to the water, 26×
  // the scene's own water time): there is one, and the speed without it is the frames over the rest.
  const double budget = j["parts_wall_s"]["energy_budget"];
  BOOST_TEST(budget > 0.0);
  BOOST_TEST(std::abs(j["frames_per_s_wall_without_energy_budget"].get<double>() - 18 / (wall - budget)) <= 1e-9 * (18 / (wall - budget)));
  BOOST_TEST(j["slowest_frame"]["wall_s"].get<double>() <= wall);
  BOOST_TEST(j["water_steps"].get<long>() == 18);  // one water step per frame (Δt = 1/90 s)
  // The head's smoothing: 3 passes by default; a head 5 cm wide on 2 cm cells takes 2 (5/2)² = 12.5
  // passes, rounded to 13 (solvers/scene/coupled_scene.hpp), and the water still receives the
  // stone's vertical impulse (smoothing keeps the head's sum: model/README.md §2.4).
  BOOST_TEST(j["head_width_m"].get<double>() == 0.0);
  BOOST_TEST(j["head_smoothing_passes"].get<int>() == 3);
  BOOST_TEST(j["level_in_time"].get<std::string>() == "held");  // the default (model/water/height_field_surface.hpp)
  const auto wide = run_stoneskip("scene " + small_seed(0.2) + " --set water.head_width_m=0.05 --json", false);
  BOOST_REQUIRE_MESSAGE(wide.status == 0, wide.out);
  const auto w = nlohmann::json::parse(wide.out);
  BOOST_TEST(w["head_smoothing_passes"].get<int>() == 13);
  const double received = w["water_vertical_impulse_N_s"].get<double>() + w["water_impulse_pending_N_s"].get<double>();
  BOOST_TEST(std::abs(received - w["stone_vertical_impulse_N_s"].get<double>()) <= 1e-9 * w["stone_vertical_impulse_N_s"].get<double>());
  // The coupled limit of model/README.md §2.2: the free limit 2/√(−min symbol) over √2, √6/4 for
  // the seed's isotropic stencil (to round-off); a stencil of zero weights couples no cell, has no
  // limit, and says so (JSON has no infinity).
  BOOST_TEST(std::abs(j["coupled_courant_limit"].get<double>() - std::sqrt(6.0) / 4) <= 1e-15);
  BOOST_TEST(!j["coupled_courant_limit_unbounded"].get<bool>());
  const auto zero = run_stoneskip("scene " + small_seed(0.05) +
                                      " --set water.stencil=custom --set stencil.centre=0 --set stencil.orth=0 "
                                      "--set stencil.diag=0 --json",
                                  false);
  BOOST_REQUIRE_MESSAGE(zero.status == 0, zero.out);
  const auto z = nlohmann::json::parse(zero.out);
  BOOST_TEST(z["coupled_courant_limit"].is_null());
  BOOST_TEST(z["coupled_courant_limit_unbounded"].get<bool>());
  const auto run = run_stoneskip("run " + small_seed(0.2) + " --json", false);
  BOOST_REQUIRE(run.status == 0);
  const auto t = nlohmann::json::parse(run.out);
  const auto& scene_contacts = j["throw"]["contacts"];
  BOOST_REQUIRE(!scene_contacts.empty());
  BOOST_TEST(t["contacts"].size() >= scene_contacts.size());
  for (std::size_t k = 0; k < scene_contacts.size() && k < t["contacts"].size(); ++k) {
    BOOST_TEST(t["contacts"][k]["start_s"].get<double>() == scene_contacts[k]["start_s"].get<double>());
    if (k + 1 < scene_contacts.size())
      BOOST_TEST(t["contacts"][k]["end_s"].get<double>() == scene_contacts[k]["end_s"].get<double>());
  }
}

BOOST_AUTO_TEST_CASE(a_movie_is_made_under_a_temporary_folder_with_a_percent_in_its_name) {
  // The frames' folder sits under TMPDIR, and ffmpeg's image2 reads '%' in a path as a conversion:
  // TMPDIR=/x/tmp%05d drew every frame and then failed (exit 3, "seq_%05d.png: No such file").
  // Oracle: the movie is made, with its 18 frames (0.2 s at 90 frames/s, as above).
  TempDir tmp("stoneskip-movie-percent");
  const fs::path odd = tmp.path() / "tmp%05d";
  fs::create_directories(odd);
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  ::setenv("TMPDIR", odd.c_str(), 1);
  const fs::path movie = tmp.path() / "m.mp4";
  const auto r = run_stoneskip("scene " + small_seed(0.2) + " --movie-slow 1 --movie " + movie.string() + " --movie-size 320x160");
  if (old) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(probed_frames(movie) == 18);
}

BOOST_AUTO_TEST_CASE(a_tmpdir_that_is_no_folder_is_named_before_the_scene_runs) {
  // TMPDIR naming a missing folder, or a file, ended a movie with "internal error", exit 3, and no
  // word of TMPDIR. Oracle: the input rules, one line naming TMPDIR, exit 2, no movie.
  TempDir tmp("stoneskip-movie-tmpdir");
  const fs::path file = tmp.path() / "a-file";
  std::ofstream(file) << "x";
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  for (const fs::path& bad : {tmp.path() / "missing", file}) {
    ::setenv("TMPDIR", bad.c_str(), 1);
    const fs::path movie = tmp.path() / "m.mp4";
    const auto r = run_stoneskip("scene " + small_seed(0.2) + " --movie " + movie.string() + " --movie-size 320x160");
    if (old) ::setenv("TMPDIR", saved.c_str(), 1);
    else ::unsetenv("TMPDIR");
    BOOST_TEST(r.status == 2, bad << ": exit " << r.status << ": " << r.out);
    BOOST_TEST(r.out.find("TMPDIR=" + bad.string()) != std::string::npos, r.out);
    BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1, r.out);
    BOOST_TEST(!fs::exists(movie));
  }
}

BOOST_AUTO_TEST_CASE(a_movie_has_duration_times_rate_frames) {
  // Oracle: without slow motion the movie plays in real time — ffprobe counts duration × rate
  // frames: 0.2 s at 90 frames/s (MP4, every frame) = 18; as a GIF (≤ 30 frames/s: every third) = 6.
  TempDir tmp("stoneskip-movie");
  for (const auto& [name, frames] : {std::pair<std::string, long>{"m.mp4", 18}, {"m.gif", 6}}) {
    const fs::path movie = tmp.path() / name;
    const auto r = run_stoneskip("scene " + small_seed(0.2) + " --movie-slow 1 --movie " + movie.string() + " --movie-size 320x160");
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
    BOOST_TEST(fs::file_size(movie) > 0u);
    BOOST_TEST(probed_frames(movie) == frames, name);
    // The movie carries stoneskip's mark (MP4 metadata, a GIF comment that ffprobe still reads
    // past, above), so a second run replaces it; a file of the user's under the name is refused
    // (exit 2) and kept (tools/io/foreign_output.hpp).
    BOOST_TEST(stoneskip::stoneskip_wrote(movie, stoneskip::OutputFormat::movie), name);
    const auto again = run_stoneskip("scene " + small_seed(0.2) + " --movie-slow 1 --movie " + movie.string() + " --movie-size 320x160");
    BOOST_TEST(again.status == 0, again.out);
    const fs::path mine = tmp.path() / ("mine_" + name);
    { std::ofstream(mine) << "precious\n"; }
    const auto refused = run_stoneskip("scene " + small_seed(0.2) + " --movie " + mine.string());
    BOOST_TEST(refused.status == 2, refused.out);
    BOOST_TEST(refused.out.find("exists and is not a movie stoneskip wrote") != std::string::npos, refused.out);
    BOOST_TEST(read_file(mine) == "precious\n");
  }
}

BOOST_AUTO_TEST_CASE(a_movie_slows_down_by_its_factor_around_each_contact) {
  // Oracle: the rule of reports/scene/scene_movie.hpp counted here from the scene's own contacts
  // (its JSON): scene frame k (t = k/90 s) within 0.03 s of a contact is shown 8 times (MP4, every
  // frame: 8× slow motion), any other once; ffprobe counts the sum. The 0.2 s scene has a contact.
  TempDir tmp("stoneskip-movie-slow");
  const fs::path movie = tmp.path() / "m.mp4";
  const auto r = run_stoneskip("scene " + small_seed(0.2) + " --json --movie " + movie.string() + " --movie-size 320x160", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  const auto j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
  const auto& contacts = j["throw"]["contacts"];
  BOOST_REQUIRE(!contacts.empty());
  const double margin_s = 0.03, tiny = 1e-9;  // the default margin; a frame time rounded either way
  long expected = 0, slow = 0;
  for (long k = 1; k <= 18; ++k) {
    const double t = k / 90.0;
    bool near = false;
    for (const auto& c : contacts)
      near = near || (t >= c["start_s"].get<double>() - margin_s - tiny && t <= c["end_s"].get<double>() + margin_s + tiny);
    expected += near ? 8 : 1;
    slow += near;
  }
  BOOST_TEST(slow > 0);
  BOOST_TEST(j["movie"]["time_warp"].get<double>() == 8.0);
  BOOST_TEST(j["movie"]["slow_drawn"].get<long>() == slow);
  BOOST_TEST(j["movie"]["frames"].get<long>() == expected);
  BOOST_TEST(probed_frames(movie) == expected);
}

BOOST_AUTO_TEST_CASE(bad_scene_input_fails_before_any_work_and_leaves_no_movie) {
  // Oracle: the input rules — one line naming the key or option, exit 2, no output file.
  TempDir tmp("stoneskip-movie-bad");
  const fs::path avi = tmp.path() / "m.avi";
  auto r = run_stoneskip("scene " + small_seed(0.2) + " --movie " + avi.string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find(".mp4 or .gif") != std::string::npos, r.out);
  BOOST_TEST(!fs::exists(avi));
  const fs::path mp4 = tmp.path() / "m.mp4";
  r = run_stoneskip("scene " + small_seed(0.2) + " --set water.dt_s=0.03 --movie " + mp4.string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("water.dt_s") != std::string::npos, r.out);
  BOOST_TEST(r.out.find("coupled stability limit") != std::string::npos, r.out);
  BOOST_TEST(!fs::exists(mp4));
  r = run_stoneskip("scene " + small_seed(0.2) + " --movie " + mp4.string() + " --movie-rate 40");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("divided by a whole number") != std::string::npos, r.out);
  // 0 is not read as "the format's default" (it once was, silently).
  r = run_stoneskip("scene " + small_seed(0.2) + " --movie " + mp4.string() + " --movie-rate 0");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("--movie-rate: must be > 0 frames/s (got 0)") != std::string::npos, r.out);
  BOOST_TEST(fs::is_empty(tmp.path()));
}

BOOST_AUTO_TEST_CASE(a_movie_past_the_movie_limits_is_refused_before_the_scene_runs) {
  // Oracle: tools/scene/resource_estimate.hpp — a still-water scene of 100 s at 1e5 frames/s
  // is 1e7 movie frames, 5e11 pixels at 320×160 (limit 5e10): exit 2, one line naming --movie and
  // the pixels, nothing written, and within seconds (the scene itself never runs).
  TempDir tmp("stoneskip-movie-limit");
  const fs::path mp4 = tmp.path() / "m.mp4";
  const auto r = run_stoneskip("scene cases/paper_8ms_spin.toml --set scene.frame_rate_hz=1e5 --set scene.duration_s=100 --movie " +
                               mp4.string() + " --movie-size 320x160");
  BOOST_TEST(r.status == 2, r.out);
  BOOST_TEST(r.out.find("--movie: ") != std::string::npos, r.out);
  BOOST_TEST(r.out.find("movie pixels") != std::string::npos, r.out);
  BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1, r.out);
  BOOST_TEST(fs::is_empty(tmp.path()));
}

BOOST_AUTO_TEST_CASE(water_frames_are_stored_at_the_first_frame_at_or_after_each_time) {
  // Oracles: the frame rule (frame k shows t = k/90 s; 0.05 s → k = 5, 0.1 s → k = 9, 0 → k = 1),
  // and the scene's own water volume: the pond starts flat, so the last stored frame's Σ z d²
  // must equal the JSON's water_volume_change_m3, computed in double from the live field; the
  // stored heights are float32, so they agree to float32 rounding of the summed |z| (kFloat32).
  constexpr double kFloat32 = 1e-6;  // a few float32 ulps of each summed height
  const TempDir dir("stoneskip_water_frames");
  const fs::path out = dir.path() / "scene.h5";
  const auto r = run_stoneskip("scene " + small_seed(0.1) + " --json --out " + out.string() + " --water-frames 0.05,0.1,0,0.1", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  const auto j = nlohmann::json::parse(r.out);
  const stoneskip::Hdf5Reader f(out);
  const auto w = f.root().open_group("water");
  BOOST_TEST(w.read_ints("frame") == (std::vector<long long>{1, 5, 9}));  // sorted, the repeated 0.1 once
  const auto t = w.read_vector("t_s");
  BOOST_REQUIRE(t.size() == 3u);
  BOOST_TEST(t[1] == 5 / 90.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(w.attr_int("nx") == 60);
  BOOST_TEST(w.attr_int("ny") == 60);
  const auto z = w.read_vector("height_m");
  BOOST_REQUIRE(z.size() == 3u * 60 * 60);
  const double d = w.attr_double("cell_m");
  double volume = 0, magnitude = 0;
  for (std::size_t k = 2 * 3600; k < z.size(); ++k) {
    volume += z[k] * d * d;
    magnitude += std::abs(z[k]) * d * d;
  }
  BOOST_TEST(magnitude > 0);  // the stone has disturbed the water by then
  BOOST_TEST(std::abs(volume - j["water_volume_change_m3"].get<double>()) <= kFloat32 * magnitude + 1e-15);
  // The throw is stored as `run --out` stores it.
  BOOST_TEST(f.root().open_group("realtime").attr_int("bounces") == j["bounces"].get<long long>());
  BOOST_TEST(f.root().open_group("scene").attr_int("frames") == 9);
}

BOOST_AUTO_TEST_CASE(water_frames_out_of_the_scene_or_without_a_file_are_refused) {
  // Oracle: the documented bounds (tools/README.md): times within the scene, at most 100 frames,
  // a file to store them in; one line naming --water-frames, exit 2, no file left.
  const TempDir dir("stoneskip_water_frames_bad");
  const fs::path out = dir.path() / "scene.h5";
  auto refused = [&](const std::string& args, const std::string& words) {
    const auto r = run_stoneskip("scene " + small_seed(0.1) + " " + args);
    BOOST_TEST(r.status == 2, args);
    BOOST_TEST(r.out.find("--water-frames") != std::string::npos, r.out);
    BOOST_TEST(r.out.find(words) != std::string::npos, r.out);
    BOOST_TEST(!fs::exists(out));
  };
  refused("--water-frames 0.05", "needs --out");
  for (const char* option : {"--movie-size 100x100", "--movie-rate 30", "--movie-slow 2"}) {
    const auto r = run_stoneskip("scene " + small_seed(0.1) + " " + option);
    BOOST_TEST(r.status == 2, option);
    BOOST_TEST(r.out.find("needs --movie FILE") != std::string::npos, r.out);
  }
  refused("--out " + out.string() + " --water-frames 0.2", "0 to 0.1 s");
  std::string many;
  for (int i = 0; i < 101; ++i) many += (i ? "," : "") + std::string("0.05");
  refused("--out " + out.string() + " --water-frames " + many, "at most 100");
  // A duration between two frames: 0.105 s at 90 frames/s is 9.45 frames. The scene runs 9 whole
  // frames, to 0.1 s, and says so; a time past its last frame has no frame "at or after" it (main
  // returned frame 9 for 0.104 s, and stored a duration of 0.105 s).
  const auto cut = run_stoneskip("scene " + small_seed(0.105) + " --out " + out.string() + " --water-frames 0.104");
  BOOST_TEST(cut.status == 2, cut.out);
  BOOST_TEST(cut.out.find("0 to 0.1 s, its last frame (got 0.104)") != std::string::npos, cut.out);
  const auto ran = run_stoneskip("scene " + small_seed(0.105) + " --out " + out.string());
  BOOST_REQUIRE_MESSAGE(ran.status == 0, ran.out);
  BOOST_TEST(ran.out.find("is 9.45 frames of 1/90 s: the scene runs 9 whole frames, to 0.1 s") != std::string::npos, ran.out);
  const stoneskip::Hdf5Reader f(out);
  BOOST_TEST(f.root().open_group("scene").attr_double("duration_s") == 9 / 90.0);
  BOOST_TEST(f.root().open_group("scene").attr_double("duration_asked_s") == 0.105);
}

BOOST_AUTO_TEST_CASE(contacts_off_the_pond_are_named_and_the_movie_and_result_are_not_one_file) {
  // Oracle: the geometry. The small seed's pond covers x in [-0.1, 1.08] m around the first touch
  // (x ≈ 0.4 m); moved to x = 100 m, every contact lies off it (the surface there is the edge's and
  // the water takes no push), and the text says so. The pond in place keeps its first contact on.
  const auto on = run_stoneskip("scene " + small_seed(0.2) + " --json", false);
  BOOST_REQUIRE_MESSAGE(on.status == 0, on.out);
  const auto j = nlohmann::json::parse(on.out);
  BOOST_REQUIRE(!j["throw"]["contacts"].empty());
  const auto off_in_place = j["contacts_off_pond"].get<std::vector<int>>();
  BOOST_TEST((std::find(off_in_place.begin(), off_in_place.end(), 1) == off_in_place.end()));
  BOOST_TEST(std::abs(j["pond_extent_m"]["x"][1].get<double>() - (-0.1 + 59 * 0.02)) <= 1e-12);
  const auto moved = run_stoneskip("scene " + small_seed(0.2) + " --set water.origin_x_m=100 --json", false);
  BOOST_REQUIRE_MESSAGE(moved.status == 0, moved.out);
  const auto m = nlohmann::json::parse(moved.out);
  BOOST_TEST(m["contacts_off_pond"].size() == m["throw"]["contacts"].size());
  BOOST_TEST(std::abs(m["water_vertical_impulse_N_s"].get<double>()) <= 1e-12);  // the water took nothing
  const auto text = run_stoneskip("scene " + small_seed(0.2) + " --set water.origin_x_m=100", false);
  BOOST_TEST(text.out.find("note      contact 1 (x = ") != std::string::npos, text.out);
  BOOST_TEST(text.out.find("lies outside the pond, x in [100, 101.2] m") != std::string::npos, text.out);
  BOOST_TEST(m["throw"]["notes"].dump().find("outside the pond") != std::string::npos, m.dump());
  BOOST_TEST(j["throw"]["notes"].dump().find("outside the pond") == std::string::npos, j.dump());
  // --movie and --out naming one file: refused before any work (the result overwrote the movie).
  TempDir d("stoneskip_scene_same_out");
  const std::string f = (d.path() / "m.mp4").string();
  const auto same = run_stoneskip("scene " + small_seed(0.05) + " --movie " + f + " --out " + f, true);
  BOOST_TEST(same.status == 2);
  BOOST_TEST(same.out.find("also the --movie file") != std::string::npos, same.out);
  BOOST_TEST(!fs::exists(f));
}

BOOST_AUTO_TEST_SUITE_END()
