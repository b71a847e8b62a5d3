#pragma once
// The captures report (`stoneskip capture validate FILE... --out DIR`, kind "captures"): one page,
// DIR/index.md, formatted from DIR/data.h5 alone — first the verdicts of every capture with a link
// to its part of the page, then one section per capture: its verdict and reasons, timing,
// the motion with the still part, the swing, clipping and the release marked, the release state as
// measured in the room and as mapped to the virtual stone (with intervals), what the solvers make of
// it and the settings. The findings are computed in verification/captures/capture_findings.hpp;
// nothing here computes a result or decides a verdict.
//
// data.h5: the root record (/report) holds the stone case the solvers ran with; /sections holds
// one record per capture (capture_findings) and "index" (capture_index_findings).
#include "reports/common/stored_report.hpp"

namespace stoneskip {

RenderedReport render_captures_report(const StoredReport& stored);

}  // namespace stoneskip
