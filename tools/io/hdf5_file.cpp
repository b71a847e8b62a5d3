#include "tools/io/hdf5_file.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <system_error>

#include "stoneskip_version.hpp"
#include "tools/io/column_units.hpp"
#include "tools/io/hdf5_strings_apart.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {

// HDF5's own error stack printing is silenced: failures surface as exceptions with our message.
struct SilenceHdf5 {
  SilenceHdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
};
const SilenceHdf5 kSilence;

// The final name of the file this thread's innermost Hdf5Writer writes (nullptr: none).
thread_local const std::filesystem::path* t_writing = nullptr;

// Runs one HDF5 call and throws where it failed. errno is cleared before the call, so that the
// cause read after it is the call's own, not one left by an earlier, unrelated failure.
template <class Call>
void check(Call&& call, const std::string& what) {
  errno = 0;
  const herr_t status = call();
  if (status >= 0) return;
  // A write that failed for want of room (a large dataset goes to the disk at once, past HDF5's
  // cache): the output place's fault, exit 2 (tools/cli/main.cpp), not an internal error.
  const int e = errno;
  if ((e == ENOSPC || e == EDQUOT || e == EFBIG || e == EIO) && t_writing)
    throw_input_error(t_writing->string(), 0, "",
                      "cannot write the HDF5 file (" + std::string(std::strerror(e)) + ", at " + what + "); nothing written there");
  if (e == ENOSPC || e == EDQUOT || e == EFBIG || e == EIO) throw std::system_error(e, std::generic_category(), "HDF5: " + what);
  throw std::runtime_error("HDF5: " + what);
}

// A dataset's values that would not read: with the Fletcher-32 checksum (checksummed_layout) a
// value changed on disk fails here.
std::string read_failed(const std::string& path) {
  return "cannot read " + path + " (values damaged on disk fail their checksum; or not numbers)";
}

hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: " + what);
  return id;
}

H5Id scalar_space() { return H5Id(H5Screate(H5S_SCALAR), H5Sclose); }

H5Id open_attr(hid_t obj, const std::string& name) {
  return H5Id(check_id(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "no attribute " + name), H5Aclose);
}

H5Id replace_attr(hid_t obj, const std::string& name, hid_t type, hid_t space) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  return H5Id(check_id(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                       "cannot create attribute " + name),
              H5Aclose);
}

void set_string_attr(hid_t obj, const std::string& name, const std::string& value) {
  H5Id t = vlen_string_type();
  H5Id s = scalar_space();
  H5Id a = replace_attr(obj, name, t.get(), s.get());
  const char* p = value.c_str();
  check([&] { return H5Awrite(a.get(), t.get(), &p); }, "write attribute " + name);
}

// A 1-D array of strings as an attribute (h5py reads it as a list of str).
void set_strings_attr(hid_t obj, const std::string& name, const std::vector<std::string>& values) {
  H5Id t = vlen_string_type();
  const hsize_t n = values.size();
  H5Id s(H5Screate_simple(1, &n, nullptr), H5Sclose);
  H5Id a = replace_attr(obj, name, t.get(), s.get());
  std::vector<const char*> ptrs;
  for (const auto& v : values) ptrs.push_back(v.c_str());
  if (n > 0) check([&] { return H5Awrite(a.get(), t.get(), ptrs.data()); }, "write attribute " + name);
}

// A link to another file (an external link) is not followed: stoneskip writes none, and the file
// it names would be read by the library in this process, unchecked and outside the isolation of
// this one (isolated_read.hpp, hdf5_strings_apart.hpp).
void require_in_file(hid_t loc, const std::string& name, const std::string& path) {
  H5L_info_t link;  // HDF5 1.10 (Debian 12)
  if (H5Lget_info(loc, name.c_str(), &link, H5P_DEFAULT) >= 0 && link.type == H5L_TYPE_EXTERNAL)
    throw std::runtime_error("HDF5: " + path + " is a link to another file");
}

