// hdf5_strings_apart.hpp: an Hdf5Reader's strings come from the table a child read, not from the
// library in this process. Oracles: the values written (every kind of string the reader reads); a
// table of other values put in the file's place (what the reader returns is the table's); a link
// to another file is refused, and an address in another file is not the table's; the same group by a
// soft link or around a cycle of hard links finds its strings, and the walk of the cycle ends;
// bytes cut short are not a table.
#include "tools/io/hdf5_strings_apart.hpp"

#include <boost/test/unit_test.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"
#include "tools/io/scratch_dir.hpp"

namespace stoneskip {
namespace {

// The object's address and the file's number, as the table keys them.
H5O_info_t info_of(hid_t obj) {
  H5O_info_t info;
  BOOST_REQUIRE(H5Oget_info2(obj, &info, H5O_INFO_BASIC) >= 0);
  return info;
}

// What the reader returns for attribute `name`, or the error's text.
std::string attr_or_error(const H5Group& g, const std::string& name) {
  try {
    return g.attr_string(name);
  } catch (const std::runtime_error& e) {
    return std::string("error: ") + e.what();
  }
}

// A file of every kind of string the reader reads: scalar attributes on the root, a group and a
// dataset; a dataset of strings; a table's `columns` and `units` (arrays), and an old table's
// comma-separated `columns` (a scalar), made with the C API.
void write_sample(const std::filesystem::path& path) {
  Hdf5Writer w(path);
  w.root().set_attr("title", "a throw");
  H5Group g = w.root().create_group("run");
  g.set_attr("outcome", std::string("sank\non the third contact"));
  g.set_attr("bounces", 3.0);
  g.write_strings("notes", {"first", "", "third, with a comma"});
  Table t;
  t.columns = {"t_s", "z_m"};
  t.units = {"s", "m"};
  t.add_row({0.0, 0.1});
  g.write_table("trace", t);
  g.write_table("old", t);  // its columns then rewritten as one comma-separated string
  H5Id ds(H5Dopen2(g.id(), "old", H5P_DEFAULT), H5Dclose);
  BOOST_REQUIRE(H5Adelete(ds.get(), "columns") >= 0);
  H5Id type = vlen_string_type();
  H5Id space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Id a(H5Acreate2(ds.get(), "columns", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const char* cols = "a_m,b_s";
  BOOST_REQUIRE(H5Awrite(a.get(), type.get(), &cols) >= 0);
  w.commit();
}

BOOST_AUTO_TEST_SUITE(hdf5_strings_apart)

BOOST_AUTO_TEST_CASE(the_reader_returns_every_string_as_written) {
  ScratchDir dir("stoneskip_strings_apart");
  const auto path = dir.dir / "sample.h5";
  write_sample(path);
  const Hdf5Reader r(path);
  BOOST_TEST(r.root().attr_string("title") == "a throw");
  const H5Group g = r.root().open_group("run");
  BOOST_TEST(g.attr_string("outcome") == "sank\non the third contact");
  BOOST_TEST(g.attr_double("bounces") == 3.0);
  BOOST_TEST((g.read_strings("notes") == std::vector<std::string>{"first", "", "third, with a comma"}));
  const Table t = g.read_table("trace");
  BOOST_TEST((t.columns == std::vector<std::string>{"t_s", "z_m"}));
  BOOST_TEST((t.units == std::vector<std::string>{"s", "m"}));
  BOOST_TEST((g.read_table("old").columns == std::vector<std::string>{"a_m", "b_s"}));
  // The table as the walk read it: the keys the reader looks up, and nothing else.
  int fds[2];
  BOOST_REQUIRE(::pipe(fds) == 0);
  write_string_table(path, fds[1]);  // small: it fits the pipe's buffer
  ::close(fds[1]);
  std::string bytes;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) bytes.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  Hdf5StringTable table = parse_string_table(bytes);
  using K = Hdf5StringTable::Kind;
  BOOST_TEST(table.entries.size() == 7u);  // title, outcome, notes, and each table's columns and units
  const H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  const H5Id old(H5Dopen2(file.get(), "/run/old", H5P_DEFAULT), H5Dclose);
  const H5Id trace(H5Dopen2(file.get(), "/run/trace", H5P_DEFAULT), H5Dclose);
  const H5Id notes(H5Dopen2(file.get(), "/run/notes", H5P_DEFAULT), H5Dclose);
  const H5Id run(H5Gopen2(file.get(), "/run", H5P_DEFAULT), H5Gclose);
  table.fileno = info_of(run.get()).fileno;
  BOOST_REQUIRE(table.find(old.get(), K::attribute, "columns") != nullptr);
  BOOST_TEST((*table.find(old.get(), K::attribute, "columns") == std::vector<std::string>{"a_m,b_s"}));
  BOOST_REQUIRE(table.find(trace.get(), K::attribute, "units") != nullptr);
  BOOST_TEST((*table.find(trace.get(), K::attribute, "units") == std::vector<std::string>{"s", "m"}));
  BOOST_TEST(table.find(notes.get(), K::dataset, "") != nullptr);
  BOOST_TEST(table.find(run.get(), K::attribute, "bounces") == nullptr);  // a number, read by the library
  table.fileno += 1;  // the same address in another file is another object
  BOOST_TEST(table.find(notes.get(), K::dataset, "") == nullptr);
  // Cut anywhere short of its end mark, the bytes are no table.
  for (std::size_t cut : {std::size_t{0}, std::size_t{1}, bytes.size() / 2, bytes.size() - 1})
    BOOST_CHECK_THROW(parse_string_table(bytes.substr(0, cut)), std::runtime_error);
  BOOST_CHECK_THROW(parse_string_table(bytes + "E"), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(a_group_given_a_table_reads_its_strings_from_it_not_from_the_file) {
  ScratchDir dir("stoneskip_strings_apart");
  const auto path = dir.dir / "sample.h5";
  write_sample(path);
  H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  H5Id root_id(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  const H5Id notes(H5Dopen2(file.get(), "/run/notes", H5P_DEFAULT), H5Dclose);
  const H5Id run_id(H5Gopen2(file.get(), "/run", H5P_DEFAULT), H5Gclose);
  auto table = std::make_shared<Hdf5StringTable>();
  table->fileno = info_of(root_id.get()).fileno;
  table->entries[{info_of(root_id.get()).addr, 'A', "title"}] = {"from the table"};
  table->entries[{info_of(notes.get()).addr, 'D', ""}] = {"x", "y", "z"};
  const H5Group root(std::move(root_id), "", table);
  BOOST_TEST(root.attr_string("title") == "from the table");
  const H5Group run = root.open_group("run");
  BOOST_TEST((run.read_strings("notes") == std::vector<std::string>{"x", "y", "z"}));
  // Not in the table: an error, although the library could read it from the file.
  BOOST_TEST(attr_or_error(run, "outcome") == "error: HDF5: read attribute outcome");
  // In the table with another number of elements than the file's: an error too.
  table->entries[{info_of(run_id.get()).addr, 'A', "outcome"}] = {"a", "b"};
  BOOST_TEST(attr_or_error(run, "outcome") == "error: HDF5: read attribute outcome");
}

BOOST_AUTO_TEST_CASE(a_group_by_any_path_finds_its_strings_and_a_link_to_another_file_is_refused) {
  ScratchDir dir("stoneskip_strings_apart");
  const auto path = dir.dir / "links.h5";
  const auto other = dir.dir / "other.h5";
  {
    Hdf5Writer w(other);
    w.root().create_group("g").set_attr("name", "in the other file");
    w.commit();
  }
  {
    Hdf5Writer w(path);
    H5Group real = w.root().create_group("real");
    real.set_attr("name", "reached");
    BOOST_REQUIRE(H5Lcreate_soft("/real", w.root().id(), "alias", H5P_DEFAULT, H5P_DEFAULT) >= 0);
    // /real/up is the root again: a walk that followed every path would not end.
    BOOST_REQUIRE(H5Lcreate_hard(w.root().id(), ".", real.id(), "up", H5P_DEFAULT, H5P_DEFAULT) >= 0);
    BOOST_REQUIRE(H5Lcreate_external(other.c_str(), "/g", w.root().id(), "ext", H5P_DEFAULT, H5P_DEFAULT) >= 0);
    w.commit();
  }
  const Hdf5Reader r(path);
  BOOST_TEST(r.root().open_group("real").attr_string("name") == "reached");
  BOOST_TEST(r.root().open_group("alias").attr_string("name") == "reached");
  BOOST_TEST(r.root().open_group("real").open_group("up").open_group("real").attr_string("name") == "reached");
  // The library would follow the external link; the walk does not, and the reader refuses it.
  try {
    r.root().open_group("ext");
    BOOST_ERROR("a link to another file was followed");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()) == "HDF5: /ext is a link to another file");
  }
  BOOST_CHECK_THROW(r.root().child_kind("ext"), std::runtime_error);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
