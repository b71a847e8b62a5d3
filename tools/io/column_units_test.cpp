// Every stored table carries one unit per column. Oracles: the project's naming convention (a
// column's unit is its suffix: "t_s", "entry_speed_m_s"; no suffix: a count, flag or ratio, "1"),
// the units the writer states where a name cannot carry them, and a file in the layout written
// before the units (one comma-separated `columns` string), made here with the HDF5 C API.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "tools/io/scratch_dir.hpp"
#include "tools/io/column_units.hpp"
#include "tools/io/hdf5_file.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

struct Scratch : ScratchDir {
  Scratch() : ScratchDir("stoneskip_units") {}
};

}  // namespace

BOOST_AUTO_TEST_CASE(a_column_unit_is_the_suffix_its_name_ends_with_the_longest_first) {
  BOOST_TEST(column_unit("t_s") == "s");
  BOOST_TEST(column_unit("x_m") == "m");
  BOOST_TEST(column_unit("entry_speed_m_s") == "m/s");        // not "s"
  BOOST_TEST(column_unit("momentum_kg_m_s") == "kg m/s");     // not "m/s"
  BOOST_TEST(column_unit("volume_time_m3_s") == "m^3 s");     // a product, not a rate
  BOOST_TEST(column_unit("water_N_s") == "N s");              // an impulse, not a time
  BOOST_TEST(column_unit("max_wetted_area_m2") == "m^2");
  BOOST_TEST(column_unit("spin_rev_s") == "rev/s");
  BOOST_TEST(column_unit("wx_rad_s") == "rad/s");
  BOOST_TEST(column_unit("wx_deg_s") == "deg/s");
  BOOST_TEST(column_unit("entry_attack_angle_deg") == "deg");
  BOOST_TEST(column_unit("energy_J") == "J");
  BOOST_TEST(column_unit("fluid_power_W") == "W");
  BOOST_TEST(column_unit("interval_ms") == "ms");
  BOOST_TEST(column_unit("ax_g") == "g_n");
  BOOST_TEST(column_unit("throw.speed_m_s") == "m/s");  // a sweep's varied key
  // Rates, accelerations and squares, which "_s" and "_m_s" had caught ("'1'" for g, "s" for a
  // damping rate in a sweep's table).
  BOOST_TEST(column_unit("environment.gravity_m_s2") == "m/s^2");
  BOOST_TEST(column_unit("water.damping_per_s") == "1/s");
  BOOST_TEST(column_unit("sweep_throws_per_s") == "1/s");
  BOOST_TEST(column_unit("scene.frame_rate_hz") == "Hz");
  BOOST_TEST(column_unit("V2_m2_s2") == "m^2/s^2");
  BOOST_TEST(column_unit("spin2_rev2_s2") == "rev^2/s^2");
  BOOST_TEST(column_unit("draught_impulse_m3_s") == "m^3 s");
  BOOST_TEST(column_unit("interval_low_percent") == "%");
  BOOST_TEST(column_unit("mean_cpu_per_frame_us") == "us");
  BOOST_TEST(column_unit("width_px") == "px");
}

BOOST_AUTO_TEST_CASE(a_name_without_a_suffix_is_dimensionless_unless_its_table_gives_the_meaning) {
  for (const char* n : {"bounces", "n", "steps", "sigma", "kd", "rtol", "bisected", "qw", "s", "_s"})
    BOOST_TEST(column_unit(n) == "1", n);
  for (const char* n : {"value", "error", "x", "low", "high", "lo", "hi", "h"}) BOOST_TEST(column_unit(n) == "", n);
}

BOOST_AUTO_TEST_CASE(a_table_is_stored_with_its_names_and_units_as_string_arrays_and_read_back) {
  Scratch s;
  const fs::path f = s.dir / "t.h5";
  Table t{{"h_s", "value", "bounces"}, {}, {"", "m", ""}};
  t.add_row({1e-3, 0.5, 3});
  {
    Hdf5Writer w(f);
    w.root().write_table("points", t);
    w.commit();
  }
  const Table back = Hdf5Reader(f).root().read_table("points");
  BOOST_TEST(back.columns == t.columns);
  BOOST_TEST(back.units == (std::vector<std::string>{"s", "m", "1"}));  // stated where given, else from the name
  BOOST_TEST(back.values == t.values);
  BOOST_CHECK_THROW(Hdf5Writer(s.dir / "bad.h5").root().write_table("x", Table{{"a", "b"}, {}, {"m"}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(a_table_written_before_the_units_is_still_read_its_units_coming_from_the_names) {
  Scratch s;
  const fs::path f = s.dir / "old.h5";
  {
    const hid_t file = H5Fcreate(f.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t dims[2] = {1, 2};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t ds = H5Dcreate2(file, "old", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const double v[2] = {0.25, 7};
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(ds, "columns", type, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const char* cols = "t_s,bounces";
    H5Awrite(a, type, &cols);
    H5Aclose(a);
    H5Sclose(scalar);
    H5Tclose(type);
    H5Dclose(ds);
    H5Sclose(space);
    H5Fclose(file);
  }
  const Hdf5Reader r(f);
  BOOST_TEST((r.root().child_kind("old") == H5Group::ChildKind::table));
  const Table t = r.root().read_table("old");
  BOOST_TEST(t.columns == (std::vector<std::string>{"t_s", "bounces"}));
  BOOST_TEST(t.units.empty());
  BOOST_TEST(t.unit(0) == "s");
  BOOST_TEST(t.unit(1) == "1");
  BOOST_TEST(t.column("bounces") == std::vector<double>{7});
}