H5Id open_dataset(hid_t loc, const std::string& name, const std::string& path) {
  require_in_file(loc, name, path);
  return H5Id(check_id(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "no dataset " + path), H5Dclose);
}

// The number of elements of an attribute's dataspace (a scalar: 1; a null one: 0).
hssize_t attr_elements(hid_t a) {
  H5Id space(H5Aget_space(a), H5Sclose);
  return H5Sget_simple_extent_npoints(space.get());
}

// An attribute read into one value must hold one: the library writes every element it holds, and
// a crafted file's array of 1000 where one is read overwrote the stack.
void require_one(hid_t a, const std::string& name) {
  const hssize_t n = attr_elements(a);
  if (n != 1) throw std::runtime_error("HDF5: attribute " + name + " holds " + std::to_string(n) + " values, not one");
}

// The strings of attribute `name` of obj, one per element (with one_value: exactly one): from the
// table read apart in a child (hdf5_strings_apart.hpp), or, with none (a writer's groups, or this
// process is that child), from the library.
std::vector<std::string> get_strings_attr(hid_t obj, const std::string& name, const Hdf5StringTable* table, bool one_value = false) {
  H5Id a = open_attr(obj, name);
  if (one_value) require_one(a.get(), name);
  const hssize_t n = attr_elements(a.get());
  if (table) {
    const std::vector<std::string>* v = table->find(obj, Hdf5StringTable::Kind::attribute, name);
    if (!v || static_cast<hssize_t>(v->size()) != n) throw std::runtime_error("HDF5: read attribute " + name);
    return *v;
  }
  std::vector<char*> ptrs(static_cast<std::size_t>(std::max<hssize_t>(n, 0)), nullptr);
  const H5Id stored(H5Aget_type(a.get()), H5Tclose);
  const H5Id t = string_type_for(stored.get());
  if (!ptrs.empty()) check([&] { return H5Aread(a.get(), t.get(), ptrs.data()); }, "read attribute " + name);
  std::vector<std::string> out;
  for (char* p : ptrs) {
    out.emplace_back(p ? p : "");
    H5free_memory(p);
  }
  return out;
}

std::string get_string_attr(hid_t obj, const std::string& name, const Hdf5StringTable* table) {
  return get_strings_attr(obj, name, table, true).front();
}

// A table's column names: a string array (current files) or one comma-separated string (files
// written before the units).
std::vector<std::string> get_column_names(hid_t ds, const Hdf5StringTable* table) {
  H5Id a = open_attr(ds, "columns");
  H5Id space(H5Aget_space(a.get()), H5Sclose);
  if (H5Sget_simple_extent_type(space.get()) == H5S_SIMPLE) return get_strings_attr(ds, "columns", table);
  std::vector<std::string> names;
  const std::string cols = get_string_attr(ds, "columns", table);
  std::size_t start = 0;
  while (!cols.empty()) {
    const std::size_t comma = cols.find(',', start);
    names.push_back(cols.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

// A dataset's values are raw data, which no HDF5 format checksums; the Fletcher-32 filter (HDF5
// User's Guide, "Filters") stores a checksum with each chunk and the library verifies it on
// reading, so a value changed on disk is an error, not a number read as stored. Filters need a
// chunked layout: one chunk of the whole dataset, or of as many leading slices as fit in 64 MiB.
// An empty dataset (no values) and variable-length strings (whose values live in the global heap,
// which the filter would not cover: read apart, hdf5_strings_apart.hpp) stay contiguous.
H5Id checksummed_layout(hid_t type, const std::vector<hsize_t>& dims) {
  H5Id plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (plist.get() < 0) throw std::runtime_error("HDF5: cannot create a dataset property list");
  const bool empty = dims.empty() || std::any_of(dims.begin(), dims.end(), [](hsize_t d) { return d == 0; });
  if (empty || H5Tis_variable_str(type) > 0) return plist;
  std::vector<hsize_t> chunk = dims;
  const hsize_t element = H5Tget_size(type);
  hsize_t slice = element;  // bytes of one leading slice
  for (std::size_t i = 1; i < dims.size(); ++i) slice *= dims[i];
  constexpr hsize_t kMaxChunkBytes = hsize_t(64) << 20;
  chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], kMaxChunkBytes / std::max<hsize_t>(slice, 1)));
  if (H5Pset_chunk(plist.get(), static_cast<int>(chunk.size()), chunk.data()) < 0 || H5Pset_fletcher32(plist.get()) < 0)
    throw std::runtime_error("HDF5: cannot set a checksummed layout");
  return plist;
}

