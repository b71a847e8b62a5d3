#pragma once
// The waves report's figures, built from the stored section records (verification/waves/
// wave_studies.hpp says what each holds). One line style per stencil, the same in every figure.
#include "reports/common/figure.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

Figure consistency_figure(const Record& consistency);
Figure convergence_figure(const Record& convergence, const std::string& kind);  // "space", "time", "both", "walls_<boundary>"
Figure isotropy_polar_figure(const Record& isotropy);
Figure isotropy_spread_figure(const Record& isotropy);
Figure isotropy_measured_figure(const Record& isotropy);
Figure ring_figure(const Record& isotropy);
Figure stability_figure(const Record& stability);
Figure work_precision_figure(const Record& speed);

}  // namespace stoneskip
