#include "verification/study/record.hpp"

#include <algorithm>
#include <cstring>
#include <set>

namespace stoneskip {

namespace {

constexpr const char* kChildrenAttr = "_children";

bool valid_key(const std::string& key) {
  if (key.empty() || key[0] == '_') return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
           c == '-';
  });
}

bool same_table(const Table& a, const Table& b) {
  if (a.columns != b.columns || a.values.size() != b.values.size()) return false;
  // Bitwise, so that NaN equals NaN: a stored table is the same table.
  return a.values.empty() || std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)) == 0;
}

std::string join_lines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "\n") + x;
  return s;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < s.size()) {
    const std::size_t nl = s.find('\n', start);
    out.push_back(s.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  return out;
}

}  // namespace

Record::Record(const Record& o)
    : path_(o.path_), numbers_(o.numbers_), texts_(o.texts_), tables_(o.tables_), strings_(o.strings_) {
  for (const auto& [k, c] : o.children_) children_.emplace_back(k, std::make_unique<Record>(*c));
}

Record& Record::operator=(const Record& o) {
  if (this != &o) {
    Record copy(o);
    *this = std::move(copy);
  }
  return *this;
}

void Record::claim(const std::string& key, char kind) {
  if (!valid_key(key)) throw RecordError(path_ + ": invalid key '" + key + "'");
  const bool taken = (kind != 'n' && numbers_.count(key)) || (kind != 't' && texts_.count(key)) ||
                     (kind != 'T' && tables_.count(key)) || (kind != 's' && strings_.count(key)) ||
                     (kind != 'c' && has_child(key));
  if (taken) throw RecordError(path_ + ": key '" + key + "' is already used for another kind of value");
}

void Record::missing(const std::string& key, const char* kind) const {
  throw RecordError((path_.empty() ? std::string("/") : path_) + ": no " + kind + " '" + key + "'");
}

Record& Record::set(const std::string& key, double value) {
  claim(key, 'n');
  numbers_[key] = value;
  return *this;
}

Record& Record::set(const std::string& key, const std::string& text) {
  claim(key, 't');
  texts_[key] = text;
  return *this;
}

Record& Record::set_table(const std::string& key, Table table) {
  claim(key, 'T');
  if (!table.columns.empty() && table.values.size() % table.columns.size() != 0)
    throw RecordError(path_ + ": table '" + key + "' has a ragged last row");
  tables_[key] = std::move(table);
  return *this;
}

Record& Record::set_strings(const std::string& key, std::vector<std::string> list) {
  claim(key, 's');
  strings_[key] = std::move(list);
  return *this;
}

Record& Record::child(const std::string& key) {
  for (auto& [k, c] : children_)
    if (k == key) return *c;
  claim(key, 'c');
  children_.emplace_back(key, std::make_unique<Record>(child_path(key)));
  return *children_.back().second;
}

void Record::rebase(const std::string& path) {
  path_ = path;
  for (auto& [k, c] : children_) c->rebase(child_path(k));
}

Record& Record::add_child(const std::string& key, Record r) {
  Record& slot = child(key);
  slot = std::move(r);
  slot.rebase(child_path(key));
  return slot;
}

bool Record::has_child(const std::string& key) const {
  for (const auto& [k, c] : children_)
    if (k == key) return true;
  return false;
}

bool Record::has(const std::string& key) const {
  return numbers_.count(key) || texts_.count(key) || tables_.count(key) || strings_.count(key) || has_child(key);
}

double Record::number(const std::string& key) const {
  auto it = numbers_.find(key);
  if (it == numbers_.end()) missing(key, "number");
  return it->second;
}

const std::string& Record::text(const std::string& key) const {
  auto it = texts_.find(key);
  if (it == texts_.end()) missing(key, "text");
  return it->second;
}

const Table& Record::table(const std::string& key) const {
  auto it = tables_.find(key);
  if (it == tables_.end()) missing(key, "table");
  return it->second;
}

const std::vector<std::string>& Record::strings(const std::string& key) const {
  auto it = strings_.find(key);
  if (it == strings_.end()) missing(key, "list of strings");
  return it->second;
}

const Record& Record::at(const std::string& key) const {
  for (const auto& [k, c] : children_)
    if (k == key) return *c;
  missing(key, "record");
}