H5Id create_dataset(hid_t loc, const std::string& name, hid_t type, const std::vector<hsize_t>& dims) {
  H5Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  const H5Id layout = checksummed_layout(type, dims);
  return H5Id(check_id(H5Dcreate2(loc, name.c_str(), type, space.get(), H5P_DEFAULT, layout.get(), H5P_DEFAULT),
                       "cannot create dataset " + name),
              H5Dclose);
}

std::vector<hsize_t> dataset_dims(hid_t ds) {
  H5Id space(H5Dget_space(ds), H5Sclose);
  int rank = H5Sget_simple_extent_ndims(space.get());
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

hsize_t element_count(const std::vector<hsize_t>& dims) {
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  return n;
}

}  // namespace

H5Id::H5Id(hid_t id, Closer closer) : id_(id), closer_(closer) {}
H5Id::~H5Id() {
  if (id_ >= 0 && closer_) closer_(id_);
}
H5Id::H5Id(H5Id&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = -1; }
H5Id& H5Id::operator=(H5Id&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0 && closer_) closer_(id_);
    id_ = o.id_;
    closer_ = o.closer_;
    o.id_ = -1;
  }
  return *this;
}

void Table::add_row(const std::vector<double>& row) {
  if (row.size() != columns.size()) throw std::invalid_argument("Table::add_row: wrong column count");
  values.insert(values.end(), row.begin(), row.end());
}

bool Table::has_column(const std::string& name) const {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

std::vector<double> Table::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] == name) {
      std::vector<double> out(rows());
      for (std::size_t r = 0; r < out.size(); ++r) out[r] = values[r * columns.size() + c];
      return out;
    }
  }
  throw std::out_of_range("no column " + name);
}

std::string Table::unit(std::size_t c) const {
  if (c < units.size() && !units[c].empty()) return units[c];
  return column_unit(columns.at(c));
}

H5Group H5Group::create_group(const std::string& name) const {
  hid_t g = check_id(H5Gcreate2(id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     "cannot create group " + name);
  return H5Group(H5Id(g, H5Gclose), path_ + "/" + name);
}

H5Group H5Group::open_group(const std::string& name) const {
  require_in_file(id(), name, path_ + "/" + name);
  hid_t g = check_id(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), "no group " + path_ + "/" + name);
  return H5Group(H5Id(g, H5Gclose), path_ + "/" + name, strings_);
}

bool H5Group::has(const std::string& name) const { return H5Lexists(id(), name.c_str(), H5P_DEFAULT) > 0; }

std::vector<std::string> H5Group::children() const {
  std::vector<std::string> names;
  H5Literate(
      id(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* link_name, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->emplace_back(link_name);
        return 0;
      },
      &names);
  return names;
}

