// libFuzzer target: the header-driven CSV reader (and the analysis of whatever it accepts) on
// arbitrary bytes. The first byte picks the reader's options (remote 0–2, a --columns map or not,
// the format forced or recognised) so those paths are fuzzed too. Bad input must end in an
// InputError, never a crash, a hang or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tools/capture/capture_format.hpp"
#include "tools/io/input_error.hpp"
#include "verification/captures/capture_analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  stoneskip::CaptureReadOptions r;
  r.format = (mode & 0x08) ? "" : "csv";
  r.csv.remote = mode & 0x03;
  if (mode & 0x04) r.csv.columns = "t[ms]=Time,ax=Acc X #WM1,ay=Acc Y #WM1,az=Acc Z #WM1,raw_yaw=Raw Yaw #WM1";
  try {
    const stoneskip::Trace t = stoneskip::parse_capture(text, "fuzz", r);
    stoneskip::CaptureOptions o;
    o.members = 2;
    (void)stoneskip::analyse_capture(t, o);
  } catch (const stoneskip::InputError&) {
  }
  return 0;
}
