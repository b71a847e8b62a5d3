#pragma once
// Metadata comments shared by the text formats ("# key: value" lines, documented in
// tools/capture/README.md): the device calibration, the nominal report rate and the mounting.
//
//   # calibration.block: 80 80 80 00 9a 9a 9a 00 00 c5     EEPROM 0x16–0x1f, hex
//   # calibration.accel_zero_counts: 512,512,512          (and accel_one_g_counts, accel_sign)
//   # calibration.gyro_zero_counts: 8192,8192,8192        (and gyro_slow_counts_per_deg_s,
//                                                           gyro_fast_factor, gyro_sign)
//   # nominal_rate_hz: 100
//   # mounting.lever_arm_m: 0,0.6,0                        (any key of mounting.hpp)
//   # thrower.release_height_m: 0.3                        (any key of virtual_thrower.hpp)
// Other comments are ignored; an unknown calibration.*, mounting.* or thrower.* key is an error,
// and so is a key within two edits of one of ours (refuse_misspelt_header_key).
#include <string>
#include <string_view>
#include <vector>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

// Applies a header key to the trace. Returns false if the key is not one of ours (the caller
// ignores it); throws InputError naming FILE:LINE and the key for a bad value.
bool apply_header_key(Trace& trace, const std::string& key, const std::string& value, const std::string& file,
                      long line);

// A comment key that is none of ours (apply_header_key returned false) but within two edits of
// one — nominal_rate_hz, `more_keys` (a format's own), or the prefix of calibration.*, mounting.*,
// thrower.* — is a misspelt key, not a comment: InputError naming FILE:LINE, the key and the key
// it resembles. Anything further from every key stays a comment.
void refuse_misspelt_header_key(const std::string& key, const std::vector<std::string>& more_keys, const std::string& file,
                                long line);

// For the line-by-line readers: true when the (trimmed) line is blank or a comment, which the
// reader then skips; a "# key: value" comment is applied to the trace on the way (a misspelt key
// refused, above).
bool skip_blank_or_header(Trace& trace, std::string_view trimmed_line, const std::string& file, long line);

// After the whole file: one accelerometer count line without the other (the missing half would
// be the nominal calibration's, silently) is refused, naming the line given.
void refuse_half_calibration(const Trace& trace, const std::string& file);

// The header lines (with "# ") describing a trace's calibration, rate and mounting.
std::string header_lines(const Trace& trace);

}  // namespace stoneskip
