// The ranking of the N best designs (common/design/search/ranking.h): its order and threshold by
// hand, offer_cone against sorting every member of a cone on seeded random costs, and the
// padded designs left out by default, by hand and against filtering every design sorted.

#include "design/search/ranking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace envdesign::design {
namespace {

TEST(Ranking, KeepsTheBestInSpecOrderAndPrunesAgainstTheLast) {
    Ranking r(3, Padding::LISTED);
    EXPECT_EQ(r.threshold(), INF);
    EXPECT_TRUE(r.may_enter(1e9, 99)); // not full: anything finite may enter
    EXPECT_FALSE(r.may_enter(INF, 0)); // infinite objectives are not ranked
    EXPECT_TRUE(r.offer({5, 0, {}}));
    EXPECT_TRUE(r.offer({7, 1, {0}}));
    EXPECT_TRUE(r.offer({6, 1, {1}}));
    EXPECT_FALSE(r.offer({6, 1, {1}})); // once per configuration
    EXPECT_FALSE(r.offer({INF, 0, {4}}));
    ASSERT_EQ(r.designs().size(), 3u);
    EXPECT_EQ(r.designs()[1].configuration, (Configuration{1}));
    EXPECT_EQ(r.threshold(), 7);
    // Nearly equal to the last: only with no more modifications (then cost and spec order
    // decide); below it: always; above: never.
    EXPECT_TRUE(r.may_enter(7 * (1 + 1e-14), 1));
    EXPECT_FALSE(r.may_enter(7, 2));
    EXPECT_TRUE(r.may_enter(6.9, 5));
    EXPECT_FALSE(r.may_enter(7.1, 0));
    EXPECT_FALSE(r.offer({7, 1, {2}}));  // ties {0}: same size and cost, later in spec order
    EXPECT_TRUE(r.offer({7, 0.5, {3}})); // ties {0}, cheaper
    EXPECT_EQ(r.designs()[2].configuration, (Configuration{3}));
    EXPECT_TRUE(r.offer({6, 1, {0}})); // ties {1}, earlier in spec order
    EXPECT_EQ(r.designs()[1].configuration, (Configuration{0}));
    EXPECT_EQ(r.designs()[2].configuration, (Configuration{1}));
    EXPECT_EQ(r.threshold(), 6);
    EXPECT_EQ(Ranking(0).size(), 1);
}

// One task of IE 2 and robot cost 3 (alpha = kappa = T = 1): objective = 5 + beta * C.
DesignProblem problem_with_costs(const std::vector<double> &costs, double beta) {
    DesignProblem p;
    p.weights.beta = beta;
    p.tasks.push_back(DesignTask{"t", 1, {}, {}});
    for (std::size_t i = 0; i < costs.size(); ++i)
        p.modifications.push_back({"m" + std::to_string(i), costs[i], {}});
    return p;
}

TEST(Ranking, OfferConeAgreesWithSortingEveryMember) {
    TaskExplicability task;
    task.status = ExplicabilityStatus::SOLVED;
    task.ie = 2, task.robot_cost = 3, task.human_plan_cost = 3;
    const std::vector<const TaskExplicability *> tasks{&task};
    const double palette[] = {0, 0, 1, 1, 2, 0.5, 3};
    long long most_offered_of_zero_costs = 0;
    for (unsigned seed = 0; seed < 400; ++seed) {
        std::mt19937 random(seed);
        int n = 4 + static_cast<int>(random() % 9);
        std::vector<double> costs;
        for (int i = 0; i < n; ++i)
            costs.push_back(seed % 7 == 0 ? 0.0 : palette[random() % 7]);
        double beta = seed % 5 == 0 ? 0.0 : 1.0 + static_cast<double>(random() % 3);
        DesignProblem problem = problem_with_costs(costs, beta);
        Configuration design{0};
        std::vector<int> free;
        for (int m = 1; m < n; ++m)
            if (random() % 4 != 0) // the rest touch a witness: not in the cone
                free.push_back(m);
        int max_size = static_cast<int>(random() % 4); // 0: no limit
        int size = 1 + static_cast<int>(random() % 8);
        Ranking ranking(size, Padding::LISTED);
        std::vector<RankedDesign> everything;
        auto offer = [&](const RankedDesign &d) {
            ranking.offer(d);
            everything.push_back(d);
        };
        // Designs found elsewhere first, some as good as members.
        for (int other = static_cast<int>(random() % 4); other > 0; --other) {
            Configuration c{n + other};
            offer({5 + static_cast<double>(random() % 6), 0, c});
        }
        double base = objective_lower_bound(problem, design_cost(problem, design), tasks);
        offer({base, design_cost(problem, design), design});
        long long offered = offer_cone(problem, design, tasks, free, max_size, ranking);
        for (int mask = 1; mask < (1 << free.size()); ++mask) {
            Configuration c = design;
            for (std::size_t i = 0; i < free.size(); ++i)
                if (mask >> i & 1)
                    c.push_back(free[i]);
            if (max_size > 0 && static_cast<int>(c.size()) > max_size)
                continue;
            std::sort(c.begin(), c.end());
            double cost = design_cost(problem, c);
            everything.push_back({objective_lower_bound(problem, cost, tasks), cost, c});
        }
        std::sort(everything.begin(), everything.end(), ranks_before);
        everything.resize(std::min<std::size_t>(everything.size(), size));
        ASSERT_EQ(ranking.designs().size(), everything.size()) << "seed " << seed;
        for (std::size_t i = 0; i < everything.size(); ++i)
            EXPECT_EQ(ranking.designs()[i].configuration, everything[i].configuration)
                << "seed " << seed << ", rank " << i + 1;
        if (seed % 7 == 0 && max_size == 0)
            most_offered_of_zero_costs = std::max(most_offered_of_zero_costs, offered);
    }
    // All costs zero: every member ties with the design; only members small enough to enter
    // are visited, not the 2^11 subsets.
    EXPECT_LT(most_offered_of_zero_costs, 100);
}

// Padded: a design one modification smaller ranks before it. By hand, three listed at most.
TEST(Ranking, LeavesOutDesignsWithAModificationThatDoesNotPay) {
    Ranking r(3);
    EXPECT_EQ(r.padding(), Padding::LEFT_OUT);
    EXPECT_TRUE(r.offer({5, 0, {}}));
    EXPECT_TRUE(r.offer({4, 1, {0}}));    // pays for 0: 4 < 5
    EXPECT_TRUE(r.offer({4, 1, {0, 1}})); // ties {0}: 1 does not pay; kept, not listed
    EXPECT_TRUE(r.offer({6, 1, {2}}));    // {} is better without 2
    ASSERT_EQ(r.designs().size(), 2u);
    EXPECT_FALSE(r.full());
    EXPECT_EQ(r.threshold(), INF); // two listed: nothing may be pruned yet
    EXPECT_TRUE(r.offer({3.5, 2, {0, 3}}));
    ASSERT_EQ(r.designs().size(), 3u);
    EXPECT_EQ(r.designs()[0].configuration, (Configuration{0, 3}));
    EXPECT_EQ(r.designs()[1].configuration, (Configuration{0}));
    EXPECT_EQ(r.designs()[2].configuration, (Configuration{}));
    // Three listed, but {0, 3} less 3 is not known: it may still turn out padded, so nothing
    // may be pruned against the third yet.
    EXPECT_FALSE(r.full());
    EXPECT_EQ(r.threshold(), INF);
    // {3} at 4.5 confirms {0, 3}, pays for 3 (it beats {} at 5) and takes the third place.
    EXPECT_TRUE(r.offer({4.5, 1, {3}}));
    EXPECT_EQ(r.designs()[2].configuration, (Configuration{3}));
    EXPECT_TRUE(r.full());
    EXPECT_EQ(r.threshold(), 4.5);
    EXPECT_FALSE(r.may_enter(4.5, 2)); // ties the last with more modifications
    EXPECT_FALSE(r.offer({5, 0, {}})); // offered twice
    // {3, 9} ties {0, 3} at a lower cost: first. Then {9} at 3 comes, and {3, 9} less 3 is
    // better: 3 does not pay in {3, 9} after all, which leaves the list.
    EXPECT_TRUE(r.offer({3.5, 1, {3, 9}}));
    EXPECT_EQ(r.designs()[0].configuration, (Configuration{3, 9}));
    EXPECT_TRUE(r.offer({3, 1, {9}}));
    std::vector<Configuration> listed;
    for (const auto &d : r.designs())
        listed.push_back(d.configuration);
    EXPECT_EQ(listed, (std::vector<Configuration>{{9}, {0, 3}, {0}}));
    // The first five with every design listed: {0, 1} is third.
    Ranking all(3, Padding::LISTED);
    for (const RankedDesign &d : std::vector<RankedDesign>{
             {5, 0, {}}, {4, 1, {0}}, {4, 1, {0, 1}}, {6, 1, {2}}, {3.5, 2, {0, 3}}})
        all.offer(d);
    EXPECT_EQ(all.designs()[1].configuration, (Configuration{0}));
    EXPECT_EQ(all.designs()[2].configuration, (Configuration{0, 1}));
}

// Every design of a seeded random landscape offered in random order, some of it as cones,
// against sorting every design and dropping those with a one-smaller subset before them.
TEST(Ranking, PaddedDesignsLeftOutAgreeWithFilteringEverySortedDesign) {
    for (unsigned seed = 0; seed < 300; ++seed) {
        std::mt19937 random(seed);
        const int n = 3 + static_cast<int>(random() % 4);
        std::vector<double> costs;
        for (int i = 0; i < n; ++i)
            costs.push_back(static_cast<double>(random() % 3));
        DesignProblem problem = problem_with_costs(costs, 1.0 + static_cast<double>(random() % 2));
        // Task values per design: a few levels, so that ties and padding both happen; a
        // design holding a "dud" keeps the values of the design without it (a cone).
        std::vector<bool> dud(n);
        for (int i = 0; i < n; ++i)
            dud[i] = random() % 3 == 0;
        std::vector<double> level(1 << n);
        for (auto &l : level)
            l = static_cast<double>(random() % 4);
        auto base_of = [&](int mask) {
            for (int i = 0; i < n; ++i)
                if (dud[i])
                    mask &= ~(1 << i);
            return mask;
        };
        auto config = [&](int mask) {
            Configuration c;
            for (int i = 0; i < n; ++i)
                if (mask >> i & 1)
                    c.push_back(i);
            return c;
        };
        auto tasks_of = [&](int mask) {
            TaskExplicability t;
            t.status = ExplicabilityStatus::SOLVED;
            t.ie = 1 + level[base_of(mask)], t.robot_cost = 3, t.human_plan_cost = 3;
            return t;
        };
        std::vector<RankedDesign> everything;
        for (int mask = 0; mask < (1 << n); ++mask) {
            Configuration c = config(mask);
            TaskExplicability t = tasks_of(mask);
            double cost = design_cost(problem, c);
            everything.push_back({objective_lower_bound(problem, cost, {&t}), cost, c});
        }
        int size = 1 + static_cast<int>(random() % 5);
        Ranking ranking(size);
        // The designs without duds are offered one by one (in random order), each with its
        // cone of duds, as the witness search does.
        std::vector<int> order;
        for (int mask = 0; mask < (1 << n); ++mask)
            if (base_of(mask) == mask)
                order.push_back(mask);
        std::shuffle(order.begin(), order.end(), random);
        for (int mask : order) {
            TaskExplicability t = tasks_of(mask);
            Configuration c = config(mask);
            double cost = design_cost(problem, c);
            ranking.offer({objective_lower_bound(problem, cost, {&t}), cost, c});
            std::vector<int> free;
            for (int i = 0; i < n; ++i)
                if (dud[i])
                    free.push_back(i);
            EXPECT_EQ(offer_cone(problem, c, {&t}, free, 0, ranking), 0); // kept as a cone
        }
        std::sort(everything.begin(), everything.end(), ranks_before);
        std::vector<Configuration> want;
        for (std::size_t i = 0; i < everything.size() && static_cast<int>(want.size()) < size;
             ++i) {
            const Configuration &d = everything[i].configuration;
            bool padded = false;
            for (std::size_t j = 0; j < i; ++j) {
                const Configuration &s = everything[j].configuration;
                padded = padded || (s.size() + 1 == d.size() &&
                                    std::includes(d.begin(), d.end(), s.begin(), s.end()));
            }
            if (!padded)
                want.push_back(d);
        }
        std::vector<Configuration> got;
        for (const auto &d : ranking.designs())
            got.push_back(d.configuration);
        EXPECT_EQ(got, want) << "seed " << seed;
    }
}

} // namespace
} // namespace envdesign::design
