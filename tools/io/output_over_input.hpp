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

// Throws InputError (naming `option`) if the two outputs of one command are the same file however
// spelt (`scene --movie m.mp4 --out m.mp4` wrote the HDF5 result over the movie and exited 0).
// Either empty: nothing to compare.
void refuse_same_output(const std::filesystem::path& output, const std::string& option,
                        const std::filesystem::path& other, const std::string& other_option);

}  // namespace stoneskip
