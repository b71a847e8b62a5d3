#pragma once
// The truth file beside a synthetic capture (`stoneskip capture synthesize` writes
// `NAME.truth.toml` beside `NAME`; a gesture file `NAME.txt` has `NAME.truth.toml`): read with the
// project's TOML reader, so a damaged one is an InputError naming the file, line and key.
#include <filesystem>
#include <optional>

#include "verification/captures/capture_truth.hpp"

namespace stoneskip {

// The truth file for `capture`, or an empty path when there is none.
std::filesystem::path capture_truth_file(const std::filesystem::path& capture);

// Its [throw] values (arm_speed_m_s and pivot_speed_m_s when written), or nothing when the capture
// has no truth file.
std::optional<CaptureTruth> read_capture_truth(const std::filesystem::path& capture);

}  // namespace stoneskip
