#pragma once
// Finished throws in transit: rows of a sweep's table plus their notes, and one byte encoding of
// them shared by the MPI messages and the journal records (same machine architecture assumed:
// native doubles, little- or big-endian as the host; a journal records which).
#include <cstdint>
#include <string>
#include <vector>

#include "verification/sweep/throw_record.hpp"

namespace stoneskip {

struct RowBatch {
  std::size_t width = 0;         // columns per row
  std::vector<double> values;    // rows × width, row-major
  std::vector<ThrowNote> notes;

  std::size_t rows() const { return width ? values.size() / width : 0; }
  void add_row(const std::vector<double>& row);  // throws std::invalid_argument on a wrong width
  void append(const RowBatch& other);
  std::uint64_t throw_index(std::size_t row) const;  // column 0
  void clear();
};

std::vector<unsigned char> encode(const RowBatch& b);
// False (and b unspecified) when the bytes are not a well-formed batch.
bool decode(const unsigned char* data, std::size_t size, RowBatch& b);

// FNV-1a, 64 bits (Fowler, Noll & Vo): the journal's record checksum.
std::uint64_t fnv1a64(const unsigned char* data, std::size_t size);

}  // namespace stoneskip
