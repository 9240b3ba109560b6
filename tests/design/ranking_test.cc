// The ranking of the N best designs (common/design/ranking.h): its order and threshold by
// hand, and offer_cone against sorting every member of a cone on seeded random costs.

#include "design/ranking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace envdesign::design {
namespace {

TEST(Ranking, KeepsTheBestInSpecOrderAndPrunesAgainstTheLast) {
    Ranking r(3);
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
        Ranking ranking(size);
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

} // namespace
} // namespace envdesign::design
