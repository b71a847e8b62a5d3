#pragma once
// The figures of the waves report, built from the study results (data tables + gnuplot script,
// reports/common/figure.hpp). Table names are prefixed with the figure's name because all the
// .dat files of a report share one folder.
#include <vector>

#include "reports/common/figure.hpp"
#include "verification/waves/wave_studies.hpp"

namespace stoneskip {

Figure consistency_figure(const WaveStudies& s);
Figure convergence_figure(const WaveStudies& s, const std::string& kind);  // "space", "time", "both"
Figure isotropy_polar_figure(const WaveStudies& s);
Figure isotropy_spread_figure(const WaveStudies& s);
Figure isotropy_measured_figure(const WaveStudies& s);
Figure ring_figure(const WaveStudies& s);
Figure stability_figure(const WaveStudies& s);
Figure work_precision_figure(const WaveStudies& s);

}  // namespace stoneskip
