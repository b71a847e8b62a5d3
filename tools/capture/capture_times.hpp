#pragma once
// A capture's sample times as the readers hand them on: host clocks stamp in Unix time, so a reader
// counts them from the first sample, but only where every time is sane; an absurd one (beyond
// kMaxCaptureTimeSpread_s of the median) is left as written, for the sanity check
// (capture_format.cpp) to name with its line and its value.
#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

// The median of the finite sample times (0 for none).
double median_time_s(const Trace& trace);

// Subtracts the first sample's time from every sample's, where every time is finite and within
// kMaxCaptureTimeSpread_s (capture_text.hpp) of the median; otherwise leaves them as written.
void count_times_from_first(Trace& trace);

}  // namespace stoneskip
