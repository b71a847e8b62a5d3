#pragma once
// An output must never replace what the command reads: `run case.toml --out case.toml` would turn
// the case into HDF5, and `sweep-plot sp1/results.h5 --out sp1` would delete its own input with the
// folder it replaces. The comparison resolves links, "." and ".." (std::filesystem::
// weakly_canonical) and, where both exist, compares the files themselves (equivalent: a hard link
// is the same file), so no spelling of the same path gets through.
#include <filesystem>
#include <string>
#include <vector>

namespace stoneskip {

enum class OutputKind { file, folder };

// Throws InputError (naming `option`, the output and the input) if `output` is one of `inputs`,
// or, for a folder output, if the folder holds one of them (at any depth). Empty inputs are skipped.
void refuse_output_over_inputs(const std::filesystem::path& output, OutputKind kind,
                               const std::vector<std::filesystem::path>& inputs, const std::string& option = "--out");

}  // namespace stoneskip
