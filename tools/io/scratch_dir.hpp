// A test's scratch folder: TMP/<stem>_<pid>, emptied when made and removed at the end of the
// test. Shared by the tests of tools/io, reports/ and tools/cli (header only; tests only).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace stoneskip {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& stem)
      : dir(std::filesystem::temp_directory_path() / (stem + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  // Writes `text` to dir/name and returns the path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  const std::filesystem::path dir;
};

// Runs a test from another folder (a command started elsewhere): the working folder is `to` while
// this lives, and what it was before afterwards.
class WorkingFolder {
 public:
  explicit WorkingFolder(const std::filesystem::path& to) : back_(std::filesystem::current_path()) {
    std::filesystem::current_path(to);
  }
  ~WorkingFolder() {
    std::error_code ec;
    std::filesystem::current_path(back_, ec);
  }
  WorkingFolder(const WorkingFolder&) = delete;
  WorkingFolder& operator=(const WorkingFolder&) = delete;

 private:
  std::filesystem::path back_;
};

}  // namespace stoneskip
