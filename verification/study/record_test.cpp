// Tests of the findings records: stored and read back unchanged, strict about keys, and the
// verdict rules decide the same phrase from stored inputs.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <hdf5.h>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "verification/study/order_record.hpp"
#include "verification/study/record.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {
namespace {

Record sample() {
  Record r;
  r.set("pi", M_PI).set("label", "five_point").set("n", 7).set("missing_value", std::numeric_limits<double>::quiet_NaN());
  Table t{{"h_s", "error"}, {1e-3, 2e-6, 5e-4, 5e-7}};
  r.set_table("points", t);
  r.set_strings("names", {"a", "b, with a comma", ""});
  r.child("zeta").set("x", 1.0);
  r.child("alpha").child("deep").set("word", "second child, stored order kept");
  return r;
}

BOOST_AUTO_TEST_SUITE(record_)

BOOST_AUTO_TEST_CASE(a_record_reads_back_from_hdf5_bit_for_bit_with_its_children_in_order) {
  // Oracle: the record itself — store then load gives an equal record (numbers compared bitwise,
  // NaN included) and the children in the order they were added, not alphabetical.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / ("record-test-" + std::to_string(::getpid()) + ".h5");
  const Record r = sample();
  {
    Hdf5Writer w(file);
    store_record(w.root().create_group("r"), r);
    w.commit();
  }
  Hdf5Reader in(file);
  const Record back = load_record(in.root().open_group("r"));
  std::filesystem::remove(file);
  BOOST_TEST((back == r));
  BOOST_TEST(back.child_names() == (std::vector<std::string>{"zeta", "alpha"}), boost::test_tools::per_element());
  BOOST_TEST(std::isnan(back.number("missing_value")));
  BOOST_TEST(back.at("alpha").at("deep").text("word") == "second child, stored order kept");
}

// Loads /r of `file`; the RecordError's words, or "" when it loads.
std::string load_error(const std::filesystem::path& file) {
  try {
    Hdf5Reader in(file);
    load_record(in.root().open_group("r"));
    return "";
  } catch (const RecordError& e) {
    return e.what();
  }
}

BOOST_AUTO_TEST_CASE(a_crafted_record_tree_is_refused_at_once_naming_what_is_wrong) {
  // Oracle: the bounds load_record states (record.hpp): an order naming a child twice, records
  // nested more than 64 deep (a group hard-linked into itself), more than 100 000 records (a
  // lattice of groups linked 10 times at each of 6 levels: 10^6 paths to 7 groups). Each was read
  // for minutes or without end before (render stalled 118 s on a repeated `_children` name); now
  // each is one RecordError naming the group, and the well-formed tree beside them still loads.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / ("record-crafted-" + std::to_string(::getpid()) + ".h5");
  auto write = [&](const std::function<void(hid_t)>& craft) {
    {
      Hdf5Writer w(file);
      store_record(w.root().create_group("r"), sample());
      w.commit();
    }
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    BOOST_REQUIRE(f >= 0);
    craft(f);
    H5Fclose(f);
  };
  write([](hid_t) {});
  BOOST_TEST(load_error(file).empty());
  std::string repeated;
  for (int i = 0; i < 5000; ++i) repeated += i ? "\nalpha" : "alpha";  // 30 kB: within an attribute's 64 kB
  {
    Hdf5Writer w(file);
    H5Group r = w.root().create_group("r");
    r.create_group("alpha");
    r.set_attr("_children", repeated);
    w.commit();
  }
  BOOST_TEST(load_error(file).find("names the record 'alpha' twice") != std::string::npos, load_error(file));
  write([](hid_t f) { H5Lcreate_hard(f, "/r/alpha", f, "/r/alpha/deep/again", H5P_DEFAULT, H5P_DEFAULT); });
  BOOST_TEST(load_error(file).find("nested more than 64 deep") != std::string::npos, load_error(file));
  write([](hid_t f) {
    std::string level = "/r/zeta";
    for (int depth = 0; depth < 6; ++depth) {
      const std::string next = level + "/l0";
      H5Gclose(H5Gcreate2(f, next.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
      for (int k = 1; k < 10; ++k)
        H5Lcreate_hard(f, next.c_str(), f, (level + "/l" + std::to_string(k)).c_str(), H5P_DEFAULT, H5P_DEFAULT);
      level = next;
    }
  });
  BOOST_TEST(load_error(file).find("more than 100000 records") != std::string::npos, load_error(file));
  std::filesystem::remove(file);
}

BOOST_AUTO_TEST_CASE(a_missing_or_mistyped_key_is_an_error_naming_the_path) {
  // Oracle: the contract — a report never invents a value, so reading what is not there throws.
  const Record r = sample();
  BOOST_CHECK_THROW(r.number("label"), RecordError);  // a text, not a number
  BOOST_CHECK_THROW(r.text("nope"), RecordError);
  BOOST_CHECK_THROW(r.at("zeta").at("x"), RecordError);
  try {
    r.at("alpha").at("deep").number("nope");
  } catch (const RecordError& e) {
    BOOST_TEST(std::string(e.what()).find("/alpha/deep") != std::string::npos, e.what());
  }
  Record w;
  w.set("k", 1.0);
  BOOST_CHECK_THROW(w.set("k", "now a text"), RecordError);  // one key, one kind
  BOOST_CHECK_THROW(w.set("bad/key", 1.0), RecordError);
}

BOOST_AUTO_TEST_CASE(an_order_fit_verdict_is_decided_again_from_its_stored_inputs) {
  // Oracle: the rule applied twice — once when stored, once from the stored numbers — agrees; a
  // stored phrase edited by hand is reported as contradicted.
  Record r;
  const OrderFit fit = fit_order({0.1, 0.05, 0.025, 0.0125}, {1e-2, 2.5e-3, 6.25e-4, 1.5625e-4});  // exactly order 2
  store_order_fit(r, "fit", fit, OrderJudgement{2, 0.1, 0.25});
  BOOST_TEST(r.at("fit").at("verdict").text("verdict") == to_string(OrderVerdict::converges_at_expected_order));
  BOOST_TEST(contradicted_verdicts(r).empty());
  Record forged = r;
  forged.child("fit").child("verdict").set("verdict", "does not converge");
  BOOST_TEST(contradicted_verdicts(forged).size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_stored_order_fit_whose_error_grew_at_a_refinement_claims_no_order) {
  // Oracle: judge_order on the fit itself. Errors 1e-2, 2e-3, 2.2e-3, 1e-4, 2e-5 over halvings
  // fall overall (the interval excludes 0 and 4) but grow once: the stored phrase, decided from
  // the stored inputs, must be judge_order's "order not established", as the reason says, and not
  // the interval-only verdict it had been ("converges, not at the expected order").
  Record r;
  const OrderFit fit = fit_order({0.16, 0.08, 0.04, 0.02, 0.01}, {1e-2, 2e-3, 2.2e-3, 1e-4, 2e-5});
  const OrderJudgement j{4, 0.25, 0.25};
  BOOST_REQUIRE(fit.order_low > 0.25);
  BOOST_TEST((judge_order(fit, j).verdict == OrderVerdict::order_not_established));
  store_order_fit(r, "fit", fit, j);
  BOOST_TEST(r.at("fit").at("verdict").text("verdict") == to_string(OrderVerdict::order_not_established));
  BOOST_TEST(contradicted_verdicts(r).empty());
}

BOOST_AUTO_TEST_CASE(rules_decide_from_their_inputs_at_the_edges) {
  // Oracle: each rule's definition (verification/study/verdict_rules.hpp) at and beside its edge.
  Record in;
  in.set("limit_min", 0.7071).set("limit_max", 0.7071 + 5e-7).set("tolerance", 1e-6);
  BOOST_TEST(decide("limit_range", in) == "independent of the damping");
  in.set("limit_max", 0.7071 + 2e-6);
  BOOST_TEST(decide("limit_range", in) == "depends on the damping");
  Record g;
  g.set("gain", std::numeric_limits<double>::quiet_NaN()).set("material_gain", 1.5);
  BOOST_TEST(decide("work_gain", g) == "not established");
  g.set("gain", 1.49);
  BOOST_TEST(decide("work_gain", g) == "no other stencil is materially faster");
  g.set("gain", 1.5);
  BOOST_TEST(decide("work_gain", g) == "another stencil is faster");
  BOOST_CHECK_THROW(decide("no_such_rule", g), RecordError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
