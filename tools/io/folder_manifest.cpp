#include "tools/io/folder_manifest.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader =
    "# stoneskip folder manifest v1: what stoneskip wrote here (d FOLDER, f SIZE FNV1A64 FILE); it replaces this "
    "folder only while it holds nothing else\n";

struct Entry {
  bool folder = false;
  std::uintmax_t size = 0;
  std::string hash;
};

// FNV-1a 64 of a file's bytes (Fowler, Noll & Vo): a change of any byte shows.
std::string file_hash(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::uint64_t h = 14695981039346656037ull;
  char buf[65536];
  while (f) {
    f.read(buf, sizeof buf);
    for (std::streamsize i = 0; i < f.gcount(); ++i) {
      h ^= static_cast<unsigned char>(buf[i]);
      h *= 1099511628211ull;
    }
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

// "<name>.tmp-<digits>[-<digits>]" (atomic_file.hpp) left by a killed writer.
bool is_temporary_name(const std::string& name) {
  const auto at = name.rfind(".tmp-");
  if (at == std::string::npos || at + 5 == name.size()) return false;
  return std::all_of(name.begin() + static_cast<long>(at) + 5, name.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '-'; });
}

bool plain_name(const std::string& rel) { return rel.find('\n') == std::string::npos && !rel.empty(); }

// What is under dir now: relative path → entry. Links and special files are returned as such
// (`other` receives the first one's relative path).
std::map<std::string, Entry> scan(const fs::path& dir, bool hash, std::string* other) {
  std::map<std::string, Entry> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string rel = fs::relative(it->path(), dir, ec).generic_string();
    if (rel == kFolderManifest) continue;
    const fs::file_type type = it->symlink_status(ec).type();
    Entry e;
    if (type == fs::file_type::directory) {
      e.folder = true;
    } else if (type == fs::file_type::regular) {
      e.size = it->file_size(ec);
      if (hash) e.hash = file_hash(it->path());
    } else {
      if (other && other->empty()) *other = rel;
      continue;
    }
    out[rel] = e;
  }
  if (ec && other && other->empty()) *other = "(unreadable: " + ec.message() + ")";
  return out;
}

std::string text_of(const std::map<std::string, Entry>& entries) {
  std::string s = kHeader;
  for (const auto& [rel, e] : entries) {
    if (!plain_name(rel)) continue;
    s += e.folder ? "d " + rel + "\n" : "f " + std::to_string(e.size) + " " + e.hash + " " + rel + "\n";
  }
  return s;
}

// A manifest's entry stays inside its folder: relative, without "." or ".." components (a crafted
// "figures/../../x" would otherwise let a render remove a file outside the folder).
bool inside_name(const std::string& rel) {
  const fs::path p(rel);
  if (p.is_absolute() || rel.empty()) return false;
  for (const auto& part : p)
    if (part == ".." || part == "." || part.empty()) return false;
  return true;
}

bool read_manifest_entries(const fs::path& dir, std::map<std::string, Entry>& out);

// The manifest's entries; false (and none) if there is none or it is not one.
bool read_manifest(const fs::path& dir, std::map<std::string, Entry>& out) {
  if (read_manifest_entries(dir, out)) return true;
  out.clear();
  return false;
}

bool read_manifest_entries(const fs::path& dir, std::map<std::string, Entry>& out) {
  std::error_code ec;
  const fs::path m = dir / kFolderManifest;
  if (fs::symlink_status(m, ec).type() != fs::file_type::regular) return false;
  std::ifstream f(m, std::ios::binary);
  std::string line;
  if (!std::getline(f, line) || line + "\n" != kHeader) return false;
  while (std::getline(f, line)) {
    Entry e;
    if (line.rfind("d ", 0) == 0) {
      e.folder = true;
      if (!inside_name(line.substr(2))) return false;
      out[line.substr(2)] = e;
      continue;
    }
    std::istringstream in(line);
    std::string kind, rel;
    if (!(in >> kind >> e.size >> e.hash) || kind != "f" || e.hash.size() != 16) return false;
    std::getline(in >> std::ws, rel);
    if (!inside_name(rel)) return false;
    out[rel] = e;
  }
  return true;
}

}  // namespace

