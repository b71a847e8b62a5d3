#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

const char* to_string(ReferenceMethod m) {
  switch (m) {
    case ReferenceMethod::bdf: return "bdf";
    case ReferenceMethod::adams: return "adams";
  }
  return "unknown";
}

bool parse_reference_method(const std::string& s, ReferenceMethod& out) {
  if (s == "bdf") {
    out = ReferenceMethod::bdf;
    return true;
  }
  if (s == "adams") {
    out = ReferenceMethod::adams;
    return true;
  }
  return false;
}

}  // namespace stoneskip
