#include "ir/scoped_name.h"

#include <algorithm>

namespace mdlc::ir {

std::optional<SplitName> SplitScopedName(std::string_view name) {
  if (name.empty()) return std::nullopt;
  if (name.starts_with("::") || name.ends_with("::")) return std::nullopt;
  if (name.find("::::") != std::string_view::npos) return std::nullopt;
  const size_t pos = name.rfind("::");
  if (pos == std::string_view::npos) return SplitName{{}, name};
  return SplitName{name.substr(0, pos), name.substr(pos + 2)};
}

std::string JoinScopedName(std::string_view scope, std::string_view name) {
  if (scope.empty()) return std::string(name);
  if (name.empty()) return std::string(scope);
  std::string joined;
  joined.reserve(scope.size() + 2 + name.size());
  joined.append(scope).append("::").append(name);
  return joined;
}

namespace {
// optimal string alignment distance: edits plus adjacent transpositions,
// the usual shape of a typo ("amr" for "arm")
size_t EditDistance(std::string_view a, std::string_view b) {
  const size_t n = a.size(), m = b.size();
  std::vector<size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (size_t j = 0; j <= m; ++j) prev[j] = j;
  for (size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= m; ++j) {
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
      }
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}
}  // namespace

std::optional<std::string> ClosestName(std::string_view wanted,
                                       const std::vector<std::string_view>& candidates) {
  // only a typo's worth of edits, and never scan absurdly many candidates
  const size_t limit = std::max<size_t>(1, (wanted.size() + 2) / 3);
  std::optional<std::string> best;
  size_t best_distance = limit + 1;
  size_t scanned = 0;
  for (std::string_view c : candidates) {
    if (++scanned > 10000) break;
    const size_t length_gap = c.size() > wanted.size() ? c.size() - wanted.size()
                                                       : wanted.size() - c.size();
    if (length_gap >= best_distance) continue;
    const size_t d = EditDistance(wanted, c);
    if (d < best_distance) {
      best_distance = d;
      best = std::string(c);
    }
  }
  return best;
}

}  // namespace mdlc::ir
