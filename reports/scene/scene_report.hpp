#pragma once
// The scene report, rendered from its data.h5 alone: the section records
// written by run_scene_studies() (verification/scene/scene_studies.hpp) become index.md and the
// figures (the still frames drawn by the same gnuplot commands as the movies,
// reports/scene/frame_plot.hpp). Every number and verdict in the text is a stored value.
#include "reports/common/stored_report.hpp"

namespace stoneskip {

RenderedReport render_scene_report(const StoredReport& stored);

}  // namespace stoneskip
