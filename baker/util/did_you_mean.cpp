#include "baker/util/did_you_mean.h"

#include <algorithm>

namespace kiln {

int EditDistance(const std::string& a, const std::string& b) {
  const size_t n = a.size(), m = b.size();
  // d[i][j]: distance of a's first i and b's first j characters, three rows kept.
  std::vector<int> before(m + 1), previous(m + 1), current(m + 1);
  for (size_t j = 0; j <= m; ++j) previous[j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i) {
    current[0] = static_cast<int>(i);
    for (size_t j = 1; j <= m; ++j) {
      int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[m];
}

std::string ClosestName(const std::string& word, const std::vector<std::string>& candidates) {
  const int allowed =
      std::max(1, std::min(3, static_cast<int>(word.size()) / 3));  // typos, not other words
  std::string best;
  int bestDistance = allowed + 1;
  for (const std::string& c : candidates) {
    if (c == word) return "";
    int d = EditDistance(word, c);
    if (d < bestDistance) best = c, bestDistance = d;
  }
  return best;
}

std::string DidYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best = ClosestName(word, candidates);
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

}  // namespace kiln
