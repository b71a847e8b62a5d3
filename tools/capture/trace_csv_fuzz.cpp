// libFuzzer target: the trace_csv reader (and the analysis of whatever it accepts) on arbitrary bytes.
// Bad input must end in an InputError, never a crash, a hang or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tools/capture/capture_format.hpp"
#include "tools/io/input_error.hpp"
#include "verification/captures/capture_analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const stoneskip::Trace t = stoneskip::parse_capture(text, "fuzz", "trace_csv");
    stoneskip::CaptureOptions o;
    o.members = 2;
    (void)stoneskip::analyse_capture(t, o);
  } catch (const stoneskip::InputError&) {
  }
  return 0;
}
