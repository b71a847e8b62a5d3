#include "tools/capture/capture_truth_file.hpp"

#include <cmath>
#include <vector>

#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/io/toml_table.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {
constexpr double kMaxSpeed_m_s = 1000, kMaxSpin_rev_s = 1000;
}  // namespace

fs::path capture_truth_file(const fs::path& capture) {
  std::error_code ec;
  fs::path direct = capture;
  direct += ".truth.toml";
  std::vector<fs::path> names{direct};
  if (capture.has_extension()) names.push_back(capture.parent_path() / (capture.stem().string() + ".truth.toml"));
  for (const fs::path& p : names) {
    // Beside the capture that is read: a shipped capture named from elsewhere has its truth in the
    // shipped cases too (shipped_files.hpp). The name as given is returned, and read the same way.
    const fs::path at = locate_input(p);
    if (fs::is_regular_file(at, ec)) return p;
    // Something under the truth's name that is no file (a folder, a FIFO, a dangling link) is not
    // passed over in silence: the comparison with the truth would vanish without a word.
    if (fs::symlink_status(at, ec).type() != fs::file_type::not_found && !ec)
      throw_input_error(p.string(), 0, "",
                        "is not a regular file (a truth file beside the capture must be one; move it away to read the "
                        "capture without its truth)");
  }
  return {};
}

std::optional<CaptureTruth> read_capture_truth(const fs::path& capture) {
  const fs::path file = capture_truth_file(capture);
  if (file.empty()) return std::nullopt;
  const TomlDocument doc = load_toml(file.string());
  TomlTable top = doc.top();
  TomlTable th = top.table("throw");
  CaptureTruth t;
  t.file = file.string();
  // The bounds of the case files' [throw] keys (tools/scene/stone_case.hpp: kMaxSpeed_m_s,
  // kMaxSpin_rev_s), a throw's speed > 0.
  t.speed_m_s = th.bounded("speed_m_s", 0, kMaxSpeed_m_s);
  th.require_positive("speed_m_s", t.speed_m_s);
  t.attack_angle_deg = th.bounded("attack_angle_deg", -90, 90);
  t.path_angle_deg = th.bounded("path_angle_deg", -90, 90);
  t.spin_rev_s = th.bounded("spin_rev_s", -kMaxSpin_rev_s, kMaxSpin_rev_s);
  t.rise_m = th.bounded("rise_m", -10, 10);
  t.arm_speed_m_s = th.bounded_or("arm_speed_m_s", std::nan(""), 0, kMaxSpeed_m_s);
  t.pivot_speed_m_s = th.bounded_or("pivot_speed_m_s", std::nan(""), 0, kMaxSpeed_m_s);
  th.maybe_number("release_t_s");
  th.finish();
  // What synthesize writes beside them (SyntheticTruth::toml), not compared: read, so that a
  // misspelt or unknown key anywhere in the file is an error, not ignored.
  if (auto st = top.maybe_table("stone")) {
    for (const char* k : {"height_m", "finger_spin_rev_s", "total_spin_rev_s"}) st->maybe_number(k);
    st->finish();
  }
  if (auto rec = top.maybe_table("recording")) {
    for (const char* k : {"still_s", "reports_sent", "dropped_reports", "repeated_reports", "range_switches", "clipped_samples"})
      rec->maybe_number(k);
    rec->finish();
  }
  top.finish();
  return t;
}

}  // namespace stoneskip