void write_folder_manifest(const fs::path& dir, const std::vector<std::string>& leave_out) {
  std::string other;
  auto entries = scan(dir, true, &other);
  // Refused before anything is removed: a folder that is not all stoneskip's is left as it is.
  if (!other.empty())
    throw_input_error(dir.string(), 0, "", "holds '" + other + "', which is not a plain file or folder: no manifest written");
  for (auto it = entries.begin(); it != entries.end();) {
    const std::string top = it->first.substr(0, it->first.find('/'));
    // A temporary a killed writer left in the folder (a resumed build's work folder holds the
    // earlier run's "data.h5.tmp-PID") is removed, not listed and shipped.
    const bool stale = !it->second.folder && is_temporary_name(fs::path(it->first).filename().string());
    if (stale) {
      std::error_code ec;
      fs::remove(dir / it->first, ec);
    }
    it = stale || std::find(leave_out.begin(), leave_out.end(), top) != leave_out.end() ? entries.erase(it) : std::next(it);
  }
  write_text_file(dir / kFolderManifest, text_of(entries));
}

void update_folder_manifest(const fs::path& dir, const std::vector<fs::path>& written) {
  std::map<std::string, Entry> listed, keep;
  const auto now = scan(dir, true, nullptr);
  if (read_manifest(dir, listed))
    for (const auto& [rel, e] : listed) {
      auto it = now.find(rel);
      if (it != now.end() && it->second.folder == e.folder && it->second.size == e.size && it->second.hash == e.hash)
        keep[rel] = e;
    }
  for (const auto& w : written) {
    const std::string rel = w.generic_string();
    auto it = now.find(rel);
    if (it == now.end()) continue;
    keep[rel] = it->second;
    // Its folders too (figures/ for figures/a.png).
    for (fs::path p = fs::path(rel).parent_path(); !p.empty(); p = p.parent_path()) {
      auto f = now.find(p.generic_string());
      if (f != now.end() && f->second.folder) keep[p.generic_string()] = f->second;
    }
  }
  write_text_file(dir / kFolderManifest, text_of(keep));
}

bool may_overwrite(const fs::path& dir, const std::vector<fs::path>& files, std::string* why) {
  std::map<std::string, Entry> listed;
  const bool has_manifest = read_manifest(dir, listed);
  for (const auto& f : files) {
    std::error_code ec;
    const fs::path p = dir / f;
    const fs::file_type type = fs::symlink_status(p, ec).type();
    if (type == fs::file_type::not_found) continue;
    const std::string rel = f.generic_string();
    auto it = listed.find(rel);
    const bool same = type == fs::file_type::regular && it != listed.end() && !it->second.folder &&
                      it->second.size == fs::file_size(p, ec) && !ec && it->second.hash == file_hash(p);
    if (!same) {
      struct stat st {};
      const bool regular = type == fs::file_type::regular;
      if (why)
        *why = "'" + p.string() + "', which " +
               (!regular && ::lstat(p.c_str(), &st) == 0 ? "is " + file_type_words(st.st_mode)
                : !has_manifest ? std::string("stoneskip did not write (the folder holds no ") + kFolderManifest + ")"
                : it == listed.end() ? std::string("stoneskip did not write")
                                     : std::string("changed since stoneskip wrote it"));
      return false;
    }
  }
  return true;
}

std::size_t remove_listed_except(const fs::path& dir, const fs::path& under, const std::vector<fs::path>& written) {
  std::map<std::string, Entry> listed;
  if (!read_manifest(dir, listed)) return 0;
  std::vector<std::string> keep;
  for (const auto& w : written) keep.push_back(w.generic_string());
  const std::string prefix = under.generic_string() + "/";
  std::size_t removed = 0;
  for (const auto& [rel, e] : listed) {
    if (e.folder || rel.rfind(prefix, 0) != 0 || std::find(keep.begin(), keep.end(), rel) != keep.end()) continue;
    std::error_code ec;
    const fs::path p = dir / rel;
    if (fs::symlink_status(p, ec).type() != fs::file_type::regular || fs::file_size(p, ec) != e.size || ec ||
        file_hash(p) != e.hash)
      continue;
    if (fs::remove(p, ec)) ++removed;
  }
  return removed;
}

bool holds_only_its_manifest(const fs::path& dir, std::string* why) {
  auto say = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  std::map<std::string, Entry> listed;
  if (!read_manifest(dir, listed)) return say("it holds no stoneskip manifest (" + std::string(kFolderManifest) + ")");
  std::string other;
  const auto now = scan(dir, false, &other);
  if (!other.empty()) return say("'" + other + "' is a link or a special file");
  for (const auto& [rel, e] : now) {
    auto it = listed.find(rel);
    if (it == listed.end()) {
      if (!e.folder && is_temporary_name(fs::path(rel).filename().string())) continue;
      return say("'" + rel + "' is not something stoneskip wrote there");
    }
    if (it->second.folder != e.folder || it->second.size != e.size ||
        (!e.folder && it->second.hash != file_hash(dir / rel)))
      return say("'" + rel + "' changed since stoneskip wrote it");
  }
  return true;
}

}  // namespace stoneskip
