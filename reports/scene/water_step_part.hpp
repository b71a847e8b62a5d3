#pragma once
// Section 6's part on the level between water steps (verification/scene/scene_step_findings.hpp):
// its words, table, verdict and figures, from the record "grid/water_step" alone.
#include "reports/common/section.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

void water_step_part(SectionWriter& w, const Record& ws);

}  // namespace stoneskip
