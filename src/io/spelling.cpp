#include "fosssim/io/spelling.h"

#include <algorithm>
#include <cctype>

namespace fosssim::io {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

int editDistance(const std::string& a, const std::string& b) {
  // Names are short (attribute and element names); a 64-letter word is no misspelling of them.
  if (a.size() > 64 || b.size() > 64) return 1 << 20;
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string closestName(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string folded = lower(word);
  for (const auto& c : candidates)
    if (lower(c) == folded && c != word) return c;
  int best = 1 << 20;
  std::vector<std::string> closest;
  for (const auto& c : candidates) {
    const int d = editDistance(folded, lower(c));
    if (d < best) best = d, closest.clear();
    if (d == best) closest.push_back(c);
  }
  if (closest.size() != 1) return "";
  const size_t shorter = std::min(word.size(), closest.front().size());
  const size_t longer = std::max(word.size(), closest.front().size());
  const int allowed = shorter <= 4 ? 1 : 2;
  // A complete replacement ("x" for "m") is no misspelling.
  if (best == 0 || best > allowed || static_cast<size_t>(best) >= longer) return "";
  return closest.front();
}

}  // namespace fosssim::io
