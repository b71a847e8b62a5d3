#pragma once
// The sections of the stones report. Each turns a study's result into data (HDF5 group), figures
// and Markdown; none of them integrates anything.
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "verification/stones/bounce_sweep.hpp"
#include "verification/stones/hard_cases.hpp"
#include "verification/stones/realtime_convergence.hpp"
#include "verification/stones/reference_tolerance.hpp"
#include "verification/stones/validation.hpp"
#include "verification/stones/work_precision.hpp"

namespace stoneskip {

struct SectionOutput {
  std::string markdown;
  std::vector<Figure> figures;
};

SectionOutput convergence_section(const RealtimeConvergenceResult& conv, const ReferenceToleranceResult& tol,
                                  const H5Group& data);
SectionOutput work_precision_section(const WorkPrecisionResult& wp, const H5Group& data);
SectionOutput sweeps_section(const std::vector<BounceSweepResult>& sweeps, const std::vector<ThrowHistory>& fig9,
                             const H5Group& data);
SectionOutput hard_cases_section(const std::vector<HardCaseResult>& hard, const std::vector<StableStepRow>& stable,
                                 const StableStepOptions& stable_options, const H5Group& data);
SectionOutput validation_section(const ValidationResult& v, const H5Group& data);

// Shared formatting.
std::string fmt_or_dash(double v, int significant = 3);
std::string history_group_name(const std::string& label);  // [a-z0-9_] from a label
void write_history(const H5Group& parent, const std::string& name, const ThrowHistory& h);

}  // namespace stoneskip
