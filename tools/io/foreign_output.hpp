#pragma once
// `--out FILE` over a file that exists: stoneskip replaces only a file it wrote (never one of the
// user's that happens to bear the name), and only with one of the same kind. It recognises its own
// by what it puts in them:
//   * hdf5: an HDF5 file whose root carries stoneskip's `code_version` (stamp_provenance,
//     hdf5_file.hpp) and is a throw's file — `run`, `scene`, `capture throw` — not a sweep's
//     result (root attribute `sweep_file`) or a report's data (root attribute `report`), which
//     `run --out` once replaced without a word;
//   * hdf5_sweep: the same, a sweep's result — `sweep`;
//   * trace_csv: a text file whose first line is the trace's own, "# stoneskip trace v1"
//     (tools/capture/trace_csv.hpp) — `capture convert`;
//   * movie: a GIF89a, or an MP4 ("ftyp" at byte 4), holding kMovieMarker (reports/scene/
//     scene_movie.cpp writes it: MP4 metadata, a GIF comment) — `scene --movie`.
// A text file that merely starts with "# stoneskip" (a user's notes, a synthetic capture, which is
// an input) is not an output of any of them; nor is an HDF5 file replaced by a trace, or the other
// way round. Anything else is refused with an InputError naming the option and the file, before
// any work. A file that does not exist, or is no regular file, is left to check_output_destination.
#include <filesystem>
#include <string>

namespace stoneskip {

inline constexpr const char* kMovieMarker = "made by stoneskip";

enum class OutputFormat { hdf5, hdf5_sweep, trace_csv, movie };
const char* to_string(OutputFormat f);  // "a throw's HDF5 file", "a sweep's HDF5 file", "a trace", "a movie"

// True if `path` is a regular file stoneskip wrote, of that kind (the marks above).
bool stoneskip_wrote(const std::filesystem::path& path, OutputFormat format);

void refuse_foreign_output(const std::filesystem::path& path, OutputFormat format, const std::string& option = "--out");

}  // namespace stoneskip
