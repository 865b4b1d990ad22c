#include "scene/did_you_mean.hpp"

#include <algorithm>
#include <cctype>

namespace sphdem {

namespace {

std::size_t allowed_edits(const std::string& a, const std::string& b) {
  const std::size_t shorter = std::min(a.size(), b.size());
  const std::size_t limit = shorter <= 4 ? 1 : 2;
  return shorter == 0 ? 0 : std::min(limit, shorter - 1);
}

}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
  auto low = [](char c) { return std::tolower(static_cast<unsigned char>(c)); };
  const std::size_t n = a.size(), m = b.size();
  // three rows of the table: i - 2, i - 1, i
  std::vector<std::size_t> before(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
        cur[j] = std::min(cur[j], before[j - 2] + 1);  // two neighbours swapped
    }
    std::swap(before, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}

std::string closest_name(const std::string& got, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_d = 0;
  for (const std::string& name : names) {
    if (name == got) continue;
    const std::size_t limit = allowed_edits(got, name);
    const std::size_t gap =
        got.size() > name.size() ? got.size() - name.size() : name.size() - got.size();
    if (gap > limit) continue;  // the distance is at least the difference in length
    const std::size_t d = edit_distance(got, name);
    if (d <= limit && (best.empty() || d < best_d)) {
      best = name;
      best_d = d;
    }
  }
  return best;
}

std::string did_you_mean(const std::string& got, const std::vector<std::string>& names) {
  const std::string best = closest_name(got, names);
  return best.empty() ? "" : "; did you mean '" + best + "'?";
}

}  // namespace sphdem
