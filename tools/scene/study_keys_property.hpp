#pragma once
// Test support for the study-file property tests (stone_study_keys_property_test.cpp,
// wave_study_keys_property_test.cpp: two files, since the stone and wave studies' headers cannot
// share a translation unit). Study files (cases/README.md, "Study files"): the README lists their
// keys in tables, without bounds, so the property is the one every key shares: a value no key can
// take — an inline table where a number, string or array is expected, a number beyond a double,
// NaN — is refused in one line naming the key, within a second. The keys are every scalar or
// array key of the shipped full preset (which states every key), each required to be named in
// the README; arrays of tables ([[validation.measured]], ...) are left to the study-file tests.
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "tools/io/input_error.hpp"
#include "tools/io/toml_table.hpp"

namespace stoneskip::test {

inline void study_leaf_keys(const toml::value& v, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, x] : v.as_table()) {
    const std::string full = prefix.empty() ? k : prefix + "." + k;
    if (x.is_table()) study_leaf_keys(x, full, out);
    else if (!(x.is_array() && !x.as_array().empty() && x.as_array().front().is_table())) out.push_back(full);
  }
}

// Returns how many values were checked.
inline int check_study_keys(const std::string& file, const std::function<void(const std::vector<std::string>&)>& load) {
  constexpr double kMaxSecondsPerValue = 1.0;  // a load takes milliseconds: this only catches a hang
  std::ifstream in("cases/README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string studies = readme.substr(readme.find("## Study files"));
  std::vector<std::string> keys;
  study_leaf_keys(load_toml(file).root, "", keys);
  int checked = 0;
  for (const auto& key : keys) {
    const std::string name = key.substr(key.rfind('.') + 1);
    // [case] and an [initial] surface are documented once, with case files ("as in a wave case's [initial]").
    const bool shared = key.rfind("case.", 0) == 0 || key.find(".initial.") != std::string::npos;
    const std::string& doc = shared ? readme : studies;
    BOOST_TEST((doc.find("`" + name + "`") != std::string::npos || (shared && doc.find("\n" + name + " = ") != std::string::npos)),
               key << " is not in cases/README.md");
    if (key == "study.kind") continue;  // it decides which reader runs
    for (const char* bad : {"{ a = 1 }", "1e400", "nan"}) {
      const auto t0 = std::chrono::steady_clock::now();
      std::string e;
      try {
        load({key + "=" + bad});
      } catch (const InputError& x) {
        e = x.what();
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      BOOST_TEST_CONTEXT(file << ": " << key << " = " << bad) {
        BOOST_TEST(!e.empty(), "accepted");
        BOOST_TEST(e.find('\n') == std::string::npos, e);
        BOOST_TEST(e.find(name) != std::string::npos, e);
        BOOST_TEST(seconds < kMaxSecondsPerValue);
      }
      ++checked;
    }
  }
  return checked;
}

}  // namespace stoneskip::test