H5Group::ChildKind H5Group::child_kind(const std::string& name) const {
  H5O_info_t info;  // HDF5 1.10 (Debian 12)
  require_in_file(id(), name, path_ + "/" + name);
  if (H5Oget_info_by_name2(id(), name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0)
    throw std::runtime_error("HDF5: no object " + path_ + "/" + name);
  if (info.type == H5O_TYPE_GROUP) return ChildKind::group;
  if (info.type != H5O_TYPE_DATASET) return ChildKind::other;
  H5Id ds = open_dataset(id(), name, path_ + "/" + name);
  H5Id type(H5Dget_type(ds.get()), H5Tclose);
  const auto dims = dataset_dims(ds.get());
  if (H5Tget_class(type.get()) == H5T_STRING) return dims.size() == 1 ? ChildKind::strings : ChildKind::other;
  if (H5Tget_class(type.get()) != H5T_FLOAT) return ChildKind::other;
  if (dims.size() == 2 && H5Aexists(ds.get(), "columns") > 0) return ChildKind::table;
  if (dims.size() == 1) return ChildKind::vector;
  return ChildKind::other;
}

void H5Group::write_vector(const std::string& name, const std::vector<double>& v, const std::string& units) const {
  H5Id ds = create_dataset(id(), name, H5T_NATIVE_DOUBLE, {static_cast<hsize_t>(v.size())});
  if (!v.empty()) check([&] { return H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()); }, "write " + name);
  if (!units.empty()) set_string_attr(ds.get(), "units", units);
}

void H5Group::write_ints(const std::string& name, const std::vector<long long>& v) const {
  H5Id ds = create_dataset(id(), name, H5T_NATIVE_LLONG, {static_cast<hsize_t>(v.size())});
  if (!v.empty()) check([&] { return H5Dwrite(ds.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()); }, "write " + name);
}

void H5Group::write_table(const std::string& name, const Table& t) const {
  H5Id ds = create_dataset(id(), name, H5T_NATIVE_DOUBLE,
                           {static_cast<hsize_t>(t.rows()), static_cast<hsize_t>(t.columns.size())});
  if (!t.values.empty())
    check([&] { return H5Dwrite(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.values.data()); }, "write " + name);
  if (!t.units.empty() && t.units.size() != t.columns.size())
    throw std::invalid_argument("write_table " + name + ": " + std::to_string(t.units.size()) + " units for " +
                                std::to_string(t.columns.size()) + " columns");
  std::vector<std::string> units;
  for (std::size_t c = 0; c < t.columns.size(); ++c) units.push_back(t.unit(c));
  set_strings_attr(ds.get(), "columns", t.columns);
  set_strings_attr(ds.get(), "units", units);
}

void H5Group::write_floats_3d(const std::string& name, const std::vector<float>& v, const std::array<std::size_t, 3>& dims,
                              const std::string& units) const {
  if (v.size() != dims[0] * dims[1] * dims[2]) throw std::invalid_argument("write_floats_3d " + name + ": size does not match dims");
  H5Id ds = create_dataset(id(), name, H5T_NATIVE_FLOAT,
                           {static_cast<hsize_t>(dims[0]), static_cast<hsize_t>(dims[1]), static_cast<hsize_t>(dims[2])});
  if (!v.empty()) check([&] { return H5Dwrite(ds.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()); }, "write " + name);
  set_string_attr(ds.get(), "units", units);
}

void H5Group::write_strings(const std::string& name, const std::vector<std::string>& v) const {
  H5Id t = vlen_string_type();
  H5Id ds = create_dataset(id(), name, t.get(), {static_cast<hsize_t>(v.size())});
  std::vector<const char*> ptrs;
  for (const auto& s : v) ptrs.push_back(s.c_str());
  if (!v.empty()) check([&] { return H5Dwrite(ds.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()); }, "write " + name);
}

std::vector<double> H5Group::read_vector(const std::string& name) const {
  H5Id ds = open_dataset(id(), name, path_ + "/" + name);
  std::vector<double> v(element_count(dataset_dims(ds.get())));
  if (!v.empty()) check([&] { return H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()); }, read_failed(path_ + "/" + name));
  return v;
}

std::vector<long long> H5Group::read_ints(const std::string& name) const {
  H5Id ds = open_dataset(id(), name, path_ + "/" + name);
  std::vector<long long> v(element_count(dataset_dims(ds.get())));
  if (!v.empty()) check([&] { return H5Dread(ds.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()); }, read_failed(path_ + "/" + name));
  return v;
}

