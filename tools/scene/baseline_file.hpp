#pragma once
// Golden baseline files (cases/baselines/*.toml, documented in cases/README.md): reading one into a
// BounceBaseline (verification/stones/bounce_baseline.hpp, where the comparison lives), the sweep
// it describes (its stone case loaded and its solver settings applied), and the file's text after
// a new run (`stoneskip regress --update`).
#include <filesystem>
#include <string>

#include "verification/stones/bounce_baseline.hpp"

namespace stoneskip {

// threshold_tolerance and compare_tolerance must be at least this fraction of the grid's span
// (values.back() − values.front()): the bisection then halves a bracket at most ~30 times.
constexpr double kMinRelativeThresholdTolerance = 1e-9;
constexpr double kMaxBounceCount = 1e6;  // a stored count beyond this is not a count
constexpr int kDefaultEnsembleMembers = 8;  // nudged throws per grid value where the file names none

// Reads a baseline file; InputError ("FILE:LINE: key: what") on anything malformed. A file
// without [result] is accepted (has_result = false) so that `regress --update` can fill it.
BounceBaseline read_baseline(const std::string& path);

// The case file of a baseline: as written if it exists relative to the working directory, else
// relative to the repository root two folders above the baseline (cases/baselines/X.toml).
std::filesystem::path resolve_case_file(const BounceBaseline& b);

// The sweep a baseline describes (loads the case; InputError on a bad case, or on solver settings
// that the case's own [solver] would refuse).
BounceSweepSpec sweep_of(const BounceBaseline& b);

// A new baseline file's text: its settings, then the result of a run.
std::string baseline_text(const BounceBaseline& settings, const BounceSweepResult& result, const std::string& generated);

// `regress --update`: the file's text as it was up to its [result] table (settings, comments and
// layout kept as the user wrote them), then the new run's [result]; a file without [result] gets
// one at its end. The old [result], and anything after it, is replaced.
std::string updated_baseline_text(const std::string& old_text, const BounceSweepResult& result, const std::string& generated);

// The [result] table of a baseline file for a run.
std::string result_section_text(const BounceSweepResult& result, const std::string& generated);

}  // namespace stoneskip
