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
constexpr char kTraceLine[] = "# stoneskip trace v1";  // tools/capture/trace_csv.hpp kTraceCsvMagic

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

const char* to_string(OutputFormat f) {
  switch (f) {
    case OutputFormat::hdf5: return "a throw's HDF5 file";
    case OutputFormat::hdf5_sweep: return "a sweep's HDF5 file";
    case OutputFormat::trace_csv: return "a trace";
    case OutputFormat::movie: return "a movie";
  }
  return "?";
}

bool stoneskip_wrote(const fs::path& path, OutputFormat format) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  std::ifstream f(path, std::ios::binary);
  char head[32] = {};
  f.read(head, sizeof head);
  const auto got = static_cast<std::size_t>(f.gcount());
  switch (format) {
    case OutputFormat::hdf5:
    case OutputFormat::hdf5_sweep:
      if (got < sizeof kHdf5Signature || std::memcmp(head, kHdf5Signature, sizeof kHdf5Signature) != 0) return false;
      try {
        const Hdf5Reader r(path);
        const H5Group& root = r.root();
        if (!root.has_attr("code_version") || root.attr_string("code_version").rfind("stoneskip ", 0) != 0) return false;
        // A report's data.h5 (`report`) or a sweep page's (`source`, reports/sweep/sweep_page.cpp):
        // only their own commands replace them.
        if (root.has_attr("report") || root.has_attr("source")) return false;
        return root.has_attr("sweep_file") == (format == OutputFormat::hdf5_sweep);
      } catch (const std::exception&) {
        return false;
      }
    case OutputFormat::trace_csv: {
      // The whole first line is the trace's (a line "# stoneskip trace v1 and my notes" is not).
      const std::size_t n = sizeof kTraceLine - 1;
      return got > n && std::memcmp(head, kTraceLine, n) == 0 && (head[n] == '\n' || (head[n] == '\r' && got > n + 1 && head[n + 1] == '\n'));
    }
    case OutputFormat::movie: {
      // The movie's mark counts only in a movie (a GIF89a, or an ISO media file: "ftyp" at byte 4,
      // ISO/IEC 14496-12 §4.3): a user's notes that say "made by stoneskip" are theirs.
      const bool gif = got >= 6 && std::memcmp(head, "GIF89a", 6) == 0;
      const bool mp4 = got >= 8 && std::memcmp(head + 4, "ftyp", 4) == 0;
      return (gif || mp4) && holds_marker(f);
    }
  }
  return false;
}

void refuse_foreign_output(const fs::path& path, OutputFormat format, const std::string& option) {
  struct stat st {};
  if (path.empty() || ::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  if (!stoneskip_wrote(path, format))
    throw_input_error(option, 0, "",
                      "'" + path.string() + "' exists and is not " + to_string(format) +
                          " stoneskip wrote (no stoneskip mark of that kind in it): refusing to replace it; remove it or "
                          "choose another name");
}

}  // namespace stoneskip
