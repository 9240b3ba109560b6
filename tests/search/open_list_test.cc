#include "search/open_list.h"

#include <gtest/gtest.h>

#include <random>
#include <tuple>

namespace envdesign::search {
namespace {

std::vector<StateID> drain(OpenList &open) {
    std::vector<StateID> out;
    while (!open.empty())
        out.push_back(open.pop());
    return out;
}

TEST(BucketOpenList, OrdersByFThenHThenFifo) {
    BucketOpenList open;
    open.push(1, {5, 0, 3});
    open.push(2, {5, 0, 1});
    open.push(3, {4, 0, 4});
    open.push(4, {5, 0, 1});
    open.push(5, {5, 0, 3});
    EXPECT_EQ(open.pop(), 3U);
    open.push(6, {3, 0, 0}); // f below the last popped one (inconsistent heuristic)
    EXPECT_EQ(drain(open), (std::vector<StateID>{6, 2, 4, 1, 5}));
}

TEST(HeapOpenList, SecondaryCostComesBetweenFAndH) {
    HeapOpenList open;
    open.push(1, {5, 2, 0});
    open.push(2, {5, 1, 3});
    open.push(3, {5, 1, 3});
    open.push(4, {4, 9, 9});
    open.push(5, {5, 1, 1});
    EXPECT_EQ(drain(open), (std::vector<StateID>{4, 5, 2, 3, 1}));
}

// Both lists agree with a stable sort on random keys when secondary costs are 0.
TEST(OpenLists, AgreeWithStableSort) {
    std::mt19937 rng(2);
    std::vector<std::tuple<int, int, StateID>> entries;
    BucketOpenList bucket;
    HeapOpenList heap;
    for (StateID id = 0; id < 2000; ++id) {
        int h = static_cast<int>(rng() % 30);
        int f = h + static_cast<int>(rng() % 30);
        entries.emplace_back(f, h, id);
        bucket.push(id, {f, 0, h});
        heap.push(id, {f, 0, h});
    }
    std::stable_sort(entries.begin(), entries.end(), [](const auto &a, const auto &b) {
        return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
    });
    std::vector<StateID> expected;
    for (const auto &e : entries)
        expected.push_back(std::get<2>(e));
    EXPECT_EQ(drain(bucket), expected);
    EXPECT_EQ(drain(heap), expected);
}

} // namespace
} // namespace envdesign::search
