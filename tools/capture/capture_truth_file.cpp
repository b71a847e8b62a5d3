#include "tools/capture/capture_truth_file.hpp"

#include <cmath>

#include "tools/io/toml_table.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

fs::path capture_truth_file(const fs::path& capture) {
  std::error_code ec;
  fs::path direct = capture;
  direct += ".truth.toml";
  if (fs::is_regular_file(direct, ec)) return direct;
  const fs::path by_stem = capture.parent_path() / (capture.stem().string() + ".truth.toml");
  if (capture.has_extension() && fs::is_regular_file(by_stem, ec)) return by_stem;
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
  t.speed_m_s = th.number("speed_m_s");
  t.attack_angle_deg = th.number("attack_angle_deg");
  t.path_angle_deg = th.number("path_angle_deg");
  t.spin_rev_s = th.number("spin_rev_s");
  t.rise_m = th.number("rise_m");
  t.arm_speed_m_s = th.number_or("arm_speed_m_s", std::nan(""));
  t.pivot_speed_m_s = th.number_or("pivot_speed_m_s", std::nan(""));
  return t;
}

}  // namespace stoneskip
