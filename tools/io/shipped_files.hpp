#pragma once
// The shipped cases (studies, scenes, throws, captures, baselines) from any working directory.
// A relative input path under "cases/" that does not exist where it is given is looked up in the
// shipped cases: first <prefix>/share/stoneskip/cases beside an installed binary
// (<prefix>/bin/stoneskip, `cmake --install`), then the source tree recorded at build time. The
// path as given is what a report or an error names, so a report does not depend on where it ran.
#include <filesystem>

namespace stoneskip {

// The folder of the shipped cases, or an empty path when neither place holds one.
std::filesystem::path shipped_cases_dir();

// `path` itself when it exists, is absolute, or does not start with "cases/"; else the shipped
// copy when that exists; else `path` (so the error names what was given).
std::filesystem::path locate_input(const std::filesystem::path& path);

}  // namespace stoneskip
