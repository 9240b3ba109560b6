// Grounding of a small hand-checked task: which facts and operators survive reachability,
// static-fact removal, the compilation of negative preconditions and relevance pruning.

#include "ground/grounder.h"
#include "pddl/parser.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace envdesign::ground {
namespace {

GroundTask ground_tiny() {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/tiny/";
    pddl::Domain domain = pddl::parse_domain_file(dir + "domain.pddl");
    pddl::Problem problem = pddl::parse_problem_file(dir + "problem.pddl", domain);
    return ground(domain, problem);
}

std::vector<std::string> names(const GroundTask &task, const std::vector<FactId> &facts) {
    std::vector<std::string> result;
    for (FactId f : facts)
        result.push_back(task.fact_names[f]);
    std::sort(result.begin(), result.end());
    return result;
}

const GroundOperator &find_operator(const GroundTask &task, const std::string &name) {
    auto it = std::find_if(task.operators.begin(), task.operators.end(),
                           [&](const GroundOperator &op) { return op.name == name; });
    EXPECT_NE(it, task.operators.end()) << name;
    return *it;
}

TEST(Grounder, StopsWhenAsked) {
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/huge-grounding/";
    pddl::Domain domain = pddl::parse_domain_file(dir + "domain.pddl");
    pddl::Problem problem = pddl::parse_problem_file(dir + "problem.pddl", domain);
    int asked = 0;
    // Asked every few thousand steps while reachability runs: the fifth time says stop.
    EXPECT_THROW(ground(domain, problem, nullptr, [&] { return ++asked == 5; }), GroundingStopped);
    EXPECT_EQ(asked, 5);
}

TEST(Grounder, AStopThatNeverSaysStopChangesNothing) {
    GroundTask plain = ground_tiny();
    const std::string dir = std::string(ENVDESIGN_TEST_DATA) + "/tiny/";
    pddl::Domain domain = pddl::parse_domain_file(dir + "domain.pddl");
    pddl::Problem problem = pddl::parse_problem_file(dir + "problem.pddl", domain);
    GroundTask asked = ground(domain, problem, nullptr, [] { return false; });
    EXPECT_EQ(asked.fact_names, plain.fact_names);
    EXPECT_EQ(asked.num_operators(), plain.num_operators());
}

TEST(Grounder, KeepsOnlyReachableRelevantFactsAndOperators) {
    GroundTask task = ground_tiny();
    // at x3, locked lab and its complement, visited hub; visited kitchen/lab are irrelevant.
    EXPECT_EQ(names(task,
                    [&] {
                        std::vector<FactId> all(task.num_facts());
                        for (FactId f = 0; f < task.num_facts(); ++f)
                            all[f] = f;
                        return all;
                    }()),
              (std::vector<std::string>{"(at r1 hub)", "(at r1 kitchen)", "(at r1 lab)",
                                        "(locked lab)", "(not (locked lab))", "(visited hub)"}));
    // six moves between three connected places (none to itself), one unlock of the lab.
    EXPECT_EQ(task.num_operators(), 7);
    EXPECT_TRUE(task.has_action_costs);
}

TEST(Grounder, CompilesNegativePreconditionsAndCosts) {
    GroundTask task = ground_tiny();
    const GroundOperator &unlock = find_operator(task, "(unlock r1 lab)");
    EXPECT_EQ(unlock.cost, 5);
    EXPECT_EQ(names(task, unlock.pre), (std::vector<std::string>{"(at r1 hub)", "(locked lab)"}));
    EXPECT_EQ(names(task, unlock.add), (std::vector<std::string>{"(not (locked lab))"}));
    EXPECT_EQ(names(task, unlock.del), (std::vector<std::string>{"(locked lab)"}));
    const GroundOperator &enter = find_operator(task, "(move r1 hub lab)");
    EXPECT_EQ(enter.cost, 2);
    EXPECT_EQ(names(task, enter.pre),
              (std::vector<std::string>{"(at r1 hub)", "(not (locked lab))"}));
    EXPECT_EQ(find_operator(task, "(move r1 kitchen lab)").cost, 1);
    EXPECT_EQ(names(task, task.initial_state),
              (std::vector<std::string>{"(at r1 kitchen)", "(locked lab)"}));
    EXPECT_EQ(names(task, task.goal), (std::vector<std::string>{"(at r1 lab)", "(visited hub)"}));
}

TEST(Grounder, BlocksworldFourBlocksHasThirtyTwoOperators) {
    const std::string dir = std::string(ENVDESIGN_SHARED_DIR) + "/benchmarks/ipc/blocks/";
    pddl::Domain domain = pddl::parse_domain_file(dir + "domain.pddl");
    pddl::Problem problem = pddl::parse_problem_file(dir + "probBLOCKS-4-0.pddl", domain);
    GroundTask task = ground(domain, problem);
    // 4 pick-up + 4 put-down + 12 stack + 12 unstack; on 12, ontable 4, clear 4, holding 4,
    // handempty 1.
    EXPECT_EQ(task.num_operators(), 32);
    EXPECT_EQ(task.num_facts(), 25);
    EXPECT_FALSE(task.has_action_costs);
}

} // namespace
} // namespace envdesign::ground
