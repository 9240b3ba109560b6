#pragma once
// For the tests of explanations: the two models of a seeded generated pair
// (explaining_generator.h), parsed, and the brute force over subsets of differences.

#include "design/model/configuration.h"
#include "explaining_generator.h"
#include "pddl/parser.h"
#include "pddl/sexpr.h"

#include <functional>
#include <string>
#include <vector>

namespace envdesign::design::testing {

// The paper's Blocksworld models for one problem file of tests/data/paper/blocksworld/
// ("20/init-7-1-goal-7-0.pddl"), each side's problem parsed against its own domain.
inline ModelPair paper_blocksworld(const std::string &problem) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/paper/blocksworld/";
    ModelPair m;
    m.robot_domain = pddl::parse_domain_file(dir + "domain-robot.pddl");
    m.human_domain = pddl::parse_domain_file(dir + "domain-human.pddl");
    m.robot_problem = pddl::parse_problem_file(dir + problem, m.robot_domain);
    m.human_problem = pddl::parse_problem_file(dir + problem, m.human_domain);
    return m;
}

inline ModelPair models_of(const GeneratedPair &g) {
    ModelPair m;
    m.robot_domain =
        pddl::parse_domain(pddl::read_sexpr(pair_domain(g, g.robot), "robot-domain"), "rd");
    m.human_domain =
        pddl::parse_domain(pddl::read_sexpr(pair_domain(g, g.human), "human-domain"), "hd");
    m.robot_problem = pddl::parse_problem(pddl::read_sexpr(pair_problem(g, g.robot, "t"), "rp"),
                                          "rp", m.robot_domain);
    m.human_problem = pddl::parse_problem(pddl::read_sexpr(pair_problem(g, g.human, "t"), "hp"),
                                          "hp", m.human_domain);
    return m;
}

// The least size of a subset of n differences for which `passes` holds, trying all 2^n (in the
// order of the bit masks, not by size); -1 if it holds for none.
inline int smallest_passing_subset(int n,
                                   const std::function<bool(const std::vector<int> &)> &passes) {
    int best = -1;
    for (unsigned mask = 0; mask < (1u << n); ++mask) {
        int size = __builtin_popcount(mask);
        if (best >= 0 && size >= best)
            continue;
        std::vector<int> chosen;
        for (int i = 0; i < n; ++i)
            if (mask & (1u << i))
                chosen.push_back(i);
        if (passes(chosen))
            best = size;
    }
    return best;
}

} // namespace envdesign::design::testing
