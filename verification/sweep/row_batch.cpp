#include "verification/sweep/row_batch.hpp"

#include <cstring>
#include <stdexcept>

namespace stoneskip {

void RowBatch::add_row(const std::vector<double>& row) {
  if (row.size() != width) throw std::invalid_argument("RowBatch::add_row: wrong column count");
  values.insert(values.end(), row.begin(), row.end());
}

void RowBatch::append(const RowBatch& other) {
  if (other.rows() == 0 && other.notes.empty()) return;
  if (width == 0) width = other.width;
  if (other.width != width && other.rows() > 0) throw std::invalid_argument("RowBatch::append: wrong column count");
  values.insert(values.end(), other.values.begin(), other.values.end());
  notes.insert(notes.end(), other.notes.begin(), other.notes.end());
}

std::uint64_t RowBatch::throw_index(std::size_t row) const { return static_cast<std::uint64_t>(values.at(row * width)); }

void RowBatch::clear() {
  values.clear();
  notes.clear();
}

namespace {

template <class T>
void put(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

void put_string(std::vector<unsigned char>& out, const std::string& s) {
  put<std::uint64_t>(out, s.size());
  out.insert(out.end(), s.begin(), s.end());
}

struct Reader {
  const unsigned char* p;
  std::size_t left;
  template <class T>
  bool get(T& v) {
    if (left < sizeof(T)) return false;
    std::memcpy(&v, p, sizeof(T));
    p += sizeof(T);
    left -= sizeof(T);
    return true;
  }
  bool get_string(std::string& s) {
    std::uint64_t n = 0;
    if (!get(n) || n > left) return false;
    s.assign(reinterpret_cast<const char*>(p), n);
    p += n;
    left -= n;
    return true;
  }
};

}  // namespace

// Layout: u64 width, u64 rows, rows × width doubles, u64 notes, per note (u64 throw, string solver,
// string detail); a string is u64 length + bytes.
std::vector<unsigned char> encode(const RowBatch& b) {
  std::vector<unsigned char> out;
  out.reserve(16 + b.values.size() * sizeof(double));
  put<std::uint64_t>(out, b.width);
  put<std::uint64_t>(out, b.rows());
  const auto* v = reinterpret_cast<const unsigned char*>(b.values.data());
  out.insert(out.end(), v, v + b.rows() * b.width * sizeof(double));
  put<std::uint64_t>(out, b.notes.size());
  for (const auto& n : b.notes) {
    put<std::uint64_t>(out, n.throw_index);
    put_string(out, n.solver);
    put_string(out, n.detail);
  }
  return out;
}

bool decode(const unsigned char* data, std::size_t size, RowBatch& b) {
  Reader r{data, size};
  std::uint64_t width = 0, rows = 0, notes = 0;
  if (!r.get(width) || !r.get(rows)) return false;
  if (width > (1u << 20) || (width == 0 && rows > 0)) return false;
  if (width && rows > r.left / (width * sizeof(double))) return false;
  b.width = width;
  b.values.resize(rows * width);
  if (rows * width != 0) std::memcpy(b.values.data(), r.p, rows * width * sizeof(double));
  r.p += rows * width * sizeof(double);
  r.left -= rows * width * sizeof(double);
  if (!r.get(notes) || notes > r.left) return false;
  b.notes.resize(notes);
  for (auto& n : b.notes)
    if (!r.get(n.throw_index) || !r.get_string(n.solver) || !r.get_string(n.detail)) return false;
  return r.left == 0;
}

std::uint64_t fnv1a64(const unsigned char* data, std::size_t size) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= data[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace stoneskip
