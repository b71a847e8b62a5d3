#include "tools/io/output_over_input.hpp"

#include <algorithm>
#include <system_error>

#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  const bool same = fs::equivalent(a, b, ec);
  return !ec && same;
}

// True if `inner` lies in `folder` (both resolved), at any depth.
bool inside(const fs::path& inner, const fs::path& folder) {
  const auto f = std::distance(folder.begin(), folder.end());
  if (std::distance(inner.begin(), inner.end()) <= f) return false;
  return std::equal(folder.begin(), folder.end(), inner.begin());
}

}  // namespace

void refuse_output_over_inputs(const fs::path& output, OutputKind kind, const std::vector<fs::path>& inputs,
                               const std::string& option) {
  if (output.empty()) return;  // the commands refuse an empty name themselves
  const fs::path out = resolved(output);
  for (const auto& input : inputs) {
    if (input.empty()) continue;
    // The file that is read: a "cases/…" name missing here is the shipped case (shipped_files.hpp),
    // which an output here cannot hold (main blamed `--out .` for a shipped input it did not hold).
    const fs::path read = locate_input(input);
    const fs::path in = resolved(read);
    if (in == out || same_file(output, read))
      throw_input_error(option, 0, "", "'" + output.string() + "' is the input '" + input.string() + "': refusing to overwrite it");
    if (kind == OutputKind::folder && inside(in, out))
      throw_input_error(option, 0, "",
                        "folder '" + output.string() + "' holds the input '" + input.string() + "': refusing to replace it");
  }
}

void refuse_same_output(const fs::path& output, const std::string& option, const fs::path& other,
                        const std::string& other_option) {
  if (output.empty() || other.empty()) return;
  if (resolved(output) == resolved(other) || same_file(output, other))
    throw_input_error(option, 0, "",
                      "'" + output.string() + "' is also the " + other_option + " file: give the two outputs different names");
}

}  // namespace stoneskip
