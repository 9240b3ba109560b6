#include "plan_diff.h"

#include <algorithm>

namespace envdesign::client {

std::vector<DiffStep> plan_diff(const std::vector<std::string> &a,
                                const std::vector<std::string> &b) {
    // lcs[i][j]: the longest common subsequence of a[i..] and b[j..]. Plans are short (tens
    // of actions), so the quadratic table is fine.
    std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> lcs(n + 1, std::vector<int>(m + 1, 0));
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            lcs[i][j] =
                a[i] == b[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
    std::vector<DiffStep> out;
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && a[i] == b[j]) {
            out.push_back({DiffSide::BOTH, a[i]});
            ++i, ++j;
        } else if (i < n && (j == m || lcs[i + 1][j] >= lcs[i][j + 1])) {
            out.push_back({DiffSide::ONLY_FIRST, a[i++]});
        } else {
            out.push_back({DiffSide::ONLY_SECOND, b[j++]});
        }
    }
    return out;
}

bool plans_differ(const std::vector<DiffStep> &diff) {
    return std::any_of(diff.begin(), diff.end(),
                       [](const DiffStep &s) { return s.side != DiffSide::BOTH; });
}

} // namespace envdesign::client
