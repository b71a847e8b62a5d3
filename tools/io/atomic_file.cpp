#include "tools/io/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <system_error>

#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path final_path) : final_(std::move(final_path)) {
  fs::path dir = final_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw_input_error(final_.string(), 0, "", "cannot write: folder '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw_input_error(final_.string(), 0, "", "cannot write: folder '" + dir.string() + "' is not writable");
  }
  if (fs::is_directory(final_, ec)) {
    throw_input_error(final_.string(), 0, "", "cannot write: it is a folder");
  }
  tmp_ = final_;
  tmp_ += ".tmp-" + std::to_string(::getpid());
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(tmp_, ec);
  }
}

void AtomicOutput::commit() {
  std::error_code ec;
  fs::rename(tmp_, final_, ec);
  if (ec) throw_input_error(final_.string(), 0, "", "cannot write: " + ec.message());
  committed_ = true;
}

void write_text_file(const fs::path& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream f(out.temporary_path(), std::ios::binary);
    f << text;
    f.close();
    if (!f) throw_input_error(path.string(), 0, "", "cannot write");
  }
  out.commit();
}

std::string read_text_file(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw_input_error(path.string(), 0, "", "cannot read: no such file");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw_input_error(path.string(), 0, "", "cannot read");
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace stoneskip
