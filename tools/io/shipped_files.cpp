#include "tools/io/shipped_files.hpp"

#include <system_error>

#ifndef STONESKIP_SOURCE_DIR
#define STONESKIP_SOURCE_DIR ""
#endif

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

// This binary's folder (Linux: /proc/self/exe), or empty.
fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return !p.empty() && fs::is_directory(p, ec);
}

}  // namespace

fs::path shipped_cases_dir() {
  static const fs::path dir = [] {
    const fs::path installed = executable_dir() / ".." / "share" / "stoneskip" / "cases";
    if (is_dir(executable_dir()) && is_dir(installed)) return installed.lexically_normal();
    const fs::path source = fs::path(STONESKIP_SOURCE_DIR) / "cases";
    if (!fs::path(STONESKIP_SOURCE_DIR).empty() && is_dir(source)) return source;
    return fs::path();
  }();
  return dir;
}

fs::path locate_input(const fs::path& path) {
  std::error_code ec;
  if (path.empty() || path.is_absolute() || fs::exists(fs::symlink_status(path, ec))) return path;
  auto it = path.begin();
  if (it == path.end() || *it != "cases") return path;
  const fs::path root = shipped_cases_dir();
  if (root.empty()) return path;
  fs::path shipped = root;
  for (++it; it != path.end(); ++it) shipped /= *it;
  return fs::exists(shipped, ec) ? shipped : path;
}

}  // namespace stoneskip
