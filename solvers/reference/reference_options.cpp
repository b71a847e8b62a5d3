#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

namespace {
template <class E, std::size_t N>
bool parse_enum(const std::string& s, const E (&all)[N], E& out) {
  for (E e : all) {
    if (s == to_string(e)) {
      out = e;
      return true;
    }
  }
  return false;
}
}  // namespace

const char* to_string(ReferenceMethod m) {
  switch (m) {
    case ReferenceMethod::bdf: return "bdf";
    case ReferenceMethod::adams: return "adams";
  }
  return "unknown";
}

bool parse_reference_method(const std::string& s, ReferenceMethod& out) {
  static const ReferenceMethod all[] = {ReferenceMethod::bdf, ReferenceMethod::adams};
  return parse_enum(s, all, out);
}

const char* to_string(RestartStrategy r) {
  switch (r) {
    case RestartStrategy::every_event: return "every_event";
    case RestartStrategy::every_crossing: return "every_crossing";
    case RestartStrategy::at_jumps: return "at_jumps";
    case RestartStrategy::never: return "never";
  }
  return "unknown";
}

bool parse_restart_strategy(const std::string& s, RestartStrategy& out) {
  static const RestartStrategy all[] = {RestartStrategy::every_event, RestartStrategy::every_crossing,
                                        RestartStrategy::at_jumps, RestartStrategy::never};
  return parse_enum(s, all, out);
}

const char* to_string(ToleranceScaling t) {
  switch (t) {
    case ToleranceScaling::per_component: return "per_component";
    case ToleranceScaling::uniform: return "uniform";
  }
  return "unknown";
}

bool parse_tolerance_scaling(const std::string& s, ToleranceScaling& out) {
  static const ToleranceScaling all[] = {ToleranceScaling::per_component, ToleranceScaling::uniform};
  return parse_enum(s, all, out);
}

}  // namespace stoneskip
