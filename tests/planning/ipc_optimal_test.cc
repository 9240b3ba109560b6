// Optimality on real IPC instances: our cost equals Fast Downward's astar(lmcut()) cost from
// ../shared/benchmarks/ipc/optimal-costs.csv, and the independent validator accepts the plan
// with that cost. CI runs the instances FD solves with few expansions; the benchmark command
// (tests/benchmarks/ipc_benchmark.py) runs them all.

#include "pddl/parser.h"
#include "planning/planner.h"
#include "validate/plan_validator.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace envdesign::planning {
namespace {

struct Instance {
    std::string domain, problem;
    long long cost = 0;
    long long expansions = 0;
};

void PrintTo(const Instance &i, std::ostream *out) { *out << i.domain << "/" << i.problem; }

const std::string IPC_DIR = std::string(ENVDESIGN_SHARED_DIR) + "/benchmarks/ipc/";
constexpr long long CI_MAX_EXPANSIONS = 12000;

std::vector<Instance> ci_sample() {
    std::ifstream csv(IPC_DIR + "optimal-costs.csv");
    std::vector<Instance> sample;
    std::string line;
    std::getline(csv, line); // header
    while (std::getline(csv, line)) {
        std::vector<std::string> f;
        std::stringstream fields(line);
        for (std::string field; std::getline(fields, field, ',');)
            f.push_back(field);
        if (f.size() < 6 || f[2] != "yes" || std::stoll(f[5]) > CI_MAX_EXPANSIONS)
            continue;
        sample.push_back({f[0], f[1], std::stoll(f[3]), std::stoll(f[5])});
    }
    return sample;
}

class IpcOptimalTest : public ::testing::TestWithParam<Instance> {};

TEST_P(IpcOptimalTest, CostEqualsReferenceAndPlanValidates) {
    const Instance &instance = GetParam();
    std::string domain_file = IPC_DIR + instance.domain + "/domain.pddl";
    std::string problem_file = IPC_DIR + instance.domain + "/" + instance.problem;
    PlanReport report = plan_files(domain_file, problem_file, {});
    ASSERT_EQ(report.status, search::SearchStatus::SOLVED);
    EXPECT_EQ(report.cost, instance.cost);
    pddl::Domain domain = pddl::parse_domain_file(domain_file);
    pddl::Problem problem = pddl::parse_problem_file(problem_file, domain);
    validate::Validation validation = validate::validate_plan(domain, problem, report.plan);
    EXPECT_TRUE(validation.valid) << validation.error;
    EXPECT_EQ(validation.cost, instance.cost);
}

std::string instance_name(const ::testing::TestParamInfo<Instance> &info) {
    std::string name = info.param.domain + "_" + info.param.problem;
    for (char &c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)))
            c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Ipc, IpcOptimalTest, ::testing::ValuesIn(ci_sample()), instance_name);

} // namespace
} // namespace envdesign::planning
