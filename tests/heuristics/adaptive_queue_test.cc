#include "heuristics/adaptive_queue.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

namespace envdesign::heuristics {
namespace {

TEST(AdaptiveQueue, BucketModeIsLifoWithinAKey) {
    AdaptiveQueue q;
    q.push(2, 10);
    q.push(0, 11);
    q.push(2, 12);
    q.push(0, 13);
    EXPECT_EQ(q.pop(), std::make_pair(0, 13));
    EXPECT_EQ(q.pop(), std::make_pair(0, 11));
    q.push(1, 14); // below the current bucket after pops: must still come first
    EXPECT_EQ(q.pop(), std::make_pair(1, 14));
    EXPECT_EQ(q.pop(), std::make_pair(2, 12));
    EXPECT_EQ(q.pop(), std::make_pair(2, 10));
    EXPECT_TRUE(q.empty());
}

TEST(AdaptiveQueue, ClearEmptiesAndAllowsReuse) {
    AdaptiveQueue q;
    q.push(5, 1);
    q.push(3, 2);
    q.clear();
    EXPECT_TRUE(q.empty());
    q.push(4, 7);
    EXPECT_EQ(q.pop(), std::make_pair(4, 7));
}

// Keys >= 100 beyond the push count switch to the heap; order by key must survive the
// switch and later pushes, on random input, against a sorted reference.
TEST(AdaptiveQueue, HeapModeKeepsKeyOrder) {
    std::mt19937 rng(7);
    for (int round = 0; round < 20; ++round) {
        AdaptiveQueue q;
        std::multiset<int> keys;
        std::uniform_int_distribution<int> small(0, 50), large(0, 100000);
        for (int i = 0; i < 30; ++i) {
            int key = i < 10 ? small(rng) : large(rng);
            q.push(key, i);
            keys.insert(key);
            if (i % 4 == 3) {
                auto [k, v] = q.pop();
                ASSERT_EQ(k, *keys.begin());
                keys.erase(keys.begin());
            }
        }
        while (!q.empty()) {
            auto [k, v] = q.pop();
            ASSERT_EQ(k, *keys.begin());
            keys.erase(keys.begin());
        }
        EXPECT_TRUE(keys.empty());
    }
}

} // namespace
} // namespace envdesign::heuristics
