#include "tools/io/edit_distance.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace stoneskip {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  // The optimal string alignment distance: Levenshtein's insertions, deletions and substitutions,
  // and a swap of two neighbouring letters as one edit (the commonest typo: "cuont" for "count" is
  // one edit, and Levenshtein's two put it past a five-letter key's limit of one).
  auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  };
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

bool looks_misspelt(const std::string& key, const std::string& known) {
  return key != known && edit_distance(key, known) <= std::min<std::size_t>(2, known.size() / 3);
}

}  // namespace stoneskip
