#pragma once
// For the end-to-end tests: edits one attribute, or one cell of a 2-D float64 table, of a result
// file as a user with h5py would, to see what stoneskip then does with it. The attribute is deleted and made again (HDF5 1.10 cannot
// rewrite an attribute of these files in place), with the type stoneskip writes: a double, a
// 64-bit integer, or a variable-length UTF-8 string.
#include <boost/test/unit_test.hpp>

#include <hdf5.h>

#include <filesystem>
#include <string>

namespace stoneskip::test {

namespace detail {
template <typename Write>
void replace_attribute(const std::filesystem::path& file, const std::string& object, const char* name, hid_t type,
                       const Write& write) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  BOOST_REQUIRE(f >= 0);
  BOOST_REQUIRE(H5Adelete_by_name(f, object.c_str(), name, H5P_DEFAULT) >= 0);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(f, object.c_str(), name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  BOOST_REQUIRE(a >= 0);
  BOOST_REQUIRE(write(a) >= 0);
  H5Aclose(a);
  H5Sclose(space);
  H5Fclose(f);
}
}  // namespace detail

inline void set_attribute(const std::filesystem::path& file, const std::string& object, const char* name, double value) {
  detail::replace_attribute(file, object, name, H5T_NATIVE_DOUBLE, [&](hid_t a) { return H5Awrite(a, H5T_NATIVE_DOUBLE, &value); });
}

inline void set_attribute(const std::filesystem::path& file, const std::string& object, const char* name, long long value) {
  detail::replace_attribute(file, object, name, H5T_NATIVE_LLONG, [&](hid_t a) { return H5Awrite(a, H5T_NATIVE_LLONG, &value); });
}

inline void set_attribute(const std::filesystem::path& file, const std::string& object, const char* name,
                          const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const char* text = value.c_str();
  detail::replace_attribute(file, object, name, type, [&](hid_t a) { return H5Awrite(a, type, &text); });
  H5Tclose(type);
}

// Cell (row, column) of the 2-D float64 dataset `table` (e.g. "/throws"), written in place.
inline void set_cell(const std::filesystem::path& file, const std::string& table, unsigned long long row,
                     unsigned long long column, double value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  BOOST_REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, table.c_str(), H5P_DEFAULT);
  BOOST_REQUIRE(d >= 0);
  const hid_t space = H5Dget_space(d);
  const hsize_t start[2] = {row, column}, count[2] = {1, 1};
  BOOST_REQUIRE(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr) >= 0);
  const hsize_t one = 1;
  const hid_t memory = H5Screate_simple(1, &one, nullptr);
  BOOST_REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, &value) >= 0);
  H5Sclose(memory);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
}

}  // namespace stoneskip::test