Table H5Group::read_table(const std::string& name) const {
  H5Id ds = open_dataset(id(), name, path_ + "/" + name);
  auto dims = dataset_dims(ds.get());
  Table t;
  t.columns = get_column_names(ds.get(), strings_.get());
  if (H5Aexists(ds.get(), "units") > 0) {
    t.units = get_strings_attr(ds.get(), "units", strings_.get());
    if (t.units.size() != t.columns.size()) throw std::runtime_error("HDF5: " + name + " has " + std::to_string(t.units.size()) +
                                                                     " units for " + std::to_string(t.columns.size()) + " columns");
  }
  t.values.resize(element_count(dims));
  if (dims.size() != 2 || dims[1] != t.columns.size()) throw std::runtime_error("HDF5: " + name + " is not a table");
  if (!t.values.empty())
    check([&] { return H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.values.data()); }, read_failed(path_ + "/" + name));
  return t;
}

std::vector<std::string> H5Group::read_strings(const std::string& name) const {
  H5Id ds = open_dataset(id(), name, path_ + "/" + name);
  const std::size_t n = element_count(dataset_dims(ds.get()));
  if (strings_) {
    const auto* v = strings_->find(ds.get(), Hdf5StringTable::Kind::dataset, "");
    if (!v || v->size() != n) throw std::runtime_error("HDF5: read " + name);
    return *v;
  }
  std::vector<char*> ptrs(n, nullptr);
  const H5Id stored(H5Dget_type(ds.get()), H5Tclose);
  const H5Id t = string_type_for(stored.get());
  if (!ptrs.empty()) check([&] { return H5Dread(ds.get(), t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()); }, "read " + name);
  std::vector<std::string> out;
  for (char* p : ptrs) {
    out.emplace_back(p ? p : "");
    H5free_memory(p);
  }
  return out;
}

void H5Group::set_attr(const std::string& name, const std::string& value) const { set_string_attr(id(), name, value); }

void H5Group::set_attr(const std::string& name, double value) const {
  H5Id s = scalar_space();
  H5Id a = replace_attr(id(), name, H5T_NATIVE_DOUBLE, s.get());
  check([&] { return H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value); }, "write attribute " + name);
}

void H5Group::set_attr(const std::string& name, long long value) const {
  H5Id s = scalar_space();
  H5Id a = replace_attr(id(), name, H5T_NATIVE_LLONG, s.get());
  check([&] { return H5Awrite(a.get(), H5T_NATIVE_LLONG, &value); }, "write attribute " + name);
}

bool H5Group::has_attr(const std::string& name) const { return H5Aexists(id(), name.c_str()) > 0; }

std::vector<std::string> H5Group::attr_names() const {
  std::vector<std::string> names;
  hsize_t idx = 0;
  H5Aiterate2(
      id(), H5_INDEX_NAME, H5_ITER_INC, &idx,
      [](hid_t, const char* attr_name, const H5A_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->emplace_back(attr_name);
        return 0;
      },
      &names);
  return names;
}

bool H5Group::attr_is_string(const std::string& name) const {
  H5Id a = open_attr(id(), name);
  H5Id t(H5Aget_type(a.get()), H5Tclose);
  return H5Tget_class(t.get()) == H5T_STRING;
}
std::string H5Group::attr_string(const std::string& name) const {
  return get_string_attr(id(), name, strings_.get());
}

double H5Group::attr_double(const std::string& name) const {
  H5Id a = open_attr(id(), name);
  require_one(a.get(), name);
  double v = 0;
  check([&] { return H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v); }, "read attribute " + name);
  return v;
}

long long H5Group::attr_int(const std::string& name) const {
  H5Id a = open_attr(id(), name);
  require_one(a.get(), name);
  long long v = 0;
  check([&] { return H5Aread(a.get(), H5T_NATIVE_LLONG, &v); }, "read attribute " + name);
  return v;
}

