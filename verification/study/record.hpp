#pragma once
// A study's findings as stored values: the numbers, texts (labels, verdicts and the computed
// reasons for them), tables and nested records that a report may format and nothing it would have
// to compute. Every study in verification/ turns its result into Records; a report section is a
// function of one Record read back from data.h5 (reports/), so a report is a function of its file.
//
// Keys are unique within a record whatever their kind ([A-Za-z0-9_.-], units in the name:
// "limit_sigma", "cpu_s"). Reading a key that is missing, or of another kind, throws RecordError
// naming the record's path and the key: a report never invents a value.
//
// On disk (store_record / load_record): a record is an HDF5 group; numbers and texts are its
// attributes, tables 2-D datasets with a `columns` attribute, string lists 1-D string datasets,
// children sub-groups; the children's order is kept in the attribute `_children`.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"

namespace stoneskip {

class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Record {
 public:
  explicit Record(std::string path = "") : path_(std::move(path)) {}
  Record(const Record& other);
  Record& operator=(const Record& other);
  Record(Record&&) noexcept = default;
  Record& operator=(Record&&) noexcept = default;

  // Writing (a key already used for another kind is an error; the same kind is replaced).
  Record& set(const std::string& key, double value);
  Record& set(const std::string& key, int value) { return set(key, static_cast<double>(value)); }
  Record& set(const std::string& key, long value) { return set(key, static_cast<double>(value)); }
  Record& set(const std::string& key, long long value) { return set(key, static_cast<double>(value)); }
  Record& set(const std::string& key, std::size_t value) { return set(key, static_cast<double>(value)); }
  Record& set(const std::string& key, bool value) { return set(key, value ? 1.0 : 0.0); }
  Record& set(const std::string& key, const std::string& text);
  Record& set(const std::string& key, const char* text) { return set(key, std::string(text)); }
  Record& set_table(const std::string& key, Table table);
  Record& set_strings(const std::string& key, std::vector<std::string> list);
  Record& child(const std::string& key);  // the child of that name, created empty if missing
  Record& add_child(const std::string& key, Record r);  // replaces a child of that name

  // Reading.
  bool has(const std::string& key) const;
  bool has_number(const std::string& key) const { return numbers_.count(key) > 0; }
  bool has_text(const std::string& key) const { return texts_.count(key) > 0; }
  bool has_table(const std::string& key) const { return tables_.count(key) > 0; }
  bool has_child(const std::string& key) const;
  double number(const std::string& key) const;
  bool flag(const std::string& key) const { return number(key) != 0; }
  const std::string& text(const std::string& key) const;
  const Table& table(const std::string& key) const;
  const std::vector<std::string>& strings(const std::string& key) const;
  const Record& at(const std::string& key) const;
  std::vector<std::string> child_names() const;  // in the order they were added
  const std::string& path() const { return path_; }

  const std::map<std::string, double>& numbers() const { return numbers_; }
  const std::map<std::string, std::string>& texts() const { return texts_; }
  const std::map<std::string, Table>& tables() const { return tables_; }
  const std::map<std::string, std::vector<std::string>>& string_lists() const { return strings_; }

  bool operator==(const Record& other) const;

 private:
  void claim(const std::string& key, char kind);  // checks the key and that it is free for `kind`
  [[noreturn]] void missing(const std::string& key, const char* kind) const;
  std::string child_path(const std::string& key) const { return path_ + "/" + key; }
  void rebase(const std::string& path);

  std::string path_;
  std::map<std::string, double> numbers_;
  std::map<std::string, std::string> texts_;
  std::map<std::string, Table> tables_;
  std::map<std::string, std::vector<std::string>> strings_;
  std::vector<std::pair<std::string, std::unique_ptr<Record>>> children_;
};

void store_record(const H5Group& group, const Record& r);
Record load_record(const H5Group& group);

}  // namespace stoneskip
