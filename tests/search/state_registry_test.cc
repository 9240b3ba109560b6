#include "search/state_registry.h"

#include "search_test_util.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

namespace envdesign::search {
namespace {

// 40 facts: a group of 7 (3 bits), a group of 3 (2 bits), 30 ungrouped (1 bit each) = 35
// bits -> two bins.
ground::GroundTask packed_task() {
    ground::GroundTask task = testing::make_task(40);
    task.mutex_groups = {{0, 1, 2, 3, 4, 5, 6}, {10, 20, 30}};
    return task;
}

std::vector<ground::FactId> random_state(const ground::GroundTask &task, std::mt19937 &rng) {
    std::vector<ground::FactId> facts;
    std::set<ground::FactId> grouped;
    for (const auto &group : task.mutex_groups) {
        grouped.insert(group.begin(), group.end());
        int pick = std::uniform_int_distribution<int>(0, static_cast<int>(group.size()))(rng);
        if (pick < static_cast<int>(group.size()))
            facts.push_back(group[pick]);
    }
    for (ground::FactId f = 0; f < task.num_facts(); ++f)
        if (!grouped.count(f) && rng() % 2)
            facts.push_back(f);
    std::sort(facts.begin(), facts.end());
    return facts;
}

TEST(StateCodec, PackUnpackRoundTrip) {
    ground::GroundTask task = packed_task();
    StateCodec codec(task);
    EXPECT_EQ(codec.num_bins(), 2);
    std::mt19937 rng(3);
    UnpackedState state(codec);
    for (int i = 0; i < 500; ++i) {
        std::vector<ground::FactId> facts = random_state(task, rng);
        std::vector<StateCodec::Bin> bins(codec.num_bins());
        codec.pack(facts, bins.data());
        codec.unpack(bins.data(), state);
        ASSERT_EQ(state.facts, facts);
        for (ground::FactId f = 0; f < task.num_facts(); ++f)
            ASSERT_EQ(state.holds(f), std::binary_search(facts.begin(), facts.end(), f));
    }
}

TEST(StateCodec, ApplyDeletesBeforeAddsAndSparesTrueGroupMates) {
    ground::GroundTask task = packed_task();
    testing::add_op(task, "(move)", {1}, {2}, {1});        // within a group
    testing::add_op(task, "(del-false)", {}, {}, {3, 12}); // 3 is false while 1 is true
    testing::add_op(task, "(del-add)", {}, {4, 12}, {1});  // group: add wins the variable
    StateCodec codec(task);
    std::vector<StateCodec::Bin> s(codec.num_bins()), t(codec.num_bins());
    UnpackedState out(codec);
    codec.pack(std::vector<ground::FactId>{1, 12, 20}, s.data());
    codec.apply(s.data(), 0, t.data());
    codec.unpack(t.data(), out);
    EXPECT_EQ(out.facts, (std::vector<ground::FactId>{2, 12, 20}));
    codec.apply(s.data(), 1, t.data());
    codec.unpack(t.data(), out);
    EXPECT_EQ(out.facts, (std::vector<ground::FactId>{1, 20}));
    codec.apply(s.data(), 2, t.data());
    codec.unpack(t.data(), out);
    EXPECT_EQ(out.facts, (std::vector<ground::FactId>{4, 12, 20}));
}

TEST(StateCodec, OverlappingGroupsThrow) {
    ground::GroundTask task = testing::make_task(3);
    task.mutex_groups = {{0, 1}, {1, 2}};
    EXPECT_THROW(StateCodec codec(task), std::invalid_argument);
}

TEST(StateRegistry, BytesPerState) {
    EXPECT_EQ(StateRegistry(packed_task()).bytes_per_state(), 8U);
    // Without mutex groups every fact costs a bit: 40 facts -> 2 bins as well; 32 -> 1.
    EXPECT_EQ(StateRegistry(testing::make_task(32)).bytes_per_state(), 4U);
    EXPECT_EQ(StateRegistry(testing::make_task(0)).bytes_per_state(), 4U);
}

// 16 groups of 4 facts. If every group always has a true fact (one initially, and moves
// delete one fact of a group only while adding another), a group needs 2 bits and all fit
// one bin; a single operator that only deletes makes its group need a "none" value.
TEST(StateRegistry, ExactlyOneGroupsNeedNoNoneValue) {
    ground::GroundTask task = testing::make_task(64);
    for (int g = 0; g < 16; ++g) {
        task.mutex_groups.push_back({4 * g, 4 * g + 1, 4 * g + 2, 4 * g + 3});
        task.initial_state.push_back(4 * g);
        testing::add_op(task, "(move)", {4 * g}, {4 * g + 1}, {4 * g});
    }
    EXPECT_EQ(StateRegistry(task).bytes_per_state(), 4U);
    StateRegistry registry(task);
    StateID init = registry.insert_facts(task.initial_state).id;
    StateID succ = registry.insert_successor(init, 3).id;
    UnpackedState out(registry.codec());
    registry.unpack(succ, out);
    std::vector<ground::FactId> expected = task.initial_state;
    expected[3] = 13;
    EXPECT_EQ(out.facts, expected);
    // A delete without an add of a group mate: group 0 may become empty -> 3 bits.
    testing::add_op(task, "(drop)", {0}, {}, {0});
    EXPECT_EQ(StateRegistry(task).bytes_per_state(), 8U);
}

TEST(StateRegistry, DeduplicatesAndKeepsIdsDense) {
    ground::GroundTask task = packed_task();
    StateRegistry registry(task);
    std::mt19937 rng(5);
    std::map<std::vector<ground::FactId>, StateID> seen;
    UnpackedState out(registry.codec());
    for (int i = 0; i < 20000; ++i) { // enough to grow the hash table several times
        std::vector<ground::FactId> facts = random_state(task, rng);
        InsertResult r = registry.insert_facts(facts);
        auto it = seen.find(facts);
        if (it == seen.end()) {
            ASSERT_TRUE(r.is_new);
            ASSERT_EQ(r.id, seen.size());
            seen.emplace(facts, r.id);
        } else {
            ASSERT_FALSE(r.is_new);
            ASSERT_EQ(r.id, it->second);
        }
    }
    EXPECT_EQ(registry.size(), seen.size());
    for (const auto &[facts, id] : seen) {
        registry.unpack(id, out);
        ASSERT_EQ(out.facts, facts);
    }
}

TEST(StateRegistry, SuccessorsAreRegisteredOnce) {
    ground::GroundTask task = testing::grid_task(3);
    StateRegistry registry(task);
    StateID init = registry.insert_facts(task.initial_state).id;
    InsertResult right = registry.insert_successor(init, 0); // (move v0 v1)
    EXPECT_TRUE(right.is_new);
    EXPECT_EQ(right.id, 1U);
    InsertResult back = registry.insert_successor(right.id, 1); // (move v1 v0)
    EXPECT_FALSE(back.is_new);
    EXPECT_EQ(back.id, init);
    EXPECT_EQ(registry.size(), 2U);
}

} // namespace
} // namespace envdesign::search
