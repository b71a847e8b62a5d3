#pragma once
// What stoneskip wrote in an output folder (a report, a sweep page), kept in the folder as
// `stoneskip-manifest.txt` (written atomically): every file with its size and FNV-1a 64 hash, and
// every folder. A folder is replaced only if it holds nothing but what its manifest lists, unchanged
// (temporaries "<name>.tmp-<digits>" a killed writer left are allowed): a file the user dropped in,
// or edited, or a link, keeps it from being replaced. A folder without a manifest (made by hand, or
// by a stoneskip before manifests) is not stoneskip's to replace.
//
//   # stoneskip folder manifest v1 ...
//   d figures
//   f 1234 0123456789abcdef figures/a.png
#include <filesystem>
#include <string>
#include <vector>

namespace stoneskip {

inline constexpr const char* kFolderManifest = "stoneskip-manifest.txt";

// Lists everything under `dir` (the manifest itself excepted, and the top-level entries named in
// `leave_out`, which the caller removes next) and writes the manifest atomically. A temporary a
// killed writer left ("<name>.tmp-<digits>", as a resumed build's work folder can hold) is
// removed, not listed. A link or a
// special file under `dir` is an InputError: stoneskip writes neither.
void write_folder_manifest(const std::filesystem::path& dir, const std::vector<std::string>& leave_out = {});

// After writing `written` (paths relative to `dir`) into a folder in place (`report render DIR`):
// the manifest lists those files, and of what it listed before, what is still there unchanged.
// Anything else in the folder (the user's) stays unlisted, so the folder is not replaceable.
void update_folder_manifest(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& written);

// Before writing `files` (relative to `dir`) into a folder in place: true if that replaces nothing
// stoneskip did not write, each being absent or a plain file the manifest lists, unchanged. False
// with the reason (naming the first that is not) otherwise; a folder without a manifest has no
// file stoneskip may replace.
bool may_overwrite(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& files,
                   std::string* why = nullptr);

// After writing `written` in place: removes the files under `under` (relative to `dir`) that the
// manifest lists, unchanged, and that are not among `written` (what an earlier rendering drew and
// this one does not), so no stale figure stays listed as stoneskip's. Call before
// update_folder_manifest. Returns how many were removed.
std::size_t remove_listed_except(const std::filesystem::path& dir, const std::filesystem::path& under,
                                 const std::vector<std::filesystem::path>& written);

// True if every entry under `dir` is listed in its manifest, unchanged (files: same size and hash).
// False with the reason (naming the first entry that is not) otherwise.
bool holds_only_its_manifest(const std::filesystem::path& dir, std::string* why = nullptr);

}  // namespace stoneskip
