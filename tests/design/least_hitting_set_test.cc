// least_hitting_set (explanation_hitting.h) on seeded random set families: the
// lexicographically least of the least hitting sets, by the definition (subsets of size 0, 1,
// ... in lexicographic order), with or without the caller's lower bound.

#include "design/reconciliation/explanation_hitting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace envdesign::design {
namespace {

// The lexicographically least of the least hitting sets by definition: subsets of size 0,
// 1, ... in lexicographic order.
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

TEST(LeastHittingSet, TheLexicographicallyLeastOfTheLeastOnRandomFamilies) {
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
        std::vector<int> expected = hitting_by_definition(sets, size);
        EXPECT_EQ(least_hitting_set(sets, size), expected) << "trial " << trial;
        // The size of the least hitting set of the first sets, as the explanation search passes.
        std::vector<std::vector<int>> first(sets.begin(), sets.end() - 1);
        int at_least = static_cast<int>(hitting_by_definition(first, size).size());
        EXPECT_EQ(least_hitting_set(sets, size, at_least), expected) << "trial " << trial;
        // Some least hitting set: as small, ascending, and hitting every set.
        std::vector<int> some = some_least_hitting_set(sets, size, at_least);
        EXPECT_EQ(some.size(), expected.size()) << "trial " << trial;
        EXPECT_TRUE(std::is_sorted(some.begin(), some.end()));
        for (const auto &s : sets)
            EXPECT_TRUE(std::find_first_of(s.begin(), s.end(), some.begin(), some.end()) != s.end())
                << "trial " << trial;
    }
}

TEST(LeastHittingSet, TiesGoToTheLexicographicallyLeast) {
    EXPECT_EQ(least_hitting_set({{1, 3}, {2, 3}}, 5), (std::vector<int>{3}));
    EXPECT_EQ(least_hitting_set({{0, 4}, {1, 4}, {2, 3}}, 5), (std::vector<int>{2, 4}));
    // Branching on the first smallest set, {2, 3}, finds {1, 2} first; {0, 3} is less.
    EXPECT_EQ(least_hitting_set({{2, 3}, {1, 3}, {0, 2}}, 4), (std::vector<int>{0, 3}));
    EXPECT_EQ(least_hitting_set({{1, 3}, {0, 2}}, 4), (std::vector<int>{0, 1}));
    EXPECT_EQ(least_hitting_set({{0, 1}, {0, 1}}, 2), (std::vector<int>{0}));
    EXPECT_EQ(least_hitting_set({}, 3), std::vector<int>{});
}

} // namespace
} // namespace envdesign::design
