#include "search/successor_generator.h"

#include "search_test_util.h"

#include <gtest/gtest.h>

#include <random>

namespace envdesign::search {
namespace {

// Against brute force on random tasks, with mutex groups steering the key choice and
// operators without preconditions.
TEST(SuccessorGenerator, MatchesBruteForce) {
    std::mt19937 rng(11);
    for (int round = 0; round < 100; ++round) {
        ground::GroundTask task = testing::make_task(12);
        task.mutex_groups = {{0, 1, 2, 3}, {4, 5}};
        std::uniform_int_distribution<int> fact(0, 11), size(0, 3);
        for (int o = 0; o < 40; ++o) {
            std::vector<ground::FactId> pre;
            for (int i = size(rng); i > 0; --i)
                pre.push_back(fact(rng));
            std::sort(pre.begin(), pre.end());
            pre.erase(std::unique(pre.begin(), pre.end()), pre.end());
            testing::add_op(task, "(o)", pre, {}, {});
        }
        SuccessorGenerator generator(task);
        StateCodec codec(task);
        UnpackedState state(codec);
        std::vector<ground::OperatorId> applicable;
        for (int s = 0; s < 20; ++s) {
            std::vector<ground::FactId> facts;
            facts.push_back(static_cast<int>(rng() % 4));
            facts.push_back(4 + static_cast<int>(rng() % 2));
            for (int f = 6; f < 12; ++f)
                if (rng() % 2)
                    facts.push_back(f);
            std::vector<StateCodec::Bin> bins(codec.num_bins());
            codec.pack(facts, bins.data());
            codec.unpack(bins.data(), state);
            generator.applicable_operators(state, applicable);
            std::sort(applicable.begin(), applicable.end()); // FD's order, compared as a set
            std::vector<ground::OperatorId> expected;
            for (int o = 0; o < task.num_operators(); ++o) {
                const auto &pre = task.operators[o].pre;
                if (std::all_of(pre.begin(), pre.end(), [&](int p) { return state.holds(p); }))
                    expected.push_back(o);
            }
            ASSERT_EQ(applicable, expected);
        }
    }
}

// FD's generator yields operators sorted by their preconditions in FD's fact order; here
// all facts are ungrouped and causally independent, so FD's Tarjan pass reverses their
// sorted names: (c) < (b) < (a). Ties (equal preconditions) go by operator name.
TEST(SuccessorGenerator, FastDownwardOrder) {
    ground::GroundTask task;
    task.fact_names = {"(c)", "(a)", "(b)"};
    testing::add_op(task, "(o1)", {0}, {}, {});    // pre (c)
    testing::add_op(task, "(o2)", {1, 2}, {}, {}); // pre (b) (a)
    testing::add_op(task, "(o3)", {}, {}, {});     // no precondition: first
    testing::add_op(task, "(o4)", {1}, {}, {});    // pre (a): after (b) (a)
    testing::add_op(task, "(o0)", {0}, {}, {});    // same as o1, smaller name
    SuccessorGenerator generator(task);
    StateCodec codec(task);
    UnpackedState state(codec);
    std::vector<StateCodec::Bin> bins(codec.num_bins());
    codec.pack(std::vector<ground::FactId>{0, 1, 2}, bins.data());
    codec.unpack(bins.data(), state);
    std::vector<ground::OperatorId> applicable;
    generator.applicable_operators(state, applicable);
    EXPECT_EQ(applicable, (std::vector<ground::OperatorId>{2, 4, 0, 1, 3}));
}

} // namespace
} // namespace envdesign::search
