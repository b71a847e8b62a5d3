#pragma once
// `--out FILE` over a file that exists: stoneskip replaces only a file it wrote (never one of the
// user's that happens to bear the name). It recognises its own by what it puts in them:
//   * an HDF5 file whose root carries stoneskip's `code_version` (stamp_provenance, hdf5_file.hpp);
//   * a text file that starts with "# stoneskip" (a converted capture, a sweep design);
//   * a movie (a GIF89a, or an MP4: "ftyp" at byte 4) holding kMovieMarker (reports/scene/
//     scene_movie.cpp writes it: MP4 metadata, a GIF comment).
// Anything else is refused with an InputError naming the option and the file, before any work. A
// file that does not exist, or is no regular file, is left to check_output_destination.
#include <filesystem>
#include <string>

namespace stoneskip {

inline constexpr const char* kMovieMarker = "made by stoneskip";

// True if `path` is a regular file stoneskip wrote (the marks above).
bool stoneskip_wrote(const std::filesystem::path& path);

void refuse_foreign_output(const std::filesystem::path& path, const std::string& option = "--out");

}  // namespace stoneskip