std::vector<std::string> Record::child_names() const {
  std::vector<std::string> out;
  for (const auto& [k, c] : children_) out.push_back(k);
  return out;
}

bool Record::operator==(const Record& o) const {
  if (texts_ != o.texts_ || strings_ != o.strings_ || numbers_.size() != o.numbers_.size() ||
      tables_.size() != o.tables_.size() || children_.size() != o.children_.size())
    return false;
  for (const auto& [k, v] : numbers_) {
    auto it = o.numbers_.find(k);
    if (it == o.numbers_.end() || std::memcmp(&v, &it->second, sizeof v) != 0) return false;
  }
  for (const auto& [k, t] : tables_) {
    auto it = o.tables_.find(k);
    if (it == o.tables_.end() || !same_table(t, it->second)) return false;
  }
  for (std::size_t i = 0; i < children_.size(); ++i)
    if (children_[i].first != o.children_[i].first || !(*children_[i].second == *o.children_[i].second)) return false;
  return true;
}

void store_record(const H5Group& g, const Record& r) {
  for (const auto& [k, v] : r.numbers()) g.set_attr(k, v);
  for (const auto& [k, v] : r.texts()) g.set_attr(k, v);
  for (const auto& [k, t] : r.tables()) g.write_table(k, t);
  for (const auto& [k, v] : r.string_lists()) g.write_strings(k, v);
  const auto names = r.child_names();
  for (const auto& k : names) store_record(g.create_group(k), r.at(k));
  if (!names.empty()) g.set_attr(kChildrenAttr, join_lines(names));
}

namespace {

// Bounds on a stored record tree, so a crafted file (a `_children` order naming one group a
// million times, groups hard-linked into themselves or into a wide lattice) is refused at once
// instead of read for minutes or without end. The reports stoneskip writes nest a few levels and
// hold a few thousand records; the bounds are far above that.
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxRecords = 100000;

Record load_bounded(const H5Group& g, int depth, std::size_t& loaded) {
  if (depth > kMaxDepth)
    throw RecordError(g.path() + ": records nested more than " + std::to_string(kMaxDepth) + " deep (a group linked into itself?)");
  if (++loaded > kMaxRecords)
    throw RecordError(g.path() + ": more than " + std::to_string(kMaxRecords) + " records in one file (groups linked more than once?)");
  Record r(g.path());
  for (const auto& a : g.attr_names()) {
    if (a == kChildrenAttr) continue;
    if (g.attr_is_string(a))
      r.set(a, g.attr_string(a));
    else
      r.set(a, g.attr_double(a));
  }
  std::vector<std::string> groups;
  for (const auto& c : g.children()) {
    switch (g.child_kind(c)) {
      case H5Group::ChildKind::group: groups.push_back(c); break;
      case H5Group::ChildKind::table: r.set_table(c, g.read_table(c)); break;
      case H5Group::ChildKind::strings: r.set_strings(c, g.read_strings(c)); break;
      case H5Group::ChildKind::vector: {
        Table t;
        t.columns = {"value"};
        t.values = g.read_vector(c);
        r.set_table(c, t);
        break;
      }
      case H5Group::ChildKind::other:
        throw RecordError(g.path() + "/" + c + ": not a value a record can hold");
    }
  }
  // Children in the stored order; any group the order does not name (written by hand) after them.
  // The order names each existing group at most once, so it is never longer than the groups.
  const std::set<std::string> present(groups.begin(), groups.end());
  std::vector<std::string> order = g.has_attr(kChildrenAttr) ? split_lines(g.attr_string(kChildrenAttr)) : std::vector<std::string>{};
  std::set<std::string> named;
  for (const auto& c : order) {
    if (!present.count(c))
      throw RecordError(g.path() + ": the stored order names a missing record '" + c.substr(0, 64) + "'");
    if (!named.insert(c).second) throw RecordError(g.path() + ": the stored order names the record '" + c + "' twice");
  }
  for (const auto& c : groups)
    if (!named.count(c)) order.push_back(c);
  for (const auto& c : order) r.add_child(c, load_bounded(g.open_group(c), depth + 1, loaded));
  return r;
}

}  // namespace

Record load_record(const H5Group& g) {
  std::size_t loaded = 0;
  return load_bounded(g, 0, loaded);
}

}  // namespace stoneskip
