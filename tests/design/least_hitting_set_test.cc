// least_hitting_set (explanation_hitting.h) on seeded random set families: the same set as the
// exhaustive branch and bound it replaced (so explanations stay the same), of the least size by
// the definition (subsets of size 0, 1, ...), with or without the caller's lower bound.

#include "design/reconciliation/explanation_hitting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

namespace envdesign::design {
namespace {

// The exhaustive branch and bound least_hitting_set had: branch on the smallest set not hit
// (the first of equally small ones), its elements in order; keep the first smallest found.
std::vector<int> hitting_by_branch_and_bound(const std::vector<std::vector<int>> &sets, int size) {
    std::vector<int> chosen, best;
    std::vector<bool> in(size, false);
    bool found = false;
    std::function<void()> branch = [&] {
        if (found && chosen.size() + 1 > best.size())
            return;
        const std::vector<int> *open = nullptr;
        for (const auto &s : sets) {
            bool hit = false;
            for (int e : s)
                hit = hit || in[e];
            if (!hit && (!open || s.size() < open->size()))
                open = &s;
        }
        if (!open) {
            std::vector<int> sorted = chosen;
            std::sort(sorted.begin(), sorted.end());
            if (!found || sorted.size() < best.size() ||
                (sorted.size() == best.size() && sorted < best)) {
                best = std::move(sorted);
                found = true;
            }
            return;
        }
        for (int e : *open) {
            in[e] = true;
            chosen.push_back(e);
            branch();
            chosen.pop_back();
            in[e] = false;
        }
    };
    if (!sets.empty())
        branch();
    return best;
}

// A least hitting set by definition: subsets of size 0, 1, ... in lexicographic order.
std::vector<int> hitting_by_definition(const std::vector<std::vector<int>> &sets, int size) {
    for (int k = 0; k <= size; ++k) {
        std::vector<int> subset(k);
        for (int i = 0; i < k; ++i)
            subset[i] = i;
        while (true) {
            bool hits = std::all_of(sets.begin(), sets.end(), [&](const std::vector<int> &s) {
                return std::any_of(s.begin(), s.end(), [&](int e) {
                    return std::binary_search(subset.begin(), subset.end(), e);
                });
            });
            if (hits)
                return subset;
            int i = k - 1;
            while (i >= 0 && subset[i] == size - k + i)
                --i;
            if (i < 0)
                break;
            ++subset[i];
            for (int j = i + 1; j < k; ++j)
                subset[j] = subset[j - 1] + 1;
        }
    }
    return {};
}

TEST(LeastHittingSet, SameAsTheBranchAndBoundOnRandomFamilies) {
    std::mt19937 rng(24);
    for (int trial = 0; trial < 400; ++trial) {
        int size = 3 + static_cast<int>(rng() % 10);
        int count = 1 + static_cast<int>(rng() % 9);
        std::vector<std::vector<int>> sets(count);
        for (auto &s : sets) {
            for (int e = 0; e < size; ++e)
                if (rng() % 3 == 0)
                    s.push_back(e);
            if (s.empty())
                s.push_back(static_cast<int>(rng() % size));
        }
        std::vector<int> expected = hitting_by_branch_and_bound(sets, size);
        EXPECT_EQ(least_hitting_set(sets, size), expected) << "trial " << trial;
        EXPECT_EQ(expected.size(), hitting_by_definition(sets, size).size()) << "trial " << trial;
        // The size of the least hitting set of the first sets, as the explanation search passes.
        std::vector<std::vector<int>> first(sets.begin(), sets.end() - 1);
        int at_least = static_cast<int>(hitting_by_definition(first, size).size());
        EXPECT_EQ(least_hitting_set(sets, size, at_least), expected) << "trial " << trial;
    }
}

TEST(LeastHittingSet, TiesGoToTheFirstInTheBranchingOrder) {
    // {1, 3} first (smallest): 3 hits both. {0, 4} is branched on first: 4 with 2 or 3, not
    // the lexicographically lesser {0, 1, ...}, which is larger anyway; {2, 3} before {0, 4}.
    EXPECT_EQ(least_hitting_set({{1, 3}, {2, 3}}, 5), (std::vector<int>{3}));
    EXPECT_EQ(least_hitting_set({{0, 4}, {1, 4}, {2, 3}}, 5), (std::vector<int>{2, 4}));
    // Of {0, 2} and {1, 3}'s hitting pairs, branching on {1, 3} then {0, 2} finds {0, 1}.
    EXPECT_EQ(least_hitting_set({{1, 3}, {0, 2}}, 4), (std::vector<int>{0, 1}));
    EXPECT_EQ(least_hitting_set({{0, 1}, {0, 1}}, 2), (std::vector<int>{0}));
    EXPECT_EQ(least_hitting_set({}, 3), std::vector<int>{});
}

} // namespace
} // namespace envdesign::design
