#include "tools/io/hdf5_strings_apart.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <optional>
#include <set>
#include <stdexcept>

#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/isolated_read.hpp"

// The table's bytes, as the child writes them to the pipe (one machine, one build: native byte
// order): records, each
//   kind (1 byte: 'A' or 'D'), the object's address (8 bytes), the attribute's name (an 8-byte
//   length and its bytes), the element count (8 bytes), then each element (a length, its bytes);
// then 'E' once the walk is whole. A walk that failed part way (no 'E') is not a table.

namespace stoneskip {

namespace {

// Elements above this in one attribute or dataset are not read (their pointers alone would take
// gigabytes): a reader that asks for them gets "not in the table".
constexpr hssize_t kMostElements = hssize_t{1} << 26;

class Out {
 public:
  explicit Out(int fd) : fd_(fd) {}
  void u8(char c) { buf_.push_back(c); }
  void u64(std::uint64_t v) { buf_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void text(const std::string& s) {
    u64(s.size());
    buf_ += s;
    if (buf_.size() > (1u << 16)) flush();
  }
  void flush() {
    std::size_t at = 0;
    while (at < buf_.size()) {
      const ssize_t n = ::write(fd_, buf_.data() + at, buf_.size() - at);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error("the pipe closed");
      at += static_cast<std::size_t>(n);
    }
    buf_.clear();
  }

 private:
  int fd_;
  std::string buf_;
};

// The strings of an attribute (is_attr) or a dataset, read as hdf5_file.cpp reads them, written
// out as one record (each string straight from the library's copy: no second copy of them all);
// nothing where the library refuses.
void put_strings(Out& out, hid_t obj, bool is_attr, Hdf5StringTable::Kind kind, haddr_t addr, const std::string& name) {
  const H5Id space(is_attr ? H5Aget_space(obj) : H5Dget_space(obj), H5Sclose);
  if (!space.valid()) return;
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n < 0 || n > kMostElements) return;
  std::vector<char*> ptrs(static_cast<std::size_t>(n), nullptr);
  const H5Id stored(is_attr ? H5Aget_type(obj) : H5Dget_type(obj), H5Tclose);
  const H5Id t = string_type_for(stored.get());
  if (n > 0) {
    const herr_t st = is_attr ? H5Aread(obj, t.get(), ptrs.data())
                              : H5Dread(obj, t.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data());
    if (st < 0) return;
  }
  out.u8(static_cast<char>(kind));
  out.u64(addr);
  out.text(name);
  out.u64(ptrs.size());
  for (char*& p : ptrs) {
    out.text(p ? std::string(p) : std::string());
    H5free_memory(p);
    p = nullptr;
  }
}

// Every string-typed attribute of obj.
void walk_attributes(hid_t obj, haddr_t addr, Out& out) {
  std::vector<std::string> names;
  hsize_t idx = 0;
  H5Aiterate2(
      obj, H5_INDEX_NAME, H5_ITER_INC, &idx,
      [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->emplace_back(name);
        return 0;
      },
      &names);
  for (const auto& name : names) {
    const H5Id a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
    if (!a.valid()) continue;
    const H5Id t(H5Aget_type(a.get()), H5Tclose);
    if (!t.valid() || H5Tget_class(t.get()) != H5T_STRING) continue;
    put_strings(out, a.get(), true, Hdf5StringTable::Kind::attribute, addr, name);
  }
}

// obj and, for a group, everything below it by hard links; each object once.
void walk(hid_t obj, std::set<haddr_t>& seen, Out& out) {
  H5O_info_t info;  // HDF5 1.10 (Debian 12), as hdf5_file.cpp
  if (H5Oget_info2(obj, &info, H5O_INFO_BASIC) < 0 || !seen.insert(info.addr).second) return;
  walk_attributes(obj, info.addr, out);
  if (info.type == H5O_TYPE_DATASET) {
    const H5Id t(H5Dget_type(obj), H5Tclose);
    if (t.valid() && H5Tget_class(t.get()) == H5T_STRING)
      put_strings(out, obj, false, Hdf5StringTable::Kind::dataset, info.addr, "");
    return;
  }
  if (info.type != H5O_TYPE_GROUP) return;
  std::vector<std::string> hard;
  H5Literate(
      obj, H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t* link, void* data) -> herr_t {
        if (link->type == H5L_TYPE_HARD) static_cast<std::vector<std::string>*>(data)->emplace_back(name);
        return 0;
      },
      &hard);
  for (const auto& name : hard) {
    const H5Id child(H5Oopen(obj, name.c_str(), H5P_DEFAULT), H5Oclose);
    if (child.valid()) walk(child.get(), seen, out);
  }
}

class In {
 public:
  explicit In(const std::string& bytes) : s_(bytes) {}
  bool done() const { return at_ == s_.size(); }
  char u8() {
    need(1);
    return s_[at_++];
  }
  std::uint64_t u64() {
    need(sizeof(std::uint64_t));
    std::uint64_t v = 0;
    std::memcpy(&v, s_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::string text() {
    const std::uint64_t n = u64();
    need(n);
    std::string t = s_.substr(at_, n);
    at_ += n;
    return t;
  }

 private:
  void need(std::uint64_t n) const {
    if (n > s_.size() - at_) throw std::runtime_error("the table ends early");
  }
  const std::string& s_;
  std::size_t at_ = 0;
};

}  // namespace

const std::vector<std::string>* Hdf5StringTable::find(hid_t obj, Kind kind, const std::string& name) const {
  H5O_info_t info;
  if (H5Oget_info2(obj, &info, H5O_INFO_BASIC) < 0 || info.fileno != fileno) return nullptr;
  const auto it = entries.find({static_cast<std::uint64_t>(info.addr), static_cast<char>(kind), name});
  return it == entries.end() ? nullptr : &it->second;
}

void write_string_table(const std::filesystem::path& file, int fd) {
  Out out(fd);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f >= 0) {
    const H5Id owned(f, H5Fclose);
    const H5Id root(H5Oopen(f, "/", H5P_DEFAULT), H5Oclose);
    std::set<haddr_t> seen;
    if (root.valid()) walk(root.get(), seen, out);
  }
  // A file the library cannot open: an empty table, and the reader's own open says why.
  out.u8('E');
  out.flush();
}

Hdf5StringTable parse_string_table(const std::string& bytes) {
  Hdf5StringTable t;
  In in(bytes);
  for (;;) {
    const char kind = in.u8();
    if (kind == 'E') break;
    if (kind != 'A' && kind != 'D') throw std::runtime_error("a record of unknown kind");
    const std::uint64_t addr = in.u64();
    std::string name = in.text();
    const std::uint64_t n = in.u64();
    std::vector<std::string> values;
    for (std::uint64_t k = 0; k < n; ++k) values.push_back(in.text());  // each takes ≥ 8 bytes: n is bounded
    t.entries[{addr, kind, std::move(name)}] = std::move(values);
  }
  if (!in.done()) throw std::runtime_error("bytes after its end");
  return t;
}

std::optional<Hdf5StringTable> read_strings_apart(const std::filesystem::path& file) {
  if (in_isolated_child()) return std::nullopt;
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  // A file's own strings take about as many bytes as they hold, plus their paths and lengths.
  const std::size_t most = (std::size_t{64} << 20) + 16 * static_cast<std::size_t>(ec ? 0 : size);
  const auto bytes = read_in_child_first(file, [&](int fd) { write_string_table(file, fd); }, most);
  if (!bytes) return std::nullopt;
  try {
    return parse_string_table(*bytes);
  } catch (const std::exception& e) {
    throw_input_error(file.string(), 0, "",
                      std::string("is a damaged HDF5 file: its strings could not be read apart (") + e.what() +
                          "); nothing was written");
  }
}

}  // namespace stoneskip
