#pragma once
// The stones report, rendered from its data.h5 alone: the section records written by
// run_stone_studies() (verification/stones/stone_studies.hpp) become index.md and the figures.
#include "reports/common/stored_report.hpp"

namespace stoneskip {

RenderedReport render_stones_report(const StoredReport& stored);

}  // namespace stoneskip
