#include "tools/io/foreign_output.hpp"

#include <sys/stat.h>

#include <cstring>
#include <fstream>

#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

constexpr char kHdf5Signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};  // HDF5 spec §II.A
constexpr char kTextMark[] = "# stoneskip";

bool holds_marker(std::ifstream& f) {
  const std::string marker = kMovieMarker;
  std::string window;
  char buf[1 << 16];
  f.clear();
  f.seekg(0);
  while (f) {
    f.read(buf, sizeof buf);
    window.append(buf, static_cast<std::size_t>(f.gcount()));
    if (window.find(marker) != std::string::npos) return true;
    window.erase(0, window.size() > marker.size() ? window.size() - marker.size() : 0);  // a marker across reads
  }
  return false;
}

}  // namespace

bool stoneskip_wrote(const fs::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  std::ifstream f(path, std::ios::binary);
  char head[16] = {};
  f.read(head, sizeof head);
  const auto got = static_cast<std::size_t>(f.gcount());
  if (got >= sizeof kHdf5Signature && std::memcmp(head, kHdf5Signature, sizeof kHdf5Signature) == 0) {
    try {
      const Hdf5Reader r(path);
      return r.root().has_attr("code_version") && r.root().attr_string("code_version").rfind("stoneskip ", 0) == 0;
    } catch (const std::exception&) {
      return false;
    }
  }
  if (got >= sizeof kTextMark - 1 && std::memcmp(head, kTextMark, sizeof kTextMark - 1) == 0) return true;
  // The movie's mark counts only in a movie (a GIF89a, or an ISO media file: "ftyp" at byte 4,
  // ISO/IEC 14496-12 §4.3): a user's notes that say "made by stoneskip" are theirs.
  const bool gif = got >= 6 && std::memcmp(head, "GIF89a", 6) == 0;
  const bool mp4 = got >= 8 && std::memcmp(head + 4, "ftyp", 4) == 0;
  return (gif || mp4) && holds_marker(f);
}

void refuse_foreign_output(const fs::path& path, const std::string& option) {
  struct stat st {};
  if (path.empty() || ::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  if (!stoneskip_wrote(path))
    throw_input_error(option, 0, "",
                      "'" + path.string() + "' exists and stoneskip did not write it (no stoneskip mark in it): "
                      "refusing to replace it; remove it or choose another name");
}

}  // namespace stoneskip
