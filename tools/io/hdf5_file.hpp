#pragma once
// Small RAII handles over the HDF5 C API: files, groups, datasets of doubles (1-D with a units
// attribute; 2-D tables with `columns` and `units` attributes, each an array of strings, one per
// column), 3-D float32 arrays, integer and string attributes; reading back the same. Everything a
// result file or a report's data needs, nothing more.
//
// Writing goes through AtomicOutput: Hdf5Writer creates "<path>.tmp-PID" and renames it over the
// destination in commit(), so a failed run leaves no partial .h5 file.
#include <hdf5.h>

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tools/io/atomic_file.hpp"

namespace stoneskip {

// An owned hid_t with its matching close function.
class H5Id {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Id() = default;
  H5Id(hid_t id, Closer closer);
  ~H5Id();
  H5Id(H5Id&& o) noexcept;
  H5Id& operator=(H5Id&& o) noexcept;
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

// A row-major table of doubles with named columns (units in the names: "t_s", "x_m", ...).
// Stored as a 2-D dataset with two string-array attributes: `columns` (the names) and `units`
// (one per column: `units` when given and not empty, else column_unit(name), tools/io/column_units.hpp).
// Files written before the units (one comma-separated `columns` string) are still read.
struct Table {
  std::vector<std::string> columns;
  std::vector<double> values;  // rows × columns, row-major
  std::vector<std::string> units = {};  // empty, or one per column ("" = from the name)
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  void add_row(const std::vector<double>& row);
  std::vector<double> column(const std::string& name) const;  // throws std::out_of_range
  bool has_column(const std::string& name) const;  // data written by an older version may lack one
  // The unit of column c: units[c] when given and not empty, else column_unit(columns[c]).
  std::string unit(std::size_t c) const;
};

struct Hdf5StringTable;  // hdf5_strings_apart.hpp

class H5Group {
 public:
  // strings: where a reader's groups take their variable-length strings from (read apart, in a
  // child: hdf5_strings_apart.hpp); null for a writer's groups, which read their own.
  explicit H5Group(H5Id id, std::string path, std::shared_ptr<const Hdf5StringTable> strings = nullptr)
      : id_(std::move(id)), path_(std::move(path)), strings_(std::move(strings)) {}
  hid_t id() const { return id_.get(); }
  const std::string& path() const { return path_; }

  H5Group create_group(const std::string& name) const;
  H5Group open_group(const std::string& name) const;
  bool has(const std::string& name) const;
  std::vector<std::string> children() const;  // links, in name order
  // What a child link is: a group, a 2-D table with a `columns` attribute, a list of strings, a
  // 1-D vector of doubles, or something else.
  enum class ChildKind { group, table, strings, vector, other };
  ChildKind child_kind(const std::string& name) const;

  // Datasets.
  void write_vector(const std::string& name, const std::vector<double>& v, const std::string& units = "") const;
  void write_ints(const std::string& name, const std::vector<long long>& v) const;
  void write_table(const std::string& name, const Table& t) const;
  void write_strings(const std::string& name, const std::vector<std::string>& v) const;
  // A 3-D array of float32 (dims[0] × dims[1] × dims[2], row-major) with a units attribute.
  void write_floats_3d(const std::string& name, const std::vector<float>& v, const std::array<std::size_t, 3>& dims,
                       const std::string& units) const;
  std::vector<double> read_vector(const std::string& name) const;
  std::vector<long long> read_ints(const std::string& name) const;
  Table read_table(const std::string& name) const;
  std::vector<std::string> read_strings(const std::string& name) const;

  // Attributes on this group.
  void set_attr(const std::string& name, const std::string& value) const;
  void set_attr(const std::string& name, double value) const;
  void set_attr(const std::string& name, long long value) const;
  bool has_attr(const std::string& name) const;
  std::vector<std::string> attr_names() const;  // in name order
  bool attr_is_string(const std::string& name) const;
  // A scalar attribute's value; an error where the attribute holds other than one element.
  std::string attr_string(const std::string& name) const;
  double attr_double(const std::string& name) const;
  long long attr_int(const std::string& name) const;

 private:
  H5Id id_;
  std::string path_;
  std::shared_ptr<const Hdf5StringTable> strings_;
};

// Whether an Hdf5Writer's flush or close has failed in this process, or a writer was given up
// before its commit (HDF5 may then still hold the file, and its clean-up at exit can crash on it:
// the CLI's main ends without that clean-up).
bool hdf5_write_failed();

// A new HDF5 file, written atomically.
class Hdf5Writer {
 public:
  explicit Hdf5Writer(const std::filesystem::path& path);
  ~Hdf5Writer();
  H5Group& root() { return *root_; }
  // Flushes and closes the file, then renames it into place. A flush or close that fails (a full
  // disk: HDF5 caches what it writes, so the failure shows here) is an InputError naming the file,
  // and the temporary is removed: nothing is renamed into place.
  void commit();

 private:
  AtomicOutput out_;
  hid_t file_ = -1;  // closed (its result checked) by commit(); by the destructor otherwise
  std::unique_ptr<H5Group> root_;
  // The file this thread writes, for a write that fails for want of room before the commit (a
  // large dataset goes to the disk at once): its error names the file, as commit()'s does.
  const std::filesystem::path* previous_writing_ = nullptr;
};

// The type every string here is written as: variable-length, UTF-8. A read takes the character
// set of what it reads (string_type_for): HDF5 1.10 refuses a conversion between the two sets
// in a fresh process (it finds one only after other string conversions have run there).
H5Id vlen_string_type(H5T_cset_t cset = H5T_CSET_UTF8);
// The type to read the strings of an attribute or dataset of type `stored` as.
H5Id string_type_for(hid_t stored);

// An existing HDF5 file, read only. Throws InputError naming the file if it cannot be opened, or
// if reading its strings apart refuses it (hdf5_strings_apart.hpp: its strings are never read by
// this process).
class Hdf5Reader {
 public:
  explicit Hdf5Reader(const std::filesystem::path& path);
  const H5Group& root() const { return *root_; }

 private:
  std::unique_ptr<H5Group> root_;
};

// Attaches the code version ("stoneskip 0.1.0 (git ...)") and the creation time (UTC) to a group.
void stamp_provenance(const H5Group& g);

}  // namespace stoneskip
