#pragma once
// The sections of the stones report, each a function of its stored record (verification/stones/
// stone_studies.hpp says what each holds). None of them computes a result or decides a verdict.
#include <string>

#include "reports/common/plot.hpp"
#include "reports/common/section.hpp"

namespace stoneskip {

SectionOutput convergence_section(const Record& convergence);
// The convergence section's words on the study's adaptive schemes (the series against the
// tolerance), each piece "" where it ran none (convergence_section.cpp; its test).
struct ConvergenceAdaptiveWords {
  std::string runs;          // ", its adaptive scheme (`bs32`) with shrinking tolerances (rtol = atol_m)"
  std::string members;       // ", and `bs32`'s fixed-step member 3 when the scheme runs alone"
  std::string proportional;  // "; the adaptive scheme's error should fall in proportion to its tolerance (…)"
  std::string fitted;        // " The adaptive scheme's errors against its tolerance are fitted with a single power."
};
ConvergenceAdaptiveWords convergence_adaptive_words(const Record& convergence);
SectionOutput work_precision_section(const Record& work_precision);
SectionOutput work_precision_grid_section(const Record& work_precision_grid);  // subsection 2.1
// mesh (optional): the mesh study's record (§3c), whose verdict on the base stone's mesh the
// section states beside its counts.
SectionOutput sweeps_section(const Record& sweeps, const Record& fig9, const Record* mesh = nullptr);
SectionOutput count_ensembles_section(const Record& count_ensembles);  // count_ensembles_section.cpp
SectionOutput mesh_section(const Record& mesh);                        // mesh_section.cpp
SectionOutput hard_cases_section(const Record& hard_cases);
SectionOutput validation_section(const Record& validation);
SectionOutput ranking_section(const Record& validation);  // the validation record's "ranking"

// A stored throw history's attack angle against time, as a plot series (validation_section.cpp).
PlotSeries attack_angle_series(const Record& history, const std::string& title, const std::string& style);

}  // namespace stoneskip
