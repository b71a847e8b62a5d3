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
  // Three rolling rows (the swap looks two rows back): memory in the shorter key's length, not
  // the product (a 3 MB header key beside a short one took 518 MB).
  const std::string& x = a.size() >= b.size() ? a : b;
  const std::string& y = a.size() >= b.size() ? b : a;
  const std::size_t n = x.size(), m = y.size();
  std::vector<std::size_t> two_back(m + 1), back(m + 1), row(m + 1);
  for (std::size_t j = 0; j <= m; ++j) back[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      row[j] = std::min({back[j] + 1, row[j - 1] + 1, back[j - 1] + (same(x[i - 1], y[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(x[i - 1], y[j - 2]) && same(x[i - 2], y[j - 1])) row[j] = std::min(row[j], two_back[j - 2] + 1);
    }
    std::swap(two_back, back);
    std::swap(back, row);
  }
  return back[m];
}

bool looks_misspelt(const std::string& key, const std::string& known) {
  const std::size_t limit = std::min<std::size_t>(2, known.size() / 3);
  // The distance is at least the difference of the lengths: a long key is not compared at all.
  const std::size_t apart = key.size() > known.size() ? key.size() - known.size() : known.size() - key.size();
  return key != known && apart <= limit && edit_distance(key, known) <= limit;
}

}  // namespace stoneskip
