#pragma once
// The variable-length strings of an HDF5 file, read in a child process and nowhere else.
//
// HDF5 keeps these strings in its global heap, which it does not check: a heap object whose stored
// size is larger than the string that refers to it makes the library copy past the end of its own
// buffer (H5HG_read) — a heap overflow that need not crash (AddressSanitizer finds it; a normal
// build reads on with its heap damaged). isolated_read.hpp already refuses a file whose read crashes
// or hangs a child; a silent overflow passed that test and then happened again in-process. So an
// Hdf5Reader (hdf5_file.hpp) never reads a variable-length string itself: a forked child walks the
// file (every group and dataset reachable by hard links from the root, each object once) and reads
// every string-typed attribute and dataset the way the reader would, and sends them back over a
// pipe; the reader's string reads look them up. A damage that overflows now does so in the child,
// which is thrown away.
//
// The table is keyed by the object's address in the file, so a group reached by any path (a
// second hard link, a soft link, a cycle of links) finds its strings. The walk does not follow a
// link to another file, nor does the reader (hdf5_file.cpp refuses it: stoneskip writes none), and
// an object in another file is not the table's (its file number differs). The child's output is
// bounded (a crafted file can make many references to one long string); past the bound the file
// is refused.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace stoneskip {

struct Hdf5StringTable {
  enum class Kind : char { attribute = 'A', dataset = 'D' };
  // The object's address in the file (its object header's), the kind, and the attribute's name
  // ("" for a dataset's own values): the strings, one per element, read as variable-length
  // strings of the stored character set (string_type_for, hdf5_file.hpp; a null string read as "",
  // each cut at its first NUL).
  std::map<std::tuple<std::uint64_t, char, std::string>, std::vector<std::string>> entries;
  // The library's number of the file as the reader opened it (H5O_info_t::fileno): an object
  // with another number is in another file.
  unsigned long fileno = 0;

  // The strings of obj (an open group or dataset): nullptr where the walk has no such entry (not
  // reached, in another file, or the library could not read it).
  const std::vector<std::string>* find(hid_t obj, Kind kind, const std::string& name) const;
};

// The walk, in this process: writes the table's bytes to fd (the child's side; see the .cpp for the
// format). Exposed for the tests.
void write_string_table(const std::filesystem::path& file, int fd);
// The bytes write_string_table wrote, read back; std::runtime_error where they are not whole.
Hdf5StringTable parse_string_table(const std::string& bytes);

// The table of the file's strings, read in a child (refusals as isolated_read.hpp's: InputError
// "<file>: is a damaged HDF5 file: …"); nullopt where no child could be made, or this process is
// such a child already: the caller then reads the strings itself. Its fileno is the caller's to set.
std::optional<Hdf5StringTable> read_strings_apart(const std::filesystem::path& file);

}  // namespace stoneskip