Hdf5Writer::Hdf5Writer(const std::filesystem::path& path) : out_(path) {
  // The temporary exists (AtomicOutput made it, empty): H5F_ACC_TRUNC takes it over. The file is
  // written in the HDF5 1.8 format (superblock 2, object headers 2), whose metadata carry
  // checksums that the library verifies on reading: a damaged header is then an error, not a value
  // read as stored. (The library's default, the earliest format, has none; the global heap of the
  // variable-length strings has none in any format: those are read apart, hdf5_strings_apart.hpp.)
  const H5Id access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (access.get() < 0 || H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18) < 0)
    throw_input_error(path.string(), 0, "", "cannot set the HDF5 file format");
  hid_t f = H5Fcreate(out_.temporary_path().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (f < 0) throw_input_error(path.string(), 0, "", "cannot create HDF5 file");
  file_ = f;
  root_ = std::make_unique<H5Group>(H5Id(H5Gopen2(file_, "/", H5P_DEFAULT), H5Gclose), "");
  previous_writing_ = t_writing;
  t_writing = &out_.final_path();
}

namespace {
std::atomic<bool> g_write_failed{false};
}  // namespace

bool hdf5_write_failed() { return g_write_failed.load(); }

Hdf5Writer::~Hdf5Writer() {
  if (t_writing == &out_.final_path()) t_writing = previous_writing_;
  root_.reset();
  if (file_ >= 0) {
    // Not committed (an error on the way): the temporary is removed by out_. The library may still
    // hold the file after a failed write; its clean-up at exit could crash on it (main ends without).
    g_write_failed = true;
    H5Fclose(file_);
  }
}

void Hdf5Writer::commit() {
  const int saved = errno;
  errno = 0;
  const bool flushed = H5Fflush(file_, H5F_SCOPE_GLOBAL) >= 0;
  const int flush_errno = flushed ? 0 : errno;  // the cause, before the close can overwrite it
  root_.reset();
  const hid_t f = file_;
  file_ = -1;
  errno = 0;
  const bool closed = H5Fclose(f) >= 0;
  const int close_errno = closed ? 0 : errno;
  if (!flushed || !closed) {
    g_write_failed = true;
    const int e = flush_errno != 0 ? flush_errno : close_errno;
    const std::string why = e != 0 ? std::strerror(e) : "the HDF5 library reported an error";
    throw_input_error(out_.final_path().string(), 0, "", "cannot write the HDF5 file (" + why + "); nothing written there");
  }
  errno = saved;
  out_.commit();
}

Hdf5Reader::Hdf5Reader(const std::filesystem::path& path) {
  require_regular_file(path);
  if (H5Fis_hdf5(path.c_str()) <= 0) throw_input_error(path.string(), 0, "", "not an HDF5 file");
  std::optional<Hdf5StringTable> strings = read_strings_apart(path);
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw_input_error(path.string(), 0, "", "cannot open HDF5 file");
  H5Id file(f, H5Fclose);
  H5Id root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  std::shared_ptr<const Hdf5StringTable> table;
  if (strings) {
    H5O_info_t info;  // HDF5 1.10 (Debian 12)
    if (H5Oget_info2(root.get(), &info, H5O_INFO_BASIC) < 0) throw_input_error(path.string(), 0, "", "cannot open HDF5 file");
    strings->fileno = info.fileno;
    table = std::make_shared<const Hdf5StringTable>(std::move(*strings));
  }
  root_ = std::make_unique<H5Group>(std::move(root), "", std::move(table));
}

H5Id vlen_string_type(H5T_cset_t cset) {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, H5T_VARIABLE);
  H5Tset_cset(t, cset);
  return H5Id(t, H5Tclose);
}

H5Id string_type_for(hid_t stored) {
  const H5T_cset_t cset = H5Tget_cset(stored);
  return vlen_string_type(cset == H5T_CSET_ASCII ? H5T_CSET_ASCII : H5T_CSET_UTF8);
}

void stamp_provenance(const H5Group& g) {
  g.set_attr("code_version", std::string("stoneskip ") + kVersion + " (git " + kGitDescribe + ")");
  std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  g.set_attr("created_utc", std::string(buf));
}

}  // namespace stoneskip
