#pragma once
// The waves report, rendered from its data.h5 alone: the section records written by
// run_wave_studies() (verification/waves/wave_studies.hpp) become index.md and the figures.
// Every number and verdict in the text is a stored value; the words around them explain.
#include "reports/common/stored_report.hpp"

namespace stoneskip {

RenderedReport render_waves_report(const StoredReport& stored);

}  // namespace stoneskip
