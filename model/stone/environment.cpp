#include "model/stone/environment.hpp"

namespace stoneskip {

const char* to_string(Convention c) { return c == Convention::paper ? "paper" : "physical"; }

bool parse_convention(const std::string& s, Convention& out) {
  if (s == "physical") {
    out = Convention::physical;
    return true;
  }
  if (s == "paper") {
    out = Convention::paper;
    return true;
  }
  return false;
}

}  // namespace stoneskip
