#pragma once
// Output files appear whole or not at all: everything is written to "<name>.tmp-<pid>" beside the
// final path and renamed over it on commit(). A writer destroyed before commit() (an exception, a
// bad input found late) removes its temporary file, so no partial output is ever left behind.
#include <filesystem>
#include <string>

namespace stoneskip {

class AtomicOutput {
 public:
  // Checks that the destination's folder exists and is writable; throws InputError otherwise.
  explicit AtomicOutput(std::filesystem::path final_path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temporary_path() const { return tmp_; }
  const std::filesystem::path& final_path() const { return final_; }
  void commit();  // rename temporary -> final

 private:
  std::filesystem::path final_;
  std::filesystem::path tmp_;
  bool committed_ = false;
};

// Writes a whole text file atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// Reads a whole text file; InputError naming the file if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace stoneskip
